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
!> Internal variables per point, nhist = 4 of them: the in-plane part
!> (xx, yy, xy) of a symmetric tensor -- eps_p (tensor shear) in small
!> strain, Cp^-1 in finite strain -- and ebar. The zz component follows:
!> eps_p is traceless (eps_p,zz = -(eps_p,xx + eps_p,yy)) and det Cp = 1
!> (Cp^-1_zz = 1 / (Cp^-1_xx Cp^-1_yy - Cp^-1_xy^2)), so it is not stored
!> (the J2 step is bound by its memory traffic on large meshes), and the
!> flow stays exactly isochoric in both. Energies per unit (reference) volume: elastic
!>   W_e = p^2/(2K) + s:s/(4G)   or   (K/2)(tr eps_e)^2 + G |dev eps_e|^2   (P-6)
!> and plastic work by the trapezoid, exact for linear hardening,
!>   dW_p = (1/2)(sigma_y(ebar_n) + sigma_y(ebar_n+1)) (ebar_n+1 - ebar_n). (P-7)
module raccord_plasticity
  use raccord_kinds, only: wp
  use raccord_material, only: moduli_t
  use raccord_finite_kernel, only: fin_chunk_len
  implicit none
  private

  !> J2 material with linear isotropic hardening: sigma_y = yield0 + H ebar.
  type, public :: j2_t
    real(wp) :: yield0 = 0.0_wp      !< initial yield stress sigma_y0
    real(wp) :: hardening = 0.0_wp   !< linear isotropic hardening modulus H (0: perfectly plastic)
  end type j2_t

  !> Internal variables per integration point: tensor (xx, yy, xy, zz), ebar.
  integer, parameter, public :: nhist = 4
  integer, parameter, public :: h_xx = 1, h_yy = 2, h_xy = 3, h_ebar = 4
  real(wp), parameter :: r23 = 0.816496580927726_wp   ! sqrt(2/3)
  real(wp), parameter :: third = 1.0_wp/3.0_wp

  public :: j2_initial_history, j2_return_small, j2_return_hencky, j2_small_lanes, j2_hencky_lanes, j2_small_trial_lanes, &
    j2_hencky_ftt_lanes

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
    end if
  end function j2_initial_history

  !> Small-strain radial return (P-1)..(P-3) at one point. eps = total strain
  !> (xx, yy, xy (tensor), zz); hold/hnew = internal variables before/after
  !> (eps_p xx, yy, xy and ebar);
  !> sig = stress (xx, yy, xy, zz); we = W_e (P-6); dwp = dW_p (P-7); both
  !> per unit volume. With theta_bar present, the volumetric strain is
  !> replaced by it (B-bar: eps_bar = dev eps + theta_bar/3 I).
  pure subroutine j2_return_small(m, j2, eps, hold, hnew, sig, we, dwp, theta_bar)
    type(moduli_t), intent(in) :: m
    type(j2_t), intent(in) :: j2
    real(wp), intent(in) :: eps(4), hold(nhist)
    real(wp), intent(out) :: hnew(nhist), sig(4), we, dwp
    real(wp), intent(in), optional :: theta_bar
    real(wp) :: tb(fin_chunk_len), w1(fin_chunk_len), d1(fin_chunk_len), hn(fin_chunk_len, nhist)
    real(wp) :: s1(fin_chunk_len, 4), e1(fin_chunk_len, 4), h1(fin_chunk_len, nhist)
    ! lane 1 of a chunk
    e1 = 0.0_wp
    h1 = 0.0_wp
    tb = 0.0_wp
    e1(1, :) = eps
    h1(1, :) = hold
    tb(1) = eps(1) + eps(2) + eps(4)
    if (present(theta_bar)) tb(1) = theta_bar
    call j2_small_lanes(1, m, j2, e1, tb, h1, s1, w1, d1)
    hn = h1
    hnew = hn(1, :)
    sig = s1(1, :)
    we = w1(1)
    dwp = d1(1)
  end subroutine j2_return_small

  !> Finite-strain return (P-4), (P-1)..(P-3), (P-5) at one point, plane
  !> strain (F33 = 1). f = in-plane F (11, 21, 12, 22); hold/hnew = Cp^-1
  !> (xx, yy, xy) and ebar; tau = Kirchhoff stress (xx, yy, xy, zz);
  !> we = W_e per reference volume (P-6); dwp (P-7). With jbar present
  !> (mean dilatation), the pressure is K ln(jbar) J/jbar and the volumetric
  !> energy is left to the caller (V_e (K/2) ln(jbar)^2).
  pure subroutine j2_return_hencky(m, j2, f, hold, hnew, tau, we, dwp, jbar)
    type(moduli_t), intent(in) :: m
    type(j2_t), intent(in) :: j2
    real(wp), intent(in) :: f(4), hold(nhist)
    real(wp), intent(out) :: hnew(nhist), tau(4), we, dwp
    real(wp), intent(in), optional :: jbar
    real(wp) :: jb(fin_chunk_len), w1(fin_chunk_len), d1(fin_chunk_len), wm(fin_chunk_len)
    real(wp) :: hn(fin_chunk_len, nhist), t1(fin_chunk_len, 4), f1(fin_chunk_len, 4), h1(fin_chunk_len, nhist)
    ! lane 1 of a chunk
    f1 = 0.0_wp
    h1 = 0.0_wp
    jb = 1.0_wp
    f1(1, :) = f
    h1(1, :) = hold
    if (present(jbar)) jb(1) = jbar
    call j2_hencky_lanes(1, m, j2, present(jbar), f1, jb, h1, t1, w1, d1, wm)
    hn = h1
    hnew = hn(1, :)
    tau = t1(1, :)
    we = w1(1)
    dwp = d1(1)
  end subroutine j2_return_hencky

  !> (P-1)..(P-3) on n lanes of a chunk (leading dimension the chunk
  !> length, a constant, so that the loop vectorises): the form the chunk
  !> kernels call, one Gauss point of a chunk of elements per call, without
  !> a branch. eps(:, 4) total strain, tb the volumetric strain to use (its
  !> own trace, or the element's mean with B-bar).
  pure subroutine j2_small_lanes(n, m, j2, eps, tb, h, sig, we, dwp)
    integer, intent(in) :: n
    integer, parameter :: ld = fin_chunk_len
    type(moduli_t), intent(in) :: m
    type(j2_t), intent(in) :: j2
    real(wp), intent(in) :: eps(ld, 4), tb(ld)
    real(wp), intent(inout) :: h(ld, nhist)
    real(wp), intent(out) :: sig(ld, 4), we(ld), dwp(ld)
    real(wp) :: e1, e2, e3, e4, tr3, s1, s2, s3, s4, nrm, f, dg, sc, eb, eb0, th, g2, rh, r4g, hk
    integer :: i
    g2 = 2.0_wp*m%g
    rh = 1.0_wp/(g2 + 2.0_wp*j2%hardening/3.0_wp)
    ! constants of every lane: 1/(4G) of W_e, K/2; no division in the loop
    ! but the return's own 1/|s_tr|
    r4g = 1.0_wp/(2.0_wp*g2)
    hk = 0.5_wp*m%k
    do i = 1, n
      e1 = eps(i, 1) - h(i, 1)
      e2 = eps(i, 2) - h(i, 2)
      e3 = eps(i, 3) - h(i, 3)
      e4 = eps(i, 4) + h(i, 1) + h(i, 2)        ! eps_p,zz = -(eps_p,xx + eps_p,yy)
      eb0 = h(i, h_ebar)
      th = tb(i)
      ! deviator of the elastic trial strain (eps_p is traceless)
      tr3 = (e1 + e2 + e4)*third
      s1 = g2*(e1 - tr3)
      s2 = g2*(e2 - tr3)
      s4 = g2*(e4 - tr3)
      s3 = g2*e3
      nrm = sqrt(s1*s1 + s2*s2 + s4*s4 + 2.0_wp*s3*s3)
      f = nrm - r23*(j2%yield0 + j2%hardening*eb0)
      dg = max(f, 0.0_wp)*rh
      sc = dg/max(nrm, tiny(1.0_wp))
      h(i, 1) = h(i, 1) + sc*s1
      h(i, 2) = h(i, 2) + sc*s2
      h(i, 3) = h(i, 3) + sc*s3
      sc = 1.0_wp - g2*sc
      s1 = sc*s1
      s2 = sc*s2
      s3 = sc*s3
      s4 = sc*s4
      eb = eb0 + r23*dg
      h(i, h_ebar) = eb
      sig(i, 1) = s1 + m%k*th
      sig(i, 2) = s2 + m%k*th
      sig(i, 3) = s3
      sig(i, 4) = s4 + m%k*th
      we(i) = hk*th*th + (s1*s1 + s2*s2 + s4*s4 + 2.0_wp*s3*s3)*r4g
      dwp(i) = (j2%yield0 + 0.5_wp*j2%hardening*(eb0 + eb))*(eb - eb0)
    end do
  end subroutine j2_small_lanes

  !> The elastic trial (P-1) on n lanes of virgin points (eps_p = 0, ebar =
  !> 0): sig and we as j2_small_lanes gives them, written with the same
  !> expressions in the same order, and below = every lane's |s_tr|^2 below
  !> (sqrt(2/3) sigma_y0)^2 (1 - 1e-12), a margin far above the round-off of
  !> the square root, so that f_tr < 0 there too. Then the return is the
  !> identity (dgamma = 0 exactly: the internal variables stay 0 and s is
  !> scaled by 1), so sig and we are the return's bits, and the caller may
  !> leave the internal variables unread and unwritten. No division and no
  !> square root.
  pure subroutine j2_small_trial_lanes(n, m, j2, eps, tb, sig, we, below)
    integer, intent(in) :: n
    integer, parameter :: ld = fin_chunk_len
    type(moduli_t), intent(in) :: m
    type(j2_t), intent(in) :: j2
    real(wp), intent(in) :: eps(ld, 4), tb(ld)
    real(wp), intent(out) :: sig(ld, 4), we(ld)
    logical, intent(out) :: below
    real(wp) :: e1, e2, e3, e4, tr3, s1, s2, s3, s4, nrm2, nmax, th, g2, r4g, hk, lim
    integer :: i
    g2 = 2.0_wp*m%g
    r4g = 1.0_wp/(2.0_wp*g2)
    hk = 0.5_wp*m%k
    lim = (r23*j2%yield0)**2*(1.0_wp - 1.0e-12_wp)
    nmax = 0.0_wp
    do i = 1, n
      e1 = eps(i, 1)
      e2 = eps(i, 2)
      e3 = eps(i, 3)
      e4 = eps(i, 4)
      th = tb(i)
      tr3 = (e1 + e2 + e4)*third
      s1 = g2*(e1 - tr3)
      s2 = g2*(e2 - tr3)
      s4 = g2*(e4 - tr3)
      s3 = g2*e3
      nrm2 = s1*s1 + s2*s2 + s4*s4 + 2.0_wp*s3*s3
      nmax = max(nmax, nrm2)
      sig(i, 1) = s1 + m%k*th
      sig(i, 2) = s2 + m%k*th
      sig(i, 3) = s3
      sig(i, 4) = s4 + m%k*th
      we(i) = hk*th*th + (s1*s1 + s2*s2 + s4*s4 + 2.0_wp*s3*s3)*r4g
    end do
    below = nmax <= lim
  end subroutine j2_small_trial_lanes

  !> (P-4), (P-1)..(P-3), (P-5) on n lanes, plane strain: f(:, 4) the
  !> in-plane F, F_zz = 1 (j2_hencky_ftt_lanes).
  pure subroutine j2_hencky_lanes(n, m, j2, mean, f, jb, h, tau, we, dwp, wmod)
    integer, intent(in) :: n
    integer, parameter :: ld = fin_chunk_len
    type(moduli_t), intent(in) :: m
    type(j2_t), intent(in) :: j2
    logical, intent(in) :: mean
    real(wp), intent(in) :: f(ld, 4), jb(ld)
    real(wp), intent(inout) :: h(ld, nhist)
    real(wp), intent(out) :: tau(ld, 4), we(ld), dwp(ld), wmod(ld)
    real(wp) :: one(ld)
    one = 1.0_wp
    call j2_hencky_ftt_lanes(n, m, j2, mean, f, one, jb, h, tau, we, dwp, wmod)
  end subroutine j2_hencky_lanes

  !> (P-4), (P-1)..(P-3), (P-5) on n lanes. f(:, 4) in-plane F (xx, yx,
  !> xy, yy) and ftt the out-of-plane stretch: 1 in plane strain, F_tt =
  !> r/R in axisymmetry, where the hoop direction is the third principal
  !> direction (be_tr,33 = ftt^2 Cp^-1_33, Cp^-1_33 = 1/det of the in-plane
  !> Cp^-1: det Cp = 1, the flow is isochoric). h = in-plane Cp^-1 and
  !> ebar; tau Kirchhoff (xx, yy, xy, 33). With mean, jb is the element's
  !> volume ratio (mean dilatation) and we leaves out the volumetric
  !> energy. wmod: a bound of the current wave modulus (K + 4G/3 + the
  !> largest principal |tau|, the elastic moduli: plastic flow only
  !> softens) for the stable step.
  pure subroutine j2_hencky_ftt_lanes(n, m, j2, mean, f, ftt, jb, h, tau, we, dwp, wmod)
    integer, intent(in) :: n
    integer, parameter :: ld = fin_chunk_len
    type(moduli_t), intent(in) :: m
    type(j2_t), intent(in) :: j2
    logical, intent(in) :: mean
    real(wp), intent(in) :: f(ld, 4), ftt(ld), jb(ld)
    real(wp), intent(inout) :: h(ld, nhist)
    real(wp), intent(out) :: tau(ld, 4), we(ld), dwp(ld), wmod(ld)
    real(wp) :: f11, f21, f12, f22, f33, q11, q22, q12, g11, g12, g21, g22, b11, b22, b12, b33
    real(wp) :: mid, rad, rr, cs, sn, e1, e2, e3, tr, d1, d2, d3, nrm, fy, dg, sc, eb, p, t1, t2, t3, j, j2d, rj
    real(wp) :: a1, a2, x11, x22, x12, g2, rh, wvol, pvol, jbi, eb0
    integer :: i
    g2 = 2.0_wp*m%g
    rh = 1.0_wp/(g2 + 2.0_wp*j2%hardening/3.0_wp)
    wvol = merge(0.0_wp, 0.5_wp*m%k, mean)
    pvol = merge(1.0_wp, 0.0_wp, mean)
    do i = 1, n
      f11 = f(i, 1)
      f21 = f(i, 2)
      f12 = f(i, 3)
      f22 = f(i, 4)
      f33 = ftt(i)
      q11 = h(i, 1)
      q22 = h(i, 2)
      q12 = h(i, 3)
      eb0 = h(i, h_ebar)
      ! (P-4): be_tr = F Cp^-1 F^T (in-plane block), be33 = F_33^2 Cp^-1_33
      g11 = f11*q11 + f12*q12
      g12 = f11*q12 + f12*q22
      g21 = f21*q11 + f22*q12
      g22 = f21*q12 + f22*q22
      b11 = g11*f11 + g12*f12
      b22 = g21*f21 + g22*f22
      b12 = g11*f21 + g12*f22
      b33 = f33*f33/(q11*q22 - q12*q12)         ! Cp^-1_33 = 1/det, det Cp = 1
      ! principal values; (cs, sn) = (cos, sin) of twice the first direction
      mid = 0.5_wp*(b11 + b22)
      rad = sqrt((0.5_wp*(b11 - b22))**2 + b12*b12)
      rr = max(2.0_wp*rad, tiny(1.0_wp))
      cs = (b11 - b22)/rr
      sn = 2.0_wp*b12/rr
      e1 = 0.5_wp*log(mid + rad)
      e2 = 0.5_wp*log(max(mid - rad, tiny(1.0_wp)))
      e3 = 0.5_wp*log(b33)
      tr = e1 + e2 + e3
      d1 = e1 - tr/3.0_wp
      d2 = e2 - tr/3.0_wp
      d3 = e3 - tr/3.0_wp
      ! (P-1)..(P-3) on the principal deviator
      nrm = g2*sqrt(d1*d1 + d2*d2 + d3*d3)
      fy = nrm - r23*(j2%yield0 + j2%hardening*eb0)
      dg = max(fy, 0.0_wp)*rh
      sc = 1.0_wp - g2*dg/max(nrm, tiny(1.0_wp))
      d1 = sc*d1
      d2 = sc*d2
      d3 = sc*d3
      eb = eb0 + r23*dg
      j2d = f11*f22 - f21*f12
      j = f33*j2d
      ! pressure (Kirchhoff): K tr eps_e, or with mean dilatation K ln(Jbar) J/Jbar
      ! (jbar is read as 1 without mean dilatation, where its term is off)
      jbi = pvol*jb(i) + (1.0_wp - pvol)
      p = (1.0_wp - pvol)*m%k*tr + pvol*m%k*log(jbi)*j/jbi
      t1 = g2*d1 + p
      t2 = g2*d2 + p
      t3 = g2*d3 + p
      tau(i, 1) = 0.5_wp*(t1 + t2) + 0.5_wp*(t1 - t2)*cs
      tau(i, 2) = 0.5_wp*(t1 + t2) - 0.5_wp*(t1 - t2)*cs
      tau(i, 3) = 0.5_wp*(t1 - t2)*sn
      tau(i, 4) = t3
      we(i) = wvol*tr*tr + m%g*(d1*d1 + d2*d2 + d3*d3)
      dwp(i) = (j2%yield0 + 0.5_wp*j2%hardening*(eb0 + eb))*(eb - eb0)
      wmod(i) = m%k + 2.0_wp*g2/3.0_wp + max(abs(t1), abs(t2), abs(t3))
      ! (P-5): be = exp(2 eps_e) in the same directions, in-plane Cp^-1 = F^-1 be F^-T
      a1 = exp(2.0_wp*(d1 + tr/3.0_wp))
      a2 = exp(2.0_wp*(d2 + tr/3.0_wp))
      x11 = 0.5_wp*(a1 + a2) + 0.5_wp*(a1 - a2)*cs
      x22 = 0.5_wp*(a1 + a2) - 0.5_wp*(a1 - a2)*cs
      x12 = 0.5_wp*(a1 - a2)*sn
      rj = 1.0_wp/j2d
      g11 = (f22*x11 - f12*x12)*rj
      g12 = (f22*x12 - f12*x22)*rj
      g21 = (f11*x12 - f21*x11)*rj
      g22 = (f11*x22 - f21*x12)*rj
      h(i, 1) = (g11*f22 - g12*f12)*rj
      h(i, 2) = (g22*f11 - g21*f21)*rj
      h(i, 3) = (g12*f11 - g11*f21)*rj
      h(i, h_ebar) = eb
    end do
  end subroutine j2_hencky_ftt_lanes
end module raccord_plasticity
