!> Element-level work of the elastic blocks, apart from the time loop's
!> chunked kernel (raccord_elastic_block): the Q4 map's Jacobian, the
!> element stiffness by Gauss sum (the reference the kernel is tested
!> against), the lumped mass, the body force, the element eigenvalue bound
!> of the stable step, and each element's share of the nodal stress
!> recovery (theory sections 1-5 and 7).
!> The procedures the parent declares (its interface block gives their
!> arguments) are defined here with `module procedure`.
submodule (raccord_elastic_block) raccord_elastic_block_element
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  use raccord_material, only: VOL_MEAN, neo_hooke_tau, neo_hooke_iso_tau, svk_tau, cauchy_from_tau, log_strain
  implicit none

  interface
    subroutine dsyev(jobz, uplo, n, a, lda, w, work, lwork, info)
      import :: wp
      character, intent(in) :: jobz, uplo
      integer, intent(in) :: n, lda, lwork
      real(wp), intent(inout) :: a(lda, *)
      real(wp), intent(out) :: w(*), work(*)
      integer, intent(out) :: info
    end subroutine dsyev
  end interface

contains

  !> detJ of the Q4 map at (xi, eta): j0 + j1 xi + j2 eta (eq. 6.2).
  module procedure q4_detj
    detj = (geo(1)*geo(5) - geo(2)*geo(4)) + xi*(geo(1)*geo(6) - geo(3)*geo(4)) + &
      eta*(geo(3)*geo(5) - geo(2)*geo(6))
  end procedure q4_detj

  !> Jacobian J_ik = dx_i/dxi_k of the Q4 map at (xi, eta) (eqs. 1.4, 6.2).
  pure function q4_jacobian(geo, xi, eta) result(jac)
    real(wp), intent(in) :: geo(ngeo), xi, eta
    real(wp) :: jac(2, 2)
    jac(1, 1) = geo(1) + geo(3)*eta
    jac(1, 2) = geo(2) + geo(3)*xi
    jac(2, 1) = geo(4) + geo(6)*eta
    jac(2, 2) = geo(5) + geo(6)*xi
  end function q4_jacobian

  !> Jacobian J_ik = dx_i/dxi_k of element e at Gauss point g of a plane
  !> small-strain Q8 block, from its coordinate copy xn (theory eq. 1.4),
  !> written as init_gauss_maps writes it (fixed-size xe, the same matmul),
  !> so that H and c rebuilt here have the bits they had when stored.
  pure function q8_jacobian(blk, e, g) result(jac)
    type(elastic_block_t), intent(in) :: blk
    integer, intent(in) :: e, g
    real(wp) :: jac(2, 2), xe(2, max_nen)
    integer :: a
    ! node by node (a vector-subscript section made a heap temporary at
    ! each call: two per Gauss point of a Q8 element in a frame's stress)
    do a = 1, blk%nen
      xe(:, a) = blk%xn(:, blk%conn(a, e))
    end do
    jac = matmul(xe(:, 1:blk%nen), transpose(blk%dnref(:, :, g)))
  end function q8_jacobian

  !> c = w_g detJ h of element e at Gauss point g.
  pure real(wp) function gauss_c(blk, e, g) result(cg)
    type(elastic_block_t), intent(in) :: blk
    integer, intent(in) :: e, g
    real(wp) :: jac(2, 2), detj
    if (blk%etype == ELEM_Q4 .and. .not. blk%axisymmetric) then
      cg = blk%wts(g)*blk%thickness*q4_detj(blk%geo(:, e), blk%gxi(1, g), blk%gxi(2, g))
    else if (blk%kernel == KERN_Q8) then
      jac = q8_jacobian(blk, e, g)
      detj = jac(1, 1)*jac(2, 2) - jac(1, 2)*jac(2, 1)
      cg = blk%wts(g)*detj*blk%thickness
    else
      cg = blk%c(g, e)
    end if
  end function gauss_c

  !> sqrt(c) dN_a/dx (row 1) and dN_a/dy (row 2) of element e at Gauss point g.
  pure subroutine scaled_gradients(blk, e, g, gr)
    type(elastic_block_t), intent(in) :: blk
    integer, intent(in) :: e, g
    real(wp), intent(out) :: gr(:,:)
    real(wp) :: h11, h21, h12, h22, jac(2, 2), detj, sq
    integer :: ic, il, a
    if ((blk%etype == ELEM_Q4 .and. .not. blk%axisymmetric) .or. blk%kernel == KERN_Q8) then
      ! H = sqrt(c) J^-1 from the map (eqs. 1.4, 6.2), as init_gauss_maps
      ! would store it for Q8
      if (blk%kernel == KERN_Q8) then
        jac = q8_jacobian(blk, e, g)
      else
        jac = q4_jacobian(blk%geo(:, e), blk%gxi(1, g), blk%gxi(2, g))
      end if
      detj = jac(1, 1)*jac(2, 2) - jac(1, 2)*jac(2, 1)
      sq = sqrt(blk%wts(g)*detj*blk%thickness)/detj
      h11 = sq*jac(2, 2)
      h21 = -sq*jac(2, 1)
      h12 = -sq*jac(1, 2)
      h22 = sq*jac(1, 1)
    else
      ic = (e - 1)/chunk_len + 1
      il = e - (ic - 1)*chunk_len
      h11 = blk%h(il, 1, g, ic)
      h21 = blk%h(il, 2, g, ic)
      h12 = blk%h(il, 3, g, ic)
      h22 = blk%h(il, 4, g, ic)
    end if
    do a = 1, blk%nen
      gr(1, a) = blk%dnref(1, a, g)*h11 + blk%dnref(2, a, g)*h21
      gr(2, a) = blk%dnref(1, a, g)*h12 + blk%dnref(2, a, g)*h22
    end do
  end subroutine scaled_gradients

  !> Element stiffness ke(2 nen, 2 nen) = sum_g c B^T C B (theory eq. 3.2),
  !> dof order (x1, y1, x2, y2, ...). For Q4 this is the Gauss sum itself,
  !> not the split the kernel uses, so the tests compare the two.
  module procedure element_stiffness
    real(wp) :: gr(2, max_nen), l2m
    integer :: g, a, b, nen
    nen = blk%nen
    l2m = blk%lam + 2.0_wp*blk%mu
    ke = 0.0_wp
    do g = 1, blk%ngp
      call scaled_gradients(blk, e, g, gr)
      do b = 1, nen
        do a = 1, nen
          ke(2*a - 1, 2*b - 1) = ke(2*a - 1, 2*b - 1) + l2m*gr(1, a)*gr(1, b) + blk%mu*gr(2, a)*gr(2, b)
          ke(2*a - 1, 2*b) = ke(2*a - 1, 2*b) + blk%lam*gr(1, a)*gr(2, b) + blk%mu*gr(2, a)*gr(1, b)
          ke(2*a, 2*b - 1) = ke(2*a, 2*b - 1) + blk%lam*gr(2, a)*gr(1, b) + blk%mu*gr(1, a)*gr(2, b)
          ke(2*a, 2*b) = ke(2*a, 2*b) + l2m*gr(2, a)*gr(2, b) + blk%mu*gr(1, a)*gr(1, b)
        end do
      end do
    end do
    if (blk%axisymmetric) call axi_hoop_stiffness(blk, e, ke)
  end procedure element_stiffness

  !> Lumped masses of element e (theory eq. 4.1-4.2): row sum of the
  !> consistent mass for Q4, HRZ diagonal scaling for Q8.
  pure subroutine element_lumped_mass(blk, e, density, me)
    type(elastic_block_t), intent(in) :: blk
    integer, intent(in) :: e
    real(wp), intent(in) :: density
    real(wp), intent(out) :: me(:)
    real(wp) :: total, dsum, cg
    integer :: g, nen
    nen = blk%nen
    me(1:nen) = 0.0_wp
    total = 0.0_wp
    do g = 1, blk%ngp
      cg = gauss_c(blk, e, g)
      total = total + density*cg
      if (blk%etype == ELEM_Q8) then
        me(1:nen) = me(1:nen) + density*cg*blk%nref(:, g)**2
      else
        me(1:nen) = me(1:nen) + density*cg*blk%nref(:, g)
      end if
    end do
    if (blk%etype == ELEM_Q8) then
      dsum = sum(me(1:nen))
      me(1:nen) = me(1:nen)*(total/dsum)
    end if
  end subroutine element_lumped_mass

  !> m(nnode) += lumped nodal masses (thickness included).
  module procedure add_lumped_mass
    real(wp) :: me(max_nen)
    integer :: e
    do e = 1, blk%nel
      if (present(scale)) then
        call element_lumped_mass(blk, e, scale(e)*density, me)
      else
        call element_lumped_mass(blk, e, density, me)
      end if
      m(blk%conn(:, e)) = m(blk%conn(:, e)) + me(1:blk%nen)
    end do
  end procedure add_lumped_mass

  !> f(2, nnode) += consistent nodal forces int N_a b dV of a constant force
  !> per unit volume b(2) (theory eq. 5.2).
  module procedure add_body_force
    integer :: e, g, a, node
    real(wp) :: cg
    do e = 1, blk%nel
      do g = 1, blk%ngp
        cg = gauss_c(blk, e, g)
        do a = 1, blk%nen
          node = blk%conn(a, e)
          f(:, node) = f(:, node) + blk%nref(a, g)*cg*b
        end do
      end do
    end do
  end procedure add_body_force

  !> Each element's eigenvalue lambda_max(Ke, Me) (theory eq. 4.3), whose
  !> largest bounds omega_max^2 of the assembled lumped system, from LAPACK
  !> dsyev on Me^-1/2 Ke Me^-1/2. Stable step: dt <= 2/sqrt(w2).
  !> Should dsyev fail, the element's Gershgorin bound (also an upper bound)
  !> is used instead.
  module procedure element_eigenvalue_bounds
    integer, parameter :: nmax = 2*max_nen, lwork = 8*nmax
    real(wp) :: ke(nmax, nmax), me(max_nen), s(nmax), ev(nmax), work(lwork)
    integer :: e, n, i, j, info
    n = 2*blk%nen
    do e = 1, blk%nel
      w2(e) = 0.0_wp
      call element_stiffness(blk, e, ke(1:n, 1:n))
      call element_lumped_mass(blk, e, density, me)
      if (blk%axisymmetric) call axi_drop_axis_dofs(blk, e, ke(1:n, 1:n))
      do i = 1, blk%nen
        s(2*i - 1:2*i) = 1.0_wp/sqrt(me(i))
      end do
      do j = 1, n
        do i = 1, n
          ke(i, j) = s(i)*ke(i, j)*s(j)
        end do
      end do
      call dsyev('N', 'U', n, ke, nmax, ev, work, lwork, info)
      if (info == 0) then
        w2(e) = ev(n)
      else
        ! dsyev destroyed the matrix: rebuild it for the Gershgorin bound
        call element_stiffness(blk, e, ke(1:n, 1:n))
        do i = 1, n
          w2(e) = max(w2(e), sum(abs(ke(i, 1:n))*s(1:n))*s(i))
        end do
      end if
    end do
  end procedure element_eigenvalue_bounds

  !> Upper bound of omega_max^2 of the assembled lumped system: the largest
  !> of the element bounds (element_eigenvalue_bounds).
  module procedure max_eigenvalue_bound
    real(wp), allocatable :: w2e(:)
    allocate(w2e(blk%nel))
    call element_eigenvalue_bounds(blk, density, w2e)
    w2 = 0.0_wp
    if (blk%nel > 0) w2 = maxval(w2e)
  end procedure max_eigenvalue_bound

  !> The displacements of element e's nodes, node by node: the section
  !> u(:, blk%conn(:, e)) made a heap temporary per element and frame.
  pure subroutine gather_element(blk, e, u, ue)
    type(elastic_block_t), intent(in) :: blk
    integer, intent(in) :: e
    real(wp), intent(in) :: u(:,:)
    real(wp), intent(out) :: ue(2, max_nen)
    integer :: a
    do a = 1, blk%nen
      ue(:, a) = u(:, blk%conn(a, e))
    end do
  end subroutine gather_element

  !> The Gauss-point values sg of element e extrapolated to its nodes
  !> (blk%extrap, theory eq. 7.1) and added to the nodal sums s, one count
  !> per node in wsum (add_nodal_stress averages them). Point by point, in
  !> the order matmul(sg(:, 1:ngp), blk%extrap(a, :)) summed, which made a
  !> heap temporary per node (1.2 million over Fig. 2(a)'s five frames).
  pure subroutine add_extrapolated(blk, e, sg, s, wsum)
    type(elastic_block_t), intent(in) :: blk
    integer, intent(in) :: e
    real(wp), intent(in) :: sg(4, max_gp)
    real(wp), intent(inout) :: s(:,:), wsum(:)
    real(wp) :: sa(4)
    integer :: a, g, node
    do a = 1, blk%nen
      node = blk%conn(a, e)
      sa = 0.0_wp
      do g = 1, blk%ngp
        sa = sa + sg(:, g)*blk%extrap(a, g)
      end do
      s(:, node) = s(:, node) + sa
      wsum(node) = wsum(node) + 1.0_wp
    end do
  end subroutine add_extrapolated

  !> The nodal stress contributions of element e (add_nodal_stress).
  module procedure add_element_stress
    real(wp) :: gr(2, max_nen), sg(4, max_gp), ue(2, max_nen), gu(2, 2), tr, rs
    integer :: g, nen
    nen = blk%nen
    call gather_element(blk, e, u, ue)
    do g = 1, blk%ngp
      call scaled_gradients(blk, e, g, gr)
      rs = 1.0_wp/sqrt(gauss_c(blk, e, g))
      ! grad u_ij = du_i/dx_j (theory eq. 3.1)
      gu = matmul(ue(:, 1:nen), transpose(gr(:, 1:nen)))*rs
      tr = blk%lam*(gu(1, 1) + gu(2, 2))
      sg(1, g) = tr + 2.0_wp*blk%mu*gu(1, 1)
      sg(2, g) = tr + 2.0_wp*blk%mu*gu(2, 2)
      sg(3, g) = blk%mu*(gu(1, 2) + gu(2, 1))
      if (blk%plane_stress) then
        sg(4, g) = 0.0_wp
      else
        sg(4, g) = blk%poisson*(sg(1, g) + sg(2, g))
      end if
    end do
    call add_extrapolated(blk, e, sg, s, wsum)
  end procedure add_element_stress

  !> The nodal contributions of finite-strain element e (add_nodal_stress):
  !> Cauchy stress sigma = tau/J (M-2, M-3) at each Gauss point, with the
  !> element's mean-dilatation pressure when the block uses it; with
  !> strain, the logarithmic strain ln(B)/2 instead.
  module procedure add_element_finite
    real(wp) :: gr(2, max_nen), sg(4, max_gp), ue(2, max_nen), gu(2, 2), rs, f(4, max_gp), detf(max_gp)
    real(wp) :: tau(4), tau33, jbar, vsum, cg, p
    integer :: g, nen
    nen = blk%nen
    call gather_element(blk, e, u, ue)
    jbar = 0.0_wp
    vsum = 0.0_wp
    do g = 1, blk%ngp
      call scaled_gradients(blk, e, g, gr)
      cg = gauss_c(blk, e, g)
      rs = 1.0_wp/sqrt(cg)
      ! grad_X u (F-1)
      gu = matmul(ue(:, 1:nen), transpose(gr(:, 1:nen)))*rs
      f(:, g) = [1.0_wp + gu(1, 1), gu(2, 1), gu(1, 2), 1.0_wp + gu(2, 2)]
      detf(g) = f(1, g)*f(4, g) - f(2, g)*f(3, g)
      jbar = jbar + detf(g)*cg
      vsum = vsum + cg
    end do
    jbar = jbar/vsum
    do g = 1, blk%ngp
      if (strain) then
        sg(:, g) = log_strain(f(:, g))
        cycle
      end if
      if (.not. (detf(g) > 0.0_wp)) then
        sg(:, g) = ieee_value(1.0_wp, ieee_quiet_nan)
        cycle
      end if
      if (blk%material == MAT_SVK) then
        call svk_tau(blk%moduli, f(:, g), tau, tau33)
      else if (blk%volumetric == VOL_MEAN) then
        call neo_hooke_iso_tau(blk%moduli, f(:, g), detf(g), tau, tau33)
        p = blk%moduli%k*(jbar - 1.0_wp)*detf(g)
        tau(1) = tau(1) + p
        tau(4) = tau(4) + p
        tau33 = tau33 + p
      else
        call neo_hooke_tau(blk%moduli, f(:, g), detf(g), tau, tau33)
      end if
      sg(:, g) = cauchy_from_tau(detf(g), tau, tau33)
    end do
    call add_extrapolated(blk, e, sg, s, wsum)
  end procedure add_element_finite

  !> The nodal small strain (exx, eyy, exy, ezz) of small-strain element e;
  !> ezz = -nu/(1-nu) (exx + eyy) in plane stress, 0 in plane strain.
  module procedure add_element_small_strain
    real(wp) :: gr(2, max_nen), sg(4, max_gp), ue(2, max_nen), gu(2, 2), rs
    integer :: g, nen
    nen = blk%nen
    call gather_element(blk, e, u, ue)
    do g = 1, blk%ngp
      call scaled_gradients(blk, e, g, gr)
      rs = 1.0_wp/sqrt(gauss_c(blk, e, g))
      gu = matmul(ue(:, 1:nen), transpose(gr(:, 1:nen)))*rs
      sg(1, g) = gu(1, 1)
      sg(2, g) = gu(2, 2)
      sg(3, g) = 0.5_wp*(gu(1, 2) + gu(2, 1))
      sg(4, g) = 0.0_wp
      if (blk%plane_stress) sg(4, g) = -blk%poisson/(1.0_wp - blk%poisson)*(gu(1, 1) + gu(2, 2))
    end do
    call add_extrapolated(blk, e, sg, s, wsum)
  end procedure add_element_small_strain

  !> H = sqrt(c) J^-1 and c = w detJ thickness at every Gauss point of a Q8
  !> block (theory eq. 6.1), if h and c are allocated (store_gauss_maps):
  !> J0^-1 = H/sqrt(c) of the finite and j2 Q8 kernels. A plane small-strain
  !> Q8 block stores neither (its kernel rebuilds J from the coordinates)
  !> and only checks detJ. Fails (EXIT_INPUT) on detJ <= 0, naming the
  !> element.
  module procedure init_gauss_maps
    character(len=*), parameter :: where = 'init_elastic_block: '
    real(wp) :: jac(2, 2), detj, cg, sq, xe(2, max_nen)
    integer :: e, g, ic, il
    logical :: store
    store = allocated(blk%h)
    if (store) blk%h = 0.0_wp
    do e = 1, blk%nel
      xe(:, 1:blk%nen) = x(:, blk%conn(:, e))
      ic = (e - 1)/chunk_len + 1
      il = e - (ic - 1)*chunk_len
      do g = 1, blk%ngp
        ! J_ik = dx_i/dxi_k (theory eq. 1.4)
        jac = matmul(xe(:, 1:blk%nen), transpose(blk%dnref(:, :, g)))
        detj = jac(1, 1)*jac(2, 2) - jac(1, 2)*jac(2, 1)
        if (.not. (detj > 0.0_wp)) then
          call raise_error(err, EXIT_INPUT, where // 'element ' // str(e) // ' (' // element_name(blk%etype) // &
            ', block index) has detJ = ' // str(detj) // ' <= 0 at Gauss point ' // str(g) // &
            '; its nodes must be counter-clockwise and the element not degenerate')
          return
        end if
        if (.not. store) cycle
        cg = blk%wts(g)*detj*blk%thickness
        blk%c(g, e) = cg
        sq = sqrt(cg)/detj
        ! H = sqrt(c) J^-1, stored column-major (H11, H21, H12, H22)
        blk%h(il, 1, g, ic) = sq*jac(2, 2)
        blk%h(il, 2, g, ic) = -sq*jac(2, 1)
        blk%h(il, 3, g, ic) = -sq*jac(1, 2)
        blk%h(il, 4, g, ic) = sq*jac(1, 1)
      end do
    end do
  end procedure init_gauss_maps

  !> H and c of a Q8 block that leaves the plane small-strain kernel.
  module procedure store_gauss_maps
    character(len=256) :: msg
    integer :: stat
    if (blk%etype /= ELEM_Q8) return
    if (.not. allocated(blk%h)) then
      allocate(blk%h(chunk_len, 4, blk%ngp, blk%nchunk), blk%c(blk%ngp, blk%nel), stat=stat, errmsg=msg)
      if (stat /= 0) then
        call raise_error(err, EXIT_INPUT, 'store_gauss_maps: cannot allocate the data of ' // str(blk%nel) // &
          ' elements: ' // trim(msg) // '; use a smaller mesh or more memory')
        return
      end if
      call init_gauss_maps(blk, x, err)
    end if
    if (allocated(blk%xn)) deallocate(blk%xn)
  end procedure store_gauss_maps
end submodule raccord_elastic_block_element
