!> Setting up an elastic block (raccord_elastic_block's init_elastic_block):
!> the input checks, the reference element and Gauss rule, the stress
!> extrapolation, the colouring of the chunk groups and their first
!> touches, and the element data of the block's kernel (init_q4_data for
!> Q4, init_gauss_maps for Q8). Set-up only: nothing here runs in the time
!> loop. The interface is the parent's; the procedure is defined here with
!> `module procedure`.
submodule (raccord_elastic_block) raccord_elastic_block_init
  implicit none

contains

  !> Set up a block (the parent's interface says what and which errors).
  module procedure init_elastic_block
    character(len=*), parameter :: where = 'init_elastic_block: '
    integer :: nen, n1, ngp, i, j, g, a, stat
    real(wp) :: gx(3), gw(3), nat(2), lag(3, 2)
    character(len=256) :: msg

    nen = nodes_per_element(etype)
    if (nen == 0) then
      call raise_error(err, EXIT_INPUT, where // 'unknown element type ' // str(etype) // &
        '; use ELEM_Q4 or ELEM_Q8')
      return
    end if
    if (size(conn, 1) /= nen) then
      call raise_error(err, EXIT_INPUT, where // 'connectivity has ' // str(size(conn, 1)) // &
        ' rows, a ' // element_name(etype) // ' element needs ' // str(nen))
      return
    end if
    if (size(x, 1) /= 2) then
      call raise_error(err, EXIT_INPUT, where // 'coordinates must be x(2, nnode)')
      return
    end if
    if (any(conn < 1) .or. any(conn > size(x, 2))) then
      call raise_error(err, EXIT_INPUT, where // 'connectivity refers to a node outside 1..' // &
        str(size(x, 2)) // '; check the mesh and the node numbering')
      return
    end if
    if (.not. (young > 0.0_wp)) then
      call raise_error(err, EXIT_INPUT, where // 'Young''s modulus must be > 0, got ' // str(young))
      return
    end if
    if (.not. (poisson > -1.0_wp .and. poisson < 0.5_wp)) then
      call raise_error(err, EXIT_INPUT, where // 'Poisson''s ratio must lie in (-1, 0.5), got ' // str(poisson))
      return
    end if
    if (.not. (thickness > 0.0_wp)) then
      call raise_error(err, EXIT_INPUT, where // 'thickness must be > 0, got ' // str(thickness))
      return
    end if

    blk%etype = etype
    blk%nen = nen
    blk%nel = size(conn, 2)
    blk%young = young
    blk%poisson = poisson
    blk%thickness = thickness
    blk%plane_stress = plane_stress
    ! Lame constants (theory eq. 3.1); plane stress condenses sigma_zz = 0
    blk%mu = young/(2.0_wp*(1.0_wp + poisson))
    blk%lam = young*poisson/((1.0_wp + poisson)*(1.0_wp - 2.0_wp*poisson))
    if (plane_stress) blk%lam = 2.0_wp*blk%lam*blk%mu/(blk%lam + 2.0_wp*blk%mu)

    n1 = 2
    if (etype == ELEM_Q8) n1 = 3
    ngp = n1*n1
    blk%ngp = ngp
    blk%nchunk = (blk%nel + chunk_len - 1)/chunk_len
    call gauss_legendre(n1, gx(1:n1), gw(1:n1))

    allocate(blk%conn(nen, blk%nel), blk%wts(ngp), blk%nref(nen, ngp), blk%dnref(2, nen, ngp), &
      blk%extrap(nen, ngp), blk%gxi(2, ngp), stat=stat, errmsg=msg)
    if (stat == 0) then
      if (etype == ELEM_Q4) then
        allocate(blk%q4(chunk_len, nq4, blk%nchunk), blk%geo(ngeo, blk%nel), stat=stat, errmsg=msg)
      else
        ! (the nodes up to the block's highest: a model's blocks each keep
        ! their own copy)
        allocate(blk%xn, source=x(:, 1:maxval(conn)), stat=stat, errmsg=msg)
      end if
    end if
    if (stat /= 0) then
      call raise_error(err, EXIT_INPUT, where // 'cannot allocate the data of ' // str(blk%nel) // &
        ' elements: ' // trim(msg) // '; use a smaller mesh or more memory')
      return
    end if
    blk%conn = conn
    blk%group_len = max(1, min(max_group, blk%nchunk/group_divisor))
    call colour_chunks(blk%conn, size(x, 2), chunk_len*blk%group_len, blk%colour_ptr, blk%colour_group, err)
    if (err%failed()) return
    blk%ncolour = size(blk%colour_ptr) - 1
    ! On its own a block claims every node it touches; a model re-claims
    ! over all its blocks in order (raccord_model_build).
    block
      logical, allocatable :: claimed(:)
      allocate(claimed(size(x, 2)), source=.false.)
      call claim_first_touch(blk, claimed)
    end block

    ! tensor Gauss rule, g = i + n1 (j - 1): xi = gx(i), eta = gx(j)
    do j = 1, n1
      do i = 1, n1
        g = i + n1*(j - 1)
        blk%wts(g) = gw(i)*gw(j)
        blk%gxi(:, g) = [gx(i), gx(j)]
        call shape_quad(etype, gx(i), gx(j), blk%nref(:, g), blk%dnref(:, :, g))
      end do
    end do

    ! Extrapolation (theory eq. 7.1): the tensor Lagrange interpolant through
    ! the n1 x n1 Gauss points, evaluated at each node; exact for stresses
    ! that are polynomials of degree n1 - 1 in each natural coordinate.
    do a = 1, nen
      nat = node_natural_coords(a)
      do i = 1, n1
        lag(i, 1) = lagrange_1d(gx(1:n1), i, nat(1))
        lag(i, 2) = lagrange_1d(gx(1:n1), i, nat(2))
      end do
      do j = 1, n1
        do i = 1, n1
          blk%extrap(a, i + n1*(j - 1)) = lag(i, 1)*lag(j, 2)
        end do
      end do
    end do

    if (etype == ELEM_Q4) then
      blk%kernel = KERN_Q4
      call init_q4_data(blk, x, err)
    else
      ! the plane Q8 kernel keeps only the coordinates (xn); H and c are
      ! built by store_gauss_maps if another kernel takes the block over.
      ! Here init_gauss_maps only checks detJ > 0 at every point.
      blk%kernel = KERN_Q8
      call init_gauss_maps(blk, x, err)
    end if
  end procedure init_elastic_block


  !> 1D Lagrange basis polynomial i through the points p, at s.
  pure real(wp) function lagrange_1d(p, i, s)
    real(wp), intent(in) :: p(:), s
    integer, intent(in) :: i
    integer :: k
    lagrange_1d = 1.0_wp
    do k = 1, size(p)
      if (k /= i) lagrange_1d = lagrange_1d*(s - p(k))/(p(i) - p(k))
    end do
  end function lagrange_1d
end submodule raccord_elastic_block_init
