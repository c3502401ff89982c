!> Gauss-Legendre quadrature on [-1, 1] (doc/theory-elements.md, section 2).
!>
!> An n-point rule integrates polynomials of degree 2n-1 exactly. The points
!> are the roots of the Legendre polynomial P_n, found by Newton's method from
!> the Chebyshev-like guess cos(pi (i - 1/4)/(n + 1/2)) (Abramowitz & Stegun
!> 22.16.6), and the weights are w_i = 2 / ((1 - x_i^2) P_n'(x_i)^2)
!> (A&S 25.4.29). The result agrees with the tabulated rules to round-off for
!> every n the element library uses (1..5).
module raccord_quadrature
  use raccord_kinds, only: wp, pi
  implicit none
  private

  public :: gauss_legendre

contains

  !> n-point Gauss-Legendre rule: points xi(1:n) ascending, weights w(1:n).
  pure subroutine gauss_legendre(n, xi, w)
    integer, intent(in) :: n
    real(wp), intent(out) :: xi(n), w(n)
    integer :: i, k, it
    real(wp) :: x, p0, p1, p2, dp, dx
    do i = 1, (n + 1)/2
      x = cos(pi*(real(i, wp) - 0.25_wp)/(real(n, wp) + 0.5_wp))
      do it = 1, 100
        ! Bonnet's recurrence (k+1) P_{k+1} = (2k+1) x P_k - k P_{k-1}
        p0 = 1.0_wp
        p1 = x
        do k = 1, n - 1
          p2 = (real(2*k + 1, wp)*x*p1 - real(k, wp)*p0)/real(k + 1, wp)
          p0 = p1
          p1 = p2
        end do
        if (n == 1) p0 = 1.0_wp
        ! P_n'(x) = n (x P_n - P_{n-1}) / (x^2 - 1)
        dp = real(n, wp)*(x*p1 - p0)/(x*x - 1.0_wp)
        dx = p1/dp
        x = x - dx
        if (abs(dx) <= 4.0_wp*epsilon(1.0_wp)) exit
      end do
      ! one more evaluation at the converged root for the weight
      p0 = 1.0_wp
      p1 = x
      do k = 1, n - 1
        p2 = (real(2*k + 1, wp)*x*p1 - real(k, wp)*p0)/real(k + 1, wp)
        p0 = p1
        p1 = p2
      end do
      if (n == 1) p0 = 1.0_wp
      dp = real(n, wp)*(x*p1 - p0)/(x*x - 1.0_wp)
      xi(i) = -x
      xi(n + 1 - i) = x
      w(i) = 2.0_wp/((1.0_wp - x*x)*dp*dp)
      w(n + 1 - i) = w(i)
    end do
    ! the middle root of an odd rule is exactly 0
    if (mod(n, 2) == 1) xi((n + 1)/2) = 0.0_wp
  end subroutine gauss_legendre
end module raccord_quadrature
