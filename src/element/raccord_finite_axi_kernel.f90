!> Internal force of finite-strain axisymmetric elements, total Lagrangian,
!> one chunk of Q4 or Q8 elements at a time (doc/theory-axisymmetric.md,
!> section "Finite strain and plasticity"; method brief
!> method-finite-plastic-axi.md sections 1, 2.1 and 9).
!>
!> (r, z) = (x, y). At each Gauss point g, with J0^-1 (pg), 1/R_g (rr) and
!> c = w_g det J0 2 pi R_g (cw) stored once at set-up, the 3x3 gradient is
!> block diagonal,
!>   F = [[F_rr F_rZ 0], [F_zR F_zZ 0], [0 0 F_tt]],
!>   F_2 = I + (sum_a u_a dN_a/dxi^T) J0^-1,  F_tt = r/R = 1 + u_r/R,  (FA-1)
!>   J = F_tt det F_2,
!> and with the first Piola-Kirchhoff stress P = tau F^-T (P_tt = tau_tt/F_tt)
!>   f_a += c P_2 J0^-T dN_a/dxi,  f_ra += c P_tt N_a / R,            (FA-2)
!> the exact gradient of the stored energy sum_g c W(F) (the hoop strain is
!> taken at the Gauss points, R_g > 0: axis nodes never divide). Mean
!> dilatation (Q4 default for neo_hooke and j2) takes the volumetric energy
!> on Jbar = sum_g c J_g / V_e, V_e = sum_g c, the volumes weighted by
!> 2 pi R, as (F-3) of raccord_finite_kernel and (J-2) of
!> raccord_plastic_kernel.                                               (FA-3)
!> Laws: neo-Hooke (M-1, M-2) and St Venant-Kirchhoff (M-3) on the full
!> 3x3 F, and J2 with Hencky elasticity and the exponential-map return
!> (P-4, P-5) with the hoop stretch as third principal direction. The law
!> is chosen once per chunk and Gauss point, never inside the element loop.
!> Each chunk reports the stored energy sum_g c W (and for j2 the plastic
!> work of the step), the smallest J, the Cauchy stress (rr, zz, rz, tt) at
!> every point, and with monitor the largest omega^2 estimate: the plane
!> current-length estimate 4 c_e^2 / L_e^2 (raccord_kernel_monitor.inc, on
!> the current r-z area) times the element's hoop factor, the ratio of its
!> exact eigenvalue bound (hoop stiffness included, axis dofs dropped) to
!> that estimate at rest, at least 1 (raccord_elastic_block_finite_axi).
module raccord_finite_axi_kernel
  use raccord_kinds, only: wp, pi
  use raccord_material, only: moduli_t, MAT_NEO_HOOKE, MAT_SVK, MAT_J2, VOL_MEAN
  use raccord_plasticity, only: j2_t, nhist, j2_hencky_ftt_lanes
  use raccord_finite_kernel, only: fin_chunk_len
  implicit none
  private

  public :: kernel_finite_axi_q4, kernel_finite_axi_q8

  integer, parameter :: max_nen = 8, max_gp = 9
  integer, parameter :: ld = fin_chunk_len

