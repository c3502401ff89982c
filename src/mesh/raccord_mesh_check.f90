!> Checks shared by every mesh format, and the step from the file's view
!> (mesh_draft_t: file ids, sets by id) to the solver's (mesh_t: internal
!> indices, surfaces attached to their parent elements).
!>
!> Order matters: ids are checked first so every later message can trust
!> them; unreferenced nodes are dropped before the sets are resolved so that
!> no set carries a node without mass; element shape is checked before the
!> surfaces, whose orientation relies on counter-clockwise elements.
module raccord_mesh_check
  use raccord_kinds, only: wp, i8
  use raccord_error, only: error_t, raise_error, EXIT_INPUT
  use raccord_log, only: log_info, log_warn
  use raccord_strings, only: str, clipped
  use raccord_int_map, only: int_map_t, map_init, map_insert, map_get, pair_key, text_key
  use raccord_mesh, only: mesh_t, node_set_t, elem_set_t, surface_t, MAX_NEN, ELEM_Q4, ELEM_Q8, case_kept, &
    nodes_per_element, side_nodes, element_name
  use raccord_mesh_draft, only: mesh_draft_t, where_text
  use raccord_mesh_quality, only: check_element_shape, SHAPE_OK, SHAPE_CLOCKWISE, DEGENERATE_RTOL
  implicit none
  private

  public :: finalize_mesh

  character(len=*), parameter :: caller = 'finalize_mesh'

