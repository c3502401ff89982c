!> Forward-increment Lagrange multipliers (Carpenter, Taylor & Katona 1991;
!> method brief section 3) with the discrete contact and Coulomb
!> conditions of the paper, equation (19):
!>   (G1 lambda)_j >= 0,  gn_j >= 0,  (G1 lambda)_j gn_j = 0,
!>   |(G1 tau)_j| <= mu (G1 lambda)_j,  stick: gt_j = 0,  slip: (G1 tau)_j gt_j <= 0,
!> where gn = G1^-T g_w and gt = G1^-T s_w are the nodal gap and slip at
!> t(n+1) after the correction dx = dt^2 M^-1 sum_j w_j (lambda_j n_j + tau_j t_j).
!> (Signs: lambda >= 0 is a pressure; the paper writes sigma_n <= 0.)
!>
!> The correction is linear in the multipliers:
!>   G1' gn = g_w* + dt^2 (Knn lambda + Knt tau),   G1' gt = s_w* + dt^2 (Ktn lambda + Ktt tau),
!> with K = B M^-1 B' banded (B: the constraint rows). It is solved by a
!> primal-dual active-set iteration (semismooth Newton for the complementarity
!> functions min(F, c g) and the friction projection): for fixed open /
!> stick / slip sets the conditions are linear. Without friction they are
!> solved on the active multipliers alone (the Delassus form, band
!> Cholesky: solve_frictionless); with friction and a diagonal G1
!> (node-to-segment) on lambda of the active and tau of the sticking
!> constraints (solve_diagonal_friction); with friction and a banded G1
!> (mortar) on lambda of the active and q = tau - mu S lambda of the
!> sticking constraints, the q next to a long slip zone bordered
!> (solve_banded_friction); otherwise (weighted conditions with friction,
!> or a reduced form declining) the saddle form: the unknowns
!> (lambda_j, gn_j [, tau_j, gt_j]) interleaved node by node,
!> the known gaps and slips left out, give one banded saddle system, solved
!> by a banded LU with partial pivoting (raccord_band_solver, LAPACK's dgbsv
!> algorithm without the per-column BLAS calls). doc/theory-contact.md,
!> section 3. The sets are updated from
!>   active:  F_j - c_j gn_j > 0,     stick: |T_j - c_j gt_j| <= mu F_j,
!> (F = G1 lambda, T = G1 tau, c_j = G1_jj^2 / (dt^2 Knn_jj)) until they no
!> longer change; the solution then satisfies (19) exactly.
!> Cost per iteration is linear in the number of constraints. mu = 0 drops
!> the tangential unknowns altogether.
!> With cs%weighted (mortar) the same conditions bear on each multiplier
!> and its own weighted gap and slip, i.e. G1 is replaced by the identity
!> in the conditions (lambda_j >= 0, g_w(j) >= 0, lambda_j g_w(j) = 0,
!> |tau_j| <= mu lambda_j, ...): the nodal gap G1^-T g_w mixes the open
!> neighbours' gaps into a closed node's, and with rows frozen per step
!> that gave the bodies energy (doc/theory-contact.md, section 7).
!> Degrees of freedom with prescribed motion have M^-1 = 0: infinitely
!> massive, they take no correction.
module raccord_multiplier_solver
  use raccord_kinds, only: wp
  use raccord_constraint_set, only: constraint_set_t, G1_MAX_BAND
  use raccord_band_solver, only: band_solve, band_factor, band_subst, band_cholesky_solve
  implicit none
  private

  integer, parameter, public :: ST_OPEN = 0, ST_STICK = 1, ST_SLIP = 2
  !> Gaps below this fraction of a constraint's length are round-off of
  !> touching surfaces (a length of 1 in coordinates of order 1e3 carries
  !> errors of 1e-13).
  real(wp), parameter :: GAP_ROUNDOFF = 1.0e-12_wp
  !> Reduced (Delassus) form: most active neighbours of one open row of Z.
  integer, parameter :: ZMAX = 4*G1_MAX_BAND + 2
  !> Saddle form (friction with a banded G1): leave out the known gaps of
  !> the constraints in contact (their unit rows).
  logical, parameter :: eliminate_gaps = .true.
  !> Saddle form: iterations after which one change of set is taken per
  !> iteration (least_index_change).
  integer, parameter :: LEAST_INDEX_AFTER = 30
  !> Reduced form with friction and a banded G1: a stick constraint next to
  !> a run of open and slipping constraints with at least BORDER_SLIP
  !> slipping ones takes a border unknown (its column of Z_t is dense over
  !> the run); at most BORDER_MAX of them, else the saddle form.
  integer, parameter :: BORDER_SLIP = 8, BORDER_MAX = 12

  !> Workspace and results, indexed by constraint; buffers grow only.
  type, public :: solver_work_t
    real(wp), allocatable :: lam(:), tau(:), gn(:), gt(:), fn(:), ft(:), c(:)
    integer, allocatable :: status(:), status_old(:)
    real(wp), allocatable :: sigma(:)
    real(wp), allocatable :: knn(:,:), knt(:,:), ktn(:,:), ktt(:,:)   !< (-kb:kb, m)
    integer :: kb = 0
    real(wp), allocatable :: ab(:,:), rhs(:)
    integer, allocatable :: var(:,:)     !< (4, m) unknown index of lambda_j, gn_j, tau_j, gt_j (0: eliminated)
    integer, allocatable :: vfirst(:)    !< (m + 1) first unknown of constraint j
    integer, allocatable :: fcol(:), lcol(:), ext(:)   !< per row: first, last column; band_solve scratch
    integer, allocatable :: ipiv(:)
    integer, allocatable :: node_first(:), node_last(:)   !< per global node: rows touching it
    integer, allocatable :: node_ptr(:), node_row(:), node_ent(:)   !< node -> (row, entry) lists
    integer, allocatable :: touched(:)
    ! Reduced (Delassus) solve: compressed active index, open list, the
    ! open multipliers in terms of the active ones (Z), the band of R.
    integer, allocatable :: ia(:), olist(:), zcnt(:), zcol(:,:)
    real(wp), allocatable :: zval(:,:), rb(:,:), xr(:)
    integer :: reduced_calls = 0                  !< solves done in the reduced form (all iterations)
    ! Reduced form with friction and a banded G1 (solve_banded_friction):
    ! tangential index and list (stick kept, open and slip eliminated), the
    ! sign s of tau = q + mu s lambda, the slip-free rows of q in terms of
    ! q_K (Zt), the unknown of lambda_j and q_j (< 0: a border unknown),
    ! the rows of N_n and N_t in the unknowns, the border blocks.
    integer, allocatable :: it(:), ulist(:), ztcnt(:), ztcol(:,:), ulam(:), uq(:), bmark(:)
    real(wp), allocatable :: ztval(:,:), sgn(:), qv(:)
    integer, allocatable :: ncnt(:), ncol(:,:), tcnt(:), tcol(:,:)
    real(wp), allocatable :: nval(:,:), tval(:,:)
    real(wp), allocatable :: bc(:,:), bd(:,:), bx(:,:), be(:,:), bg(:)
    !> Use the saddle form only (tests compare the reduced forms with it).
    logical :: saddle_only = .false.
    integer :: border_unknowns = 0                !< border unknowns of the last solve_banded_friction
    ! Report of the last solve.
    integer :: iterations = 0
    logical :: converged = .true.
    real(wp) :: residual = 0.0_wp
    integer :: dropped = 0                        !< constraints with no movable node
    logical :: singular = .false.                 !< the last solve met a singular system
  end type solver_work_t

  public :: solve_multipliers


