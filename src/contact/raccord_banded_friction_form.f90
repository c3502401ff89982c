!> The frictional form of the multiplier solve for a banded G1 (mortar;
!> doc/theory-contact.md, section 3, "Friction with a banded G1"): the
!> active-set iteration on lambda of the active and q = tau - mu S lambda
!> of the sticking constraints, the q next to a long slip zone bordered
!> (Schur complement).
module raccord_banded_friction_form
  use raccord_kinds, only: wp
  use raccord_constraint_set, only: constraint_set_t
  use raccord_band_solver, only: band_factor, band_subst
  use raccord_solver_work, only: solver_work_t, ST_OPEN, ST_STICK, ST_SLIP, ZMAX, &
    ensure1, ensure2, ensure_i, ensure_i2
  use raccord_solver_conditions, only: LEAST_INDEX_AFTER, least_index_change, update_sets, &
    holds_to_roundoff, band_matvec
  use raccord_g1_runs, only: open_from_active, run_transposed
  implicit none
  private

  !> Reduced form with friction and a banded G1: a stick constraint next to
  !> a run of open and slipping constraints with at least BORDER_SLIP
  !> slipping ones takes a border unknown (its column of Z_t is dense over
  !> the run); at most BORDER_MAX of them, else the saddle form.
  integer, parameter :: BORDER_SLIP = 8, BORDER_MAX = 12

  public :: solve_banded_friction

