!> The reduced form of the multiplier solve with friction and a banded G1
!> (mortar; raccord_multiplier_solver, solve_banded_friction;
!> doc/theory-contact.md, section 3) against the saddle form on the same
!> constraint sets: synthetic mortar-like rows (slave nodes on a line with
!> a P1 mass-matrix G1 of half band 1, or a pentadiagonal one of half band
!> 2, master nodes above), random inverse masses, normals, gaps and slips
!> chosen so that the sets hold open ends, slip zones of either direction
!> (long ones, whose stick neighbours are border unknowns) on either side
!> of a stick zone (as in a run: paper Fig. 3).
!> Asserted: the reduced form takes the solve (and its border unknowns are
!> exercised), and it ends on the saddle form's sets, slip directions and
!> iteration count with the same multipliers, gaps and slips to round-off.
program test_friction_reduced
  use raccord_kinds, only: wp
  use raccord_check, only: failure_t, new_test, run_tests, check
  use raccord_constraint_set, only: constraint_set_t, cs_start, cs_add_row, cs_add_entry, cs_finish_row
  use raccord_multiplier_solver, only: solver_work_t, solve_multipliers, ST_OPEN, ST_STICK, ST_SLIP
  implicit none

  integer, parameter :: MMAX = 64
  integer :: urand_state = 12345

  call run_tests('friction_reduced', [ &
    new_test('P1 band 1: reduced form = saddle form on random sets', test_band1), &
    new_test('band 2: reduced form = saddle form on random sets', test_band2)])

