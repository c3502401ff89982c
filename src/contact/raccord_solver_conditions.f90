!> The discrete contact and Coulomb conditions of the paper, equation (19),
!> as the multiplier solve's forms test them (doc/theory-contact.md,
!> section 3): the set update from the complementarity functions, the
!> least-index rule against cycling, the residual of (19), and G1 (the
!> band storage of cs%g1, and the identity of the weighted conditions).
module raccord_solver_conditions
  use raccord_kinds, only: wp
  use raccord_constraint_set, only: constraint_set_t
  use raccord_solver_work, only: solver_work_t, ST_OPEN, ST_STICK, ST_SLIP
  implicit none
  private

  !> Gaps below this fraction of a constraint's length are round-off of
  !> touching surfaces (a length of 1 in coordinates of order 1e3 carries
  !> errors of 1e-13).
  real(wp), parameter :: GAP_ROUNDOFF = 1.0e-12_wp
  !> Iterations after which one change of set is taken per iteration
  !> (least_index_change; saddle form and banded friction form).
  integer, parameter, public :: LEAST_INDEX_AFTER = 30
  public :: least_index_change, update_sets, condition_residual, band_matvec, g1_at, g1c
  public :: holds_to_roundoff, tested_sum, tested_row

contains

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

  !> After LEAST_INDEX_AFTER iterations, whether the iterate (for the sets
  !> it was solved with, w%status) satisfies (19) to within w%tolerance
  !> (&contact_pair tolerance, default 1e-12: round-off, the fraction
  !> GAP_ROUNDOFF of the active test's band), relative as in
  !> condition_residual: the iteration then ends there, converged,
  !> instead of updating the sets.
  !> Where a decision of update_sets falls on round-off, the sets can
  !> alternate between iterates that all solve (19): the corner node of a
  !> Q8 slave edge on the axis (axisymmetric, mortar P1) carries the length
  !> integral of N_corner 2 pi r ds = 0 (-1.2e-17), so its active test has
  !> no round-off band and went open / slip / open ... on the sign of
  !> F_j - c_j gn_j = +-1e-19 until max_iterations (one change per
  !> iteration, which the least-index rule keeps; residual 2e-16 at every
  !> iterate; tests/fuzz/seeds/axi.nml, step 1). A solve that settles within
  !> LEAST_INDEX_AFTER iterations is unchanged (doc/theory-contact.md,
  !> section 3).
  logical function holds_to_roundoff(cs, mu, friction, it, w) result(holds)
    type(constraint_set_t), intent(in) :: cs
    real(wp), intent(in) :: mu
    logical, intent(in) :: friction
    integer, intent(in) :: it                  !< the iteration of the iterate
    type(solver_work_t), intent(in) :: w
    integer :: j
    real(wp) :: lscale, g
    holds = .false.
    if (it <= LEAST_INDEX_AFTER) return
    if (condition_residual(cs, mu, friction, w) > w%tolerance) return
    ! and what condition_residual leaves out: a slipping constraint slips
    ! against its tangential force (slip: T_j = mu F_j sigma_j, gt_j sigma_j <= 0)
    if (friction) then
      lscale = length_scale(cs)
      do j = 1, cs%m
        if (w%status(j) /= ST_SLIP) cycle
        g = w%gt(j)
        if (cs%weighted .and. cs%length(j) > 0.0_wp) g = g/cs%length(j)
        if (w%sigma(j)*g > w%tolerance*lscale) return
      end do
    end if
    holds = .true.
  end function holds_to_roundoff

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
    lscale = length_scale(cs)
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
        if (friction .and. .not. cs%tcorners) r = max(r, (abs(tc) - mu*fc)/fscale)
      end if
      ! tangential corner multipliers: the Coulomb bound of each owner on
      ! its tested forces (raccord_saddle_form, solve_saddle_tc)
      if (friction .and. cs%tcorners) then
        if (cs%tcor(1, j) < 0) r = max(r, (abs(tested_sum(cs, w%ft, j)) - &
          mu*max(tested_sum(cs, w%fn, j), 0.0_wp))/fscale)
      end if
    end do
    r = max(r, 0.0_wp)
  end function condition_residual

  !> Row i of the test T' of owner row j of tangential corner multipliers
  !> (cs%tcorners) and its weight wi: s = 0 the owner itself (1), s = 1, 2
  !> the mid rows that take its value (1/2); i = 0 where there is none.
  pure subroutine tested_row(cs, j, s, i, wi)
    type(constraint_set_t), intent(in) :: cs
    integer, intent(in) :: j, s
    integer, intent(out) :: i
    real(wp), intent(out) :: wi
    if (s == 0) then
      i = j
      wi = 1.0_wp
    else
      i = max(cs%tmid(s, j), 0)
      wi = 0.5_wp
    end if
  end subroutine tested_row

  !> (T' v)_j for an owner row j of tangential corner multipliers
  !> (cs%tcorners): v_j plus half of v on each mid row that takes its value.
  pure real(wp) function tested_sum(cs, v, j) result(t)
    type(constraint_set_t), intent(in) :: cs
    real(wp), intent(in) :: v(:)
    integer, intent(in) :: j
    integer :: s, i
    real(wp) :: wi
    t = v(j)
    do s = 1, 2
      call tested_row(cs, j, s, i, wi)
      if (i > 0) t = t + wi*v(i)
    end do
  end function tested_sum

  !> The shortest length a multiplier acts on, the scale of the gaps in
  !> condition_residual; a row of zero length (an axisymmetric node on the
  !> axis: 2 pi r = 0) would make any gap huge.
  real(wp) function length_scale(cs) result(lscale)
    type(constraint_set_t), intent(in) :: cs
    lscale = minval(cs%length(1:cs%m), mask=cs%length(1:cs%m) > 0.0_wp)
    if (.not. (lscale > 0.0_wp .and. lscale < huge(1.0_wp))) lscale = 1.0_wp
  end function length_scale

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
end module raccord_solver_conditions
