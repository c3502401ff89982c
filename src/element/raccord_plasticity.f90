!> J2 (von Mises) plasticity with linear isotropic hardening at one point
!> (doc/theory-plasticity.md; method brief method-finite-plastic-axi.md
!> sections 6-8).
!>
!> Small strain (radial return, Wilkins 1964; Simo & Hughes 1998), with the
!> full 3D tensors of plane strain (eps_zz = 0 kept as a component):
!>   eps_e,tr = eps - eps_p(n),  theta = tr eps_e,tr,  s_tr = 2G dev eps_e,tr
!>   f_tr = |s_tr| - sqrt(2/3) (sigma_y0 + H ebar(n))                      (P-1)
!>   dgamma = <f_tr> / (2G + 2H/3),  n = s_tr / |s_tr|                      (P-2)
!>   s = s_tr - 2G dgamma n,  eps_p += dgamma n,  ebar += sqrt(2/3) dgamma  (P-3)
!>   sigma = s + K theta I
!> The return is exact along proportional paths, so closed forms hold to
!> round-off. Written without a branch (dgamma = 0 when elastic) so that the
!> chunk kernel's lanes stay in step.
!>
!> Finite strain (Hencky elasticity, multiplicative split F = Fe Fp,
!> exponential-map return; Eterovic & Bathe 1990, Simo 1992): with
!> Cp^-1(n) stored,
!>   be_tr = F Cp^-1(n) F^T,  eps_tr = (1/2) ln be_tr (principal values)   (P-4)
!> then (P-1)..(P-3) on the three principal values give eps_e and the
!> Kirchhoff stress tau = 2G dev eps_e + p_tau I, and
!>   be = sum_i exp(2 eps_e,i) n_i (x) n_i,  Cp^-1 = F^-1 be F^-T.         (P-5)
!> The return preserves tr eps (plastic flow is isochoric, det Cp = 1 kept).
!> For small strain and rotation (1/2) ln be ~ eps_e and (P-4, P-5) reduce
!> to the small-strain return; no rate appears, so elastic cycles store and
!> give back exactly the Hencky energy.
!>
!> Internal variables per point, nhist of them: the symmetric tensor
!> (xx, yy, xy, zz) -- eps_p (tensor shear) in small strain, Cp^-1 in finite
!> strain -- and ebar. Energies per unit (reference) volume: elastic
!>   W_e = p^2/(2K) + s:s/(4G)   or   (K/2)(tr eps_e)^2 + G |dev eps_e|^2   (P-6)
!> and plastic work by the trapezoid, exact for linear hardening,
!>   dW_p = (1/2)(sigma_y(ebar_n) + sigma_y(ebar_n+1)) (ebar_n+1 - ebar_n). (P-7)
module raccord_plasticity
  use raccord_kinds, only: wp
  use raccord_material, only: moduli_t
  implicit none
  private

  !> J2 material with linear isotropic hardening: sigma_y = yield0 + H ebar.
  type, public :: j2_t
    real(wp) :: yield0 = 0.0_wp      !< initial yield stress sigma_y0
    real(wp) :: hardening = 0.0_wp   !< linear isotropic hardening modulus H (0: perfectly plastic)
  end type j2_t

  !> Internal variables per integration point: tensor (xx, yy, xy, zz), ebar.
  integer, parameter, public :: nhist = 5
  integer, parameter, public :: h_xx = 1, h_yy = 2, h_xy = 3, h_zz = 4, h_ebar = 5
  real(wp), parameter :: r23 = 0.816496580927726_wp   ! sqrt(2/3)

  public :: j2_initial_history, j2_return_small, j2_return_hencky

