!> Full rings (closed contact surfaces) in memory for the closed-loop
!> contact tests: rect_mesh on the unit square wrapped round the origin,
!> theta = 2 pi (1 - x) (elements stay counter-clockwise), r from the inner
!> boundary to the outer along each ray, and the seam x = 1 merged onto
!> x = 0. The surfaces 'bottom' (inner circle) and 'top' (outer circle)
!> are closed loops; node sets 'xaxis' (nodes on y = 0) and 'yaxis' (on
!> x = 0) hold the rigid motions with symmetric supports.
module closed_ring_mesh
  use raccord_kinds, only: wp, pi
  use raccord_mesh, only: mesh_t, surface_t, node_set_t
  use raccord_test_meshes, only: rect_mesh
  implicit none
  private

  public :: ring_full, boundary_radius

contains

  !> Radius at angle th (0 <= th < 2 pi) of a boundary: the circle r0
  !> (nfacet = 0) or the chords of the regular nfacet-gon inscribed in it
  !> with a vertex at th = 0.
  pure real(wp) function boundary_radius(th, r0, nfacet) result(r)
    real(wp), intent(in) :: th, r0
    integer, intent(in) :: nfacet
    real(wp) :: d, tm
    integer :: k
    r = r0
    if (nfacet == 0) return
    d = 2.0_wp*pi/nfacet
    k = max(0, min(int(th/d), nfacet - 1))
    tm = (real(k, wp) + 0.5_wp)*d
    r = r0*cos(0.5_wp*d)/cos(th - tm)
  end function boundary_radius

  !> Full ring of nth x nr elements (etype Q4 or Q8) between the inner
  !> boundary (ri, fi facets) and the outer one (ro, fo facets). nth a
  !> multiple of 4 puts nodes on both axes.
  subroutine ring_full(mesh, etype, nth, nr, ri, fi, ro, fo)
    type(mesh_t), intent(out) :: mesh
    integer, intent(in) :: etype, nth, nr, fi, fo
    real(wp), intent(in) :: ri, ro
    type(mesh_t) :: sq
    integer, allocatable :: newid(:)
    integer :: n, q, nn, k, e, j
    real(wp) :: th, t, r1, r2
    real(wp), parameter :: tol = 1.0e-12_wp

    call rect_mesh(sq, etype, nth, nr, 1.0_wp, 1.0_wp)
    ! Nodes on x = 1 take the index of their twin on x = 0.
    allocate(newid(sq%nnode), source=0)
    nn = 0
    do n = 1, sq%nnode
      if (abs(sq%x(1, n) - 1.0_wp) < tol) cycle
      nn = nn + 1
      newid(n) = nn
    end do
    do n = 1, sq%nnode
      if (abs(sq%x(1, n) - 1.0_wp) >= tol) cycle
      do q = 1, sq%nnode
        if (abs(sq%x(1, q)) < tol .and. abs(sq%x(2, q) - sq%x(2, n)) < tol) newid(n) = newid(q)
      end do
    end do
    mesh%source = 'ring_full'
    mesh%nnode = nn
    mesh%nelem = sq%nelem
    allocate(mesh%x(2, nn), mesh%node_id(nn))
    do n = 1, sq%nnode
      if (abs(sq%x(1, n) - 1.0_wp) < tol) cycle
      th = 2.0_wp*pi*(1.0_wp - sq%x(1, n))
      if (th >= 2.0_wp*pi - tol) th = 0.0_wp
      t = sq%x(2, n)
      r1 = boundary_radius(th, ri, fi)
      r2 = boundary_radius(th, ro, fo)
      mesh%x(:, newid(n)) = (r1 + (r2 - r1)*t)*[cos(th), sin(th)]
      mesh%node_id(newid(n)) = newid(n)
    end do
    ! Exact zeros on the axes (cos(pi/2) is 6e-17).
    where (abs(mesh%x) < 1.0e-13_wp) mesh%x = 0.0_wp
    mesh%etype = sq%etype
    mesh%elem_id = sq%elem_id
    mesh%conn = sq%conn
    do e = 1, mesh%nelem
      do j = 1, size(mesh%conn, 1)
        if (mesh%conn(j, e) > 0) mesh%conn(j, e) = newid(mesh%conn(j, e))
      end do
    end do
    mesh%esets = sq%esets
    ! The loops: rect_mesh's 'bottom' (surface 1) and 'top' (surface 3).
    allocate(mesh%surfaces(2))
    mesh%surfaces(1) = sq%surfaces(1)
    mesh%surfaces(2) = sq%surfaces(3)
    do k = 1, 2
      associate (s => mesh%surfaces(k))
        do e = 1, s%nedge
          do j = 1, 3
            if (s%edge(j, e) > 0) s%edge(j, e) = newid(s%edge(j, e))
          end do
        end do
      end associate
    end do
    allocate(mesh%nsets(4))
    mesh%nsets(1)%name = 'bottom'
    mesh%nsets(1)%nodes = loop_nodes(mesh%surfaces(1))
    mesh%nsets(2)%name = 'top'
    mesh%nsets(2)%nodes = loop_nodes(mesh%surfaces(2))
    mesh%nsets(3)%name = 'xaxis'
    mesh%nsets(3)%nodes = pack([(n, n = 1, nn)], mesh%x(2, :) == 0.0_wp)
    mesh%nsets(4)%name = 'yaxis'
    mesh%nsets(4)%nodes = pack([(n, n = 1, nn)], mesh%x(1, :) == 0.0_wp)
  end subroutine ring_full

  !> Nodes of a loop surface, each once (the start and mid node of each edge).
  function loop_nodes(s) result(nodes)
    type(surface_t), intent(in) :: s
    integer, allocatable :: nodes(:)
    integer :: e
    nodes = [(s%edge(1, e), e = 1, s%nedge)]
    if (s%nen_edge == 3) nodes = [nodes, [(s%edge(3, e), e = 1, s%nedge)]]
  end function loop_nodes
end module closed_ring_mesh
