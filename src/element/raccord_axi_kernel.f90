!> Small-strain axisymmetric kernels (doc/theory-axisymmetric.md; method
!> brief method-finite-plastic-axi.md section 9.1): fe = K_e ue for a chunk
!> of Q4 or Q8 elements in the (r, z) = (x, y) half-plane, Hooke's law,
!> full Gauss integration weighted by 2 pi r.
!>
!> Per Gauss point g of each element the block keeps (raccord_elastic_block_axi)
!>   H = sqrt(c) J^-1 (2x2, as the plane Q8 kernel)  and  s = sqrt(c)/r_g,
!> c = w_g detJ 2 pi r_g, so that with the reference shape functions N_a
!> and their natural derivatives D_a (the same for every element)
!>   sqrt(c) (eps_rr, eps_zz, gamma_rz) from (sum_a u_a D_a^T) H,
!>   sqrt(c) eps_tt = s sum_a u_ra N_a                 (hoop strain u_r/r)
!>   f_a += (sqrt(c) sigma_in-plane) H^T D_a,  f_ra += (sqrt(c) sigma_tt) s N_a
!> which is f = K u with K = sum_g c B^T D B, B the 4-row axisymmetric
!> strain matrix (rows rr, zz, tt, rz). The four strain components at a
!> Gauss point are explicit (g11, g22, gtt, g12 + g21): a plasticity
!> return replaces the Hooke lines without touching the rest.
!> Gauss points are interior, r_g > 0 for r >= 0 nodes: no division by 0.
module raccord_axi_kernel
  use raccord_kinds, only: wp
  use raccord_finite_kernel, only: fin_chunk_len
  implicit none
  private

  public :: kernel_axi_q4, kernel_axi_q8

  integer, parameter :: chunk_len = fin_chunk_len, max_nen = 8

