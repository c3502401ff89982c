!> Axisymmetric contact (doc/verification.md, "Axisymmetric contact"; method
!> brief method-finite-plastic-axi.md 9.4-9.5):
!>  - the contact patch test: two coaxial cylinders pressed axially through
!>    a flat non-matching interface that reaches the axis; mortar P1 and P0
!>    give the uniform pressure at round-off, with and without friction;
!>    node-to-segment is printed and bounded;
!>  - Hertz, a sphere on a half-space (tests/axisymmetric/data): peak
!>    pressure and contact radius against p0 = (6 P E*^2/(pi^3 R^2))^(1/3)
!>    and a = (3 P R/(4 E*))^(1/3) with the measured total force P, mortar
!>    P1 and node-to-segment (argument 'slow': also mortar P0 and Q8).
program test_axi_contact
  use raccord_kinds, only: wp, pi
  use raccord_check, only: failure_t, new_test, run_tests, check, check_close
  use raccord_error, only: error_t
  use raccord_strings, only: str
  use raccord_mesh, only: mesh_t, ELEM_Q4, ELEM_Q8
  use raccord_scene, only: scene_t, BC_FIXED, BC_PRESSURE, BC_DISPLACEMENT, METHOD_NTS, METHOD_MORTAR, MULT_P1, MULT_P0
  use raccord_model, only: model_t
  use raccord_time_step, only: time_plan_t
  use raccord_state, only: state_t
  use raccord_central_difference, only: advance_state
  use raccord_contact_pair, only: contact_pair_t
  use raccord_multiplier_solver, only: ST_OPEN
  use raccord_test_meshes, only: rect_mesh
  use raccord_scene_runner, only: scene_run_t, run_deck
  use dynamics_support, only: add_bc, add_pair, contact_step, two_body_scene, prepare_contact, add_amplitude
  implicit none

  character(len=16) :: arg
  logical :: slow

  call get_command_argument(1, arg)
  slow = trim(arg) == 'slow'
  if (trim(arg) == 'study') then
    call run_tests('axi_hertz_study', [new_test('study: Hertz sphere, Q4, mesh levels L1-L3', test_study)])
  else if (slow) then
    call run_tests('axi_contact_slow', [ &
      new_test('slow: Hertz sphere, Q4, mortar P0', test_hertz_p0), &
      new_test('slow: Hertz sphere, Q8, mortar P1', test_hertz_q8)])
  else
    call run_tests('axi_contact', [ &
      new_test('patch test, coaxial cylinders 5:7 (Q4): mortar P1, P0 exact; NTS bounded', test_patch_q4), &
      new_test('patch test, Q8 slave on Q4 master 3:5', test_patch_q8), &
      new_test('shaft pulled through a squeezed sleeve: friction force = mu N (ring totals)', test_sleeve), &
      new_test('Hertz sphere on a half-space, Q4: mortar P1 and node-to-segment', test_hertz)])
  end if

