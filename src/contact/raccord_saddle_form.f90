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
  use raccord_solver_work, only: solver_work_t, ST_OPEN, ST_STICK, ST_SLIP, ensure2
  use raccord_solver_conditions, only: LEAST_INDEX_AFTER, least_index_change, update_sets, &
    holds_to_roundoff, band_matvec, g1c
  implicit none
  private

  !> Saddle form (friction with a banded G1): leave out the known gaps of
  !> the constraints in contact (their unit rows).
  logical, parameter :: eliminate_gaps = .true.

  public :: solve_saddle, scale_rows

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
    integer :: j, i
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
    ! Rows of j couple to the unknowns of k = j - bw .. j + bw.
    kl = 0
    ku = 0
    do j = 1, m
      ku = max(ku, w%vfirst(min(m, j + bw) + 1) - 1 - w%vfirst(j))
      kl = max(kl, w%vfirst(j + 1) - 1 - w%vfirst(max(1, j - bw)))
      ! The row profiles are found by assemble (a contact row is a unit row).
      do i = w%vfirst(j), w%vfirst(j + 1) - 1
        w%fcol(i) = n + 1
        w%lcol(i) = 0
      end do
    end do
  end subroutine layout

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
end module raccord_saddle_form
