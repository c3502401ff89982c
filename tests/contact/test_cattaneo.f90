!> Cattaneo-Mindlin partial slip (method brief section 7; doc/scenes.md
!> section 3; input/verification/cattaneo): the Hertz cylinder pressed by
!> a driven top, then pulled by Q = 1200 N/mm < mu P, mu = 0.3, identical
!> materials, mortar P1 with the block as slave. Against the closed form
!> with the P and Q measured from the run (contact resultant on the slave):
!>   a = sqrt(4 P R / (pi E*)), p0 = 2 P / (pi a), c = a sqrt(1 - Q/(mu P)),
!>   q(x) = mu p0 sqrt(1 - x^2/a^2) - [|x| < c] mu p0 (c/a) sqrt(1 - x^2/c^2).
!>
!> Tangential traction: the `shear` output (G1 tau)_j / integral of phi_j,
!> the weighted multiplier over its length. It is what the discrete Coulomb
!> law (19) bears on, so stick/slip and |q| <= mu p hold for it exactly;
!> the nodal multiplier lam_t itself alternates node to node in the stick
!> zone (G1 couples neighbours; reported, not asserted).
!>
!> Without an argument only the coarse mesh runs (CTest `cattaneo`, quick);
!> `test_cattaneo moderate` runs the moderate mesh (CTest
!> `cattaneo_moderate`, slow).
program test_cattaneo
  use raccord_kinds, only: wp, pi
  use raccord_check, only: failure_t, new_test, run_tests, check, check_close
  use raccord_error, only: error_t
  use raccord_scene_runner, only: scene_run_t, run_deck
  use raccord_multiplier_solver, only: ST_STICK, ST_SLIP
  use mortar_profile_support, only: profile_t, profile_of_run
  implicit none

  real(wp), parameter :: MU = 0.3_wp, RADIUS = 10.0_wp, YOUNG = 200000.0_wp, POISSON = 0.3_wp
  real(wp), parameter :: Q_APPLIED = 60.0_wp*20.0_wp   !< traction 60 MPa on the 20 mm top

  if (command_argument_count() == 0) then
    call run_tests('cattaneo', [new_test('coarse mesh (a/5.8): stick zone, traction, Coulomb', test_coarse)])
  else
    call run_tests('cattaneo', [new_test('coarse mesh (a/5.8): stick zone, traction, Coulomb', test_coarse), &
      new_test('moderate mesh (a/14.4): stick zone, traction, Coulomb', test_moderate)])
  end if

