!> Internal force of finite-strain (hyperelastic) elements, total
!> Lagrangian, one chunk of elements at a time (doc/theory-finite.md).
!>
!> At each Gauss point g of the reference element, with H = sqrt(c) J0^-1
!> (J0 = dX/dxi, c = w_g det J0 t0, stored once at set-up) and the natural
!> derivatives dN_a/dxi shared by every element,
!>   F = I + (sum_a u_a dN_a/dxi^T) J0^-1 = I + (d H)/sqrt(c),          (F-1)
!>   f_a += c P(F) J0^-T dN_a/dxi = sqrt(c) (P H^T) dN_a/dxi,           (F-2)
!> which is the gradient of the stored energy sum_g W(F) c (P = dW/dF).
!> With mean dilatation (Nagtegaal, Parks & Rice 1974; Simo, Taylor &
!> Pister 1985) the volumetric energy is taken on the element's volume ratio
!>   Jbar = sum_g J_g c_g / V_e,  V_e = sum_g c_g,                      (F-3)
!>   Pi_e = sum_g W_iso(F_g) c_g + V_e U(Jbar),  U = (K/2)(J - 1)^2,
!> so that P_g = (tau_iso(F_g) + K (Jbar - 1) J_g I) F_g^-T, still the
!> exact gradient of Pi_e: the energy balance stays as exact as with full
!> integration, and Q4 does not lock when nu -> 1/2.
!>
!> The kernels loop over the Gauss points outside and over the chunk's
!> elements inside (unit stride across SIMD lanes, as the small-strain
!> kernels); the material is chosen once per chunk and Gauss point, never
!> inside the element loop. Besides the forces each chunk reports its
!> stored energy, its smallest J (an inverted element stops the run) and,
!> when asked, its largest omega^2 estimate for the stable step on the
!> current geometry (method brief 5.1-5.2): dt_e = L_e / c_e with
!> L_e = (current area) / (longest current corner diagonal) (x 0.3 for Q8)
!> and rho0 c_e^2 the material's bound of the current wave modulus.
module raccord_finite_kernel
  use raccord_kinds, only: wp
  use raccord_material, only: moduli_t, MAT_NEO_HOOKE, MAT_SVK, VOL_MEAN
  implicit none
  private

  public :: kernel_finite_q4, kernel_finite_q8

  !> Elements per chunk: the same as raccord_elastic_block's chunk_len.
  integer, parameter, public :: fin_chunk_len = 32
  !> Where grad_X h of Gauss point g sits in the Q4 reference data pg(:, 4, 4):
  !> pg(q4h_row(g):q4h_row(g)+1, q4h_col(g)) (raccord_elastic_block_finite, q4_split).
  integer, parameter, public :: q4h_row(4) = [1, 3, 1, 3], q4h_col(4) = [3, 3, 4, 4]
  integer, parameter :: max_nen = 8, max_gp = 9

