!> Mass scaling (issue #19, raccord_mass_scaling): only the elements whose
!> own stable step is below the target get mass, the step reaches the
!> target and the energy balance of the scaled system closes (Q4 and Q8);
!> quasi-static Hertz (mortar P1 and node-to-segment) scaled stays within
!> 0.5 % of the unscaled run and passes the quasi-static check; a wave in
!> a bar, where dynamics matter, is changed by the scaling and the
!> kinetic-energy check says so.
program test_mass_scaling
  use raccord_kinds, only: wp, i8
  use raccord_check, only: failure_t, new_test, run_tests, check, check_close
  use raccord_error, only: error_t
  use raccord_mesh, only: mesh_t, ELEM_Q4, ELEM_Q8, find_node_set
  use raccord_scene, only: scene_t, BC_FIXED, BC_PRESSURE, METHOD_MORTAR
  use raccord_material, only: KIN_FINITE, MAT_NEO_HOOKE
  use raccord_model, only: model_t
  use raccord_model_build, only: build_model
  use raccord_time_step, only: time_plan_t, choose_time_step
  use raccord_state, only: state_t, init_state
  use raccord_elastic_block, only: element_eigenvalue_bounds
  use raccord_kinetic_check, only: kinetic_check_t, init_kinetic_check, watch_kinetic_energy
  use raccord_scene_runner, only: scene_run_t, prepare_deck, step_predict, step_finish
  use raccord_central_difference, only: advance_state
  use raccord_test_meshes, only: rect_mesh
  use dynamics_support, only: one_body_scene, add_bc, start_march, march_steps
  implicit none

  real(wp), parameter :: young = 200000.0_wp, rho = 7.8e-9_wp, safety = 0.9_wp
  integer, parameter :: nx = 12                  !< elements along the graded bar
  real(wp), parameter :: ratio = 1.3_wp, l0 = 1.0_wp, height = 25.0_wp

  call run_tests('mass_scaling', [ &
    new_test('Q4: only the elements below the target change, step at the target, balance closes', test_scaled_q4), &
    new_test('Q8: only the elements below the target change, step at the target, balance closes', test_scaled_q8), &
    new_test('finite strain Q4 and Q8: the variable step at rest reaches the target', test_finite), &
    new_test('quasi-static Hertz, mortar P1 and node-to-segment: scaled within 0.5 % of unscaled', test_hertz), &
    new_test('wave in a bar: mass scaling changes it and the kinetic-energy check says so', test_wave)])

contains

  !> Bar [0, L] x [0, height], one element high, nx elements whose lengths
  !> grow by `ratio` from l0 at the clamped left end: the short elements set
  !> the stable step. Each element stays a rectangle (Q8 midside nodes at
  !> the middle of their edges).
  subroutine graded_bar(mesh, etype)
    type(mesh_t), intent(out) :: mesh
    integer, intent(in) :: etype
    real(wp) :: xc(0:nx), s
    integer :: i, k
    call rect_mesh(mesh, etype, nx, 1, real(nx, wp), height)
    xc(0) = 0.0_wp
    do i = 1, nx
      xc(i) = xc(i - 1) + l0*ratio**(i - 1)
    end do
    ! uniform x = s in [0, nx] -> piecewise linear through the graded corners
    do k = 1, mesh%nnode
      s = mesh%x(1, k)
      i = min(nx - 1, int(s))
      mesh%x(1, k) = xc(i) + (s - real(i, wp))*(xc(i + 1) - xc(i))
    end do
  end subroutine graded_bar

  !> Scene of the graded bar: clamped left, plane stress, nu = 0 (a 1D
  !> wave), the mass-scaling target dt_target (0: none).
  subroutine bar_scene(scene, t_end, dt_target)
    type(scene_t), intent(out) :: scene
    real(wp), intent(in) :: t_end, dt_target
    call one_body_scene(scene, young, 0.0_wp, rho, .true., t_end)
    scene%time%safety = safety
    scene%time%mass_scaling_dt = dt_target
    call add_bc(scene, 'left', BC_FIXED, comp=[.true., .true.])
  end subroutine bar_scene

  subroutine scaled_case(failure, etype)
    type(failure_t), allocatable, intent(out) :: failure
    integer, intent(in) :: etype
    integer, parameter :: nsteps = 4000
    type(mesh_t) :: mesh
    type(scene_t) :: s0, s1
    type(model_t) :: m0, m1
    type(time_plan_t) :: p0, p1
    type(state_t) :: state
    type(error_t) :: err
    real(wp), allocatable :: w2e(:), balance(:)
    logical, allocatable :: scaled(:), touched(:)
    real(wp) :: dt_t, w2_t, added, len_e
    integer :: e, nsc, k
    character(len=160) :: msg

    call graded_bar(mesh, etype)
    call bar_scene(s0, 1.0e-4_wp, 0.0_wp)
    call build_model(s0, mesh, m0, err)
    call choose_time_step(s0, m0, p0, err)
    call check(failure, .not. err%failed(), 'unscaled model: ' // err%message)
    if (allocated(failure)) return
    ! target: 4 x the unscaled step, which the shortest elements are far below
    dt_t = 4.0_wp*safety*p0%dt_stable
    call bar_scene(s1, 1.0e-4_wp, dt_t)
    call build_model(s1, mesh, m1, err)
    call choose_time_step(s1, m1, p1, err)
    call check(failure, .not. err%failed(), 'scaled model: ' // err%message)
    if (allocated(failure)) return

    ! The elements expected to be scaled: own step safety*2/omega_e below dt_t.
    associate (blk => m0%bodies(1)%blocks(1))
      allocate(w2e(blk%nel), scaled(blk%nel), touched(m0%nnode))
      call element_eigenvalue_bounds(blk, rho, w2e)
      scaled = safety*2.0_wp/sqrt(w2e) < dt_t
      nsc = count(scaled)
      write(msg, '(a,i0,a,i0)') 'elements scaled: expected ', nsc, ', reported ', m1%bodies(1)%nscaled
      call check(failure, nsc > 0 .and. nsc < blk%nel, 'the target scales some elements, not all: ' // trim(msg))
      call check(failure, m1%bodies(1)%nscaled == nsc, trim(msg))
      ! Nodes of unscaled elements only keep their mass bit for bit; the
      ! others gain.
      touched = .false.
      do e = 1, blk%nel
        if (scaled(e)) touched(blk%conn(:, e)) = .true.
      end do
      call check(failure, all(pack(m1%mass, .not. touched) == pack(m0%mass, .not. touched)), &
        'a node of unscaled elements only changed its mass')
      call check(failure, all(pack(m1%mass, touched) > pack(m0%mass, touched)), &
        'a node of a scaled element did not gain mass')
      ! Added mass: sum over the scaled elements of (s_e - 1) rho A_e (MS-1),
      ! A_e = length x height (thickness 1), from the geometry.
      w2_t = (2.0_wp*safety/dt_t)**2
      added = 0.0_wp
      do e = 1, blk%nel
        k = blk%conn(1, e)
        len_e = maxval(m0%x(1, blk%conn(:, e))) - minval(m0%x(1, blk%conn(:, e)))
        if (scaled(e)) added = added + (w2e(e)/w2_t - 1.0_wp)*rho*len_e*height
      end do
      call check_close(failure, sum(m1%mass) - sum(m0%mass), added, 'added mass against sum (s_e - 1) rho A_e', &
        rel_tol=1.0e-10_wp)
      call check_close(failure, m1%bodies(1)%mass - m1%bodies(1)%mass_unscaled, added, &
        'reported added mass of the body', rel_tol=1.0e-10_wp)
    end associate

    ! The step reaches the target: safety * stable step = dt_t, and the plan's
    ! step is dt_t shortened only to end at t_end.
    call check_close(failure, safety*p1%dt_stable, dt_t, 'safety x stable step of the scaled model', rel_tol=1.0e-12_wp)
    call check(failure, p1%dt <= dt_t*(1.0_wp + 1.0e-14_wp) .and. &
      p1%dt >= dt_t*(1.0_wp - 1.0_wp/real(p1%nsteps, wp)), 'plan step not at the target')
    write(msg, '(a,i0,a,i0)') 'steps unscaled ', p0%nsteps, ', scaled ', p1%nsteps
    write(*, '(8x,a)') trim(msg)
    call check(failure, real(p0%nsteps, wp)/real(p1%nsteps, wp) > 3.99_wp, 'fewer steps by the factor 4: ' // trim(msg))

    ! Energy balance of the scaled system over free vibration.
    s1%bodies(1)%velocity = [0.0_wp, 1000.0_wp]
    call build_model(s1, mesh, m1, err)
    call choose_time_step(s1, m1, p1, err)
    allocate(balance(nsteps))
    call init_state(m1, p1%dt, int(nsteps, i8), state)
    call start_march(m1, state)
    call march_steps(m1, state, nsteps, balance)
    write(msg, '(a,es10.3)') 'largest relative energy balance error ', maxval(abs(balance))
    write(*, '(8x,a)') trim(msg)
    call check(failure, maxval(abs(balance)) < 1.0e-10_wp, trim(msg))
    call check(failure, state%energy%kinetic > 0.0_wp .and. state%energy%internal > 0.0_wp, 'no motion')
  end subroutine scaled_case

  subroutine test_scaled_q4(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call scaled_case(failure, ELEM_Q4)
  end subroutine test_scaled_q4

  subroutine test_scaled_q8(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call scaled_case(failure, ELEM_Q8)
  end subroutine test_scaled_q8

  !> A finite-strain (neo-Hooke, plane strain) graded bar: the factors also
  !> cover the kernel's own current-length estimate, so the plan's stable
  !> step (which includes that estimate at rest) is the target.
  subroutine test_finite(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(mesh_t) :: mesh
    type(scene_t) :: s0, s1
    type(model_t) :: m0, m1
    type(time_plan_t) :: p0, p1
    type(error_t) :: err
    integer :: k, et(2)
    et = [ELEM_Q4, ELEM_Q8]
    do k = 1, 2
      call graded_bar(mesh, et(k))
      call bar_scene(s0, 1.0e-4_wp, 0.0_wp)
      s0%bodies(1)%plane_stress = .false.
      s0%bodies(1)%poisson = 0.3_wp
      s0%bodies(1)%kinematics = KIN_FINITE
      s0%bodies(1)%material = MAT_NEO_HOOKE
      call build_model(s0, mesh, m0, err)
      call choose_time_step(s0, m0, p0, err)
      s1 = s0
      s1%time%mass_scaling_factor = 4.0_wp
      call build_model(s1, mesh, m1, err)
      call choose_time_step(s1, m1, p1, err)
      call check(failure, .not. err%failed(), 'finite bar: ' // err%message)
      if (allocated(failure)) return
      call check(failure, m1%has_finite .and. m1%bodies(1)%nscaled > 0, 'finite bar: nothing scaled')
      call check_close(failure, p1%dt_stable, 4.0_wp*p0%dt_stable, 'finite bar: stable step at the target', &
        rel_tol=1.0e-12_wp)
    end do
  end subroutine test_finite

  !> Run a deck to its end with the quasi-static check of the program.
  subroutine run_checked(path, run, check_state, err)
    character(len=*), intent(in) :: path
    type(scene_run_t), intent(out) :: run
    type(kinetic_check_t), intent(out) :: check_state
    type(error_t), intent(inout) :: err
    call prepare_deck(path, run, err)
    if (err%failed()) return
    call init_kinetic_check(check_state, run%model%scaling%active, run%scene%time%kinetic_ratio_warn, &
      run%scene%time%kinetic_check_from, run%plan%t_end)
    do
      call step_predict(run, err)
      if (err%failed()) return
      call step_finish(run, err)
      if (err%failed()) return
      if (check_state%active) call watch_kinetic_energy(check_state, run%state)
      if (run%state%step == run%state%nsteps) exit
      call advance_state(run%state)
    end do
  end subroutine run_checked

  !> Peak contact pressure of pair 1 at the end (mortar: the largest
  !> multiplier lambda_n, the pressure of the mixed form; node-to-segment:
  !> the largest nodal pressure) and the sum of the nodal normal forces.
  subroutine contact_result(run, peak, force)
    type(scene_run_t), intent(in) :: run
    real(wp), intent(out) :: peak, force
    if (run%scene%contacts(1)%method == METHOD_MORTAR) then
      peak = maxval(run%pairs(1)%lam_n)
    else
      peak = maxval(run%pairs(1)%pressure)
    end if
    force = run%pairs(1)%normal_sum
  end subroutine contact_result

  !> The coarse Hertz regression decks (ramp to P over 2.5e-4 s, hold to
  !> 4e-4 s) unscaled and with mass_scaling_factor = 5
  !> (tests/data/decks/mass_scaling): peak pressure and normal force within
  !> 0.5 % of the unscaled run (the study's goal), no quasi-static warning.
  subroutine test_hertz(failure)
    type(failure_t), allocatable, intent(out) :: failure
    character(len=*), parameter :: base(2) = [character(len=32) :: 'reg_mortar_p1_slave_block', 'reg_nts_slave_block']
    type(scene_run_t) :: r0, r1
    type(kinetic_check_t) :: c0, c1
    type(error_t) :: err
    real(wp) :: pk0, f0, pk1, f1
    integer :: k
    character(len=200) :: msg
    do k = 1, 2
      call run_checked('input/verification/hertz/' // trim(base(k)) // '.nml', r0, c0, err)
      call check(failure, .not. err%failed(), 'unscaled ' // trim(base(k)) // ': ' // err%message)
      if (allocated(failure)) return
      call run_checked('tests/data/decks/mass_scaling/' // trim(base(k)) // '_ms5.nml', r1, c1, err)
      call check(failure, .not. err%failed(), 'scaled ' // trim(base(k)) // ': ' // err%message)
      if (allocated(failure)) return
      call check(failure, r1%model%scaling%active .and. r1%model%bodies(1)%nscaled > 0, 'the deck scales no element')
      call contact_result(r0, pk0, f0)
      call contact_result(r1, pk1, f1)
      write(msg, '(a,i0,a,i0,a,es10.3,a,es10.3,a,f7.4)') trim(base(k)) // ': steps ', r0%plan%nsteps, ' -> ', &
        r1%plan%nsteps, ', peak change ', (pk1 - pk0)/pk0, ', force change ', (f1 - f0)/f0, &
        ', largest KE/IE ', c1%ratio_max
      write(*, '(8x,a)') trim(msg)
      call check_close(failure, pk1, pk0, 'scaled peak pressure against the unscaled, ' // trim(msg), rel_tol=5.0e-3_wp)
      call check_close(failure, f1, f0, 'scaled normal force against the unscaled, ' // trim(msg), rel_tol=5.0e-3_wp)
      call check(failure, real(r0%plan%nsteps, wp)/real(r1%plan%nsteps, wp) > 4.99_wp, 'not 5 x fewer steps: ' // trim(msg))
      call check(failure, c1%active .and. .not. c1%warned, 'the quasi-static check warned on quasi-static Hertz: ' // &
        trim(msg))
      call check(failure, abs(r1%worst_balance) < 1.0e-6_wp, 'energy balance of the scaled run')
    end do
  end subroutine test_hertz

  !> Step pressure p on the right end of the graded bar, clamp on the left,
  !> to t = 1.6 L/c. d'Alembert: the front reaches the clamp at L/c and the
  !> clamp reaction jumps from 0 to 2 p H. Scaled to 4 x the step, the short
  !> elements at the clamp carry waves up to 4 x slower: the front arrives
  !> 10 % later (the error mass scaling causes where dynamics matter), and
  !> the kinetic-energy check of the program (its default start, the
  !> second half of the run) warns: in a wave, kinetic and internal energy
  !> are about equal.
  subroutine test_wave(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp), parameter :: p = 100.0_wp
    type(mesh_t) :: mesh
    type(scene_t) :: s0, s1
    type(model_t) :: m0, m1
    type(time_plan_t) :: p0, p1
    type(error_t) :: err
    type(kinetic_check_t) :: kc0, kc1
    real(wp) :: t_end, arrival0, arrival1, exact, change
    character(len=200) :: msg

    call graded_bar(mesh, ELEM_Q4)
    exact = maxval(mesh%x(1, :))/sqrt(young/rho)
    t_end = 1.6_wp*exact
    call bar_scene(s0, t_end, 0.0_wp)
    call add_bc(s0, 'right', BC_PRESSURE, pressure=p)
    call build_model(s0, mesh, m0, err)
    call choose_time_step(s0, m0, p0, err)
    call bar_scene(s1, t_end, 4.0_wp*safety*p0%dt_stable)
    call add_bc(s1, 'right', BC_PRESSURE, pressure=p)
    call build_model(s1, mesh, m1, err)
    call choose_time_step(s1, m1, p1, err)
    call check(failure, .not. err%failed(), 'wave scenes: ' // err%message)
    if (allocated(failure)) return
    ! the check as the program runs it; off on the unscaled run
    call init_kinetic_check(kc0, m0%scaling%active, s0%time%kinetic_ratio_warn, s0%time%kinetic_check_from, t_end)
    call init_kinetic_check(kc1, m1%scaling%active, s1%time%kinetic_ratio_warn, s1%time%kinetic_check_from, t_end)
    call bar_run(m0, p0, kc0, p*height, arrival0)
    call bar_run(m1, p1, kc1, p*height, arrival1)
    change = (arrival1 - arrival0)/arrival0
    write(msg, '(a,f7.4,a,f7.4,a,f7.4,a,f6.3)') 'arrival at the clamp / (L/c): unscaled ', arrival0/exact, &
      ', scaled ', arrival1/exact, ' (change ', change, '); scaled largest KE/IE ', kc1%ratio_max
    write(*, '(8x,a)') trim(msg)
    ! the front is smeared over the coarse elements (up to a fifth of L):
    ! unscaled it arrives 7 % late at half height
    call check(failure, abs(arrival0/exact - 1.0_wp) < 0.1_wp, 'unscaled arrival off d''Alembert: ' // trim(msg))
    ! 10 % measured: 20 x the 0.5 % scaled quasi-static runs stay within
    call check(failure, change > 0.05_wp, 'mass scaling should delay the front by more than 5 %: ' // trim(msg))
    call check(failure, .not. kc0%active, 'the check runs on an unscaled run')
    call check(failure, kc1%warned, 'the kinetic-energy check missed the dynamic scene: ' // trim(msg))
  end subroutine test_wave

  !> March the bar to its end; arrival = first time the clamp's x reaction
  !> reaches half its reflected value 2 p H (the middle of the front).
  subroutine bar_run(model, plan, kc, half, arrival)
    type(model_t), intent(in) :: model
    type(time_plan_t), intent(in) :: plan
    type(kinetic_check_t), intent(inout) :: kc
    real(wp), intent(in) :: half
    real(wp), intent(out) :: arrival
    type(state_t) :: st
    real(wp) :: bal(1), rx
    integer :: k
    arrival = huge(1.0_wp)
    call init_state(model, plan%dt, plan%nsteps, st)
    call start_march(model, st)
    do while (st%step < st%nsteps)
      call march_steps(model, st, 1, bal)
      if (kc%active) call watch_kinetic_energy(kc, st)
      rx = 0.0_wp
      do k = 1, model%ncdof
        if (model%cdof_comp(k) == 1) rx = rx + st%reaction(k)
      end do
      if (abs(rx) >= half .and. arrival == huge(1.0_wp)) arrival = st%time
    end do
  end subroutine bar_run
end program test_mass_scaling
