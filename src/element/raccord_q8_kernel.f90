!> Small-strain plane Q8 kernel by sum factorisation (doc/theory-elements.md,
!> eqs. 6.6-6.10; doc/performance.md "Q8 element step"): fe = K_e ue for a
!> chunk of Q8 elements, K_e = sum_g c B^T C B over the 3x3 Gauss rule
!> (eq. 3.2), the same K as the Gauss-point form of eq. 6.1 up to round-off.
!>
!> The serendipity field is the biquadratic (Q9) interpolant of the eight
!> nodal values and of the centre value
!>   u_c = (u_5 + u_6 + u_7 + u_8)/2 - (u_1 + u_2 + u_3 + u_4)/4     (eq. 6.6)
!> (the value for which the xi^2 eta^2 coefficient of the Q9 field
!> vanishes), so on the tensor 3x3 Gauss rule the natural gradient factorises
!> into 1D operators along eta and xi (eq. 6.7): with l_k the quadratic
!> Lagrange basis on the nodes -1, 0, 1 and the Gauss points -r, 0, r
!> (r = sqrt(3/5)),
!>   interpolation  b = B a:  b_1,3 = (r^2/2)(a_1 + a_3) + (1 - r^2) a_2 -+ (r/2)(a_3 - a_1),
!>                            b_2 = a_2
!>   derivative     d = D a:  d_1,3 = (a_3 - a_1)/2 -+ r (a_1 + a_3 - 2 a_2),
!>                            d_2 = (a_3 - a_1)/2,
!> du/dxi = D_xi B_eta U and du/deta = B_xi D_eta U (eq. 6.7). The nodal
!> forces use the transposes in reverse order (eq. 6.8), and the centre
!> force goes back to the nodes with the weights of eq. 6.6:
!> f_a += -F_c/4 (corners), +F_c/2 (mid-sides) (eq. 6.9).
!>
!> The geometry is not stored per element at all: gather_q8 reads the
!> element's node coordinates through the connectivity with u (less node
!> 1's), instead of the 36 reals of H = sqrt(c) J^-1 per element that were
!> the larger part of the bytes the step streamed at 1e5 elements; the
!> kernel applies the same gradient to them, and at each point (eq. 6.10),
!> with A = adj(J) = detJ J^-1,
!>   g = d A = detJ grad u,  t = (w_g h/detJ) C(sym g) A^T = c sigma J^-T,
!> f_a += t D_a, one division per point. Per element about 800 flops
!> (2 x 2 gradients of about 85, 9 points of about 30, 2 force
!> transposes of about 95) against about 770 for eq. 6.1's sums over the 8
!> nodes at each point, but 160 bytes fewer to stream, 6 constants instead
!> of the 144-entry derivative table, and the nodal values read and the
!> forces written once per element instead of once per point.
!>
!> Node order (raccord_shape): corners 1-4 at (-1,-1), (1,-1), (1,1),
!> (-1,1), mid-sides 5 (0,-1), 6 (1,0), 7 (0,1), 8 (-1,0); Gauss points
!> g = i + 3 (j - 1) at (xi, eta) = (p_i, p_j), p = (-r, 0, r).
module raccord_q8_kernel
  use raccord_kinds, only: wp
  use raccord_finite_kernel, only: fin_chunk_len
  implicit none
  private

  public :: kernel_q8, gather_q8, scatter_q8

  integer, parameter :: chunk_len = fin_chunk_len, max_nen = 8, ngp = 9

