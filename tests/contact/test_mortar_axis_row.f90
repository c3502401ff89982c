!> The axis row of axisymmetric mortar contact in the default multiplier
!> spaces, P1 and P0 (doc/theory-contact-mortar.md section 7, "The axis
!> row of P1 and P0"; issue #16 item 5). With dual multipliers the axis
!> corner of a Q8 slave edge had a ring weight D_axis = integral of
!> N_axis 2 pi r dGamma of either sign, its psi with it, and its row came
!> and went: the finite-strain frictionless hollow ball as dual slave got
!> 85 % of the 5.3e-2 of the energy scale contact gave it from that row,
!> pushing the sunk pole out in single steps (section 9, "The axis"). In
!> P1 and P0 the same D_axis changes sign too (it is the axis node's
!> nodal weight, the row's length), but the row's own weight is
!> integral of psi_axis 2 pi r dGamma with psi_axis >= 0, bounded away
!> from 0 (section 7), so the row cannot drop.
!> The scene: that ball (tests/axisymmetric/data/ball_q8.inp, neo-Hooke,
!> j2 plate, damped; the deck of axi_finite_cases.sh without friction)
!> with the ball's outer surface, which reaches the axis at the pole, as
!> slave, to t = 0.08 (first contact at t = 0.01; the dual row's events
!> were between t = 0.039 and 0.047), P1 and P0, conditions 'nodal' (the
!> default) and 'weighted'. Asserted for the row of the slave node on the
!> axis, every step: D_axis takes both signs over the run (the case is
!> exercised), the row is a constraint at every step once it is one (no
!> drop and return), its weight stays within a factor 2 of its largest,
!> the running sum of its contact work -lambda (g(x(n+1)) - g(x(n-1)))/2
!> (tools/mortar/row_work.f90) never falls below -1e-3 of the energy
!> scale (no energy through the axis row), its multiplier stays below 3
!> times the other rows' largest (no push-out spike: dual's were 1e4
!> times), every step converges; with 'weighted' also that contact as a
!> whole gives at most 1e-3 of the energy scale.
program test_mortar_axis_row
  use raccord_kinds, only: wp
  use raccord_check, only: failure_t, new_test, run_tests, check
  use raccord_error, only: error_t
  use raccord_scene, only: MULT_P1, MULT_P0
  use raccord_scene_runner, only: scene_run_t, prepare_deck, step_predict, step_finish
  use raccord_central_difference, only: advance_state
  use raccord_contact_energy, only: contact_energy_watch_t, watch_contact_energy
  use raccord_multiplier_solver, only: ST_OPEN
  implicit none

  call run_tests('mortar_axis_row', [ &
    new_test('finite-strain ball as Q8 slave, P1 and P0, nodal and weighted: the axis row stays, gives no energy', &
      test_ball_axis_row)])

contains

  subroutine test_ball_axis_row(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call axis_row_case(failure, MULT_P1, .false., 'P1, nodal')
    call axis_row_case(failure, MULT_P0, .false., 'P0, nodal')
    call axis_row_case(failure, MULT_P1, .true., 'P1, weighted')
    call axis_row_case(failure, MULT_P0, .true., 'P0, weighted')
  end subroutine test_ball_axis_row

  subroutine axis_row_case(failure, mult, weighted, name)
    type(failure_t), allocatable, intent(inout) :: failure
    integer, intent(in) :: mult
    logical, intent(in) :: weighted
    character(len=*), intent(in) :: name
    real(wp), parameter :: T_STOP = 0.08_wp
    real(wp), parameter :: BOUND = 1.0e-3_wp      !< energy, over the energy scale
    type(scene_run_t), allocatable :: run
    type(contact_energy_watch_t) :: watch
    type(error_t) :: err
    character(len=512) :: root
    character(len=:), allocatable :: path
    character(len=200) :: msg
    real(wp) :: gm, gp, wj, w_axis, w_least, d_lo, d_hi, len_lo, len_hi, lam_ax, lam_other, rmax
    integer :: u, length, stat, c, cax, j, jax, e, p, npresent, ndrop, nreturn, nflip, nsteps
    logical :: was_present, was_closed, closed
    call get_environment_variable('RACCORD_SOURCE_DIR', root, length, stat)
    path = './mortar_axis_row_ball.nml'
    open(newunit=u, file=path, status='replace', action='write')
    write(u, '(a)') '&mesh file = ''' // trim(root) // '/tests/axisymmetric/data/ball_q8.inp'' /'
    write(u, '(a)') '&body name = ''ball'', elset = ''ball'', young = 10.0, poisson = 0.45, density = 1.0e-3, ' // &
      'hypothesis = ''axisymmetric'', kinematics = ''finite'', material = ''neo_hooke'' /'
    write(u, '(a)') '&body name = ''plate'', elset = ''plate'', young = 200.0, poisson = 0.3, density = 1.0e-3, ' // &
      'hypothesis = ''axisymmetric'', kinematics = ''finite'', material = ''j2'', yield_stress = 0.5 /'
    write(u, '(a)') '&amplitude name = ''ramp'', time = 0.0, 0.15, value = 0.0, 1.0 /'
    write(u, '(a)') '&boundary set = ''b_bottom'', type = ''fixed'', components = ''y'' /'
    write(u, '(a)') '&boundary set = ''p_top'', type = ''displacement'', components = ''xy'', value = 0.0, -0.16, ' // &
      'amplitude = ''ramp'' /'
    write(u, '(a)') '&time t_end = 0.25, damping = 20.0 /'
    write(u, '(a)') '&contact_pair slave = ''b_right'', master = ''p_bottom'', method = ''mortar'', friction = 0.0 /'
    close(u)
    allocate(run)
    call prepare_deck(path, run, err, multiplier=mult, weighted=weighted)
    call check(failure, .not. err%failed(), name // ': ball deck: set-up failed')
    if (allocated(failure)) return
    ! The slave chain node on the axis (reference r = 0): the pole.
    associate (sl => run%pairs(1)%slave)
      rmax = maxval(abs(run%model%x(1, sl%node(1:sl%nnode))))
      cax = 0
      do c = 1, sl%nnode
        if (abs(run%model%x(1, sl%node(c))) <= 1.0e-12_wp*rmax) cax = c
      end do
    end associate
    call check(failure, cax > 0, name // ': no slave node on the axis')
    if (allocated(failure)) return
    npresent = 0; ndrop = 0; nreturn = 0; nflip = 0; nsteps = 0
    was_present = .false.; was_closed = .false.
    w_axis = 0.0_wp; w_least = 0.0_wp; lam_ax = 0.0_wp; lam_other = 0.0_wp
    d_lo = huge(1.0_wp); d_hi = -huge(1.0_wp); len_lo = huge(1.0_wp); len_hi = 0.0_wp
    do
      call step_predict(run, err)
      if (.not. err%failed()) call step_finish(run, err)
      if (err%failed()) exit
      call watch_contact_energy(run%pairs, run%state, watch)
      nsteps = nsteps + 1
      associate (cs => run%pairs(1)%cs, pr => run%pairs(1))
        jax = 0
        do j = 1, cs%m
          if (cs%snode(j) == cax) then
            jax = j
            lam_ax = max(lam_ax, abs(pr%work%lam(j)))
          else
            lam_other = max(lam_other, abs(pr%work%lam(j)))
          end if
        end do
        if (jax > 0) then
          ! The row's contact work over the step (central difference of
          ! its gap g_j = sum_p w_jp x_p . n_j, as row_work).
          gm = 0.0_wp
          gp = 0.0_wp
          do e = cs%row_ptr(jax), cs%row_ptr(jax + 1) - 1
            p = cs%ent_node(e)
            gm = gm + cs%ent_w(e)*dot_product(run%model%x(:, p) + run%state%u_prev(:, p), cs%normal(:, jax))
            gp = gp + cs%ent_w(e)*dot_product(run%model%x(:, p) + run%state%u_next(:, p), cs%normal(:, jax))
          end do
          wj = -pr%work%lam(jax)*(gp - gm)/2.0_wp
          w_axis = w_axis + wj
          if (run%state%energy%scale > 0.0_wp) w_least = min(w_least, w_axis/run%state%energy%scale)
          npresent = npresent + 1
          closed = pr%st_c(jax) /= ST_OPEN
          if (was_present .and. (closed .neqv. was_closed)) nflip = nflip + 1
          was_closed = closed
          d_lo = min(d_lo, cs%length(jax))
          d_hi = max(d_hi, cs%length(jax))
          len_lo = min(len_lo, pr%mortar%len(cax))
          len_hi = max(len_hi, pr%mortar%len(cax))
        end if
        if (cs%m > 0) then
          if (was_present .and. jax == 0) ndrop = ndrop + 1
          if (.not. was_present .and. jax > 0 .and. npresent > 1) nreturn = nreturn + 1
        end if
        was_present = jax > 0
      end associate
      if (run%state%time >= T_STOP .or. run%state%step == run%state%nsteps) exit
      call advance_state(run%state)
    end do
    call check(failure, .not. err%failed(), name // ': ball deck: run failed')
    if (allocated(failure)) return
    write(*, '(8x,a,a,i0,a,i0,a,i0,a,i0,a,i0)') name, ': axis row in ', npresent, ' steps of ', nsteps, &
      ', drops ', ndrop, ', returns ', nreturn, ', open/closed changes ', nflip
    write(*, '(8x,a,a,2es10.2,a,2es10.2,a,es10.2,a,2es10.2,a,es10.2)') name, ': D_axis ', d_lo, d_hi, &
      ', row weight ', len_lo, len_hi, ', least running work / scale ', w_least, ', lambda axis, others ', &
      lam_ax, lam_other, ', energy given / scale ', watch%worst
    call check(failure, d_lo < 0.0_wp .and. d_hi > 0.0_wp, name // &
      ': the axis node''s ring weight D_axis did not change sign (the case is not exercised)')
    write(msg, '(a,i0,a,i0,a)') ': the axis row was dropped ', ndrop, ' times and came back ', nreturn, ' times'
    call check(failure, npresent > 0 .and. ndrop == 0 .and. nreturn == 0, name // trim(msg))
    call check(failure, len_lo >= 0.5_wp*len_hi, name // ': the axis row''s weight fell below half its largest')
    call check(failure, w_least >= -BOUND, name // ': the axis row gave the bodies more than 1e-3 of the energy scale')
    call check(failure, lam_ax <= 3.0_wp*lam_other, name // ': the axis multiplier spiked above 3 times the others''')
    call check(failure, run%pairs(1)%failed_total == 0, name // ': unconverged multiplier steps')
    if (weighted) call check(failure, watch%worst <= BOUND, name // &
      ': contact gave the bodies more than 1e-3 of the energy scale')
  end subroutine axis_row_case
end program test_mortar_axis_row
