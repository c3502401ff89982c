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
!> stick / slip sets the conditions are linear, and the unknowns
!> (lambda_j, gn_j [, tau_j, gt_j]) interleaved node by node give one banded
!> system, solved by a banded LU with partial pivoting (raccord_band_solver,
!> LAPACK's dgbsv algorithm without the per-column BLAS calls). The sets
!> are updated from
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
  use raccord_band_solver, only: band_solve
  implicit none
  private

  integer, parameter, public :: ST_OPEN = 0, ST_STICK = 1, ST_SLIP = 2
  !> Gaps below this fraction of a constraint's length are round-off of
  !> touching surfaces (a length of 1 in coordinates of order 1e3 carries
  !> errors of 1e-13).
  real(wp), parameter :: GAP_ROUNDOFF = 1.0e-12_wp

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
    call ensure_i(w%ext, 2*nu*m)

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
        w%gn(j) = w%rhs(w%var(2, j))
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
    end do
    if (.not. same) w%converged = .false.
    w%residual = condition_residual(cs, mu, friction, w)
    status(1:m) = w%status(1:m)
    sigma(1:m) = w%sigma(1:m)
  end subroutine solve_multipliers

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
  !> order: lambda_j, gn_j; with friction tau_j, and gt_j unless j sticks
  !> (gt_j = 0: its row and column drop out). Eliminating the known slips
  !> takes a quarter of the unknowns out of a zone in stick and narrows its
  !> band (the banded LU costs about n kl (kl + ku) with the local band).
  !> The known gaps of the constraints in contact are kept as unknowns
  !> with their unit rows: eliminating them too changed the pivot order
  !> enough to change the converged active set of a badly conditioned
  !> case (mortar P0, a slave of 4 facets on a curved master, 1:8;
  !> test_curved). Each condition row takes the index of its unknown: the
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
      n = n + 1
      w%var(2, j) = n
      w%var(3:4, j) = 0
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
      do i = w%vfirst(j), w%vfirst(j + 1) - 1
        w%fcol(i) = w%vfirst(max(1, j - bw))
        w%lcol(i) = w%vfirst(min(m, j + bw) + 1) - 1
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
        call put(r, w%var(2, k), g1c(cs, k, j))
        if (abs(j - k) <= w%kb) then
          call put(r, w%var(1, k), -dt2*w%knn(k - j, j))
          if (friction) call put(r, w%var(3, k), -dt2*w%knt(k - j, j))
        end if
      end do
      w%rhs(r) = cs%gap_w(j)
      ! Normal condition: gn_j = 0 (in contact) or (G1 lambda)_j = 0 (open).
      r = w%var(2, j)
      w%rhs(r) = 0.0_wp
      if (w%status(j) /= ST_OPEN) then
        call put(r, r, 1.0_wp)
      else
        do k = max(1, j - cs%g1_band), min(m, j + cs%g1_band)
          call put(r, w%var(1, k), g1c(cs, j, k))
        end do
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
    call scale_rows(n, kl, ku, w)
  contains
    subroutine put(i, jj, a)
      integer, intent(in) :: i, jj
      real(wp), intent(in) :: a
      ! LAPACK general band storage (dgbsv): AB(kl+ku+1+i-j, j) = A(i, j).
      w%ab(kl + ku + 1 + i - jj, jj) = w%ab(kl + ku + 1 + i - jj, jj) + a
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
    w%kb = 0
    do t = 1, ntouched
      p = w%touched(t)
      do a = w%node_ptr(p), w%node_last(p) - 1
        do b = w%node_ptr(p), w%node_last(p) - 1
          w%kb = max(w%kb, abs(w%node_row(a) - w%node_row(b)))
        end do
      end do
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
          ! Stored as k(jb - ja, ja) = K(ja, jb).
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
