!> Consistent nodal forces of loads on element edges
!> (doc/theory-elements.md, section 5).
module raccord_edge_load
  use raccord_kinds, only: wp, pi
  use raccord_quadrature, only: gauss_legendre
  use raccord_shape, only: shape_line
  implicit none
  private

  public :: add_edge_traction, add_edge_traction_axi

contains

  !> Consistent nodal forces fe(2, 3) (start, end, mid; mid zero for a
  !> 2-node edge) of a constant traction(2) [force/length^2] plus a pressure
  !> [positive pushes into the body] on an edge xe(2, 3) ordered
  !> counter-clockwise around the body, times the thickness (theory eq. 5.1):
  !>   f_a = h int N_a (t |x'(s)| - p n(s) |x'(s)|) ds,  n |x'| = (y', -x').
  !> The pressure integrand is a polynomial (degree 1 + 2 for a 3-node edge),
  !> integrated exactly by 2 Gauss points. The traction integrand holds
  !> |x'(s)|, a polynomial only on straight edges; a 3-node edge uses 10
  !> points (exact to degree 19): relative error 3e-8 on an edge whose mid
  !> node sits 0.23 chord lengths off the chord, round-off on mild curvature.
  pure subroutine add_edge_traction(nen_edge, xe, traction, pressure, thickness, fe)
    integer, intent(in) :: nen_edge
    real(wp), intent(in) :: xe(2, 3), traction(2), pressure, thickness
    real(wp), intent(out) :: fe(2, 3)
    integer, parameter :: max_gp = 10
    real(wp) :: sg(max_gp), wg(max_gp), n(3), dn(3), tang(2), nrm(2), jac
    integer :: ngp, g, a, nen
    fe = 0.0_wp
    nen = min(max(nen_edge, 2), 3)
    if (nen_edge /= nen) return
    ngp = 2
    if (nen == 3) ngp = max_gp
    call gauss_legendre(ngp, sg(1:ngp), wg(1:ngp))
    do g = 1, ngp
      call shape_line(nen, sg(g), n, dn)
      tang = 0.0_wp
      do a = 1, nen
        tang = tang + dn(a)*xe(:, a)
      end do
      jac = norm2(tang)
      ! outward normal times |x'|: the tangent turned clockwise
      nrm = [tang(2), -tang(1)]
      do a = 1, nen
        fe(:, a) = fe(:, a) + wg(g)*thickness*n(a)*(traction*jac - pressure*nrm)
      end do
    end do
  end subroutine add_edge_traction

  !> The same on an axisymmetric body (x = r, y the axis): ring-total nodal
  !> forces f_a = 2 pi int N_a (t |x'| - p n |x'|) r(s) ds (method brief
  !> 9.1; for a straight 2-node edge f1 = 2 pi p h (2 r1 + r2)/6 ...). The
  !> pressure integrand gains a degree from r(s): 2 points are exact for a
  !> 2-node edge (degree 2), 10 points for a 3-node edge, as above.
  pure subroutine add_edge_traction_axi(nen_edge, xe, traction, pressure, fe)
    integer, intent(in) :: nen_edge
    real(wp), intent(in) :: xe(2, 3), traction(2), pressure
    real(wp), intent(out) :: fe(2, 3)
    integer, parameter :: max_gp = 10
    real(wp) :: sg(max_gp), wg(max_gp), n(3), dn(3), tang(2), nrm(2), jac, r
    integer :: ngp, g, a, nen
    fe = 0.0_wp
    nen = min(max(nen_edge, 2), 3)
    if (nen_edge /= nen) return
    ngp = 2
    if (nen == 3) ngp = max_gp
    call gauss_legendre(ngp, sg(1:ngp), wg(1:ngp))
    do g = 1, ngp
      call shape_line(nen, sg(g), n, dn)
      tang = 0.0_wp
      r = 0.0_wp
      do a = 1, nen
        tang = tang + dn(a)*xe(:, a)
        r = r + n(a)*xe(1, a)
      end do
      jac = norm2(tang)
      nrm = [tang(2), -tang(1)]
      do a = 1, nen
        fe(:, a) = fe(:, a) + wg(g)*2.0_wp*pi*r*n(a)*(traction*jac - pressure*nrm)
      end do
    end do
  end subroutine add_edge_traction_axi
end module raccord_edge_load