contains

  !> Solve for the multipliers of constraint set cs. status(1:m) holds the
  !> initial guess of the sets (ST_OPEN, ST_STICK, ST_SLIP) and returns the
  !> final ones; sigma(1:m) the slip directions.
  subroutine solve_multipliers(cs, minv, alpha, h, dt, mu, max_iter, status, sigma, w)
    type(constraint_set_t), intent(in) :: cs
    real(wp), intent(in) :: minv(:,:)          !< (2, nnode) inverse mass per dof, 0 where prescribed
    real(wp), intent(in) :: alpha(:)           !< (nnode) mass-proportional damping of each node
    real(wp), intent(in) :: h                  !< velocity step: dt, or dt/2 on the first step
    real(wp), intent(in) :: dt, mu
    integer, intent(in) :: max_iter
    integer, intent(inout) :: status(:)        !< (m) initial guess in, final sets out
    real(wp), intent(inout) :: sigma(:)        !< (m) slip directions
    type(solver_work_t), intent(inout) :: w
    integer :: m, it, j, nu, n, kl, ku, ldab, info, bw
    logical :: friction, same

    m = cs%m
    w%iterations = 0
    w%converged = .true.
    w%residual = 0.0_wp
    w%dropped = 0
    w%singular = .false.
    if (m == 0) return
    friction = mu > 0.0_wp
    nu = merge(4, 2, friction)
    call delassus(cs, minv, alpha, h/dt, h, friction, w)
    w%status(1:m) = status(1:m)
    w%sigma(1:m) = sigma(1:m)
    if (.not. friction) where (w%status(1:m) == ST_SLIP) w%status(1:m) = ST_STICK
    do j = 1, m
      if (w%knn(0, j) > 0.0_wp) then
        w%c(j) = g1c(cs, j, j)**2/(dt*dt*w%knn(0, j))
      else
        w%c(j) = 0.0_wp
        w%dropped = w%dropped + 1
      end if
    end do
    bw = max(w%kb, cs%g1_band)
    call ensure_i2(w%var, 4, m)
    call ensure_i(w%vfirst, m + 1)
    call ensure1(w%rhs, nu*m)
    call ensure_i(w%ipiv, nu*m)
    call ensure_i(w%fcol, nu*m)
    call ensure_i(w%lcol, nu*m)
    call ensure_i(w%ext, 3*nu*m)

    ! The Delassus forms (below) first, the saddle form if they decline.
    ! They are written for the paper's conditions (19); weighted conditions
    ! (cs%weighted: G1 the identity in the conditions) take the saddle form.
    if (w%saddle_only) then
      continue
    else if (.not. friction .and. .not. cs%weighted) then
      call solve_frictionless(cs, dt, max_iter, w, same, info)
      if (info == 0) then
        call finish_solve(cs, mu, friction, same, w, status, sigma)
        return
      end if
      w%status(1:m) = status(1:m)
      where (w%status(1:m) == ST_SLIP) w%status(1:m) = ST_STICK
      w%iterations = 0
    else if (friction .and. cs%g1_band == 0 .and. .not. cs%weighted) then
      call solve_diagonal_friction(cs, dt, mu, max_iter, w, same, info)
      if (info == 0) then
        call finish_solve(cs, mu, friction, same, w, status, sigma)
        return
      end if
      w%status(1:m) = status(1:m)
      w%sigma(1:m) = sigma(1:m)
      w%iterations = 0
    else if (friction .and. .not. cs%weighted .and. any(w%status(1:m) /= ST_STICK)) then
      ! (A guess of all in stick leaves the saddle form nothing to
      ! eliminate: it is then the same system, with less bookkeeping.)
      call solve_banded_friction(cs, dt, mu, max_iter, w, same, info)
      if (info == 0) then
        call finish_solve(cs, mu, friction, same, w, status, sigma)
        return
      end if
      w%status(1:m) = status(1:m)
      w%sigma(1:m) = sigma(1:m)
      w%iterations = 0
    end if

    do it = 1, max_iter
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
      call update_sets(cs, m, mu, friction, w)
      same = all(w%status(1:m) == w%status_old(1:m))
      if (same) exit
      if (it > LEAST_INDEX_AFTER) call least_index_change(m, w)
    end do
    call finish_solve(cs, mu, friction, same, w, status, sigma)
  end subroutine solve_multipliers

  !> Keep only the first constraint's change of set (the least index) and
  !> take the others back. The active-set iteration changes every set at
  !> once, which settles when the Delassus matrix is close to diagonal (the
  !> paper's nodal conditions: G1^-T K G1^-1); with the weighted conditions
  !> K itself is used, and next to the axis or at the end of a contact zone
  !> a row's neighbour can outweigh it (the ball as Q8 slave in
  !> axisymmetry: Ktt(8,9) = 202 against Ktt(9,9) = 31), and four
  !> constraints went round a stick/slip cycle of period 4 until
  !> max_iterations. Taking one change per iteration, the least index
  !> first (Murty's rule for complementarity problems with a P-matrix),
  !> ends such a cycle; it starts only after LEAST_INDEX_AFTER iterations,
  !> so a solve that settles before is unchanged (doc/theory-contact.md,
  !> section 3).
  subroutine least_index_change(m, w)
    integer, intent(in) :: m
    type(solver_work_t), intent(inout) :: w
    integer :: j
    logical :: first
    first = .true.
    do j = 1, m
      if (w%status(j) == w%status_old(j)) cycle
      if (first) then
        first = .false.
      else
        w%status(j) = w%status_old(j)
      end if
    end do
  end subroutine least_index_change

  !> The report of a solve (converged when the sets settled, the residual
  !> of the conditions) and the final sets and slip directions handed back.
  subroutine finish_solve(cs, mu, friction, same, w, status, sigma)
    type(constraint_set_t), intent(in) :: cs
    real(wp), intent(in) :: mu
    logical, intent(in) :: friction, same
    type(solver_work_t), intent(inout) :: w
    integer, intent(inout) :: status(:)
    real(wp), intent(inout) :: sigma(:)
    if (.not. same) w%converged = .false.
    w%residual = condition_residual(cs, mu, friction, w)
    status(1:cs%m) = w%status(1:cs%m)
    sigma(1:cs%m) = w%sigma(1:cs%m)
  end subroutine finish_solve

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
      call update_sets(cs, m, 0.0_wp, .false., w)
      same = all(w%status(1:m) == w%status_old(1:m))
      if (same) exit
    end do
    w%reduced_calls = w%reduced_calls + 1
  end subroutine solve_frictionless

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
      call friction_matrix(cs, dt2, mu, n, nb, kl, ku, w, info)
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
  !> change within 2 g1_band constraints).
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
        if (g1_at(cs, j, k) == 0.0_wp) cycle
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
          if (g1_at(cs, j, k) /= 0.0_wp .and. w%sgn(k) /= 0.0_wp) sj = w%sgn(k)
        end do
        if (sj == 0.0_wp) cycle
        do k = max(1, j - g1b), min(m, j + g1b)
          if (g1_at(cs, j, k) /= 0.0_wp .and. w%sgn(k) == 0.0_wp) w%sgn(k) = sj
        end do
      end do
    end do
    ! Check: constant over every open and slipping row, sigma_j on a slipping one.
    do j = 1, m
      if (w%status(j) == ST_STICK) cycle
      sj = w%sgn(j)
      if (w%status(j) == ST_SLIP) sj = w%sigma(j)
      do k = max(1, j - g1b), min(m, j + g1b)
        if (g1_at(cs, j, k) == 0.0_wp) cycle
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
      ns = count(w%status(w%ulist(p1:p2)) == ST_SLIP)
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
  !> entry (over B and C), as in the saddle form.
  subroutine friction_matrix(cs, dt2, mu, n, nb, kl, ku, w, info)
    type(constraint_set_t), intent(in) :: cs
    real(wp), intent(in) :: dt2, mu
    integer, intent(in) :: n, nb, kl, ku
    type(solver_work_t), intent(inout) :: w
    integer, intent(out) :: info
    integer :: m, i, k, ldab, kv, r, c, b, rn, rt, cn, ct
    real(wp) :: ann, ant, atn, att, sc
    m = cs%m
    info = 0
    ldab = 2*kl + ku + 1
    kv = kl + ku + 1
    w%ab(1:ldab, 1:n) = 0.0_wp
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
            if (cn > 0) w%ab(kv + rn - cn, cn) = w%ab(kv + rn - cn, cn) + ann
            if (ct > 0) w%ab(kv + rn - ct, ct) = w%ab(kv + rn - ct, ct) + ant
          end if
          if (rt > 0) then
            if (cn > 0) w%ab(kv + rt - cn, cn) = w%ab(kv + rt - cn, cn) + atn
            if (ct > 0) w%ab(kv + rt - ct, ct) = w%ab(kv + rt - ct, ct) + att
          end if
          cycle
        end if
        call add_block(w%ncnt(i), w%ncol(:, i), w%nval(:, i), w%ncnt(k), w%ncol(:, k), w%nval(:, k), ann)
        call add_block(w%ncnt(i), w%ncol(:, i), w%nval(:, i), w%tcnt(k), w%tcol(:, k), w%tval(:, k), ant)
        call add_block(w%tcnt(i), w%tcol(:, i), w%tval(:, i), w%ncnt(k), w%ncol(:, k), w%nval(:, k), atn)
        call add_block(w%tcnt(i), w%tcol(:, i), w%tval(:, i), w%tcnt(k), w%tcol(:, k), w%tval(:, k), att)
      end do
    end do
    do r = 1, n
      sc = 0.0_wp
      do c = w%fcol(r), w%lcol(r)
        sc = max(sc, abs(w%ab(kv + r - c, c)))
      end do
      do b = 1, nb
        sc = max(sc, abs(w%bc(r, b)))
      end do
      if (sc <= 0.0_wp) then
        info = -5
        return
      end if
      sc = 1.0_wp/sc
      do c = w%fcol(r), w%lcol(r)
        w%ab(kv + r - c, c) = w%ab(kv + r - c, c)*sc
      end do
      do b = 1, nb
        w%bc(r, b) = w%bc(r, b)*sc
      end do
      w%rhs(r) = w%rhs(r)*sc
    end do
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
              w%ab(kv + r - c, c) = w%ab(kv + r - c, c) + x*valc(e2)
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

  !> Solve [B C; D' E] [x; y] = [rhs; bg] in place (x in rhs, y in bg):
  !> B by the band LU, then the border unknowns from the Schur complement
  !> E - D' B^-1 C (dense LU with partial pivoting, nb <= BORDER_MAX), x =
  !> B^-1 (rhs - C y).
  subroutine solve_bordered(n, nb, kl, ku, w, info)
    integer, intent(in) :: n, nb, kl, ku
    type(solver_work_t), intent(inout) :: w
    integer, intent(out) :: info
    integer :: ldab, b, b2, c, piv, ip(BORDER_MAX)
    real(wp) :: t, amax
    ldab = 2*kl + ku + 1
    call band_factor(n, kl, ku, w%ab(1:ldab, 1:n), w%ipiv, w%fcol, w%lcol, w%ext, info)
    if (info /= 0) return
    call band_subst(n, kl, ku, w%ab(1:ldab, 1:n), w%ipiv, w%ext, w%rhs)
    if (nb == 0) return
    do b = 1, nb
      w%bx(1:n, b) = w%bc(1:n, b)
      call band_subst(n, kl, ku, w%ab(1:ldab, 1:n), w%ipiv, w%ext, w%bx(:, b))
    end do
    ! S = E - D' X, g - D' x
    do b = 1, nb
      t = w%bg(b)
      do c = 1, n
        t = t - w%bd(c, b)*w%rhs(c)
      end do
      w%bg(b) = t
      do b2 = 1, nb
        t = w%be(b, b2)
        do c = 1, n
          t = t - w%bd(c, b)*w%bx(c, b2)
        end do
        w%be(b, b2) = t
      end do
    end do
    ! Dense LU with partial pivoting, then the solve.
    do c = 1, nb
      piv = c
      amax = abs(w%be(c, c))
      do b = c + 1, nb
        if (abs(w%be(b, c)) > amax) then
          amax = abs(w%be(b, c))
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
          t = w%be(c, b2)
          w%be(c, b2) = w%be(piv, b2)
          w%be(piv, b2) = t
        end do
        t = w%bg(c)
        w%bg(c) = w%bg(piv)
        w%bg(piv) = t
      end if
      do b = c + 1, nb
        t = w%be(b, c)/w%be(c, c)
        w%be(b, c) = t
        do b2 = c + 1, nb
          w%be(b, b2) = w%be(b, b2) - t*w%be(c, b2)
        end do
        w%bg(b) = w%bg(b) - t*w%bg(c)
      end do
    end do
    do c = nb, 1, -1
      t = w%bg(c)
      do b2 = c + 1, nb
        t = t - w%be(c, b2)*w%bg(b2)
      end do
      w%bg(c) = t/w%be(c, c)
    end do
    ! x = B^-1 rhs - X y
    do b = 1, nb
      t = w%bg(b)
      do c = 1, n
        w%rhs(c) = w%rhs(c) - w%bx(c, b)*t
      end do
    end do
  end subroutine solve_bordered

  !> Solve G1_CC' x = v in place over each run C of list (constraints less
  !> than g1_band + 1 apart): v holds the right-hand sides at the list's
  !> constraints and returns the solution there.
  subroutine run_transposed(cs, list, nl, v, w, info)
    type(constraint_set_t), intent(in) :: cs
    integer, intent(in) :: list(:), nl
    real(wp), intent(inout) :: v(:)
    type(solver_work_t), intent(inout) :: w
    integer, intent(out) :: info
    integer :: p1, p2, p, nc
    info = 0
    p1 = 1
    do while (p1 <= nl)
      p2 = p1
      do while (p2 < nl)
        if (list(p2 + 1) - list(p2) > cs%g1_band) exit
        p2 = p2 + 1
      end do
      nc = p2 - p1 + 1
      if (nc == 1) then
        if (cs%g1(0, list(p1)) == 0.0_wp) then
          info = -1
          return
        end if
        v(list(p1)) = v(list(p1))/cs%g1(0, list(p1))
      else
        do p = p1, p2
          w%xr(p - p1 + 1) = v(list(p))
        end do
        call run_solve(cs, list, p1, nc, .true., w, info)
        if (info /= 0) return
        do p = p1, p2
          v(list(p)) = w%xr(p - p1 + 1)
        end do
      end if
      p1 = p2 + 1
    end do
  end subroutine run_transposed

  !> Z = -G1_OO^-1 G1_OA run by run: an open run is a maximal sequence of
  !> open constraints less than g1_band + 1 apart (G1_OO is block diagonal
  !> over the runs); its columns are the active constraints within
  !> g1_band of it. Row p of Z (open constraint olist(p)) is kept as up to
  !> ZMAX (column, value) pairs.
  subroutine open_from_active(cs, olist, no, ia, zcnt, zcol, zval, w, info)
    type(constraint_set_t), intent(in) :: cs
    integer, intent(in) :: olist(:)              !< (no) the eliminated constraints, in order
    integer, intent(in) :: no
    integer, intent(in) :: ia(:)                 !< (m) > 0: a kept constraint (a column of Z)
    integer, intent(inout) :: zcnt(:), zcol(:,:)
    real(wp), intent(inout) :: zval(:,:)
    type(solver_work_t), intent(inout) :: w
    integer, intent(out) :: info
    integer :: p1, p2, p, nc, b, g1b
    logical :: nz
    info = 0
    g1b = cs%g1_band
    p1 = 1
    runs: do while (p1 <= no)
      p2 = p1
      do while (p2 < no)
        if (olist(p2 + 1) - olist(p2) > g1b) exit
        p2 = p2 + 1
      end do
      nc = p2 - p1 + 1
      zcnt(p1:p2) = 0
      do b = max(1, olist(p1) - g1b), min(cs%m, olist(p2) + g1b)
        if (ia(b) <= 0) cycle
        nz = .false.
        do p = p1, p2
          w%xr(p - p1 + 1) = -g1_at(cs, olist(p), b)
          nz = nz .or. w%xr(p - p1 + 1) /= 0.0_wp
        end do
        if (.not. nz) cycle
        call run_solve(cs, olist, p1, nc, .false., w, info)
        if (info /= 0) return
        do p = p1, p2
          if (w%xr(p - p1 + 1) == 0.0_wp) cycle
          if (zcnt(p) == ZMAX) then
            info = -1
            return
          end if
          zcnt(p) = zcnt(p) + 1
          zcol(zcnt(p), p) = b
          zval(zcnt(p), p) = w%xr(p - p1 + 1)
        end do
      end do
      p1 = p2 + 1
    end do runs
  end subroutine open_from_active

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

  !> Solve G1_CC x = xr (or G1_CC' x = xr) in place for the open run
  !> olist(p1 : p1 + nc - 1), with the band LU.
  subroutine run_solve(cs, olist, p1, nc, transposed, w, info)
    type(constraint_set_t), intent(in) :: cs
    integer, intent(in) :: olist(:)       !< the constraints of the runs
    integer, intent(in) :: p1, nc
    logical, intent(in) :: transposed
    type(solver_work_t), intent(inout) :: w
    integer, intent(out) :: info
    integer :: g1b, ldab, p, q, jp, jq
    g1b = cs%g1_band
    ldab = 3*g1b + 1
    call ensure2(w%ab, ldab, nc)
    w%ab(1:ldab, 1:nc) = 0.0_wp
    do p = 1, nc
      jp = olist(p1 - 1 + p)
      w%fcol(p) = max(1, p - g1b)
      w%lcol(p) = min(nc, p + g1b)
      do q = w%fcol(p), w%lcol(p)
        jq = olist(p1 - 1 + q)
        ! band storage of dgbsv: A(p, q) in ab(kl + ku + 1 + p - q, q)
        if (transposed) then
          w%ab(2*g1b + 1 + p - q, q) = g1_at(cs, jq, jp)
        else
          w%ab(2*g1b + 1 + p - q, q) = g1_at(cs, jp, jq)
        end if
      end do
    end do
    call band_solve(nc, g1b, g1b, w%ab(1:ldab, 1:nc), w%ipiv, w%xr, w%fcol, w%lcol, w%ext, info)
  end subroutine run_solve

  !> R = N' M N and its right-hand side -N' g_w* (in xr), in the active
  !> numbering, lower band: rb(d + 1, k) = R(k + d, k). M(a, b) = dt^2 Knn(a, b).
  !> R = M_AA + M_AO Z + (M_AO Z)' + Z' M_OO Z.
  subroutine reduced_matrix(cs, dt2, no, krcap, w, kr, info)
    type(constraint_set_t), intent(in) :: cs
    real(wp), intent(in) :: dt2
    integer, intent(in) :: no, krcap
    type(solver_work_t), intent(inout) :: w
    integer, intent(out) :: kr, info
    integer :: m, a, b, p, q, e, e2, o, o2, na
    real(wp) :: z, v, mo
    m = cs%m
    info = 0
    kr = 0
    na = count(w%ia(1:m) > 0)
    w%rb(1:krcap + 1, 1:na) = 0.0_wp
    do a = 1, m
      if (w%ia(a) <= 0) cycle
      w%xr(w%ia(a)) = -cs%gap_w(a)
      do b = max(1, a - w%kb), a
        if (w%ia(b) <= 0) cycle
        ! K(a, b) is stored as knn(b - a, a)
        call add(w%ia(a), w%ia(b), dt2*w%knn(b - a, a))
      end do
    end do
    do p = 1, no
      o = w%olist(p)
      do e = 1, w%zcnt(p)
        b = w%zcol(e, p)
        z = w%zval(e, p)
        w%xr(w%ia(b)) = w%xr(w%ia(b)) - z*cs%gap_w(o)
        ! M_AO Z and its transpose: one entry of the lower band each (twice on the diagonal)
        do a = max(1, o - w%kb), min(m, o + w%kb)
          if (w%ia(a) <= 0) cycle
          v = z*dt2*w%knn(o - a, a)
          if (a == b) v = 2.0_wp*v
          call add(max(w%ia(a), w%ia(b)), min(w%ia(a), w%ia(b)), v)
        end do
        ! Z' M_OO Z, the lower half
        do o2 = max(1, o - w%kb), min(m, o + w%kb)
          if (w%ia(o2) >= 0) cycle
          q = -w%ia(o2)
          mo = z*dt2*w%knn(o2 - o, o)
          do e2 = 1, w%zcnt(q)
            if (w%ia(b) < w%ia(w%zcol(e2, q))) cycle
            call add(w%ia(b), w%ia(w%zcol(e2, q)), mo*w%zval(e2, q))
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
      w%rb(i - k + 1, k) = w%rb(i - k + 1, k) + x
    end subroutine add
  end subroutine reduced_matrix

  !> Active-set update from the complementarity functions. A constraint is
  !> active when fn - c gn > c GAP_ROUNDOFF length: gaps within round-off of
  !> zero (a surface sliding at zero gap along another, grazing) and
  !> multipliers whose force is below what closes such a gap leave a node as
  !> it is open, instead of letting round-off toggle it from step to step
  !> (chatter; tests/contact/test_stability.f90, grazing).
  subroutine update_sets(cs, m, mu, friction, w)
    type(constraint_set_t), intent(in) :: cs
    integer, intent(in) :: m
    real(wp), intent(in) :: mu
    logical, intent(in) :: friction
    type(solver_work_t), intent(inout) :: w
    integer :: j
    real(wp) :: z, fc, tc, gtol
    do j = 1, m
      if (w%c(j) <= 0.0_wp) then
        w%status(j) = ST_OPEN
        cycle
      end if
      call condition_forces(cs, w, j, fc, tc, gtol)
      if (fc - w%c(j)*w%gn(j) > w%c(j)*GAP_ROUNDOFF*gtol) then
        if (.not. friction) then
          w%status(j) = ST_STICK
        else
          z = tc - w%c(j)*w%gt(j)
          if (abs(z) <= mu*max(fc, 0.0_wp)) then
            w%status(j) = ST_STICK
          else
            w%status(j) = ST_SLIP
            w%sigma(j) = sign(1.0_wp, z)
          end if
        end if
      else
        w%status(j) = ST_OPEN
      end if
    end do
  end subroutine update_sets

  !> The normal and tangential force the conditions bear on (G1 lambda,
  !> G1 tau; lambda, tau when cs%weighted) and the gap's round-off scale
  !> (the constraint's length; times G1_jj for a weighted gap).
  subroutine condition_forces(cs, w, j, fc, tc, gtol)
    type(constraint_set_t), intent(in) :: cs
    type(solver_work_t), intent(in) :: w
    integer, intent(in) :: j
    real(wp), intent(out) :: fc, tc, gtol
    if (cs%weighted) then
      fc = w%lam(j)
      tc = w%tau(j)
      gtol = cs%length(j)*abs(cs%g1(0, j))
    else
      fc = w%fn(j)
      tc = w%ft(j)
      gtol = cs%length(j)
    end if
  end subroutine condition_forces

  !> Largest violation of (19) by the final iterate, relative: gaps to the
  !> shortest nonzero constraint length, forces to the largest normal force.
  real(wp) function condition_residual(cs, mu, friction, w) result(r)
    type(constraint_set_t), intent(in) :: cs
    real(wp), intent(in) :: mu
    logical, intent(in) :: friction
    type(solver_work_t), intent(in) :: w
    integer :: j, m
    real(wp) :: fscale, lscale, fc, tc, gtol, g
    m = cs%m
    fscale = 0.0_wp
    do j = 1, m
      call condition_forces(cs, w, j, fc, tc, gtol)
      fscale = max(fscale, abs(fc))
    end do
    fscale = max(fscale, tiny(1.0_wp))
    ! the shortest length a multiplier acts on; a row of zero length (an
    ! axisymmetric node on the axis: 2 pi r = 0) would make any gap huge
    lscale = minval(cs%length(1:m), mask=cs%length(1:m) > 0.0_wp)
    if (.not. (lscale > 0.0_wp .and. lscale < huge(1.0_wp))) lscale = 1.0_wp
    r = 0.0_wp
    do j = 1, m
      call condition_forces(cs, w, j, fc, tc, gtol)
      ! a weighted gap is a gap times a length: over the row's own length
      g = w%gn(j)
      if (cs%weighted .and. cs%length(j) > 0.0_wp) g = g/cs%length(j)
      if (w%status(j) == ST_OPEN) then
        if (w%c(j) > 0.0_wp) r = max(r, -g/lscale, abs(fc)/fscale)
      else
        r = max(r, abs(g)/lscale, -fc/fscale)
        if (friction) r = max(r, (abs(tc) - mu*fc)/fscale)
      end if
    end do
    r = max(r, 0.0_wp)
  end function condition_residual

  !> F = G1 v (band product).
  subroutine band_matvec(cs, v, f)
    type(constraint_set_t), intent(in) :: cs
    real(wp), intent(in) :: v(:)
    real(wp), intent(inout) :: f(:)
    integer :: j, d, k
    do j = 1, cs%m
      f(j) = 0.0_wp
      do d = -cs%g1_band, cs%g1_band
        k = j + d
        if (k < 1 .or. k > cs%m) cycle
        ! G1(j, k) = g1(j - k, k).
        f(j) = f(j) + cs%g1(j - k, k)*v(k)
      end do
    end do
  end subroutine band_matvec

  !> G1(j, k) from the band storage (0 outside the band).
  pure real(wp) function g1_at(cs, j, k)
    type(constraint_set_t), intent(in) :: cs
    integer, intent(in) :: j, k
    g1_at = 0.0_wp
    if (abs(j - k) <= cs%g1_band) g1_at = cs%g1(j - k, k)
  end function g1_at

  !> The G1 of the conditions: G1(j, k), or the identity when the
  !> conditions bear on each multiplier and its weighted gap (cs%weighted).
  pure real(wp) function g1c(cs, j, k)
    type(constraint_set_t), intent(in) :: cs
    integer, intent(in) :: j, k
    if (cs%weighted) then
      g1c = merge(1.0_wp, 0.0_wp, j == k)
    else
      g1c = g1_at(cs, j, k)
    end if
  end function g1c

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

  !> K = B M^-1 B' in band form, accumulated node by node:
  !> K(j, k) += w_jp w_kp n_j . (M_p^-1 n_k) for every node p the rows share.
  !> A force f at t(n) moves u(n+1) by dt^2 (h/dt) M^-1 f / (1 + alpha h/2):
  !> (CD-1) with its semi-implicit damping, and the half first step.
  subroutine delassus(cs, minv, alpha, h_ratio, h, friction, w)
    type(constraint_set_t), intent(in) :: cs
    real(wp), intent(in) :: minv(:,:), alpha(:), h_ratio, h
    logical, intent(in) :: friction
    type(solver_work_t), intent(inout) :: w
    integer :: m, j, e, p, nn, a, b, ja, jb, ea, eb, ntouched, t, pos
    real(wp) :: wa, wb, mi(2)
    m = cs%m
    nn = size(minv, 2)
    call ensure_work(w, m, nn, cs%nent)
    ! Rows touching each node, and the band width they imply.
    ntouched = 0
    do e = 1, cs%nent
      p = cs%ent_node(e)
      if (w%node_first(p) == 0) then
        ntouched = ntouched + 1
        w%touched(ntouched) = p
        w%node_ptr(p) = 0
      end if
      w%node_ptr(p) = w%node_ptr(p) + 1
      w%node_first(p) = 1
    end do
    ! CSR offsets over touched nodes (node_last holds the fill position).
    pos = 1
    do t = 1, ntouched
      p = w%touched(t)
      w%node_last(p) = pos
      pos = pos + w%node_ptr(p)
      w%node_ptr(p) = w%node_last(p)
    end do
    do j = 1, m
      do e = cs%row_ptr(j), cs%row_ptr(j + 1) - 1
        p = cs%ent_node(e)
        w%node_row(w%node_last(p)) = j
        w%node_ent(w%node_last(p)) = e
        w%node_last(p) = w%node_last(p) + 1
      end do
    end do
    ! A node's rows are listed in increasing order (filled row by row).
    w%kb = 0
    do t = 1, ntouched
      p = w%touched(t)
      w%kb = max(w%kb, w%node_row(w%node_last(p) - 1) - w%node_row(w%node_ptr(p)))
    end do
    w%kb = min(w%kb, m)
    call ensure_band(w%knn, w%kb, m)
    call ensure_band(w%knt, w%kb, m)
    call ensure_band(w%ktn, w%kb, m)
    call ensure_band(w%ktt, w%kb, m)
    w%knn(-w%kb:w%kb, 1:m) = 0.0_wp
    if (friction) then
      w%knt(-w%kb:w%kb, 1:m) = 0.0_wp
      w%ktn(-w%kb:w%kb, 1:m) = 0.0_wp
      w%ktt(-w%kb:w%kb, 1:m) = 0.0_wp
    end if
    do t = 1, ntouched
      p = w%touched(t)
      mi = h_ratio/(1.0_wp + 0.5_wp*alpha(p)*h)*minv(:, p)
      do a = w%node_ptr(p), w%node_last(p) - 1
        ja = w%node_row(a)
        ea = w%node_ent(a)
        wa = cs%ent_w(ea)
        do b = w%node_ptr(p), w%node_last(p) - 1
          jb = w%node_row(b)
          eb = w%node_ent(b)
          wb = cs%ent_w(eb)
          ! Stored as k(jb - ja, ja) = K(ja, jb). (Both orders of a pair are
          ! summed as written: copying the mirror entry, symmetric to
          ! round-off, moved the active set of test_curved's mortar P0 case.)
          w%knn(jb - ja, ja) = w%knn(jb - ja, ja) + wa*wb*sum(cs%normal(:, ja)*mi*cs%normal(:, jb))
          if (friction) then
            w%knt(jb - ja, ja) = w%knt(jb - ja, ja) + wa*wb*sum(cs%normal(:, ja)*mi*cs%tangent(:, jb))
            w%ktn(jb - ja, ja) = w%ktn(jb - ja, ja) + wa*wb*sum(cs%tangent(:, ja)*mi*cs%normal(:, jb))
            w%ktt(jb - ja, ja) = w%ktt(jb - ja, ja) + wa*wb*sum(cs%tangent(:, ja)*mi*cs%tangent(:, jb))
          end if
        end do
      end do
    end do
    ! Reset the per-node marks for the next call (touched nodes only).
    do t = 1, ntouched
      w%node_first(w%touched(t)) = 0
    end do
  end subroutine delassus

  subroutine ensure_work(w, m, nn, nent)
    type(solver_work_t), intent(inout) :: w
    integer, intent(in) :: m, nn, nent
    integer :: cap
    if (.not. allocated(w%node_first)) then
      allocate(w%node_first(nn), w%node_last(nn), w%node_ptr(nn), source=0)
      allocate(w%touched(nn))
    end if
    call ensure_i(w%node_row, nent)
    call ensure_i(w%node_ent, nent)
    if (allocated(w%lam)) then
      if (size(w%lam) >= m) return
    end if
    cap = max(m, 16)
    call ensure_i(w%status, cap)
    call ensure_i(w%status_old, cap)
    call ensure1(w%sigma, cap)
    if (allocated(w%lam)) deallocate(w%lam, w%tau, w%gn, w%gt, w%fn, w%ft, w%c)
    allocate(w%lam(cap), w%tau(cap), w%gn(cap), w%gt(cap), w%fn(cap), w%ft(cap), w%c(cap), source=0.0_wp)
  end subroutine ensure_work

  subroutine ensure_band(a, kb, m)
    real(wp), allocatable, intent(inout) :: a(:,:)
    integer, intent(in) :: kb, m
    if (allocated(a)) then
      if (lbound(a, 1) <= -kb .and. size(a, 2) >= m) return
      deallocate(a)
    end if
    allocate(a(-max(kb, 2):max(kb, 2), max(m, 16)))
  end subroutine ensure_band

  !> Grow-only: the band's height changes with the sets.
  subroutine ensure2(a, n1, n2)
    real(wp), allocatable, intent(inout) :: a(:,:)
    integer, intent(in) :: n1, n2
    integer :: c1, c2
    c1 = n1
    c2 = max(n2, 1)
    if (allocated(a)) then
      if (size(a, 1) >= n1 .and. size(a, 2) >= n2) return
      c1 = max(c1, size(a, 1))
      c2 = max(c2, size(a, 2))
      deallocate(a)
    end if
    allocate(a(c1, c2))
  end subroutine ensure2

  subroutine ensure_i2(a, n1, n2)
    integer, allocatable, intent(inout) :: a(:,:)
    integer, intent(in) :: n1, n2
    if (allocated(a)) then
      if (size(a, 1) >= n1 .and. size(a, 2) >= n2) return
      deallocate(a)
    end if
    allocate(a(n1, max(n2, 16)))
  end subroutine ensure_i2

  subroutine ensure1(a, n)
    real(wp), allocatable, intent(inout) :: a(:)
    integer, intent(in) :: n
    if (allocated(a)) then
      if (size(a) >= n) return
      deallocate(a)
    end if
    allocate(a(max(n, 1)))
  end subroutine ensure1

  subroutine ensure_i(a, n)
    integer, allocatable, intent(inout) :: a(:)
    integer, intent(in) :: n
    if (allocated(a)) then
      if (size(a) >= n) return
      deallocate(a)
    end if
    allocate(a(max(n, 1)))
  end subroutine ensure_i
end module raccord_multiplier_solver
