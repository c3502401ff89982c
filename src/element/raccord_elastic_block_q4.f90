!> Set-up of the small-strain plane Q4 blocks: each element's map
!> coefficients geo (eq. 6.2; cold, for mass, body force, stiffness and
!> stress) and the 11 reals per element the Q4 kernel reads in the time
!> loop (beta, gamma, M; theory eqs. 6.2-6.5, raccord_q4_kernel).
submodule (raccord_elastic_block) raccord_elastic_block_q4
  implicit none

  !> Natural coordinates of the Q4 corners and the hourglass vector h = xi eta.
  real(wp), parameter :: xi_c(4) = [-1.0_wp, 1.0_wp, 1.0_wp, -1.0_wp]
  real(wp), parameter :: eta_c(4) = [-1.0_wp, -1.0_wp, 1.0_wp, 1.0_wp]
  real(wp), parameter :: hg_c(4) = [1.0_wp, -1.0_wp, 1.0_wp, -1.0_wp]

contains

  !> The Q4 data of every element (declared in raccord_elastic_block).
  module procedure init_q4_data
    character(len=*), parameter :: where = 'init_elastic_block: '
    real(wp) :: xe(2, 4), geo(ngeo), detj, j4, s, bgx(4), bgy(4), gam(4), hm(3), p1, p2, wq, xi, eta, l2m
    integer :: e, g, ic, il, a

    l2m = blk%lam + 2.0_wp*blk%mu
    blk%q4 = 0.0_wp
    do e = 1, blk%nel
      ! relative to node 1: the sums below have zero-sum weights, and this
      ! keeps their round-off at the element's size, not its distance from 0
      do a = 1, 4
        xe(:, a) = x(:, blk%conn(a, e)) - x(:, blk%conn(1, e))
      end do
      ! eq. 6.2: x(xi, eta) = x0 + a xi + b eta + c xi eta, a = xi_c . x / 4, ...
      geo(1) = 0.25_wp*dot_product(xi_c, xe(1, :))
      geo(2) = 0.25_wp*dot_product(eta_c, xe(1, :))
      geo(3) = 0.25_wp*dot_product(hg_c, xe(1, :))
      geo(4) = 0.25_wp*dot_product(xi_c, xe(2, :))
      geo(5) = 0.25_wp*dot_product(eta_c, xe(2, :))
      geo(6) = 0.25_wp*dot_product(hg_c, xe(2, :))
      blk%geo(:, e) = geo
      do g = 1, blk%ngp
        detj = q4_detj(geo, blk%gxi(1, g), blk%gxi(2, g))
        if (.not. (detj > 0.0_wp)) then
          call raise_error(err, EXIT_INPUT, where // 'element ' // str(e) // ' (' // element_name(ELEM_Q4) // &
            ', block index) has detJ = ' // str(detj) // ' <= 0 at Gauss point ' // str(g) // &
            '; its nodes must be counter-clockwise and the element not degenerate')
          return
        end if
      end do
      associate (ax => geo(1), bx => geo(2), cx => geo(3), ay => geo(4), by => geo(5), cy => geo(6))
        ! mean gradient b = dN/dx at the centre (eq. 6.2); 4 detJ(0) = area A
        j4 = 4.0_wp*(ax*by - bx*ay)
        bgx(1) = (ay - by)/j4
        bgy(1) = (bx - ax)/j4
        bgx(2) = (ay + by)/j4
        bgy(2) = -(ax + bx)/j4
        bgx(3:4) = -bgx(1:2)
        bgy(3:4) = -bgy(1:2)
        ! hourglass vector (eq. 6.3): gamma = (h - (h . x) b_x - (h . y) b_y)/4
        gam = 0.25_wp*hg_c - cx*bgx - cy*bgy
        ! H_ij = sum_g w_g h detJ_g dh/dx_i dh/dx_j, dh/dx = p/detJ (eq. 6.4)
        hm = 0.0_wp
        do g = 1, blk%ngp
          xi = blk%gxi(1, g)
          eta = blk%gxi(2, g)
          p1 = eta*by - xi*ay
          p2 = xi*ax - eta*bx
          wq = blk%wts(g)*blk%thickness/q4_detj(geo, xi, eta)
          hm(1) = hm(1) + wq*p1*p1
          hm(2) = hm(2) + wq*p1*p2
          hm(3) = hm(3) + wq*p2*p2
        end do
      end associate
      s = sqrt(j4*blk%thickness)
      ic = (e - 1)/chunk_len + 1
      il = e - (ic - 1)*chunk_len
      blk%q4(il, q4_bx1, ic) = s*bgx(1)
      blk%q4(il, q4_bx2, ic) = s*bgx(2)
      blk%q4(il, q4_by1, ic) = s*bgy(1)
      blk%q4(il, q4_by2, ic) = s*bgy(2)
      blk%q4(il, q4_g1:q4_g1 + 3, ic) = gam
      ! hourglass stiffness (eq. 6.5)
      blk%q4(il, q4_m11, ic) = l2m*hm(1) + blk%mu*hm(3)
      blk%q4(il, q4_m12, ic) = (blk%lam + blk%mu)*hm(2)
      blk%q4(il, q4_m22, ic) = l2m*hm(3) + blk%mu*hm(1)
    end do
  end procedure init_q4_data

end submodule raccord_elastic_block_q4