contains

  !> Frictional active-set iteration with a banded G1 (mortar) on the
  !> active multipliers and the sticking tangential ones (doc/theory-contact.md,
  !> section 3, "Friction with a banded G1"). With tau = q + mu S lambda,
  !> S = diag(s) and s_k = sigma_j for every k in row j of G1 of every
  !> slipping j (constant over the row of an open j), the slip condition
  !> (G1 tau)_j = mu sigma_j (G1 lambda)_j and the open one (G1 tau)_j = 0
  !> both read (G1 q)_j = 0. So, as the open multipliers in the
  !> frictionless form, lambda = N_n lambda_A (N_n = [I; Z_n], Z_n =
  !> -G1_OO^-1 G1_OA) and q = N_t q_K (N_t = [I; Z_t], Z_t = -G1_UU^-1 G1_UK,
  !> K stick, U open or slip), N_n' G1' and N_t' G1' remove the unknown
  !> gaps and slips, and for fixed sets
  !>   N_n' [(Mnn + mu Mnt S) N_n lambda_A + Mnt N_t q_K] = -N_n' g_w*
  !>   N_t' [(Mtn + mu Mtt S) N_n lambda_A + Mtt N_t q_K] = -N_t' s_w*
  !> (M = dt^2 K), banded in the unknowns lambda_j, q_j interleaved by
  !> constraint except for the q_k next to a slip zone: Z_t's column is
  !> dense over the zone, so those few (border) unknowns are eliminated by
  !> their Schur complement (solve_bordered). The gaps and slips of the
  !> others follow from their rows, run by run. Same update rule as the
  !> saddle form (update_sets, least_index_change after LEAST_INDEX_AFTER),
  !> so the same sets and iterations to round-off. info /= 0: no such s (a
  !> change of slip direction within 2 g1_band constraints), a singular
  !> block, more than ZMAX neighbours or BORDER_MAX border unknowns: the
  !> caller solves the saddle form.
  subroutine solve_banded_friction(cs, dt, mu, max_iter, w, same, info)
    type(constraint_set_t), intent(in) :: cs
    real(wp), intent(in) :: dt, mu
    integer, intent(in) :: max_iter
    type(solver_work_t), intent(inout) :: w
    logical, intent(out) :: same
    integer, intent(out) :: info
    integer :: m, it, j, k, p, e, na, no, nu, n, nb, kl, ku, ldab, g1b
    real(wp) :: dt2, v
    real(wp), allocatable :: abuf(:,:)

    m = cs%m
    g1b = cs%g1_band
    dt2 = dt*dt
    info = 0
    same = .false.
    call ensure_i(w%ia, m)
    call ensure_i(w%olist, m)
    call ensure_i(w%zcnt, m)
    call ensure_i2(w%zcol, ZMAX, m)
    call ensure2(w%zval, ZMAX, m)
    call ensure1(w%xr, m)
    call ensure1(w%rowsc, 2*m)
    call ensure_i(w%it, m)
    call ensure_i(w%ulist, m)
    call ensure_i(w%ztcnt, m)
    call ensure_i2(w%ztcol, ZMAX, m)
    call ensure2(w%ztval, ZMAX, m)
    call ensure_i(w%ulam, m)
    call ensure_i(w%uq, m)
    call ensure_i(w%bmark, m)
    call ensure1(w%sgn, m)
    call ensure1(w%qv, m)
    call ensure_i(w%ncnt, m)
    call ensure_i2(w%ncol, ZMAX, m)
    call ensure2(w%nval, ZMAX, m)
    call ensure_i(w%tcnt, m)
    call ensure_i2(w%tcol, ZMAX, m)
    call ensure2(w%tval, ZMAX, m)
    call ensure2(w%bc, 2*m, BORDER_MAX)
    call ensure2(w%bd, 2*m, BORDER_MAX)
    call ensure2(w%bx, 2*m, BORDER_MAX)
    call ensure2(w%be, BORDER_MAX, BORDER_MAX + 1)
    call ensure1(w%bg, BORDER_MAX)
    do it = 1, max_iter
      w%iterations = it
      w%status_old(1:m) = w%status(1:m)
      ! Normal: ia(j) > 0 index among the active, < 0 minus that among the open.
      ! Tangential: it(j) > 0 stick, < 0 minus the index among the open or slipping.
      na = 0
      no = 0
      nu = 0
      do j = 1, m
        if (w%status(j) == ST_OPEN) then
          no = no + 1
          w%olist(no) = j
          w%ia(j) = -no
        else
          na = na + 1
          w%ia(j) = na
        end if
        if (w%status(j) == ST_STICK) then
          w%it(j) = 1
        else
          nu = nu + 1
          w%ulist(nu) = j
          w%it(j) = -nu
        end if
      end do
      call slip_signs(cs, w, info)
      if (info /= 0) return
      call open_from_active(cs, w%olist, no, w%ia, w%zcnt, w%zcol, w%zval, w, info)
      if (info /= 0) return
      call open_from_active(cs, w%ulist, nu, w%it, w%ztcnt, w%ztcol, w%ztval, w, info)
      if (info /= 0) return
      call number_unknowns(cs, nu, w, n, nb, info)
      if (info /= 0) return
      w%border_unknowns = nb
      call friction_profile(cs, n, w, kl, ku)
      ldab = 2*kl + ku + 1
      call ensure2(w%ab, ldab, n)
      ! (w%ab lent to friction_matrix as a separate argument: moved out of
      ! w and back, no copy and no allocation)
      call move_alloc(w%ab, abuf)
      call friction_matrix(cs, dt2, mu, n, nb, kl, ku, w, abuf, info)
      call move_alloc(abuf, w%ab)
      if (info /= 0) return
      call solve_bordered(n, nb, kl, ku, w, info)
      if (info /= 0) return
      ! lambda = N_n x, q = N_t x, tau = q + mu S lambda
      do j = 1, m
        v = 0.0_wp
        do e = 1, w%ncnt(j)
          v = v + w%nval(e, j)*unknown(w%ncol(e, j))
        end do
        w%lam(j) = v
        v = 0.0_wp
        do e = 1, w%tcnt(j)
          v = v + w%tval(e, j)*unknown(w%tcol(e, j))
        end do
        w%qv(j) = v
      end do
      do j = 1, m
        w%tau(j) = w%qv(j) + mu*w%sgn(j)*w%lam(j)
      end do
      ! Gaps of the open, slips of the open and slipping constraints, from
      ! their rows (G1_OO' gn_O = (g_w* + M lambda ...)_O, run by run).
      do j = 1, m
        w%gn(j) = 0.0_wp
        w%gt(j) = 0.0_wp
      end do
      do p = 1, no
        j = w%olist(p)
        v = cs%gap_w(j)
        do k = max(1, j - w%kb), min(m, j + w%kb)
          v = v + dt2*(w%knn(k - j, j)*w%lam(k) + w%knt(k - j, j)*w%tau(k))
        end do
        w%gn(j) = v
      end do
      call run_transposed(cs, w%olist, no, w%gn, w, info)
      if (info /= 0) return
      do p = 1, nu
        j = w%ulist(p)
        v = cs%slip_w(j)
        do k = max(1, j - w%kb), min(m, j + w%kb)
          v = v + dt2*(w%ktn(k - j, j)*w%lam(k) + w%ktt(k - j, j)*w%tau(k))
        end do
        w%gt(j) = v
      end do
      call run_transposed(cs, w%ulist, nu, w%gt, w, info)
      if (info /= 0) return
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
      if (it > LEAST_INDEX_AFTER) call least_index_change(m, w)
    end do
    w%reduced_calls = w%reduced_calls + 1
  contains
    real(wp) function unknown(c)
      integer, intent(in) :: c
      if (c > 0) then
        unknown = w%rhs(c)
      else
        unknown = w%bg(-c)
      end if
    end function unknown
  end subroutine solve_banded_friction

  !> The sign s of tau = q + mu S lambda (solve_banded_friction): s_k =
  !> sigma_j over row j of G1 of each slipping j, then spread along the
  !> open runs so that it is constant over every open row (forward and
  !> backward), 0 where nothing asks for a sign. info = -3 when some row of
  !> an open or slipping constraint cannot have it (slip directions that
  !> change within 2 g1_band constraints). (k stays within the band of j:
  !> G1(j, k) is read as g1(j - k, k), the inlined g1_at.)
  subroutine slip_signs(cs, w, info)
    type(constraint_set_t), intent(in) :: cs
    type(solver_work_t), intent(inout) :: w
    integer, intent(out) :: info
    integer :: m, j, k, g1b, pass, j0, j1, dj
    real(wp) :: sj
    m = cs%m
    g1b = cs%g1_band
    info = 0
    w%sgn(1:m) = 0.0_wp
    do j = 1, m
      if (w%status(j) /= ST_SLIP) cycle
      do k = max(1, j - g1b), min(m, j + g1b)
        if (cs%g1(j - k, k) == 0.0_wp) cycle
        if (w%sgn(k) == 0.0_wp) then
          w%sgn(k) = w%sigma(j)
        else if (w%sgn(k) /= w%sigma(j)) then
          info = -3
          return
        end if
      end do
    end do
    do pass = 1, 2
      if (pass == 1) then
        j0 = 1
        j1 = m
        dj = 1
      else
        j0 = m
        j1 = 1
        dj = -1
      end if
      do j = j0, j1, dj
        if (w%status(j) /= ST_OPEN) cycle
        sj = 0.0_wp
        do k = max(1, j - g1b), min(m, j + g1b)
          if (cs%g1(j - k, k) /= 0.0_wp .and. w%sgn(k) /= 0.0_wp) sj = w%sgn(k)
        end do
        if (sj == 0.0_wp) cycle
        do k = max(1, j - g1b), min(m, j + g1b)
          if (cs%g1(j - k, k) /= 0.0_wp .and. w%sgn(k) == 0.0_wp) w%sgn(k) = sj
        end do
      end do
    end do
    ! Check: constant over every open and slipping row, sigma_j on a slipping one.
    do j = 1, m
      if (w%status(j) == ST_STICK) cycle
      sj = w%sgn(j)
      if (w%status(j) == ST_SLIP) sj = w%sigma(j)
      do k = max(1, j - g1b), min(m, j + g1b)
        if (cs%g1(j - k, k) == 0.0_wp) cycle
        if (w%sgn(k) /= sj) then
          info = -3
          return
        end if
      end do
    end do
  end subroutine slip_signs

  !> Unknowns of solve_banded_friction: lambda_j of the active and q_j of
  !> the sticking constraints, interleaved in constraint order, except the
  !> q_k next to a run of open and slipping constraints with
  !> BORDER_SLIP or more slipping ones (their column of Z_t is dense over
  !> the run): those are numbered apart, -1, -2, ... (at most BORDER_MAX).
  !> Then the rows of N_n and N_t in these unknowns.
  subroutine number_unknowns(cs, nu, w, n, nb, info)
    type(constraint_set_t), intent(in) :: cs
    integer, intent(in) :: nu
    type(solver_work_t), intent(inout) :: w
    integer, intent(out) :: n, nb, info
    integer :: m, j, p, p1, p2, e, ns, g1b
    m = cs%m
    g1b = cs%g1_band
    info = 0
    w%bmark(1:m) = 0
    p1 = 1
    do while (p1 <= nu)
      p2 = p1
      do while (p2 < nu)
        if (w%ulist(p2 + 1) - w%ulist(p2) > g1b) exit
        p2 = p2 + 1
      end do
      ! (a loop: count over a vector subscript allocated a temporary per run)
      ns = 0
      do p = p1, p2
        if (w%status(w%ulist(p)) == ST_SLIP) ns = ns + 1
      end do
      if (ns >= BORDER_SLIP) then
        do p = p1, p2
          do e = 1, w%ztcnt(p)
            w%bmark(w%ztcol(e, p)) = 1
          end do
        end do
      end if
      p1 = p2 + 1
    end do
    n = 0
    nb = 0
    do j = 1, m
      w%ulam(j) = 0
      w%uq(j) = 0
      if (w%status(j) /= ST_OPEN) then
        n = n + 1
        w%ulam(j) = n
      end if
      if (w%status(j) == ST_STICK) then
        if (w%bmark(j) /= 0) then
          nb = nb + 1
          if (nb > BORDER_MAX) then
            info = -4
            return
          end if
          w%uq(j) = -nb
        else
          n = n + 1
          w%uq(j) = n
        end if
      end if
    end do
    do j = 1, m
      if (w%ia(j) > 0) then
        w%ncnt(j) = 1
        w%ncol(1, j) = w%ulam(j)
        w%nval(1, j) = 1.0_wp
      else
        p = -w%ia(j)
        w%ncnt(j) = w%zcnt(p)
        do e = 1, w%zcnt(p)
          w%ncol(e, j) = w%ulam(w%zcol(e, p))
          w%nval(e, j) = w%zval(e, p)
        end do
      end if
      if (w%it(j) > 0) then
        w%tcnt(j) = 1
        w%tcol(1, j) = w%uq(j)
        w%tval(1, j) = 1.0_wp
      else
        p = -w%it(j)
        w%tcnt(j) = w%ztcnt(p)
        do e = 1, w%ztcnt(p)
          w%tcol(e, j) = w%uq(w%ztcol(e, p))
          w%tval(e, j) = w%ztval(e, p)
        end do
      end if
      ! bmark(j) > 0 from here on: both rows of N at j are unit rows of
      ! banded unknowns or empty (friction_matrix's short cut)
      w%bmark(j) = 0
      if ((w%ia(j) > 0 .or. w%ncnt(j) == 0) .and. ((w%it(j) > 0 .and. w%uq(j) > 0) .or. w%tcnt(j) == 0)) &
        w%bmark(j) = 1
    end do
  end subroutine number_unknowns

  !> Each banded row's first and last column (fcol, lcol) and the half
  !> bands: row r of N(i, :) meets the columns of N(k, :) for |i - k| <= kb.
  subroutine friction_profile(cs, n, w, kl, ku)
    type(constraint_set_t), intent(in) :: cs
    integer, intent(in) :: n
    type(solver_work_t), intent(inout) :: w
    integer, intent(out) :: kl, ku
    integer :: m, i, k, e, c, lo, hi, r
    m = cs%m
    ! xr-sized integer scratch: the least and largest banded column of row i of N
    w%fcol(1:n) = n + 1
    w%lcol(1:n) = 0
    do i = 1, m
      w%ext(i) = n + 1
      w%ext(m + i) = 0
      do e = 1, w%ncnt(i)
        c = w%ncol(e, i)
        if (c > 0) then
          w%ext(i) = min(w%ext(i), c)
          w%ext(m + i) = max(w%ext(m + i), c)
        end if
      end do
      do e = 1, w%tcnt(i)
        c = w%tcol(e, i)
        if (c > 0) then
          w%ext(i) = min(w%ext(i), c)
          w%ext(m + i) = max(w%ext(m + i), c)
        end if
      end do
    end do
    do i = 1, m
      if (w%ext(m + i) == 0) cycle
      lo = n + 1
      hi = 0
      do k = max(1, i - w%kb), min(m, i + w%kb)
        lo = min(lo, w%ext(k))
        hi = max(hi, w%ext(m + k))
      end do
      do e = 1, w%ncnt(i)
        r = w%ncol(e, i)
        if (r <= 0) cycle
        w%fcol(r) = min(w%fcol(r), lo)
        w%lcol(r) = max(w%lcol(r), hi)
      end do
      do e = 1, w%tcnt(i)
        r = w%tcol(e, i)
        if (r <= 0) cycle
        w%fcol(r) = min(w%fcol(r), lo)
        w%lcol(r) = max(w%lcol(r), hi)
      end do
    end do
    kl = 0
    ku = 0
    do r = 1, n
      if (w%lcol(r) == 0) then
        w%fcol(r) = r
        w%lcol(r) = r
      end if
      kl = max(kl, r - w%fcol(r))
      ku = max(ku, w%lcol(r) - r)
    end do
  end subroutine friction_profile

  !> The matrix and right-hand side of solve_banded_friction: the banded
  !> block B in w%ab (general band storage), the border columns C (bc),
  !> rows D' (bd: bd(c, b) = row b, column c) and block E (be), the
  !> right-hand sides in rhs and bg. Banded rows are scaled to unit largest
  !> entry (over B and C), as in the saddle form. B is w%ab's storage
  !> passed as ab, one contiguous (2 kl + ku + 1, n) block (zeroed in one
  !> pass). (The
  !> same sums moved into an explicit-shape kernel ran 10 % slower on
  !> Fig. 3: inlined into the driver, the four block updates of a pair
  !> compiled worse; issue #16, fifth pass.)
  subroutine friction_matrix(cs, dt2, mu, n, nb, kl, ku, w, ab, info)
    type(constraint_set_t), intent(in) :: cs
    real(wp), intent(in) :: dt2, mu
    integer, intent(in) :: n, nb, kl, ku
    type(solver_work_t), intent(inout) :: w     !< (its ab moved out into the argument ab)
    real(wp), intent(inout) :: ab(2*kl + ku + 1, n)   !< w%ab's storage as one contiguous block
    integer, intent(out) :: info
    integer :: m, i, k, kv, rn, rt, cn, ct
    real(wp) :: ann, ant, atn, att
    m = cs%m
    info = 0
    kv = kl + ku + 1
    ab = 0.0_wp
    w%rhs(1:n) = 0.0_wp
    if (nb > 0) then
      w%bc(1:n, 1:nb) = 0.0_wp
      w%bd(1:n, 1:nb) = 0.0_wp
      w%be(1:nb, 1:nb) = 0.0_wp
      w%bg(1:nb) = 0.0_wp
    end if
    do i = 1, m
      if (w%ncnt(i) == 0 .and. w%tcnt(i) == 0) cycle
      call add_rhs(w%ncnt(i), w%ncol(:, i), w%nval(:, i), -cs%gap_w(i))
      call add_rhs(w%tcnt(i), w%tcol(:, i), w%tval(:, i), -cs%slip_w(i))
      do k = max(1, i - w%kb), min(m, i + w%kb)
        if (w%ncnt(k) == 0 .and. w%tcnt(k) == 0) cycle
        ! (Mnn + mu Mnt S)(i, k), Mnt, (Mtn + mu Mtt S), Mtt; K(i, k) = k(k - i, i)
        ant = dt2*w%knt(k - i, i)
        att = dt2*w%ktt(k - i, i)
        ann = dt2*w%knn(k - i, i) + mu*w%sgn(k)*ant
        atn = dt2*w%ktn(k - i, i) + mu*w%sgn(k)*att
        if (w%bmark(i) > 0 .and. w%bmark(k) > 0) then
          ! both rows of N unit rows or empty (no open or slipping neighbour, no border):
          ! the same sums as add_block's
          rn = w%ulam(i)
          rt = max(w%uq(i), 0)
          cn = w%ulam(k)
          ct = max(w%uq(k), 0)
          if (rn > 0) then
            if (cn > 0) ab(kv + rn - cn, cn) = ab(kv + rn - cn, cn) + ann
            if (ct > 0) ab(kv + rn - ct, ct) = ab(kv + rn - ct, ct) + ant
          end if
          if (rt > 0) then
            if (cn > 0) ab(kv + rt - cn, cn) = ab(kv + rt - cn, cn) + atn
            if (ct > 0) ab(kv + rt - ct, ct) = ab(kv + rt - ct, ct) + att
          end if
          cycle
        end if
        call add_block(w%ncnt(i), w%ncol(:, i), w%nval(:, i), w%ncnt(k), w%ncol(:, k), w%nval(:, k), ann)
        call add_block(w%ncnt(i), w%ncol(:, i), w%nval(:, i), w%tcnt(k), w%tcol(:, k), w%tval(:, k), ant)
        call add_block(w%tcnt(i), w%tcol(:, i), w%tval(:, i), w%ncnt(k), w%ncol(:, k), w%nval(:, k), atn)
        call add_block(w%tcnt(i), w%tcol(:, i), w%tval(:, i), w%tcnt(k), w%tcol(:, k), w%tval(:, k), att)
      end do
    end do
    ! Row scaling, column by column (contiguous in the band storage; by
    ! rows it ran along the band's diagonals, a cache line per entry):
    ! rowsc(r), the largest magnitude in row r over B and C, then
    ! 1/rowsc(r) times each entry of the row, the same factor per entry as
    ! row by row (the band outside the rows' profiles is zero). Issue #16,
    ! sixth pass.
    call scale_rows(n, nb, kl, ku, size(w%bc, 1), ab, w%bc, w%rhs, w%rowsc, info)
  contains
    subroutine add_rhs(cnt, col, val, g)
      integer, intent(in) :: cnt, col(:)
      real(wp), intent(in) :: val(:), g
      integer :: e
      do e = 1, cnt
        if (col(e) > 0) then
          w%rhs(col(e)) = w%rhs(col(e)) + val(e)*g
        else
          w%bg(-col(e)) = w%bg(-col(e)) + val(e)*g
        end if
      end do
    end subroutine add_rhs
    subroutine add_block(cr, colr, valr, cc, colc, valc, a)
      integer, intent(in) :: cr, colr(:), cc, colc(:)
      real(wp), intent(in) :: valr(:), valc(:), a
      integer :: e1, e2, r, c
      real(wp) :: x
      if (a == 0.0_wp) return
      do e1 = 1, cr
        r = colr(e1)
        x = valr(e1)*a
        do e2 = 1, cc
          c = colc(e2)
          if (r > 0) then
            if (c > 0) then
              ab(kv + r - c, c) = ab(kv + r - c, c) + x*valc(e2)
            else
              w%bc(r, -c) = w%bc(r, -c) + x*valc(e2)
            end if
          else
            if (c > 0) then
              w%bd(c, -r) = w%bd(c, -r) + x*valc(e2)
            else
              w%be(-r, -c) = w%be(-r, -c) + x*valc(e2)
            end if
          end if
        end do
      end do
    end subroutine add_block
  end subroutine friction_matrix

  !> Scale the banded rows of friction_matrix to unit largest entry over B
  !> (band storage ab) and C (bc): info = -5 when a row is zero.
  subroutine scale_rows(n, nb, kl, ku, ldb, ab, bc, rhs, rowsc, info)
    integer, intent(in) :: n, nb, kl, ku, ldb
    real(wp), intent(inout) :: ab(2*kl + ku + 1, n), bc(ldb, *), rhs(n)
    real(wp), intent(out) :: rowsc(n)     !< scratch: the row scales
    integer, intent(out) :: info
    integer :: kv, r, c, b
    info = 0
    kv = kl + ku + 1
    rowsc(1:n) = 0.0_wp
    do c = 1, n
      do r = max(1, c - ku), min(n, c + kl)
        rowsc(r) = max(rowsc(r), abs(ab(kv + r - c, c)))
      end do
    end do
    do b = 1, nb
      do r = 1, n
        rowsc(r) = max(rowsc(r), abs(bc(r, b)))
      end do
    end do
    do r = 1, n
      if (rowsc(r) <= 0.0_wp) then
        info = -5
        return
      end if
      rowsc(r) = 1.0_wp/rowsc(r)
    end do
    do c = 1, n
      do r = max(1, c - ku), min(n, c + kl)
        ab(kv + r - c, c) = ab(kv + r - c, c)*rowsc(r)
      end do
    end do
    do b = 1, nb
      do r = 1, n
        bc(r, b) = bc(r, b)*rowsc(r)
      end do
    end do
    do r = 1, n
      rhs(r) = rhs(r)*rowsc(r)
    end do
  end subroutine scale_rows

  !> Solve [B C; D' E] [x; y] = [rhs; bg] in place (x in rhs, y in bg):
  !> B by the band LU, then the border unknowns from the Schur complement
  !> E - D' B^-1 C (dense LU with partial pivoting, nb <= BORDER_MAX), x =
  !> B^-1 (rhs - C y). B is w%ab read as a contiguous (2 kl + ku + 1, n)
  !> block, as friction_matrix wrote it. (bc, bd and bx are grown together,
  !> so they share their leading dimension.)
  subroutine solve_bordered(n, nb, kl, ku, w, info)
    integer, intent(in) :: n, nb, kl, ku
    type(solver_work_t), intent(inout) :: w
    integer, intent(out) :: info
    call bordered_kernel(n, nb, kl, ku, size(w%bc, 1), w%ab, w%ipiv, w%fcol(1:n), w%lcol(1:n), w%ext, &
      w%rhs(1:n), w%bc, w%bd, w%bx, w%be, w%bg, info)
  end subroutine solve_bordered

  !> solve_bordered on explicit-shape arrays.
  subroutine bordered_kernel(n, nb, kl, ku, ldb, ab, ipiv, fcol, lcol, ext, rhs, bc, bd, bx, be, bg, info)
    integer, intent(in) :: n, nb, kl, ku, ldb
    real(wp), intent(inout) :: ab(2*kl + ku + 1, n)
    integer, intent(inout) :: ipiv(:), ext(:)
    integer, intent(in) :: fcol(n), lcol(n)
    real(wp), intent(inout) :: rhs(n)
    real(wp), intent(inout), dimension(ldb, BORDER_MAX) :: bc, bd, bx
    real(wp), intent(inout) :: be(BORDER_MAX, BORDER_MAX + 1), bg(BORDER_MAX)
    integer, intent(out) :: info
    integer :: b, b2, c, piv, ip(BORDER_MAX)
    real(wp) :: t, amax
    call band_factor(n, kl, ku, ab, ipiv, fcol, lcol, ext, info)
    if (info /= 0) return
    call band_subst(n, kl, ku, ab, ipiv, ext, rhs)
    if (nb == 0) return
    do b = 1, nb
      bx(1:n, b) = bc(1:n, b)
      call band_subst(n, kl, ku, ab, ipiv, ext, bx(1:n, b))
    end do
    ! S = E - D' X, g - D' x
    do b = 1, nb
      t = bg(b)
      do c = 1, n
        t = t - bd(c, b)*rhs(c)
      end do
      bg(b) = t
      do b2 = 1, nb
        t = be(b, b2)
        do c = 1, n
          t = t - bd(c, b)*bx(c, b2)
        end do
        be(b, b2) = t
      end do
    end do
    ! Dense LU with partial pivoting, then the solve.
    do c = 1, nb
      piv = c
      amax = abs(be(c, c))
      do b = c + 1, nb
        if (abs(be(b, c)) > amax) then
          amax = abs(be(b, c))
          piv = b
        end if
      end do
      ip(c) = piv
      if (amax == 0.0_wp) then
        info = -6
        return
      end if
      if (piv /= c) then
        do b2 = 1, nb
          t = be(c, b2)
          be(c, b2) = be(piv, b2)
          be(piv, b2) = t
        end do
        t = bg(c)
        bg(c) = bg(piv)
        bg(piv) = t
      end if
      do b = c + 1, nb
        t = be(b, c)/be(c, c)
        be(b, c) = t
        do b2 = c + 1, nb
          be(b, b2) = be(b, b2) - t*be(c, b2)
        end do
        bg(b) = bg(b) - t*bg(c)
      end do
    end do
    do c = nb, 1, -1
      t = bg(c)
      do b2 = c + 1, nb
        t = t - be(c, b2)*bg(b2)
      end do
      bg(c) = t/be(c, c)
    end do
    ! x = B^-1 rhs - X y
    do b = 1, nb
      t = bg(b)
      do c = 1, n
        rhs(c) = rhs(c) - bx(c, b)*t
      end do
    end do
  end subroutine bordered_kernel
end module raccord_banded_friction_form
