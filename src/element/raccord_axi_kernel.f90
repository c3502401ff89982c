!> Small-strain axisymmetric kernels (doc/theory-axisymmetric.md; method
!> brief method-finite-plastic-axi.md section 9.1): fe = K_e ue for a chunk
!> of Q4 or Q8 elements in the (r, z) = (x, y) half-plane, Hooke's law,
!> full Gauss integration weighted by 2 pi r.
!>
!> Q8: per Gauss point g of each element the block keeps (raccord_elastic_block_axi)
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
!> Q4 keeps 11 reals per element instead (axi_q4_data, kernel_axi_q4).
!> Gauss points are interior, r_g > 0 for r >= 0 nodes: no division by 0.
module raccord_axi_kernel
  use raccord_kinds, only: wp, pi
  use raccord_finite_kernel, only: fin_chunk_len
  use, intrinsic :: iso_c_binding, only: c_loc, c_intptr_t
  implicit none
  private

  public :: kernel_axi_q4, kernel_axi_q8, axi_q4_data, axi_q4_shift, put_axi_q4

  integer, parameter :: chunk_len = fin_chunk_len, max_nen = 8
  !> Slots of the Q4 kernel data (axi_q4_data): the map's a, b, c of r and
  !> of z, the centre radius, 1/(detJ_g r_g) at the 4 Gauss points
  integer, parameter, public :: naxq4 = 11
  integer, parameter :: axq4_ar = 1, axq4_br = 2, axq4_cr = 3, axq4_az = 4, axq4_bz = 5, axq4_cz = 6, &
    axq4_r0 = 7, axq4_w1 = 8
  !> Q4 Gauss points in the block's order, g = i + 2 (j - 1) at (gx(i), gx(j))
  real(wp), parameter :: q = 0.577350269189625765_wp
  real(wp), parameter :: xg(4) = [-q, q, -q, q], eg(4) = [-q, -q, q, q]

