!> Quadrature rules and shape functions (src/element/raccord_quadrature.f90,
!> src/element/raccord_shape.f90).
program test_element_shape
  use raccord_kinds, only: wp
  use raccord_mesh, only: ELEM_Q4, ELEM_Q8, nodes_per_element
  use raccord_quadrature, only: gauss_legendre
  use raccord_shape, only: shape_quad, shape_line, node_natural_coords
  use raccord_check, only: failure_t, new_test, run_tests, check, check_close
  use raccord_strings, only: str
  implicit none

  !> sample points inside the reference square (not symmetric on purpose)
  real(wp), parameter :: pts(2, 5) = reshape([0.0_wp, 0.0_wp, 0.31_wp, -0.72_wp, -0.93_wp, 0.48_wp, &
    0.66_wp, 0.87_wp, -0.15_wp, -0.41_wp], [2, 5])

  call run_tests('element_shape', [ &
    new_test('gauss exact to degree 2n-1', test_gauss_exact), &
    new_test('gauss not exact at degree 2n', test_gauss_not_beyond), &
    new_test('quad partition of unity', test_quad_unity), &
    new_test('quad Kronecker property', test_quad_kronecker), &
    new_test('quad derivatives vs finite differences', test_quad_derivatives), &
    new_test('line shapes', test_line)])

