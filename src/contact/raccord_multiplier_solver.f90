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
!> With cs%tcorners (mortar on a Q8 slave, edge_multipliers =
!> 'tangential_corners') the tangential unknowns are tau = T tau_c, the
!> corner space's, and the tangential conditions are tested with T'
!> (raccord_saddle_form, solve_saddle_tc; doc/reproduction.md, "The Q8
!> stick zigzag: tangential corner multipliers"); the normal ones are (19).
!> Degrees of freedom with prescribed motion have M^-1 = 0: infinitely
!> massive, they take no correction.
!>
!> This module is the driver: it builds K (raccord_delassus), picks the
!> form and hands back the sets. The forms: raccord_frictionless_form,
!> raccord_nts_friction_form, raccord_banded_friction_form,
!> raccord_saddle_form; the conditions and the set rule:
!> raccord_solver_conditions; the workspace: raccord_solver_work.
module raccord_multiplier_solver
  use raccord_kinds, only: wp
  use raccord_constraint_set, only: constraint_set_t
  use raccord_solver_work, only: solver_work_t, ST_OPEN, ST_STICK, ST_SLIP, &
    ensure1, ensure_i, ensure_i2
  use raccord_solver_conditions, only: condition_residual
  use raccord_delassus, only: delassus
  use raccord_frictionless_form, only: solve_frictionless
  use raccord_nts_friction_form, only: solve_diagonal_friction
  use raccord_banded_friction_form, only: solve_banded_friction
  use raccord_saddle_form, only: solve_saddle, solve_saddle_tc
  implicit none
  private

  public :: solver_work_t, ST_OPEN, ST_STICK, ST_SLIP
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
    integer :: m, j, nu, info, bw
    logical :: friction, same
    real(wp) :: gjj

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
        ! G1 of the conditions on the diagonal, g1c(cs, j, j), written out:
        ! the function of another module was one call per constraint
        gjj = 1.0_wp
        if (.not. cs%weighted) gjj = cs%g1(0, j)
        w%c(j) = gjj**2/(dt*dt*w%knn(0, j))
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
    if (friction .and. cs%tcorners) then
      ! tangential corner multipliers: their own saddle form
      call solve_saddle_tc(cs, dt, mu, bw, max_iter, w, same)
      call finish_solve(cs, mu, friction, same, w, status, sigma)
      return
    else if (w%saddle_only) then
      continue
    else if (.not. friction .and. .not. cs%weighted) then
      call solve_frictionless(cs, dt, max_iter, w, same, info)
      if (info == 0) then
        call finish_solve(cs, mu, friction, same, w, status, sigma)
        return
      end if
    else if (friction .and. cs%g1_band == 0 .and. .not. cs%weighted) then
      call solve_diagonal_friction(cs, dt, mu, max_iter, w, same, info)
      if (info == 0) then
        call finish_solve(cs, mu, friction, same, w, status, sigma)
        return
      end if
    else if (friction .and. .not. cs%weighted .and. any(w%status(1:m) /= ST_STICK)) then
      ! (A guess of all in stick leaves the saddle form nothing to
      ! eliminate: it is then the same system, with less bookkeeping.)
      call solve_banded_friction(cs, dt, mu, max_iter, w, same, info)
      if (info == 0) then
        call finish_solve(cs, mu, friction, same, w, status, sigma)
        return
      end if
    end if

    ! A reduced form that declined leaves in w%status the sets of its
    ! iteration w%iterations, not yet solved: the saddle form continues
    ! from there (the same update rule, so the same iterations to round-off)
    ! instead of starting again from the guess.
    call solve_saddle(cs, dt, mu, friction, bw, max_iter, w, same)
    call finish_solve(cs, mu, friction, same, w, status, sigma)
  end subroutine solve_multipliers

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
end module raccord_multiplier_solver
