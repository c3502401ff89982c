!> Small-strain plane Q4 kernel in the exact split of the fully integrated
!> stiffness (doc/theory-elements.md, eqs. 6.2-6.5; theory section 6): the
!> 2x2 bilinear stiffness splits exactly into a constant-strain part built
!> on the mean gradient b (= the gradient at the element centre) and a
!> rank-2 hourglass part,
!>   K = (A h) B0^T C B0 + (gamma gamma^T) (x) M,
!> M the 2x2 Gauss sum of the hourglass-strain energy. A block keeps
!> beta = sqrt(A h) b (4 reals, b_3 = -b_1, b_4 = -b_2), gamma (4) and M (3)
!> per element: 11 reals and about 60 flops per element and step
!> (kernel_q4). The block builds them at set-up (init_q4_data in the
!> submodule raccord_elastic_block_q4, with the cold map coefficients
!> geo(6) that serve mass, body force, stiffness and stress).
!>
!> The kernel takes one chunk of chunk_len elements, data stored
!> chunk-major (element index first), as the block's add_internal_force
!> gathers and scatters it; it is called once per chunk, so its call is not
!> in the per-element loop.
module raccord_q4_kernel
  use raccord_kinds, only: wp
  use raccord_finite_kernel, only: fin_chunk_len
  implicit none
  private

  public :: kernel_q4
  public :: nq4, q4_bx1, q4_bx2, q4_by1, q4_by2, q4_g1, q4_m11, q4_m12, q4_m22

  integer, parameter :: chunk_len = fin_chunk_len, max_nen = 8
  !> Slots of the Q4 hot data q4(chunk_len, nq4, nchunk): beta_x1, beta_x2,
  !> beta_y1, beta_y2 (beta = sqrt(A h) b, eq. 6.2), gamma_1..4 (eq. 6.3),
  !> M11, M12, M22 (eq. 6.5).
  integer, parameter :: nq4 = 11
  integer, parameter :: q4_bx1 = 1, q4_bx2 = 2, q4_by1 = 3, q4_by2 = 4, q4_g1 = 5, &
    q4_m11 = 9, q4_m12 = 10, q4_m22 = 11

contains

  !> fe = K_e ue for nc Q4 elements of a chunk, fully integrated K in the
  !> exact split K = (A h) B0^T C B0 + (gamma gamma^T) (x) M (theory eqs.
  !> 6.2-6.5). One element per iteration, the loop runs across the chunk in
  !> SIMD lanes; every array is read with unit stride.
  pure subroutine kernel_q4(nc, lam, mu, hq, ue, fe)
    integer, intent(in) :: nc
    real(wp), intent(in) :: lam, mu, hq(chunk_len, nq4), ue(chunk_len, 2, max_nen)
    real(wp), intent(inout) :: fe(chunk_len, 2, max_nen)
    real(wp) :: bx1, bx2, by1, by2, g1, g2, g3, g4, dx13, dx24, dy13, dy24
    real(wp) :: gxx, gxy, gyx, gyy, tr, sxx, syy, sxy, fx1, fx2, fy1, fy2, qx, qy, rx, ry, mu2
    integer :: i
    mu2 = 2.0_wp*mu
    elements: do i = 1, nc
      bx1 = hq(i, q4_bx1)
      bx2 = hq(i, q4_bx2)
      by1 = hq(i, q4_by1)
      by2 = hq(i, q4_by2)
      ! constant-strain part (eq. 6.2): sqrt(A h) grad u = sum_a u_a beta_a^T,
      ! with beta_3 = -beta_1, beta_4 = -beta_2
      dx13 = ue(i, 1, 1) - ue(i, 1, 3)
      dx24 = ue(i, 1, 2) - ue(i, 1, 4)
      dy13 = ue(i, 2, 1) - ue(i, 2, 3)
      dy24 = ue(i, 2, 2) - ue(i, 2, 4)
      gxx = bx1*dx13 + bx2*dx24
      gxy = by1*dx13 + by2*dx24
      gyx = bx1*dy13 + bx2*dy24
      gyy = by1*dy13 + by2*dy24
      ! Hooke (eq. 3.1), scaled by sqrt(A h); f_a = sigma beta_a
      tr = lam*(gxx + gyy)
      sxx = tr + mu2*gxx
      syy = tr + mu2*gyy
      sxy = mu*(gxy + gyx)
      fx1 = sxx*bx1 + sxy*by1
      fx2 = sxx*bx2 + sxy*by2
      fy1 = sxy*bx1 + syy*by1
      fy2 = sxy*bx2 + syy*by2
      ! hourglass part (eqs. 6.4-6.5): q = gamma . u, f_a += gamma_a M q
      g1 = hq(i, q4_g1)
      g2 = hq(i, q4_g1 + 1)
      g3 = hq(i, q4_g1 + 2)
      g4 = hq(i, q4_g1 + 3)
      qx = g1*ue(i, 1, 1) + g2*ue(i, 1, 2) + g3*ue(i, 1, 3) + g4*ue(i, 1, 4)
      qy = g1*ue(i, 2, 1) + g2*ue(i, 2, 2) + g3*ue(i, 2, 3) + g4*ue(i, 2, 4)
      rx = hq(i, q4_m11)*qx + hq(i, q4_m12)*qy
      ry = hq(i, q4_m12)*qx + hq(i, q4_m22)*qy
      fe(i, 1, 1) = fx1 + g1*rx
      fe(i, 1, 2) = fx2 + g2*rx
      fe(i, 1, 3) = g3*rx - fx1
      fe(i, 1, 4) = g4*rx - fx2
      fe(i, 2, 1) = fy1 + g1*ry
      fe(i, 2, 2) = fy2 + g2*ry
      fe(i, 2, 3) = g3*ry - fy1
      fe(i, 2, 4) = g4*ry - fy2
    end do elements
  end subroutine kernel_q4

end module raccord_q4_kernel
