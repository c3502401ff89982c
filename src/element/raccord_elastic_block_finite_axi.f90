!> Axisymmetric blocks in finite strain (raccord_elastic_block;
!> doc/theory-axisymmetric.md, section "Finite strain and plasticity"): the
!> data of the kernel raccord_finite_axi_kernel (1/R_g and the hoop factor
!> of the stable-step estimate), the calls of the kernel for hyperelastic
!> and j2 blocks, and the nodal Cauchy stress or logarithmic strain with
!> the hoop component. The procedures the parent declares are defined here
!> with `module procedure`.
submodule (raccord_elastic_block) raccord_elastic_block_finite_axi
  use raccord_material, only: log_strain
  use raccord_finite_axi_kernel, only: kernel_finite_axi_q4, kernel_finite_axi_q8
  implicit none

contains

  !> 1/R_g = hoop/sqrt(c) at every Gauss point (make_axisymmetric's data)
  !> and each element's hoop factor: its exact eigenvalue bound at rest
  !> (element_eigenvalue_bounds: the hoop stiffness and the 2 pi r lumped
  !> masses, the axis nodes' radial dofs dropped) over the kernel's plane
  !> current-length estimate at rest, at least 1. The kernel multiplies its
  !> estimate by it at every monitored step, so that the variable step is
  !> the exact bound on the undeformed mesh and follows the deformation
  !> (lengths, wave modulus) from there.
  module procedure init_finite_axi
    character(len=*), parameter :: where = 'init_finite_axi: '
    real(wp), allocatable :: w2e(:), w2f(:)
    integer :: e, ic, il, stat
    character(len=256) :: msg
    allocate(blk%rr(chunk_len, blk%ngp, blk%nchunk), blk%hfac(chunk_len, blk%nchunk), w2e(blk%nel), &
      w2f(blk%nel), stat=stat, errmsg=msg)
    if (stat /= 0) then
      call raise_error(err, EXIT_INPUT, where // 'cannot allocate the data of ' // str(blk%nel) // &
        ' elements: ' // trim(msg) // '; use a smaller mesh or more memory')
      return
    end if
    ! padding lanes: F_tt = 1, never scattered
    blk%rr = 0.0_wp
    blk%hfac = 1.0_wp
    do e = 1, blk%nel
      ic = (e - 1)/chunk_len + 1
      il = e - (ic - 1)*chunk_len
      blk%rr(il, :, ic) = blk%hoop(il, :, ic)/sqrt(blk%c(:, e))
    end do
    call element_eigenvalue_bounds(blk, blk%density, w2e)
    call finite_axi_w2_elements(blk, w2f)
    do e = 1, blk%nel
      ic = (e - 1)/chunk_len + 1
      il = e - (ic - 1)*chunk_len
      blk%hfac(il, ic) = max(1.0_wp, w2e(e)/w2f(e))
    end do
  end procedure init_finite_axi

  module procedure finite_axi_chunk
    select case (blk%kernel)
    case (KERN_FINITE_AXI_Q4, KERN_J2_FINITE_AXI_Q4)
      call kernel_finite_axi_q4(nc, blk%material, blk%volumetric, blk%moduli, blk%j2, blk%nref, blk%dnref, &
        blk%pg(:, :, :, ic), blk%rr(:, :, ic), blk%cw(:, :, ic), blk%vol0(:, ic), blk%diag(:, :, ic), &
        blk%rinv(:, ic), blk%hfac(:, ic), mon, hist, ue, fe, sg, act, en, dis, jm, jel, w2)
    case default
      call kernel_finite_axi_q8(nc, blk%material, blk%volumetric, blk%moduli, blk%j2, blk%nref, blk%dnref, &
        blk%pg(:, :, :, ic), blk%rr(:, :, ic), blk%cw(:, :, ic), blk%vol0(:, ic), blk%diag(:, :, ic), &
        blk%rinv(:, ic), blk%hfac(:, ic), mon, hist, ue, fe, sg, act, en, dis, jm, jel, w2)
    end select
  end procedure finite_axi_chunk

  module procedure finite_axi_elastic_chunk
    real(wp) :: hist(chunk_len, nhist, max_gp), sg(chunk_len, 4, max_gp), act(chunk_len), dis
    ! (hist: not read by the hyperelastic laws)
    call finite_axi_chunk(blk, ic, nc, mon, hist, ue, fe, sg, act, en, dis, jm, jel, w2)
  end procedure finite_axi_elastic_chunk

  !> The kernel at u = 0 with 1/rho zero on every lane but one gives that
  !> lane's estimate (a j2 block at rest has the neo-Hooke one: K + 4G/3 in
  !> both), times the element's hoop factor (1 until init_finite_axi sets it).
  module procedure finite_axi_w2_elements
    real(wp) :: ue(chunk_len, 2, max_nen), fe(chunk_len, 2, max_nen), rl(chunk_len), en, dis, jm, w2c
    real(wp) :: hist(chunk_len, nhist, max_gp), sg(chunk_len, 4, max_gp), act(chunk_len)
    integer :: ic, e0, nc, l, jel, mat
    mat = merge(MAT_NEO_HOOKE, blk%material, blk%material == MAT_J2)
    ue = 0.0_wp
    hist = 0.0_wp
    do ic = 1, blk%nchunk
      e0 = (ic - 1)*chunk_len
      nc = min(chunk_len, blk%nel - e0)
      do l = 1, nc
        rl = 0.0_wp
        rl(l) = blk%rinv(l, ic)
        if (blk%etype == ELEM_Q4) then
          call kernel_finite_axi_q4(nc, mat, blk%volumetric, blk%moduli, blk%j2, blk%nref, blk%dnref, &
            blk%pg(:, :, :, ic), blk%rr(:, :, ic), blk%cw(:, :, ic), blk%vol0(:, ic), blk%diag(:, :, ic), &
            rl, blk%hfac(:, ic), .true., hist, ue, fe, sg, act, en, dis, jm, jel, w2c)
        else
          call kernel_finite_axi_q8(nc, mat, blk%volumetric, blk%moduli, blk%j2, blk%nref, blk%dnref, &
            blk%pg(:, :, :, ic), blk%rr(:, :, ic), blk%cw(:, :, ic), blk%vol0(:, ic), blk%diag(:, :, ic), &
            rl, blk%hfac(:, ic), .true., hist, ue, fe, sg, act, en, dis, jm, jel, w2c)
        end if
        w2(e0 + l) = w2c
      end do
    end do
  end procedure finite_axi_w2_elements

  !> Stress: the kernel's Cauchy stress at the Gauss points (hyperelastic
  !> blocks; j2 blocks take add_group_j2_stress). Strain: ln V in the r-z
  !> plane (log_strain of F_2) and ln F_tt. Both extrapolated to the nodes
  !> (theory eq. 7.1).
  module procedure add_group_finite_axi
    real(wp) :: ue(chunk_len, 2, max_nen), fe(chunk_len, 2, max_nen), sgp(chunk_len, 4, max_gp)
    real(wp) :: hist(chunk_len, nhist, max_gp), act(chunk_len), en, dis, jm, w2
    real(wp) :: d(4), ur, f2(4), e4(4)
    integer :: ic, e0, nc, i, a, g, node, jel, ngp
    ngp = blk%ngp
    hist = 0.0_wp
    do ic = (grp - 1)*blk%group_len + 1, min(grp*blk%group_len, blk%nchunk)
      e0 = (ic - 1)*chunk_len
      nc = min(chunk_len, blk%nel - e0)
      do a = 1, blk%nen
        do i = 1, nc
          node = blk%conn(a, e0 + i)
          ue(i, :, a) = u(:, node)
        end do
      end do
      if (strain) then
        do g = 1, ngp
          do i = 1, nc
            d = 0.0_wp
            ur = 0.0_wp
            do a = 1, blk%nen
              d = d + [ue(i, 1, a)*blk%dnref(1, a, g), ue(i, 1, a)*blk%dnref(2, a, g), &
                ue(i, 2, a)*blk%dnref(1, a, g), ue(i, 2, a)*blk%dnref(2, a, g)]
              ur = ur + ue(i, 1, a)*blk%nref(a, g)
            end do
            ! (FA-1) as the kernel: F_2 = I + d J0^-1, F_tt = 1 + u_r/R
            f2(1) = 1.0_wp + d(1)*blk%pg(i, 1, g, ic) + d(2)*blk%pg(i, 2, g, ic)
            f2(2) = d(3)*blk%pg(i, 1, g, ic) + d(4)*blk%pg(i, 2, g, ic)
            f2(3) = d(1)*blk%pg(i, 3, g, ic) + d(2)*blk%pg(i, 4, g, ic)
            f2(4) = 1.0_wp + d(3)*blk%pg(i, 3, g, ic) + d(4)*blk%pg(i, 4, g, ic)
            e4 = log_strain(f2)
            e4(4) = log(max(1.0_wp + ur*blk%rr(i, g, ic), tiny(1.0_wp)))
            sgp(i, :, g) = e4
          end do
        end do
      else
        call finite_axi_chunk(blk, ic, nc, .false., hist, ue, fe, sgp, act, en, dis, jm, jel, w2)
      end if
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
  end procedure add_group_finite_axi
end submodule raccord_elastic_block_finite_axi
