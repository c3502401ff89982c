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
!> The bound of that rule is the pair's `&contact_pair tolerance` (default
!> 1e-12): the seed with tolerance = 1e-30 in its deck, below the
!> iterates' round-off, turns the rule off, and where the default run's
!> step 1 needed it (more than 30 iterations) that step then runs to
!> max_iterations and is reported unconverged; with tolerance = 1e-3 the
!> solve is the default's (a cycling step ends at the same iterate, the
!> others settle before the rule applies). Either value reaches the
!> solver's workspace.
program test_roundoff_cycle
  use raccord_kinds, only: wp
  use raccord_check, only: failure_t, new_test, run_tests, check
  use raccord_error, only: error_t
  use raccord_scene_runner, only: scene_run_t, prepare_deck, step_predict, step_finish
  use raccord_central_difference, only: advance_state
  use raccord_solver_conditions, only: LEAST_INDEX_AFTER
  implicit none

  call run_tests('roundoff_cycle', [ &
    new_test('axisymmetric seed: a row of zero length converges at every step', test_axi_seed), &
    new_test('&contact_pair tolerance bounds the residual that ends a cycling solve', test_tolerance)])

contains

  !> The seed's deck with `tolerance = tol` on its contact pair (mesh path
  !> made absolute), run to the end: step 1's iterations, the unconverged
  !> steps, the largest residual and the tolerance the solver holds.
  subroutine seed_run(tol, it1, failed, res_max, held, ok)
    character(len=*), intent(in) :: tol
    integer, intent(out) :: it1
    integer, intent(out) :: failed
    real(wp), intent(out) :: res_max, held
    logical, intent(out) :: ok
    type(scene_run_t), allocatable :: run
    type(error_t) :: err
    character(len=512) :: root, line
    integer :: length, stat, uin, uout, ios, k
    call get_environment_variable('RACCORD_SOURCE_DIR', root, length, stat)
    open(newunit=uin, file=trim(root) // '/tests/fuzz/seeds/axi.nml', status='old', action='read')
    open(newunit=uout, file='./roundoff_cycle_tol.nml', status='replace', action='write')
    do
      read(uin, '(a)', iostat=ios) line
      if (ios /= 0) exit
      k = index(line, 'file = ''axi.inp''')
      if (k > 0) line = line(1:k - 1) // 'file = ''' // trim(root) // '/tests/fuzz/seeds/axi.inp''' // &
        trim(line(k + 16:))
      k = index(line, 'friction = 0.2')
      if (k > 0) line = line(1:k - 1) // 'friction = 0.2, tolerance = ' // tol // trim(line(k + 14:))
      write(uout, '(a)') trim(line)
    end do
    close(uin)
    close(uout)
    it1 = -1
    failed = -1
    res_max = huge(1.0_wp)
    held = 0.0_wp
    allocate(run)
    call prepare_deck('./roundoff_cycle_tol.nml', run, err)
    do while (.not. err%failed())
      call step_predict(run, err)
      if (err%failed()) exit
      call step_finish(run, err)
      if (err%failed()) exit
      if (run%state%step == 1) it1 = run%pairs(1)%iterations
      if (run%state%step == run%state%nsteps) exit
      call advance_state(run%state)
    end do
    ok = .not. err%failed()
    if (.not. ok) return
    failed = int(run%pairs(1)%failed_total)
    res_max = run%pairs(1)%residual_max
    held = run%pairs(1)%work%tolerance
  end subroutine seed_run

  subroutine test_tolerance(failure)
    type(failure_t), allocatable, intent(out) :: failure
    integer :: it_def, it_tight, it_loose, f_def, f_tight, f_loose, max_iter
    real(wp) :: r_def, r_tight, r_loose, h_def, h_tight, h_loose
    logical :: ok
    character(len=200) :: msg
    call seed_run('1e-12', it_def, f_def, r_def, h_def, ok)
    call check(failure, ok, 'axi.nml, tolerance = 1e-12: run failed')
    if (allocated(failure)) return
    call seed_run('1e-30', it_tight, f_tight, r_tight, h_tight, ok)
    call check(failure, ok, 'axi.nml, tolerance = 1e-30: run failed')
    if (allocated(failure)) return
    call seed_run('1e-3', it_loose, f_loose, r_loose, h_loose, ok)
    call check(failure, ok, 'axi.nml, tolerance = 1e-3: run failed')
    if (allocated(failure)) return
    write(*, '(8x,a,3(i0,a,i0,a,es9.2,a))') 'step-1 iterations, unconverged steps, largest residual: 1e-12: ', &
      it_def, ', ', f_def, ', ', r_def, '; 1e-30: ', it_tight, ', ', f_tight, ', ', r_tight, '; 1e-3: ', &
      it_loose, ', ', f_loose, ', ', r_loose, ''
    call check(failure, h_def == 1.0e-12_wp .and. h_tight == 1.0e-30_wp .and. h_loose == 1.0e-3_wp, &
      'the deck''s tolerance does not reach the solver')
    ! the seed's max_iterations (the deck default)
    max_iter = 200
    if (it_def > LEAST_INDEX_AFTER) then
      ! step 1 cycled and the rule ended it: without the rule it runs on
      write(msg, '(a,i0,a,i0,a)') 'tolerance = 1e-30: step 1 took ', it_tight, ' iterations and ', f_tight, &
        ' steps were unconverged (expected max_iterations and at least 1)'
      call check(failure, it_tight == max_iter .and. f_tight >= 1, trim(msg))
    else
      write(*, '(8x,a)') 'step 1 settled before the rule in this build: the tight tolerance is not exercised'
    end if
    write(msg, '(a,i0,a,i0,a,i0)') 'tolerance = 1e-3: step 1 took ', it_loose, ' iterations against ', it_def, &
      '; unconverged ', f_loose
    call check(failure, it_loose == it_def .and. f_loose == 0, trim(msg))
  end subroutine test_tolerance

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
