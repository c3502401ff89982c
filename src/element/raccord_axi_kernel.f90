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

  !> fe = K_e ue for nc axisymmetric Q4 elements (2x2 Gauss).
  pure subroutine kernel_axi_q4(nc, lam, mu, nref, dn, h, hoop, ue, fe)
    integer, parameter :: nen = 4, ngp = 4
    include 'raccord_axi_kernel_body.inc'
  end subroutine kernel_axi_q4

  !> fe = K_e ue for nc axisymmetric Q8 elements (3x3 Gauss).
  pure subroutine kernel_axi_q8(nc, lam, mu, nref, dn, h, hoop, ue, fe)
    integer, parameter :: nen = 8, ngp = 9
    include 'raccord_axi_kernel_body.inc'
  end subroutine kernel_axi_q8
end module raccord_axi_kernel