contains

  !> The Q4 kernel's 11 reals per element (axq4_*, the slots of the
  !> block's q4 array): the map x(xi, eta) = (r, z) = x0 + a xi + b eta +
  !> c xi eta (a, b, c of r and of z; theory-axisymmetric.md A.2), the
  !> centre radius r0 = x0_r and, per Gauss point, 1/(detJ_g r_g). xe are
  !> the element's 4 corners, counter-clockwise.
  pure function axi_q4_data(xe) result(hq)
    real(wp), intent(in) :: xe(2, 4)
    real(wp) :: hq(naxq4)
    real(wp), parameter :: xic(4) = [-1.0_wp, 1.0_wp, 1.0_wp, -1.0_wp], etac(4) = [-1.0_wp, -1.0_wp, 1.0_wp, 1.0_wp]
    real(wp) :: d(2, 4), rg, dj
    integer :: a, g
    ! relative to node 1: zero-sum weights, round-off at the element's size
    do a = 1, 4
      d(:, a) = xe(:, a) - xe(:, 1)
    end do
    hq(axq4_ar) = 0.25_wp*dot_product(xic, d(1, :))
    hq(axq4_br) = 0.25_wp*dot_product(etac, d(1, :))
    hq(axq4_cr) = 0.25_wp*dot_product(xic*etac, d(1, :))
    hq(axq4_az) = 0.25_wp*dot_product(xic, d(2, :))
    hq(axq4_bz) = 0.25_wp*dot_product(etac, d(2, :))
    hq(axq4_cz) = 0.25_wp*dot_product(xic*etac, d(2, :))
    hq(axq4_r0) = 0.25_wp*sum(xe(1, :))
    do g = 1, 4
      call q4_point(hq, xg(g), eg(g), rg, dj)
      hq(axq4_w1 + g - 1) = 1.0_wp/(dj*rg)
    end do
  end function axi_q4_data

  !> How many reals into a (the block's q4 array) the Q4 kernel data start so
  !> that every chunk begins on a 64-byte boundary (0 to 7): the kernel
  !> loads 8 lanes at a time, and loads split across two cache lines cost
  !> it up to 1.8x (performance.md, "Axisymmetric kernels"). The chunk
  !> stride, chunk_len naxq4 reals, is a multiple of 64 bytes.
  integer function axi_q4_shift(a) result(shift)
    real(wp), intent(in), target :: a(*)
    integer(c_intptr_t) :: addr
    integer :: rem
    addr = transfer(c_loc(a(1)), addr)
    rem = int(modulo(addr, 64_c_intptr_t))
    shift = 0
    if (mod(rem, storage_size(a(1))/8) == 0) shift = mod(64 - rem, 64)/(storage_size(a(1))/8)
  end function axi_q4_shift

  !> Element il of a chunk's Q4 kernel data (the chunk passed by its first
  !> real, as the kernel receives it).
  pure subroutine put_axi_q4(hq, il, d)
    real(wp), intent(inout) :: hq(chunk_len, naxq4)
    integer, intent(in) :: il
    real(wp), intent(in) :: d(naxq4)
    hq(il, :) = d
  end subroutine put_axi_q4

  !> r_g and detJ_g of a Q4 from its map coefficients, as the kernel forms them.
  pure subroutine q4_point(hq, xi, eta, rg, dj)
    real(wp), intent(in) :: hq(naxq4), xi, eta
    real(wp), intent(out) :: rg, dj
    rg = hq(axq4_r0) + hq(axq4_ar)*xi + hq(axq4_br)*eta + hq(axq4_cr)*(xi*eta)
    dj = (hq(axq4_ar) + hq(axq4_cr)*eta)*(hq(axq4_bz) + hq(axq4_cz)*xi) - &
      (hq(axq4_br) + hq(axq4_cr)*xi)*(hq(axq4_az) + hq(axq4_cz)*eta)
  end subroutine q4_point

  !> fe = K_e ue for nc axisymmetric Q4 elements (2x2 Gauss), in the
  !> bilinear basis (1, xi, eta, xi eta): with N_a = (1 + xi_a xi)(1 + eta_a eta)/4
  !> the nodal values enter only through q_k = sum_a c_ak u_a, c_a = (1, xi_a,
  !> eta_a, xi_a eta_a), so that at a point
  !>   du/dxi = (q1 + eta q3)/4,  du/deta = (q2 + xi q3)/4,
  !>   u = (q0 + xi q1 + eta q2 + xi eta q3)/4,
  !> and the nodal forces are f_a = sum_k c_ak p_k/4 with p_k the Gauss sums of
  !> the stresses against the same basis (theory-axisymmetric.md A.2).
  !> The geometry is rebuilt at each point from the 11 stored reals
  !> (axi_q4_data): J from the map's a, b, c, r_g, detJ_g and the stored
  !> w = 1/(detJ_g r_g). With A = adj J = detJ J^-1 and c_g = 2 pi detJ r_g
  !> (w_g = 1), the strains are carried times detJ (no division):
  !>   detJ eps_in = (du/dxi) A,  detJ eps_tt = u_r (detJ/r) = u_r detJ^2 w,
  !>   f_a += 2 pi [(r/detJ) (detJ sigma_in) A^T D_a + (detJ sigma_tt) N_a e_r],
  !> r/detJ = r^2 w; the factors 1/4 and 2 pi fold into lam and mu (pi/8).
  !> The same K as the generic form (raccord_axi_kernel_body.inc, Q8's),
  !> tested against the Gauss-sum stiffness; 11 reals per element as the
  !> plane Q4 kernel (performance.md, "Axisymmetric kernels").
  pure subroutine kernel_axi_q4(nc, lam, mu, hq, ue, fe)
    integer, parameter :: ngp = 4
    integer, intent(in) :: nc
    real(wp), intent(in) :: lam, mu
    real(wp), intent(in) :: hq(chunk_len, naxq4), ue(chunk_len, 2, max_nen)
    real(wp), intent(inout) :: fe(chunk_len, 2, max_nen)
    real(wp) :: r0, r1, r2, r3, z1, z2, z3, pr0, pr1, pr2, pr3, pz1, pz2, pz3
    real(wp) :: ar, br, cr, az, bz, cz, x0, xe, xn, ye, yn, rg, dj, w, kp, ki
    real(wp) :: d11, d12, d21, d22, g11, g12, g21, g22, gtt, ur, tr, s11, s22, s12, stt
    real(wp) :: t11, t12, t21, t22, ht, lams, mus, mu2, xi, eta
    integer :: g, i
    lams = lam*(pi/8.0_wp)
    mus = mu*(pi/8.0_wp)
    mu2 = 2.0_wp*mus
    elements: do i = 1, nc
      ar = hq(i, axq4_ar)
      br = hq(i, axq4_br)
      cr = hq(i, axq4_cr)
      az = hq(i, axq4_az)
      bz = hq(i, axq4_bz)
      cz = hq(i, axq4_cz)
      x0 = hq(i, axq4_r0)
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
      ! unrolled, the points' xi and eta are constants and the element loop
      ! vectorises whole (without it gfortran keeps a point loop inside the
      ! vectorised element loop, measured 1.2-2x slower at 1e5 elements);
      ! other compilers ignore the directive
      !GCC$ unroll 4
      gauss: do g = 1, ngp
        xi = xg(g)
        eta = eg(g)
        ! J = [dr/dxi dr/deta; dz/dxi dz/deta] = [xe xn; ye yn], r_g, detJ_g
        xe = ar + cr*eta
        xn = br + cr*xi
        ye = az + cz*eta
        yn = bz + cz*xi
        rg = x0 + ar*xi + br*eta + cr*(xi*eta)
        dj = xe*yn - xn*ye
        w = hq(i, axq4_w1 + g - 1)
        kp = rg*rg*w
        ki = dj*dj*w
        ! 4 x the natural gradient and u_r at the point
        d11 = r1 + eta*r3
        d12 = r2 + xi*r3
        d21 = z1 + eta*z3
        d22 = z2 + xi*z3
        ur = r0 + xi*r1 + eta*r2 + (xi*eta)*r3
        ! 4 detJ times (eps_rr, du_r/dz, du_z/dr, eps_zz, eps_tt)
        g11 = d11*yn - d12*ye
        g12 = d12*xe - d11*xn
        g21 = d21*yn - d22*ye
        g22 = d22*xe - d21*xn
        gtt = ur*ki
        ! Hooke on (rr, zz, tt, rz); the in-plane part times r/detJ
        tr = lams*(g11 + g22 + gtt)
        s11 = kp*(tr + mu2*g11)
        s22 = kp*(tr + mu2*g22)
        stt = tr + mu2*gtt
        s12 = kp*(mus*(g12 + g21))
        t11 = s11*yn - s12*xn
        t12 = s12*xe - s11*ye
        t21 = s12*yn - s22*xn
        t22 = s22*xe - s12*ye
        ht = stt
        ! Gauss sums against the basis (f_a = sum_k c_ak p_k)
        pr0 = pr0 + ht
        pr1 = pr1 + t11 + ht*xi
        pr2 = pr2 + t12 + ht*eta
        pr3 = pr3 + t11*eta + t12*xi + ht*(xi*eta)
        pz1 = pz1 + t21
        pz2 = pz2 + t22
        pz3 = pz3 + t21*eta + t22*xi
      end do gauss
      ! c_a = (1, xi_a, eta_a, xi_a eta_a) at the corners (-1,-1), (1,-1), (1,1), (-1,1)
      fe(i, 1, 1) = pr0 - pr1 - pr2 + pr3
      fe(i, 1, 2) = pr0 + pr1 - pr2 - pr3
      fe(i, 1, 3) = pr0 + pr1 + pr2 + pr3
      fe(i, 1, 4) = pr0 - pr1 + pr2 - pr3
      fe(i, 2, 1) = -pz1 - pz2 + pz3
      fe(i, 2, 2) = pz1 - pz2 - pz3
      fe(i, 2, 3) = pz1 + pz2 + pz3
      fe(i, 2, 4) = -pz1 + pz2 - pz3
    end do elements
  end subroutine kernel_axi_q4

  !> fe = K_e ue for nc axisymmetric Q8 elements (3x3 Gauss).
  pure subroutine kernel_axi_q8(nc, lam, mu, nref, dn, h, hoop, ue, fe)
    integer, parameter :: nen = 8, ngp = 9
    include 'raccord_axi_kernel_body.inc'
  end subroutine kernel_axi_q8
end module raccord_axi_kernel