contains

  !> The internal variables of a virgin point: eps_p = 0 (small strain) or
  !> Cp^-1 = I (finite strain), ebar = 0.
  pure function j2_initial_history(finite) result(h)
    logical, intent(in) :: finite
    real(wp) :: h(nhist)
    h = 0.0_wp
    if (finite) then
      h(h_xx) = 1.0_wp
      h(h_yy) = 1.0_wp
      h(h_zz) = 1.0_wp
    end if
  end function j2_initial_history

  !> Small-strain radial return (P-1)..(P-3) at one point. eps = total strain
  !> (xx, yy, xy (tensor), zz); hold/hnew = internal variables before/after;
  !> sig = stress (xx, yy, xy, zz); we = W_e (P-6); dwp = dW_p (P-7); both
  !> per unit volume. With theta_bar present, the volumetric strain is
  !> replaced by it (B-bar: eps_bar = dev eps + theta_bar/3 I).
  pure subroutine j2_return_small(m, j2, eps, hold, hnew, sig, we, dwp, theta_bar)
    type(moduli_t), intent(in) :: m
    type(j2_t), intent(in) :: j2
    real(wp), intent(in) :: eps(4), hold(nhist)
    real(wp), intent(out) :: hnew(nhist), sig(4), we, dwp
    real(wp), intent(in), optional :: theta_bar
    real(wp) :: th, e(4), s(4), nrm, f, dg, sc, eb
    e = eps - hold(1:4)
    th = e(1) + e(2) + e(4)
    if (present(theta_bar)) th = theta_bar
    ! deviator of the elastic trial strain (plastic strain is traceless, so
    ! the trace of eps - eps_p is the trace of eps)
    s(1) = 2.0_wp*m%g*(e(1) - (e(1) + e(2) + e(4))/3.0_wp)
    s(2) = 2.0_wp*m%g*(e(2) - (e(1) + e(2) + e(4))/3.0_wp)
    s(4) = 2.0_wp*m%g*(e(4) - (e(1) + e(2) + e(4))/3.0_wp)
    s(3) = 2.0_wp*m%g*e(3)
    nrm = sqrt(s(1)**2 + s(2)**2 + s(4)**2 + 2.0_wp*s(3)**2)
    f = nrm - r23*(j2%yield0 + j2%hardening*hold(h_ebar))
    dg = max(f, 0.0_wp)/(2.0_wp*m%g + 2.0_wp*j2%hardening/3.0_wp)
    sc = dg/max(nrm, tiny(1.0_wp))
    hnew(1:4) = hold(1:4) + sc*s
    s = (1.0_wp - 2.0_wp*m%g*sc)*s
    eb = hold(h_ebar) + r23*dg
    hnew(h_ebar) = eb
    sig = s
    sig(1) = sig(1) + m%k*th
    sig(2) = sig(2) + m%k*th
    sig(4) = sig(4) + m%k*th
    we = 0.5_wp*m%k*th*th + (s(1)**2 + s(2)**2 + s(4)**2 + 2.0_wp*s(3)**2)/(4.0_wp*m%g)
    dwp = (j2%yield0 + 0.5_wp*j2%hardening*(hold(h_ebar) + eb))*(eb - hold(h_ebar))
  end subroutine j2_return_small

  !> Finite-strain return (P-4), (P-1)..(P-3), (P-5) at one point, plane
  !> strain (F33 = 1). f = in-plane F (11, 21, 12, 22); hold/hnew = Cp^-1
  !> (xx, yy, xy, zz) and ebar; tau = Kirchhoff stress (xx, yy, xy, zz);
  !> we = W_e per reference volume (P-6); dwp (P-7). With jbar present
  !> (mean dilatation), the pressure is K ln(jbar) J/jbar and the volumetric
  !> energy is left to the caller (V_e (K/2) ln(jbar)^2).
  pure subroutine j2_return_hencky(m, j2, f, hold, hnew, tau, we, dwp, jbar)
    type(moduli_t), intent(in) :: m
    type(j2_t), intent(in) :: j2
    real(wp), intent(in) :: f(4), hold(nhist)
    real(wp), intent(out) :: hnew(nhist), tau(4), we, dwp
    real(wp), intent(in), optional :: jbar
    real(wp) :: b11, b22, b12, b33, mid, rad, rr, cs, sn, l1, l2, e1, e2, e3, tr, d1, d2, d3, nrm
    real(wp) :: fy, dg, sc, eb, p, t1, t2, j, c11, c22, c12, a1, a2, x11, x22, x12, jb
    real(wp) :: g11, g21, g12, g22
    ! (P-4): be_tr = F Cp^-1 F^T (in-plane block), be33 = Cp^-1_33
    associate (f11 => f(1), f21 => f(2), f12 => f(3), f22 => f(4), q11 => hold(1), q22 => hold(2), &
        q12 => hold(3))
      g11 = f11*q11 + f12*q12
      g12 = f11*q12 + f12*q22
      g21 = f21*q11 + f22*q12
      g22 = f21*q12 + f22*q22
      b11 = g11*f11 + g12*f12
      b22 = g21*f21 + g22*f22
      b12 = g11*f21 + g12*f22
    end associate
    b33 = hold(h_zz)
    ! principal values and the double-angle direction of the in-plane block
    mid = 0.5_wp*(b11 + b22)
    rad = sqrt((0.5_wp*(b11 - b22))**2 + b12*b12)
    rr = max(2.0_wp*rad, tiny(1.0_wp))
    cs = (b11 - b22)/rr
    sn = 2.0_wp*b12/rr
    l1 = mid + rad
    l2 = max(mid - rad, tiny(1.0_wp))
    e1 = 0.5_wp*log(l1)
    e2 = 0.5_wp*log(l2)
    e3 = 0.5_wp*log(b33)
    tr = e1 + e2 + e3
    d1 = e1 - tr/3.0_wp
    d2 = e2 - tr/3.0_wp
    d3 = e3 - tr/3.0_wp
    ! (P-1)..(P-3) on the principal deviator
    nrm = 2.0_wp*m%g*sqrt(d1*d1 + d2*d2 + d3*d3)
    fy = nrm - r23*(j2%yield0 + j2%hardening*hold(h_ebar))
    dg = max(fy, 0.0_wp)/(2.0_wp*m%g + 2.0_wp*j2%hardening/3.0_wp)
    sc = 1.0_wp - 2.0_wp*m%g*dg/max(nrm, tiny(1.0_wp))
    d1 = sc*d1
    d2 = sc*d2
    d3 = sc*d3
    eb = hold(h_ebar) + r23*dg
    j = f(1)*f(4) - f(2)*f(3)
    if (present(jbar)) then
      jb = jbar
      p = m%k*log(jb)*j/jb
      we = m%g*(d1*d1 + d2*d2 + d3*d3)
    else
      p = m%k*tr
      we = 0.5_wp*m%k*tr*tr + m%g*(d1*d1 + d2*d2 + d3*d3)
    end if
    t1 = 2.0_wp*m%g*d1 + p
    t2 = 2.0_wp*m%g*d2 + p
    tau(1) = 0.5_wp*(t1 + t2) + 0.5_wp*(t1 - t2)*cs
    tau(2) = 0.5_wp*(t1 + t2) - 0.5_wp*(t1 - t2)*cs
    tau(3) = 0.5_wp*(t1 - t2)*sn
    tau(4) = 2.0_wp*m%g*d3 + p
    ! (P-5): be = exp(2 eps_e) in the same directions, Cp^-1 = F^-1 be F^-T
    a1 = exp(2.0_wp*(d1 + tr/3.0_wp))
    a2 = exp(2.0_wp*(d2 + tr/3.0_wp))
    x11 = 0.5_wp*(a1 + a2) + 0.5_wp*(a1 - a2)*cs
    x22 = 0.5_wp*(a1 + a2) - 0.5_wp*(a1 - a2)*cs
    x12 = 0.5_wp*(a1 - a2)*sn
    associate (f11 => f(1), f21 => f(2), f12 => f(3), f22 => f(4))
      ! F^-1 = [[f22, -f12], [-f21, f11]]/J; G = F^-1 be, Cp^-1 = G F^-T
      g11 = (f22*x11 - f12*x12)/j
      g12 = (f22*x12 - f12*x22)/j
      g21 = (f11*x12 - f21*x11)/j
      g22 = (f11*x22 - f21*x12)/j
      c11 = (g11*f22 - g12*f12)/j
      c12 = (g11*(-f21) + g12*f11)/j
      c22 = (g21*(-f21) + g22*f11)/j
    end associate
    hnew(h_xx) = c11
    hnew(h_yy) = c22
    hnew(h_xy) = c12
    hnew(h_zz) = exp(2.0_wp*(d3 + tr/3.0_wp))
    hnew(h_ebar) = eb
    dwp = (j2%yield0 + 0.5_wp*j2%hardening*(hold(h_ebar) + eb))*(eb - hold(h_ebar))
  end subroutine j2_return_hencky
end module raccord_plasticity
