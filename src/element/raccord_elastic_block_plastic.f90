!> J2 elastoplastic blocks (raccord_elastic_block; doc/theory-plasticity.md):
!> the set-up of the block's kernel, its internal variables, the plastic
!> work the kernel reports and the plastic outputs. The procedures the
!> parent declares are defined here with `module procedure`.
submodule (raccord_elastic_block) raccord_elastic_block_plastic
  use raccord_plasticity, only: j2_initial_history, h_ebar
  use raccord_plastic_kernel, only: kernel_j2_small_q4, kernel_j2_small_q8, kernel_j2_finite_q4, kernel_j2_finite_q8, &
    kernel_j2_axi_q4, kernel_j2_axi_q8
  implicit none

contains

  !> Turn a block into a J2 block: the kernel of its kinematics and element
  !> type, and the reference data it shares with the finite-strain kernels.
  module procedure make_plastic
    character(len=*), parameter :: where = 'make_plastic: '
    if (blk%plane_stress) then
      call raise_error(err, EXIT_INPUT, where // 'J2 plasticity is built for plane strain only; ' // &
        'use hypothesis = ''plane_strain''')
      return
    end if
    if (.not. (j2%yield0 > 0.0_wp) .or. .not. (j2%hardening >= 0.0_wp)) then
      call raise_error(err, EXIT_INPUT, where // 'the yield stress must be > 0 and the hardening >= 0, got ' // &
        str(j2%yield0) // ' and ' // str(j2%hardening))
      return
    end if
    if (.not. (density > 0.0_wp)) then
      call raise_error(err, EXIT_INPUT, where // 'the density must be > 0, got ' // str(density))
      return
    end if
    call store_gauss_maps(blk, x, err)   ! Q8: H and c in place of the plane kernel's xn
    if (err%failed()) return
    blk%kinematics = kinematics
    blk%material = MAT_J2
    blk%volumetric = volumetric
    blk%density = density
    blk%j2 = j2
    blk%moduli = make_moduli(blk%young, blk%poisson)
    if (blk%axisymmetric) then
      ! on the axisymmetric block's data (make_axisymmetric, called before):
      ! H = sqrt(c) J^-1, the hoop factor, and c = w detJ 2 pi r_g here
      ! in chunk layout with V_e = sum_g c
      if (kinematics == KIN_FINITE) then
        ! finite strain: the axisymmetric finite kernel (raccord_finite_axi_kernel)
        blk%kernel = merge(KERN_J2_FINITE_AXI_Q4, KERN_J2_FINITE_AXI_Q8, blk%etype == ELEM_Q4)
        call init_reference_data(blk, x, err)
        if (.not. err%failed()) call init_finite_axi(blk, err)
        return
      end if
      blk%kernel = merge(KERN_J2_AXI_Q4, KERN_J2_AXI_Q8, blk%etype == ELEM_Q4)
      call axi_weights(blk)
    else if (kinematics == KIN_FINITE) then
      blk%kernel = merge(KERN_J2_FINITE_Q4, KERN_J2_FINITE_Q8, blk%etype == ELEM_Q4)
      call init_reference_data(blk, x, err)
    else
      blk%kernel = merge(KERN_J2_SMALL_Q4, KERN_J2_SMALL_Q8, blk%etype == ELEM_Q4)
      call init_reference_data(blk, x, err)
    end if
  contains
    !> c and V_e of an axisymmetric block in the kernels' chunk layout
    !> (padding lanes: c = 1, never scattered).
    subroutine axi_weights(b)
      type(elastic_block_t), intent(inout) :: b
      integer :: e, ic, il
      allocate(b%cw(chunk_len, b%ngp, b%nchunk), b%vol0(chunk_len, b%nchunk))
      b%cw = 1.0_wp
      b%vol0 = real(b%ngp, wp)
      do e = 1, b%nel
        ic = (e - 1)/chunk_len + 1
        il = e - (ic - 1)*chunk_len
        b%cw(il, :, ic) = b%c(:, e)
        b%vol0(il, ic) = sum(b%c(:, e))
      end do
    end subroutine axi_weights
  end procedure make_plastic

  !> A virgin block: eps_p = 0 or Cp^-1 = I, ebar = 0 at every point.
  module procedure init_plastic
    real(wp) :: h0(nhist)
    integer :: v
    allocate(plastic%h(chunk_len, nhist, blk%ngp, blk%nchunk))
    h0 = j2_initial_history(blk%kinematics == KIN_FINITE)
    do v = 1, nhist
      plastic%h(:, v, :, :) = h0(v)
    end do
    allocate(plastic%virgin(blk%nchunk))
    ! only the small-strain plane kernels use the flag (elsewhere .false.)
    plastic%track = blk%kernel == KERN_J2_SMALL_Q4 .or. blk%kernel == KERN_J2_SMALL_Q8
    call settle_plastic(plastic)
  end procedure init_plastic

  module procedure settle_plastic
    integer :: ic
    do ic = 1, size(plastic%virgin)
      plastic%virgin(ic) = plastic%track .and. all(plastic%h(:, :, :, ic) == 0.0_wp)
    end do
  end procedure settle_plastic

  module procedure watch_dissipation
    integer :: k
    w = 0.0_wp
    if (.not. allocated(watch%dissip)) return
    do k = 1, size(watch%dissip)
      w = w + watch%dissip(k)
    end do
  end procedure watch_dissipation

  module procedure add_nodal_plastic
    integer :: e, ic, il, a, node
    real(wp) :: eb, act
    do e = 1, blk%nel
      ic = (e - 1)/chunk_len + 1
      il = e - (ic - 1)*chunk_len
      eb = sum(plastic%h(il, h_ebar, :, ic))/real(blk%ngp, wp)
      act = merge(1.0_wp, 0.0_wp, watch%active(il, ic))
      do a = 1, blk%nen
        node = blk%conn(a, e)
        s(1, node) = s(1, node) + eb
        y(1, node) = y(1, node) + act
        wsum(node) = wsum(node) + 1.0_wp
      end do
    end do
  end procedure add_nodal_plastic

  !> The block's J2 kernel on one chunk, chosen once per chunk from the
  !> kernel fixed at make_plastic; the one place that calls the J2 kernels
  !> (the time loop's forces and the stress output).
  module procedure j2_chunk
    logical :: mean
    mean = blk%volumetric == VOL_MEAN
    jm = 1.0_wp
    jel = 0
    w2 = 0.0_wp
    select case (blk%kernel)
    case (KERN_J2_SMALL_Q4)
      call kernel_j2_small_q4(nc, blk%moduli, blk%j2, mean, blk%dnref, blk%pg(:, :, :, ic), blk%cw(:, :, ic), &
        blk%vol0(:, ic), blk%diag(:, :, ic), blk%rinv(:, ic), blk%thickness, mon, hist, virgin, ue, fe, sg, act, en, dis, &
        jm, jel, w2)
    case (KERN_J2_SMALL_Q8)
      call kernel_j2_small_q8(nc, blk%moduli, blk%j2, mean, blk%dnref, blk%pg(:, :, :, ic), blk%cw(:, :, ic), &
        blk%vol0(:, ic), blk%diag(:, :, ic), blk%rinv(:, ic), blk%thickness, mon, hist, virgin, ue, fe, sg, act, en, dis, &
        jm, jel, w2)
    case (KERN_J2_FINITE_Q4)
      call kernel_j2_finite_q4(nc, blk%moduli, blk%j2, mean, blk%dnref, blk%pg(:, :, :, ic), blk%cw(:, :, ic), &
        blk%vol0(:, ic), blk%diag(:, :, ic), blk%rinv(:, ic), blk%thickness, mon, hist, virgin, ue, fe, sg, act, en, dis, &
        jm, jel, w2)
    case (KERN_J2_FINITE_Q8)
      call kernel_j2_finite_q8(nc, blk%moduli, blk%j2, mean, blk%dnref, blk%pg(:, :, :, ic), blk%cw(:, :, ic), &
        blk%vol0(:, ic), blk%diag(:, :, ic), blk%rinv(:, ic), blk%thickness, mon, hist, virgin, ue, fe, sg, act, en, dis, &
        jm, jel, w2)
    case (KERN_J2_AXI_Q4)
      call kernel_j2_axi_q4(nc, blk%moduli, blk%j2, mean, blk%nref, blk%dnref, blk%h(:, :, :, ic), &
        blk%hoop(:, :, ic), blk%cw(:, :, ic), blk%vol0(:, ic), hist, ue, fe, sg, act, en, dis)
    case (KERN_J2_AXI_Q8)
      call kernel_j2_axi_q8(nc, blk%moduli, blk%j2, mean, blk%nref, blk%dnref, blk%h(:, :, :, ic), &
        blk%hoop(:, :, ic), blk%cw(:, :, ic), blk%vol0(:, ic), hist, ue, fe, sg, act, en, dis)
    case (KERN_J2_FINITE_AXI_Q4, KERN_J2_FINITE_AXI_Q8)
      call finite_axi_chunk(blk, ic, nc, mon, hist, ue, fe, sg, act, en, dis, jm, jel, w2)
    end select
  end procedure j2_chunk

  !> The group's chunks through the kernel (on a copy of their internal
  !> variables, so the run's state is untouched), then each element's
  !> Gauss-point stresses extrapolated to its nodes (theory eq. 7.1).
  module procedure add_group_j2_stress
    real(wp) :: ue(chunk_len, 2, max_nen), fe(chunk_len, 2, max_nen), sgp(chunk_len, 4, max_gp)
    real(wp) :: hist(chunk_len, nhist, max_gp), act(chunk_len), en, dis, jm, w2
    integer :: ic, e0, nc, i, a, g, node, jel, ngp
    logical :: virgin
    ngp = blk%ngp
    do ic = (grp - 1)*blk%group_len + 1, min(grp*blk%group_len, blk%nchunk)
      e0 = (ic - 1)*chunk_len
      nc = min(chunk_len, blk%nel - e0)
      do a = 1, blk%nen
        do i = 1, nc
          node = blk%conn(a, e0 + i)
          ue(i, :, a) = u(:, node)
        end do
      end do
      hist(:, :, 1:ngp) = plastic%h(:, :, :, ic)
      virgin = plastic%virgin(ic)
      call j2_chunk(blk, ic, nc, .false., hist, virgin, ue, fe, sgp, act, en, dis, jm, jel, w2)
      ! sgp holds the points in the kernel's layout (chunk_len, 4, ngp),
      ! read in place (a reshaped copy made a heap temporary per chunk)
      do i = 1, nc
        do a = 1, blk%nen
          node = blk%conn(a, e0 + i)
          do g = 1, ngp
            s(:, node) = s(:, node) + blk%extrap(a, g)*sgp(i, :, g)
          end do
          wsum(node) = wsum(node) + 1.0_wp
        end do
      end do
    end do
  end procedure add_group_j2_stress
end submodule raccord_elastic_block_plastic
