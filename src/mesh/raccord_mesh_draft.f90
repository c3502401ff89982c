!> The mesh as the file states it, before checking: entities keep their file
!> ids and the file and line they came from, so the checks made once the
!> whole file is read (raccord_mesh_check) can still say where a fault is.
!>
!> Both readers fill this type; only raccord_mesh_check turns it into a
!> mesh_t. Arrays grow by doubling, so reading stays O(n).
module raccord_mesh_draft
  use raccord_kinds, only: wp
  use raccord_mesh, only: MAX_NEN
  use raccord_int_map, only: int_map_t, map_insert, map_get, text_key
  use raccord_strings, only: str
  implicit none
  private

  public :: add_file, add_node, add_element, find_group, add_group, add_member
  public :: add_edge_by_nodes, add_edge_by_side, find_draft_surface, add_draft_surface, where_text

  !> A file name, so that several files (Abaqus *INCLUDE) can be cited.
  type, public :: file_name_t
    character(len=:), allocatable :: path
  end type file_name_t

  !> Named list of file ids (node set or element set) with their origin.
  type, public :: draft_group_t
    character(len=:), allocatable :: name      !< spelling of its first definition, for messages and output
    character(len=:), allocatable :: key       !< the label the group is found by (raccord_mesh's label_key)
    integer :: n = 0
    integer, allocatable :: id(:)
    integer, allocatable :: file(:)        !< index in mesh_draft_t%files
    integer, allocatable :: line(:)
  end type draft_group_t

  !> Named surface: edges given either by their nodes (Gmsh line elements)
  !> or by element and side (Abaqus *SURFACE faces).
  type, public :: draft_surface_t
    character(len=:), allocatable :: name      !< spelling of its first definition
    character(len=:), allocatable :: key       !< the label it is found by (label_key)
    integer :: n = 0
    integer, allocatable :: node(:,:)      !< (3, n) file node ids start, end, mid (0: none); 0 when by side
    integer, allocatable :: elem(:)        !< file element id when given by side, else 0
    integer, allocatable :: side(:)        !< side 1..4 when given by side, else 0
    integer, allocatable :: file(:)
    integer, allocatable :: line(:)
  end type draft_surface_t

  type, public :: mesh_draft_t
    character(len=:), allocatable :: format_name       !< 'gmsh' or 'abaqus': chooses the fix-it hints
    integer :: nfile = 0
    type(file_name_t), allocatable :: files(:)
    integer :: nnode = 0
    integer, allocatable :: node_id(:)
    real(wp), allocatable :: x(:,:)                   !< (2, nnode)
    real(wp), allocatable :: z(:)                     !< (nnode) the file's z, 0 if it has none (finalize_mesh checks it is one plane)
    integer, allocatable :: node_file(:), node_line(:)
    integer :: nelem = 0
    integer, allocatable :: elem_id(:), etype(:)
    integer, allocatable :: conn(:,:)                 !< (MAX_NEN, nelem) file node ids, 0-padded
    integer, allocatable :: elem_file(:), elem_line(:)
    integer :: nnset = 0, neset = 0, nsurf = 0
    !> label -> index of nsets, esets, surfaces (text_key of the key), so a
    !> file of many sets, or of many elements in groups, reads in O(n)
    type(int_map_t) :: nset_index, eset_index, surf_index
    type(draft_group_t), allocatable :: nsets(:)
    type(draft_group_t), allocatable :: esets(:)
    type(draft_surface_t), allocatable :: surfaces(:)
    character(len=:), allocatable :: axi_types         !< axisymmetric element types met (CAX4, ...), '' if none
  end type mesh_draft_t

contains

  !> Register a file and return its index for later locations.
  subroutine add_file(d, path, ifile)
    type(mesh_draft_t), intent(inout) :: d
    character(len=*), intent(in) :: path
    integer, intent(out) :: ifile
    type(file_name_t), allocatable :: tmp(:)
    if (.not. allocated(d%files)) allocate(d%files(4))
    if (d%nfile == size(d%files)) then
      allocate(tmp(2*size(d%files)))
      tmp(1:d%nfile) = d%files(1:d%nfile)
      call move_alloc(tmp, d%files)
    end if
    d%nfile = d%nfile + 1
    d%files(d%nfile)%path = path
    ifile = d%nfile
  end subroutine add_file

  !> "path:line" (or just the path when the line is unknown).
  function where_text(d, ifile, line) result(s)
    type(mesh_draft_t), intent(in) :: d
    integer, intent(in) :: ifile, line
    character(len=:), allocatable :: s
    if (ifile < 1 .or. ifile > d%nfile) then
      s = '(unknown file)'
    else
      s = d%files(ifile)%path
    end if
    if (line > 0) s = s // ':' // str(line)
  end function where_text

  subroutine add_node(d, id, xy, ifile, line, z)
    type(mesh_draft_t), intent(inout) :: d
    integer, intent(in) :: id, ifile, line
    real(wp), intent(in) :: xy(2)
    real(wp), intent(in), optional :: z      !< the file's z coordinate, if it gives one
    integer :: cap
    if (.not. allocated(d%node_id)) then
      allocate(d%node_id(64), d%x(2, 64), d%z(64), d%node_file(64), d%node_line(64))
    end if
    cap = size(d%node_id)
    if (d%nnode == cap) then
      call grow_int(d%node_id, 2*cap)
      call grow_int(d%node_file, 2*cap)
      call grow_int(d%node_line, 2*cap)
      call grow_real2(d%x, 2*cap)
      call grow_real(d%z, 2*cap)
    end if
    d%nnode = d%nnode + 1
    d%node_id(d%nnode) = id
    d%x(:, d%nnode) = xy
    d%z(d%nnode) = 0.0_wp
    if (present(z)) d%z(d%nnode) = z
    d%node_file(d%nnode) = ifile
    d%node_line(d%nnode) = line
  end subroutine add_node

  !> Append a 2D element; conn holds file node ids in file order.
  subroutine add_element(d, id, etype, conn, ifile, line)
    type(mesh_draft_t), intent(inout) :: d
    integer, intent(in) :: id, etype, ifile, line
    integer, intent(in) :: conn(:)
    integer :: cap
    if (.not. allocated(d%elem_id)) then
      allocate(d%elem_id(64), d%etype(64), d%conn(MAX_NEN, 64), d%elem_file(64), d%elem_line(64))
    end if
    cap = size(d%elem_id)
    if (d%nelem == cap) then
      call grow_int(d%elem_id, 2*cap)
      call grow_int(d%etype, 2*cap)
      call grow_int(d%elem_file, 2*cap)
      call grow_int(d%elem_line, 2*cap)
      call grow_int2(d%conn, 2*cap)
    end if
    d%nelem = d%nelem + 1
    d%elem_id(d%nelem) = id
    d%etype(d%nelem) = etype
    d%conn(:, d%nelem) = 0
    d%conn(1:size(conn), d%nelem) = conn
    d%elem_file(d%nelem) = ifile
    d%elem_line(d%nelem) = line
  end subroutine add_element

  !> Index of the group of label `key` among groups(1:n), or 0. The
  !> readers give the key: a Gmsh name as it is, an Abaqus label by
  !> raccord_mesh's label_key (case ignored unless quoted). `index` maps
  !> text_key(key) to the group; two labels of one text_key (rare) are
  !> told apart by a scan.
  pure integer function find_group(groups, n, index, key)
    type(draft_group_t), intent(in) :: groups(:)
    integer, intent(in) :: n
    type(int_map_t), intent(in) :: index
    character(len=*), intent(in) :: key
    integer :: k
    find_group = map_get(index, text_key(key))
    if (find_group == 0) return
    if (groups(find_group)%key == key) return
    find_group = 0
    do k = 1, n
      if (groups(k)%key /= key) cycle
      find_group = k
      return
    end do
  end function find_group

  !> Index of the group of label `key`, created empty (spelt `name`) when absent.
  subroutine add_group(groups, n, index, name, key, k)
    type(draft_group_t), allocatable, intent(inout) :: groups(:)
    integer, intent(inout) :: n
    type(int_map_t), intent(inout) :: index
    character(len=*), intent(in) :: name, key
    integer, intent(out) :: k
    type(draft_group_t), allocatable :: tmp(:)
    integer :: prev
    if (.not. allocated(groups)) allocate(groups(4))
    k = find_group(groups, n, index, key)
    if (k > 0) return
    if (n == size(groups)) then
      allocate(tmp(2*n))
      tmp(1:n) = groups(1:n)
      call move_alloc(tmp, groups)
    end if
    n = n + 1
    k = n
    groups(k)%name = name
    groups(k)%key = key
    groups(k)%n = 0
    allocate(groups(k)%id(16), groups(k)%file(16), groups(k)%line(16))
    call map_insert(index, text_key(key), k, prev)
  end subroutine add_group

  subroutine add_member(g, id, ifile, line)
    type(draft_group_t), intent(inout) :: g
    integer, intent(in) :: id, ifile, line
    integer :: cap
    cap = size(g%id)
    if (g%n == cap) then
      call grow_int(g%id, 2*cap)
      call grow_int(g%file, 2*cap)
      call grow_int(g%line, 2*cap)
    end if
    g%n = g%n + 1
    g%id(g%n) = id
    g%file(g%n) = ifile
    g%line(g%n) = line
  end subroutine add_member

  !> Index of the surface of label `key` (as find_group), or 0.
  pure integer function find_draft_surface(d, key)
    type(mesh_draft_t), intent(in) :: d
    character(len=*), intent(in) :: key
    integer :: k
    find_draft_surface = map_get(d%surf_index, text_key(key))
    if (find_draft_surface == 0) return
    if (d%surfaces(find_draft_surface)%key == key) return
    find_draft_surface = 0
    do k = 1, d%nsurf
      if (d%surfaces(k)%key /= key) cycle
      find_draft_surface = k
      return
    end do
  end function find_draft_surface

  !> Index of the surface of label `key`, created empty (spelt `name`) when absent.
  subroutine add_draft_surface(d, name, key, k)
    type(mesh_draft_t), intent(inout) :: d
    character(len=*), intent(in) :: name, key
    integer, intent(out) :: k
    type(draft_surface_t), allocatable :: tmp(:)
    integer :: prev
    if (.not. allocated(d%surfaces)) allocate(d%surfaces(4))
    k = find_draft_surface(d, key)
    if (k > 0) return
    if (d%nsurf == size(d%surfaces)) then
      allocate(tmp(2*d%nsurf))
      tmp(1:d%nsurf) = d%surfaces(1:d%nsurf)
      call move_alloc(tmp, d%surfaces)
    end if
    d%nsurf = d%nsurf + 1
    k = d%nsurf
    d%surfaces(k)%name = name
    d%surfaces(k)%key = key
    d%surfaces(k)%n = 0
    allocate(d%surfaces(k)%node(3, 16), d%surfaces(k)%elem(16), d%surfaces(k)%side(16), &
      d%surfaces(k)%file(16), d%surfaces(k)%line(16))
    call map_insert(d%surf_index, text_key(key), k, prev)
  end subroutine add_draft_surface

  !> Edge given by its file node ids (start, end, mid or 0), Gmsh line element.
  subroutine add_edge_by_nodes(s, nodes, ifile, line)
    type(draft_surface_t), intent(inout) :: s
    integer, intent(in) :: nodes(3), ifile, line
    call next_edge(s)
    s%node(:, s%n) = nodes
    s%elem(s%n) = 0
    s%side(s%n) = 0
    s%file(s%n) = ifile
    s%line(s%n) = line
  end subroutine add_edge_by_nodes

  !> Edge given as side 1..4 of a file element id (Abaqus face S1..S4).
  subroutine add_edge_by_side(s, elem_id, side, ifile, line)
    type(draft_surface_t), intent(inout) :: s
    integer, intent(in) :: elem_id, side, ifile, line
    call next_edge(s)
    s%node(:, s%n) = 0
    s%elem(s%n) = elem_id
    s%side(s%n) = side
    s%file(s%n) = ifile
    s%line(s%n) = line
  end subroutine add_edge_by_side

  subroutine next_edge(s)
    type(draft_surface_t), intent(inout) :: s
    integer :: cap
    cap = size(s%elem)
    if (s%n == cap) then
      call grow_int2(s%node, 2*cap)
      call grow_int(s%elem, 2*cap)
      call grow_int(s%side, 2*cap)
      call grow_int(s%file, 2*cap)
      call grow_int(s%line, 2*cap)
    end if
    s%n = s%n + 1
  end subroutine next_edge

  pure subroutine grow_int(a, cap)
    integer, allocatable, intent(inout) :: a(:)
    integer, intent(in) :: cap
    integer, allocatable :: tmp(:)
    allocate(tmp(cap))
    tmp(1:size(a)) = a
    call move_alloc(tmp, a)
  end subroutine grow_int

  pure subroutine grow_int2(a, cap)
    integer, allocatable, intent(inout) :: a(:,:)
    integer, intent(in) :: cap
    integer, allocatable :: tmp(:,:)
    allocate(tmp(size(a, 1), cap))
    tmp(:, 1:size(a, 2)) = a
    call move_alloc(tmp, a)
  end subroutine grow_int2

  pure subroutine grow_real(a, cap)
    real(wp), allocatable, intent(inout) :: a(:)
    integer, intent(in) :: cap
    real(wp), allocatable :: tmp(:)
    allocate(tmp(cap))
    tmp(1:size(a)) = a
    call move_alloc(tmp, a)
  end subroutine grow_real

  pure subroutine grow_real2(a, cap)
    real(wp), allocatable, intent(inout) :: a(:,:)
    integer, intent(in) :: cap
    real(wp), allocatable :: tmp(:,:)
    allocate(tmp(size(a, 1), cap))
    tmp(:, 1:size(a, 2)) = a
    call move_alloc(tmp, a)
  end subroutine grow_real2
end module raccord_mesh_draft