contains

  !> fe = internal forces (F-2) of nc elements of a chunk; energy = their
  !> stored energy; jmin = the smallest J over their Gauss points and jmin_el
  !> the chunk position of that element; with monitor, w2 = the largest
  !> omega^2 estimate 4 c^2 / L^2 of the chunk (0 when not asked).
  !> dn(2, nen, ngp): natural derivatives; pg(:, 4, ngp): the reference
  !> geometry, for Q8 J0^-1 column-major at each point, for Q4 the exact
  !> split grad_X N_a = b_a + gamma_a grad_X h (raccord_elastic_block_finite,
  !> q4_split), with which F = F0 + q (x) grad_X h at each point and
  !> f_a = Pbar b_a + gamma_a r, Pbar = sum_g c P, r = sum_g c P grad_X h; cw(:, g) = c = w det J0 t0; vol0 = V_e; diag(:, 1:4) = reference
  !> corner diagonals X3 - X1, X4 - X2 (x, y each); lfac = 1 (Q4) or 0.3 (Q8);
  !> rinv = 1/rho0 per element (mass scaling: 1/(s_e rho0)); thickness t0 turns the element volume into its area.
  !> The body is raccord_finite_kernel_body.inc, one copy per element type.
  !>
  !> Q4: 4 nodes, 2x2 Gauss, L_e = A / longest diagonal.
  pure subroutine kernel_finite_q4(nc, mat, vol, m, dn, pg, cw, vol0, diag, rinv, thickness, monitor, &
      ue, fe, energy, jmin, jmin_el, w2)
    integer, parameter :: nen = 4, ngp = 4
    real(wp), parameter :: lfac = 1.0_wp
    logical, parameter :: split = .true.
    include 'raccord_finite_kernel_body.inc'
  end subroutine kernel_finite_q4

  !> Q8: 8 nodes, 3x3 Gauss, L_e = 0.3 A / longest corner diagonal.
  pure subroutine kernel_finite_q8(nc, mat, vol, m, dn, pg, cw, vol0, diag, rinv, thickness, monitor, &
      ue, fe, energy, jmin, jmin_el, w2)
    integer, parameter :: nen = 8, ngp = 9
    real(wp), parameter :: lfac = 0.3_wp
    logical, parameter :: split = .false.
    include 'raccord_finite_kernel_body.inc'
  end subroutine kernel_finite_q8

  !> Neo-Hooke (M-1, M-2) at one Gauss point of nc elements: P into pk,
  !> c W added to we, the wave-modulus bound (method brief 5.2) maxed into
  !> wmod. With mean dilatation the pressure is the element's pbar and the
  !> volumetric energy is not added here (the caller adds V_e U(Jbar)).
  !> One power per point; the loop has no branch and vectorises.
  pure subroutine neo_hooke_chunk(nc, m, mean, f, detf, pbar, cw, pk, we, wmod)
    integer, intent(in) :: nc
    type(moduli_t), intent(in) :: m
    logical, intent(in) :: mean
    real(wp), intent(in) :: f(fin_chunk_len, 4), detf(fin_chunk_len), pbar(fin_chunk_len), cw(fin_chunk_len)
    real(wp), intent(out) :: pk(fin_chunk_len, 4)
    real(wp), intent(inout) :: we(fin_chunk_len), wmod(fin_chunk_len)
    real(wp) :: pb(fin_chunk_len), vol_w
    real(wp) :: f11, f21, f12, f22, j, b11, b22, b12, trb, jm23, gj, tr3, t11, t22, t12, t33, p, r, rad, mid, tmax
    real(wp) :: mubar
    integer :: i
    ! the pressure of each element: K (J - 1) per point, or the element's
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
      j = detf(i)
      ! B = F F^T (in-plane), B33 = 1
      b11 = f11*f11 + f12*f12
      b22 = f21*f21 + f22*f22
      b12 = f11*f21 + f12*f22
      trb = b11 + b22 + 1.0_wp
      jm23 = exp(log(j)*(-2.0_wp/3.0_wp))
      ! isochoric Kirchhoff stress G dev(Bbar) (M-2)
      gj = m%g*jm23
      tr3 = trb/3.0_wp
      t11 = gj*(b11 - tr3)
      t22 = gj*(b22 - tr3)
      t12 = gj*b12
      t33 = gj*(1.0_wp - tr3)
      ! wave modulus bound: K J^2 + (4 mubar + 7 max|tau_dev,a|)/3
      mubar = m%g*jm23*trb/3.0_wp
      mid = 0.5_wp*(t11 + t22)
      rad = sqrt((0.5_wp*(t11 - t22))**2 + t12*t12)
      tmax = max(abs(mid + rad), abs(mid - rad), abs(t33))
      wmod(i) = max(wmod(i), m%k*j*j + (4.0_wp*mubar + 7.0_wp*tmax)/3.0_wp)
      ! stored energy C10 (Ibar1 - 3) [+ (K/2)(J - 1)^2] (M-1)
      we(i) = we(i) + cw(i)*(0.5_wp*m%g*(jm23*trb - 3.0_wp) + vol_w*(j - 1.0_wp)**2)
      ! tau = G dev(Bbar) + p J I, P = tau F^-T, F^-T = [[F22, -F21], [-F12, F11]]/J
      p = pb(i)*j
      t11 = t11 + p
      t22 = t22 + p
      r = 1.0_wp/j
      pk(i, 1) = r*(t11*f22 - t12*f12)
      pk(i, 2) = r*(t12*f22 - t22*f12)
      pk(i, 3) = r*(t12*f11 - t11*f21)
      pk(i, 4) = r*(t22*f11 - t12*f21)
    end do
  end subroutine neo_hooke_chunk

  !> St Venant-Kirchhoff (M-3) at one Gauss point of nc elements: P = F S
  !> into pk, c W added to we, the bound (lam + 2 mu) lmax(B)^2 + max|tau|
  !> maxed into wmod.
  pure subroutine svk_chunk(nc, m, f, cw, pk, we, wmod)
    integer, intent(in) :: nc
    type(moduli_t), intent(in) :: m
    real(wp), intent(in) :: f(fin_chunk_len, 4), cw(fin_chunk_len)
    real(wp), intent(out) :: pk(fin_chunk_len, 4)
    real(wp), intent(inout) :: we(fin_chunk_len), wmod(fin_chunk_len)
    real(wp) :: f11, f21, f12, f22, e11, e22, e12, tr, s11, s22, s12, p11, p21, p12, p22
    real(wp) :: t11, t22, t12, b11, b22, b12, bmax, mid, rad, tmax
    integer :: i
    do i = 1, nc
      f11 = f(i, 1)
      f21 = f(i, 2)
      f12 = f(i, 3)
      f22 = f(i, 4)
      ! E = (F^T F - I)/2, S = lam tr E I + 2 mu E
      e11 = 0.5_wp*(f11*f11 + f21*f21 - 1.0_wp)
      e22 = 0.5_wp*(f12*f12 + f22*f22 - 1.0_wp)
      e12 = 0.5_wp*(f11*f12 + f21*f22)
      tr = m%lam*(e11 + e22)
      s11 = tr + 2.0_wp*m%g*e11
      s22 = tr + 2.0_wp*m%g*e22
      s12 = 2.0_wp*m%g*e12
      p11 = f11*s11 + f12*s12
      p21 = f21*s11 + f22*s12
      p12 = f11*s12 + f12*s22
      p22 = f21*s12 + f22*s22
      pk(i, 1) = p11
      pk(i, 2) = p21
      pk(i, 3) = p12
      pk(i, 4) = p22
      we(i) = we(i) + cw(i)*(0.5_wp*m%lam*(e11 + e22)**2 + m%g*(e11*e11 + e22*e22 + 2.0_wp*e12*e12))
      ! bound of the wave modulus: tau = P F^T, B = F F^T
      t11 = p11*f11 + p12*f12
      t22 = p21*f21 + p22*f22
      t12 = p21*f11 + p22*f12
      b11 = f11*f11 + f12*f12
      b22 = f21*f21 + f22*f22
      b12 = f11*f21 + f12*f22
      bmax = max(1.0_wp, 0.5_wp*(b11 + b22) + sqrt((0.5_wp*(b11 - b22))**2 + b12*b12))
      mid = 0.5_wp*(t11 + t22)
      rad = sqrt((0.5_wp*(t11 - t22))**2 + t12*t12)
      tmax = max(abs(mid + rad), abs(mid - rad), abs(tr))
      wmod(i) = max(wmod(i), (m%lam + 2.0_wp*m%g)*bmax*bmax + tmax)
    end do
  end subroutine svk_chunk
end module raccord_finite_kernel
