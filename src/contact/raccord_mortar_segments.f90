!> Geometry and basis functions of mortar matching ("raccord integral",
!> paper sections 2-3; method brief section 5; doc/theory-contact-mortar.md):
!> slave nodal normals, the interpolated slave normal field, the two
!> projections of the segmentation (a master point onto a slave segment
!> along the slave normal field; a slave point along its normal onto a
!> master segment), and the multiplier functions psi_j of M_h^1 and M_h^0
!> (equations (8)-(11)) restricted to one slave segment.
!>
!> Multipliers live on the slave corner nodes (the segment ends) and, on
!> 3-node (Q8) edges, on the mid-side nodes too, unless `corners` (issue
!> #16: a multiplier on every trace node makes the Q8 stick traction zigzag
!> from corner to mid node; the corner space removes it but gave energy on
!> curved frictional cases, so no deck selects it yet). On a segment with
!> parameter xi in [-1, 1], corners at xi = -1, +1, corner space:
!>   P1: psi_start = (1 - xi)/2, psi_end = (1 + xi)/2, linear over the
!>       whole segment (2- and 3-node edges alike);
!>   P0: psi_start = 1 on [-1, 0), psi_end = 1 on [0, 1], the dual cells of
!>       the corner chain (bound z at the segment's parameter midpoint).
!> On 3-node edges these are the lower-order multiplier spaces of
!> quadratic mortar (one degree below the trace, inf-sup stable). Without
!> `corners` a 3-node edge has a multiplier on every trace node: hats on
!> [-1, 0] and [0, 1], P0 cells bounded at xi = -1/2, +1/2 (the default;
!> doc/theory-contact-mortar.md, section 1).
module raccord_mortar_segments
  use raccord_kinds, only: wp
  use raccord_shape, only: shape_line
  use raccord_scene, only: MULT_P0
  use raccord_segment, only: segment_point
  implicit none
  private

  !> Parameter of local node a (start, end, mid) on a segment.
  real(wp), parameter, public :: NODE_XI(3) = [-1.0_wp, 1.0_wp, 0.0_wp]

  public :: outward_normal, normal_field, project_along_field, end_offset, root_along_field, intersect_ray, &
    multiplier_basis, multiplier_breaks, cross2

contains

  !> z-component of the cross product of two plane vectors.
  pure real(wp) function cross2(a, b)
    real(wp), intent(in) :: a(2), b(2)
    cross2 = a(1)*b(2) - a(2)*b(1)
  end function cross2

  !> Unit outward normal of a segment at xi: the tangent turned clockwise
  !> (chains run counter-clockwise around their body).
  pure function outward_normal(nen, xs, xi) result(n)
    integer, intent(in) :: nen
    real(wp), intent(in) :: xs(2, 3), xi
    real(wp) :: n(2), p(2), t(2)
    call segment_point(nen, xs, xi, p, t)
    n = [t(2), -t(1)]/max(sqrt(t(1)**2 + t(2)**2), tiny(1.0_wp))
  end function outward_normal

  !> Slave normal field at xi, interpolated from the nodal normals nn(2, nen)
  !> (start, end, mid) with the segment's shape functions, and its
  !> derivative; not normalised (only its direction is used for rays).
  pure subroutine normal_field(nen, nn, xi, n, dn)
    integer, intent(in) :: nen
    real(wp), intent(in) :: nn(2, 3), xi
    real(wp), intent(out) :: n(2), dn(2)
    real(wp) :: sh(3), dsh(3)
    call shape_line(nen, xi, sh, dsh)
    n = nn(:, 1)*sh(1) + nn(:, 2)*sh(2)
    dn = nn(:, 1)*dsh(1) + nn(:, 2)*dsh(2)
    if (nen == 3) then
      n = n + nn(:, 3)*sh(3)
      dn = dn + nn(:, 3)*dsh(3)
    end if
  end subroutine normal_field

  !> Slave parameter xi in [-1, 1] of the point p seen along the slave
  !> normal field: the root of F(xi) = (p - x_s(xi)) x n(xi). F is monotone
  !> on sane meshes; when it keeps one sign on [-1, 1] the point lies beyond
  !> an end and that end is returned (the segmentation clips to it anyway).
  !> Closed form for a straight segment with one normal (F linear: one
  !> Newton step); bracketed Newton otherwise.
  pure real(wp) function project_along_field(nen, xs, nn, p) result(xi)
    integer, intent(in) :: nen
    real(wp), intent(in) :: xs(2, 3), nn(2, 3), p(2)
    xi = root_along_field(nen, xs, nn, p, end_offset(xs(:, 1), nn(:, 1), p), end_offset(xs(:, 2), nn(:, 2), p))
  end function project_along_field

  !> F of project_along_field at a slave node: (p - x_node) x n_node. It is
  !> F(-1) of the segment that starts at the node and F(+1) of the one that
  !> ends there (every shape function is exactly 0 or 1 at a node), so a
  !> caller that projects the same point on consecutive slave segments can
  !> evaluate it once per node (raccord_mortar).
  pure real(wp) function end_offset(xnode, nnode, p) result(f)
    real(wp), intent(in) :: xnode(2), nnode(2), p(2)
    f = cross2(p - xnode, nnode)
  end function end_offset

  !> project_along_field with F(-1) = flo and F(+1) = fhi already known
  !> (end_offset at the start and end nodes of the segment).
  pure real(wp) function root_along_field(nen, xs, nn, p, flo, fhi) result(xi)
    integer, intent(in) :: nen
    real(wp), intent(in) :: xs(2, 3), nn(2, 3), p(2), flo, fhi
    ! No root inside: p is past the end where it lies ahead of both end
    ! nodes' normal lines, F = (p - x) x n having the sign of t x n. The
    ! smaller |F| (bracketed_root's rule, right for a straight ray) picked
    ! the wrong end for a far master corner when the slave normals turn
    ! (a master facet beyond a vertex was integrated over a whole slave
    ! segment it does not face; doc/verification.md section 13).
    if (flo /= 0.0_wp .and. fhi /= 0.0_wp .and. sign(1.0_wp, flo) == sign(1.0_wp, fhi)) then
      if (sign(1.0_wp, flo) == sign(1.0_wp, cross2(xs(:, 2) - xs(:, 1), nn(:, 1) + nn(:, 2)))) then
        xi = 1.0_wp
      else
        xi = -1.0_wp
      end if
      return
    end if
    if (nen == 2 .and. flo /= 0.0_wp .and. fhi /= 0.0_wp) then
      xi = root_along_line(xs, nn, p, flo, fhi)
      return
    end if
    xi = bracketed_root(1, nen, xs, nn, p, [0.0_wp, 0.0_wp], flo, fhi)
  end function root_along_field

  !> root_along_field on a straight 2-node segment, in closed form. With
  !> x(xi) = xc + xi dx and n(xi) = nc + xi dn (linear shape functions),
  !>   F(xi) = (p - x(xi)) x n(xi) = c + b xi + a xi^2,
  !>   a = -(dx x dn),  b = (p - xc) x dn - dx x nc,  c = (p - xc) x nc,
  !> and F(-1) = flo, F(+1) = fhi of opposite signs: the quadratic has
  !> exactly one root in (-1, 1), taken with the cancellation-free pair
  !> q = -(b + sign(b) sqrt(b^2 - 4ac))/2, roots q/a and c/q, and polished
  !> by one Newton step (the bracketed Newton it replaces iterated the same
  !> F to 4 eps; doc/theory-contact-mortar.md, "Segmentation").
  pure real(wp) function root_along_line(xs, nn, p, flo, fhi) result(xi)
    real(wp), intent(in) :: xs(2, 3), nn(2, 3), p(2), flo, fhi
    real(wp) :: xc(2), dx(2), nc(2), dn(2), r(2), a, b, c, q, disc, r1, r2, f, fp
    xc = 0.5_wp*(xs(:, 1) + xs(:, 2))
    dx = 0.5_wp*(xs(:, 2) - xs(:, 1))
    nc = 0.5_wp*(nn(:, 1) + nn(:, 2))
    dn = 0.5_wp*(nn(:, 2) - nn(:, 1))
    r = p - xc
    a = -(dx(1)*dn(2) - dx(2)*dn(1))
    b = (r(1)*dn(2) - r(2)*dn(1)) - (dx(1)*nc(2) - dx(2)*nc(1))
    c = r(1)*nc(2) - r(2)*nc(1)
    disc = max(b*b - 4.0_wp*a*c, 0.0_wp)
    q = -0.5_wp*(b + sign(sqrt(disc), b))
    if (q == 0.0_wp) then
      ! b = 0 and a c >= 0 cannot bracket a root; the chord of the ends.
      xi = -1.0_wp - 2.0_wp*flo/(fhi - flo)
    else
      r2 = c/q
      if (a /= 0.0_wp) then
        r1 = q/a
        ! The root inside the bracket (the other lies outside it).
        if (abs(r1) < abs(r2)) r2 = r1
      end if
      xi = r2
    end if
    xi = max(-1.0_wp, min(1.0_wp, xi))
    ! One Newton step on F (restores the last bits where the quadratic's
    ! coefficients cancel).
    f = c + xi*(b + xi*a)
    fp = b + 2.0_wp*xi*a
    if (fp /= 0.0_wp) xi = max(-1.0_wp, min(1.0_wp, xi - f/fp))
  end function root_along_line

  !> Master parameter eta in [-1, 1] where the line q + alpha n meets the
  !> master segment xm: root of G(eta) = (x_m(eta) - q) x n, clipped to the
  !> end where |G| is smaller when there is none inside. G is linear for a
  !> 2-node master: eta = -1 + 2 G(-1) / (G(-1) - G(1)) in closed form (the
  !> chord of the bracketed iteration, which one Newton step would only
  !> move by round-off); bracketed Newton for a 3-node master.
  pure real(wp) function intersect_ray(nen, xm, q, n) result(eta)
    integer, intent(in) :: nen
    real(wp), intent(in) :: xm(2, 3), q(2), n(2)
    real(wp) :: dummy(2, 3), glo, ghi
    glo = cross2(xm(:, 1) - q, n)
    ghi = cross2(xm(:, 2) - q, n)
    if (nen == 2) then
      if (glo == 0.0_wp) then
        eta = -1.0_wp
      else if (ghi == 0.0_wp) then
        eta = 1.0_wp
      else if (sign(1.0_wp, glo) == sign(1.0_wp, ghi)) then
        eta = merge(-1.0_wp, 1.0_wp, abs(glo) < abs(ghi))
      else
        eta = -1.0_wp - 2.0_wp*glo/(ghi - glo)
      end if
      return
    end if
    dummy = 0.0_wp
    eta = bracketed_root(2, nen, xm, dummy, q, n, glo, ghi)
  end function intersect_ray

  !> Root on [-1, 1] of F (kind 1: along the normal field of segment xs;
  !> kind 2: ray q + alpha n against segment xs), given its end values flo =
  !> F(-1), fhi = F(+1): Newton kept inside a shrinking sign-change bracket
  !> (bisection when a step leaves it).
  pure real(wp) function bracketed_root(kind, nen, xs, nn, q, n, flo_in, fhi_in) result(s)
    integer, intent(in) :: kind, nen
    real(wp), intent(in) :: xs(2, 3), nn(2, 3), q(2), n(2), flo_in, fhi_in
    real(wp) :: lo, hi, flo, fhi, f, fp, snew
    integer :: it
    lo = -1.0_wp
    hi = 1.0_wp
    flo = flo_in
    fhi = fhi_in
    if (flo == 0.0_wp) then
      s = lo
      return
    end if
    if (fhi == 0.0_wp) then
      s = hi
      return
    end if
    if (sign(1.0_wp, flo) == sign(1.0_wp, fhi)) then
      ! No root inside: the side where |F| grows away from the root is out.
      if (abs(flo) < abs(fhi)) then
        s = lo
      else
        s = hi
      end if
      return
    end if
    ! Start from the chord (secant) guess: exact when F is linear.
    s = lo - flo*(hi - lo)/(fhi - flo)
    do it = 1, 60
      call eval(s, f, fp)
      if (f == 0.0_wp) return
      if (sign(1.0_wp, f) == sign(1.0_wp, flo)) then
        lo = s
        flo = f
      else
        hi = s
        fhi = f
      end if
      if (fp /= 0.0_wp) then
        snew = s - f/fp
      else
        snew = 0.5_wp*(lo + hi)
      end if
      if (snew <= lo .or. snew >= hi) snew = 0.5_wp*(lo + hi)
      if (abs(snew - s) <= 4.0_wp*epsilon(1.0_wp)) then
        s = snew
        return
      end if
      s = snew
    end do
  contains
    pure subroutine eval(t, f, fp)
      real(wp), intent(in) :: t
      real(wp), intent(out) :: f, fp
      real(wp) :: x(2), dx(2), m(2), dm(2), n1, n2
      if (nen == 2) then
        ! Straight segment: segment_point and normal_field written out
        ! (shape_line's linear functions; no calls in the iteration).
        n1 = 0.5_wp*(1.0_wp - t)
        n2 = 0.5_wp*(1.0_wp + t)
        x = xs(:, 1)*n1 + xs(:, 2)*n2
        dx = xs(:, 1)*(-0.5_wp) + xs(:, 2)*0.5_wp
        if (kind == 1) then
          m = nn(:, 1)*n1 + nn(:, 2)*n2
          dm = nn(:, 1)*(-0.5_wp) + nn(:, 2)*0.5_wp
          f = cross2(q - x, m)
          fp = cross2(-dx, m) + cross2(q - x, dm)
        else
          f = cross2(x - q, n)
          fp = cross2(dx, n)
        end if
        return
      end if
      call segment_point(nen, xs, t, x, dx)
      if (kind == 1) then
        call normal_field(nen, nn, t, m, dm)
        f = cross2(q - x, m)
        fp = cross2(-dx, m) + cross2(q - x, dm)
      else
        f = cross2(x - q, n)
        fp = cross2(dx, n)
      end if
    end subroutine eval
  end function bracketed_root

  !> Interior discontinuities (P0) or kinks (P1 on 3-node edges with a
  !> multiplier on every trace node) of the multiplier functions on one
  !> segment, ascending: the mortar segments are split there so that the
  !> Gauss rule sees polynomials. `corners`: the corner space of the module
  !> header on 3-node edges (P1 linear on the whole segment: no break).
  pure subroutine multiplier_breaks(nen, multiplier, corners, nb, brk)
    integer, intent(in) :: nen, multiplier
    logical, intent(in) :: corners
    integer, intent(out) :: nb
    real(wp), intent(out) :: brk(2)
    brk = 0.0_wp
    if (nen == 2 .or. corners) then
      nb = merge(1, 0, multiplier == MULT_P0)
    else if (multiplier == MULT_P0) then
      nb = 2
      brk = [-0.5_wp, 0.5_wp]
    else
      nb = 1
    end if
  end subroutine multiplier_breaks

  !> psi(a) at xi of the multiplier of local node a (start, end, mid) on
  !> one segment. At a break the right-hand value is taken; Gauss points
  !> never sit on a break. On 3-node edges `corners` selects the corner
  !> space (psi(3) = 0: the mid node has no multiplier; see the module
  !> header), otherwise a multiplier on
  !> every trace node (hats on [-1, 0] and [0, 1]; P0 cells bounded at
  !> xi = -1/2, +1/2). For a 3-node edge of length
  !> H (straight, centred mid node) the corner space's edge integrals of
  !> N_i psi_j, local order (start, end, mid), are
  !>   P1: psi_start: (1, 0, 2) H/6     P0: psi_start: (5, -1, 8) H/24
  !> (psi_end mirrors psi_start): the P1 corner block is diagonal.
  pure subroutine multiplier_basis(nen, multiplier, corners, xi, psi)
    integer, intent(in) :: nen, multiplier
    logical, intent(in) :: corners
    real(wp), intent(in) :: xi
    real(wp), intent(out) :: psi(3)
    psi = 0.0_wp
    if (multiplier == MULT_P0) then
      ! Dual cells [z_i, z_i+1] around each chain node (paper, W_h^0).
      if (nen == 2 .or. corners) then
        if (xi < 0.0_wp) then
          psi(1) = 1.0_wp
        else
          psi(2) = 1.0_wp
        end if
      else
        if (xi < -0.5_wp) then
          psi(1) = 1.0_wp
        else if (xi > 0.5_wp) then
          psi(2) = 1.0_wp
        else
          psi(3) = 1.0_wp
        end if
      end if
    else
      ! Hats on the chain intervals (paper, W_h^1).
      if (nen == 2 .or. corners) then
        psi(1) = 0.5_wp*(1.0_wp - xi)
        psi(2) = 0.5_wp*(1.0_wp + xi)
      else if (xi < 0.0_wp) then
        psi(1) = -xi
        psi(3) = 1.0_wp + xi
      else
        psi(2) = xi
        psi(3) = 1.0_wp - xi
      end if
    end if
  end subroutine multiplier_basis
end module raccord_mortar_segments