contains

  !> exact integral of s^k on [-1, 1]
  pure real(wp) function monomial_integral(k)
    integer, intent(in) :: k
    monomial_integral = 0.0_wp
    if (mod(k, 2) == 0) monomial_integral = 2.0_wp/real(k + 1, wp)
  end function monomial_integral

  subroutine test_gauss_exact(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp) :: xi(5), w(5)
    integer :: n, k
    do n = 1, 5
      call gauss_legendre(n, xi(1:n), w(1:n))
      call check(failure, all(xi(2:n) > xi(1:n-1)), 'points ascending, n = ' // str(n))
      do k = 0, 2*n - 1
        ! integrals are O(1): absolute tolerance of a few ulps
        call check_close(failure, sum(w(1:n)*xi(1:n)**k), monomial_integral(k), &
          'n = ' // str(n) // ', degree ' // str(k), abs_tol=1.0e-14_wp)
      end do
    end do
  end subroutine test_gauss_exact

  subroutine test_gauss_not_beyond(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp) :: xi(5), w(5), err
    integer :: n
    do n = 1, 5
      call gauss_legendre(n, xi(1:n), w(1:n))
      ! the error at degree 2n is proportional to P_n's leading coefficient,
      ! >= 1e-3 for n <= 5; round-off is 1e-15
      err = abs(sum(w(1:n)*xi(1:n)**(2*n)) - monomial_integral(2*n))
      call check(failure, err > 1.0e-6_wp, 'n = ' // str(n) // ' integrates degree 2n exactly: error ' // str(err))
    end do
  end subroutine test_gauss_not_beyond

  subroutine test_quad_unity(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp) :: n(8), dn(2, 8)
    integer :: et, k, nen
    do et = ELEM_Q4, ELEM_Q8
      nen = nodes_per_element(et)
      do k = 1, size(pts, 2)
        call shape_quad(et, pts(1, k), pts(2, k), n(1:nen), dn(:, 1:nen))
        call check_close(failure, sum(n(1:nen)), 1.0_wp, 'sum N, etype ' // str(et), abs_tol=1.0e-14_wp)
        call check_close(failure, sum(dn(1, 1:nen)), 0.0_wp, 'sum dN/dxi, etype ' // str(et), abs_tol=1.0e-14_wp)
        call check_close(failure, sum(dn(2, 1:nen)), 0.0_wp, 'sum dN/deta, etype ' // str(et), abs_tol=1.0e-14_wp)
      end do
    end do
  end subroutine test_quad_unity

  subroutine test_quad_kronecker(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp) :: n(8), dn(2, 8), c(2), delta
    integer :: et, a, b, nen
    do et = ELEM_Q4, ELEM_Q8
      nen = nodes_per_element(et)
      do b = 1, nen
        c = node_natural_coords(b)
        call shape_quad(et, c(1), c(2), n(1:nen), dn(:, 1:nen))
        do a = 1, nen
          delta = merge(1.0_wp, 0.0_wp, a == b)
          call check_close(failure, n(a), delta, 'N_' // str(a) // ' at node ' // str(b) // &
            ', etype ' // str(et), abs_tol=1.0e-15_wp)
        end do
      end do
    end do
    ! the Q4 node coordinates are the corners in counter-clockwise order
    call check(failure, all(node_natural_coords(3) == [1.0_wp, 1.0_wp]), 'node 3 at (1, 1)')
    call check(failure, all(node_natural_coords(6) == [1.0_wp, 0.0_wp]), 'node 6 at (1, 0)')
  end subroutine test_quad_kronecker

  subroutine test_quad_derivatives(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp), parameter :: step = 1.0e-5_wp
    real(wp) :: n(8), dn(2, 8), np(8), nm(8), dd(2, 8), fd
    integer :: et, k, a, nen
    do et = ELEM_Q4, ELEM_Q8
      nen = nodes_per_element(et)
      do k = 1, size(pts, 2)
        call shape_quad(et, pts(1, k), pts(2, k), n(1:nen), dn(:, 1:nen))
        call shape_quad(et, pts(1, k) + step, pts(2, k), np(1:nen), dd(:, 1:nen))
        call shape_quad(et, pts(1, k) - step, pts(2, k), nm(1:nen), dd(:, 1:nen))
        do a = 1, nen
          ! shapes are quadratic at most in each variable: central
          ! differences are exact up to round-off eps/step ~ 1e-11
          fd = (np(a) - nm(a))/(2.0_wp*step)
          call check_close(failure, dn(1, a), fd, 'dN_' // str(a) // '/dxi, etype ' // str(et), abs_tol=1.0e-9_wp)
        end do
        call shape_quad(et, pts(1, k), pts(2, k) + step, np(1:nen), dd(:, 1:nen))
        call shape_quad(et, pts(1, k), pts(2, k) - step, nm(1:nen), dd(:, 1:nen))
        do a = 1, nen
          fd = (np(a) - nm(a))/(2.0_wp*step)
          call check_close(failure, dn(2, a), fd, 'dN_' // str(a) // '/deta, etype ' // str(et), abs_tol=1.0e-9_wp)
        end do
      end do
    end do
  end subroutine test_quad_derivatives

  subroutine test_line(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp), parameter :: step = 1.0e-5_wp, snode(3) = [-1.0_wp, 1.0_wp, 0.0_wp]
    real(wp) :: n(3), dn(3), np(3), nm(3), dd(3), s
    integer :: m, k, a, b
    do m = 2, 3
      do k = 1, 4
        s = -0.83_wp + 0.47_wp*real(k, wp)
        call shape_line(m, s, n(1:m), dn(1:m))
        call check_close(failure, sum(n(1:m)), 1.0_wp, 'line sum N, nen ' // str(m), abs_tol=1.0e-15_wp)
        call check_close(failure, sum(dn(1:m)), 0.0_wp, 'line sum dN, nen ' // str(m), abs_tol=1.0e-15_wp)
        call shape_line(m, s + step, np(1:m), dd(1:m))
        call shape_line(m, s - step, nm(1:m), dd(1:m))
        do a = 1, m
          call check_close(failure, dn(a), (np(a) - nm(a))/(2.0_wp*step), 'line dN_' // str(a) // &
            ', nen ' // str(m), abs_tol=1.0e-9_wp)
        end do
      end do
      do b = 1, m
        call shape_line(m, snode(b), n(1:m), dn(1:m))
        do a = 1, m
          call check_close(failure, n(a), merge(1.0_wp, 0.0_wp, a == b), 'line N_' // str(a) // &
            ' at node ' // str(b) // ', nen ' // str(m), abs_tol=1.0e-15_wp)
        end do
      end do
    end do
  end subroutine test_line
end program test_element_shape
