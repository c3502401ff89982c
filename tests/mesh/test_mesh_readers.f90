!> Mesh readers: the same mesh read from Gmsh 4.1, Gmsh 2.2 and a hand-written
!> .inp must give the same nodes, elements and sets; surfaces must be
!> oriented counter-clockwise around their parent (outward normal = tangent
!> turned clockwise); unused nodes are dropped; every malformed file gives
!> EXIT_INPUT with a message naming the file and line or the id at fault.
program test_mesh_readers
  use raccord_kinds, only: wp
  use raccord_error, only: error_t, EXIT_INPUT
  use raccord_mesh, only: mesh_t, ELEM_Q4, ELEM_Q8, find_node_set, find_elem_set, find_surface
  use raccord_mesh_io, only: read_mesh
  use raccord_check, only: run_tests, new_test, failure_t, check, check_close, fail_now
  use raccord_strings, only: str
  use mesh_test_support, only: data_path, expect_error, same_mesh_exactly, same_points, node_set_points, &
    surface_points, elem_set_centroids, check_surface_parents, xtol
  implicit none
  call run_tests('mesh_readers', [ &
    new_test('gmsh 4.1 and 2.2 give the same Q4 scene', test_scene_q4_versions), &
    new_test('Q4 scene: sets, unnamed group, interior curve', test_scene_q4_sets), &
    new_test('Q8 scene: 4.1 = 2.2, edge mid nodes on their sides', test_scene_q8), &
    new_test('rectangle: gmsh 4.1, 2.2 and .inp agree', test_rect_formats), &
    new_test('rectangle: outward normals of the four sides', test_rect_normals), &
    new_test('unused nodes dropped, sets keep used ones', test_node_dropping), &
    new_test('inp Q8 faces: mid nodes, shared side', test_inp_q8), &
    new_test('scale and format options', test_options), &
    new_test('element in two physical groups (2.2 repeats it)', test_two_groups), &
    new_test('inp labels: quoted keep case, unquoted do not', test_inp_labels), &
    new_test('bad: missing file', test_bad_missing), &
    new_test('bad: truncated msh', test_bad_truncated), &
    new_test('bad: wrong node count 2.2', test_bad_count_22), &
    new_test('bad: wrong node count 4.1', test_bad_count_41), &
    new_test('bad: non-numeric field msh', test_bad_non_numeric_msh), &
    new_test('bad: non-numeric field inp', test_bad_non_numeric_inp), &
    new_test('bad: binary msh', test_bad_binary), &
    new_test('bad: partitioned msh', test_bad_partitioned), &
    new_test('bad: triangle element', test_bad_triangle), &
    new_test('bad: 9-node quadrilateral', test_bad_quad9), &
    new_test('bad: unknown inp element type', test_bad_unknown_type), &
    new_test('bad: duplicate node id', test_bad_dup_node), &
    new_test('bad: duplicate element id', test_bad_dup_elem), &
    new_test('bad: unknown node in element', test_bad_unknown_node), &
    new_test('bad: inverted element', test_bad_inverted), &
    new_test('bad: degenerate element', test_bad_degenerate), &
    new_test('bad: clockwise inp element', test_bad_clockwise_inp), &
    new_test('bad: clockwise gmsh element', test_bad_clockwise_msh), &
    new_test('bad: undefined set in *SURFACE', test_bad_undefined_set), &
    new_test('bad: set lists unknown element', test_bad_set_unknown_elem), &
    new_test('bad: no 2D element', test_bad_no_elements) &
    ])
