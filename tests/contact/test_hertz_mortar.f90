!> Frictionless cylinder on a large block (input/verification/hertz; method
!> brief section 7): mortar P1 against Hertz on the moderate Q4 mesh (block
!> top h = a/14.4, cylinder arc h = a/16.7), each body as slave in turn, the
!> slave/master swap against node-to-segment's on the same mesh, and the
!> error falling from the coarse mesh (h = a/5.8) to the moderate one.
!>
!> Pressure: lam_n, the multiplier, which is the contact pressure of the
!> mixed formulation (paper (8)-(9); doc/theory-contact-mortar.md section
!> 2); the `pressure` output (G1 lam)_j / integral of phi_j is a weighted
!> mean of three neighbouring multipliers (on a uniform mesh
!> (lam_j-1 + 4 lam_j + lam_j+1)/6), which smooths the peak by h^2 p''/6 and
!> is zero at open nodes by construction; it is printed beside.
!> Half-width: the zero crossing of the piecewise-linear multiplier field
!> lam_h around the peak (sub-node); the active set alone resolves a only to
!> h/2 = a/29 = 3.4 %, more than the 2 % asked. The active-set figure is
!> printed beside.
program test_hertz_mortar
  use raccord_kinds, only: wp
  use raccord_check, only: failure_t, new_test, run_tests, check, check_close
  use raccord_error, only: error_t
  use raccord_scene_runner, only: scene_run_t, run_deck
  use hertz_support, only: hertz_closed_form, check_resultants
  use mortar_profile_support, only: profile_t, profile_of_run, zero_crossing_half_width, active_half_width, &
    hertz_rms_error, interior_difference
  implicit none

  real(wp), parameter :: P_LOAD = 8000.0_wp     !< 400 MPa on the 20 mm top (doc/scenes.md section 2)
  real(wp), parameter :: RADIUS = 10.0_wp
  !> Node-to-segment's swap asymmetry on the same mesh and measure, written
  !> by the hertz_nts test of this run (CTest fixture) to
  !> hertz_nts_interior_swap.txt (its `pressure` output over |x| <= 0.8 a).
  ! save: the test procedures passed to run_tests use these, and static
  ! storage spares them a trampoline (and the program an executable stack).
  real(wp), save :: nts_interior_swap = -1.0_wp
  !> Asserted: mortar's asymmetry below nts_interior_swap / SWAP_FACTOR.
  !> Measured ratio 6.8 (mortar 1.2e-3); 3 keeps mortar below 2.7e-3 p0,
  !> the interpolation error of a plain nodal comparison at 0.8 a.
  real(wp), parameter :: SWAP_FACTOR = 3.0_wp
  real(wp), save :: a, p0
  type(profile_t), save :: pb, pc, pcoarse

  call hertz_closed_form(P_LOAD, RADIUS, 200000.0_wp, 0.3_wp, a, p0)
  call run_tests('hertz_mortar', [ &
    new_test('slave = block: peak and half-width within 2 % of Hertz, force = P, energy exact', test_slave_block), &
    new_test('slave = cylinder: peak and half-width within 2 % of Hertz, force = P, energy exact', &
      test_slave_cylinder), &
    new_test('slave/master swap: mortar far below node-to-segment', test_swap), &
    new_test('coarse mesh: error larger than on the moderate mesh', test_refinement)])

