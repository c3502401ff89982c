!> Geometry of a 2- or 3-node surface segment in the current
!> configuration: position and tangent at a parameter, closest-point
!> projection of a point (node-to-segment matching, method brief section 4).
module raccord_segment
  use raccord_kinds, only: wp
  use raccord_shape, only: shape_line
  implicit none
  private

  public :: segment_point, project_on_segment, rotate_ccw

contains

  !> Position x(s) and tangent dx/ds of a segment with nodes xs(2, nen)
  !> (start, end[, mid]) at s in [-1, 1].
  pure subroutine segment_point(nen, xs, s, x, dxds, d2xds2)
    integer, intent(in) :: nen
    real(wp), intent(in) :: xs(2, 3), s
    real(wp), intent(out) :: x(2), dxds(2)
    real(wp), intent(out), optional :: d2xds2(2)
    real(wp) :: n(3), dn(3)
    call shape_line(nen, s, n, dn)
    ! xs N and xs dN written out (matmul on a 2 x nen section is a library
    ! call here, a tenth of the mortar matching).
    x = xs(:, 1)*n(1) + xs(:, 2)*n(2)
    dxds = xs(:, 1)*dn(1) + xs(:, 2)*dn(2)
    if (nen == 3) then
      x = x + xs(:, 3)*n(3)
      dxds = dxds + xs(:, 3)*dn(3)
    end if
    if (present(d2xds2)) then
      if (nen == 3) then
        ! N_start = s(s-1)/2, N_end = s(s+1)/2, N_mid = 1 - s^2: second derivatives 1, 1, -2.
        d2xds2 = xs(:, 1) + xs(:, 2) - 2.0_wp*xs(:, 3)
      else
        d2xds2 = 0.0_wp
      end if
    end if
  end subroutine segment_point

  !> Closest point of the segment's curve to p: parameter s (not clamped:
  !> |s| > 1 means the foot lies beyond an end), the foot x and the unit
  !> tangent there (when asked for). Straight segments project in closed form; quadratic ones
  !> by Newton on (x(s) - p) . x'(s) = 0 from the straight-chord guess,
  !> safeguarded: a step that does not reduce the distance is halved, and
  !> after 30 iterations the best point seen is kept.
  pure subroutine project_on_segment(nen, xs, p, s, foot, tangent)
    integer, intent(in) :: nen
    real(wp), intent(in) :: xs(2, 3), p(2)
    real(wp), intent(out) :: s, foot(2)
    real(wp), intent(out), optional :: tangent(2)
    real(wp) :: chord(2), dx(2), d2x(2), f, fp, ds, snew, dist, dnew, xn(2), dxn(2)
    integer :: it, half
    chord = xs(:, 2) - xs(:, 1)
    s = -1.0_wp + 2.0_wp*dot_product(p - xs(:, 1), chord)/max(dot_product(chord, chord), tiny(1.0_wp))
    if (nen == 3) then
      call segment_point(nen, xs, s, foot, dx)
      dist = sqrt((foot(1) - p(1))**2 + (foot(2) - p(2))**2)
      do it = 1, 30
        call segment_point(nen, xs, s, foot, dx, d2x)
        f = dot_product(foot - p, dx)
        fp = dot_product(dx, dx) + dot_product(foot - p, d2x)
        if (fp <= 0.0_wp) fp = dot_product(dx, dx)
        ds = -f/fp
        half = 0
        do
          snew = s + ds
          call segment_point(nen, xs, snew, xn, dxn)
          dnew = sqrt((xn(1) - p(1))**2 + (xn(2) - p(2))**2)
          if (dnew <= dist .or. half >= 20) exit
          ds = 0.5_wp*ds
          half = half + 1
        end do
        if (dnew > dist) exit
        s = snew
        dist = dnew
        if (abs(ds) < 1.0e-14_wp) exit
      end do
    end if
    call segment_point(nen, xs, s, foot, dx)
    if (present(tangent)) tangent = dx/max(sqrt(dx(1)**2 + dx(2)**2), tiny(1.0_wp))
  end subroutine project_on_segment

  !> v turned by +90 degrees.
  pure function rotate_ccw(v) result(r)
    real(wp), intent(in) :: v(2)
    real(wp) :: r(2)
    r = [-v(2), v(1)]
  end function rotate_ccw
end module raccord_segment
