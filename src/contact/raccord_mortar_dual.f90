!> Dual (biorthogonal) multiplier basis of mortar matching (Wohlmuth, SIAM
!> J. Numer. Anal. 38 (2000) 989-1012; Popp, Gee & Wall, IJNME 79 (2009),
!> eqs (20)-(22); doc/theory-contact-mortar.md, section 9): on each slave
!> edge, one multiplier per trace node (start, end, mid),
!>   psi_i = sum_j A_ij N_j,   A = D M^-1,
!>   D = diag(integral of N_j),   M_ij = integral of N_i N_j,
!> integrated over the whole edge with its own measure dGamma, so that
!>   integral of psi_i N_j dGamma = delta_ij integral of N_j dGamma
!> (biorthogonality) and sum_i psi_i = 1 (sum_i N_i = 1 makes the column
!> sums of M those of D, so the column sums of A = D M^-1 are 1).
!> The mortar G1 of a fully covered slave edge is then diagonal, and the
!> paper's nodal gap G1^-T g_w of (19) is the weighted gap over
!> integral of N_j: the nodal and the weighted conditions coincide there.
!>
!> The integrals use the 3-point Gauss rule of the G1 integration
!> (raccord_mortar) on the edge's own geometry (|dx/dxi|, and 2 pi r in
!> axisymmetry), so a fully covered edge integrated in one piece has a
!> G1 diagonal to round-off even on curved Q8 edges; on a straight edge
!> with a centred mid node the rule is exact and A is the constant (taken
!> as such for 2-node edges in plane strain and plane stress)
!>   2-node: [2 -1; -1 2]
!>   3-node (start, end, mid): [3/2 1/2 -1/4; 1/2 3/2 -1/4; -1 -1 3/2]
!> (tools/mortar/dual_coefficients.py derives them exactly).
!>
!> On the axis of an axisymmetric model (a 3-node edge with a corner at
!> r = 0) the corner's ring weight integral of N_axis 2 pi r dGamma is zero
!> on a straight edge with a centred mid node, but on the current geometry
!> (a curved or deformed edge, a mid node off the centre) it is a small
!> number of either sign, and its psi with it: the corner's row came and
!> went with that sign, and each time it came back it pushed out in one
!> step a corner that had sunk into the master while it had no row (energy
!> given; doc/theory-contact-mortar.md section 9, "The axis"). The axis
!> corner therefore has no multiplier: its psi is given to the mid node
!> (the boundary modification of raccord_mortar's merge_uncovered, so
!> sum_i psi_i = 1 still holds), and its position enters the mid node's
!> row with its ring weight.
module raccord_mortar_dual
  use raccord_kinds, only: wp, pi
  use raccord_shape, only: shape_line
  implicit none
  private

  !> Closed forms of A on a straight edge with constant Jacobian (local
  !> order start, end, mid; column-major: A(i, j) multiplies N_j in psi_i).
  real(wp), parameter, public :: DUAL_A2(2, 2) = reshape([2.0_wp, -1.0_wp, -1.0_wp, 2.0_wp], [2, 2])
  real(wp), parameter, public :: DUAL_A3(3, 3) = reshape([1.5_wp, 0.5_wp, -1.0_wp, &
    0.5_wp, 1.5_wp, -1.0_wp, -0.25_wp, -0.25_wp, 1.5_wp], [3, 3])

  ! 3-point Gauss-Legendre on [-1, 1] (the rule of raccord_mortar's G1).
  real(wp), parameter :: GS(3) = [-0.774596669241483377_wp, 0.0_wp, 0.774596669241483377_wp]
  real(wp), parameter :: GW(3) = [5.0_wp/9.0_wp, 8.0_wp/9.0_wp, 5.0_wp/9.0_wp]

  ! A node with |r| at most this times the edge's largest |r| is on the axis.
  real(wp), parameter :: AXIS_TOL = 1.0e-12_wp

  public :: dual_coefficients, dual_basis

contains

  !> A = D M^-1 of the edge xs(2, nen) (start, end, mid), with dGamma =
  !> |dx/dxi| dxi, times 2 pi r when axisymmetric. A(1:nen, 1:nen) is set,
  !> the rest zero. A degenerate edge (M not positive definite: zero
  !> length, r = 0 all along) gets the straight edge's closed form. An
  !> axisymmetric 3-node edge with a corner on the axis (r = 0) gives that
  !> corner's row of A to the mid node's (see the module's header).
  pure subroutine dual_coefficients(nen, xs, axisymmetric, a)
    integer, intent(in) :: nen
    real(wp), intent(in) :: xs(2, 3)
    logical, intent(in) :: axisymmetric
    real(wp), intent(out) :: a(3, 3)
    real(wp) :: m(3, 3), d(3), sh(3), dsh(3), p(2), t(2), dg, l(3, 3), y(3), rmax
    integer :: g, i, j, k
    logical :: ok

    a = 0.0_wp
    ! A straight 2-node edge in plane strain/stress has a constant Jacobian:
    ! A is the closed form (exact, and no integration per step).
    if (nen == 2 .and. .not. axisymmetric) then
      a(1:2, 1:2) = DUAL_A2
      return
    end if
    m = 0.0_wp
    d = 0.0_wp
    do g = 1, 3
      call shape_line(nen, GS(g), sh, dsh)
      p = 0.0_wp
      t = 0.0_wp
      do i = 1, nen
        p = p + xs(:, i)*sh(i)
        t = t + xs(:, i)*dsh(i)
      end do
      dg = sqrt(t(1)**2 + t(2)**2)*GW(g)
      if (axisymmetric) dg = dg*(2.0_wp*pi*p(1))
      do j = 1, nen
        d(j) = d(j) + sh(j)*dg
        do i = 1, nen
          m(i, j) = m(i, j) + sh(i)*sh(j)*dg
        end do
      end do
    end do
    ! Cholesky M = L L^T (M is symmetric positive definite on a sane edge).
    l = 0.0_wp
    ok = .true.
    do j = 1, nen
      l(j, j) = m(j, j) - sum(l(j, 1:j - 1)**2)
      if (.not. (l(j, j) > 1.0e-14_wp*maxval(abs(m(1:nen, 1:nen))))) then
        ok = .false.
        exit
      end if
      l(j, j) = sqrt(l(j, j))
      do i = j + 1, nen
        l(i, j) = (m(i, j) - sum(l(i, 1:j - 1)*l(j, 1:j - 1)))/l(j, j)
      end do
    end do
    if (.not. ok) then
      if (nen == 2) then
        a(1:2, 1:2) = DUAL_A2
      else
        a = DUAL_A3
      end if
      return
    end if
    ! A = D M^-1, i.e. A^T = M^-1 D (M symmetric): column i of A^T, row i
    ! of A, solves M y = d(i) e_i.
    do i = 1, nen
      y = 0.0_wp
      y(i) = d(i)
      do k = 1, nen
        y(k) = (y(k) - sum(l(k, 1:k - 1)*y(1:k - 1)))/l(k, k)
      end do
      do k = nen, 1, -1
        y(k) = (y(k) - sum(l(k + 1:nen, k)*y(k + 1:nen)))/l(k, k)
      end do
      a(i, 1:nen) = y(1:nen)
    end do
    ! A corner on the axis carries no ring: psi_mid <- psi_mid + psi_axis,
    ! psi_axis <- 0 (doc/theory-contact-mortar.md section 9, "The axis").
    ! The model holds the axis nodes at r = 0 exactly (u_r = 0).
    if (axisymmetric .and. nen == 3) then
      rmax = maxval(abs(xs(1, 1:3)))
      do i = 1, 2
        if (abs(xs(1, i)) <= AXIS_TOL*rmax) then
          a(3, 1:3) = a(3, 1:3) + a(i, 1:3)
          a(i, 1:3) = 0.0_wp
        end if
      end do
    end if
  end subroutine dual_coefficients

  !> psi(1:nen) at a point where the edge's shape functions are sh(1:nen):
  !> psi_i = sum_j A(i, j) sh(j).
  pure subroutine dual_basis(nen, a, sh, psi)
    integer, intent(in) :: nen
    real(wp), intent(in) :: a(3, 3), sh(3)
    real(wp), intent(out) :: psi(3)
    integer :: i
    psi = 0.0_wp
    do i = 1, nen
      psi(i) = sum(a(i, 1:nen)*sh(1:nen))
    end do
  end subroutine dual_basis
end module raccord_mortar_dual