contains

  subroutine test_band1(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call compare_forms(failure, 1)
  end subroutine test_band1

  subroutine test_band2(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call compare_forms(failure, 2)
  end subroutine test_band2

  subroutine compare_forms(failure, g1b)
    type(failure_t), allocatable, intent(out) :: failure
    integer, intent(in) :: g1b
    integer, parameter :: NCASE = 60
    type(constraint_set_t) :: cs
    type(solver_work_t) :: wr, ws
    real(wp), allocatable :: minv(:,:), alpha(:), sig0(:), sig_r(:), sig_s(:)
    integer, allocatable :: st0(:), st_r(:), st_s(:), st_keep(:)
    real(wp), allocatable :: sig_keep(:)
    integer :: m_keep, state_keep
    integer :: icase, m, j, nreduced, nwarm, nborder, nslip, nstick, nopen, calls
    real(wp) :: mu, lscale, tscale, glscale
    character(len=200) :: msg

    nreduced = 0
    nwarm = 0
    nborder = 0
    nslip = 0
    nstick = 0
    nopen = 0
    call random_seed_fixed()
    do icase = 1, NCASE
      if (mod(icase, 2) == 1) then
        m = 20 + mod(7*icase, 41)
        mu = 0.1_wp + 0.4_wp*urand()
        state_keep = urand_state
        call build_set(cs, m, g1b, minv, alpha)
      else
        m = m_keep
        urand_state = state_keep
      end if
      allocate(st0(m), st_r(m), st_s(m), sig0(m), sig_r(m), sig_s(m))
      ! the guess of the sets: all open in odd cases; in even ones the sets
      ! of the odd case before, on the same rows with gaps and slips moved
      ! by a few per cent (the previous step's sets, as in a run)
      if (mod(icase, 2) == 1 .or. .not. allocated(st_keep)) then
        st0 = ST_OPEN
        sig0 = 1.0_wp
      else
        call build_set(cs, m_keep, g1b, minv, alpha, perturb=.true.)
        m = m_keep
        st0 = st_keep(1:m)
        sig0 = sig_keep(1:m)
      end if
      st_r = st0
      sig_r = sig0
      st_s = st0
      sig_s = sig0
      ws%saddle_only = .true.
      calls = wr%reduced_calls
      call solve_multipliers(cs, minv, alpha, 1.0_wp, 1.0_wp, mu, 200, st_r, sig_r, wr)
      call solve_multipliers(cs, minv, alpha, 1.0_wp, 1.0_wp, mu, 200, st_s, sig_s, ws)
      write(msg, '(a,i0,a,i0)') 'case ', icase, ', m = ', m
      call check(failure, ws%converged .and. wr%converged, trim(msg) // ': both forms converge')
      if (allocated(failure)) return
      if (wr%reduced_calls > calls) then
        nreduced = nreduced + 1
        if (mod(icase, 2) == 0) nwarm = nwarm + 1
        if (wr%border_unknowns > 0) nborder = nborder + 1
      end if
      call check(failure, all(st_r == st_s), trim(msg) // ': the same sets')
      if (allocated(failure)) return
      call check(failure, all(sig_r == sig_s .or. st_s /= ST_SLIP), trim(msg) // ': the same slip directions')
      call check(failure, wr%iterations == ws%iterations, trim(msg) // ': the same iterations')
      if (allocated(failure)) return
      nslip = nslip + count(st_s == ST_SLIP)
      nstick = nstick + count(st_s == ST_STICK)
      nopen = nopen + count(st_s == ST_OPEN)
      lscale = maxval(abs(ws%lam(1:m)))
      tscale = max(maxval(abs(ws%tau(1:m))), 1.0e-300_wp)
      glscale = maxval(abs(cs%gap_w(1:m))) + maxval(abs(cs%slip_w(1:m)))
      call check(failure, maxval(abs(wr%lam(1:m) - ws%lam(1:m))) <= 1.0e-9_wp*lscale, &
        trim(msg) // ': lambda to round-off')
      call check(failure, maxval(abs(wr%tau(1:m) - ws%tau(1:m))) <= 1.0e-9_wp*max(tscale, mu*lscale), &
        trim(msg) // ': tau to round-off')
      call check(failure, maxval(abs(wr%gn(1:m) - ws%gn(1:m))) <= 1.0e-9_wp*glscale, &
        trim(msg) // ': nodal gaps to round-off')
      call check(failure, maxval(abs(wr%gt(1:m) - ws%gt(1:m))) <= 1.0e-9_wp*glscale, &
        trim(msg) // ': nodal slips to round-off')
      call check(failure, wr%residual < 1.0e-10_wp, trim(msg) // ': conditions (19) hold')
      if (allocated(failure)) return
      if (mod(icase, 2) == 1) then
        st_keep = st_s
        sig_keep = sig_s
        m_keep = m
        state_keep = urand_state
      end if
      deallocate(st0, st_r, st_s, sig0, sig_r, sig_s)
    end do
    write(*, '(a,i0,a,i0,a,i0,a,i0,a,i0,a)') '  band ', g1b, ': reduced form in ', nreduced, ' of ', NCASE, &
      ' cases (', nwarm, ' of the ', NCASE/2, ' warm-started ones),'
    write(*, '(a,i0,a,i0,a,i0,a,i0,a)') '  ', nborder, ' with border unknowns; final sets: ', nopen, ' open, ', &
      nstick, ' stick, ', nslip, ' slip'
    ! The comparison means something only if the reduced form took the
    ! solves started from the previous sets (from all open, the first
    ! iterate slips everywhere, in both directions side by side, and the
    ! saddle form takes over), with border unknowns in some, and all three
    ! sets occur.
    call check(failure, nwarm >= (8*NCASE)/20, 'the reduced form takes the warm-started solves')
    call check(failure, nborder >= 5, 'border unknowns (long slip zones) exercised')
    call check(failure, nslip > 0 .and. nstick > 0 .and. nopen > 0, 'open, stick and slip all occur')
  end subroutine compare_forms

  !> Slave nodes 1..m on a line (spacing 1), master nodes m+1..2m+1 above;
  !> row j: slave nodes j - g1b .. j + g1b with -G1(i, j), master nodes j,
  !> j + 1 with +G21; the weighted gap and slip set directly: closed in a
  !> middle zone, slip of one direction to the left of it and the other to
  !> the right, small in between (stick).
  subroutine build_set(cs, m, g1b, minv, alpha, perturb)
    type(constraint_set_t), intent(inout) :: cs
    integer, intent(in) :: m, g1b
    real(wp), allocatable, intent(inout) :: minv(:,:), alpha(:)
    logical, intent(in), optional :: perturb
    real(wp), allocatable :: x(:,:), du(:,:)
    real(wp) :: g1(-2:2), th, nrm(2), c, half, a1, a2, s, wcore
    integer :: j, i, nn, lo, hi
    nn = 2*MMAX + 1      ! the solver's node lists are sized by its first call
    if (allocated(minv)) deallocate(minv, alpha)
    allocate(minv(2, nn), alpha(nn), x(2, nn), du(2, nn))
    do j = 1, nn
      minv(:, j) = 0.5_wp + urand()
    end do
    alpha = 0.0_wp
    x = 0.0_wp
    du = 0.0_wp
    if (g1b == 1) then
      g1 = [0.0_wp, 1.0_wp/6.0_wp, 2.0_wp/3.0_wp, 1.0_wp/6.0_wp, 0.0_wp]
    else
      g1 = [-0.05_wp, 0.2_wp, 0.7_wp, 0.2_wp, -0.05_wp]
    end if
    call cs_start(cs, m)
    do j = 1, m
      th = 0.05_wp*(urand() - 0.5_wp)
      nrm = [sin(th), cos(th)]
      call cs_add_row(cs, j, j, nrm, 1.0_wp, real(j, wp))
      do i = max(1, j - g1b), min(m, j + g1b)
        call cs_add_entry(cs, i, -g1(i - j)*(1.0_wp + 0.1_wp*urand()))
      end do
      call cs_add_entry(cs, m + j, 0.5_wp + 0.1_wp*urand())
      call cs_add_entry(cs, m + j + 1, 0.5_wp + 0.1_wp*urand())
      call cs_finish_row(cs, x, du)
    end do
    cs%g1_band = g1b
    do j = 1, m
      do i = max(1, j - g1b), min(m, j + g1b)
        ! G1(i, j) is the negated slave weight of row j at slave node i
        cs%g1(i - j, j) = -cs%ent_w(cs%row_ptr(j) + i - max(1, j - g1b))
      end do
    end do
    ! Gaps: closed from lo to hi (a few constraints from either end), open outside.
    lo = 1 + int(0.25_wp*m*urand())
    hi = m - int(0.25_wp*m*urand())
    c = 0.5_wp*(lo + hi)
    half = max(0.5_wp*(hi - lo), 1.0_wp)
    a1 = 0.2_wp + urand()
    a2 = 0.2_wp + urand()
    wcore = g1b + 1 + 4.0_wp*urand()
    do j = 1, m
      ! a smooth overlap, largest at c, closing at lo and hi, with a little noise
      cs%gap_w(j) = -0.01_wp*(1.0_wp - ((j - c)/half)**2) + 1.0e-4_wp*(urand() - 0.5_wp)
      ! slip: +a1 to the left, -a2 to the right of a stick core of random width
      s = (j - c)/half
      if (abs(j - c) <= wcore) then
        cs%slip_w(j) = 1.0e-6_wp*(urand() - 0.5_wp)
      else if (s < 0.0_wp) then
        cs%slip_w(j) = 0.01_wp*a1*(abs(j - c) - wcore)/half
      else
        cs%slip_w(j) = -0.01_wp*a2*(abs(j - c) - wcore)/half
      end if
    end do
    ! the next step: the same rows (the same random draws), gaps and slips a little moved
    if (present(perturb)) then
      do j = 1, m
        cs%gap_w(j) = cs%gap_w(j) + 5.0e-4_wp*(urand_fresh() - 0.5_wp)
        cs%slip_w(j) = cs%slip_w(j)*(1.0_wp + 0.05_wp*(urand_fresh() - 0.5_wp))
      end do
    end if
  end subroutine build_set

  !> A small linear congruential generator: the same cases on every platform.
  real(wp) function urand()
    urand_state = int(mod(1103515245_8*int(urand_state, 8) + 12345_8, 2147483648_8))
    urand = real(urand_state, wp)/2147483648.0_wp
  end function urand

  !> A second stream (the perturbations of the even cases).
  real(wp) function urand_fresh()
    integer, save :: state2 = 777
    state2 = int(mod(1103515245_8*int(state2, 8) + 12345_8, 2147483648_8))
    urand_fresh = real(state2, wp)/2147483648.0_wp
  end function urand_fresh

  subroutine random_seed_fixed()
    real(wp) :: r
    integer :: k
    do k = 1, 3
      r = urand()
    end do
  end subroutine random_seed_fixed
end program test_friction_reduced
