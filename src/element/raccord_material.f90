!> Materials and kinematics of a body, and the finite-strain (hyperelastic)
!> laws at one point (doc/theory-finite.md; method brief
!> method-finite-plastic-axi.md sections 1-3, 5.2).
!>
!> A body is small strain with Hooke's law (today's kernels, raccord_elastic_block),
!> or finite strain with one of two hyperelastic laws, written in plane
!> strain with the 3x3 deformation gradient [[F11 F12 0],[F21 F22 0],[0 0 1]]:
!>
!>  - compressible neo-Hooke in the form of Abaqus and CalculiX,
!>      W = C10 (Ibar1 - 3) + (J - 1)^2 / D1,  Ibar1 = J^(-2/3) tr B,      (M-1)
!>      C10 = G/2, D1 = 2/K, G = E/(2(1+nu)), K = E/(3(1-2nu)),
!>      tau = J sigma = G dev(Bbar) + K J (J - 1) I,  Bbar = J^(-2/3) B;   (M-2)
!>  - St Venant-Kirchhoff, W = (lam/2)(tr E)^2 + mu E:E,
!>      S = lam tr(E) I + 2 mu E,  E = (C - I)/2.                           (M-3)
!>
!> The routines here work on one point: the stress recovery for output and
!> the tests use them; the time loop's kernel has its own vectorised chunk
!> forms of the same laws (raccord_finite_kernel), checked against these and
!> the closed forms by tests/element/test_finite.f90 and tests/finite.
!> Components: a 2x2 in-plane tensor is (11, 21, 12, 22), column-major like F(2,2).
module raccord_material
  use raccord_kinds, only: wp
  implicit none
  private

  !> Kinematics of a body (&body kinematics).
  integer, parameter, public :: KIN_SMALL = 1, KIN_FINITE = 2
  !> Materials (&body material).
  integer, parameter, public :: MAT_LINEAR = 1, MAT_NEO_HOOKE = 2, MAT_SVK = 3, MAT_J2 = 4
  !> Volumetric treatment of a finite-strain body (&body volumetric):
  !> full integration, or mean dilatation (one pressure per element).
  integer, parameter, public :: VOL_AUTO = 0, VOL_FULL = 1, VOL_MEAN = 2

  !> Moduli of one material, derived once from young and poisson.
  type, public :: moduli_t
    real(wp) :: young = 0.0_wp, poisson = 0.0_wp
    real(wp) :: g = 0.0_wp        !< shear modulus mu = G
    real(wp) :: lam = 0.0_wp      !< Lame lambda (3D, plane strain)
    real(wp) :: k = 0.0_wp        !< bulk modulus
  end type moduli_t

  public :: make_moduli, kinematics_name, material_name, volumetric_name
  public :: neo_hooke_tau, neo_hooke_iso_tau, svk_tau, cauchy_from_tau, log_strain