contains
  subroutine hertz_case(failure, deck, prof, accuracy)
    type(failure_t), allocatable, intent(inout) :: failure
    character(len=*), intent(in) :: deck
    type(profile_t), intent(out) :: prof
    logical, intent(in) :: accuracy
    type(scene_run_t) :: run
    type(error_t) :: err
    real(wp) :: peak, hw, hw_set, force
    call run_deck('input/verification/hertz/' // deck, run, err)
    call check(failure, .not. err%failed(), 'run failed')
    if (allocated(failure)) return
    call profile_of_run(run, prof)
    peak = maxval(prof%lam)
    hw = zero_crossing_half_width(prof%x, prof%lam)
    hw_set = active_half_width(prof%x, prof%status)
    force = abs(run%pairs(1)%force(2))
    write(*, '(a,f7.2,a,f7.2,a,f7.2,a,f7.2,a,f7.3,a,f6.3,a,es9.2)') '        ' // deck // ': peak lam ', &
      100.0_wp*(peak/p0 - 1.0_wp), ' % (pressure ', 100.0_wp*(maxval(prof%pres)/p0 - 1.0_wp), &
      ' %), half-width zero crossing ', 100.0_wp*(hw/a - 1.0_wp), ' % (active set ', &
      100.0_wp*(hw_set/a - 1.0_wp), ' %), |Fy|/P - 1 ', 100.0_wp*(force/P_LOAD - 1.0_wp), ' %, RMS/p0 ', &
      hertz_rms_error(prof, a, p0), ', energy ', abs(run%state%energy%balance)/run%state%energy%scale
    call check_resultants(failure, run, P_LOAD, a, RADIUS)
    ! Energy balance relative to the largest energy, at the end of the run.
    ! Not run%worst_balance: at step 0 the energy scale is still 0 while the
    ! mortar gap of the curved master (see doc/verification.md) already moves
    ! the bodies, so a round-off balance of 1e-21 reads 1e287 there.
    call check(failure, abs(run%state%energy%balance) < 1.0e-10_wp*run%state%energy%scale, &
      'energy balance not exact')
    call check(failure, run%pairs(1)%failed_total == 0, 'unconverged multiplier steps')
    if (.not. accuracy) return
    call check_close(failure, peak, p0, 'peak multiplier against Hertz p0', rel_tol=0.02_wp)
    call check_close(failure, hw, a, 'half-width (zero crossing of lam_h) against Hertz a', rel_tol=0.02_wp)
  end subroutine hertz_case

  subroutine test_slave_block(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call hertz_case(failure, 'q4_mortar_p1_slave_block.nml', pb, .true.)
  end subroutine test_slave_block

  subroutine test_slave_cylinder(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call hertz_case(failure, 'q4_mortar_p1_slave_cylinder.nml', pc, .true.)
  end subroutine test_slave_cylinder

  !> Swap asymmetry away from the contact edges, |x| <= 0.8 a, of the
  !> residuals r = p - p_Hertz: r_block - r_cyl at the nodes of either
  !> profile, the other interpolated linearly. Interpolating the residual
  !> rather than p removes the interpolation error of the square-root
  !> profile itself (up to h^2/8 |p''| = 2.8e-3 p0 at 0.8 a for h = a/14.4,
  !> as large as mortar's whole asymmetry), so what remains is the methods'.
  !> Over the whole surface the largest difference sits in the interval that
  !> straddles an edge, where a nodal profile of a square-root edge costs
  !> O(p0 sqrt(h/a)) whatever the method: 8.1e-2 there for mortar as for
  !> node-to-segment (printed, not asserted).
  subroutine test_swap(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp) :: d_lam, d_pres, d_plain, d_all
    call check(failure, allocated(pb%x) .and. allocated(pc%x), 'the two runs above must run first')
    if (allocated(failure)) return
    call read_nts_swap(failure)
    if (allocated(failure)) return
    d_lam = interior_difference(pb%x, residual(pb%x, pb%lam), pc%x, residual(pc%x, pc%lam), -0.8_wp*a, 0.8_wp*a)/p0
    d_pres = interior_difference(pb%x, residual(pb%x, pb%pres), pc%x, residual(pc%x, pc%pres), &
      -0.8_wp*a, 0.8_wp*a)/p0
    d_plain = interior_difference(pb%x, pb%lam, pc%x, pc%lam, -0.8_wp*a, 0.8_wp*a)/p0
    d_all = interior_difference(pb%x, pb%pres, pc%x, pc%pres, -huge(1.0_wp), huge(1.0_wp))/p0
    write(*, '(a,es10.3,a,es10.3,a,es10.3)') '        mortar swap, |x| <= 0.8 a, residuals: lam ', d_lam, &
      ', pressure ', d_pres, '; node-to-segment (pressure) ', nts_interior_swap
    write(*, '(a,es10.3,a,es10.3,a,f5.2)') '        plain lam |x| <= 0.8 a ', d_plain, &
      '; whole surface (pressure) ', d_all, '; node-to-segment / mortar ', nts_interior_swap/d_lam
    call check(failure, d_lam < nts_interior_swap/SWAP_FACTOR, &
      'mortar swap asymmetry not below node-to-segment''s by the factor asserted')
  end subroutine test_swap

  !> Node-to-segment's figure from the hertz_nts test of this build.
  subroutine read_nts_swap(failure)
    type(failure_t), allocatable, intent(inout) :: failure
    integer :: unit, ios
    open(newunit=unit, file='hertz_nts_interior_swap.txt', status='old', action='read', iostat=ios)
    if (ios == 0) read(unit, *, iostat=ios) nts_interior_swap
    if (ios == 0) close(unit)
    call check(failure, ios == 0 .and. nts_interior_swap > 0.0_wp, 'hertz_nts_interior_swap.txt missing: ' // &
      'run the hertz_nts test first (ctest does, through its fixture)')
  end subroutine read_nts_swap

  !> p - p_Hertz at the nodes x.
  pure function residual(x, p) result(r)
    real(wp), intent(in) :: x(:), p(:)
    real(wp) :: r(size(x))
    r = p - p0*sqrt(max(0.0_wp, 1.0_wp - (x/a)**2))
  end function residual

  !> The coarse mesh (h = a/5.8, 2.5 times the moderate h) must be further
  !> from Hertz. RMS over |x| < a: the square-root edge limits a nodal
  !> profile to O(h) there, so about 2.5 times is expected; asserted: more
  !> than 1.5 times (an order of convergence above 0.44).
  subroutine test_refinement(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp) :: rc, rm
    call check(failure, allocated(pb%x), 'the moderate slave = block run must run first')
    if (allocated(failure)) return
    call hertz_case(failure, 'reg_mortar_p1_slave_block.nml', pcoarse, .false.)
    if (allocated(failure)) return
    rc = hertz_rms_error(pcoarse, a, p0)
    rm = hertz_rms_error(pb, a, p0)
    write(*, '(a,es10.3,a,es10.3,a,f6.2,a,f5.2)') '        RMS(lam - p)/p0: coarse ', rc, ', moderate ', rm, &
      ', ratio ', rc/rm, ', order ', log(rc/rm)/log(2.5_wp)
    call check(failure, rc > 1.5_wp*rm, 'the coarse mesh is not further from Hertz than the moderate one')
  end subroutine test_refinement
end program test_hertz_mortar
