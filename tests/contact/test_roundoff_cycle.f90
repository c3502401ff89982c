!> Active sets that alternate on round-off (raccord_solver_conditions,
!> holds_to_roundoff; doc/theory-contact.md, section 3). The axisymmetric
!> fuzz seed (tests/fuzz/seeds/axi.nml: a CAX8 punch on a CAX8 disc, mortar
!> P1, mu = 0.2) has a slave corner node on the axis whose row carries the
!> length integral of N_corner 2 pi r ds = 0 (round-off: about -1e-17), so
!> the active test of that node has no round-off band; at step 1 its
!> decision fell on the sign of F_j - c_j gn_j = +-1e-19 and the sets went
!> open / slip / open ... until max_iterations (200), every iterate
!> solving (19) to 2e-16 (Check build; the Release build's arithmetic
!> happened to settle).
!> Asserted: the row of zero length is there (the case is exercised), no
!> step of the run is left unconverged, the solve of step 1 ends within
!> a few iterations after the least-index threshold, the largest residual
!> of (19) stays at round-off, and the contact force carries the load.
program test_roundoff_cycle
  use raccord_kinds, only: wp
  use raccord_check, only: failure_t, new_test, run_tests, check
  use raccord_error, only: error_t
  use raccord_scene_runner, only: scene_run_t, prepare_deck, step_predict, step_finish
  use raccord_central_difference, only: advance_state
  implicit none

  call run_tests('roundoff_cycle', [ &
    new_test('axisymmetric seed: a row of zero length converges at every step', test_axi_seed)])

contains

  subroutine test_axi_seed(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(scene_run_t), allocatable :: run
    type(error_t) :: err
    real(wp) :: lmax, lmin
    integer :: m, it1
    character(len=160) :: msg

    allocate(run)
    lmin = huge(1.0_wp)
    lmax = 0.0_wp
    it1 = -1
    call prepare_deck('tests/fuzz/seeds/axi.nml', run, err)
    do while (.not. err%failed())
      call step_predict(run, err)
      if (err%failed()) exit
      call step_finish(run, err)
      if (err%failed()) exit
      if (run%state%step == 1) then
        ! the rows of step 1, where the sets cycled
        m = run%pairs(1)%cs%m
        lmax = maxval(abs(run%pairs(1)%cs%length(1:m)))
        lmin = minval(abs(run%pairs(1)%cs%length(1:m)))
        it1 = run%pairs(1)%iterations
      end if
      if (run%state%step == run%state%nsteps) exit
      call advance_state(run%state)
    end do
    call check(failure, .not. err%failed(), 'axi.nml: run failed')
    if (allocated(failure)) return
    write(msg, '(a,es10.2,a,es10.2)') 'axi.nml: a row of zero length expected at step 1 (axis corner): smallest |length| ', &
      lmin, ' of ', lmax
    call check(failure, lmin <= 1.0e-14_wp*lmax, trim(msg))
    write(msg, '(a,i0,a)') 'axi.nml: ', it1, ' active-set iterations at step 1 (200 when it cycled)'
    call check(failure, it1 >= 1 .and. it1 <= 40, trim(msg))
    associate (pair => run%pairs(1))
      write(msg, '(a,i0,a,i0,a)') 'axi.nml: ', pair%failed_total, ' unconverged steps in ', pair%steps, ' (0 expected)'
      call check(failure, pair%failed_total == 0, trim(msg))
      ! 70 steps; step 1 may take the least-index threshold (30) and a
      ! few more, the others about one or two each (200 when it cycled)
      write(msg, '(a,i0,a)') 'axi.nml: ', pair%iterations_total, ' active-set iterations over the run'
      call check(failure, pair%iterations_total <= 3*pair%steps + 40, trim(msg))
      write(msg, '(a,es10.2)') 'axi.nml: largest residual of (19) ', pair%residual_max
      call check(failure, pair%residual_max <= 1.0e-12_wp, trim(msg))
      ! the punch's pressure (50 MPa on r < 1: 157 N) is carried through
      ! the contact at the end (t = 1.5 us, the load ramped over 1 us)
      write(msg, '(a,2es12.4)') 'axi.nml: contact force on the punch ', pair%force
      call check(failure, pair%force(2) > 0.0_wp, trim(msg))
    end associate
  end subroutine test_axi_seed
end program test_roundoff_cycle