contains

  !> Read a good mesh; any error is a test failure.
  subroutine read_good(failure, name, mesh, format, scale)
    type(failure_t), allocatable, intent(inout) :: failure
    character(len=*), intent(in) :: name
    type(mesh_t), intent(out) :: mesh
    character(len=*), intent(in), optional :: format
    real(wp), intent(in), optional :: scale
    type(error_t) :: err
    call read_mesh(data_path(name), mesh, err, format, scale)
    if (err%failed()) call fail_now(failure, name // ': ' // err%message)
  end subroutine read_good

  !> Outward normals (tangent turned clockwise, normalised) of every edge of
  !> a surface must all be close to n.
  subroutine check_normals(failure, mesh, name, n, label)
    type(failure_t), allocatable, intent(inout) :: failure
    type(mesh_t), intent(in) :: mesh
    character(len=*), intent(in) :: name, label
    real(wp), intent(in) :: n(2)
    integer :: k, m
    real(wp) :: t(2), normal(2)
    k = find_surface(mesh, name)
    call check(failure, k > 0, label // ': no surface ' // name)
    if (allocated(failure)) return
    call check(failure, mesh%surfaces(k)%nedge > 0, label // ': surface ' // name // ' is empty')
    do m = 1, mesh%surfaces(k)%nedge
      t = mesh%x(:, mesh%surfaces(k)%edge(2, m)) - mesh%x(:, mesh%surfaces(k)%edge(1, m))
      normal = [t(2), -t(1)]/norm2(t)
      call check(failure, dot_product(normal, n) > 0.99_wp, label // ': surface ' // name // ' edge ' // &
        str(m) // ' has normal (' // str(normal(1), 3) // ', ' // str(normal(2), 3) // ')')
    end do
  end subroutine check_normals

  subroutine test_scene_q4_versions(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(mesh_t) :: a, b
    call read_good(failure, 'scene_q4.v41.msh', a)
    call read_good(failure, 'scene_q4.v22.msh', b)
    if (allocated(failure)) return
    call check(failure, a%nelem == 32, 'scene: 24 + 8 elements expected, got ' // str(a%nelem))
    call check(failure, all(a%etype == ELEM_Q4), 'scene: all elements Q4')
    call same_mesh_exactly(failure, a, b, 'scene Q4 4.1 vs 2.2')
  end subroutine test_scene_q4_versions

  subroutine test_scene_q4_sets(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(mesh_t) :: m
    integer :: k
    call read_good(failure, 'scene_q4.v41.msh', m)
    if (allocated(failure)) return
    k = find_elem_set(m, 'block')
    call check(failure, k > 0, 'no element set block')
    if (allocated(failure)) return
    call check(failure, size(m%esets(k)%elems) == 24, 'block: 24 elements')
    k = find_elem_set(m, 'body')
    call check(failure, k > 0, 'no element set body')
    if (allocated(failure)) return
    call check(failure, size(m%esets(k)%elems) == 8, 'body: 8 elements')
    ! physical curve: a surface and a node set of the same name
    k = find_surface(m, 'base')
    call check(failure, k > 0, 'no surface base')
    if (allocated(failure)) return
    ! Gmsh names compare exactly (Gmsh's physical names are case-sensitive)
    call check(failure, find_surface(m, 'Base') == 0 .and. find_node_set(m, 'BASE') == 0 .and. &
      find_elem_set(m, 'Body') == 0, 'a Gmsh name found in another case')
    call check(failure, m%surfaces(k)%nedge == 8 .and. m%surfaces(k)%nen_edge == 2, 'base: 8 two-node edges')
    k = find_node_set(m, 'base')
    call check(failure, k > 0, 'no node set base')
    if (allocated(failure)) return
    call check(failure, size(m%nsets(k)%nodes) == 9, 'base: 9 nodes, got ' // str(size(m%nsets(k)%nodes)))
    call check(failure, all(abs(m%x(2, m%nsets(k)%nodes)) <= xtol), 'base nodes on y = 0')
    ! unnamed physical curve 20 is named by its tag
    call check(failure, find_surface(m, '20') > 0 .and. find_node_set(m, '20') > 0, 'unnamed group "20"')
    ! physical point
    call check(failure, same_points(node_set_points(m, 'anchor'), reshape([0.0_wp, 0.0_wp], [2, 1])), &
      'anchor is the node at the origin')
    ! the interior curve between the two halves of the block
    k = find_surface(m, 'interface')
    call check(failure, k > 0, 'no surface interface')
    if (allocated(failure)) return
    call check(failure, m%surfaces(k)%nedge == 3 .and. all(m%surfaces(k)%elem == -1), &
      'interface: 3 interior edges with elem = -1')
    call check(failure, size(node_set_points(m, 'interface'), 2) == 4, 'interface node set: 4 nodes')
    ! every other edge is its parent's side
    call check_surface_parents(failure, m)
    call check_normals(failure, m, 'base', [0.0_wp, -1.0_wp], 'scene')
    call check_normals(failure, m, 'block_top', [0.0_wp, 1.0_wp], 'scene')
    call check_normals(failure, m, '20', [-1.0_wp, 0.0_wp], 'scene')
    call check_normals(failure, m, 'body_top', [0.0_wp, 1.0_wp], 'scene')
    call check_arc_normals(failure, m, 'scene Q4')
  end subroutine test_scene_q4_sets

  !> The upper body's curved bottom is an arc of the circle centred at
  !> (1, 1.8) and the body lies inside that circle, so each edge's outward
  !> normal must point away from the centre.
  subroutine check_arc_normals(failure, m, label)
    type(failure_t), allocatable, intent(inout) :: failure
    type(mesh_t), intent(in) :: m
    character(len=*), intent(in) :: label
    real(wp), parameter :: centre(2) = [1.0_wp, 1.8_wp]
    real(wp) :: t(2), normal(2), radial(2)
    integer :: k, j
    k = find_surface(m, 'body_bottom')
    call check(failure, k > 0, label // ': no surface body_bottom')
    if (allocated(failure)) return
    call check(failure, m%surfaces(k)%nedge == 4, label // ': body_bottom has 4 edges')
    do j = 1, m%surfaces(k)%nedge
      t = m%x(:, m%surfaces(k)%edge(2, j)) - m%x(:, m%surfaces(k)%edge(1, j))
      normal = [t(2), -t(1)]/norm2(t)
      radial = 0.5_wp*(m%x(:, m%surfaces(k)%edge(2, j)) + m%x(:, m%surfaces(k)%edge(1, j))) - centre
      ! the body lies inside the circle, so outward is away from its centre
      call check(failure, dot_product(normal, radial/norm2(radial)) > 0.95_wp, &
        label // ': body_bottom edge ' // str(j) // ' normal not radial outward')
    end do
  end subroutine check_arc_normals

  subroutine test_scene_q8(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(mesh_t) :: a, b
    real(wp), parameter :: centre(2) = [1.0_wp, 1.8_wp]
    real(wp) :: r, mid(2)
    integer :: k, j
    call read_good(failure, 'scene_q8.v41.msh', a)
    call read_good(failure, 'scene_q8.v22.msh', b)
    if (allocated(failure)) return
    call same_mesh_exactly(failure, a, b, 'scene Q8 4.1 vs 2.2')
    call check(failure, a%nelem == 32 .and. all(a%etype == ELEM_Q8), 'scene Q8: 32 Q8 elements')
    call check_surface_parents(failure, a)
    call check_arc_normals(failure, a, 'scene Q8')
    if (allocated(failure)) return
    r = sqrt(0.4_wp**2 + 0.6_wp**2)
    do k = 1, size(a%surfaces)
      associate (s => a%surfaces(k))
        call check(failure, s%nen_edge == 3, 'Q8 surface ' // s%name // ': nen_edge = 3')
        do j = 1, s%nedge
          call check(failure, s%edge(3, j) > 0, 'Q8 surface ' // s%name // ': edge without mid node')
          if (allocated(failure)) return
          mid = a%x(:, s%edge(3, j))
          if (s%name == 'body_bottom') then
            call check_close(failure, norm2(mid - centre), r, 'arc mid node on the circle', rel_tol=1.0e-9_wp)
          else
            call check(failure, all(abs(mid - 0.5_wp*(a%x(:, s%edge(1, j)) + a%x(:, s%edge(2, j)))) <= xtol), &
              'Q8 surface ' // s%name // ': mid node not at the middle of its straight edge')
          end if
        end do
      end associate
    end do
  end subroutine test_scene_q8

  subroutine test_rect_formats(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(mesh_t) :: g41, g22, inp
    character(len=8), parameter :: sides(4) = [character(len=8) :: 'bottom', 'right', 'top', 'left']
    integer :: k
    call read_good(failure, 'rect.v41.msh', g41)
    call read_good(failure, 'rect.v22.msh', g22)
    call read_good(failure, 'rect.inp', inp)
    if (allocated(failure)) return
    call same_mesh_exactly(failure, g41, g22, 'rect 4.1 vs 2.2')
    call check(failure, inp%nnode == 12 .and. g41%nnode == 12, 'rect: 12 nodes, inp has ' // str(inp%nnode))
    call check(failure, inp%nelem == 6 .and. g41%nelem == 6, 'rect: 6 elements')
    call check(failure, same_points(g41%x, inp%x), 'rect: same node coordinates in .msh and .inp')
    call check(failure, same_points(elem_set_centroids(g41, 'plate'), elem_set_centroids(inp, 'plate')) .and. &
      size(elem_set_centroids(inp, 'plate'), 2) == 6, 'rect: element set plate differs')
    call check(failure, same_points(node_set_points(g41, 'corner'), node_set_points(inp, 'corner')) .and. &
      size(node_set_points(inp, 'corner'), 2) == 1, 'rect: node set corner differs')
    do k = 1, 4
      call check(failure, same_points(node_set_points(g41, trim(sides(k))), node_set_points(inp, trim(sides(k)))) &
        .and. size(node_set_points(inp, trim(sides(k))), 2) > 0, 'rect: node set ' // trim(sides(k)) // ' differs')
      call check(failure, same_points(surface_points(g41, trim(sides(k))), surface_points(inp, trim(sides(k)))) &
        .and. size(surface_points(inp, trim(sides(k))), 2) > 0, 'rect: surface ' // trim(sides(k)) // ' differs')
    end do
    call check_surface_parents(failure, inp)
    ! sets defined by GENERATE and by the name of another set
    call check(failure, size(elem_set_centroids(inp, 'lower'), 2) == 3, 'rect.inp: elset lower (GENERATE) has 3')
    call check(failure, size(node_set_points(inp, 'left'), 2) == 3, 'rect.inp: nset left has 3 nodes')
    ! one set, spelt as first defined, found in any case (Abaqus labels
    ! are case-insensitive: doc/mesh-formats.md, "Set and surface names")
    call check(failure, find_elem_set(inp, 'PLATE') == find_elem_set(inp, 'plate') .and. &
      find_elem_set(inp, 'Plate') == find_elem_set(inp, 'plate') .and. find_elem_set(inp, 'plate') > 0 .and. &
      size(inp%esets) == 3, 'rect.inp: ELSET=plate and ELSET=PLATE are one set, found in any case')
    if (find_elem_set(inp, 'plate') > 0) call check(failure, inp%esets(find_elem_set(inp, 'plate'))%name == 'plate', &
      'rect.inp: the set keeps the spelling of its first definition')
  end subroutine test_rect_formats

  subroutine test_rect_normals(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(mesh_t) :: m
    character(len=12), parameter :: files(3) = [character(len=12) :: 'rect.v41.msh', 'rect.v22.msh', 'rect.inp']
    integer :: k
    do k = 1, 3
      call read_good(failure, trim(files(k)), m)
      if (allocated(failure)) return
      call check_normals(failure, m, 'bottom', [0.0_wp, -1.0_wp], trim(files(k)))
      call check_normals(failure, m, 'right', [1.0_wp, 0.0_wp], trim(files(k)))
      call check_normals(failure, m, 'top', [0.0_wp, 1.0_wp], trim(files(k)))
      call check_normals(failure, m, 'left', [-1.0_wp, 0.0_wp], trim(files(k)))
      call check(failure, all(m%surfaces(:)%nen_edge == 2), trim(files(k)) // ': Q4 edges have 2 nodes')
    end do
  end subroutine test_rect_normals

  subroutine test_node_dropping(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(mesh_t) :: m
    integer :: k, n
    logical, allocatable :: used(:)
    ! the scene file holds 52 nodes: 51 on the elements and a free point
    ! in the physical point "stray"
    call read_good(failure, 'scene_q4.v41.msh', m)
    if (allocated(failure)) return
    call check(failure, m%nnode == 51, 'scene: 51 used nodes expected, got ' // str(m%nnode))
    allocate(used(m%nnode))
    used = .false.
    do k = 1, m%nelem
      used(m%conn(1:4, k)) = .true.
    end do
    call check(failure, all(used), 'scene: a node is used by no element')
    call check(failure, all(norm2(m%x - spread([3.0_wp, 3.0_wp], 2, m%nnode), dim=1) > xtol), &
      'scene: the free point (3, 3) was kept')
    k = find_node_set(m, 'stray')
    call check(failure, k > 0, 'scene: node set stray must exist (empty)')
    if (allocated(failure)) return
    call check(failure, size(m%nsets(k)%nodes) == 0, 'scene: stray keeps only used nodes (none)')
    ! the .inp: node 99 is in no element but in the NSET of *NODE
    call read_good(failure, 'rect.inp', m)
    if (allocated(failure)) return
    call check(failure, .not. any(m%node_id == 99), 'rect.inp: node 99 kept')
    k = find_node_set(m, 'ALLNODES')
    call check(failure, k > 0, 'rect.inp: node set ALLNODES (from *Node, nset=) missing')
    if (allocated(failure)) return
    n = size(m%nsets(k)%nodes)
    call check(failure, n == 12, 'rect.inp: ALLNODES keeps the 12 used nodes, got ' // str(n))
  end subroutine test_node_dropping

  subroutine test_inp_q8(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(mesh_t) :: m
    integer :: k
    call read_good(failure, 'q8_pair.inp', m)
    if (allocated(failure)) return
    call check(failure, m%nnode == 13 .and. m%nelem == 2 .and. all(m%etype == ELEM_Q8), 'q8_pair: 13 nodes, 2 Q8')
    k = find_surface(m, 'top')
    call check(failure, k > 0, 'q8_pair: no surface top')
    if (allocated(failure)) return
    associate (s => m%surfaces(k))
      call check(failure, s%nedge == 2 .and. s%nen_edge == 3, 'top: 2 three-node edges')
      if (allocated(failure)) return
      ! element 1, S3 runs 5 -> 6 with mid 11; element 2, S3 runs 4 -> 5 with mid 10
      call check(failure, all(m%node_id(s%edge(:, 1)) == [5, 6, 11]), 'top edge 1: nodes 5, 6, mid 11')
      call check(failure, all(m%node_id(s%edge(:, 2)) == [4, 5, 10]), 'top edge 2: nodes 4, 5, mid 10')
      call check(failure, all(s%side == 3) .and. all(m%elem_id(s%elem) == [1, 2]), 'top: side 3 of elements 1, 2')
    end associate
    call check_normals(failure, m, 'top', [0.0_wp, 1.0_wp], 'q8_pair')
    k = find_surface(m, 'middle')
    call check(failure, k > 0, 'q8_pair: no surface middle')
    if (allocated(failure)) return
    call check(failure, m%surfaces(k)%elem(1) == -1 .and. m%node_id(m%surfaces(k)%edge(3, 1)) == 13, &
      'middle: the shared side 2-5 is interior (elem = -1), mid node 13')
    call check(failure, same_points(node_set_points(m, 'middle'), &
      reshape([1.0_wp, 0.0_wp, 1.0_wp, 1.0_wp, 1.0_wp, 0.5_wp], [2, 3])), 'middle node set: 3 nodes on x = 1')
  end subroutine test_inp_q8

  subroutine test_options(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(mesh_t) :: m
    type(error_t) :: err
    call read_good(failure, 'rect.inp', m, scale=2.0_wp)
    if (allocated(failure)) return
    call check_close(failure, maxval(m%x(1, :)), 6.0_wp, 'scale 2: x reaches 6', abs_tol=xtol)
    call check_close(failure, maxval(m%x(2, :)), 4.0_wp, 'scale 2: y reaches 4', abs_tol=xtol)
    call read_good(failure, 'rect.v41.msh', m, format='GMSH')
    call check(failure, m%nelem == 6, 'format=GMSH read the msh')
    ! an .inp read as Gmsh is refused, naming the file
    call read_mesh(data_path('rect.inp'), m, err, format='gmsh')
    call check(failure, err%code == EXIT_INPUT .and. index(err%message, 'rect.inp:') > 0, &
      'format=gmsh on an .inp must fail naming the file')
    call err%clear()
    call read_mesh(data_path('scene_q4.geo'), m, err)
    call check(failure, err%code == EXIT_INPUT .and. index(err%message, 'extension') > 0, &
      'unknown extension must fail')
    call err%clear()
    call read_mesh(data_path('rect.inp'), m, err, scale=-1.0_wp)
    call check(failure, err%code == EXIT_INPUT .and. index(err%message, 'scale') > 0, 'negative scale must fail')
  end subroutine test_options

  subroutine test_two_groups(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(mesh_t) :: a, b
    integer :: ka, kb
    call read_good(failure, 'two_groups.v41.msh', a)
    call read_good(failure, 'two_groups.v22.msh', b)
    if (allocated(failure)) return
    call check(failure, a%nelem == 1, 'two_groups 4.1: one element, got ' // str(a%nelem))
    call check(failure, b%nelem == 1, 'two_groups 2.2: the repeated element is merged, got ' // str(b%nelem))
    if (allocated(failure)) return
    ka = find_elem_set(b, 'a')
    kb = find_elem_set(b, 'b')
    call check(failure, ka > 0 .and. kb > 0, 'two_groups 2.2: element sets a and b')
    if (allocated(failure)) return
    call check(failure, all(b%esets(ka)%elems == [1]) .and. all(b%esets(kb)%elems == [1]), &
      'two_groups 2.2: the one element is in both sets')
    ! (element ids differ: 2.2 numbers the lines of every group first)
    call check(failure, a%nnode == 4 .and. same_points(a%x, b%x), 'two_groups: the same 4 nodes')
    call check(failure, b%surfaces(find_surface(b, 'd'))%nedge == 2 .and. &
      b%surfaces(find_surface(b, 'c'))%nedge == 1, 'two_groups: curve 1 in surfaces c and d')
  end subroutine test_two_groups

  !> Abaqus's label rule (doc/mesh-formats.md, "Set and surface names"):
  !> "top" and top are two sets, "TOP" and top one; blanks count only in
  !> quotes; the deck's name finds a label spelt as it first, else an
  !> unquoted label in any case.
  subroutine test_inp_labels(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(mesh_t) :: m
    integer :: q, u
    call read_good(failure, 'labels.inp', m)
    if (allocated(failure)) return
    q = find_node_set(m, 'top')
    u = find_node_set(m, 'TOP')
    call check(failure, q > 0 .and. u > 0 .and. q /= u, 'labels: "top" and top are two node sets')
    if (allocated(failure)) return
    call check(failure, same_ids(m, m%nsets(q)%nodes, [4]), 'labels: "top" holds node 4 alone')
    call check(failure, same_ids(m, m%nsets(u)%nodes, [5, 6]), 'labels: top and "TOP" are one set (nodes 5, 6)')
    call check(failure, find_node_set(m, 'Top') == u .and. find_node_set(m, 'tOp') == u, &
      'labels: the unquoted TOP is found in any case but the quoted one''s')
    call check(failure, m%nsets(u)%name == 'TOP', 'labels: beside "top", top goes by its label TOP, got ' // &
      m%nsets(u)%name)
    q = find_node_set(m, 'Left Edge')
    u = find_node_set(m, 'LEFTEDGE')
    call check(failure, q > 0 .and. u > 0 .and. q /= u, 'labels: "Left Edge" and LeftEdge are two node sets')
    if (allocated(failure)) return
    call check(failure, same_ids(m, m%nsets(q)%nodes, [1]) .and. same_ids(m, m%nsets(u)%nodes, [2, 4]), &
      'labels: left edge (blanks ignored) joins LeftEdge, not "Left Edge"')
    call check(failure, find_node_set(m, 'left edge') == u .and. find_node_set(m, 'left Edge') == u, &
      'labels: the deck''s name with blanks reads as the unquoted label')
    u = find_node_set(m, 'both')
    call check(failure, u > 0, 'labels: node set both')
    if (u > 0) call check(failure, same_ids(m, m%nsets(u)%nodes, [4, 5, 6]), &
      'labels: a data line names "top" (node 4) and Top (5, 6)')
    q = find_elem_set(m, 'Plate')
    u = find_elem_set(m, 'PLATE')
    call check(failure, q > 0 .and. u > 0 .and. q /= u .and. find_elem_set(m, 'plate') == u, &
      'labels: ELSET="Plate" and ELSET=plate are two sets, plate found as PLATE')
    q = find_surface(m, 'upper')
    u = find_surface(m, 'UPPER')
    call check(failure, q > 0 .and. u > 0 .and. q /= u .and. size(m%surfaces) == 2, &
      'labels: *SURFACE "upper" and upper are two surfaces')
    if (q > 0 .and. u > 0 .and. q /= u) then
      call check(failure, m%surfaces(q)%nedge == 1 .and. m%surfaces(u)%nedge == 1 .and. &
        m%elem_id(m%surfaces(q)%elem(1)) == 1 .and. m%elem_id(m%surfaces(u)%elem(1)) == 2, &
        'labels: "upper" is the face of element 1 ("Plate"), upper that of element 2 (plate)')
      call check(failure, m%surfaces(q)%name /= m%surfaces(u)%name, 'labels: the two surfaces are named apart')
    end if
  end subroutine test_inp_labels

  !> The file ids of internal node indices nodes(:) are ids(:), in order.
  logical function same_ids(m, nodes, ids)
    type(mesh_t), intent(in) :: m
    integer, intent(in) :: nodes(:), ids(:)
    same_ids = size(nodes) == size(ids)
    if (same_ids) same_ids = all(m%node_id(nodes) == ids)
  end function same_ids

  subroutine test_bad_missing(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'no_such_mesh.msh', 'no_such_mesh.msh', 'does not exist')
  end subroutine test_bad_missing

  subroutine test_bad_truncated(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'truncated.msh', 'truncated.msh', '$Nodes', 'truncated')
  end subroutine test_bad_truncated

  subroutine test_bad_count_22(failure)
    type(failure_t), allocatable, intent(out) :: failure
    ! the header says 13 nodes, $EndNodes comes after 12 (line 27)
    call expect_error(failure, 'wrong_count.msh', 'wrong_count.msh:27', 'counts')
  end subroutine test_bad_count_22

  subroutine test_bad_count_41(failure)
    type(failure_t), allocatable, intent(out) :: failure
    ! the header (line 5) says 5 nodes, the one block holds 4
    call expect_error(failure, 'wrong_count.v41.msh', 'wrong_count.v41.msh:5', 'announces 5 nodes')
  end subroutine test_bad_count_41

  subroutine test_bad_non_numeric_msh(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'non_numeric.msh', 'non_numeric.msh:17', '"2x"')
  end subroutine test_bad_non_numeric_msh

  subroutine test_bad_non_numeric_inp(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'non_numeric.inp', 'non_numeric.inp:4', '"1.O"')
  end subroutine test_bad_non_numeric_inp

  subroutine test_bad_binary(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'binary.msh', 'binary.msh:2', 'Mesh.Binary = 0')
  end subroutine test_bad_binary

  subroutine test_bad_partitioned(failure)
    type(failure_t), allocatable, intent(out) :: failure
    ! gmsh rect.geo -2 -part 2: the physical groups hide behind partition entities
    call expect_error(failure, 'partitioned.msh', 'partitioned.msh:25', 'partitioned')
  end subroutine test_bad_partitioned

  subroutine test_bad_triangle(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'triangle.msh', 'triangle.msh:33', 'type 2', 'Recombine')
  end subroutine test_bad_triangle

  subroutine test_bad_quad9(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'quad9.msh', 'quad9.msh:22', '9-node', 'SecondOrderIncomplete = 1')
  end subroutine test_bad_quad9

  subroutine test_bad_unknown_type(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'unknown_type.inp', 'unknown_type.inp:6', 'CPE3')
  end subroutine test_bad_unknown_type

  subroutine test_bad_dup_node(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'dup_node.inp', 'dup_node.inp:6', 'duplicate node id 2', 'dup_node.inp:4')
  end subroutine test_bad_dup_node

  subroutine test_bad_dup_elem(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'dup_elem.inp', 'dup_elem.inp:11', 'duplicate element id 1')
  end subroutine test_bad_dup_elem

  subroutine test_bad_unknown_node(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'unknown_node.inp', 'unknown_node.inp:8', 'element 7', 'node 42')
  end subroutine test_bad_unknown_node

  subroutine test_bad_inverted(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'inverted.inp', 'inverted.inp:8: element 5', 'inverted or degenerate')
  end subroutine test_bad_inverted

  subroutine test_bad_degenerate(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'degenerate.inp', 'degenerate.inp:8: element 8', 'degenerate', 'corner 2')
  end subroutine test_bad_degenerate

  subroutine test_bad_clockwise_inp(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'clockwise.inp', 'clockwise.inp:8: element 3', 'node order clockwise', &
      'list the corners counter-clockwise')
  end subroutine test_bad_clockwise_inp

  subroutine test_bad_clockwise_msh(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'clockwise.msh', 'element 1', 'node order clockwise', 'ReverseMesh Surface')
  end subroutine test_bad_clockwise_msh

  subroutine test_bad_undefined_set(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'undefined_set.inp', 'undefined_set.inp:10', '"plates"', 'undefined')
  end subroutine test_bad_undefined_set

  subroutine test_bad_set_unknown_elem(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'set_unknown_elem.inp', 'set_unknown_elem.inp:10', 'element 9')
  end subroutine test_bad_set_unknown_elem

  subroutine test_bad_no_elements(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'no_elements.inp', 'no_elements.inp', 'no 2D element')
  end subroutine test_bad_no_elements
end program test_mesh_readers