contains

  pure function make_moduli(young, poisson) result(m)
    real(wp), intent(in) :: young, poisson
    type(moduli_t) :: m
    m%young = young
    m%poisson = poisson
    m%g = young/(2.0_wp*(1.0_wp + poisson))
    m%lam = young*poisson/((1.0_wp + poisson)*(1.0_wp - 2.0_wp*poisson))
    m%k = young/(3.0_wp*(1.0_wp - 2.0_wp*poisson))
  end function make_moduli

  pure function kinematics_name(kin) result(s)
    integer, intent(in) :: kin
    character(len=:), allocatable :: s
    select case (kin)
    case (KIN_FINITE)
      s = 'finite'
    case default
      s = 'small'
    end select
  end function kinematics_name

  pure function material_name(mat) result(s)
    integer, intent(in) :: mat
    character(len=:), allocatable :: s
    select case (mat)
    case (MAT_NEO_HOOKE)
      s = 'neo_hooke'
    case (MAT_SVK)
      s = 'svk'
    case (MAT_J2)
      s = 'j2'
    case default
      s = 'linear_elastic'
    end select
  end function material_name

  pure function volumetric_name(vol) result(s)
    integer, intent(in) :: vol
    character(len=:), allocatable :: s
    select case (vol)
    case (VOL_FULL)
      s = 'full'
    case (VOL_MEAN)
      s = 'mean_dilatation'
    case default
      s = 'auto'
    end select
  end function volumetric_name

  !> Kirchhoff stress of neo-Hooke (M-2) in plane strain: tau(4) in-plane
  !> (11, 21, 12, 22) and tau33. f = (F11, F21, F12, F22); detf = det F.
  pure subroutine neo_hooke_tau(m, f, detf, tau, tau33)
    type(moduli_t), intent(in) :: m
    real(wp), intent(in) :: f(4), detf
    real(wp), intent(out) :: tau(4), tau33
    real(wp) :: p
    call neo_hooke_iso_tau(m, f, detf, tau, tau33)
    p = m%k*detf*(detf - 1.0_wp)
    tau(1) = tau(1) + p
    tau(4) = tau(4) + p
    tau33 = tau33 + p
  end subroutine neo_hooke_tau

  !> Isochoric part G dev(Bbar) of the neo-Hooke Kirchhoff stress (M-2),
  !> used alone with mean dilatation (its pressure is the element's).
  pure subroutine neo_hooke_iso_tau(m, f, detf, tau, tau33)
    type(moduli_t), intent(in) :: m
    real(wp), intent(in) :: f(4), detf
    real(wp), intent(out) :: tau(4), tau33
    real(wp) :: b11, b22, b12, tr3, gj
    ! B = F F^T (in-plane block), B33 = 1
    b11 = f(1)*f(1) + f(3)*f(3)
    b22 = f(2)*f(2) + f(4)*f(4)
    b12 = f(1)*f(2) + f(3)*f(4)
    tr3 = (b11 + b22 + 1.0_wp)/3.0_wp
    gj = m%g/cbrt2(detf)
    tau(1) = gj*(b11 - tr3)
    tau(2) = gj*b12
    tau(3) = tau(2)
    tau(4) = gj*(b22 - tr3)
    tau33 = gj*(1.0_wp - tr3)
  end subroutine neo_hooke_iso_tau

  !> Kirchhoff stress of St Venant-Kirchhoff (M-3), tau = F S F^T, plane strain.
  pure subroutine svk_tau(m, f, tau, tau33)
    type(moduli_t), intent(in) :: m
    real(wp), intent(in) :: f(4)
    real(wp), intent(out) :: tau(4), tau33
    real(wp) :: e11, e22, e12, tr, s11, s22, s12, p11, p21, p12, p22
    ! E = (F^T F - I)/2
    e11 = 0.5_wp*(f(1)*f(1) + f(2)*f(2) - 1.0_wp)
    e22 = 0.5_wp*(f(3)*f(3) + f(4)*f(4) - 1.0_wp)
    e12 = 0.5_wp*(f(1)*f(3) + f(2)*f(4))
    tr = m%lam*(e11 + e22)
    s11 = tr + 2.0_wp*m%g*e11
    s22 = tr + 2.0_wp*m%g*e22
    s12 = 2.0_wp*m%g*e12
    ! P = F S, then tau = P F^T
    p11 = f(1)*s11 + f(3)*s12
    p21 = f(2)*s11 + f(4)*s12
    p12 = f(1)*s12 + f(3)*s22
    p22 = f(2)*s12 + f(4)*s22
    tau(1) = p11*f(1) + p12*f(3)
    tau(2) = p21*f(1) + p22*f(3)
    tau(3) = tau(2)
    tau(4) = p21*f(2) + p22*f(4)
    tau33 = tr          ! S33 = lam tr E, F33 = 1
  end subroutine svk_tau

  !> Cauchy stress (sxx, syy, sxy, szz) = tau / J.
  pure function cauchy_from_tau(detf, tau, tau33) result(s)
    real(wp), intent(in) :: detf, tau(4), tau33
    real(wp) :: s(4)
    s = [tau(1), tau(4), tau(2), tau33]/detf
  end function cauchy_from_tau

  !> Logarithmic (Hencky) strain (exx, eyy, exy, ezz) = ln(V) = ln(B)/2,
  !> from the eigen-decomposition of the in-plane B; ezz = 0 in plane strain.
  pure function log_strain(f) result(e)
    real(wp), intent(in) :: f(4)
    real(wp) :: e(4)
    real(wp) :: b11, b22, b12, mean, rad, l1, l2, c, s, n, h1, h2
    b11 = f(1)*f(1) + f(3)*f(3)
    b22 = f(2)*f(2) + f(4)*f(4)
    b12 = f(1)*f(2) + f(3)*f(4)
    mean = 0.5_wp*(b11 + b22)
    rad = sqrt((0.5_wp*(b11 - b22))**2 + b12**2)
    l1 = mean + rad
    l2 = max(mean - rad, tiny(1.0_wp))
    h1 = 0.5_wp*log(l1)
    h2 = 0.5_wp*log(l2)
    if (rad <= 1.0e-14_wp*mean) then
      e = [h1, h1, 0.0_wp, 0.0_wp]
      return
    end if
    ! eigenvector of l1: (b12, l1 - b11) or (l1 - b22, b12), whichever is longer
    if (abs(b11 - l1) < abs(b22 - l1)) then
      c = l1 - b22
      s = b12
    else
      c = b12
      s = l1 - b11
    end if
    n = sqrt(c*c + s*s)
    c = c/n
    s = s/n
    e(1) = h1*c*c + h2*s*s
    e(2) = h1*s*s + h2*c*c
    e(3) = (h1 - h2)*c*s
    e(4) = 0.0_wp
  end function log_strain

  !> J^(2/3) for J > 0 (the caller has checked J > 0).
  elemental real(wp) function cbrt2(j) result(r)
    real(wp), intent(in) :: j
    r = exp(log(j)*(2.0_wp/3.0_wp))
  end function cbrt2
end module raccord_material