contains

  subroutine test_coarse(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call cattaneo_case(failure, 'reg_mortar_p1_slave_block.nml')
  end subroutine test_coarse

  subroutine test_moderate(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call cattaneo_case(failure, 'q4_mortar_p1_slave_block.nml')
  end subroutine test_moderate

  subroutine cattaneo_case(failure, deck)
    type(failure_t), allocatable, intent(out) :: failure
    character(len=*), intent(in) :: deck
    type(scene_run_t) :: run
    type(error_t) :: err
    type(profile_t) :: pr
    real(wp) :: p_load, q_load, e_star, a, p0, c, left, right, c_h, h, s, rms_shear, rms_lam, ratio_nodal, &
      coulomb, qh
    integer :: i, n, first, last, nstick, nslip

    call run_deck('input/verification/cattaneo/' // deck, run, err)
    call check(failure, .not. err%failed(), 'run failed')
    if (allocated(failure)) return
    call profile_of_run(run, pr)
    ! Measured loads: the contact resultant on the slave (block) body.
    p_load = abs(run%pairs(1)%force(2))
    q_load = abs(run%pairs(1)%force(1))
    e_star = YOUNG/(2.0_wp*(1.0_wp - POISSON**2))
    a = sqrt(4.0_wp*p_load*RADIUS/(pi*e_star))
    p0 = 2.0_wp*p_load/(pi*a)
    c = a*sqrt(1.0_wp - q_load/(MU*p_load))

    ! Stick zone from the nodes' status: each edge midway between the
    ! outermost stick node and its (slipping) outer neighbour, which places
    ! it within h/2 when the statuses are right: tolerance h/2 on c.
    n = size(pr%x)
    first = 0
    last = 0
    nstick = 0
    nslip = 0
    do i = 1, n
      if (pr%status(i) == ST_SLIP) nslip = nslip + 1
      if (pr%status(i) /= ST_STICK) cycle
      nstick = nstick + 1
      if (first == 0) first = i
      last = i
    end do
    call check(failure, nstick > 0 .and. nslip > 0, 'no partial slip: stick and slip nodes must both exist')
    if (allocated(failure)) return
    call check(failure, first > 1 .and. last < n, 'the stick zone reaches the end of the slave surface')
    if (allocated(failure)) return
    left = 0.5_wp*(pr%x(first) + pr%x(first - 1))
    right = 0.5_wp*(pr%x(last) + pr%x(last + 1))
    c_h = 0.5_wp*(right - left)
    h = max(pr%x(first) - pr%x(first - 1), pr%x(last + 1) - pr%x(last))

    ! Traction with the sign of Q (the resultant of the shear profile), and
    ! its RMS error over |x| < a relative to mu p0. Tolerance h/a: q has
    ! square-root behaviour at |x| = a and a square-root cusp at |x| = c, so
    ! the few nodes within h of them err by O(mu p0 sqrt(h/a)) and the rest
    ! by O(h^2); over the 2a/h nodes of the zone that is an RMS of order
    ! mu p0 h/a (0.18 on the coarse mesh, 0.07 on the moderate one).
    s = sign(1.0_wp, sum(pr%shear))
    rms_shear = 0.0_wp
    rms_lam = 0.0_wp
    ratio_nodal = 0.0_wp
    coulomb = -huge(1.0_wp)
    nstick = 0
    do i = 1, n
      ! Discrete Coulomb law (19) on the weighted multipliers, every node.
      coulomb = max(coulomb, abs(pr%shear(i)) - MU*pr%pres(i))
      if (pr%status(i) /= 0 .and. pr%lam(i) > 0.0_wp) ratio_nodal = max(ratio_nodal, abs(pr%tau(i))/(MU*pr%lam(i)))
      if (abs(pr%x(i)) >= a) cycle
      qh = q_exact(pr%x(i), a, p0, c)
      rms_shear = rms_shear + (s*pr%shear(i) - qh)**2
      rms_lam = rms_lam + (s*pr%tau(i) - qh)**2
      nstick = nstick + 1
    end do
    rms_shear = sqrt(rms_shear/real(nstick, wp))/(MU*p0)
    rms_lam = sqrt(rms_lam/real(nstick, wp))/(MU*p0)

    write(*, '(a,f8.1,a,f7.1,a,f6.4,a,f6.4,a,f7.4,a,f7.4,a,f6.4,a)') '        ' // deck // ': P ', p_load, &
      ', Q ', q_load, ', c/a expected ', c/a, ', measured ', c_h/a, ' (edges ', left, ', ', right, &
      '; tolerance h/2 = ', 0.5_wp*h/a, ' a)'
    write(*, '(a,f6.4,a,f6.4,a,f6.3,a,es9.2,a,es9.2)') '        RMS(q_h - q)/(mu p0): shear ', rms_shear, &
      ' (tolerance h/a = ', h/a, '), lam_t ', rms_lam, '; max(|shear| - mu pressure)/(mu p0) ', coulomb/(MU*p0), &
      '; energy ', abs(run%state%energy%balance)/run%state%energy%scale
    write(*, '(a,f6.3)') '        nodal multipliers: max |lam_t|/(mu lam_n) over active nodes ', ratio_nodal

    call check_close(failure, q_load, Q_APPLIED, 'tangential contact force = applied Q at rest', rel_tol=0.01_wp)
    call check_close(failure, c_h, c, 'stick-zone half-width c', abs_tol=0.5_wp*h)
    call check(failure, rms_shear <= h/a, 'tangential traction: RMS error over the contact zone above h/a')
    call check(failure, coulomb <= 1.0e-9_wp*MU*p0, 'Coulomb |q| <= mu p violated')
    ! Energy balance relative to the largest energy, at the end of the run.
    ! Not run%worst_balance: at step 0 the energy scale is still 0 while the
    ! mortar gap of the curved master (see doc/verification.md) already moves
    ! the bodies, so a round-off balance of 1e-21 reads 1e287 there.
    call check(failure, abs(run%state%energy%balance) < 1.0e-10_wp*run%state%energy%scale, &
      'energy balance not exact')
    call check(failure, run%pairs(1)%failed_total == 0, 'unconverged multiplier steps')
  end subroutine cattaneo_case

  !> Cattaneo-Mindlin traction (method brief section 7).
  pure real(wp) function q_exact(x, a, p0, c) result(q)
    real(wp), intent(in) :: x, a, p0, c
    q = MU*p0*sqrt(max(0.0_wp, 1.0_wp - (x/a)**2))
    if (abs(x) < c) q = q - MU*p0*(c/a)*sqrt(1.0_wp - (x/c)**2)
  end function q_exact
end program test_cattaneo
