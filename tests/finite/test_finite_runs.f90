!> Finite-strain runs through the whole explicit loop (tests/finite/data):
!> homogeneous confined compression and stretch against the closed forms
!> in the static limit, the stored energy, the energy balance falling as
!> dt^2, the step following the deforming mesh, and an inverted element
!> stopping the run.
program test_finite_runs
  use raccord_kinds, only: wp
  use raccord_error, only: error_t, EXIT_NUMERIC
  use raccord_material, only: moduli_t, make_moduli
  use raccord_elastic_block, only: add_nodal_stress
  use raccord_scene_runner, only: scene_run_t, run_deck, prepare_deck, step_predict, step_finish
  use raccord_central_difference, only: advance_state
  use raccord_check, only: failure_t, new_test, run_tests, check, check_close
  use raccord_strings, only: str
  implicit none

  real(wp), parameter :: young = 7000.0_wp, nu = 0.3_wp

  call run_tests('finite_runs', [ &
    new_test('neo-Hooke Q4 confined compression to 50 %', test_neo_q4_compression), &
    new_test('neo-Hooke Q8 confined stretch to 200 %', test_neo_q8_stretch), &
    new_test('SVK Q4 confined stretch to 200 %', test_svk_q4_stretch), &
    new_test('SVK Q8 confined compression by 20 %', test_svk_q8_compression), &
    new_test('energy balance error falls as dt^2', test_balance_order), &
    new_test('inverted element stops the run (exit 3)', test_inversion), &
    new_test('a spinning body keeps its energy and no spurious stress', test_spin)])

