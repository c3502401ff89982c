!> Finite-strain set-up and the per-chunk watch of the elastic blocks
!> (raccord_elastic_block; doc/theory-finite.md): the total Lagrangian data
!> J0^-1 and c per Gauss point, the block's kernel, and what the kernel
!> reports each step (stored energy, smallest J, stable-step estimate).
!> The procedures the parent declares are defined here with
!> `module procedure`.
submodule (raccord_elastic_block) raccord_elastic_block_finite
  implicit none

contains

  !> H = sqrt(c) J^-1 and c = w detJ thickness at every Gauss point (theory
  !> eq. 6.1), for the Q8 kernel and every finite-strain kernel. Fails
  !> (EXIT_INPUT) on detJ <= 0, naming the element.
  module procedure init_gauss_maps
    character(len=*), parameter :: where = 'init_elastic_block: '
    real(wp) :: jac(2, 2), detj, cg, sq, xe(2, max_nen)
    integer :: e, g, ic, il, stat
    character(len=256) :: msg
    if (.not. allocated(blk%h)) then
      allocate(blk%h(chunk_len, 4, blk%ngp, blk%nchunk), blk%c(blk%ngp, blk%nel), stat=stat, errmsg=msg)
      if (stat /= 0) then
        call raise_error(err, EXIT_INPUT, where // 'cannot allocate the data of ' // str(blk%nel) // &
          ' elements: ' // trim(msg) // '; use a smaller mesh or more memory')
        return
      end if
    end if
    blk%h = 0.0_wp
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

  !> Turn a block set up by init_elastic_block into a finite-strain block
  !> (total Lagrangian, doc/theory-finite.md) of the given material
  !> (MAT_NEO_HOOKE or MAT_SVK) and volumetric treatment (VOL_FULL or
  !> VOL_MEAN), reference density rho0. Plane strain only: plane stress is
  !> refused (EXIT_INPUT). The small-strain data stay: they give the initial
  !> stable step (at F = I both laws have Hooke's tangent).
  module procedure make_finite
    character(len=*), parameter :: where = 'make_finite: '
    integer :: e, g, ic, il, stat
    character(len=256) :: msg
    real(wp) :: x1(2), x2(2), x3(2), x4(2)
    if (blk%plane_stress) then
      call raise_error(err, EXIT_INPUT, where // 'finite strain is built for plane strain only; ' // &
        'use hypothesis = ''plane_strain'' or kinematics = ''small''')
      return
    end if
    if (material /= MAT_NEO_HOOKE .and. material /= MAT_SVK) then
      call raise_error(err, EXIT_INPUT, where // 'material ''' // material_name(material) // &
        ''' has no finite-strain law; use ''neo_hooke'' or ''svk''')
      return
    end if
    if (.not. (density > 0.0_wp)) then
      call raise_error(err, EXIT_INPUT, where // 'the density must be > 0, got ' // str(density))
      return
    end if
    blk%kinematics = KIN_FINITE
    blk%material = material
    blk%volumetric = volumetric
    blk%density = density
    blk%moduli = make_moduli(blk%young, blk%poisson)
    blk%kernel = merge(KERN_FINITE_Q4, KERN_FINITE_Q8, blk%etype == ELEM_Q4)
    if (.not. allocated(blk%h)) call init_gauss_maps(blk, x, err)
    if (err%failed()) return
    allocate(blk%jinv(chunk_len, 4, blk%ngp, blk%nchunk), blk%cw(chunk_len, blk%ngp, blk%nchunk), &
      blk%vol0(chunk_len, blk%nchunk), &
      blk%diag(chunk_len, 4, blk%nchunk), stat=stat, errmsg=msg)
    if (stat /= 0) then
      call raise_error(err, EXIT_INPUT, where // 'cannot allocate the data of ' // str(blk%nel) // &
        ' elements: ' // trim(msg) // '; use a smaller mesh or more memory')
      return
    end if
    ! padding lanes of the last chunk: a unit element, never scattered
    blk%jinv = 0.0_wp
    blk%jinv(:, 1, :, :) = 1.0_wp
    blk%jinv(:, 4, :, :) = 1.0_wp
    blk%cw = 1.0_wp
    blk%vol0 = 1.0_wp
    blk%diag = 1.0_wp
    do e = 1, blk%nel
      ic = (e - 1)/chunk_len + 1
      il = e - (ic - 1)*chunk_len
      do g = 1, blk%ngp
        ! J0^-1 = H / sqrt(c), c (init_gauss_maps)
        blk%jinv(il, :, g, ic) = blk%h(il, :, g, ic)/sqrt(blk%c(g, e))
        blk%cw(il, g, ic) = blk%c(g, e)
      end do
      ! V_e summed as the kernel sums the current volume (F-3), so that
      ! Jbar = 1 exactly at rest
      blk%vol0(il, ic) = 0.0_wp
      do g = 1, blk%ngp
        blk%vol0(il, ic) = blk%vol0(il, ic) + 1.0_wp*blk%cw(il, g, ic)
      end do
      ! corner diagonals (corners are the element's first four nodes)
      x1 = x(:, blk%conn(1, e))
      x2 = x(:, blk%conn(2, e))
      x3 = x(:, blk%conn(3, e))
      x4 = x(:, blk%conn(4, e))
      blk%diag(il, 1:2, ic) = x3 - x1
      blk%diag(il, 3:4, ic) = x4 - x2
    end do
  end procedure make_finite

  !> Allocate a block's watch (one entry per chunk).
  module procedure init_watch
    allocate(watch%energy(blk%nchunk), watch%jmin(blk%nchunk), watch%w2(blk%nchunk), source=0.0_wp)
    allocate(watch%jmin_el(blk%nchunk), source=0)
    watch%jmin = 1.0_wp
  end procedure init_watch

  !> The finite-strain block's omega^2 estimate on its undeformed mesh
  !> (the kernel's current-length estimate at u = 0), for the plan's step.
  module procedure finite_w2_at_rest
    real(wp), allocatable :: u(:,:), f(:,:)
    type(block_watch_t) :: watch
    allocate(u(2, nnode), f(2, nnode), source=0.0_wp)
    call init_watch(blk, watch)
    call add_internal_force(blk, u, f, watch=watch, monitor=.true.)
    w2 = watch_w2(watch)
  end procedure finite_w2_at_rest

  !> Stored energy of the block at the last forces, summed in chunk order.
  module procedure watch_energy
    integer :: k
    w = 0.0_wp
    do k = 1, size(watch%energy)
      w = w + watch%energy(k)
    end do
  end procedure watch_energy

  !> Largest omega^2 estimate of the block at the last monitored forces.
  module procedure watch_w2
    w2 = maxval(watch%w2)
  end procedure watch_w2

  !> The block's first inverted element (J <= 0 at a Gauss point) at the
  !> last forces, 0 if none; jmin its smallest J.
  module procedure watch_inverted
    integer :: k
    e = 0
    jmin = minval(watch%jmin)
    do k = 1, size(watch%jmin)
      if (watch%jmin(k) <= 0.0_wp) then
        e = (k - 1)*chunk_len + watch%jmin_el(k)
        return
      end if
    end do
  end procedure watch_inverted
end submodule raccord_elastic_block_finite
