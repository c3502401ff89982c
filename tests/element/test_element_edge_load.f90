!> Consistent edge loads (src/element/raccord_edge_load.f90). References are
!> computed independently by composite Simpson integration along the edge.
program test_element_edge_load
  use raccord_kinds, only: wp
  use raccord_edge_load, only: add_edge_traction
  use raccord_check, only: failure_t, new_test, run_tests, check, check_close
  use raccord_strings, only: str
  implicit none

  real(wp), parameter :: thick = 0.7_wp

  call run_tests('element_edge_load', [ &
    new_test('straight 2-node edge: force and moment', test_straight2), &
    new_test('straight 3-node edge: force, moment, 1/6 2/3 1/6', test_straight3), &
    new_test('curved 3-node edge under pressure: exact', test_curved_pressure), &
    new_test('curved 3-node edge under traction', test_curved_traction), &
    new_test('pressure pushes into the body', test_pressure_inward)])

contains

  !> Reference resultant force and moment (about the origin) of
  !> h (t |x'| - p n|x'|) along the edge, by composite Simpson on nsub
  !> sub-intervals of the quadratic (or linear) parametrisation.
  subroutine reference(nen, xe, t, p, nsub, force, moment)
    integer, intent(in) :: nen, nsub
    real(wp), intent(in) :: xe(2, 3), t(2), p
    real(wp), intent(out) :: force(2), moment
    integer :: k
    real(wp) :: s, ds, wk, xs(2), dxs(2), q(2)
    force = 0.0_wp
    moment = 0.0_wp
    ds = 2.0_wp/real(nsub, wp)
    do k = 0, nsub
      s = -1.0_wp + ds*real(k, wp)
      wk = merge(1.0_wp, merge(4.0_wp, 2.0_wp, mod(k, 2) == 1), k == 0 .or. k == nsub)*ds/3.0_wp
      if (nen == 2) then
        xs = 0.5_wp*(1.0_wp - s)*xe(:, 1) + 0.5_wp*(1.0_wp + s)*xe(:, 2)
        dxs = 0.5_wp*(xe(:, 2) - xe(:, 1))
      else
        xs = 0.5_wp*s*(s - 1.0_wp)*xe(:, 1) + 0.5_wp*s*(s + 1.0_wp)*xe(:, 2) + (1.0_wp - s*s)*xe(:, 3)
        dxs = (s - 0.5_wp)*xe(:, 1) + (s + 0.5_wp)*xe(:, 2) - 2.0_wp*s*xe(:, 3)
      end if
      ! load density: traction times arc length minus pressure times the
      ! outward normal (tangent turned clockwise) times arc length
      q = thick*(t*norm2(dxs) - p*[dxs(2), -dxs(1)])
      force = force + wk*q
      moment = moment + wk*(xs(1)*q(2) - xs(2)*q(1))
    end do
  end subroutine reference

  subroutine resultants(xe, fe, force, moment)
    real(wp), intent(in) :: xe(2, 3), fe(2, 3)
    real(wp), intent(out) :: force(2), moment
    integer :: a
    force = sum(fe, dim=2)
    moment = 0.0_wp
    do a = 1, 3
      moment = moment + xe(1, a)*fe(2, a) - xe(2, a)*fe(1, a)
    end do
  end subroutine resultants

  subroutine compare(failure, nen, xe, t, p, nsub, rtol, label)
    type(failure_t), allocatable, intent(inout) :: failure
    integer, intent(in) :: nen, nsub
    real(wp), intent(in) :: xe(2, 3), t(2), p, rtol
    character(len=*), intent(in) :: label
    real(wp) :: fe(2, 3), f(2), m, fr(2), mr, scale
    call add_edge_traction(nen, xe, t, p, thick, fe)
    call resultants(xe, fe, f, m)
    call reference(nen, xe, t, p, nsub, fr, mr)
    ! tolerance relative to the load scale |load| * length (* lever arm)
    scale = norm2(fr) + 1.0e-300_wp
    call check_close(failure, f(1), fr(1), label // ' Fx', abs_tol=rtol*scale)
    call check_close(failure, f(2), fr(2), label // ' Fy', abs_tol=rtol*scale)
    call check_close(failure, m, mr, label // ' moment', abs_tol=rtol*scale*maxval(abs(xe)))
    if (nen == 2) call check(failure, all(fe(:, 3) == 0.0_wp), label // ': mid force of a 2-node edge not zero')
  end subroutine compare

  subroutine test_straight2(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp) :: xe(2, 3)
    xe = reshape([0.3_wp, -0.2_wp, 2.1_wp, 1.4_wp, 0.0_wp, 0.0_wp], [2, 3])
    ! integrands are polynomials of degree <= 2: Simpson is exact
    call compare(failure, 2, xe, [1.3_wp, -2.2_wp], 0.0_wp, 2, 1.0e-14_wp, 'traction')
    call compare(failure, 2, xe, [0.0_wp, 0.0_wp], 3.1_wp, 2, 1.0e-14_wp, 'pressure')
    call compare(failure, 2, xe, [-0.4_wp, 0.9_wp], -1.7_wp, 2, 1.0e-14_wp, 'both')
  end subroutine test_straight2

  subroutine test_straight3(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp) :: xe(2, 3), fe(2, 3), total
    xe = reshape([0.3_wp, -0.2_wp, 2.1_wp, 1.4_wp, 1.2_wp, 0.6_wp], [2, 3])
    call compare(failure, 3, xe, [1.3_wp, -2.2_wp], 0.5_wp, 20, 1.0e-14_wp, 'straight Q8 edge')
    call add_edge_traction(3, xe, [0.0_wp, 1.0_wp], 0.0_wp, thick, fe)
    total = sum(fe(2, :))
    call check_close(failure, fe(2, 1)/total, 1.0_wp/6.0_wp, 'start share', abs_tol=1.0e-14_wp)
    call check_close(failure, fe(2, 2)/total, 1.0_wp/6.0_wp, 'end share', abs_tol=1.0e-14_wp)
    call check_close(failure, fe(2, 3)/total, 2.0_wp/3.0_wp, 'mid share', abs_tol=1.0e-14_wp)
  end subroutine test_straight3

  subroutine test_curved_pressure(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp) :: xe(2, 3)
    ! a clearly curved edge (mid node off the chord by 0.35 of its length)
    xe = reshape([0.0_wp, 0.0_wp, 2.0_wp, 0.5_wp, 1.15_wp, -0.45_wp], [2, 3])
    ! pressure integrands are cubic: Simpson exact, round-off only
    call compare(failure, 3, xe, [0.0_wp, 0.0_wp], 2.5_wp, 40, 1.0e-13_wp, 'curved pressure')
  end subroutine test_curved_pressure

  subroutine test_curved_traction(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp) :: xe(2, 3)
    xe = reshape([0.0_wp, 0.0_wp, 2.0_wp, 0.5_wp, 1.15_wp, -0.45_wp], [2, 3])
    ! |x'(s)| is not a polynomial: the 10-point rule's error on this strongly
    ! curved edge (mid node 0.23 chord lengths off the chord) is 3e-8 of the load (Simpson reference with 4000
    ! sub-intervals is accurate to ~1e-14)
    call compare(failure, 3, xe, [1.3_wp, -2.2_wp], 0.0_wp, 4000, 1.0e-7_wp, 'curved traction')
  end subroutine test_curved_traction

  subroutine test_pressure_inward(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp) :: xe(2, 3), fe(2, 3)
    ! bottom edge of a body above y = 0, counter-clockwise: start (0,0), end (2,0)
    xe = reshape([0.0_wp, 0.0_wp, 2.0_wp, 0.0_wp, 1.0_wp, 0.0_wp], [2, 3])
    call add_edge_traction(2, xe, [0.0_wp, 0.0_wp], 3.0_wp, thick, fe)
    call check(failure, all(fe(2, 1:2) > 0.0_wp), 'pressure on the bottom edge must push up (+y), got ' // &
      str(fe(2, 1)))
    call check_close(failure, sum(fe(2, :)), 3.0_wp*2.0_wp*thick, 'total pressure force')
    call check_close(failure, sum(fe(1, :)), 0.0_wp, 'no tangential force', abs_tol=1.0e-14_wp)
    ! right edge of the same body, going up: pressure pushes in -x
    xe = reshape([2.0_wp, 0.0_wp, 2.0_wp, 1.0_wp, 2.0_wp, 0.5_wp], [2, 3])
    call add_edge_traction(3, xe, [0.0_wp, 0.0_wp], 3.0_wp, thick, fe)
    call check(failure, sum(fe(1, :)) < 0.0_wp, 'pressure on the right edge must push in -x')
    call check_close(failure, sum(fe(1, :)), -3.0_wp*thick, 'total pressure force, right edge')
  end subroutine test_pressure_inward
end program test_element_edge_load
