!> The saddle form of the multiplier solve (doc/theory-contact.md,
!> section 3): the unknowns (lambda_j, gn_j [, tau_j, gt_j]) interleaved
!> constraint by constraint, the known gaps and slips left out, give one
!> banded system for fixed sets, solved by the banded LU with partial
!> pivoting (raccord_band_solver). Taken for the weighted conditions with
!> friction and when a reduced form declines.
module raccord_saddle_form
  use raccord_kinds, only: wp
  use raccord_constraint_set, only: constraint_set_t
  use raccord_band_solver, only: band_solve
  use raccord_solver_work, only: solver_work_t, ST_OPEN, ST_STICK, ST_SLIP, ensure2, ensure1, ensure_i
  use raccord_solver_conditions, only: LEAST_INDEX_AFTER, least_index_change, update_sets, &
    holds_to_roundoff, band_matvec, g1c, tested_sum, tested_row
  implicit none
  private

  !> Saddle form (friction with a banded G1): leave out the known gaps of
  !> the constraints in contact (their unit rows).
  logical, parameter :: eliminate_gaps = .true.

  public :: solve_saddle, solve_saddle_tc, scale_rows

contains

  !> Active-set iteration on the saddle form: for the sets in w%status,
  !> assemble and solve, update the sets (update_sets), until they no longer
  !> change or max_iter; one change per iteration after LEAST_INDEX_AFTER.
  !> It starts at iteration max(1, w%iterations): a reduced form that
  !> declined at its iteration k leaves the sets of that iteration, which
  !> the saddle form solves as its iteration k.
  !> same: the sets settled. A singular system stops the iteration with
  !> w%converged = .false. and w%singular = .true.
  subroutine solve_saddle(cs, dt, mu, friction, bw, max_iter, w, same)
    type(constraint_set_t), intent(in) :: cs
    real(wp), intent(in) :: dt, mu
    logical, intent(in) :: friction
    integer, intent(in) :: bw                  !< half band of the couplings: max(kb, g1_band)
    integer, intent(in) :: max_iter
    type(solver_work_t), intent(inout) :: w
    logical, intent(out) :: same
    integer :: m, it, j, n, kl, ku, ldab, info

    m = cs%m
    same = .false.
    do it = max(1, w%iterations), max_iter
      w%iterations = it
      w%status_old(1:m) = w%status(1:m)
      call layout(m, friction, bw, w, n, kl, ku)
      ldab = 2*kl + ku + 1
      call ensure2(w%ab, ldab, n)
      call assemble(cs, dt, mu, friction, bw, kl, ku, w)
      call band_solve(n, kl, ku, w%ab(1:ldab, 1:n), w%ipiv, w%rhs, w%fcol, w%lcol, w%ext, info)
      if (info /= 0) then
        ! A singular system means constraints that cannot move: report as
        ! not converged with the multipliers of the previous iterate.
        w%converged = .false.
        w%singular = .true.
        exit
      end if
      do j = 1, m
        w%lam(j) = w%rhs(w%var(1, j))
        w%gn(j) = 0.0_wp
        if (w%var(2, j) > 0) w%gn(j) = w%rhs(w%var(2, j))
        w%tau(j) = 0.0_wp
        w%gt(j) = 0.0_wp
        if (friction) then
          w%tau(j) = w%rhs(w%var(3, j))
          if (w%var(4, j) > 0) w%gt(j) = w%rhs(w%var(4, j))
        end if
      end do
      call band_matvec(cs, w%lam, w%fn)
      call band_matvec(cs, w%tau, w%ft)
      ! an iterate that solves (19) to round-off ends a long iteration
      ! (holds_to_roundoff: sets that alternate on round-off)
      if (holds_to_roundoff(cs, mu, friction, it, w)) then
        same = .true.
        exit
      end if
      call update_sets(cs, m, mu, friction, w)
      same = all(w%status(1:m) == w%status_old(1:m))
      if (same) exit
      if (it > LEAST_INDEX_AFTER) call least_index_change(m, w)
    end do
  end subroutine solve_saddle

  !> Unknowns for the current sets, constraint by constraint in chain
  !> order: lambda_j, gn_j unless j is in contact (gn_j = 0, with
  !> eliminate_gaps); with friction tau_j, and gt_j unless j sticks
  !> (gt_j = 0: its row and column drop out). Eliminating the known gaps
  !> and slips halves the unknowns of a zone in stick and narrows its band
  !> (the banded LU costs about n kl (kl + ku) with the local band). (The
  !> frictionless case, where eliminating the gaps here once changed the
  !> active set of test_curved's badly conditioned mortar P0 case, no
  !> longer comes here: solve_frictionless.) Each condition row takes the index of its unknown: the
  !> gap definition that of lambda_j, the normal condition that of gn_j,
  !> the slip definition that of tau_j, the tangential condition that of
  !> gt_j. Returns the size and the band.
  subroutine layout(m, friction, bw, w, n, kl, ku)
    integer, intent(in) :: m, bw
    logical, intent(in) :: friction
    type(solver_work_t), intent(inout) :: w
    integer, intent(out) :: n, kl, ku
    integer :: j
    n = 0
    do j = 1, m
      w%vfirst(j) = n + 1
      n = n + 1
      w%var(1, j) = n
      w%var(2:4, j) = 0
      if (w%status(j) == ST_OPEN .or. .not. eliminate_gaps) then
        n = n + 1
        w%var(2, j) = n
      end if
      if (friction) then
        n = n + 1
        w%var(3, j) = n
        if (w%status(j) /= ST_STICK) then
          n = n + 1
          w%var(4, j) = n
        end if
      end if
    end do
    w%vfirst(m + 1) = n + 1
    call band_extent(m, n, bw, w, kl, ku)
  end subroutine layout

  !> The half bandwidths kl, ku of the n unknowns numbered constraint by
  !> constraint (w%vfirst), the rows of j coupling to the unknowns of
  !> k = j - bw .. j + bw; the row profiles (fcol, lcol) reset, to be found
  !> by the assembly (a contact row is a unit row). layout and layout_tc.
  subroutine band_extent(m, n, bw, w, kl, ku)
    integer, intent(in) :: m, n, bw
    type(solver_work_t), intent(inout) :: w
    integer, intent(out) :: kl, ku
    integer :: j, i
    kl = 0
    ku = 0
    do j = 1, m
      ku = max(ku, w%vfirst(min(m, j + bw) + 1) - 1 - w%vfirst(j))
      kl = max(kl, w%vfirst(j + 1) - 1 - w%vfirst(max(1, j - bw)))
      do i = w%vfirst(j), w%vfirst(j + 1) - 1
        w%fcol(i) = n + 1
        w%lcol(i) = 0
      end do
    end do
  end subroutine band_extent

  !> The banded linear system for the current sets (unknowns of layout),
  !> rows scaled to unit largest entry (the blocks mix lengths and inverse
  !> masses).
  subroutine assemble(cs, dt, mu, friction, bw, kl, ku, w)
    type(constraint_set_t), intent(in) :: cs
    real(wp), intent(in) :: dt, mu
    logical, intent(in) :: friction
    integer, intent(in) :: bw, kl, ku
    type(solver_work_t), intent(inout) :: w
    integer :: j, k, m, r, n
    real(wp) :: dt2
    m = cs%m
    dt2 = dt*dt
    n = w%vfirst(m + 1) - 1
    w%ab(1:2*kl + ku + 1, 1:n) = 0.0_wp
    do j = 1, m
      ! Gap definition: G1' gn - dt^2 (Knn lambda + Knt tau) = g_w*. The
      ! nodal gap pairs with the nodal force F = G1 lambda (F . gn = lambda . g_w),
      ! so it is G1' that maps it to the weighted gap; G1 is not symmetric
      ! on Q8 edges or where the contact zone ends inside a P0 dual cell.
      r = w%var(1, j)
      do k = max(1, j - bw), min(m, j + bw)
        if (w%var(2, k) > 0) call put(r, w%var(2, k), g1c(cs, k, j))
        if (abs(j - k) <= w%kb) then
          call put(r, w%var(1, k), -dt2*w%knn(k - j, j))
          if (friction) call put(r, w%var(3, k), -dt2*w%knt(k - j, j))
        end if
      end do
      w%rhs(r) = cs%gap_w(j)
      ! Normal condition: gn_j = 0 (in contact) or (G1 lambda)_j = 0 (open).
      ! (An eliminated contact gap has no row.)
      r = w%var(2, j)
      if (r > 0) then
        w%rhs(r) = 0.0_wp
        if (w%status(j) /= ST_OPEN) then
          call put(r, r, 1.0_wp)
        else
          do k = max(1, j - cs%g1_band), min(m, j + cs%g1_band)
            call put(r, w%var(1, k), g1c(cs, j, k))
          end do
        end if
      end if
      if (.not. friction) cycle
      ! Slip definition: G1' gt - dt^2 (Ktn lambda + Ktt tau) = s_w*.
      r = w%var(3, j)
      do k = max(1, j - bw), min(m, j + bw)
        if (w%var(4, k) > 0) call put(r, w%var(4, k), g1c(cs, k, j))
        if (abs(j - k) <= w%kb) then
          call put(r, w%var(1, k), -dt2*w%ktn(k - j, j))
          call put(r, w%var(3, k), -dt2*w%ktt(k - j, j))
        end if
      end do
      w%rhs(r) = cs%slip_w(j)
      ! Tangential condition: open (G1 tau)_j = 0; slip (G1 tau)_j - mu
      ! sigma_j (G1 lambda)_j = 0; stick gt_j = 0 (eliminated).
      if (w%var(4, j) == 0) cycle
      r = w%var(4, j)
      w%rhs(r) = 0.0_wp
      if (w%status(j) == ST_SLIP) then
        do k = max(1, j - cs%g1_band), min(m, j + cs%g1_band)
          call put(r, w%var(3, k), g1c(cs, j, k))
          call put(r, w%var(1, k), -mu*w%sigma(j)*g1c(cs, j, k))
        end do
      else
        do k = max(1, j - cs%g1_band), min(m, j + cs%g1_band)
          call put(r, w%var(3, k), g1c(cs, j, k))
        end do
      end if
    end do
    ! Each row's first and last column as assembled: band_solve and
    ! scale_rows then skip the zeros outside them (the unit rows of the
    ! contact gaps, the short condition rows), with the same arithmetic.
    do r = 1, n
      if (w%lcol(r) == 0) then
        w%fcol(r) = r
        w%lcol(r) = r
      end if
    end do
    call scale_rows(n, kl, ku, w)
  contains
    subroutine put(i, jj, a)
      integer, intent(in) :: i, jj
      real(wp), intent(in) :: a
      ! LAPACK general band storage (dgbsv): AB(kl+ku+1+i-j, j) = A(i, j).
      w%ab(kl + ku + 1 + i - jj, jj) = w%ab(kl + ku + 1 + i - jj, jj) + a
      w%fcol(i) = min(w%fcol(i), jj)
      w%lcol(i) = max(w%lcol(i), jj)
    end subroutine put
  end subroutine assemble

  !> Scale each row to unit largest entry, by one reciprocal per row (a
  !> division per band entry was a quarter of the solve).
  subroutine scale_rows(n, kl, ku, w)
    integer, intent(in) :: n, kl, ku
    type(solver_work_t), intent(inout) :: w
    integer :: i, jj
    real(wp) :: s
    do i = 1, n
      s = 0.0_wp
      do jj = w%fcol(i), w%lcol(i)
        s = max(s, abs(w%ab(kl + ku + 1 + i - jj, jj)))
      end do
      if (s <= 0.0_wp) then
        ! An empty row: a constraint with no movable node. Pin its unknown.
        w%ab(kl + ku + 1, i) = 1.0_wp
        w%rhs(i) = 0.0_wp
        cycle
      end if
      s = 1.0_wp/s
      do jj = w%fcol(i), w%lcol(i)
        w%ab(kl + ku + 1 + i - jj, jj) = w%ab(kl + ku + 1 + i - jj, jj)*s
      end do
      w%rhs(i) = w%rhs(i)*s
    end do
  end subroutine scale_rows
  !> The saddle form with tangential corner multipliers (cs%tcorners, a
  !> Q8 slave with a multiplier on every trace node; issue #16 item 3,
  !> doc/reproduction.md, "The Q8 stick zigzag: tangential corner
  !> multipliers"). The normal unknowns and conditions are those of
  !> solve_saddle (every trace node, (19)); the tangential ones are a change
  !> of basis tau = T tau_c, gt = T gt_c, with T the identity on the owner
  !> rows (corners, master corner rows) and 1/2, 1/2 from a mid row to its
  !> edge's corners (P1: the corner's linear hat over the edge, psi_c +
  !> psi_m/2 on each neighbouring edge; P0: the cells' values with a mid
  !> cell at the mean of its corners'), and the tangential conditions
  !> tested with T': for owner c, with (T' v)_c = v_c + (v_m1 + v_m2)/2,
  !>   slip definition  T'(G1' T gt_c - dt^2 (Ktn lambda + Ktt T tau_c)) = T' s_w*,
  !>   stick            gt_c = 0,
  !>   slip             (T' G1 T tau_c)_c = mu sigma_c (T' G1 lambda)_c,
  !> i.e. the Coulomb bound of a corner is the normal force its own test
  !> function takes, the same test as the tangential force's (a uniform
  !> pressure gives the bound mu p times the hat's integral, as for the
  !> tangential force). The stick / slip set of an owner is kept apart
  !> from the normal set (w%tstat): a corner whose own row is open still
  !> carries the tangential test of its closed mid neighbours; where its
  !> whole support is open the bound is 0 and its tau_c comes out 0.
  !> On exit w%status is the usual one per row: open where the normal row
  !> is open, otherwise its owner's stick / slip (a mid row: slip when a
  !> corner slips); w%tau and w%gt of a mid row are T's mean.
  subroutine solve_saddle_tc(cs, dt, mu, bw0, max_iter, w, same)
    type(constraint_set_t), intent(in) :: cs
    real(wp), intent(in) :: dt, mu
    integer, intent(in) :: bw0                 !< half band of the couplings: max(kb, g1_band)
    integer, intent(in) :: max_iter
    type(solver_work_t), intent(inout) :: w
    logical, intent(out) :: same
    integer :: m, it, j, n, kl, ku, ldab, info, bw, s, a
    real(wp) :: gcc, kcc, wa

    m = cs%m
    same = .false.
    ! T reaches one row further on each side, a master corner row between
    ! a corner and its mid node one more.
    bw = bw0 + 4
    call ensure_i(w%tstat, m)
    call ensure_i(w%tstat_old, m)
    call ensure1(w%ct, m)
    call ensure1(w%rhs, 4*m)
    do j = 1, m
      if (cs%tcor(1, j) < 0) then
        w%tstat(j) = merge(ST_STICK, ST_SLIP, w%status(j) == ST_STICK)
        ! c of the tangential test: (G1~_cc)^2 / (dt^2 Ktt~_cc), the tested
        ! diagonals G1~ = T' G1 T, Ktt~ = T' Ktt T (as c_j of the rows)
        gcc = 0.0_wp
        kcc = 0.0_wp
        do s = 0, 2
          call tested_row(cs, j, s, a, wa)
          if (a > 0) call diag_sum(a, wa)
        end do
        w%ct(j) = 0.0_wp
        if (kcc > 0.0_wp) w%ct(j) = gcc**2/(dt*dt*kcc)
      else
        w%tstat(j) = ST_SLIP
        w%ct(j) = 0.0_wp
      end if
      if (w%status(j) /= ST_OPEN) w%status(j) = ST_STICK
    end do
    do it = max(1, w%iterations), max_iter
      w%iterations = it
      w%status_old(1:m) = w%status(1:m)
      w%tstat_old(1:m) = w%tstat(1:m)
      call layout_tc(cs, m, bw, w, n, kl, ku)
      ldab = 2*kl + ku + 1
      call ensure2(w%ab, ldab, n)
      call assemble_tc(cs, dt, mu, bw0, kl, ku, w)
      call band_solve(n, kl, ku, w%ab(1:ldab, 1:n), w%ipiv, w%rhs, w%fcol, w%lcol, w%ext, info)
      if (info /= 0) then
        w%converged = .false.
        w%singular = .true.
        exit
      end if
      do j = 1, m
        w%lam(j) = w%rhs(w%var(1, j))
        w%gn(j) = 0.0_wp
        if (w%var(2, j) > 0) w%gn(j) = w%rhs(w%var(2, j))
        w%tau(j) = 0.0_wp
        w%gt(j) = 0.0_wp
        if (w%var(3, j) > 0) w%tau(j) = w%rhs(w%var(3, j))
        if (w%var(4, j) > 0) w%gt(j) = w%rhs(w%var(4, j))
      end do
      do j = 1, m
        if (cs%tcor(1, j) < 0) cycle
        do s = 1, 2
          a = cs%tcor(s, j)
          if (a <= 0) cycle
          w%tau(j) = w%tau(j) + 0.5_wp*w%tau(a)
          w%gt(j) = w%gt(j) + 0.5_wp*w%gt(a)
        end do
      end do
      call band_matvec(cs, w%lam, w%fn)
      call band_matvec(cs, w%tau, w%ft)
      call update_sets_tc(cs, m, mu, w)
      same = all(w%status(1:m) == w%status_old(1:m)) .and. all(w%tstat(1:m) == w%tstat_old(1:m))
      if (same) exit
      if (it > LEAST_INDEX_AFTER) then
        call least_index_change(m, w)
        do j = 1, m
          if (w%status(j) /= w%status_old(j)) then
            w%tstat(1:m) = w%tstat_old(1:m)
            exit
          end if
        end do
      end if
    end do
    ! the sets handed back, one per row (header)
    do j = 1, m
      if (w%status(j) == ST_OPEN) cycle
      if (cs%tcor(1, j) < 0) then
        w%status(j) = w%tstat(j)
      else
        do s = 1, 2
          a = cs%tcor(s, j)
          if (a <= 0) cycle
          if (w%tstat(a) == ST_SLIP) w%status(j) = ST_SLIP
          w%sigma(j) = w%sigma(a)
        end do
      end if
    end do
  contains
    subroutine diag_sum(i, wi)
      integer, intent(in) :: i
      real(wp), intent(in) :: wi
      integer :: k, ss
      real(wp) :: wk
      do ss = 0, 2
        call tested_row(cs, j, ss, k, wk)
        if (k <= 0) cycle
        gcc = gcc + wi*wk*g1c(cs, i, k)
        if (abs(k - i) <= w%kb) kcc = kcc + wi*wk*w%ktt(k - i, i)
      end do
    end subroutine diag_sum
  end subroutine solve_saddle_tc

  !> Unknowns of solve_saddle_tc: lambda_j and gn_j (open) on every row;
  !> tau_j and gt_j (slip) on the owner rows only.
  subroutine layout_tc(cs, m, bw, w, n, kl, ku)
    type(constraint_set_t), intent(in) :: cs
    integer, intent(in) :: m, bw
    type(solver_work_t), intent(inout) :: w
    integer, intent(out) :: n, kl, ku
    integer :: j
    n = 0
    do j = 1, m
      w%vfirst(j) = n + 1
      n = n + 1
      w%var(1, j) = n
      w%var(2:4, j) = 0
      if (w%status(j) == ST_OPEN) then
        n = n + 1
        w%var(2, j) = n
      end if
      if (cs%tcor(1, j) < 0) then
        n = n + 1
        w%var(3, j) = n
        if (w%tstat(j) /= ST_STICK) then
          n = n + 1
          w%var(4, j) = n
        end if
      end if
    end do
    w%vfirst(m + 1) = n + 1
    call band_extent(m, n, bw, w, kl, ku)
  end subroutine layout_tc

  !> The banded system of solve_saddle_tc for the current sets (its header).
  subroutine assemble_tc(cs, dt, mu, bc, kl, ku, w)
    type(constraint_set_t), intent(in) :: cs
    real(wp), intent(in) :: dt, mu
    integer, intent(in) :: bc            !< half band of the couplings G1 and K: max(kb, g1_band)
    integer, intent(in) :: kl, ku
    type(solver_work_t), intent(inout) :: w
    integer :: j, k, m, r, n, i, s
    real(wp) :: dt2, wi
    m = cs%m
    dt2 = dt*dt
    n = w%vfirst(m + 1) - 1
    w%ab(1:2*kl + ku + 1, 1:n) = 0.0_wp
    do j = 1, m
      ! Gap definition: G1' gn - dt^2 (Knn lambda + Knt T tau_c) = g_w*.
      r = w%var(1, j)
      do k = max(1, j - bc), min(m, j + bc)
        if (w%var(2, k) > 0) call put(r, w%var(2, k), g1c(cs, k, j))
        if (abs(j - k) <= w%kb) then
          call put(r, w%var(1, k), -dt2*w%knn(k - j, j))
          call put_t(r, 3, k, -dt2*w%knt(k - j, j))
        end if
      end do
      w%rhs(r) = cs%gap_w(j)
      r = w%var(2, j)
      if (r > 0) then
        w%rhs(r) = 0.0_wp
        if (w%status(j) /= ST_OPEN) then
          call put(r, r, 1.0_wp)
        else
          do k = max(1, j - cs%g1_band), min(m, j + cs%g1_band)
            call put(r, w%var(1, k), g1c(cs, j, k))
          end do
        end if
      end if
      if (cs%tcor(1, j) >= 0) cycle
      ! Owner j: its slip definition and tangential condition tested with
      ! T' (its own row and half of each mid row that takes its value).
      ! Over the rows k that couple to the tested row i (G1 within
      ! g1_band, K within kb: bc): i lies up to two rows from j and T
      ! moves k's unknowns up to two rows further, so the columns stay
      ! within bc + 4 of j, the band layout_tc sized. (Over i +- (bc + 4),
      ! the zero terms beyond the coupling were put out of the band: an
      ! index past w%ab on the Q8 stick decks, and fcol/lcol widened past
      ! kl, ku.)
      r = w%var(3, j)
      w%rhs(r) = 0.0_wp
      do s = 0, 2
        call tested_row(cs, j, s, i, wi)
        if (i <= 0) cycle
        do k = max(1, i - bc), min(m, i + bc)
          call put_t(r, 4, k, wi*g1c(cs, k, i))
          if (abs(i - k) <= w%kb) then
            call put(r, w%var(1, k), -wi*dt2*w%ktn(k - i, i))
            call put_t(r, 3, k, -wi*dt2*w%ktt(k - i, i))
          end if
        end do
        w%rhs(r) = w%rhs(r) + wi*cs%slip_w(i)
      end do
      if (w%var(4, j) == 0) cycle
      ! slip: (T' G1 T tau_c)_j - mu sigma_j (T' G1 lambda)_j = 0
      r = w%var(4, j)
      w%rhs(r) = 0.0_wp
      do s = 0, 2
        call tested_row(cs, j, s, i, wi)
        if (i <= 0) cycle
        do k = max(1, i - cs%g1_band), min(m, i + cs%g1_band)
          call put_t(r, 3, k, wi*g1c(cs, i, k))
          call put(r, w%var(1, k), -mu*w%sigma(j)*wi*g1c(cs, i, k))
        end do
      end do
    end do
    do r = 1, n
      if (w%lcol(r) == 0) then
        w%fcol(r) = r
        w%lcol(r) = r
      end if
    end do
    call scale_rows(n, kl, ku, w)
  contains
    !> a times the tangential unknown (v = 3: tau, v = 4: gt) of row kk,
    !> through T: its own, or half of each of its corners'
    subroutine put_t(i0, v, kk, aa)
      integer, intent(in) :: i0, v, kk
      real(wp), intent(in) :: aa
      integer :: ss
      if (cs%tcor(1, kk) < 0) then
        if (w%var(v, kk) > 0) call put(i0, w%var(v, kk), aa)
      else
        do ss = 1, 2
          if (cs%tcor(ss, kk) <= 0) cycle
          if (w%var(v, cs%tcor(ss, kk)) > 0) call put(i0, w%var(v, cs%tcor(ss, kk)), 0.5_wp*aa)
        end do
      end if
    end subroutine put_t
    subroutine put(i0, jj, aa)
      integer, intent(in) :: i0, jj
      real(wp), intent(in) :: aa
      w%ab(kl + ku + 1 + i0 - jj, jj) = w%ab(kl + ku + 1 + i0 - jj, jj) + aa
      w%fcol(i0) = min(w%fcol(i0), jj)
      w%lcol(i0) = max(w%lcol(i0), jj)
    end subroutine put
  end subroutine assemble_tc

  !> Sets of solve_saddle_tc: the normal set of every row as update_sets
  !> without friction (w%status: open or in contact), the stick / slip set
  !> of every owner from its tested forces, stick when
  !> |T~_c - ct_c gt_c| <= mu F~_c with F~ = T' G1 lambda, T~ = T' G1 tau.
  subroutine update_sets_tc(cs, m, mu, w)
    type(constraint_set_t), intent(in) :: cs
    integer, intent(in) :: m
    real(wp), intent(in) :: mu
    type(solver_work_t), intent(inout) :: w
    integer :: j
    real(wp) :: fc, tc, z
    call update_sets(cs, m, mu, .false., w)
    do j = 1, m
      if (cs%tcor(1, j) >= 0) cycle
      fc = tested_sum(cs, w%fn, j)
      tc = tested_sum(cs, w%ft, j)
      z = tc - w%ct(j)*w%gt(j)
      if (fc > 0.0_wp .and. abs(z) <= mu*fc) then
        w%tstat(j) = ST_STICK
      else
        w%tstat(j) = ST_SLIP
        w%sigma(j) = sign(1.0_wp, z)
      end if
    end do
  end subroutine update_sets_tc
end module raccord_saddle_form