contains

  !> Check the draft and build the mesh from it. mesh%source is left to the caller.
  subroutine finalize_mesh(d, mesh, err)
    type(mesh_draft_t), intent(in) :: d
    type(mesh_t), intent(inout) :: mesh
    type(error_t), intent(inout) :: err
    integer, allocatable :: new_node(:)     ! draft node -> mesh node (0: dropped)
    type(int_map_t) :: node_map, elem_map

    if (d%nelem == 0) then
      call raise_error(err, EXIT_INPUT, where_text(d, 1, 0) // ' contains no 2D element (Q4 or Q8): ' // &
        hint(d, 'no_elements'))
      return
    end if
    call map_ids(d, node_map, elem_map, err)
    if (err%failed()) return
    call build_elements(d, node_map, new_node, mesh, err)
    if (err%failed()) return
    call check_plane(d, new_node, err)
    if (err%failed()) return
    call check_shapes(d, mesh, err)
    if (err%failed()) return
    call check_shared_sides(d, mesh, err)
    if (err%failed()) return
    call check_hanging_nodes(d, mesh, err)
    if (err%failed()) return
    call build_elem_sets(d, elem_map, mesh, err)
    if (err%failed()) return
    call build_node_sets(d, node_map, new_node, mesh, err)
    if (err%failed()) return
    call build_surfaces(d, node_map, elem_map, new_node, mesh, err)
    if (err%failed()) return
    if (d%format_name == 'abaqus') call distinct_spellings(mesh)
    mesh%axi_types = ''
    if (allocated(d%axi_types)) mesh%axi_types = d%axi_types
    mesh%ignore_case = d%format_name == 'abaqus'
  end subroutine finalize_mesh

  !> raccord is 2D: it reads x and y, so the nodes of the elements must lie
  !> in one plane z = const (Gmsh writes z = 0 for a 2D mesh, Abaqus's
  !> *NODE may give a z). A section meshed in another plane, or a surface
  !> mesh of a 3D part, would be read squashed onto x-y: refused, naming
  !> the two nodes farthest apart in z. The bound, 1e-9 of the x-y
  !> extent, passes the round-off of a plane written at constant z.
  subroutine check_plane(d, new_node, err)
    type(mesh_draft_t), intent(in) :: d
    integer, intent(in) :: new_node(:)
    type(error_t), intent(inout) :: err
    integer :: k, klo, khi
    real(wp) :: lo(2), hi(2), extent
    klo = 0
    khi = 0
    lo = huge(1.0_wp)
    hi = -huge(1.0_wp)
    do k = 1, d%nnode
      if (new_node(k) == 0) cycle
      lo = min(lo, d%x(:, k))
      hi = max(hi, d%x(:, k))
      if (klo == 0) then
        klo = k
        khi = k
      else
        if (d%z(k) < d%z(klo)) klo = k
        if (d%z(k) > d%z(khi)) khi = k
      end if
    end do
    if (klo == 0) return
    extent = maxval(hi - lo)
    if (d%z(khi) - d%z(klo) <= 1.0e-9_wp*extent) return
    call raise_error(err, EXIT_INPUT, where_text(d, d%node_file(khi), d%node_line(khi)) // ': node ' // &
      str(d%node_id(khi)) // ' has z = ' // str(d%z(khi)) // ', node ' // str(d%node_id(klo)) // ' (' // &
      where_text(d, d%node_file(klo), d%node_line(klo)) // ') has z = ' // str(d%z(klo)) // &
      ': the elements are not in one plane z = const; raccord is 2D and reads x and y only. ' // &
      'Mesh the section in the x-y plane (Gmsh: a 2D geometry at z = 0)')
  end subroutine check_plane

  !> File id -> draft index maps; a repeated id is an error at its second use.
  !> Ids must be positive (Gmsh tags and Abaqus numbers start at 1): 0
  !> stands for "no node" in a surface edge's mid node (draft_surface_t),
  !> so a node 0 could not be told from a missing one, and a zero or
  !> negative id is a damaged or hand-edited file; refused at its line.
  subroutine map_ids(d, node_map, elem_map, err)
    type(mesh_draft_t), intent(in) :: d
    type(int_map_t), intent(out) :: node_map, elem_map
    type(error_t), intent(inout) :: err
    integer :: k, prev
    call map_init(node_map, d%nnode)
    do k = 1, d%nnode
      if (d%node_id(k) <= 0) then
        call raise_error(err, EXIT_INPUT, where_text(d, d%node_file(k), d%node_line(k)) // &
          ': node id ' // str(d%node_id(k)) // ' is not positive: ' // hint(d, 'positive_id'))
        return
      end if
      call map_insert(node_map, int(d%node_id(k), i8), k, prev)
      if (prev /= 0) then
        call raise_error(err, EXIT_INPUT, where_text(d, d%node_file(k), d%node_line(k)) // &
          ': duplicate node id ' // str(d%node_id(k)) // ' (first defined at ' // &
          where_text(d, d%node_file(prev), d%node_line(prev)) // '): node ids must be unique; renumber the nodes')
        return
      end if
    end do
    call map_init(elem_map, d%nelem)
    do k = 1, d%nelem
      if (d%elem_id(k) <= 0) then
        call raise_error(err, EXIT_INPUT, where_text(d, d%elem_file(k), d%elem_line(k)) // &
          ': element id ' // str(d%elem_id(k)) // ' is not positive: ' // hint(d, 'positive_id'))
        return
      end if
      call map_insert(elem_map, int(d%elem_id(k), i8), k, prev)
      if (prev /= 0) then
        call raise_error(err, EXIT_INPUT, where_text(d, d%elem_file(k), d%elem_line(k)) // &
          ': duplicate element id ' // str(d%elem_id(k)) // ' (first defined at ' // &
          where_text(d, d%elem_file(prev), d%elem_line(prev)) // &
          '): element ids must be unique; renumber the elements')
        return
      end if
    end do
  end subroutine map_ids

  !> Connectivity in draft indices, then keep only the nodes some 2D element
  !> uses (a node without element has no mass and would stop the explicit
  !> time step), numbered in file order.
  subroutine build_elements(d, node_map, new_node, mesh, err)
    type(mesh_draft_t), intent(in) :: d
    type(int_map_t), intent(in) :: node_map
    integer, allocatable, intent(out) :: new_node(:)
    type(mesh_t), intent(inout) :: mesh
    type(error_t), intent(inout) :: err
    integer :: e, a, nen, k, n
    integer, allocatable :: conn(:,:)

    allocate(conn(MAX_NEN, d%nelem), new_node(d%nnode))
    conn = 0
    new_node = 0
    do e = 1, d%nelem
      nen = nodes_per_element(d%etype(e))
      do a = 1, nen
        k = map_get(node_map, int(d%conn(a, e), i8))
        if (k == 0) then
          call raise_error(err, EXIT_INPUT, where_text(d, d%elem_file(e), d%elem_line(e)) // &
            ': element ' // str(d%elem_id(e)) // ' references node ' // str(d%conn(a, e)) // &
            ', which is not defined: ' // hint(d, 'unknown_node'))
          return
        end if
        conn(a, e) = k
        new_node(k) = 1
      end do
      if (nen > 0) then
        do a = 1, nen - 1
          if (any(conn(a + 1:nen, e) == conn(a, e))) then
            call raise_error(err, EXIT_INPUT, where_text(d, d%elem_file(e), d%elem_line(e)) // &
              ': element ' // str(d%elem_id(e)) // ' lists node ' // str(d%conn(a, e)) // &
              ' twice: the element is degenerate; fix its connectivity or remesh')
            return
          end if
        end do
      end if
    end do

    n = 0
    do k = 1, d%nnode
      if (new_node(k) /= 0) then
        n = n + 1
        new_node(k) = n
      end if
    end do
    if (n < d%nnode) call log_info(caller, 'dropped ' // str(d%nnode - n) // &
      ' node(s) used by no 2D element (they would have no mass)')

    mesh%nnode = n
    mesh%nelem = d%nelem
    allocate(mesh%x(2, n), mesh%node_id(n))
    do k = 1, d%nnode
      if (new_node(k) == 0) cycle
      mesh%x(:, new_node(k)) = d%x(:, k)
      mesh%node_id(new_node(k)) = d%node_id(k)
    end do
    mesh%etype = d%etype(1:d%nelem)
    mesh%elem_id = d%elem_id(1:d%nelem)
    allocate(mesh%conn(MAX_NEN, d%nelem))
    mesh%conn = 0
    do e = 1, d%nelem
      nen = nodes_per_element(d%etype(e))
      mesh%conn(1:nen, e) = new_node(conn(1:nen, e))
    end do
  end subroutine build_elements

  !> Every element must map the reference square one-to-one.
  subroutine check_shapes(d, mesh, err)
    type(mesh_draft_t), intent(in) :: d
    type(mesh_t), intent(in) :: mesh
    type(error_t), intent(inout) :: err
    integer :: e, nen, status
    real(wp) :: worst
    character(len=:), allocatable :: at_point, loc
    do e = 1, mesh%nelem
      nen = nodes_per_element(mesh%etype(e))
      call check_element_shape(mesh%etype(e), mesh%x(:, mesh%conn(1:nen, e)), status, worst, at_point)
      if (status == SHAPE_OK) cycle
      loc = where_text(d, d%elem_file(e), d%elem_line(e)) // ': element ' // str(mesh%elem_id(e))
      if (status == SHAPE_CLOCKWISE) then
        call raise_error(err, EXIT_INPUT, loc // ' has its node order clockwise (det J < 0 at every ' // &
          'corner and Gauss point); raccord needs counter-clockwise elements: ' // hint(d, 'clockwise'))
      else
        call raise_error(err, EXIT_INPUT, loc // ' is inverted or degenerate: det J / (h/2)^2 = ' // &
          str(worst, 3) // ' at ' // at_point // ' (must exceed ' // str(DEGENERATE_RTOL, 1) // &
          '); look for coincident or crossed corners, an interior angle of 180 degrees or more, or ' // &
          'a Q8 mid-side node far from the middle of its side, and remesh or fix the coordinates')
      end if
      return
    end do
  end subroutine check_shapes

  !> Two elements that share a side (the same two corners) must share all
  !> of it: both without a mid-side node (Q4-Q4) or both with the same one
  !> (Q8-Q8). A Q8 beside a Q4 leaves its mid-side node hanging, free to
  !> open a gap the Q4 does not follow, and was accepted without a word.
  subroutine check_shared_sides(d, mesh, err)
    type(mesh_draft_t), intent(in) :: d
    type(mesh_t), intent(in) :: mesh
    type(error_t), intent(inout) :: err
    type(int_map_t) :: side_map
    integer :: e, s, prev, other, mine, theirs, loc(3)
    character(len=:), allocatable :: what
    call map_init(side_map, 4*mesh%nelem)
    do e = 1, mesh%nelem
      do s = 1, 4
        loc = side_nodes(mesh%etype(e), s)
        call map_insert(side_map, pair_key(mesh%conn(loc(1), e), mesh%conn(loc(2), e)), 4*(e - 1) + s, prev)
        if (prev == 0) cycle
        other = (prev - 1)/4 + 1
        mine = mid_of(e, s)
        theirs = mid_of(other, prev - 4*(other - 1))
        if (mine == theirs) cycle
        if (mine == 0 .or. theirs == 0) then
          what = 'a ' // element_name(mesh%etype(other)) // ' and a ' // element_name(mesh%etype(e)) // &
            ' share a side, whose mid-side node ' // str(mesh%node_id(max(mine, theirs))) // ' hangs: ' // &
            'use one element order in each body (all Q4 or all Q8; Gmsh: one Mesh.ElementOrder)'
        else
          what = 'their common side has two different mid-side nodes, ' // str(mesh%node_id(theirs)) // &
            ' and ' // str(mesh%node_id(mine)) // ': merge them (the mesh is not conforming)'
        end if
        call raise_error(err, EXIT_INPUT, where_text(d, d%elem_file(e), d%elem_line(e)) // ': elements ' // &
          str(mesh%elem_id(other)) // ' and ' // str(mesh%elem_id(e)) // ' (side ' // &
          str(mesh%node_id(mesh%conn(loc(1), e))) // '-' // str(mesh%node_id(mesh%conn(loc(2), e))) // '): ' // &
          what)
        return
      end do
    end do
  contains
    !> Mid-side node of side k of element el, 0 for a Q4.
    integer function mid_of(el, k)
      integer, intent(in) :: el, k
      integer :: l(3)
      l = side_nodes(mesh%etype(el), k)
      mid_of = 0
      if (mesh%etype(el) == ELEM_Q8) mid_of = mesh%conn(l(3), el)
    end function mid_of
  end subroutine check_shared_sides

  !> No hanging node: a side a-b of one element that another element's
  !> node m splits into two sides a-m and m-b of its neighbours (a 2:1
  !> refinement, or a Q8 whose mid-side node is the corner of finer
  !> elements) leaves m free to open a gap. Such a side and its two halves
  !> are each used by one element only; m is the side's mid-side node or
  !> lies on the chord a-b (within 1e-6 of its length).
  subroutine check_hanging_nodes(d, mesh, err)
    type(mesh_draft_t), intent(in) :: d
    type(mesh_t), intent(in) :: mesh
    type(error_t), intent(inout) :: err
    type(int_map_t) :: side_map
    integer, allocatable :: sa(:), sb(:), se(:), smid(:), uses(:), head(:), nxt(:), to(:)
    integer :: e, s, k, k2, j, nside, nlink, prev, a, b, m, loc(3)
    call map_init(side_map, 4*mesh%nelem)
    allocate(sa(4*mesh%nelem), sb(4*mesh%nelem), se(4*mesh%nelem), smid(4*mesh%nelem), uses(4*mesh%nelem))
    nside = 0
    do e = 1, mesh%nelem
      do s = 1, 4
        loc = side_nodes(mesh%etype(e), s)
        k = map_get(side_map, pair_key(mesh%conn(loc(1), e), mesh%conn(loc(2), e)))
        if (k > 0) then
          uses(k) = uses(k) + 1
          cycle
        end if
        nside = nside + 1
        sa(nside) = mesh%conn(loc(1), e)
        sb(nside) = mesh%conn(loc(2), e)
        se(nside) = e
        smid(nside) = 0
        if (mesh%etype(e) == ELEM_Q8) smid(nside) = mesh%conn(loc(3), e)
        uses(nside) = 1
        call map_insert(side_map, pair_key(sa(nside), sb(nside)), nside, prev)
      end do
    end do
    ! the sides used once, listed from each of their two ends
    allocate(head(mesh%nnode), nxt(2*nside), to(2*nside))
    head = 0
    nlink = 0
    do k = 1, nside
      if (uses(k) /= 1) cycle
      call link(sa(k), sb(k))
      call link(sb(k), sa(k))
    end do
    do k = 1, nside
      if (uses(k) /= 1) cycle
      a = sa(k)
      b = sb(k)
      j = head(a)
      do while (j > 0)
        m = to(j)
        j = nxt(j)
        if (m == b) cycle
        k2 = map_get(side_map, pair_key(m, b))
        if (k2 == 0) cycle
        if (uses(k2) /= 1) cycle
        if (m /= smid(k) .and. .not. on_chord(mesh%x(:, a), mesh%x(:, b), mesh%x(:, m))) cycle
        call raise_error(err, EXIT_INPUT, where_text(d, d%elem_file(se(k)), d%elem_line(se(k))) // ': node ' // &
          str(mesh%node_id(m)) // ' hangs on the side ' // str(mesh%node_id(a)) // '-' // str(mesh%node_id(b)) // &
          ' of element ' // str(mesh%elem_id(se(k))) // ': it is a corner of the neighbouring elements but ' // &
          'not of this one, so the mesh can open there; remesh without hanging nodes (conforming refinement)')
        return
      end do
    end do
  contains
    subroutine link(from, there)
      integer, intent(in) :: from, there
      nlink = nlink + 1
      to(nlink) = there
      nxt(nlink) = head(from)
      head(from) = nlink
    end subroutine link
    !> p strictly inside the segment p1-p2, off its line by at most 1e-6 of its length.
    pure logical function on_chord(p1, p2, p)
      real(wp), intent(in) :: p1(2), p2(2), p(2)
      real(wp) :: t, len2, dist2, v(2), w(2)
      v = p2 - p1
      w = p - p1
      len2 = v(1)**2 + v(2)**2
      on_chord = .false.
      if (len2 <= 0.0_wp) return
      t = (w(1)*v(1) + w(2)*v(2))/len2
      if (t <= 1.0e-6_wp .or. t >= 1.0_wp - 1.0e-6_wp) return
      dist2 = (w(1) - t*v(1))**2 + (w(2) - t*v(2))**2
      on_chord = dist2 <= 1.0e-12_wp*len2
    end function on_chord
  end subroutine check_hanging_nodes

  subroutine build_elem_sets(d, elem_map, mesh, err)
    type(mesh_draft_t), intent(in) :: d
    type(int_map_t), intent(in) :: elem_map
    type(mesh_t), intent(inout) :: mesh
    type(error_t), intent(inout) :: err
    integer :: s, m, k
    integer, allocatable :: list(:)
    allocate(mesh%esets(d%neset))
    do s = 1, d%neset
      associate (g => d%esets(s))
        allocate(list(g%n))
        do m = 1, g%n
          k = map_get(elem_map, int(g%id(m), i8))
          if (k == 0) then
            call raise_error(err, EXIT_INPUT, where_text(d, g%file(m), g%line(m)) // ': element set "' // &
              clipped(g%name, 60) // '" lists element ' // str(g%id(m)) // &
              ', which is not a defined 2D element: ' // &
              'define it or remove it from the set')
            return
          end if
          list(m) = k
        end do
        call sort_unique(list, k)
        mesh%esets(s)%name = g%name
        mesh%esets(s)%key = g%key
        mesh%esets(s)%elems = list(1:k)
        deallocate(list)
      end associate
    end do
  end subroutine build_elem_sets

  subroutine build_node_sets(d, node_map, new_node, mesh, err)
    type(mesh_draft_t), intent(in) :: d
    type(int_map_t), intent(in) :: node_map
    integer, intent(in) :: new_node(:)
    type(mesh_t), intent(inout) :: mesh
    type(error_t), intent(inout) :: err
    integer :: s, m, k, n
    integer, allocatable :: list(:)
    allocate(mesh%nsets(d%nnset))
    do s = 1, d%nnset
      associate (g => d%nsets(s))
        allocate(list(g%n))
        n = 0
        do m = 1, g%n
          k = map_get(node_map, int(g%id(m), i8))
          if (k == 0) then
            call raise_error(err, EXIT_INPUT, where_text(d, g%file(m), g%line(m)) // ': node set "' // &
              clipped(g%name, 60) // '" lists node ' // str(g%id(m)) // ', which is not defined: ' // &
              'define it or remove it from the set')
            return
          end if
          if (new_node(k) == 0) cycle       ! dropped node: no element, no mass
          n = n + 1
          list(n) = new_node(k)
        end do
        call sort_unique(list(1:n), k)
        if (k == 0 .and. g%n > 0) call log_warn(caller, 'node set "' // clipped(g%name, 60) // &
          '" is empty: none of its nodes belongs to a 2D element')
        mesh%nsets(s)%name = g%name
        mesh%nsets(s)%key = g%key
        mesh%nsets(s)%nodes = list(1:k)
        deallocate(list)
      end associate
    end do
  end subroutine build_node_sets

  !> Attach each surface edge to the element side with the same corner pair
  !> (hash of the sorted pair, O(n)) and store it in the parent's
  !> counter-clockwise order, so the outward normal is the tangent turned
  !> clockwise. A side shared by two elements is interior: elem = -1.
  !> Each surface also gives (or joins) the node set of its name.
  subroutine build_surfaces(d, node_map, elem_map, new_node, mesh, err)
    type(mesh_draft_t), intent(in) :: d
    type(int_map_t), intent(in) :: node_map, elem_map
    integer, intent(in) :: new_node(:)
    type(mesh_t), intent(inout) :: mesh
    type(error_t), intent(inout) :: err
    type(int_map_t) :: side_map, nset_index
    logical, allocatable :: shared(:)
    integer, allocatable :: listed_by(:)
    integer :: e, s, k, prev, j, m, e_par, s_par, ends(3), loc(3), nen_max, nset_used
    integer, allocatable :: nodes(:)
    character(len=:), allocatable :: at

    call map_init(side_map, 4*mesh%nelem)
    allocate(shared(4*mesh%nelem))
    shared = .false.
    do e = 1, mesh%nelem
      do s = 1, 4
        loc = side_nodes(mesh%etype(e), s)
        call map_insert(side_map, pair_key(mesh%conn(loc(1), e), mesh%conn(loc(2), e)), 4*(e - 1) + s, prev)
        if (prev /= 0) shared(prev) = .true.
      end do
    end do

    ! Which surface last listed each element side: an edge listed twice in
    ! one surface would carry its load twice.
    allocate(listed_by(4*mesh%nelem), source=0)
    allocate(mesh%surfaces(d%nsurf))
    ! the node sets, with room for one per surface, and their labels' index
    ! (many surfaces merge in O(n), not O(n^2))
    call reserve_node_sets(mesh, d%nsurf, nset_index, nset_used)
    do j = 1, d%nsurf
      associate (ds => d%surfaces(j), surf => mesh%surfaces(j))
        surf%name = ds%name
        surf%key = ds%key
        surf%nedge = ds%n
        allocate(surf%edge(3, ds%n), surf%elem(ds%n), surf%side(ds%n))
        nen_max = 2
        do m = 1, ds%n
          ends = 0
          at = where_text(d, ds%file(m), ds%line(m)) // ': surface "' // clipped(ds%name, 60) // '"'
          if (ds%elem(m) /= 0) then
            ! given as element face (Abaqus)
            e_par = map_get(elem_map, int(ds%elem(m), i8))
            if (e_par == 0) then
              call raise_error(err, EXIT_INPUT, at // ' names element ' // str(ds%elem(m)) // &
                ', which is not a defined 2D element: define it or correct the surface')
              return
            end if
            s_par = ds%side(m)
            loc = side_nodes(mesh%etype(e_par), s_par)
            k = map_get(side_map, pair_key(mesh%conn(loc(1), e_par), mesh%conn(loc(2), e_par)))
          else
            ! given by nodes (Gmsh line element)
            do k = 1, 3
              ends(k) = 0
              if (ds%node(k, m) == 0) cycle
              prev = map_get(node_map, int(ds%node(k, m), i8))
              if (prev == 0) then
                call raise_error(err, EXIT_INPUT, at // ': edge references node ' // str(ds%node(k, m)) // &
                  ', which is not defined in $Nodes: re-export the mesh')
                return
              end if
              ends(k) = new_node(prev)
            end do
            k = 0
            if (ends(1) /= 0 .and. ends(2) /= 0) k = map_get(side_map, pair_key(ends(1), ends(2)))
            if (k == 0) then
              call raise_error(err, EXIT_INPUT, at // ': edge ' // str(ds%node(1, m)) // '-' // &
                str(ds%node(2, m)) // ' is not a side of any Q4/Q8 element: ' // hint(d, 'stray_edge'))
              return
            end if
          end if
          e_par = (k - 1)/4 + 1
          s_par = k - 4*(e_par - 1)
          loc = side_nodes(mesh%etype(e_par), s_par)
          if (listed_by(k) == j) then
            call raise_error(err, EXIT_INPUT, at // ' lists the edge ' // str(mesh%node_id(mesh%conn(loc(1), e_par))) // &
              '-' // str(mesh%node_id(mesh%conn(loc(2), e_par))) // ' twice (a load on it would count twice): ' // &
              'remove the repeated line or face')
            return
          end if
          listed_by(k) = j
          surf%edge(1:2, m) = mesh%conn(loc(1:2), e_par)
          surf%edge(3, m) = 0
          if (loc(3) > 0) surf%edge(3, m) = mesh%conn(loc(3), e_par)
          if (ds%elem(m) == 0 .and. ends(3) /= 0 .and. surf%edge(3, m) /= 0 .and. ends(3) /= surf%edge(3, m)) then
            call raise_error(err, EXIT_INPUT, at // ': the mid node ' // str(ds%node(3, m)) // &
              ' of edge ' // str(ds%node(1, m)) // '-' // str(ds%node(2, m)) // &
              ' is not the mid-side node of element ' // str(mesh%elem_id(e_par)) // &
              ': the curve and the surface do not share their nodes; re-export the mesh')
            return
          end if
          if (surf%edge(3, m) /= 0) nen_max = 3
          if (shared(k)) then
            surf%elem(m) = -1     ! interior curve: no single parent, no outward side
            surf%side(m) = 0
          else
            surf%elem(m) = e_par
            surf%side(m) = s_par
          end if
        end do
        surf%nen_edge = nen_max
        if (ds%n > 0 .and. count(surf%elem(1:ds%n) == -1) > 0) call log_info(caller, 'surface "' // &
          clipped(ds%name, 60) // '" has ' // str(count(surf%elem(1:ds%n) == -1)) // &
          ' edge(s) inside the mesh (shared by two elements): usable as a node set only')
        ! the node set of the same name
        allocate(nodes(3*ds%n))
        k = 0
        do m = 1, ds%n
          do s = 1, 3
            if (surf%edge(s, m) == 0) cycle
            k = k + 1
            nodes(k) = surf%edge(s, m)
          end do
        end do
        call merge_node_set(mesh, nset_index, nset_used, ds%name, ds%key, nodes(1:k))
        deallocate(nodes)
      end associate
    end do
    if (nset_used < size(mesh%nsets)) mesh%nsets = mesh%nsets(1:nset_used)
  end subroutine build_surfaces

  !> Grow mesh%nsets by `extra` unused places (nset_used counts the used
  !> ones) and index the labels of the sets it holds (text_key).
  subroutine reserve_node_sets(mesh, extra, index, nset_used)
    type(mesh_t), intent(inout) :: mesh
    integer, intent(in) :: extra
    type(int_map_t), intent(out) :: index
    integer, intent(out) :: nset_used
    type(node_set_t), allocatable :: tmp(:)
    integer :: k, prev
    nset_used = size(mesh%nsets)
    allocate(tmp(nset_used + extra))
    do k = 1, nset_used
      call move_alloc(mesh%nsets(k)%name, tmp(k)%name)
      call move_alloc(mesh%nsets(k)%key, tmp(k)%key)
      call move_alloc(mesh%nsets(k)%nodes, tmp(k)%nodes)
    end do
    call move_alloc(tmp, mesh%nsets)
    call map_init(index, nset_used + extra)
    do k = 1, nset_used
      call map_insert(index, text_key(mesh%nsets(k)%key), k, prev)
    end do
  end subroutine reserve_node_sets

  !> Two Abaqus sets of one kind may be spelt alike and still be two labels:
  !> a quoted "top" and an unquoted top (the label TOP). The unquoted one
  !> then goes by its label (TOP) in messages and output, so that no two
  !> sets of a kind, nor two result grids, share a name.
  subroutine distinct_spellings(mesh)
    type(mesh_t), intent(inout) :: mesh
    type(int_map_t) :: kept
    integer :: j, k, prev
    ! for each kind, an index of the spellings of the quoted labels whose
    ! case counts (text_key), then each other set checked against it: O(n)
    call map_init(kept, size(mesh%nsets))
    do j = 1, size(mesh%nsets)
      if (case_kept(mesh%nsets(j)%key)) call map_insert(kept, text_key(mesh%nsets(j)%name), j, prev)
    end do
    do j = 1, size(mesh%nsets)
      if (case_kept(mesh%nsets(j)%key)) cycle
      k = map_get(kept, text_key(mesh%nsets(j)%name))
      if (k == 0) cycle
      if (mesh%nsets(k)%name == mesh%nsets(j)%name) mesh%nsets(j)%name = mesh%nsets(j)%key
    end do
    call map_init(kept, size(mesh%esets))
    do j = 1, size(mesh%esets)
      if (case_kept(mesh%esets(j)%key)) call map_insert(kept, text_key(mesh%esets(j)%name), j, prev)
    end do
    do j = 1, size(mesh%esets)
      if (case_kept(mesh%esets(j)%key)) cycle
      k = map_get(kept, text_key(mesh%esets(j)%name))
      if (k == 0) cycle
      if (mesh%esets(k)%name == mesh%esets(j)%name) mesh%esets(j)%name = mesh%esets(j)%key
    end do
    call map_init(kept, size(mesh%surfaces))
    do j = 1, size(mesh%surfaces)
      if (case_kept(mesh%surfaces(j)%key)) call map_insert(kept, text_key(mesh%surfaces(j)%name), j, prev)
    end do
    do j = 1, size(mesh%surfaces)
      if (case_kept(mesh%surfaces(j)%key)) cycle
      k = map_get(kept, text_key(mesh%surfaces(j)%name))
      if (k == 0) cycle
      if (mesh%surfaces(k)%name == mesh%surfaces(j)%name) mesh%surfaces(j)%name = mesh%surfaces(j)%key
    end do
  end subroutine distinct_spellings

  !> Add nodes to the node set of label key, creating it (spelt name) in
  !> the next place reserve_node_sets made when absent.
  subroutine merge_node_set(mesh, index, nset_used, name, key, nodes)
    type(mesh_t), intent(inout) :: mesh
    type(int_map_t), intent(inout) :: index
    integer, intent(inout) :: nset_used
    character(len=*), intent(in) :: name, key
    integer, intent(in) :: nodes(:)
    integer, allocatable :: list(:)
    integer :: k, s, n, prev
    s = map_get(index, text_key(key))
    if (s > 0) then
      if (mesh%nsets(s)%key /= key) then
        ! two labels of one text_key: scan
        s = 0
        do k = 1, nset_used
          if (mesh%nsets(k)%key == key) then
            s = k
            exit
          end if
        end do
      end if
    end if
    if (s == 0) then
      nset_used = nset_used + 1
      s = nset_used
      mesh%nsets(s)%name = name
      mesh%nsets(s)%key = key
      allocate(mesh%nsets(s)%nodes(0))
      call map_insert(index, text_key(key), s, prev)
    end if
    list = [mesh%nsets(s)%nodes, nodes]
    call sort_unique(list, n)
    mesh%nsets(s)%nodes = list(1:n)
  end subroutine merge_node_set

  !> Sort a(:) ascending in place (heap sort, O(n log n)) and move the
  !> distinct values to a(1:n).
  pure subroutine sort_unique(a, n)
    integer, intent(inout) :: a(:)
    integer, intent(out) :: n
    integer :: k, last, t
    do k = size(a)/2, 1, -1
      call sift_down(a, k, size(a))
    end do
    do last = size(a), 2, -1
      t = a(1)
      a(1) = a(last)
      a(last) = t
      call sift_down(a, 1, last - 1)
    end do
    n = min(size(a), 1)
    do k = 2, size(a)
      if (a(k) /= a(n)) then
        n = n + 1
        a(n) = a(k)
      end if
    end do
  end subroutine sort_unique

  pure subroutine sift_down(a, start, last)
    integer, intent(inout) :: a(:)
    integer, intent(in) :: start, last
    integer :: root, child, t
    root = start
    do while (2*root <= last)
      child = 2*root
      if (child < last) then
        if (a(child + 1) > a(child)) child = child + 1
      end if
      if (a(root) >= a(child)) return
      t = a(root)
      a(root) = a(child)
      a(child) = t
      root = child
    end do
  end subroutine sift_down

  !> How to fix a fault, in the words of the format the mesh came from.
  function hint(d, what) result(s)
    type(mesh_draft_t), intent(in) :: d
    character(len=*), intent(in) :: what
    character(len=:), allocatable :: s
    logical :: gmsh
    gmsh = d%format_name == 'gmsh'
    select case (what)
    case ('no_elements')
      if (gmsh) then
        s = 'mesh the surfaces in 2D (gmsh -2) with quadrilaterals (Recombine Surface), and put them in a ' // &
          'Physical Surface (with physical groups, Gmsh saves only the grouped elements)'
      else
        s = 'define the elements with *ELEMENT, TYPE=CPE4 (or CPS4, CPE8, CPS8)'
      end if
    case ('unknown_node')
      if (gmsh) then
        s = 'the $Nodes section misses it; re-export the mesh'
      else
        s = 'define it in a *NODE block or correct the element'
      end if
    case ('clockwise')
      if (gmsh) then
        s = 'in Gmsh, make the surface''s curve loop counter-clockwise, or add ' // &
          '"ReverseMesh Surface{...};" for that surface before meshing'
      else
        s = 'in the .inp, list the corners counter-clockwise (e.g. 1,4,3,2 instead of 1,2,3,4; ' // &
          'for CPE8/CPS8 reorder the mid-side nodes to match)'
      end if
    case ('positive_id')
      if (gmsh) then
        s = 'Gmsh tags start at 1; the file was edited or written by another program: renumber from 1 ' // &
          '(or mesh again and save from Gmsh)'
      else
        s = 'Abaqus node and element numbers start at 1: renumber from 1'
      end if
    case ('stray_edge')
      if (gmsh) then
        s = 'the physical curve must lie on meshed surfaces and share their nodes (put the curve in the ' // &
          'surface''s curve loop, or use Coherence)'
      else
        s = 'the edge must be a side of an element'
      end if
    case default
      s = ''
    end select
  end function hint
end module raccord_mesh_check