contains

  !> Lower cylinder a (na elements across the radius 1, type ta) under the
  !> upper cylinder b (nb, tb), both of height 0.5, E = 1000, a's bottom on
  !> rollers, pressure p on b's top; the axis nodes are held by raccord.
  !> Slave = b's bottom. Uniform axial stress -p and u_r = nu p r/E in both:
  !> the interface stays matched and every multiplier is p. Returns the
  !> spread max |x - mean|/p of the mortar multipliers (or of the
  !> node-to-segment pressures); asserts the ring-total resultant p pi.
  subroutine patch(failure, ta, na, tb, nb, method, mult, mu, spread)
    type(failure_t), allocatable, intent(inout) :: failure
    integer, intent(in) :: ta, na, tb, nb, method, mult
    real(wp), intent(in) :: mu
    real(wp), intent(out) :: spread
    real(wp), parameter :: e = 1000.0_wp, nu = 0.3_wp, rho = 1.0e-6_wp, p = 1.0_wp
    type(mesh_t) :: ma, mb, mesh
    type(scene_t) :: scene
    type(model_t) :: model
    type(contact_pair_t), allocatable :: pairs(:)
    type(time_plan_t) :: plan
    type(state_t) :: state
    type(error_t) :: err
    real(wp) :: omega1, bal_max, mean
    real(wp), allocatable :: val(:)
    spread = huge(1.0_wp)
    call rect_mesh(ma, ta, na, 2, 1.0_wp, 0.5_wp)
    call rect_mesh(mb, tb, nb, 2, 1.0_wp, 0.5_wp, y0=0.5_wp)
    omega1 = 0.5_wp*pi*sqrt(e/rho)
    call two_body_scene(ma, mb, mesh, scene, e, nu, rho, .false., 200.0_wp/omega1)
    scene%bodies(:)%axisymmetric = .true.
    scene%time%damping = 2.0_wp*omega1
    call add_bc(scene, 'a_bottom', BC_FIXED, comp=[.false., .true.])
    call add_bc(scene, 'b_top', BC_PRESSURE, pressure=p)
    call add_pair(scene, 'b_bottom', 'a_top', method, mu)
    scene%contacts(1)%multiplier = mult
    call prepare_contact(scene, mesh, model, pairs, plan, state, err)
    call check(failure, .not. err%failed(), 'setup failed')
    if (allocated(failure)) return
    bal_max = 0.0_wp
    do
      call contact_step(model, pairs, state, err)
      if (err%failed()) exit
      if (state%energy%scale > 0.0_wp) bal_max = max(bal_max, abs(state%energy%balance)/state%energy%scale)
      if (state%step == state%nsteps) exit
      call advance_state(state)
    end do
    call check(failure, .not. err%failed(), 'contact step failed')
    if (allocated(failure)) return
    if (method == METHOD_MORTAR) then
      val = pairs(1)%lam_n
    else
      val = pairs(1)%pressure
    end if
    ! node-to-segment with a quadratic slave edge: the axis node's ring area
    ! is zero, its pressure undefined (reported 0): left out
    if (method == METHOD_NTS .and. tb == ELEM_Q8) val = pack(val, model%x(1, pairs(1)%slave%node) > 0.0_wp)
    mean = sum(val)/size(val)
    spread = maxval(abs(val - mean))/p
    ! Every slave node is active, but for a quadratic (Q8) slave edge's node
    ! on the axis: its ring weight int psi r ds is zero (as is its share of
    ! a uniform load), so its constraint carries no force and stays open.
    call check(failure, all(pairs(1)%status /= ST_OPEN .or. (tb == ELEM_Q8 .and. &
      model%x(1, pairs(1)%slave%node) == 0.0_wp)), 'a slave node is open under uniform pressure')
    call check(failure, all(abs(pairs(1)%pressure - mean) < 1.0e-8_wp*p .or. method == METHOD_NTS), &
      'mortar pressure output is not the uniform multiplier (finite at the axis)')
    ! the resultant is the ring total p pi r^2
    call check_close(failure, pairs(1)%force(2), p*pi, 'contact resultant = applied load p pi', rel_tol=1.0e-8_wp)
    call check(failure, bal_max < 1.0e-10_wp, 'energy balance not exact: ' // str(bal_max))
  end subroutine patch

  subroutine trio(failure, ta, na, tb, nb, mu, label, nts_bound)
    type(failure_t), allocatable, intent(inout) :: failure
    integer, intent(in) :: ta, na, tb, nb
    real(wp), intent(in) :: mu, nts_bound
    character(len=*), intent(in) :: label
    real(wp) :: e1, e0, ents
    call patch(failure, ta, na, tb, nb, METHOD_MORTAR, MULT_P1, mu, e1)
    if (allocated(failure)) return
    call patch(failure, ta, na, tb, nb, METHOD_MORTAR, MULT_P0, mu, e0)
    if (allocated(failure)) return
    call patch(failure, ta, na, tb, nb, METHOD_NTS, MULT_P1, mu, ents)
    if (allocated(failure)) return
    write(*, '(a,a,a,es10.3,a,es10.3,a,es10.3)') '        ', label, ': max |lambda - mean|/p mortar P1 ', e1, &
      ', P0 ', e0, '; node-to-segment max |pressure - mean|/p ', ents
    call check(failure, e1 <= 1.0e-8_wp, label // ': mortar P1 multipliers not uniform')
    call check(failure, e0 <= 1.0e-8_wp, label // ': mortar P0 multipliers not uniform')
    call check(failure, ents <= nts_bound, label // ': node-to-segment error above its recorded bound')
  end subroutine trio

  subroutine test_patch_q4(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call trio(failure, ELEM_Q4, 5, ELEM_Q4, 7, 0.0_wp, 'Q4 slave 7, master 5', 0.5_wp)
  end subroutine test_patch_q4

  subroutine test_patch_q8(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call trio(failure, ELEM_Q4, 5, ELEM_Q8, 3, 0.0_wp, 'Q8 slave 3, Q4 master 5', 0.5_wp)
  end subroutine test_patch_q8

  !> A shaft (r < 0.5, z in [0, 2]) in a sleeve (0.5 < r < 1, z in [0.5,
  !> 1.5]) held axially at its ends; a pressure on the sleeve's outside
  !> squeezes it on the shaft, then the shaft's bottom is driven up. Once
  !> every contact node slips, the ring-total friction force is mu times the
  !> ring-total normal force (Coulomb), both matchings; the normal force is
  !> of the order of p times the sleeve's outer area.
  subroutine test_sleeve(failure)
    type(failure_t), allocatable, intent(out) :: failure
    integer :: method
    do method = METHOD_NTS, METHOD_MORTAR
      call sleeve_case(failure, method)
      if (allocated(failure)) return
    end do
  end subroutine test_sleeve

  subroutine sleeve_case(failure, method)
    type(failure_t), allocatable, intent(inout) :: failure
    integer, intent(in) :: method
    real(wp), parameter :: e = 1000.0_wp, nu = 0.3_wp, rho = 1.0e-6_wp, p = 1.0_wp, mu = 0.2_wp
    type(mesh_t) :: ma, mb, mesh
    type(scene_t) :: scene
    type(model_t) :: model
    type(contact_pair_t), allocatable :: pairs(:)
    type(time_plan_t) :: plan
    type(state_t) :: state
    type(error_t) :: err
    real(wp) :: omega1, t1
    call rect_mesh(ma, ELEM_Q4, 3, 12, 0.5_wp, 2.0_wp)
    call rect_mesh(mb, ELEM_Q4, 3, 7, 0.5_wp, 1.0_wp, x0=0.5_wp, y0=0.5_wp)
    omega1 = 0.5_wp*pi*sqrt(e/rho)/2.0_wp
    t1 = 40.0_wp/omega1
    call two_body_scene(ma, mb, mesh, scene, e, nu, rho, .false., 3.0_wp*t1)
    scene%bodies(:)%axisymmetric = .true.
    scene%time%damping = 2.0_wp*omega1
    call add_amplitude(scene, 'squeeze', [0.0_wp, 0.5_wp*t1], [0.0_wp, 1.0_wp])
    call add_amplitude(scene, 'pull', [0.0_wp, t1, 3.0_wp*t1], [0.0_wp, 0.0_wp, 1.0_wp])
    call add_bc(scene, 'b_bottom', BC_FIXED, comp=[.false., .true.])
    call add_bc(scene, 'b_top', BC_FIXED, comp=[.false., .true.])
    call add_bc(scene, 'b_right', BC_PRESSURE, pressure=p, amplitude='squeeze')
    call add_bc(scene, 'a_bottom', BC_DISPLACEMENT, comp=[.false., .true.], value=[0.0_wp, 2.0e-2_wp], &
      amplitude='pull')
    call add_pair(scene, 'b_left', 'a_right', method, mu)
    call prepare_contact(scene, mesh, model, pairs, plan, state, err)
    call check(failure, .not. err%failed(), 'setup failed')
    if (allocated(failure)) return
    do
      call contact_step(model, pairs, state, err)
      if (err%failed()) exit
      if (state%step == state%nsteps) exit
      call advance_state(state)
    end do
    call check(failure, .not. err%failed(), 'contact step failed')
    if (allocated(failure)) return
    associate (pair => pairs(1))
      write(*, '(a,i0,a,i0,a,i0,a,es12.5,a,es12.5,a,es10.3)') '        method ', method, ': ', pair%nslip, &
        ' of ', pair%nactive, ' active nodes slip; normal ', pair%normal_sum, ', friction ', pair%tangent_sum, &
        ', |T|/(mu N) - 1 ', abs(pair%tangent_sum)/(mu*pair%normal_sum) - 1.0_wp
      call check(failure, pair%nactive > 0 .and. pair%nslip == pair%nactive, 'not every active node slips')
      call check(failure, pair%normal_sum > 0.5_wp*p*2.0_wp*pi*1.0_wp*1.0_wp, 'normal force below p times the area')
      call check_close(failure, abs(pair%tangent_sum), mu*pair%normal_sum, 'friction force = mu N', rel_tol=1.0e-10_wp)
    end associate
  end subroutine sleeve_case

  !> Hertz (Johnson 1985; method brief 9.5) for two bodies of one material:
  !> 1/E* = 2 (1 - nu^2)/E, a = (3 P R/(4 E*))^(1/3), p0 = 3 P/(2 pi a^2)
  !> = (6 P E*^2/(pi^3 R^2))^(1/3).
  pure subroutine hertz_sphere(p_load, radius, young, nu, a, p0)
    real(wp), intent(in) :: p_load, radius, young, nu
    real(wp), intent(out) :: a, p0
    real(wp) :: e_star
    e_star = young/(2.0_wp*(1.0_wp - nu**2))
    a = (3.0_wp*p_load*radius/(4.0_wp*e_star))**(1.0_wp/3.0_wp)
    p0 = (6.0_wp*p_load*e_star**2/(pi**3*radius**2))**(1.0_wp/3.0_wp)
  end subroutine hertz_sphere

  !> Run one Hertz deck; the pressure profile along the block top, sorted by
  !> r: mortar's multiplier lam_n, node-to-segment's `pressure` (ring force
  !> over the ring area the node carries). Peak: the value at the axis;
  !> contact radius: the zero crossing of the piecewise-linear profile.
  subroutine hertz_case(failure, deck, mortar, h, study)
    type(failure_t), allocatable, intent(inout) :: failure
    character(len=*), intent(in) :: deck
    logical, intent(in) :: mortar
    real(wp), intent(in) :: h          !< slave element size at the contact
    logical, intent(in), optional :: study    !< print a table row of the mesh study
    type(scene_run_t), allocatable :: run
    type(error_t) :: err
    real(wp), allocatable :: r(:), pv(:)
    real(wp) :: p_load, a, p0, peak, radius, rms, t0, t1
    integer :: i, n, k, m
    allocate(run)
    call cpu_time(t0)
    call run_deck('tests/axisymmetric/data/' // deck, run, err)
    call cpu_time(t1)
    call check(failure, .not. err%failed(), deck // ': run failed')
    if (allocated(failure)) return
    associate (pair => run%pairs(1))
      n = pair%slave%nnode
      allocate(r(n), pv(n))
      do i = 1, n
        r(i) = run%model%x(1, pair%slave%node(i)) + run%state%u(1, pair%slave%node(i))
        pv(i) = merge(pair%lam_n(i), pair%pressure(i), mortar)
      end do
      call sort_pairs(r, pv)
      print '(a,*(f8.1))', '        p at the first slave nodes from the axis:', pv(1:6)
      p_load = abs(pair%force(2))
      call hertz_sphere(p_load, 10.0_wp, 200000.0_wp, 0.3_wp, a, p0)
      ! mortar: the multiplier at the axis; node-to-segment: the largest
      ! nodal pressure (its value at the axis, a point force over the small
      ! ring area h^2 pi/3, is noisy: printed)
      peak = merge(pv(1), maxval(pv), mortar)
      k = 1
      do while (k < n)
        if (pv(k + 1) <= 0.0_wp) exit
        k = k + 1
      end do
      radius = r(k)
      if (k < n) radius = r(k) + (r(k + 1) - r(k))*pv(k)/(pv(k) - pv(k + 1))
      write(*, '(a,f9.1,a,f7.2,a,f7.4,a,f7.2,a,f6.2,a,f7.3,a,es9.2)') '        ' // deck // ': P ', p_load, &
        ', peak ', 100.0_wp*(peak/p0 - 1.0_wp), ' % of p0; radius ', radius, ' (', &
        100.0_wp*(radius/a - 1.0_wp), ' % of a = ', a, '; h/a ', h/a, '), P / load - 1 ', p_load/15707.963_wp - 1.0_wp
      ! RMS of (p - p_Hertz)/p0 over the nodes with r < a
      rms = 0.0_wp
      m = 0
      do i = 1, n
        if (r(i) >= a) cycle
        rms = rms + (pv(i) - p0*sqrt(1.0_wp - (r(i)/a)**2))**2
        m = m + 1
      end do
      rms = sqrt(rms/real(max(m, 1), wp))/p0
      if (present(study)) write(*, '(a,f6.3,a,i6,a,i7,a,f7.2,a,f7.2,a,f7.2,a,f7.2,a,f8.1,a)') '| ' // deck // ' | ', &
        h/a, ' | ', run%model%nelem, ' | ', run%state%step, ' | ', 100.0_wp*rms, ' % | ', &
        100.0_wp*(pv(1)/p0 - 1.0_wp), ' % | ', 100.0_wp*(maxval(pv)/p0 - 1.0_wp), ' % | ', &
        100.0_wp*(radius/a - 1.0_wp), ' % | ', t1 - t0, ' |'
      if (present(study)) return
      call check(failure, pair%failed_total == 0, deck // ': unconverged multiplier steps')
      call check(failure, abs(radius - a) <= h, deck // ': contact radius off by more than one element')
      call check_close(failure, peak, p0, deck // ': peak pressure against p0', rel_tol=merge(0.03_wp, 0.05_wp, mortar))
      ! the measured force is the applied ring-total load at rest
      call check_close(failure, p_load, 50.0_wp*pi*100.0_wp, deck // ': contact force = load', rel_tol=1.0e-3_wp)
    end associate
  end subroutine hertz_case

  subroutine sort_pairs(x, y)
    real(wp), intent(inout) :: x(:), y(:)
    integer :: i, j
    real(wp) :: kx, ky
    do i = 2, size(x)
      kx = x(i)
      ky = y(i)
      j = i - 1
      do while (j >= 1)
        if (x(j) <= kx) exit
        x(j + 1) = x(j)
        y(j + 1) = y(j)
        j = j - 1
      end do
      x(j + 1) = kx
      y(j + 1) = ky
    end do
  end subroutine sort_pairs

  subroutine test_hertz(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call hertz_case(failure, 'hertz_axi_q4_mortar_p1.nml', .true., 0.1_wp)
    call hertz_case(failure, 'hertz_axi_q4_nts.nml', .false., 0.1_wp)
  end subroutine test_hertz

  subroutine test_hertz_p0(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call hertz_case(failure, 'hertz_axi_q4_mortar_p0.nml', .true., 0.1_wp)
  end subroutine test_hertz_p0

  subroutine test_hertz_q8(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call hertz_case(failure, 'hertz_axi_q8_mortar_p1.nml', .true., 0.1_wp)
  end subroutine test_hertz_q8

  !> The mesh study of doc/accuracy-cost.md section 14: Q4, slave = block
  !> top, three interface spacings (h/a 0.2, 0.1, 0.05), mortar P1 and
  !> node-to-segment; prints table rows (error of the pressure profile,
  !> RMS over r < a, at the axis, of the largest nodal value, of the
  !> contact radius; CPU seconds). Measures only.
  subroutine test_study(failure)
    type(failure_t), allocatable, intent(out) :: failure
    write(*, '(a)') '| deck | h/a | nelem | steps | err_rms | err_axis | err_max | err_radius | cpu_s |'
    write(*, '(a)') '|---|---|---|---|---|---|---|---|---|'
    call hertz_case(failure, 'hertz_axi_q4_L1_mortar_p1.nml', .true., 0.2_wp, .true.)
    call hertz_case(failure, 'hertz_axi_q4_L1_nts.nml', .false., 0.2_wp, .true.)
    call hertz_case(failure, 'hertz_axi_q4_mortar_p1.nml', .true., 0.1_wp, .true.)
    call hertz_case(failure, 'hertz_axi_q4_nts.nml', .false., 0.1_wp, .true.)
    call hertz_case(failure, 'hertz_axi_q4_L3_mortar_p1.nml', .true., 0.05_wp, .true.)
    call hertz_case(failure, 'hertz_axi_q4_L3_nts.nml', .false., 0.05_wp, .true.)
  end subroutine test_study
end program test_axi_contact