contains

  !> A copy of data/confined.nml with the material, mesh and stretch l
  !> (top displacement l - 1), written where the test runs; extra lines
  !> replace the &time group when given.
  function write_deck(name, material, mesh, l, time_group) result(path)
    character(len=*), intent(in) :: name, material, mesh
    real(wp), intent(in) :: l
    character(len=*), intent(in), optional :: time_group
    character(len=:), allocatable :: path
    character(len=512) :: root
    character(len=32) :: val
    integer :: u, length, stat
    call get_environment_variable('RACCORD_SOURCE_DIR', root, length, stat)
    path = './' // name // '.nml'
    write(val, '(es23.15)') l - 1.0_wp
    open(newunit=u, file=path, status='replace', action='write')
    write(u, '(a)') '&mesh file = ''' // trim(root) // '/tests/finite/data/' // mesh // ''' /'
    write(u, '(a)') '&body name = ''block'', young = 7000.0, poisson = 0.3, density = 1.0e-9,'
    write(u, '(a)') '  kinematics = ''finite'', material = ''' // material // ''' /'
    write(u, '(a)') '&amplitude name = ''ramp'', time = 0.0, 1.0e-4, value = 0.0, 1.0 /'
    write(u, '(a)') '&boundary set = ''bottom'', type = ''fixed'', components = ''y'' /'
    write(u, '(a)') '&boundary set = ''left'', type = ''fixed'', components = ''x'' /'
    write(u, '(a)') '&boundary set = ''right'', type = ''fixed'', components = ''x'' /'
    write(u, '(a)') '&boundary set = ''top'', type = ''displacement'', components = ''y'', value = 0.0, ' // &
      trim(adjustl(val)) // ', amplitude = ''ramp'' /'
    if (present(time_group)) then
      write(u, '(a)') time_group
    else
      write(u, '(a)') '&time t_end = 2.5e-4, damping = 1.0e6 /'
    end if
    close(u)
  end function write_deck

  !> Confined closed forms (method brief 3.3), F = diag(1, l): Cauchy
  !> (sxx, syy, sxy, szz) and the stored energy per unit volume.
  subroutine confined(material, l, s, w)
    character(len=*), intent(in) :: material
    real(wp), intent(in) :: l
    real(wp), intent(out) :: s(4), w
    type(moduli_t) :: m
    real(wp) :: e
    m = make_moduli(young, nu)
    if (material == 'neo_hooke') then
      s(2) = 2.0_wp*m%g/3.0_wp*l**(-5.0_wp/3.0_wp)*(l*l - 1.0_wp) + m%k*(l - 1.0_wp)
      s(1) = m%g/3.0_wp*l**(-5.0_wp/3.0_wp)*(1.0_wp - l*l) + m%k*(l - 1.0_wp)
      w = 0.5_wp*m%g*(l**(-2.0_wp/3.0_wp)*(2.0_wp + l*l) - 3.0_wp) + 0.5_wp*m%k*(l - 1.0_wp)**2
    else
      s(2) = (m%lam + 2.0_wp*m%g)*l*(l*l - 1.0_wp)/2.0_wp
      s(1) = m%lam*(l*l - 1.0_wp)/(2.0_wp*l)
      e = 0.5_wp*(l*l - 1.0_wp)
      w = 0.5_wp*(m%lam + 2.0_wp*m%g)*e*e
    end if
    s(3) = 0.0_wp
    s(4) = s(1)
  end subroutine confined

  !> Run the confined deck and compare every nodal stress and the stored
  !> energy with the closed form (static limit: damped hold after the ramp).
  subroutine check_confined(failure, name, material, mesh, l)
    type(failure_t), allocatable, intent(inout) :: failure
    character(len=*), intent(in) :: name, material, mesh
    real(wp), intent(in) :: l
    type(scene_run_t), allocatable :: run
    type(error_t) :: err
    real(wp), allocatable :: s(:,:), wsum(:)
    real(wp) :: expect(4), w, worst
    integer :: k, n
    allocate(run)
    call run_deck(write_deck(name, material, mesh, l), run, err)
    call check(failure, .not. err%failed(), name // ': ' // err%message)
    if (allocated(failure)) return
    call confined(material, l, expect, w)
    allocate(s(4, run%model%nnode), wsum(run%model%nnode), source=0.0_wp)
    do k = 1, size(run%model%bodies(1)%blocks)
      call add_nodal_stress(run%model%bodies(1)%blocks(k), run%state%u, s, wsum)
    end do
    worst = 0.0_wp
    do n = 1, run%model%nnode
      if (wsum(n) > 0.0_wp) worst = max(worst, maxval(abs(s(:, n)/wsum(n) - expect)))
    end do
    print '(a)', '  ' // name // ': largest nodal stress error ' // str(worst/abs(expect(2)), 3) // &
      ' of |sigma_yy| = ' // str(abs(expect(2)), 6) // '; stored energy ' // str(run%state%energy%internal, 8) // &
      ' (closed form ' // str(w, 8) // '); ' // str(run%state%step) // ' steps, last dt / planned dt ' // &
      str(run%state%dt/run%plan%dt, 3)
    ! Method brief 5.2: compressed to l = 0.5 the true stable step is 0.605
    ! of the undeformed one (the wave modulus grows faster than the length
    ! shrinks); stretched to 2 it is 0.576. The step must have followed.
    if (abs(l - 1.0_wp) >= 0.5_wp) call check(failure, run%state%dt < 0.65_wp*run%plan%dt, name // &
      ': the step did not follow the deforming mesh, dt / planned = ' // str(run%state%dt/run%plan%dt))
    call check(failure, worst < 1.0e-6_wp*abs(expect(2)), name // ': nodal stress off by ' // str(worst))
    call check_close(failure, run%state%energy%internal, w, name // ': stored energy', rel_tol=1.0e-6_wp)
    call check(failure, run%worst_balance < 1.0e-3_wp, name // ': energy balance ' // str(run%worst_balance))
  end subroutine check_confined

  subroutine test_neo_q4_compression(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call check_confined(failure, 'neo_q4_l050', 'neo_hooke', 'block.msh', 0.5_wp)
  end subroutine test_neo_q4_compression

  subroutine test_neo_q8_stretch(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call check_confined(failure, 'neo_q8_l200', 'neo_hooke', 'block_q8.msh', 2.0_wp)
  end subroutine test_neo_q8_stretch

  subroutine test_svk_q4_stretch(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call check_confined(failure, 'svk_q4_l200', 'svk', 'block.msh', 2.0_wp)
  end subroutine test_svk_q4_stretch

  subroutine test_svk_q8_compression(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call check_confined(failure, 'svk_q8_l080', 'svk', 'block_q8.msh', 0.8_wp)
  end subroutine test_svk_q8_compression

  !> Undamped, fast compression to l = 0.6 (dynamic; the step shrinks as
  !> the layer stiffens): the worst balance error over the run falls about
  !> 4x when the safety factor (so dt) is halved (doc/theory-finite.md).
  subroutine test_balance_order(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(scene_run_t), allocatable :: run
    type(error_t) :: err
    real(wp) :: e(2)
    integer :: k
    character(len=*), parameter :: groups(2) = [character(len=40) :: &
      '&time t_end = 2.0e-5, safety = 0.8 /', '&time t_end = 2.0e-5, safety = 0.4 /']
    do k = 1, 2
      allocate(run)
      call run_deck(write_deck('dyn' // str(k), 'neo_hooke', 'block.msh', 0.6_wp, trim(groups(k))), run, err)
      call check(failure, .not. err%failed(), 'run ' // str(k) // ': ' // err%message)
      if (allocated(failure)) return
      e(k) = run%worst_balance
      deallocate(run)
    end do
    print '(a)', '  worst balance error ' // str(e(1), 3) // ' (safety 0.8), ' // str(e(2), 3) // &
      ' (safety 0.4): ratio ' // str(e(1)/e(2), 3)
    call check(failure, e(1)/e(2) > 3.0_wp .and. e(1)/e(2) < 5.5_wp, 'balance error ratio ' // str(e(1)/e(2)))
    call check(failure, e(1) < 1.0e-3_wp, 'balance error ' // str(e(1)))
  end subroutine test_balance_order

  !> Driving the top through the bottom inverts the elements: exit 3,
  !> naming the element and the body.
  subroutine test_inversion(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(scene_run_t), allocatable :: run
    type(error_t) :: err
    allocate(run)
    call run_deck(write_deck('invert', 'neo_hooke', 'block.msh', -0.2_wp), run, err)
    call check(failure, err%failed(), 'the run went through an inverted mesh')
    if (allocated(failure)) return
    call check(failure, err%code == EXIT_NUMERIC, 'exit code ' // str(err%code))
    call check(failure, (index(err%message, 'inverted') > 0 .or. index(err%message, 'collapsing') > 0) .and. &
      index(err%message, 'element ') > 0 .and. index(err%message, 'body ''block''') > 0 .and. &
      index(err%message, 't = ') > 0, 'message: ' // err%message)
    print '(a)', '  ' // err%message
  end subroutine test_inversion

  !> A free unit block spinning at omega about its centre for a quarter
  !> turn (Q4 mean dilatation and Q8): it turns as a rigid body, its stress
  !> stays at the level of the centrifugal one, rho omega^2 R^2 (1e-5 of E
  !> here), and kinetic + stored energy stay constant. A small-strain body
  !> would carry a stress of the order of E after 90 degrees.
  subroutine test_spin(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call spin(failure, 'block.msh')
    if (allocated(failure)) return
    call spin(failure, 'block_q8.msh')
  end subroutine test_spin

  subroutine spin(failure, mesh_file)
    type(failure_t), allocatable, intent(inout) :: failure
    character(len=*), intent(in) :: mesh_file
    type(scene_run_t), allocatable :: run
    type(error_t) :: err
    character(len=512) :: root
    real(wp), allocatable :: s(:,:), wsum(:), r0(:,:)
    real(wp), parameter :: rho = 1.0e-9_wp, pi = acos(-1.0_wp)
    real(wp) :: omega, e0, worst_e, smax, scent, pos_err, turned(2)
    integer :: u, length, stat, i, k
    call get_environment_variable('RACCORD_SOURCE_DIR', root, length, stat)
    ! rho omega^2 R^2 = 1e-5 E with R^2 = 1/2 (the corner's distance to the centre)
    omega = sqrt(1.0e-5_wp*young/(rho*0.5_wp))
    open(newunit=u, file='spin.nml', status='replace', action='write')
    write(u, '(a)') '&mesh file = ''' // trim(root) // '/tests/finite/data/' // mesh_file // ''' /'
    write(u, '(a)') '&body name = ''block'', young = 7000.0, poisson = 0.3, density = 1.0e-9,'
    write(u, '(a)') '  kinematics = ''finite'', material = ''neo_hooke'' /'
    write(u, '(a, es23.15, a)') '&time t_end = ', 0.5_wp*pi/omega, ' /'
    close(u)
    allocate(run)
    call prepare_deck('./spin.nml', run, err)
    if (err%failed()) call check(failure, .false., 'set-up: ' // err%message)
    if (allocated(failure)) return
    associate (model => run%model, state => run%state)
      ! rigid spin about (0.5, 0.5): v = omega e_z x (X - c)
      allocate(r0(2, model%nnode))
      r0(1, :) = model%x(1, :) - 0.5_wp
      r0(2, :) = model%x(2, :) - 0.5_wp
      model%v0(1, :) = -omega*r0(2, :)
      model%v0(2, :) = omega*r0(1, :)
      state%v = model%v0
      state%v_mid = model%v0
      e0 = 0.0_wp
      worst_e = 0.0_wp
      do
        call step_predict(run, err)
        if (.not. err%failed()) call step_finish(run, err)
        if (err%failed()) call check(failure, .false., err%message)
        if (allocated(failure)) return
        if (state%step == 0) e0 = state%energy%kinetic
        worst_e = max(worst_e, abs(state%energy%kinetic + state%energy%internal - e0))
        if (state%step == state%nsteps) exit
        call advance_state(state)
      end do
    end associate
    ! after a quarter turn every node is where the turned body puts it
    pos_err = 0.0_wp
    do i = 1, run%model%nnode
      turned = [0.5_wp - r0(2, i), 0.5_wp + r0(1, i)]
      pos_err = max(pos_err, norm2(run%model%x(:, i) + run%state%u(:, i) - turned))
    end do
    allocate(s(4, run%model%nnode), wsum(run%model%nnode), source=0.0_wp)
    do k = 1, size(run%model%bodies(1)%blocks)
      call add_nodal_stress(run%model%bodies(1)%blocks(k), run%state%u, s, wsum)
    end do
    smax = 0.0_wp
    do i = 1, run%model%nnode
      if (wsum(i) > 0.0_wp) smax = max(smax, maxval(abs(s(:, i)/wsum(i))))
    end do
    scent = rho*omega**2*0.5_wp
    print '(a)', '  ' // mesh_file // ': quarter turn in ' // str(run%state%step) // ' steps; largest stress ' // &
      str(smax/scent, 3) // ' x rho omega^2 R^2 (' // str(smax/young, 3) // ' of E); kinetic + stored energy ' // &
      'drift ' // str(worst_e/e0, 3) // ' of the kinetic; position off the rigid turn by ' // str(pos_err, 3)
    call check(failure, smax < 3.0_wp*scent, mesh_file // ': stress ' // str(smax) // ' beyond the centrifugal ' // &
      'level ' // str(scent))
    call check(failure, worst_e < 1.0e-4_wp*e0, mesh_file // ': energy drifts by ' // str(worst_e/e0) // ' of e0')
    call check(failure, pos_err < 1.0e-3_wp, mesh_file // ': the body did not turn rigidly: ' // str(pos_err))
  end subroutine spin
end program test_finite_runs
