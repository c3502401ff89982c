!> Shape functions of the quadrilaterals and of their edges
!> (doc/theory-elements.md, section 1).
!>
!> Node order is raccord_mesh's: corners 1-4 counter-clockwise at
!> (xi, eta) = (-1,-1), (1,-1), (1,1), (-1,1), then (Q8) mid-side nodes
!> 5 (0,-1), 6 (1,0), 7 (0,1), 8 (-1,0). Edge (line) nodes are ordered
!> (start, end, mid) at s = -1, +1, 0, as the mesh stores surface edges.
module raccord_shape
  use raccord_kinds, only: wp
  use raccord_mesh, only: ELEM_Q4, ELEM_Q8
  implicit none
  private

  public :: shape_quad, shape_line, node_natural_coords

  !> Natural coordinates of the 8 nodes (the first 4 serve Q4).
  real(wp), parameter :: xi_node(8) = [-1.0_wp, 1.0_wp, 1.0_wp, -1.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, -1.0_wp]
  real(wp), parameter :: eta_node(8) = [-1.0_wp, -1.0_wp, 1.0_wp, 1.0_wp, -1.0_wp, 0.0_wp, 1.0_wp, 0.0_wp]

contains

  !> Natural coordinates (xi, eta) of local node a (1..8).
  pure function node_natural_coords(a) result(c)
    integer, intent(in) :: a
    real(wp) :: c(2)
    c = [xi_node(a), eta_node(a)]
  end function node_natural_coords

  !> Shape functions n(1:nen) and their natural derivatives dn(1:2, 1:nen)
  !> (row 1: d/dxi, row 2: d/deta) at (xi, eta). Unknown etype: all zero.
  pure subroutine shape_quad(etype, xi, eta, n, dn)
    integer, intent(in) :: etype
    real(wp), intent(in) :: xi, eta
    real(wp), intent(out) :: n(:), dn(:,:)
    integer :: a
    real(wp) :: xa, ya
    n = 0.0_wp
    dn = 0.0_wp
    select case (etype)
    case (ELEM_Q4)
      ! bilinear: N_a = (1 + xi xi_a)(1 + eta eta_a)/4   (theory eq. 1.1)
      do a = 1, 4
        xa = xi_node(a)
        ya = eta_node(a)
        n(a) = 0.25_wp*(1.0_wp + xi*xa)*(1.0_wp + eta*ya)
        dn(1, a) = 0.25_wp*xa*(1.0_wp + eta*ya)
        dn(2, a) = 0.25_wp*ya*(1.0_wp + xi*xa)
      end do
    case (ELEM_Q8)
      ! serendipity (theory eq. 1.2): corners
      ! N_a = (1 + xi xi_a)(1 + eta eta_a)(xi xi_a + eta eta_a - 1)/4
      do a = 1, 4
        xa = xi_node(a)
        ya = eta_node(a)
        n(a) = 0.25_wp*(1.0_wp + xi*xa)*(1.0_wp + eta*ya)*(xi*xa + eta*ya - 1.0_wp)
        dn(1, a) = 0.25_wp*xa*(1.0_wp + eta*ya)*(2.0_wp*xi*xa + eta*ya)
        dn(2, a) = 0.25_wp*ya*(1.0_wp + xi*xa)*(xi*xa + 2.0_wp*eta*ya)
      end do
      ! mid-side nodes on eta = -+1 (5, 7): N = (1 - xi^2)(1 + eta eta_a)/2
      do a = 5, 7, 2
        ya = eta_node(a)
        n(a) = 0.5_wp*(1.0_wp - xi*xi)*(1.0_wp + eta*ya)
        dn(1, a) = -xi*(1.0_wp + eta*ya)
        dn(2, a) = 0.5_wp*ya*(1.0_wp - xi*xi)
      end do
      ! mid-side nodes on xi = +-1 (6, 8): N = (1 + xi xi_a)(1 - eta^2)/2
      do a = 6, 8, 2
        xa = xi_node(a)
        n(a) = 0.5_wp*(1.0_wp + xi*xa)*(1.0_wp - eta*eta)
        dn(1, a) = 0.5_wp*xa*(1.0_wp - eta*eta)
        dn(2, a) = -eta*(1.0_wp + xi*xa)
      end do
    end select
  end subroutine shape_quad

  !> Shape functions of a 2- or 3-node line at s in [-1, 1], nodes ordered
  !> (start s=-1, end s=+1, mid s=0) (theory eq. 1.3). Other nen_edge: zero.
  pure subroutine shape_line(nen_edge, s, n, dn)
    integer, intent(in) :: nen_edge
    real(wp), intent(in) :: s
    real(wp), intent(out) :: n(:), dn(:)
    n = 0.0_wp
    dn = 0.0_wp
    select case (nen_edge)
    case (2)
      n(1) = 0.5_wp*(1.0_wp - s)
      n(2) = 0.5_wp*(1.0_wp + s)
      dn(1) = -0.5_wp
      dn(2) = 0.5_wp
    case (3)
      n(1) = 0.5_wp*s*(s - 1.0_wp)
      n(2) = 0.5_wp*s*(s + 1.0_wp)
      n(3) = 1.0_wp - s*s
      dn(1) = s - 0.5_wp
      dn(2) = s + 0.5_wp
      dn(3) = -2.0_wp*s
    end select
  end subroutine shape_line
end module raccord_shape
