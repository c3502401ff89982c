!> Contact between finite-strain bodies (issue: contact under large
!> deformation; doc/verification.md, "Finite strain"):
!>  - a neo-Hooke slider pressed onto a neo-Hooke base in stick (mu = 0.5),
!>    then the whole pair turned rigidly by 90 degrees through its clamped
!>    edges: no slip, no frictional dissipation to speak of, the contact
!>    force turns with the bodies and the final state is the pressed state
!>    turned (both matchings);
!>  - the small-strain limit: the same press with finite and with small
!>    strain differs by the order of the strain, and the difference scales
!>    with the load.
program test_finite_contact
  use raccord_kinds, only: wp
  use raccord_error, only: error_t
  use raccord_central_difference, only: advance_state
  use raccord_scene_runner, only: scene_run_t, run_deck, prepare_deck, step_predict, step_finish
  use raccord_check, only: failure_t, new_test, run_tests, check
  use raccord_strings, only: str
  implicit none

  real(wp), parameter :: pi = acos(-1.0_wp)
  real(wp), parameter :: delta = 0.004_wp             !< press of the slider top (mm)
  real(wp), parameter :: t_press = 2.0e-5_wp, t_turn0 = 3.0e-5_wp, t_turn1 = 8.0e-5_wp

  call run_tests('finite_contact', [ &
    new_test('stick under a 90 degree rigid turn, mortar', test_turn_mortar), &
    new_test('stick under a 90 degree rigid turn, node-to-segment', test_turn_nts), &
    new_test('small-strain limit of a press', test_small_limit), &
    new_test('dragged over many master segments, mortar', test_drag_mortar), &
    new_test('dragged over many master segments, node-to-segment', test_drag_nts), &
    new_test('high-speed impact of a neo-Hooke block', test_impact)])

