!> Finite-strain set-up and the per-chunk watch of the elastic blocks
!> (raccord_elastic_block; doc/theory-finite.md): the total Lagrangian data
!> J0^-1 and c per Gauss point, the block's kernel, and what the kernel
!> reports each step (stored energy, smallest J, stable-step estimate).
!> The procedures the parent declares are defined here with
!> `module procedure`.
submodule (raccord_elastic_block) raccord_elastic_block_finite
  use raccord_finite_kernel, only: q4h_row, q4h_col
  implicit none

contains

  !> Turn a block set up by init_elastic_block into a finite-strain block
  !> (total Lagrangian, doc/theory-finite.md) of the given material
  !> (MAT_NEO_HOOKE or MAT_SVK) and volumetric treatment (VOL_FULL or
  !> VOL_MEAN), reference density rho0. Plane strain only: plane stress is
  !> refused (EXIT_INPUT). The small-strain data stay: they give the initial
  !> stable step (at F = I both laws have Hooke's tangent).
  module procedure make_finite
    character(len=*), parameter :: where = 'make_finite: '
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
    call store_gauss_maps(blk, x, err)   ! Q8: H and c in place of the plane kernel's xn
    if (err%failed()) return
    blk%kernel = merge(KERN_FINITE_Q4, KERN_FINITE_Q8, blk%etype == ELEM_Q4)
    if (blk%axisymmetric) blk%kernel = merge(KERN_FINITE_AXI_Q4, KERN_FINITE_AXI_Q8, blk%etype == ELEM_Q4)
    call init_reference_data(blk, x, err)
    if (blk%axisymmetric .and. .not. err%failed()) call init_finite_axi(blk, err)
  end procedure make_finite

  !> The reference data of the finite-strain and j2 kernels: Q4 the exact
  !> gradient split (q4_split), Q8 J0^-1, and c, V_e and the corner
  !> diagonals of every element.
  module procedure init_reference_data
    character(len=*), parameter :: where = 'init_reference_data: '
    real(wp) :: pq4(4, 4)
    integer :: e, g, ic, il, stat
    character(len=256) :: msg
    real(wp) :: x1(2), x2(2), x3(2), x4(2)
    allocate(blk%pg(chunk_len, 4, blk%ngp, blk%nchunk), blk%cw(chunk_len, blk%ngp, blk%nchunk), &
      blk%vol0(chunk_len, blk%nchunk), &
      blk%diag(chunk_len, 4, blk%nchunk), blk%rinv(chunk_len, blk%nchunk), stat=stat, errmsg=msg)
    if (stat /= 0) then
      call raise_error(err, EXIT_INPUT, where // 'cannot allocate the data of ' // str(blk%nel) // &
        ' elements: ' // trim(msg) // '; use a smaller mesh or more memory')
      return
    end if
    ! padding lanes of the last chunk: a unit element, never scattered
    blk%pg = 0.0_wp
    if (blk%etype /= ELEM_Q4 .or. blk%axisymmetric) then
      blk%pg(:, 1, :, :) = 1.0_wp
      blk%pg(:, 4, :, :) = 1.0_wp
    end if
    blk%cw = 1.0_wp
    blk%rinv = 1.0_wp/blk%density
    blk%vol0 = 1.0_wp
    blk%diag = 1.0_wp
    do e = 1, blk%nel
      ic = (e - 1)/chunk_len + 1
      il = e - (ic - 1)*chunk_len
      ! (axisymmetric Q4: the Gauss-sum form, from make_axisymmetric's H and c)
      if (blk%etype == ELEM_Q4 .and. .not. blk%axisymmetric) then
        call q4_split(blk%geo(:, e), blk%gxi, pq4)
        blk%pg(il, :, :, ic) = pq4
        do g = 1, blk%ngp
          blk%cw(il, g, ic) = blk%wts(g)*blk%thickness*q4_detj(blk%geo(:, e), blk%gxi(1, g), blk%gxi(2, g))
        end do
      else
        do g = 1, blk%ngp
          ! J0^-1 = H / sqrt(c), c (init_gauss_maps, at init_elastic_block)
          blk%pg(il, :, g, ic) = blk%h(il, :, g, ic)/sqrt(blk%c(g, e))
          blk%cw(il, g, ic) = blk%c(g, e)
        end do
      end if
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
  end procedure init_reference_data

  !> The finite Q4 kernel's reference data of one element (Flanagan and
  !> Belytschko's exact split of the bilinear gradients, theory-elements.md
  !> eqs. 6.2-6.3): grad_X N_a = b_a + gamma_a grad_X h at any point, h = xi
  !> eta, b_a the gradient at the centre (b_3 = -b_1, b_4 = -b_2). pg(:, 1)
  !> = (b_x1, b_x2, b_y1, b_y2), pg(:, 2) = gamma_1..4, pg(:, 3) and pg(:, 4)
  !> = grad_X h at the Gauss points 1, 2 and 3, 4 (x, y each).
  pure subroutine q4_split(geo, gxi, pg)
    real(wp), intent(in) :: geo(ngeo), gxi(:,:)
    real(wp), intent(out) :: pg(4, 4)
    real(wp) :: j4, bgx(4), bgy(4), jac(2, 2), detj, xi, eta
    integer :: g
    associate (ax => geo(1), bx => geo(2), cx => geo(3), ay => geo(4), by => geo(5), cy => geo(6))
      j4 = 4.0_wp*(ax*by - bx*ay)
      bgx(1) = (ay - by)/j4
      bgy(1) = (bx - ax)/j4
      bgx(2) = (ay + by)/j4
      bgy(2) = -(ax + bx)/j4
      bgx(3:4) = -bgx(1:2)
      bgy(3:4) = -bgy(1:2)
      pg(:, 1) = [bgx(1), bgx(2), bgy(1), bgy(2)]
      pg(:, 2) = 0.25_wp*[1.0_wp, -1.0_wp, 1.0_wp, -1.0_wp] - cx*bgx - cy*bgy
      do g = 1, 4
        xi = gxi(1, g)
        eta = gxi(2, g)
        ! J_ik = dx_i/dxi_k of the map (eq. 6.2); grad_X h = J^-T (eta, xi)
        jac = reshape([ax + cx*eta, ay + cy*eta, bx + cx*xi, by + cy*xi], [2, 2])
        detj = jac(1, 1)*jac(2, 2) - jac(1, 2)*jac(2, 1)
        pg(q4h_row(g), q4h_col(g)) = (jac(2, 2)*eta - jac(2, 1)*xi)/detj
        pg(q4h_row(g) + 1, q4h_col(g)) = (jac(1, 1)*xi - jac(1, 2)*eta)/detj
      end do
    end associate
  end subroutine q4_split

  !> Element e of a finite-strain block gets the density scale(e) rho0 in
  !> the kernel's wave-speed estimate (the padding lanes keep 1/rho0).
  module procedure scale_element_density
    integer :: e
    if (blk%kinematics /= KIN_FINITE) return
    do e = 1, blk%nel
      blk%rinv(mod(e - 1, chunk_len) + 1, (e - 1)/chunk_len + 1) = 1.0_wp/(scale(e)*blk%density)
    end do
  end procedure scale_element_density

  !> The kernel's estimate at u = 0 for one element at a time: the chunk's
  !> kernel with 1/rho zero on every lane but one returns that lane's
  !> omega_e^2 (32 chunk evaluations per chunk, at the build only).
  module procedure finite_w2_elements
    real(wp) :: ue(chunk_len, 2, max_nen), fe(chunk_len, 2, max_nen), rl(chunk_len), en, jm, w2c
    integer :: ic, e0, nc, l, jel, mat
    w2 = 0.0_wp
    if (blk%kinematics /= KIN_FINITE) return
    if (blk%axisymmetric) then
      call finite_axi_w2_elements(blk, w2)
      return
    end if
    mat = merge(MAT_NEO_HOOKE, blk%material, blk%material == MAT_J2)
    ue = 0.0_wp
    do ic = 1, blk%nchunk
      e0 = (ic - 1)*chunk_len
      nc = min(chunk_len, blk%nel - e0)
      do l = 1, nc
        rl = 0.0_wp
        rl(l) = blk%rinv(l, ic)
        ! (a j2 block at rest has the neo-Hooke estimate: K + 4G/3 in both)
        if (blk%etype == ELEM_Q4) then
          call kernel_finite_q4(nc, mat, blk%volumetric, blk%moduli, blk%dnref, blk%pg(:, :, :, ic), &
            blk%cw(:, :, ic), blk%vol0(:, ic), blk%diag(:, :, ic), rl, blk%thickness, .true., ue, fe, en, jm, jel, w2c)
        else
          call kernel_finite_q8(nc, mat, blk%volumetric, blk%moduli, blk%dnref, blk%pg(:, :, :, ic), &
            blk%cw(:, :, ic), blk%vol0(:, ic), blk%diag(:, :, ic), rl, blk%thickness, .true., ue, fe, en, jm, jel, w2c)
        end if
        w2(e0 + l) = w2c
      end do
    end do
  end procedure finite_w2_elements

  !> Allocate a block's watch (one entry per chunk).
  module procedure init_watch
    allocate(watch%energy(blk%nchunk), watch%jmin(blk%nchunk), watch%w2(blk%nchunk), source=0.0_wp)
    allocate(watch%jmin_el(blk%nchunk), source=0)
    allocate(watch%dissip(blk%nchunk), source=0.0_wp)
    allocate(watch%active(chunk_len, blk%nchunk), source=.false.)
    watch%jmin = 1.0_wp
  end procedure init_watch

  !> The finite-strain block's omega^2 estimate on its undeformed mesh
  !> (the kernel's current-length estimate at u = 0), for the plan's step.
  module procedure finite_w2_at_rest
    real(wp), allocatable :: u(:,:), f(:,:)
    type(block_watch_t) :: watch
    type(block_plastic_t) :: plastic
    allocate(u(2, nnode), f(2, nnode), source=0.0_wp)
    call init_watch(blk, watch)
    if (blk%material == MAT_J2) then
      call init_plastic(blk, plastic)
      call add_internal_force(blk, u, f, watch=watch, monitor=.true., plastic=plastic)
    else
      call add_internal_force(blk, u, f, watch=watch, monitor=.true.)
    end if
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