contains

  !> fe = internal forces (FA-2) of nc axisymmetric elements of a chunk.
  !> mat: MAT_NEO_HOOKE, MAT_SVK or MAT_J2 (j2: yield data; hist: Cp^-1 and
  !> ebar per point, updated in place; other laws leave hist alone);
  !> vol: VOL_MEAN or not; nref(nen, ngp), dn(2, nen, ngp): shape functions
  !> and natural derivatives; pg: J0^-1 column-major; rr = 1/R_g; cw = c;
  !> vol0 = V_e; diag: reference corner diagonals; rinv0 = 1/rho per
  !> element; hfac: the hoop factor of the step estimate. Out: sg Cauchy
  !> (rr, zz, rz, tt) per point; act = 1 where a j2 return was plastic;
  !> energy = sum c W, dissip = sum c dW_p; jmin, jmin_el the smallest J and
  !> its lane; w2 the chunk's largest omega^2 estimate (0 without monitor).
  !> Q4: 2x2 Gauss, L_e = A / longest diagonal.
  pure subroutine kernel_finite_axi_q4(nc, mat, vol, m, j2, nref, dn, pg, rr, cw, vol0, diag, rinv0, hfac, &
      monitor, hist, ue, fe, sg, act, energy, dissip, jmin, jmin_el, w2)
    integer, parameter :: nen = 4, ngp = 4
    real(wp), parameter :: lfac = 1.0_wp
    include 'raccord_finite_axi_body.inc'
  end subroutine kernel_finite_axi_q4

  !> Q8: 3x3 Gauss, L_e = 0.3 A / longest corner diagonal.
  pure subroutine kernel_finite_axi_q8(nc, mat, vol, m, j2, nref, dn, pg, rr, cw, vol0, diag, rinv0, hfac, &
      monitor, hist, ue, fe, sg, act, energy, dissip, jmin, jmin_el, w2)
    integer, parameter :: nen = 8, ngp = 9
    real(wp), parameter :: lfac = 0.3_wp
    include 'raccord_finite_axi_body.inc'
  end subroutine kernel_finite_axi_q8

  !> Neo-Hooke (M-1, M-2) on the 3x3 F at one Gauss point of nc elements:
  !> f(:, 1:5) = (F_rr, F_zr, F_rz, F_zz, F_tt), detf = J; Kirchhoff tau
  !> (rr, zz, rz, tt) into tau; c W added to we; the wave-modulus bound
  !> (method brief 5.2) maxed into wmod. With mean dilatation the pressure
  !> is the element's pbar and the volumetric energy is the caller's.
  pure subroutine neo_hooke_axi_chunk(nc, m, mean, f, detf, pbar, cw, tau, we, wmod)
    integer, intent(in) :: nc
    type(moduli_t), intent(in) :: m
    logical, intent(in) :: mean
    real(wp), intent(in) :: f(ld, 5), detf(ld), pbar(ld), cw(ld)
    real(wp), intent(out) :: tau(ld, 4)
    real(wp), intent(inout) :: we(ld), wmod(ld)
    real(wp) :: pb(ld), vol_w, f11, f21, f12, f22, f33, j, b11, b22, b12, b33, trb, jm23, gj, tr3
    real(wp) :: t11, t22, t12, t33, p, mid, rad, tmax, mubar
    integer :: i
    if (mean) then
      pb(1:nc) = pbar(1:nc)
      vol_w = 0.0_wp
    else
      pb(1:nc) = m%k*(detf(1:nc) - 1.0_wp)
      vol_w = 0.5_wp*m%k
    end if
    do i = 1, nc
      f11 = f(i, 1)
      f21 = f(i, 2)
      f12 = f(i, 3)
      f22 = f(i, 4)
      f33 = f(i, 5)
      j = detf(i)
      ! B = F F^T, B_tt = F_tt^2
      b11 = f11*f11 + f12*f12
      b22 = f21*f21 + f22*f22
      b12 = f11*f21 + f12*f22
      b33 = f33*f33
      trb = b11 + b22 + b33
      jm23 = exp(log(j)*(-2.0_wp/3.0_wp))
      gj = m%g*jm23
      tr3 = trb/3.0_wp
      t11 = gj*(b11 - tr3)
      t22 = gj*(b22 - tr3)
      t12 = gj*b12
      t33 = gj*(b33 - tr3)
      mubar = gj*tr3
      mid = 0.5_wp*(t11 + t22)
      rad = sqrt((0.5_wp*(t11 - t22))**2 + t12*t12)
      tmax = max(abs(mid + rad), abs(mid - rad), abs(t33))
      wmod(i) = max(wmod(i), m%k*j*j + (4.0_wp*mubar + 7.0_wp*tmax)/3.0_wp)
      we(i) = we(i) + cw(i)*(0.5_wp*m%g*(jm23*trb - 3.0_wp) + vol_w*(j - 1.0_wp)**2)
      p = pb(i)*j
      tau(i, 1) = t11 + p
      tau(i, 2) = t22 + p
      tau(i, 3) = t12
      tau(i, 4) = t33 + p
    end do
  end subroutine neo_hooke_axi_chunk

  !> St Venant-Kirchhoff (M-3) on the 3x3 F: tau = F S F^T (rr, zz, rz, tt),
  !> c W added to we, the bound (lam + 2 mu) lmax(B)^2 + max|tau| into wmod.
  pure subroutine svk_axi_chunk(nc, m, f, cw, tau, we, wmod)
    integer, intent(in) :: nc
    type(moduli_t), intent(in) :: m
    real(wp), intent(in) :: f(ld, 5), cw(ld)
    real(wp), intent(out) :: tau(ld, 4)
    real(wp), intent(inout) :: we(ld), wmod(ld)
    real(wp) :: f11, f21, f12, f22, f33, e11, e22, e12, e33, tr, s11, s22, s12, s33, p11, p21, p12, p22
    real(wp) :: t11, t22, t12, t33, b11, b22, b12, bmax, mid, rad, tmax
    integer :: i
    do i = 1, nc
      f11 = f(i, 1)
      f21 = f(i, 2)
      f12 = f(i, 3)
      f22 = f(i, 4)
      f33 = f(i, 5)
      ! E = (F^T F - I)/2, E_tt = (F_tt^2 - 1)/2; S = lam tr E I + 2 mu E
      e11 = 0.5_wp*(f11*f11 + f21*f21 - 1.0_wp)
      e22 = 0.5_wp*(f12*f12 + f22*f22 - 1.0_wp)
      e12 = 0.5_wp*(f11*f12 + f21*f22)
      e33 = 0.5_wp*(f33*f33 - 1.0_wp)
      tr = m%lam*(e11 + e22 + e33)
      s11 = tr + 2.0_wp*m%g*e11
      s22 = tr + 2.0_wp*m%g*e22
      s12 = 2.0_wp*m%g*e12
      s33 = tr + 2.0_wp*m%g*e33
      p11 = f11*s11 + f12*s12
      p21 = f21*s11 + f22*s12
      p12 = f11*s12 + f12*s22
      p22 = f21*s12 + f22*s22
      t11 = p11*f11 + p12*f12
      t22 = p21*f21 + p22*f22
      t12 = p21*f11 + p22*f12
      t33 = f33*f33*s33
      tau(i, 1) = t11
      tau(i, 2) = t22
      tau(i, 3) = t12
      tau(i, 4) = t33
      we(i) = we(i) + cw(i)*(0.5_wp*m%lam*(e11 + e22 + e33)**2 + &
        m%g*(e11*e11 + e22*e22 + e33*e33 + 2.0_wp*e12*e12))
      b11 = f11*f11 + f12*f12
      b22 = f21*f21 + f22*f22
      b12 = f11*f21 + f12*f22
      bmax = max(1.0_wp, 0.5_wp*(b11 + b22) + sqrt((0.5_wp*(b11 - b22))**2 + b12*b12), f33*f33)
      mid = 0.5_wp*(t11 + t22)
      rad = sqrt((0.5_wp*(t11 - t22))**2 + t12*t12)
      tmax = max(abs(mid + rad), abs(mid - rad), abs(t33))
      wmod(i) = max(wmod(i), (m%lam + 2.0_wp*m%g)*bmax*bmax + tmax)
    end do
  end subroutine svk_axi_chunk
end module raccord_finite_axi_kernel
