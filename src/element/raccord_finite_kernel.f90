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
  use raccord_material, only: moduli_t, MAT_NEO_HOOKE, MAT_SVK, VOL_MEAN, neo_hooke_tau, neo_hooke_iso_tau, &
    neo_hooke_energy, neo_hooke_iso_energy, volumetric_energy, svk_tau, svk_energy, first_piola, &
    wave_modulus_neo_hooke, wave_modulus_svk
  implicit none
  private

  public :: kernel_finite

  !> Elements per chunk: the same as raccord_elastic_block's chunk_len.
  integer, parameter, public :: fin_chunk_len = 32
  integer, parameter :: max_nen = 8, max_gp = 9

contains

  !> fe = internal forces (F-2) of nc elements of a chunk; energy = their
  !> stored energy; jmin = the smallest J over their Gauss points and jmin_el
  !> the chunk position of that element; with monitor, w2 = the largest
  !> omega^2 estimate 4 c^2 / L^2 of the chunk (0 when not asked).
  !> dn(2, nen, ngp): natural derivatives; h(:, 4, g): H = sqrt(c) J0^-1
  !> column-major; sc(:, g) = sqrt(c); vol0 = V_e; diag(:, 1:4) = reference
  !> corner diagonals X3 - X1, X4 - X2 (x, y each); lfac = 1 (Q4) or 0.3 (Q8);
  !> rinv = 1/rho0; thickness t0 turns the element volume into its area.
  pure subroutine kernel_finite(nc, nen, ngp, mat, vol, m, dn, h, sc, vol0, diag, lfac, rinv, thickness, monitor, &
      ue, fe, energy, jmin, jmin_el, w2)
    integer, intent(in) :: nc, nen, ngp, mat, vol
    type(moduli_t), intent(in) :: m
    real(wp), intent(in) :: dn(2, nen, ngp), h(fin_chunk_len, 4, ngp), sc(fin_chunk_len, ngp), vol0(fin_chunk_len)
    real(wp), intent(in) :: diag(fin_chunk_len, 4), lfac, rinv, thickness
    logical, intent(in) :: monitor
    real(wp), intent(in) :: ue(fin_chunk_len, 2, max_nen)
    real(wp), intent(inout) :: fe(fin_chunk_len, 2, max_nen)
    real(wp), intent(out) :: energy, jmin, w2
    integer, intent(out) :: jmin_el
    real(wp) :: f(fin_chunk_len, 4, max_gp), detf(fin_chunk_len, max_gp), pbar(fin_chunk_len)
    real(wp) :: we(fin_chunk_len), wmod(fin_chunk_len), area(fin_chunk_len)
    real(wp) :: d11, d12, d21, d22, g11, g12, g21, g22, r, tau(4), tau33, jg, fl(4), pk(fin_chunk_len, 4)
    real(wp) :: t11, t12, t21, t22, c, dx1, dy1, dx2, dy2, l2
    integer :: g, a, i
    logical :: mean

    mean = vol == VOL_MEAN
    fe(1:nc, :, 1:nen) = 0.0_wp
    we(1:nc) = 0.0_wp
    area(1:nc) = 0.0_wp
    wmod(1:nc) = 0.0_wp
    jmin = huge(1.0_wp)
    jmin_el = 0

    ! (F-1): the deformation gradient at every Gauss point of the chunk
    gradients: do g = 1, ngp
      do i = 1, nc
        d11 = 0.0_wp
        d12 = 0.0_wp
        d21 = 0.0_wp
        d22 = 0.0_wp
        do a = 1, nen
          d11 = d11 + ue(i, 1, a)*dn(1, a, g)
          d12 = d12 + ue(i, 1, a)*dn(2, a, g)
          d21 = d21 + ue(i, 2, a)*dn(1, a, g)
          d22 = d22 + ue(i, 2, a)*dn(2, a, g)
        end do
        r = 1.0_wp/sc(i, g)
        g11 = (d11*h(i, 1, g) + d12*h(i, 2, g))*r
        g12 = (d11*h(i, 3, g) + d12*h(i, 4, g))*r
        g21 = (d21*h(i, 1, g) + d22*h(i, 2, g))*r
        g22 = (d21*h(i, 3, g) + d22*h(i, 4, g))*r
        f(i, 1, g) = 1.0_wp + g11
        f(i, 2, g) = g21
        f(i, 3, g) = g12
        f(i, 4, g) = 1.0_wp + g22
        detf(i, g) = f(i, 1, g)*f(i, 4, g) - f(i, 2, g)*f(i, 3, g)
        area(i) = area(i) + detf(i, g)*sc(i, g)**2
      end do
    end do gradients

    ! An inverted element (J <= 0) is reported, not computed: the caller
    ! stops the run (exit 3). Its stress is evaluated at |J| so that no
    ! invalid operation is raised on the way.
    do g = 1, ngp
      do i = 1, nc
        if (detf(i, g) < jmin) then
          jmin = detf(i, g)
          jmin_el = i
        end if
      end do
    end do
    if (jmin <= 0.0_wp) detf(1:nc, 1:ngp) = max(abs(detf(1:nc, 1:ngp)), tiny(1.0_wp))

    ! (F-3): the element pressure of mean dilatation and its energy
    if (mean) then
      do i = 1, nc
        jg = area(i)/vol0(i)
        pbar(i) = m%k*(jg - 1.0_wp)
        we(i) = vol0(i)*volumetric_energy(m, jg)
      end do
    end if

    ! Stress (one material per chunk) and forces (F-2)
    points: do g = 1, ngp
      select case (mat)
      case (MAT_NEO_HOOKE)
        if (mean) then
          do i = 1, nc
            fl = f(i, :, g)
            call neo_hooke_iso_tau(m, fl, detf(i, g), tau, tau33)
            tau(1) = tau(1) + pbar(i)*detf(i, g)
            tau(4) = tau(4) + pbar(i)*detf(i, g)
            pk(i, :) = first_piola(fl, detf(i, g), tau)
            we(i) = we(i) + sc(i, g)**2*neo_hooke_iso_energy(m, fl, detf(i, g))
          end do
        else
          do i = 1, nc
            fl = f(i, :, g)
            call neo_hooke_tau(m, fl, detf(i, g), tau, tau33)
            pk(i, :) = first_piola(fl, detf(i, g), tau)
            we(i) = we(i) + sc(i, g)**2*neo_hooke_energy(m, fl, detf(i, g))
          end do
        end if
        if (monitor) then
          do i = 1, nc
            fl = f(i, :, g)
            wmod(i) = max(wmod(i), wave_modulus_neo_hooke(m, fl, detf(i, g)))
          end do
        end if
      case (MAT_SVK)
        do i = 1, nc
          fl = f(i, :, g)
          call svk_tau(m, fl, tau, tau33)
          pk(i, :) = first_piola(fl, detf(i, g), tau)
          we(i) = we(i) + sc(i, g)**2*svk_energy(m, fl)
        end do
        if (monitor) then
          do i = 1, nc
            fl = f(i, :, g)
            wmod(i) = max(wmod(i), wave_modulus_svk(m, fl))
          end do
        end if
      end select
      ! fe(i, :, a) += sqrt(c) (P H^T) dN_a/dxi
      do i = 1, nc
        c = sc(i, g)
        t11 = c*(pk(i, 1)*h(i, 1, g) + pk(i, 3)*h(i, 3, g))
        t12 = c*(pk(i, 1)*h(i, 2, g) + pk(i, 3)*h(i, 4, g))
        t21 = c*(pk(i, 2)*h(i, 1, g) + pk(i, 4)*h(i, 3, g))
        t22 = c*(pk(i, 2)*h(i, 2, g) + pk(i, 4)*h(i, 4, g))
        do a = 1, nen
          fe(i, 1, a) = fe(i, 1, a) + t11*dn(1, a, g) + t12*dn(2, a, g)
          fe(i, 2, a) = fe(i, 2, a) + t21*dn(1, a, g) + t22*dn(2, a, g)
        end do
      end do
    end do points

    energy = sum(we(1:nc))
    w2 = 0.0_wp
    if (monitor) then
      ! omega_e^2 = (2 c / L)^2, c^2 = wmod/rho0, L = lfac (area/t0) / longest diagonal
      do i = 1, nc
        dx1 = diag(i, 1) + ue(i, 1, 3) - ue(i, 1, 1)
        dy1 = diag(i, 2) + ue(i, 2, 3) - ue(i, 2, 1)
        dx2 = diag(i, 3) + ue(i, 1, 4) - ue(i, 1, 2)
        dy2 = diag(i, 4) + ue(i, 2, 4) - ue(i, 2, 2)
        l2 = (lfac*abs(area(i))/thickness)**2/max(dx1*dx1 + dy1*dy1, dx2*dx2 + dy2*dy2)
        c = 4.0_wp*wmod(i)*rinv/max(l2, tiny(1.0_wp))
        w2 = max(w2, c)
      end do
    end if

  end subroutine kernel_finite
end module raccord_finite_kernel