contains

  !> The slide deck of input/verification/sliding with both bodies finite
  !> strain neo-Hooke, both clamped edges held (the test drives them).
  function turn_deck(method, material) result(path)
    character(len=*), intent(in) :: method, material
    character(len=:), allocatable :: path
    character(len=512) :: root
    integer :: u, length, stat
    call get_environment_variable('RACCORD_SOURCE_DIR', root, length, stat)
    path = './turn_' // method // '.nml'
    open(newunit=u, file=path, status='replace', action='write')
    write(u, '(a)') '&mesh file = ''' // trim(root) // '/input/verification/sliding/sliding_q4.msh'' /'
    write(u, '(a)') '&body name = ''base'', elset = ''base'', young = 20000.0, poisson = 0.3, density = 1.0e-9,'
    write(u, '(a)') '  kinematics = ''finite'', material = ''' // material // ''' /'
    write(u, '(a)') '&body name = ''slider'', elset = ''slider'', young = 20000.0, poisson = 0.3, density = 1.0e-9,'
    write(u, '(a)') '  kinematics = ''finite'', material = ''' // material // ''' /'
    write(u, '(a)') '&boundary set = ''base_bottom'', type = ''fixed'', components = ''xy'' /'
    write(u, '(a)') '&boundary set = ''slider_top'', type = ''fixed'', components = ''xy'' /'
    write(u, '(a)') '&time t_end = 1.3e-4, damping = 3.0e5 /'
    write(u, '(a)') '&contact_pair slave = ''slider_bottom'', master = ''base_top'', friction = 0.5,'
    write(u, '(a)') '  method = ''' // method // ''' /'
    close(u)
  end function turn_deck

  !> Turn angle at t: 0 before t_turn0, 90 degrees after t_turn1, a
  !> smooth (1 - cos)/2 profile between.
  pure real(wp) function angle(t)
    real(wp), intent(in) :: t
    real(wp) :: s
    s = min(1.0_wp, max(0.0_wp, (t - t_turn0)/(t_turn1 - t_turn0)))
    angle = 0.25_wp*pi*(1.0_wp - cos(pi*s))
  end function angle

  !> Position the test prescribes at t for a clamped node at X: the slider
  !> top pressed down by delta (ramped over t_press), then everything turned
  !> about the origin (the middle of the interface).
  pure function prescribed(x, top, t) result(p)
    real(wp), intent(in) :: x(2), t
    logical, intent(in) :: top
    real(wp) :: p(2), q(2), th
    q = x
    if (top) q(2) = q(2) - delta*min(1.0_wp, t/t_press)
    th = angle(t)
    p = [cos(th)*q(1) - sin(th)*q(2), sin(th)*q(1) + cos(th)*q(2)]
  end function prescribed

  !> The time loop of the program, with the clamped edges driven by the
  !> test: after the predictor, the constrained dofs are set to the
  !> prescribed positions at t(n+1) (v consistent), before contact.
  subroutine run_turn(method, failure, u_press, u_end, f_press, f_end, friction, stored, steps)
    character(len=*), intent(in) :: method
    type(failure_t), allocatable, intent(inout) :: failure
    real(wp), allocatable, intent(out) :: u_press(:,:), u_end(:,:)
    real(wp), intent(out) :: f_press(2), f_end(2), friction, stored
    integer, intent(out) :: steps
    type(scene_run_t), allocatable :: run
    type(error_t) :: err
    integer :: j, i, c, top_support
    real(wp) :: tn, p(2)
    allocate(run)
    call prepare_deck(turn_deck(method, 'neo_hooke'), run, err)
    if (err%failed()) call check(failure, .false., 'set-up: ' // err%message)
    if (allocated(failure)) return
    top_support = 0
    do j = 1, size(run%model%supports)
      if (run%model%supports(j)%set == 'slider_top') top_support = j
    end do
    associate (model => run%model, state => run%state, pairs => run%pairs)
      do
        call step_predict(run, err)
        if (err%failed()) call check(failure, .false., err%message)
        if (allocated(failure)) return
        ! the clamped edges go where the test drives them at t(n+1)
        tn = state%time + state%dt
        do j = 1, model%ncdof
          i = model%cdof_node(j)
          c = model%cdof_comp(j)
          p = prescribed(model%x(:, i), model%cdof_support(j) == top_support, tn)
          state%u_next(c, i) = p(c) - model%x(c, i)
          state%v(c, i) = (state%u_next(c, i) - state%u(c, i))/state%dt
        end do
        call step_finish(run, err)
        if (err%failed()) call check(failure, .false., 'contact: ' // err%message)
        if (allocated(failure)) return
        if (state%time <= t_turn0 .and. state%time + state%dt > t_turn0) then
          u_press = state%u
          f_press = pairs(1)%force
          stored = state%energy%internal
        end if
        if (state%step == state%nsteps) exit
        call advance_state(state)
      end do
      u_end = state%u
      f_end = pairs(1)%force
      friction = state%energy%friction
      steps = int(state%step)
      ! the pressed state turned by 90 degrees, as displacements
      do i = 1, model%nnode
        p = model%x(:, i) + u_press(:, i)
        u_press(:, i) = [-p(2), p(1)] - model%x(:, i)
      end do
    end associate
  end subroutine run_turn

  subroutine check_turn(method, failure)
    character(len=*), intent(in) :: method
    type(failure_t), allocatable, intent(inout) :: failure
    real(wp), allocatable :: u_turned(:,:), u_end(:,:)
    real(wp) :: f_press(2), f_end(2), friction, stored, diff, fturn(2)
    integer :: steps
    call run_turn(method, failure, u_turned, u_end, f_press, f_end, friction, stored, steps)
    if (allocated(failure)) return
    diff = maxval(abs(u_end - u_turned))
    fturn = [-f_press(2), f_press(1)]
    print '(a)', '  ' // method // ': pressed contact force (' // str(f_press(1), 4) // ', ' // str(f_press(2), 4) // &
      '), after the turn (' // str(f_end(1), 4) // ', ' // str(f_end(2), 4) // '); final state - turned ' // &
      'pressed state: ' // str(diff/delta, 3) // ' of the press; friction work ' // str(friction, 3) // &
      ' against ' // str(stored, 3) // ' of energy stored by the press; ' // str(steps) // ' steps'
    call check(failure, norm2(f_press) > 10.0_wp, method // ': no contact force after the press')
    call check(failure, norm2(f_end - fturn) < 1.0e-3_wp*norm2(f_press), method // &
      ': the contact force did not turn with the bodies')
    call check(failure, diff < 1.0e-3_wp*delta, method // ': the final state differs from the turned pressed ' // &
      'state by ' // str(diff) // ' (stick crept)')
    call check(failure, abs(friction) < 1.0e-6_wp*stored, method // ': friction dissipated ' // &
      str(friction) // ' in stick')
  end subroutine check_turn

  subroutine test_turn_mortar(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call check_turn('mortar', failure)
  end subroutine test_turn_mortar

  subroutine test_turn_nts(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call check_turn('node_to_segment', failure)
  end subroutine test_turn_nts

  !> The slider pressed by a pressure p onto the base (mortar, frictionless)
  !> with finite and with small strain: the relative difference of the
  !> slider's settlement is of the order of the strain, and falls at least
  !> 5x when the load falls 10x (it falls 37x: the pressure on the slider's
  !> top follows the surface, and the first-order terms nearly cancel; with
  !> the pressure held on the undeformed top it fell 16x).
  subroutine test_small_limit(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp) :: d(2), strain(2)
    integer :: k
    real(wp), parameter :: loads(2) = [200.0_wp, 20.0_wp]
    do k = 1, 2
      d(k) = relative_difference(loads(k), strain(k), failure)
      if (allocated(failure)) return
      print '(a)', '  pressure ' // str(loads(k), 3) // ': strain ' // str(strain(k), 3) // &
        ', finite vs small settlement differs by ' // str(d(k), 3)
    end do
    call check(failure, d(1) < 3.0_wp*strain(1), 'difference ' // str(d(1)) // ' not of the order of the strain ' // &
      str(strain(1)))
    call check(failure, d(2) < 0.2_wp*d(1), 'difference does not fall with the load: ' // &
      str(d(1)) // ', ' // str(d(2)))
  end subroutine test_small_limit

  !> |settlement(finite) - settlement(small)| / settlement(small) of the
  !> slider top's middle under pressure p; strain = settlement / height.
  real(wp) function relative_difference(p, strain, failure) result(d)
    real(wp), intent(in) :: p
    real(wp), intent(out) :: strain
    type(failure_t), allocatable, intent(inout) :: failure
    type(scene_run_t), allocatable :: run
    type(error_t) :: err
    real(wp) :: s(2)
    integer :: k, n, u
    character(len=512) :: root
    character(len=32) :: pv
    integer :: length, stat
    call get_environment_variable('RACCORD_SOURCE_DIR', root, length, stat)
    write(pv, '(es12.5)') p
    d = 0.0_wp
    strain = 0.0_wp
    do k = 1, 2
      open(newunit=u, file='press.nml', status='replace', action='write')
      write(u, '(a)') '&mesh file = ''' // trim(root) // '/input/verification/sliding/sliding_q4.msh'' /'
      write(u, '(a)') '&body name = ''base'', elset = ''base'', young = 20000.0, poisson = 0.3, density = 1.0e-9 /'
      if (k == 1) then
        write(u, '(a)') '&body name = ''slider'', elset = ''slider'', young = 20000.0, poisson = 0.3, ' // &
          'density = 1.0e-9, kinematics = ''finite'', material = ''neo_hooke'' /'
      else
        write(u, '(a)') '&body name = ''slider'', elset = ''slider'', young = 20000.0, poisson = 0.3, density = 1.0e-9 /'
      end if
      write(u, '(a)') '&amplitude name = ''press'', time = 0.0, 2.0e-5, value = 0.0, 1.0 /'
      write(u, '(a)') '&boundary set = ''base_bottom'', type = ''fixed'', components = ''xy'' /'
      write(u, '(a)') '&boundary set = ''slider_top'', type = ''pressure'', pressure = ' // trim(pv) // &
        ', amplitude = ''press'' /'
      write(u, '(a)') '&time t_end = 6.0e-5, damping = 1.0e6 /'
      write(u, '(a)') '&contact_pair slave = ''slider_bottom'', master = ''base_top'', method = ''mortar'' /'
      close(u)
      allocate(run)
      call run_deck('./press.nml', run, err)
      if (err%failed()) call check(failure, .false., 'press run: ' // err%message)
      if (allocated(failure)) return
      n = minloc(run%model%x(1, :)**2 + (run%model%x(2, :) - 0.5_wp)**2, 1)
      s(k) = -run%state%u(2, n)
      deallocate(run)
    end do
    d = abs(s(1) - s(2))/abs(s(2))
    strain = s(2)/0.5_wp
  end function relative_difference

  !> A soft neo-Hooke slider (finite strain) pressed onto a steel base
  !> (small strain) by its top, then dragged 1.5 mm along it, across 30 of
  !> the base's 0.05 mm segments, mu = 0.3. Returns the mean and the largest
  !> |T|/N over the sliding window, the worst energy balance and the
  !> slider's travel. (The soft slider stick-slips: 1 to 6 of its 14 contact
  !> nodes stick at any time and the mean |T|/N is about 0.2, with small
  !> strain as with finite strain; doc/verification.md, "Finite strain".)
  subroutine run_drag(method, failure, ratio_mean, ratio_max, balance, travel)
    character(len=*), intent(in) :: method
    type(failure_t), allocatable, intent(inout) :: failure
    real(wp), intent(out) :: ratio_mean, ratio_max, balance, travel
    type(scene_run_t), allocatable :: run
    type(error_t) :: err
    character(len=512) :: root
    character(len=:), allocatable :: path
    real(wp) :: r, rmax, rsum
    integer :: u, length, stat, nsample, n
    call get_environment_variable('RACCORD_SOURCE_DIR', root, length, stat)
    path = './drag_' // method // '.nml'
    open(newunit=u, file=path, status='replace', action='write')
    write(u, '(a)') '&mesh file = ''' // trim(root) // '/input/verification/sliding/sliding_q4.msh'' /'
    write(u, '(a)') '&body name = ''base'', elset = ''base'', young = 200000.0, poisson = 0.3, density = 7.8e-9 /'
    write(u, '(a)') '&body name = ''slider'', elset = ''slider'', young = 2000.0, poisson = 0.45, density = 1.0e-9,'
    write(u, '(a)') '  kinematics = ''finite'', material = ''neo_hooke'', damping = 3.0e6 /'
    write(u, '(a)') '&amplitude name = ''press'', time = 0.0, 2.0e-5, value = 0.0, 1.0 /'
    write(u, '(a)') '&amplitude name = ''drag'', time = 3.0e-5, 1.5e-4, value = 0.0, 1.0 /'
    write(u, '(a)') '&boundary set = ''base_bottom'', type = ''fixed'', components = ''xy'' /'
    write(u, '(a)') '&boundary set = ''slider_top'', type = ''displacement'', components = ''y'', ' // &
      'value = 0.0, -0.02, amplitude = ''press'' /'
    write(u, '(a)') '&boundary set = ''slider_top'', type = ''displacement'', components = ''x'', ' // &
      'value = 1.5, 0.0, amplitude = ''drag'' /'
    write(u, '(a)') '&time t_end = 1.6e-4 /'
    write(u, '(a)') '&contact_pair slave = ''slider_bottom'', master = ''base_top'', friction = 0.3,'
    write(u, '(a)') '  method = ''' // method // ''' /'
    close(u)
    allocate(run)
    call prepare_deck(path, run, err)
    if (err%failed()) call check(failure, .false., 'set-up: ' // err%message)
    if (allocated(failure)) return
    rmax = -huge(1.0_wp)
    rsum = 0.0_wp
    nsample = 0
    associate (model => run%model, state => run%state, pairs => run%pairs)
      do
        call step_predict(run, err)
        if (.not. err%failed()) call step_finish(run, err)
        if (err%failed()) call check(failure, .false., err%message)
        if (allocated(failure)) return
        ! steady sliding: the drag velocity is constant on [3e-5, 1.5e-4]
        if (state%time > 5.0e-5_wp .and. state%time < 1.45e-4_wp) then
          r = abs(pairs(1)%tangent_sum)/max(abs(pairs(1)%normal_sum), tiny(1.0_wp))
          rmax = max(rmax, r)
          rsum = rsum + r
          nsample = nsample + 1
        end if
        if (state%step == state%nsteps) exit
        call advance_state(state)
      end do
      ratio_mean = rsum/real(max(nsample, 1), wp)
      ratio_max = rmax
      balance = run%worst_balance
      n = minloc(model%x(1, :)**2 + model%x(2, :)**2 + merge(0.0_wp, 1.0e9_wp, model%node_body == 2), 1)
      travel = state%u(1, n)
    end associate
  end subroutine run_drag

  !> What holds while the soft slider is dragged: it travels the whole way
  !> (across 30 master segments), the Coulomb bound |T| <= mu N is never
  !> exceeded, friction carries a good part of mu N on average, and the
  !> energy balance stays small.
  subroutine check_drag(method, failure)
    character(len=*), intent(in) :: method
    type(failure_t), allocatable, intent(inout) :: failure
    real(wp) :: ratio_mean, ratio_max, balance, travel
    call run_drag(method, failure, ratio_mean, ratio_max, balance, travel)
    if (allocated(failure)) return
    print '(a)', '  ' // method // ': sliding |T|/N mean ' // str(ratio_mean, 4) // ', largest ' // &
      str(ratio_max, 8) // ' (mu = 0.3); slider travel ' // str(travel, 4) // ' mm; worst energy balance ' // &
      str(balance, 3)
    call check(failure, travel > 1.4_wp, method // ': the slider travelled ' // str(travel) // ' mm only')
    call check(failure, ratio_max <= 0.3_wp*(1.0_wp + 1.0e-9_wp), method // ': |T|/N reached ' // str(ratio_max))
    call check(failure, ratio_mean > 0.15_wp, method // ': mean |T|/N ' // str(ratio_mean))
    call check(failure, balance < 1.0e-2_wp, method // ': energy balance ' // str(balance))
  end subroutine check_drag

  subroutine test_drag_mortar(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call check_drag('mortar', failure)
  end subroutine test_drag_mortar

  subroutine test_drag_nts(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call check_drag('node_to_segment', failure)
  end subroutine test_drag_nts

  !> A neo-Hooke block (E 2000, nu 0.45) hitting a steel base at 0.1 and
  !> 0.3 of its wave speed (nominal strains of 10 % and 30 %), both
  !> matchings: the run completes, no energy comes from the contact
  !> (contact work >= -1e-6 of the initial kinetic energy), the balance
  !> stays small, the block bounces off (upward momentum at the end) and
  !> kinetic + stored energy never exceed the initial kinetic energy.
  subroutine test_impact(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(scene_run_t), allocatable :: run
    type(error_t) :: err
    character(len=512) :: root
    character(len=32) :: vtext
    character(len=16), parameter :: methods(2) = [character(len=16) :: 'mortar', 'node_to_segment']
    real(wp), parameter :: c = 2.75e6_wp
    real(wp) :: v, e0, vy
    integer :: u, length, stat, k, im, n
    call get_environment_variable('RACCORD_SOURCE_DIR', root, length, stat)
    do im = 1, 2
      do k = 1, 2
        v = merge(0.1_wp, 0.3_wp, k == 1)*c
        write(vtext, '(es12.5)') -v
        open(newunit=u, file='impact.nml', status='replace', action='write')
        write(u, '(a)') '&mesh file = ''' // trim(root) // '/input/verification/sliding/sliding_q4.msh'' /'
        write(u, '(a)') '&body name = ''base'', elset = ''base'', young = 200000.0, poisson = 0.3, density = 7.8e-9 /'
        write(u, '(a)') '&body name = ''slider'', elset = ''slider'', young = 2000.0, poisson = 0.45, ' // &
          'density = 1.0e-9, kinematics = ''finite'', material = ''neo_hooke'', velocity = 0.0, ' // trim(vtext) // ' /'
        write(u, '(a)') '&boundary set = ''base_bottom'', type = ''fixed'', components = ''xy'' /'
        write(u, '(a)') '&time t_end = 1.0e-6 /'
        write(u, '(a)') '&contact_pair slave = ''slider_bottom'', master = ''base_top'', friction = 0.2, ' // &
          'method = ''' // trim(methods(im)) // ''' /'
        close(u)
        allocate(run)
        call run_deck('./impact.nml', run, err)
        if (err%failed()) call check(failure, .false., trim(methods(im)) // ' impact: ' // err%message)
        if (allocated(failure)) return
        e0 = run%state%energy%initial
        vy = 0.0_wp
        do n = 1, run%model%nnode
          if (run%model%node_body(n) == 2) vy = vy + run%model%mass(n)*run%state%v_mid(2, n)
        end do
        print '(a)', '  ' // trim(methods(im)) // ', impact at ' // str(v/c, 2) // ' c: ' // str(run%state%step) // &
          ' steps, worst balance ' // str(run%worst_balance, 3) // ', least contact work ' // &
          str(run%min_contact_work/e0, 3) // ' of KE0, largest KE + W ' // str(run%max_internal/e0, 4) // &
          ' (internal) ; final momentum ' // str(vy, 3)
        call check(failure, run%min_contact_work > -1.0e-6_wp*e0, trim(methods(im)) // ': contact gave energy ' // &
          str(run%min_contact_work))
        call check(failure, run%worst_balance < 1.0e-2_wp, trim(methods(im)) // ': balance ' // str(run%worst_balance))
        call check(failure, vy > 0.0_wp, trim(methods(im)) // ': the block did not bounce off')
        call check(failure, run%state%energy%kinetic + run%state%energy%internal <= e0*(1.0_wp + 1.0e-3_wp), &
          trim(methods(im)) // ': energy grew')
        deallocate(run)
      end do
    end do
  end subroutine test_impact
end program test_finite_contact
