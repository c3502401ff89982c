!> Dynamics against closed forms: the 1D wave in a bar (d'Alembert), the
!> energy balance of undamped free vibration over 2e4 steps, and the
!> refusal of a time step above the stable one.
program test_wave_energy
  use raccord_kinds, only: wp, i8
  use raccord_check, only: failure_t, new_test, run_tests, check, check_close
  use raccord_error, only: error_t, EXIT_INPUT
  use raccord_mesh, only: mesh_t, ELEM_Q4, ELEM_Q8, find_node_set
  use raccord_scene, only: scene_t, BC_FIXED, BC_PRESSURE
  use raccord_model, only: model_t
  use raccord_model_build, only: build_model
  use raccord_time_step, only: time_plan_t, choose_time_step
  use raccord_state, only: state_t, init_state
  use raccord_test_meshes, only: rect_mesh
  use dynamics_support, only: one_body_scene, add_bc, start_march, march_to, march_steps
  implicit none

  call run_tests('wave_energy', [ &
    new_test('wave in a bar, Q4: end velocity, arrival, reflection', test_wave_q4), &
    new_test('wave in a bar, Q8: end velocity, arrival, reflection', test_wave_q8), &
    new_test('free vibration Q4: energy balance over 2e4 steps', test_energy_q4), &
    new_test('free vibration Q8: energy balance over 2e4 steps', test_energy_q8), &
    new_test('dt above the stable step is refused, at the bound it is stable', test_dt_limit)])

contains

  !> Bar [0, L] x [0, H], nu = 0, clamped at x = 0, pressure p on x = L
  !> from t = 0. d'Alembert: the front moves left at c = sqrt(E/rho);
  !> behind it the particle velocity is -p/(rho c); at the clamp the
  !> reflected wave doubles the stress, so the reaction is 2 p H.
  subroutine wave_case(failure, etype, nx)
    type(failure_t), allocatable, intent(out) :: failure
    integer, intent(in) :: etype, nx
    real(wp), parameter :: e = 200000.0_wp, rho = 7.8e-9_wp, p = 100.0_wp, lx = 100.0_wp, hy = 2.0_wp
    type(mesh_t) :: mesh
    type(scene_t) :: scene
    type(model_t) :: model
    type(time_plan_t) :: plan
    type(state_t) :: state
    type(error_t) :: err
    real(wp) :: c, tl, u_end, u_mid, u_mid_exact, v_part, rsum
    integer :: right, k, nsample
    integer, allocatable :: mid_nodes(:)

    call rect_mesh(mesh, etype, nx, 1, lx, hy)
    c = sqrt(e/rho)
    tl = lx/c
    call one_body_scene(scene, e, 0.0_wp, rho, .true., 1.6_wp*tl)
    call add_bc(scene, 'left', BC_FIXED, comp=[.true., .true.])
    call add_bc(scene, 'right', BC_PRESSURE, pressure=p)
    call build_model(scene, mesh, model, err)
    call check(failure, .not. err%failed(), 'build_model failed')
    if (allocated(failure)) return
    call choose_time_step(scene, model, plan, err)
    call init_state(model, plan%dt, plan%nsteps, state)
    right = find_node_set(mesh, 'right')
    mid_nodes = pack([(k, k = 1, mesh%nnode)], abs(mesh%x(1, :) - 0.5_wp*lx) < 1.0e-9_wp)
    call check(failure, size(mid_nodes) >= 2, 'no nodes at mid-length')
    if (allocated(failure)) return
    v_part = p/(rho*c)

    call start_march(model, state)
    ! Before the front arrives at mid-length (t = 0.5 L/c) the middle is at rest.
    call march_to(model, state, 0.35_wp*tl)
    u_mid = sum(state%u(1, mid_nodes))/size(mid_nodes)
    call check(failure, abs(u_mid) < 1.0e-3_wp*v_part*tl, 'mid-length moved before the front arrived')
    ! Behind the front: u(L/2, t) = -(p/E) c (t - L/(2c)).
    call march_to(model, state, 0.9_wp*tl)
    u_mid = sum(state%u(1, mid_nodes))/size(mid_nodes)
    u_mid_exact = -(p/e)*c*(state%time - 0.5_wp*tl)
    call check_close(failure, u_mid, u_mid_exact, 'mid-length displacement behind the front', rel_tol=5.0e-3_wp)
    ! Loaded end: u(L, t) = -v t until the reflection returns at 2L/c.
    call march_to(model, state, 1.5_wp*tl)
    u_end = sum(state%u(1, mesh%nsets(right)%nodes))/size(mesh%nsets(right)%nodes)
    call check_close(failure, u_end, -v_part*state%time, 'loaded-end displacement', rel_tol=1.0e-3_wp)
    write(*, '(a,es10.3,a,es10.3)') '        loaded end: relative error ', abs(u_end/(-v_part*state%time) - 1.0_wp), &
      '; mid-length behind the front: relative error ', abs(u_mid/u_mid_exact - 1.0_wp)
    ! Reflection at the clamp: the reaction averages 2 p H over [1.2, 1.6] L/c.
    rsum = 0.0_wp
    nsample = 0
    do while (state%time < 1.6_wp*tl - state%dt)
      call march_to(model, state, state%time + state%dt)
      if (state%time < 1.2_wp*tl) cycle
      rsum = rsum + sum(state%reaction, mask=model_cdof_x(model))
      nsample = nsample + 1
    end do
    call check_close(failure, rsum/nsample, 2.0_wp*p*hy, 'clamp reaction after reflection (mean)', rel_tol=1.0e-2_wp)
    write(*, '(a,es10.3,a,es10.3)') '        clamp reaction mean over [1.2, 1.6] L/c: relative error ', &
      abs(rsum/nsample/(2.0_wp*p*hy) - 1.0_wp), '; energy balance ', state%energy%balance/state%energy%scale
    ! Energy: the pressure's work is kinetic + internal (no loss in the bulk).
    call check(failure, abs(state%energy%balance) < 1.0e-10_wp*state%energy%scale, &
      'energy balance off by more than 1e-10 of the energy (pressure work must equal H exactly)')
  end subroutine wave_case

  function model_cdof_x(model) result(mask)
    type(model_t), intent(in) :: model
    logical, allocatable :: mask(:)
    mask = model%cdof_comp == 1
  end function model_cdof_x

  subroutine test_wave_q4(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call wave_case(failure, ELEM_Q4, 200)
  end subroutine test_wave_q4

  subroutine test_wave_q8(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call wave_case(failure, ELEM_Q8, 100)
  end subroutine test_wave_q8

  !> A plate clamped on its left side and set moving with a uniform
  !> velocity vibrates freely. Central difference conserves a modified
  !> energy exactly; the balance we report (trapezoidal work, mean
  !> velocities) differs from it by O((omega dt)^2) and must oscillate, not grow.
  subroutine energy_case(failure, etype, nx, ny)
    type(failure_t), allocatable, intent(out) :: failure
    integer, intent(in) :: etype, nx, ny
    integer, parameter :: nsteps = 20000
    type(mesh_t) :: mesh
    type(scene_t) :: scene
    type(model_t) :: model
    type(time_plan_t) :: plan
    type(state_t) :: state
    type(error_t) :: err
    real(wp), allocatable :: balance(:)
    real(wp) :: first, last
    character(len=120) :: msg

    call rect_mesh(mesh, etype, nx, ny, 10.0_wp, 2.0_wp, distortion=0.2_wp)
    call one_body_scene(scene, 1000.0_wp, 0.3_wp, 1.0e-6_wp, .false., 1.0_wp)
    scene%bodies(1)%velocity = [0.0_wp, 1.0_wp]
    call add_bc(scene, 'left', BC_FIXED, comp=[.true., .true.])
    call build_model(scene, mesh, model, err)
    call choose_time_step(scene, model, plan, err)
    allocate(balance(nsteps))
    call init_state(model, plan%dt, int(nsteps, i8), state)
    call start_march(model, state)
    call march_steps(model, state, nsteps, balance)
    first = maxval(abs(balance(1:nsteps/10)))
    last = maxval(abs(balance(nsteps - nsteps/10 + 1:)))
    write(msg, '(a,es10.3,a,es10.3)') 'first tenth ', first, ', last tenth ', last
    write(*, '(a)') '        max relative energy balance error, ' // trim(msg)
    call check(failure, maxval(abs(balance)) < 1.0e-10_wp, &
      'relative energy balance error above 1e-10 over 2e4 steps: ' // trim(msg))
    call check(failure, last < 2.0_wp*first + 1.0e-12_wp, 'energy error grows: ' // trim(msg))
    call check(failure, state%energy%kinetic > 0.0_wp .and. state%energy%internal > 0.0_wp, 'no motion')
  end subroutine energy_case

  subroutine test_energy_q4(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call energy_case(failure, ELEM_Q4, 10, 2)
  end subroutine test_energy_q4

  subroutine test_energy_q8(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call energy_case(failure, ELEM_Q8, 5, 1)
  end subroutine test_energy_q8

  !> A fixed dt 0.1 % above the stable step is refused with both figures;
  !> at the stable-step bound itself a run stays bounded for 5000 steps.
  subroutine test_dt_limit(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(mesh_t) :: mesh
    type(scene_t) :: scene
    type(model_t) :: model
    type(time_plan_t) :: plan
    type(state_t) :: state
    type(error_t) :: err
    real(wp) :: balance(5000), dt_stable

    call rect_mesh(mesh, ELEM_Q4, 8, 4, 4.0_wp, 2.0_wp, distortion=0.3_wp)
    call one_body_scene(scene, 1000.0_wp, 0.3_wp, 1.0e-6_wp, .false., 1.0_wp)
    scene%bodies(1)%velocity = [0.3_wp, 1.0_wp]
    call add_bc(scene, 'left', BC_FIXED, comp=[.true., .true.])
    call build_model(scene, mesh, model, err)
    call choose_time_step(scene, model, plan, err)
    dt_stable = plan%dt_stable
    scene%time%dt = 1.001_wp*dt_stable
    call choose_time_step(scene, model, plan, err)
    call check(failure, err%code == EXIT_INPUT, 'dt above the stable step was accepted')
    if (allocated(failure)) return
    call check(failure, index(err%message, 'exceeds the stable time step') > 0 .and. &
      index(err%message, 'dt') > 0, 'message does not say why: ' // err%message)
    call err%clear()
    scene%time%dt = dt_stable
    call choose_time_step(scene, model, plan, err)
    call check(failure, .not. err%failed(), 'dt equal to the stable step was refused')
    call init_state(model, plan%dt, 5000_i8, state)
    call start_march(model, state)
    call march_steps(model, state, 5000, balance)
    call check(failure, maxval(abs(balance)) < 1.0e-10_wp, 'run at the stable-step bound is not bounded (or energy not conserved)')
  end subroutine test_dt_limit
end program test_wave_energy