contains

  !> The chunk's nodal values ue and coordinates less node 1's xq (the
  !> kernel's geometry) of nc elements with nodes conn(:, 1:nc), from the
  !> displacements u(2, nnode) and the coordinates x(2, nnode), in one pass
  !> over conn. xq(:, :, a) = x_a - x_1 is the subtraction the block did once
  !> at set-up when it stored them, so the forces keep their bits. Scalar
  !> loads (novector): the 8-lane hardware gather of this CPU was slower
  !> than them here (doc/performance.md, "Q8 element step"). The node
  !> arrays are explicit-shape (2, *): with their leading extent known, a
  !> node's address is one scaled index instead of the multiplications by
  !> run-time strides an assumed-shape dummy costs per load
  !> (doc/performance.md, "Third pass").
  pure subroutine gather_q8(nc, conn, u, x, ue, xq)
    integer, intent(in) :: nc, conn(max_nen, nc)
    real(wp), intent(in) :: u(2, *), x(2, *)
    real(wp), intent(out) :: ue(chunk_len, 2, max_nen), xq(chunk_len, 2, max_nen)
    real(wp) :: x1, y1, x2, y2
    integer :: a, i, node, node2
    ! two elements at a time, element by element within the pair: node 1's
    ! coordinates stay in registers, each element's 8 node numbers are one
    ! contiguous read, and the two values stored one after the other fall in
    ! the same cache line, which lets the core commit them together
    !GCC$ novector
    do i = 1, nc - 1, 2
      node = conn(1, i)
      node2 = conn(1, i + 1)
      ue(i, 1, 1) = u(1, node)
      ue(i + 1, 1, 1) = u(1, node2)
      ue(i, 2, 1) = u(2, node)
      ue(i + 1, 2, 1) = u(2, node2)
      x1 = x(1, node)
      y1 = x(2, node)
      x2 = x(1, node2)
      y2 = x(2, node2)
      xq(i, 1, 1) = 0.0_wp
      xq(i + 1, 1, 1) = 0.0_wp
      xq(i, 2, 1) = 0.0_wp
      xq(i + 1, 2, 1) = 0.0_wp
      do a = 2, max_nen
        node = conn(a, i)
        node2 = conn(a, i + 1)
        ue(i, 1, a) = u(1, node)
        ue(i + 1, 1, a) = u(1, node2)
        ue(i, 2, a) = u(2, node)
        ue(i + 1, 2, a) = u(2, node2)
        xq(i, 1, a) = x(1, node) - x1
        xq(i + 1, 1, a) = x(1, node2) - x2
        xq(i, 2, a) = x(2, node) - y1
        xq(i + 1, 2, a) = x(2, node2) - y2
      end do
    end do
    if (mod(nc, 2) == 1) then
      node = conn(1, nc)
      ue(nc, 1, 1) = u(1, node)
      ue(nc, 2, 1) = u(2, node)
      x1 = x(1, node)
      y1 = x(2, node)
      xq(nc, 1, 1) = 0.0_wp
      xq(nc, 2, 1) = 0.0_wp
      do a = 2, max_nen
        node = conn(a, nc)
        ue(nc, 1, a) = u(1, node)
        ue(nc, 2, a) = u(2, node)
        xq(nc, 1, a) = x(1, node) - x1
        xq(nc, 2, a) = x(2, node) - y1
      end do
    end if
  end subroutine gather_q8

  !> f(:, conn(a, i)) += fe(i, :, a) for the chunk's nc elements, node by
  !> node in the order of the block's generic scatter (the same additions
  !> in the same order, so the same bits), with f explicit-shape (2, *)
  !> for the reason given at gather_q8.
  pure subroutine scatter_q8(nc, conn, fe, f)
    integer, intent(in) :: nc, conn(max_nen, nc)
    real(wp), intent(in) :: fe(chunk_len, 2, max_nen)
    real(wp), intent(inout) :: f(2, *)
    integer :: a, i, node
    do a = 1, max_nen
      do i = 1, nc
        node = conn(a, i)
        f(1, node) = f(1, node) + fe(i, 1, a)
        f(2, node) = f(2, node) + fe(i, 2, a)
      end do
    end do
  end subroutine scatter_q8

  !> fe = K_e ue for the first nc elements of a chunk (eqs. 6.6-6.10): r the
  !> positive 3-point Gauss abscissa of the block's rule, w its 3x3 weights,
  !> thick the thickness, xq(:, :, a) node a's coordinates less node 1's.
  !> Every loop runs across the chunk's elements in SIMD lanes with unit
  !> stride; the buffers are fixed-size locals (no allocation).
  pure subroutine kernel_q8(nc, lam, mu, r, w, thick, xq, ue, fe)
    integer, intent(in) :: nc
    real(wp), intent(in) :: lam, mu, r, w(ngp), thick, xq(chunk_len, 2, max_nen), ue(chunk_len, 2, max_nen)
    real(wp), intent(inout) :: fe(chunk_len, 2, max_nen)
    real(wp) :: dg(chunk_len, 4, ngp), jg(chunk_len, 4, ngp)
    real(wp) :: cb0, cb1, hr, mu2, q, wh
    real(wp) :: d11, d12, d21, d22, h11, h21, h12, h22, g11, g12, g21, g22, tr, s11, s22, s12
    integer :: i, k, g
    cb0 = 0.5_wp*r*r
    cb1 = 1.0_wp - r*r
    hr = 0.5_wp*r
    mu2 = 2.0_wp*mu
    ! the Jacobian J_ik = dx_i/dxi_k and the natural gradient d_ik = du_i/dxi_k
    ! at the points (eqs. 6.6-6.7)
    do k = 1, 2
      call q8_gradient(nc, k, r, cb0, cb1, hr, xq, jg)
      call q8_gradient(nc, k, r, cb0, cb1, hr, ue, dg)
    end do
    ! point stage (eq. 6.10): A = adj(J) = detJ J^-1, g = d A = detJ grad u,
    ! t = (w_g h/detJ) C(sym g) A^T = c sigma J^-T
    gauss: do g = 1, ngp
      wh = w(g)*thick
      do i = 1, nc
        d11 = dg(i, 1, g)
        d12 = dg(i, 2, g)
        d21 = dg(i, 3, g)
        d22 = dg(i, 4, g)
        ! adj(J), column-major: (J22, -J21, -J12, J11)
        h11 = jg(i, 4, g)
        h21 = -jg(i, 3, g)
        h12 = -jg(i, 2, g)
        h22 = jg(i, 1, g)
        q = wh/(h11*h22 - h12*h21)
        g11 = d11*h11 + d12*h21
        g12 = d11*h12 + d12*h22
        g21 = d21*h11 + d22*h21
        g22 = d21*h12 + d22*h22
        tr = lam*(g11 + g22)
        s11 = q*(tr + mu2*g11)
        s22 = q*(tr + mu2*g22)
        s12 = q*(mu*(g12 + g21))
        dg(i, 1, g) = s11*h11 + s12*h12
        dg(i, 2, g) = s11*h21 + s12*h22
        dg(i, 3, g) = s12*h11 + s22*h12
        dg(i, 4, g) = s12*h21 + s22*h22
      end do
    end do gauss
    do k = 1, 2
      call q8_force(nc, k, r, cb0, cb1, hr, dg, fe)
    end do
  end subroutine kernel_q8

    !> dg(:, 2k-1:2k, :) = natural gradient of displacement component k at
    !> the 9 Gauss points (eqs. 6.6-6.7).
    pure subroutine q8_gradient(nc, k, r, cb0, cb1, hr, ue, dg)
      integer, intent(in) :: nc, k
      real(wp), intent(in) :: r, cb0, cb1, hr, ue(chunk_len, 2, max_nen)
      real(wp), intent(inout) :: dg(chunk_len, 4, ngp)
      real(wp) :: u11, u21, u31, u12, u22, u32, u13, u23, u33
      real(wp) :: v11, v12, v13, v21, v22, v23, v31, v32, v33
      real(wp) :: w11, w12, w13, w21, w22, w23, w31, w32, w33
      real(wp) :: e, o, m, s, c
      integer :: i, kx, ky
      kx = 2*k - 1
      ky = 2*k
      do i = 1, nc
        ! tensor nodes u(kxi, keta), kxi, keta = 1, 2, 3 at -1, 0, 1
        u11 = ue(i, k, 1)
        u31 = ue(i, k, 2)
        u33 = ue(i, k, 3)
        u13 = ue(i, k, 4)
        u21 = ue(i, k, 5)
        u32 = ue(i, k, 6)
        u23 = ue(i, k, 7)
        u12 = ue(i, k, 8)
        ! centre (eq. 6.6)
        u22 = 0.5_wp*((u21 + u32) + (u23 + u12)) - 0.25_wp*((u11 + u31) + (u33 + u13))
        ! along eta on each column kxi: values v and derivatives w at the points
        e = u11 + u13
        o = u13 - u11
        m = cb0*e + cb1*u12
        s = hr*o
        v11 = m - s
        v12 = u12
        v13 = m + s
        w12 = 0.5_wp*o
        c = r*(e - 2.0_wp*u12)
        w11 = w12 - c
        w13 = w12 + c
        e = u21 + u23
        o = u23 - u21
        m = cb0*e + cb1*u22
        s = hr*o
        v21 = m - s
        v22 = u22
        v23 = m + s
        w22 = 0.5_wp*o
        c = r*(e - 2.0_wp*u22)
        w21 = w22 - c
        w23 = w22 + c
        e = u31 + u33
        o = u33 - u31
        m = cb0*e + cb1*u32
        s = hr*o
        v31 = m - s
        v32 = u32
        v33 = m + s
        w32 = 0.5_wp*o
        c = r*(e - 2.0_wp*u32)
        w31 = w32 - c
        w33 = w32 + c
        ! along xi on each row of points j: du/dxi = D v, du/deta = B w
        e = v11 + v31
        o = v31 - v11
        dg(i, kx, 2) = 0.5_wp*o
        c = r*(e - 2.0_wp*v21)
        dg(i, kx, 1) = 0.5_wp*o - c
        dg(i, kx, 3) = 0.5_wp*o + c
        e = w11 + w31
        o = w31 - w11
        m = cb0*e + cb1*w21
        s = hr*o
        dg(i, ky, 1) = m - s
        dg(i, ky, 2) = w21
        dg(i, ky, 3) = m + s
        e = v12 + v32
        o = v32 - v12
        dg(i, kx, 5) = 0.5_wp*o
        c = r*(e - 2.0_wp*v22)
        dg(i, kx, 4) = 0.5_wp*o - c
        dg(i, kx, 6) = 0.5_wp*o + c
        e = w12 + w32
        o = w32 - w12
        m = cb0*e + cb1*w22
        s = hr*o
        dg(i, ky, 4) = m - s
        dg(i, ky, 5) = w22
        dg(i, ky, 6) = m + s
        e = v13 + v33
        o = v33 - v13
        dg(i, kx, 8) = 0.5_wp*o
        c = r*(e - 2.0_wp*v23)
        dg(i, kx, 7) = 0.5_wp*o - c
        dg(i, kx, 9) = 0.5_wp*o + c
        e = w13 + w33
        o = w33 - w13
        m = cb0*e + cb1*w23
        s = hr*o
        dg(i, ky, 7) = m - s
        dg(i, ky, 8) = w23
        dg(i, ky, 9) = m + s
      end do
    end subroutine q8_gradient

    !> fe(:, k, :) = the nodal forces of component k from the point forces
    !> t_k1 (against d/dxi) and t_k2 (against d/deta) in dg (eqs. 6.8-6.9).
    pure subroutine q8_force(nc, k, r, cb0, cb1, hr, dg, fe)
      integer, intent(in) :: nc, k
      real(wp), intent(in) :: r, cb0, cb1, hr, dg(chunk_len, 4, ngp)
      real(wp), intent(inout) :: fe(chunk_len, 2, max_nen)
      real(wp) :: a11, a21, a31, a12, a22, a32, a13, a23, a33
      real(wp) :: b11, b21, b31, b12, b22, b32, b13, b23, b33
      real(wp) :: t1, t2, t3, p, q, m, fc, f11, f21, f31, f12, f32, f13, f23, f33
      integer :: i, kx, ky
      kx = 2*k - 1
      ky = 2*k
      do i = 1, nc
        ! along xi on each row of points j: a = D^T t_k1, b = B^T t_k2
        t1 = dg(i, kx, 1)
        t2 = dg(i, kx, 2)
        t3 = dg(i, kx, 3)
        p = r*(t3 - t1)
        q = 0.5_wp*((t1 + t3) + t2)
        a11 = p - q
        a21 = -2.0_wp*p
        a31 = p + q
        t1 = dg(i, ky, 1)
        t2 = dg(i, ky, 2)
        t3 = dg(i, ky, 3)
        p = hr*(t3 - t1)
        m = cb0*(t1 + t3)
        b11 = m - p
        b21 = cb1*(t1 + t3) + t2
        b31 = m + p
        t1 = dg(i, kx, 4)
        t2 = dg(i, kx, 5)
        t3 = dg(i, kx, 6)
        p = r*(t3 - t1)
        q = 0.5_wp*((t1 + t3) + t2)
        a12 = p - q
        a22 = -2.0_wp*p
        a32 = p + q
        t1 = dg(i, ky, 4)
        t2 = dg(i, ky, 5)
        t3 = dg(i, ky, 6)
        p = hr*(t3 - t1)
        m = cb0*(t1 + t3)
        b12 = m - p
        b22 = cb1*(t1 + t3) + t2
        b32 = m + p
        t1 = dg(i, kx, 7)
        t2 = dg(i, kx, 8)
        t3 = dg(i, kx, 9)
        p = r*(t3 - t1)
        q = 0.5_wp*((t1 + t3) + t2)
        a13 = p - q
        a23 = -2.0_wp*p
        a33 = p + q
        t1 = dg(i, ky, 7)
        t2 = dg(i, ky, 8)
        t3 = dg(i, ky, 9)
        p = hr*(t3 - t1)
        m = cb0*(t1 + t3)
        b13 = m - p
        b23 = cb1*(t1 + t3) + t2
        b33 = m + p
        ! along eta on each column kxi: F = B^T a + D^T b
        p = hr*(a13 - a11)
        m = cb0*(a11 + a13)
        f11 = m - p
        f12 = cb1*(a11 + a13) + a12
        f13 = m + p
        p = r*(b13 - b11)
        q = 0.5_wp*((b11 + b13) + b12)
        f11 = f11 + (p - q)
        f12 = f12 - 2.0_wp*p
        f13 = f13 + (p + q)
        p = hr*(a23 - a21)
        m = cb0*(a21 + a23)
        f21 = m - p
        fc = cb1*(a21 + a23) + a22
        f23 = m + p
        p = r*(b23 - b21)
        q = 0.5_wp*((b21 + b23) + b22)
        f21 = f21 + (p - q)
        fc = fc - 2.0_wp*p
        f23 = f23 + (p + q)
        p = hr*(a33 - a31)
        m = cb0*(a31 + a33)
        f31 = m - p
        f32 = cb1*(a31 + a33) + a32
        f33 = m + p
        p = r*(b33 - b31)
        q = 0.5_wp*((b31 + b33) + b32)
        f31 = f31 + (p - q)
        f32 = f32 - 2.0_wp*p
        f33 = f33 + (p + q)
        ! the centre force back to the nodes (eq. 6.9)
        fe(i, k, 1) = f11 - 0.25_wp*fc
        fe(i, k, 2) = f31 - 0.25_wp*fc
        fe(i, k, 3) = f33 - 0.25_wp*fc
        fe(i, k, 4) = f13 - 0.25_wp*fc
        fe(i, k, 5) = f21 + 0.5_wp*fc
        fe(i, k, 6) = f32 + 0.5_wp*fc
        fe(i, k, 7) = f23 + 0.5_wp*fc
        fe(i, k, 8) = f12 + 0.5_wp*fc
      end do
    end subroutine q8_force
end module raccord_q8_kernel
