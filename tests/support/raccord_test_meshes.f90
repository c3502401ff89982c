!> Structured rectangle meshes made in memory for tests: nx x ny Q4 or Q8
!> elements on [x0, x0+lx] x [y0, y0+ly], optionally distorted by a smooth
!> map that keeps the sides straight. Sets: element set 'body'; node sets
!> and surfaces 'left', 'right', 'bottom', 'top'; node set 'all'.
module raccord_test_meshes
  use raccord_kinds, only: wp, pi
  use raccord_mesh, only: mesh_t, node_set_t, elem_set_t, surface_t, ELEM_Q4, ELEM_Q8, side_nodes
  implicit none
  private

  public :: rect_mesh, join_meshes

contains

  subroutine rect_mesh(mesh, etype, nx, ny, lx, ly, x0, y0, distortion)
    type(mesh_t), intent(out) :: mesh
    integer, intent(in) :: etype, nx, ny
    real(wp), intent(in) :: lx, ly
    real(wp), intent(in), optional :: x0, y0
    real(wp), intent(in), optional :: distortion   !< amplitude of the smooth map (0.2: visibly distorted)
    integer :: i, j, e, ngx, ngy, step, nn
    integer, allocatable :: grid(:,:)
    real(wp) :: ox, oy, d, xi, yj
    ox = 0.0_wp
    oy = 0.0_wp
    d = 0.0_wp
    if (present(x0)) ox = x0
    if (present(y0)) oy = y0
    if (present(distortion)) d = distortion
    step = merge(2, 1, etype == ELEM_Q8)
    ngx = step*nx + 1
    ngy = step*ny + 1
    ! Grid points; for Q8 the centre points of elements are skipped.
    allocate(grid(ngx, ngy), source=0)
    nn = 0
    do j = 1, ngy
      do i = 1, ngx
        if (step == 2 .and. mod(i, 2) == 0 .and. mod(j, 2) == 0) cycle
        nn = nn + 1
        grid(i, j) = nn
      end do
    end do
    mesh%source = 'rect_mesh'
    mesh%nnode = nn
    allocate(mesh%x(2, nn), mesh%node_id(nn))
    do j = 1, ngy
      do i = 1, ngx
        if (grid(i, j) == 0) cycle
        ! A smooth global map that keeps the four sides straight: elements
        ! are distorted but become parallelograms under refinement, the
        ! setting in which Q8 (serendipity) keeps its full order (Arnold,
        ! Boffi & Falk, Math. Comp. 71 (2002)).
        xi = real(i - 1, wp)/real(ngx - 1, wp)
        yj = real(j - 1, wp)/real(ngy - 1, wp)
        mesh%x(:, grid(i, j)) = [ox + lx*(xi + d*0.25_wp*sin(pi*xi)*sin(2.0_wp*pi*yj)), &
                                 oy + ly*(yj + d*0.25_wp*sin(pi*yj)*sin(2.0_wp*pi*xi))]
        mesh%node_id(grid(i, j)) = grid(i, j)
      end do
    end do
    mesh%nelem = nx*ny
    allocate(mesh%etype(mesh%nelem), source=etype)
    allocate(mesh%conn(8, mesh%nelem), source=0)
    allocate(mesh%elem_id(mesh%nelem))
    e = 0
    do j = 1, ny
      do i = 1, nx
        e = e + 1
        mesh%elem_id(e) = e
        associate (a => step*(i - 1) + 1, b => step*(j - 1) + 1)
          mesh%conn(1:4, e) = [grid(a, b), grid(a + step, b), grid(a + step, b + step), grid(a, b + step)]
          if (step == 2) mesh%conn(5:8, e) = [grid(a + 1, b), grid(a + 2, b + 1), grid(a + 1, b + 2), grid(a, b + 1)]
        end associate
      end do
    end do
    allocate(mesh%esets(1))
    mesh%esets(1)%name = 'body'
    mesh%esets(1)%elems = [(e, e = 1, mesh%nelem)]
    allocate(mesh%surfaces(4), mesh%nsets(5))
    call side_surface(mesh, etype, 1, 'bottom', [(e, e = 1, nx)], 1)
    call side_surface(mesh, etype, 2, 'right', [(nx*j, j = 1, ny)], 2)
    call side_surface(mesh, etype, 3, 'top', [(nx*(ny - 1) + i, i = nx, 1, -1)], 3)
    call side_surface(mesh, etype, 4, 'left', [(nx*(j - 1) + 1, j = ny, 1, -1)], 4)
    do i = 1, 4
      mesh%nsets(i)%name = mesh%surfaces(i)%name
      mesh%nsets(i)%nodes = unique_nodes(mesh%surfaces(i))
    end do
    mesh%nsets(5)%name = 'all'
    mesh%nsets(5)%nodes = [(i, i = 1, nn)]
  end subroutine rect_mesh

  subroutine side_surface(mesh, etype, k, name, elems, side)
    type(mesh_t), intent(inout) :: mesh
    integer, intent(in) :: etype, k, side
    character(len=*), intent(in) :: name
    integer, intent(in) :: elems(:)
    integer :: i, loc(3)
    associate (s => mesh%surfaces(k))
      s%name = name
      s%nedge = size(elems)
      s%nen_edge = merge(3, 2, etype == ELEM_Q8)
      allocate(s%edge(3, s%nedge), source=0)
      s%elem = elems
      allocate(s%side(s%nedge), source=side)
      loc = side_nodes(etype, side)
      do i = 1, s%nedge
        s%edge(1, i) = mesh%conn(loc(1), elems(i))
        s%edge(2, i) = mesh%conn(loc(2), elems(i))
        if (loc(3) > 0) s%edge(3, i) = mesh%conn(loc(3), elems(i))
      end do
    end associate
  end subroutine side_surface

  !> Two separate bodies in one mesh: b's nodes and elements follow a's;
  !> every set of a is renamed '<na>_<name>' and of b '<nb>_<name>'
  !> (so element sets 'na_body' and 'nb_body').
  subroutine join_meshes(a, na, b, nb, mesh)
    type(mesh_t), intent(in) :: a, b
    character(len=*), intent(in) :: na, nb
    type(mesh_t), intent(out) :: mesh
    integer :: k, off, eoff
    off = a%nnode
    eoff = a%nelem
    mesh%source = 'join_meshes'
    mesh%nnode = a%nnode + b%nnode
    mesh%nelem = a%nelem + b%nelem
    mesh%x = reshape([a%x, b%x], [2, mesh%nnode])
    mesh%node_id = [(k, k = 1, mesh%nnode)]
    mesh%elem_id = [(k, k = 1, mesh%nelem)]
    mesh%etype = [a%etype, b%etype]
    allocate(mesh%conn(8, mesh%nelem))
    mesh%conn(:, 1:eoff) = a%conn
    mesh%conn(:, eoff+1:) = merge(b%conn + off, 0, b%conn > 0)
    allocate(mesh%esets(size(a%esets) + size(b%esets)))
    allocate(mesh%nsets(size(a%nsets) + size(b%nsets)))
    allocate(mesh%surfaces(size(a%surfaces) + size(b%surfaces)))
    do k = 1, size(a%esets)
      mesh%esets(k)%name = na // '_' // a%esets(k)%name
      mesh%esets(k)%elems = a%esets(k)%elems
    end do
    do k = 1, size(b%esets)
      mesh%esets(size(a%esets) + k)%name = nb // '_' // b%esets(k)%name
      mesh%esets(size(a%esets) + k)%elems = b%esets(k)%elems + eoff
    end do
    do k = 1, size(a%nsets)
      mesh%nsets(k)%name = na // '_' // a%nsets(k)%name
      mesh%nsets(k)%nodes = a%nsets(k)%nodes
    end do
    do k = 1, size(b%nsets)
      mesh%nsets(size(a%nsets) + k)%name = nb // '_' // b%nsets(k)%name
      mesh%nsets(size(a%nsets) + k)%nodes = b%nsets(k)%nodes + off
    end do
    do k = 1, size(a%surfaces)
      mesh%surfaces(k) = a%surfaces(k)
      mesh%surfaces(k)%name = na // '_' // a%surfaces(k)%name
    end do
    do k = 1, size(b%surfaces)
      associate (s => mesh%surfaces(size(a%surfaces) + k))
        s = b%surfaces(k)
        s%name = nb // '_' // b%surfaces(k)%name
        s%edge = merge(s%edge + off, 0, s%edge > 0)
        s%elem = s%elem + eoff
      end associate
    end do
  end subroutine join_meshes

  function unique_nodes(s) result(nodes)
    type(surface_t), intent(in) :: s
    integer, allocatable :: nodes(:)
    integer :: i, j
    allocate(nodes(0))
    do i = 1, s%nedge
      do j = 1, s%nen_edge
        if (s%edge(j, i) > 0) then
          if (.not. any(nodes == s%edge(j, i))) nodes = [nodes, s%edge(j, i)]
        end if
      end do
    end do
  end function unique_nodes
end module raccord_test_meshes
