!> The frictionless Delassus form of the multiplier solve
!> (doc/theory-contact.md, section 3): the active-set iteration on the
!> active multipliers alone, the open ones eliminated through the open
!> runs of G1, solved by band Cholesky.
module raccord_frictionless_form
  use raccord_kinds, only: wp
  use raccord_constraint_set, only: constraint_set_t
  use raccord_band_solver, only: band_cholesky_solve, zero_band
  use raccord_solver_work, only: solver_work_t, ST_OPEN, ZMAX, ensure1, ensure2, ensure_i, ensure_i2
  use raccord_solver_conditions, only: update_sets, holds_to_roundoff, band_matvec
  use raccord_g1_runs, only: open_from_active, run_solve
  implicit none
  private

  public :: solve_frictionless

contains

  !> Frictionless active-set iteration on the multipliers alone (the
  !> Delassus form; doc/theory-contact.md, section 3). For fixed sets, with
  !> A the active and O the open constraints, the conditions are
  !>   G1' gn - M lambda = g_w*  (M = dt^2 Knn),   gn_A = 0,   (G1 lambda)_O = 0.
  !> The open conditions give lambda_O = Z lambda_A, Z = -G1_OO^-1 G1_OA,
  !> nonzero only in the columns of the active constraints next to an open
  !> run (G1 is banded): lambda = N lambda_A with N = [I; Z]. N spans the
  !> null space of G1(O, :), so N' G1(O, :)' = 0 and the gap rows projected
  !> on N lose the unknown open gaps:
  !>   R lambda_A = -N' g_w*,   R = N' M N,
  !> symmetric positive definite and banded in the active numbering (half
  !> band at most kb + 2 g1_band), solved by band Cholesky. The open gaps
  !> then follow from the open rows, G1_OO' gn_O = g_w*_O + (M lambda)_O.
  !> Node-to-segment (G1 = I): Z = 0 and R = M_AA. The sets are updated as
  !> in the saddle form (update_sets), so the iteration and its result are
  !> those of the saddle form, to round-off. info /= 0 when the structure
  !> is not one this form takes (an open block of G1 singular, more active
  !> neighbours of an open run than ZMAX, R's band beyond the workspace, a
  !> pivot below CHOL_TOL of its diagonal): the caller then solves the
  !> saddle form.
  subroutine solve_frictionless(cs, dt, max_iter, w, same, info)
    type(constraint_set_t), intent(in) :: cs
    real(wp), intent(in) :: dt
    integer, intent(in) :: max_iter
    type(solver_work_t), intent(inout) :: w
    logical, intent(out) :: same
    integer, intent(out) :: info
    integer :: m, it, j, p, e, na, no, krcap, kr
    real(wp) :: v

    m = cs%m
    info = 0
    same = .false.
    krcap = 2*(w%kb + 2*cs%g1_band) + 2
    call ensure_i(w%ia, m)
    call ensure_i(w%olist, m)
    call ensure_i(w%zcnt, m)
    call ensure_i2(w%zcol, ZMAX, m)
    call ensure2(w%zval, ZMAX, m)
    call ensure2(w%rb, krcap + 1, m)
    call ensure1(w%xr, m)
    do it = 1, max_iter
      w%iterations = it
      w%status_old(1:m) = w%status(1:m)
      ! ia(j) > 0: index among the active constraints; < 0: minus the index among the open.
      na = 0
      no = 0
      do j = 1, m
        if (w%status(j) == ST_OPEN) then
          no = no + 1
          w%olist(no) = j
          w%ia(j) = -no
        else
          na = na + 1
          w%ia(j) = na
        end if
      end do
      call open_from_active(cs, w%olist, no, w%ia, w%zcnt, w%zcol, w%zval, w, info)
      if (info /= 0) return
      call reduced_matrix(cs, dt*dt, no, krcap, w, kr, info)
      if (info /= 0) return
      call band_cholesky_solve(na, kr, w%rb, w%xr, info)
      if (info /= 0) return
      do j = 1, m
        if (w%ia(j) > 0) w%lam(j) = w%xr(w%ia(j))
      end do
      do p = 1, no
        v = 0.0_wp
        do e = 1, w%zcnt(p)
          v = v + w%zval(e, p)*w%lam(w%zcol(e, p))
        end do
        w%lam(w%olist(p)) = v
      end do
      w%gn(1:m) = 0.0_wp
      w%tau(1:m) = 0.0_wp
      w%gt(1:m) = 0.0_wp
      w%ft(1:m) = 0.0_wp
      call open_gaps(cs, dt*dt, no, w, info)
      if (info /= 0) return
      call band_matvec(cs, w%lam, w%fn)
      ! an iterate that solves (19) to round-off ends a long iteration
      ! (holds_to_roundoff: sets that alternate on round-off)
      if (holds_to_roundoff(cs, 0.0_wp, .false., it, w)) then
        same = .true.
        exit
      end if
      call update_sets(cs, m, 0.0_wp, .false., w)
      same = all(w%status(1:m) == w%status_old(1:m))
      if (same) exit
    end do
    w%reduced_calls = w%reduced_calls + 1
  end subroutine solve_frictionless

  !> Gaps of the open constraints after the correction, run by run:
  !> G1_OO' gn_O = g_w*_O + (M lambda)_O (the gap rows of the open constraints).
  subroutine open_gaps(cs, dt2, no, w, info)
    type(constraint_set_t), intent(in) :: cs
    real(wp), intent(in) :: dt2
    integer, intent(in) :: no
    type(solver_work_t), intent(inout) :: w
    integer, intent(out) :: info
    integer :: p1, p2, p, nc, o, k
    real(wp) :: r
    info = 0
    p1 = 1
    do while (p1 <= no)
      p2 = p1
      do while (p2 < no)
        if (w%olist(p2 + 1) - w%olist(p2) > cs%g1_band) exit
        p2 = p2 + 1
      end do
      nc = p2 - p1 + 1
      do p = p1, p2
        o = w%olist(p)
        r = cs%gap_w(o)
        do k = max(1, o - w%kb), min(cs%m, o + w%kb)
          r = r + dt2*w%knn(k - o, o)*w%lam(k)
        end do
        w%xr(p - p1 + 1) = r
      end do
      if (nc == 1) then
        ! one open constraint alone (always so with G1 diagonal)
        if (cs%g1(0, w%olist(p1)) == 0.0_wp) then
          info = -1
          return
        end if
        w%xr(1) = w%xr(1)/cs%g1(0, w%olist(p1))
      else
        call run_solve(cs, w%olist, p1, nc, .true., w, info)
        if (info /= 0) return
      end if
      do p = p1, p2
        w%gn(w%olist(p)) = w%xr(p - p1 + 1)
      end do
      p1 = p2 + 1
    end do
  end subroutine open_gaps

  !> R = N' M N and its right-hand side -N' g_w* (in xr), in the active
  !> numbering, lower band: rb(d + 1, k) = R(k + d, k). M(a, b) = dt^2 Knn(a, b).
  !> R = M_AA + M_AO Z + (M_AO Z)' + Z' M_OO Z. The sums run in
  !> assemble_reduced on explicit-shape arrays (issue #16, fifth pass).
  subroutine reduced_matrix(cs, dt2, no, krcap, w, kr, info)
    type(constraint_set_t), intent(in) :: cs
    real(wp), intent(in) :: dt2
    integer, intent(in) :: no, krcap
    type(solver_work_t), intent(inout) :: w
    integer, intent(out) :: kr, info
    integer :: m
    m = cs%m
    call assemble_reduced(m, no, w%kb, ubound(w%knn, 1), size(w%knn, 2), krcap, size(w%rb, 1), &
      size(w%rb, 2), dt2, cs%gap_w(1:m), w%knn, w%ia(1:m), w%olist(1:max(no, 1)), &
      w%zcnt(1:max(no, 1)), w%zcol(:, 1:max(no, 1)), w%zval(:, 1:max(no, 1)), w%rb, w%xr(1:m), kr, info)
  end subroutine reduced_matrix

  !> reduced_matrix on explicit-shape arrays: the same sums in the same order.
  subroutine assemble_reduced(m, no, kb, kbs, ncap, krcap, ldr, nrcap, dt2, gap_w, knn, ia, olist, &
      zcnt, zcol, zval, rb, xr, kr, info)
    integer, intent(in) :: m, no, kb, kbs, ncap, krcap, ldr, nrcap
    real(wp), intent(in) :: dt2, gap_w(m), knn(-kbs:kbs, ncap)
    integer, intent(in) :: ia(m), olist(*), zcnt(*), zcol(ZMAX, *)
    real(wp), intent(in) :: zval(ZMAX, *)
    real(wp), intent(inout) :: rb(ldr, nrcap), xr(m)
    integer, intent(out) :: kr, info
    integer :: a, b, p, q, e, e2, o, o2, na
    real(wp) :: z, v, mo
    info = 0
    kr = 0
    na = 0
    do a = 1, m
      if (ia(a) > 0) na = na + 1
    end do
    ! whole columns of rb in one pass (the rows below krcap + 1 are not read)
    call zero_band(ldr*na, rb)
    do a = 1, m
      if (ia(a) <= 0) cycle
      xr(ia(a)) = -gap_w(a)
      do b = max(1, a - kb), a
        if (ia(b) <= 0) cycle
        ! K(a, b) is stored as knn(b - a, a)
        call add(ia(a), ia(b), dt2*knn(b - a, a))
      end do
    end do
    do p = 1, no
      o = olist(p)
      do e = 1, zcnt(p)
        b = zcol(e, p)
        z = zval(e, p)
        xr(ia(b)) = xr(ia(b)) - z*gap_w(o)
        ! M_AO Z and its transpose: one entry of the lower band each (twice on the diagonal)
        do a = max(1, o - kb), min(m, o + kb)
          if (ia(a) <= 0) cycle
          v = z*dt2*knn(o - a, a)
          if (a == b) v = 2.0_wp*v
          call add(max(ia(a), ia(b)), min(ia(a), ia(b)), v)
        end do
        ! Z' M_OO Z, the lower half
        do o2 = max(1, o - kb), min(m, o + kb)
          if (ia(o2) >= 0) cycle
          q = -ia(o2)
          mo = z*dt2*knn(o2 - o, o)
          do e2 = 1, zcnt(q)
            if (ia(b) < ia(zcol(e2, q))) cycle
            call add(ia(b), ia(zcol(e2, q)), mo*zval(e2, q))
          end do
        end do
      end do
    end do
  contains
    subroutine add(i, k, x)
      integer, intent(in) :: i, k
      real(wp), intent(in) :: x
      if (i - k > krcap) then
        info = -2
        return
      end if
      kr = max(kr, i - k)
      rb(i - k + 1, k) = rb(i - k + 1, k) + x
    end subroutine add
  end subroutine assemble_reduced
end module raccord_frictionless_form
