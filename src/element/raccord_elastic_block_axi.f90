!> Axisymmetric blocks (doc/theory-axisymmetric.md; method brief
!> method-finite-plastic-axi.md section 9): set-up of the kernel data
!> (raccord_axi_kernel), the hoop terms of the element stiffness (element
!> eigenvalue bound of the stable step, tests), and the stress and strain
!> recovery with the hoop component.
!> Coordinates (r, z) = (x, y), r >= 0; strain (eps_rr, eps_zz, eps_tt,
!> gamma_rz), eps_tt = u_r/r; int (.) dV = sum_g (.) 2 pi r_g w_g detJ_g.
submodule (raccord_elastic_block) raccord_elastic_block_axi
  use raccord_kinds, only: pi
  use raccord_axi_kernel, only: axi_q4_data, naxq4, axi_q4_shift, put_axi_q4
  implicit none

contains

  !> Kernel data of an axisymmetric block: H = sqrt(c) J^-1, c = w detJ 2 pi r_g
  !> and the hoop factor sqrt(c)/r_g at every Gauss point (theory eq. A.3).
  !> The lumped mass, body force and stress recovery read c, so they carry
  !> 2 pi r too.
  module procedure make_axisymmetric
    character(len=*), parameter :: where = 'make_axisymmetric: '
    real(wp) :: jac(2, 2), detj, cg, sq, rg, xe(2, max_nen)
    integer :: e, g, ic, il, stat
    character(len=256) :: msg
    if (blk%kinematics /= KIN_SMALL .or. blk%plane_stress) then
      call raise_error(err, EXIT_INPUT, where // 'an axisymmetric block is small strain and not plane stress')
      return
    end if
    if (blk%etype == ELEM_Q4) then
      ! q4 holds the Q4 kernel's compact data (axi_q4_data); h, c and hoop
      ! serve the stiffness, the masses, the stress output and the j2 kernel
      ! (one chunk more: the kernel's chunks start q4_shift reals in, on a
      ! 64-byte boundary, performance.md "Axisymmetric kernels")
      if (allocated(blk%q4)) deallocate(blk%q4)
      allocate(blk%q4(chunk_len, naxq4, blk%nchunk + 1), blk%h(chunk_len, 4, blk%ngp, blk%nchunk), &
        blk%c(blk%ngp, blk%nel), stat=stat, errmsg=msg)
      if (stat == 0) then
        blk%q4 = 0.0_wp
        blk%q4_shift = axi_q4_shift(blk%q4)
      end if
    else
      ! Q8: H and c (the plane kernel kept the coordinates only)
      stat = 0
      if (.not. allocated(blk%h)) allocate(blk%h(chunk_len, 4, blk%ngp, blk%nchunk), blk%c(blk%ngp, blk%nel), &
        stat=stat, errmsg=msg)
    end if
    if (stat == 0) allocate(blk%hoop(chunk_len, blk%ngp, blk%nchunk), blk%on_axis(blk%nen, blk%nel), &
      stat=stat, errmsg=msg)
    if (stat /= 0) then
      call raise_error(err, EXIT_INPUT, where // 'cannot allocate the data of ' // str(blk%nel) // &
        ' elements: ' // trim(msg) // '; use a smaller mesh or more memory')
      return
    end if
    blk%axisymmetric = .true.
    blk%thickness = 1.0_wp
    blk%h = 0.0_wp
    blk%hoop = 0.0_wp
    do e = 1, blk%nel
      xe(:, 1:blk%nen) = x(:, blk%conn(:, e))
      blk%on_axis(:, e) = xe(1, 1:blk%nen) == 0.0_wp
      if (any(xe(1, 1:blk%nen) < 0.0_wp)) then
        call raise_error(err, EXIT_INPUT, where // 'element ' // str(e) // ' (' // element_name(blk%etype) // &
          ', block index) has a node at r = x < 0; an axisymmetric mesh lies in x >= 0 (x is the radius)')
        return
      end if
      ic = (e - 1)/chunk_len + 1
      il = e - (ic - 1)*chunk_len
      do g = 1, blk%ngp
        jac = matmul(xe(:, 1:blk%nen), transpose(blk%dnref(:, :, g)))
        detj = jac(1, 1)*jac(2, 2) - jac(1, 2)*jac(2, 1)
        rg = dot_product(blk%nref(:, g), xe(1, 1:blk%nen))
        if (.not. (detj > 0.0_wp)) then
          call raise_error(err, EXIT_INPUT, where // 'element ' // str(e) // ' (' // element_name(blk%etype) // &
            ', block index) has detJ = ' // str(detj) // ' <= 0 at Gauss point ' // str(g) // &
            '; its nodes must be counter-clockwise and the element not degenerate')
          return
        end if
        if (.not. (rg > 0.0_wp)) then
          call raise_error(err, EXIT_INPUT, where // 'element ' // str(e) // ' (' // element_name(blk%etype) // &
            ', block index) has a Gauss point at r = ' // str(rg) // ' <= 0; an axisymmetric element must ' // &
            'have an edge off the axis')
          return
        end if
        ! c = w detJ 2 pi r_g (method brief 9.1)
        cg = blk%wts(g)*detj*2.0_wp*pi*rg
        blk%c(g, e) = cg
        sq = sqrt(cg)/detj
        blk%h(il, 1, g, ic) = sq*jac(2, 2)
        blk%h(il, 2, g, ic) = -sq*jac(2, 1)
        blk%h(il, 3, g, ic) = -sq*jac(1, 2)
        blk%h(il, 4, g, ic) = sq*jac(1, 1)
        blk%hoop(il, g, ic) = sqrt(cg)/rg
      end do
      if (blk%etype == ELEM_Q4) call put_axi_q4(blk%q4(1 + blk%q4_shift, 1, ic), il, axi_q4_data(xe(:, 1:4)))
    end do
    blk%kernel = merge(KERN_AXI_Q4, KERN_AXI_Q8, blk%etype == ELEM_Q4)
    if (allocated(blk%xn)) deallocate(blk%xn)   ! the plane Q8 kernel's data
  end procedure make_axisymmetric

  !> sqrt(c) N_a/r_g of element e at Gauss point g (eps_tt row of B, scaled).
  pure subroutine scaled_hoop(blk, e, g, hp)
    type(elastic_block_t), intent(in) :: blk
    integer, intent(in) :: e, g
    real(wp), intent(out) :: hp(:)
    integer :: ic, il
    ic = (e - 1)/chunk_len + 1
    il = e - (ic - 1)*chunk_len
    hp(1:blk%nen) = blk%hoop(il, g, ic)*blk%nref(:, g)
  end subroutine scaled_hoop

  !> The hoop terms of K_e = sum_g c B^T D B: with the B row tt = N_a/r on
  !> u_r and the 3D moduli (lam + 2 mu on tt-tt, lam on tt-rr and tt-zz).
  module procedure axi_hoop_stiffness
    real(wp) :: gr(2, max_nen), hp(max_nen), l2m
    integer :: g, a, b
    l2m = blk%lam + 2.0_wp*blk%mu
    do g = 1, blk%ngp
      block
        ! scaled gradients as element_stiffness: H = sqrt(c) J^-1 stored
        integer :: ic, il
        ic = (e - 1)/chunk_len + 1
        il = e - (ic - 1)*chunk_len
        do a = 1, blk%nen
          gr(1, a) = blk%dnref(1, a, g)*blk%h(il, 1, g, ic) + blk%dnref(2, a, g)*blk%h(il, 2, g, ic)
          gr(2, a) = blk%dnref(1, a, g)*blk%h(il, 3, g, ic) + blk%dnref(2, a, g)*blk%h(il, 4, g, ic)
        end do
      end block
      call scaled_hoop(blk, e, g, hp)
      do b = 1, blk%nen
        do a = 1, blk%nen
          ke(2*a - 1, 2*b - 1) = ke(2*a - 1, 2*b - 1) + l2m*hp(a)*hp(b) + blk%lam*(hp(a)*gr(1, b) + gr(1, a)*hp(b))
          ke(2*a - 1, 2*b) = ke(2*a - 1, 2*b) + blk%lam*hp(a)*gr(2, b)
          ke(2*a, 2*b - 1) = ke(2*a, 2*b - 1) + blk%lam*gr(2, a)*hp(b)
        end do
      end do
    end do
  end procedure axi_hoop_stiffness

  !> Rows and columns of the radial dofs of the axis nodes set to zero.
  module procedure axi_drop_axis_dofs
    integer :: a
    do a = 1, blk%nen
      if (.not. blk%on_axis(a, e)) cycle
      ke(2*a - 1, :) = 0.0_wp
      ke(:, 2*a - 1) = 0.0_wp
    end do
  end procedure axi_drop_axis_dofs

  !> Stress (rr, zz, rz, tt) or strain of axisymmetric element e at its
  !> Gauss points, extrapolated to the nodes (theory eq. 7.1).
  module procedure add_element_axi
    real(wp) :: gr(2, max_nen), hp(max_nen), sg(4, max_gp), ue(2, max_nen), gu(2, 2), rs, ett, tr, mu2
    integer :: g, a, nen, ic, il
    nen = blk%nen
    mu2 = 2.0_wp*blk%mu
    ue(:, 1:nen) = u(:, blk%conn(:, e))
    ic = (e - 1)/chunk_len + 1
    il = e - (ic - 1)*chunk_len
    do g = 1, blk%ngp
      rs = 1.0_wp/sqrt(blk%c(g, e))
      do a = 1, nen
        gr(1, a) = blk%dnref(1, a, g)*blk%h(il, 1, g, ic) + blk%dnref(2, a, g)*blk%h(il, 2, g, ic)
        gr(2, a) = blk%dnref(1, a, g)*blk%h(il, 3, g, ic) + blk%dnref(2, a, g)*blk%h(il, 4, g, ic)
      end do
      call scaled_hoop(blk, e, g, hp)
      gu = matmul(ue(:, 1:nen), transpose(gr(:, 1:nen)))*rs
      ett = dot_product(hp(1:nen), ue(1, 1:nen))*rs
      if (strain) then
        sg(:, g) = [gu(1, 1), gu(2, 2), 0.5_wp*(gu(1, 2) + gu(2, 1)), ett]
      else
        tr = blk%lam*(gu(1, 1) + gu(2, 2) + ett)
        sg(:, g) = [tr + mu2*gu(1, 1), tr + mu2*gu(2, 2), blk%mu*(gu(1, 2) + gu(2, 1)), tr + mu2*ett]
      end if
    end do
    do a = 1, nen
      s(:, blk%conn(a, e)) = s(:, blk%conn(a, e)) + matmul(sg(:, 1:blk%ngp), blk%extrap(a, :))
      wsum(blk%conn(a, e)) = wsum(blk%conn(a, e)) + 1.0_wp
    end do
  end procedure add_element_axi
end submodule raccord_elastic_block_axi
