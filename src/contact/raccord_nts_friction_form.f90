!> The frictional form of the multiplier solve for a diagonal G1
!> (node-to-segment; doc/theory-contact.md, section 3): the active-set
!> iteration on lambda of the active and tau of the sticking constraints.
module raccord_nts_friction_form
  use raccord_kinds, only: wp
  use raccord_constraint_set, only: constraint_set_t
  use raccord_band_solver, only: band_solve
  use raccord_solver_work, only: solver_work_t, ST_OPEN, ST_STICK, ST_SLIP, ensure2
  use raccord_solver_conditions, only: update_sets, holds_to_roundoff, band_matvec
  use raccord_saddle_form, only: scale_rows
  implicit none
  private

  public :: solve_diagonal_friction

contains

  !> Frictional active-set iteration on the multipliers alone when G1 is
  !> diagonal (node-to-segment; doc/theory-contact.md, section 3). The
  !> conditions then read constraint by constraint: open lambda_j = tau_j = 0,
  !> slip tau_j = mu sigma_j lambda_j, contact gn_j = 0, stick gt_j = 0, so
  !> for fixed sets the unknowns are lambda_j of the active and tau_j of the
  !> sticking constraints, interleaved, and the rows the Delassus rows
  !>   dt^2 (Knn lambda + Knt tau)_j = -g_w*_j   (j active),
  !>   dt^2 (Ktn lambda + Ktt tau)_j = -s_w*_j   (j sticking),
  !> with tau of the slipping ones substituted: nonsymmetric when some slip,
  !> solved by the band LU with rows scaled as in the saddle form. The gaps
  !> and slips of the other constraints follow from their rows. info /= 0 (a
  !> singular system or a zero G1_jj): the caller solves the saddle form.
  subroutine solve_diagonal_friction(cs, dt, mu, max_iter, w, same, info)
    type(constraint_set_t), intent(in) :: cs
    real(wp), intent(in) :: dt, mu
    integer, intent(in) :: max_iter
    type(solver_work_t), intent(inout) :: w
    logical, intent(out) :: same
    integer, intent(out) :: info
    integer :: m, it, j, k, n, kl, ku, ldab, kb, r
    real(wp) :: dt2, sn, st

    m = cs%m
    kb = w%kb
    dt2 = dt*dt
    info = 0
    same = .false.
    if (any(cs%g1(0, 1:m) == 0.0_wp)) then
      info = -1
      return
    end if
    do it = 1, max_iter
      w%iterations = it
      w%status_old(1:m) = w%status(1:m)
      ! Unknowns: lambda_j (var(1, j)) if active, tau_j (var(3, j)) if sticking.
      n = 0
      do j = 1, m
        w%vfirst(j) = n + 1
        w%var(:, j) = 0
        if (w%status(j) == ST_OPEN) cycle
        n = n + 1
        w%var(1, j) = n
        if (w%status(j) == ST_STICK) then
          n = n + 1
          w%var(3, j) = n
        end if
      end do
      w%vfirst(m + 1) = n + 1
      kl = 0
      ku = 0
      do j = 1, m
        ku = max(ku, w%vfirst(min(m, j + kb) + 1) - 1 - w%vfirst(j))
        kl = max(kl, w%vfirst(j + 1) - 1 - w%vfirst(max(1, j - kb)))
        do r = w%vfirst(j), w%vfirst(j + 1) - 1
          w%fcol(r) = w%vfirst(max(1, j - kb))
          w%lcol(r) = w%vfirst(min(m, j + kb) + 1) - 1
        end do
      end do
      ldab = 2*kl + ku + 1
      if (n > 0) then
        call ensure2(w%ab, ldab, n)
        w%ab(1:ldab, 1:n) = 0.0_wp
        do j = 1, m
          if (w%var(1, j) == 0) cycle
          w%rhs(w%var(1, j)) = -cs%gap_w(j)
          if (w%var(3, j) > 0) w%rhs(w%var(3, j)) = -cs%slip_w(j)
          do k = max(1, j - kb), min(m, j + kb)
            if (w%var(1, k) == 0) cycle
            ! column lambda_k, with tau_k = mu sigma_k lambda_k when k slips
            sn = 0.0_wp
            st = 0.0_wp
            if (w%status(k) == ST_SLIP) then
              sn = mu*w%sigma(k)*w%knt(k - j, j)
              st = mu*w%sigma(k)*w%ktt(k - j, j)
            end if
            call put(w%var(1, j), w%var(1, k), dt2*(w%knn(k - j, j) + sn))
            if (w%var(3, j) > 0) call put(w%var(3, j), w%var(1, k), dt2*(w%ktn(k - j, j) + st))
            if (w%var(3, k) > 0) then
              call put(w%var(1, j), w%var(3, k), dt2*w%knt(k - j, j))
              if (w%var(3, j) > 0) call put(w%var(3, j), w%var(3, k), dt2*w%ktt(k - j, j))
            end if
          end do
        end do
        call scale_rows(n, kl, ku, w)
        call band_solve(n, kl, ku, w%ab(1:ldab, 1:n), w%ipiv, w%rhs, w%fcol, w%lcol, w%ext, info)
        if (info /= 0) return
      end if
      do j = 1, m
        w%lam(j) = 0.0_wp
        w%tau(j) = 0.0_wp
        if (w%var(1, j) > 0) w%lam(j) = w%rhs(w%var(1, j))
        if (w%var(3, j) > 0) w%tau(j) = w%rhs(w%var(3, j))
        if (w%status(j) == ST_SLIP) w%tau(j) = mu*w%sigma(j)*w%lam(j)
      end do
      ! Gaps of the open, slips of the open and slipping constraints.
      do j = 1, m
        w%gn(j) = 0.0_wp
        w%gt(j) = 0.0_wp
        if (w%status(j) == ST_STICK) cycle
        sn = cs%gap_w(j)
        st = cs%slip_w(j)
        do k = max(1, j - kb), min(m, j + kb)
          sn = sn + dt2*(w%knn(k - j, j)*w%lam(k) + w%knt(k - j, j)*w%tau(k))
          st = st + dt2*(w%ktn(k - j, j)*w%lam(k) + w%ktt(k - j, j)*w%tau(k))
        end do
        if (w%status(j) == ST_OPEN) w%gn(j) = sn/cs%g1(0, j)
        w%gt(j) = st/cs%g1(0, j)
      end do
      call band_matvec(cs, w%lam, w%fn)
      call band_matvec(cs, w%tau, w%ft)
      ! an iterate that solves (19) to round-off ends a long iteration
      ! (holds_to_roundoff: sets that alternate on round-off)
      if (holds_to_roundoff(cs, mu, .true., it, w)) then
        same = .true.
        exit
      end if
      call update_sets(cs, m, mu, .true., w)
      same = all(w%status(1:m) == w%status_old(1:m))
      if (same) exit
    end do
    w%reduced_calls = w%reduced_calls + 1
  contains
    subroutine put(i, jj, a)
      integer, intent(in) :: i, jj
      real(wp), intent(in) :: a
      w%ab(kl + ku + 1 + i - jj, jj) = w%ab(kl + ku + 1 + i - jj, jj) + a
    end subroutine put
  end subroutine solve_diagonal_friction
end module raccord_nts_friction_form