contains

  !> fe = K_e ue for nc axisymmetric Q4 elements (2x2 Gauss), in the
  !> bilinear basis (1, xi, eta, xi eta): with N_a = (1 + xi_a xi)(1 + eta_a eta)/4
  !> the nodal values enter only through q_k = sum_a c_ak u_a, c_a = (1, xi_a,
  !> eta_a, xi_a eta_a), so that at a point
  !>   du/dxi = (q1 + eta q3)/4,  du/deta = (q2 + xi q3)/4,
  !>   u = (q0 + xi q1 + eta q2 + xi eta q3)/4,
  !> and the nodal forces are f_a = sum_k c_ak p_k/4 with p_k the Gauss sums of
  !> the stresses against the same basis (theory-axisymmetric.md A.2). The
  !> same K as the generic form (raccord_axi_kernel_body.inc, Q8's) in about
  !> half the flops; tested against the Gauss-sum stiffness. The Gauss
  !> points are in the block's order, g = i + 2 (j - 1) at (xi, eta) =
  !> (gx(i), gx(j)), gx = -+1/sqrt(3).
  pure subroutine kernel_axi_q4(nc, lam, mu, h, hoop, ue, fe)
    integer, parameter :: ngp = 4
    integer, intent(in) :: nc
    real(wp), intent(in) :: lam, mu
    real(wp), intent(in) :: h(chunk_len, 4, ngp), hoop(chunk_len, ngp), ue(chunk_len, 2, max_nen)
    real(wp), intent(inout) :: fe(chunk_len, 2, max_nen)
    real(wp), parameter :: q = 0.577350269189625765_wp
    real(wp), parameter :: xg(ngp) = [-q, q, -q, q], eg(ngp) = [-q, -q, q, q]
    real(wp) :: r0, r1, r2, r3, z1, z2, z3, pr0, pr1, pr2, pr3, pz1, pz2, pz3
    real(wp) :: d11, d12, d21, d22, h11, h21, h12, h22, g11, g12, g21, g22, gtt, ur, s, tr, s11, s22, s12, stt
    real(wp) :: t11, t12, t21, t22, ht, mu2, xi, eta
    integer :: g, i
    mu2 = 2.0_wp*mu
    elements: do i = 1, nc
      ! q_k of u_r and u_z (q0 of u_z is not needed: no hoop term in z)
      r0 = ue(i, 1, 1) + ue(i, 1, 2) + ue(i, 1, 3) + ue(i, 1, 4)
      r1 = -ue(i, 1, 1) + ue(i, 1, 2) + ue(i, 1, 3) - ue(i, 1, 4)
      r2 = -ue(i, 1, 1) - ue(i, 1, 2) + ue(i, 1, 3) + ue(i, 1, 4)
      r3 = ue(i, 1, 1) - ue(i, 1, 2) + ue(i, 1, 3) - ue(i, 1, 4)
      z1 = -ue(i, 2, 1) + ue(i, 2, 2) + ue(i, 2, 3) - ue(i, 2, 4)
      z2 = -ue(i, 2, 1) - ue(i, 2, 2) + ue(i, 2, 3) + ue(i, 2, 4)
      z3 = ue(i, 2, 1) - ue(i, 2, 2) + ue(i, 2, 3) - ue(i, 2, 4)
      pr0 = 0.0_wp
      pr1 = 0.0_wp
      pr2 = 0.0_wp
      pr3 = 0.0_wp
      pz1 = 0.0_wp
      pz2 = 0.0_wp
      pz3 = 0.0_wp
      gauss: do g = 1, ngp
        xi = xg(g)
        eta = eg(g)
        d11 = 0.25_wp*(r1 + eta*r3)
        d12 = 0.25_wp*(r2 + xi*r3)
        d21 = 0.25_wp*(z1 + eta*z3)
        d22 = 0.25_wp*(z2 + xi*z3)
        ur = 0.25_wp*(r0 + xi*r1 + eta*r2 + xi*eta*r3)
        h11 = h(i, 1, g)
        h21 = h(i, 2, g)
        h12 = h(i, 3, g)
        h22 = h(i, 4, g)
        s = hoop(i, g)
        ! sqrt(c) times (eps_rr, eps_zz, eps_tt) and the two shear gradients
        g11 = d11*h11 + d12*h21
        g12 = d11*h12 + d12*h22
        g21 = d21*h11 + d22*h21
        g22 = d21*h12 + d22*h22
        gtt = s*ur
        ! Hooke on (rr, zz, tt, rz), scaled by sqrt(c)
        tr = lam*(g11 + g22 + gtt)
        s11 = tr + mu2*g11
        s22 = tr + mu2*g22
        stt = tr + mu2*gtt
        s12 = mu*(g12 + g21)
        t11 = s11*h11 + s12*h12
        t12 = s11*h21 + s12*h22
        t21 = s12*h11 + s22*h12
        t22 = s12*h21 + s22*h22
        ht = stt*s
        ! Gauss sums against the basis (f_a = sum_k c_ak p_k/4)
        pr0 = pr0 + ht
        pr1 = pr1 + t11 + ht*xi
        pr2 = pr2 + t12 + ht*eta
        pr3 = pr3 + t11*eta + t12*xi + ht*xi*eta
        pz1 = pz1 + t21
        pz2 = pz2 + t22
        pz3 = pz3 + t21*eta + t22*xi
      end do gauss
      ! c_a = (1, xi_a, eta_a, xi_a eta_a) at the corners (-1,-1), (1,-1), (1,1), (-1,1)
      fe(i, 1, 1) = 0.25_wp*(pr0 - pr1 - pr2 + pr3)
      fe(i, 1, 2) = 0.25_wp*(pr0 + pr1 - pr2 - pr3)
      fe(i, 1, 3) = 0.25_wp*(pr0 + pr1 + pr2 + pr3)
      fe(i, 1, 4) = 0.25_wp*(pr0 - pr1 + pr2 - pr3)
      fe(i, 2, 1) = 0.25_wp*(-pz1 - pz2 + pz3)
      fe(i, 2, 2) = 0.25_wp*(pz1 - pz2 - pz3)
      fe(i, 2, 3) = 0.25_wp*(pz1 + pz2 + pz3)
      fe(i, 2, 4) = 0.25_wp*(-pz1 + pz2 - pz3)
    end do elements
  end subroutine kernel_axi_q4

  !> fe = K_e ue for nc axisymmetric Q8 elements (3x3 Gauss).
  pure subroutine kernel_axi_q8(nc, lam, mu, nref, dn, h, hoop, ue, fe)
    integer, parameter :: nen = 8, ngp = 9
    include 'raccord_axi_kernel_body.inc'
  end subroutine kernel_axi_q8
end module raccord_axi_kernel
