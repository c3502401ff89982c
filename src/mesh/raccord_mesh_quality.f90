!> Shape check of one element: sign and size of the Jacobian determinant of
!> the isoparametric map at the corners and at the Gauss points.
!>
!> A positive det J everywhere is what the explicit solver needs: the mass
!> and stiffness integrals use det J as a volume weight, and a negative or
!> vanishing one gives a negative or infinite stable time step. Corners are
!> where a bilinear map inverts first (det J of Q4 is linear in each of xi,
!> eta), the Gauss points are where the integrals see it; for Q8 a mid-side
!> node moved towards a corner makes det J negative near that corner.
!> Shape functions: Zienkiewicz & Taylor, The Finite Element Method, vol. 1,
!> 6th ed., sec. 6.4 (bilinear) and 6.5 (serendipity).
module raccord_mesh_quality
  use raccord_kinds, only: wp
  use raccord_mesh, only: ELEM_Q4, ELEM_Q8
  implicit none
  private

  integer, parameter, public :: SHAPE_OK = 0
  integer, parameter, public :: SHAPE_CLOCKWISE = 1     !< det J < 0 everywhere: nodes listed clockwise
  integer, parameter, public :: SHAPE_DISTORTED = 2     !< det J <= 0 or tiny somewhere: inverted or degenerate

  !> det J below this fraction of (element size / 2)^2 counts as degenerate:
  !> (h/2)^2 is det J of a square of side h, so the ratio is about the
  !> aspect ratio's inverse, and 1e-6 only catches collapsed elements.
  real(wp), parameter, public :: DEGENERATE_RTOL = 1.0e-6_wp

  public :: check_element_shape

  real(wp), parameter :: xi_node(8) = [-1.0_wp, 1.0_wp, 1.0_wp, -1.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, -1.0_wp]
  real(wp), parameter :: eta_node(8) = [-1.0_wp, -1.0_wp, 1.0_wp, 1.0_wp, -1.0_wp, 0.0_wp, 1.0_wp, 0.0_wp]

contains

  !> Classify an element from its node coordinates xe(2, nen).
  !> worst is the smallest det J / (h/2)^2 found, at point `at_point` (text).
  pure subroutine check_element_shape(etype, xe, status, worst, at_point)
    integer, intent(in) :: etype
    real(wp), intent(in) :: xe(:,:)
    integer, intent(out) :: status
    real(wp), intent(out) :: worst
    character(len=:), allocatable, intent(out) :: at_point
    real(wp), parameter :: g2 = 0.577350269189625764509148780502_wp   ! 1/sqrt(3): 2-point Gauss
    real(wp), parameter :: g3 = 0.774596669241483377035853079956_wp   ! sqrt(3/5): 3-point Gauss
    real(wp), allocatable :: xi(:), eta(:)
    character(len=16), allocatable :: label(:)
    real(wp) :: h, scale, r, rmax
    integer :: k, a, b, npt, ngauss
    logical :: all_negative
    real(wp) :: gp(3)
    integer :: i, j

    h = 0.0_wp
    do a = 1, 4
      do b = a + 1, 4
        h = max(h, norm2(xe(:, a) - xe(:, b)))
      end do
    end do
    scale = (0.5_wp*h)**2

    if (etype == ELEM_Q8) then
      ngauss = 3
      gp = [-g3, 0.0_wp, g3]
    else
      ngauss = 2
      gp = [-g2, g2, 0.0_wp]
    end if
    npt = 4 + ngauss**2
    allocate(xi(npt), eta(npt), label(npt))
    do k = 1, 4
      xi(k) = xi_node(k)
      eta(k) = eta_node(k)
      write(label(k), '(a,i0)') 'corner ', k
    end do
    k = 4
    do j = 1, ngauss
      do i = 1, ngauss
        k = k + 1
        xi(k) = gp(i)
        eta(k) = gp(j)
        write(label(k), '(a,i0)') 'Gauss point ', k - 4
      end do
    end do

    status = SHAPE_OK
    worst = huge(1.0_wp)
    rmax = -huge(1.0_wp)
    at_point = ''
    all_negative = .true.
    if (scale <= 0.0_wp) then
      ! all corners coincide
      status = SHAPE_DISTORTED
      worst = 0.0_wp
      at_point = 'all corners'
      return
    end if
    do k = 1, npt
      r = jacobian_det(etype, xe, xi(k), eta(k))/scale
      if (r < worst) then
        worst = r
        at_point = trim(label(k))
      end if
      rmax = max(rmax, r)
      if (r > -DEGENERATE_RTOL) all_negative = .false.
    end do
    if (worst > DEGENERATE_RTOL) return
    if (all_negative) then
      status = SHAPE_CLOCKWISE
    else
      status = SHAPE_DISTORTED
    end if
  end subroutine check_element_shape

  !> det of d(x,y)/d(xi,eta) at one point of the reference square.
  pure real(wp) function jacobian_det(etype, xe, xi, eta) result(det)
    integer, intent(in) :: etype
    real(wp), intent(in) :: xe(:,:), xi, eta
    real(wp) :: dn(2, 8), jac(2, 2)
    integer :: nen, a
    real(wp) :: xa, ea
    if (etype == ELEM_Q8) then
      nen = 8
      do a = 1, 4
        xa = xi_node(a)
        ea = eta_node(a)
        dn(1, a) = 0.25_wp*xa*(1.0_wp + ea*eta)*(2.0_wp*xa*xi + ea*eta)
        dn(2, a) = 0.25_wp*ea*(1.0_wp + xa*xi)*(xa*xi + 2.0_wp*ea*eta)
      end do
      do a = 5, 8
        xa = xi_node(a)
        ea = eta_node(a)
        if (xa == 0.0_wp) then
          dn(1, a) = -xi*(1.0_wp + ea*eta)
          dn(2, a) = 0.5_wp*ea*(1.0_wp - xi**2)
        else
          dn(1, a) = 0.5_wp*xa*(1.0_wp - eta**2)
          dn(2, a) = -eta*(1.0_wp + xa*xi)
        end if
      end do
    else
      nen = 4
      do a = 1, 4
        dn(1, a) = 0.25_wp*xi_node(a)*(1.0_wp + eta_node(a)*eta)
        dn(2, a) = 0.25_wp*eta_node(a)*(1.0_wp + xi_node(a)*xi)
      end do
    end if
    ! jac(i, j) = d x_i / d xi_j
    jac = matmul(xe(:, 1:nen), transpose(dn(:, 1:nen)))
    det = jac(1, 1)*jac(2, 2) - jac(1, 2)*jac(2, 1)
  end function jacobian_det
end module raccord_mesh_quality
