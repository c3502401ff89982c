!> The mesh as read from a file: nodes, 2D elements, and named sets.
!>
!> Conventions (doc/user-guide.md, "Mesh conventions"):
!> - coordinates components first, x(2, nnode); internal node and element
!>   indices are 1..n in file order, the file's ids kept in node_id/elem_id
!>   for messages and output;
!> - element nodes follow the Gmsh/Abaqus order: corners 1-4 counter-clockwise,
!>   then (Q8) mid-side nodes 5 (edge 1-2), 6 (2-3), 7 (3-4), 8 (4-1);
!> - an element set is a Gmsh physical surface or an Abaqus *ELSET;
!>   a node set is a Gmsh physical curve/point or an Abaqus *NSET
!>   (each surface also gives the node set of the same name);
!> - a surface is a chain of element edges (Gmsh physical curve, Abaqus
!>   *SURFACE); each edge stores its nodes as (start, end, mid) ordered
!>   counter-clockwise around its parent element, so the outward normal is the
!>   tangent (end - start) turned clockwise.
module raccord_mesh
  use raccord_kinds, only: wp
  implicit none
  private

  integer, parameter, public :: ELEM_Q4 = 1   !< 4-node bilinear quadrilateral (Q1)
  integer, parameter, public :: ELEM_Q8 = 2   !< 8-node serendipity quadrilateral (Q2)
  integer, parameter, public :: MAX_NEN = 8   !< most nodes of any supported element

  !> Named set of nodes (internal indices, sorted, unique).
  type, public :: node_set_t
    character(len=:), allocatable :: name
    character(len=:), allocatable :: key    !< label the lookups compare (label_key); unset: name
    integer, allocatable :: nodes(:)
  end type node_set_t

  !> Named set of elements (internal indices).
  type, public :: elem_set_t
    character(len=:), allocatable :: name
    character(len=:), allocatable :: key    !< label the lookups compare (label_key); unset: name
    integer, allocatable :: elems(:)
  end type elem_set_t

  !> Named surface: element edges with their parent element and local side.
  type, public :: surface_t
    character(len=:), allocatable :: name
    character(len=:), allocatable :: key    !< label the lookups compare (label_key); unset: name
    integer :: nedge = 0
    integer :: nen_edge = 2                 !< 2 (Q4 edges) or 3 (Q8 edges)
    integer, allocatable :: edge(:,:)       !< (3, nedge): start, end, mid (0 for 2-node edges)
    integer, allocatable :: elem(:)         !< parent element of each edge
    integer, allocatable :: side(:)         !< local side 1..4 in the parent (1: nodes 1-2, ...)
  end type surface_t

  !> Whole mesh.
  type, public :: mesh_t
    character(len=:), allocatable :: source   !< file it was read from
    integer :: nnode = 0
    integer :: nelem = 0
    real(wp), allocatable :: x(:,:)           !< (2, nnode) coordinates
    integer, allocatable :: node_id(:)        !< file id of each node
    integer, allocatable :: etype(:)          !< ELEM_Q4 or ELEM_Q8 per element
    integer, allocatable :: conn(:,:)         !< (MAX_NEN, nelem) internal node indices, 0-padded
    integer, allocatable :: elem_id(:)        !< file id of each element
    type(node_set_t), allocatable :: nsets(:)
    type(elem_set_t), allocatable :: esets(:)
    type(surface_t), allocatable :: surfaces(:)
    !> axisymmetric element types of the file (Abaqus CAX4, CAX8, ...), read
    !> as Q4/Q8; the deck's hypothesis decides (raccord_model_build warns on
    !> a mismatch). '' when none.
    character(len=:), allocatable :: axi_types
    !> set and surface names follow Abaqus's label rule (an unquoted label
    !> is read without regard to case, a quoted one exactly: label_key);
    !> Gmsh names compare exactly (doc/mesh-formats.md, "Set and surface
    !> names")
    logical :: ignore_case = .false.
  end type mesh_t

  public :: nodes_per_element, element_name
  public :: find_node_set, find_elem_set, find_surface, side_nodes, label_key, unquoted_key, case_kept

contains

  !> Number of nodes of an element type (0 for an unknown type).
  pure integer function nodes_per_element(etype)
    integer, intent(in) :: etype
    select case (etype)
    case (ELEM_Q4); nodes_per_element = 4
    case (ELEM_Q8); nodes_per_element = 8
    case default;   nodes_per_element = 0
    end select
  end function nodes_per_element

  !> Short name of an element type for messages and logs.
  pure function element_name(etype) result(s)
    integer, intent(in) :: etype
    character(len=:), allocatable :: s
    select case (etype)
    case (ELEM_Q4); s = 'Q4'
    case (ELEM_Q8); s = 'Q8'
    case default;   s = 'unknown'
    end select
  end function element_name

  !> Local node numbers (start, end, mid) of side 1..4 of an element type;
  !> mid is 0 for Q4. Counter-clockwise, so the outward normal is the
  !> tangent turned clockwise.
  pure function side_nodes(etype, side) result(loc)
    integer, intent(in) :: etype, side
    integer :: loc(3)
    integer, parameter :: corner(2, 4) = reshape([1, 2, 2, 3, 3, 4, 4, 1], [2, 4])
    loc(1:2) = corner(:, side)
    loc(3) = 0
    if (etype == ELEM_Q8) loc(3) = 4 + side
  end function side_nodes

  !> The label a set name stands for in an Abaqus file (Abaqus Analysis
  !> User's Guide, "Input syntax rules", Labels): a label in double quotes
  !> is taken as written, case and blanks included; any other label is read
  !> without regard to case and with its blanks ignored, i.e. as
  !> unquoted_key, its upper-case form without blanks. Gmsh names are
  !> their own key.
  pure function label_key(name, quoted) result(key)
    character(len=*), intent(in) :: name
    logical, intent(in) :: quoted
    character(len=:), allocatable :: key
    if (quoted) then
      key = name
    else
      key = unquoted_key(name)
    end if
  end function label_key

  !> Upper-case copy of an (ASCII) label without its blanks and tabs.
  pure function unquoted_key(name) result(key)
    character(len=*), intent(in) :: name
    character(len=:), allocatable :: key
    character(len=len(name)) :: buf
    integer :: k, n, c
    n = 0
    do k = 1, len(name)
      c = iachar(name(k:k))
      if (c == 32 .or. c == 9) cycle
      if (c >= iachar('a') .and. c <= iachar('z')) c = c - 32
      n = n + 1
      buf(n:n) = achar(c)
    end do
    key = buf(1:n)
  end function unquoted_key

  !> An Abaqus label whose case counts: it was given in double quotes and
  !> differs from its unquoted reading (a quoted "TOP" is the label TOP).
  pure logical function case_kept(key)
    character(len=*), intent(in) :: key
    case_kept = key /= unquoted_key(key)
  end function case_kept

  !> A name of the deck (trailing blanks ignored) names a set of key `key`
  !> in pass 1 when it is the key character for character, in pass 2
  !> (Abaqus only) when it reads as that key unquoted. The lookups try
  !> pass 1 on every set first, so on an Abaqus mesh with a quoted "top"
  !> and an unquoted top (the label TOP) the deck's 'top' is "top" and its
  !> 'TOP' or 'Top' is TOP, as a quoted or unquoted reference in the file
  !> would be; Gmsh names only ever match in pass 1 (exactly).
  pure logical function name_matches(mesh, key, name, pass)
    type(mesh_t), intent(in) :: mesh
    character(len=*), intent(in) :: key, name
    integer, intent(in) :: pass
    if (pass == 1) then
      name_matches = key == trim(name)
    else
      name_matches = mesh%ignore_case
      if (name_matches) name_matches = key == unquoted_key(trim(name))
    end if
  end function name_matches

  !> Index of the node set with that name (name_matches), or 0.
  pure integer function find_node_set(mesh, name)
    type(mesh_t), intent(in) :: mesh
    character(len=*), intent(in) :: name
    integer :: k, pass
    find_node_set = 0
    if (.not. allocated(mesh%nsets)) return
    do pass = 1, 2
      do k = 1, size(mesh%nsets)
        if (name_matches(mesh, set_key(mesh, mesh%nsets(k)%name, mesh%nsets(k)%key), name, pass)) then
          find_node_set = k
          return
        end if
      end do
    end do
  end function find_node_set

  !> Index of the element set with that name (name_matches), or 0.
  pure integer function find_elem_set(mesh, name)
    type(mesh_t), intent(in) :: mesh
    character(len=*), intent(in) :: name
    integer :: k, pass
    find_elem_set = 0
    if (.not. allocated(mesh%esets)) return
    do pass = 1, 2
      do k = 1, size(mesh%esets)
        if (name_matches(mesh, set_key(mesh, mesh%esets(k)%name, mesh%esets(k)%key), name, pass)) then
          find_elem_set = k
          return
        end if
      end do
    end do
  end function find_elem_set

  !> Index of the surface with that name (name_matches), or 0.
  pure integer function find_surface(mesh, name)
    type(mesh_t), intent(in) :: mesh
    character(len=*), intent(in) :: name
    integer :: k, pass
    find_surface = 0
    if (.not. allocated(mesh%surfaces)) return
    do pass = 1, 2
      do k = 1, size(mesh%surfaces)
        if (name_matches(mesh, set_key(mesh, mesh%surfaces(k)%name, mesh%surfaces(k)%key), name, pass)) then
          find_surface = k
          return
        end if
      end do
    end do
  end function find_surface

  !> A set's key; a set built in memory without one has its name read as
  !> the mesh's rule reads a name (unquoted, on an Abaqus mesh).
  pure function set_key(mesh, name, key) result(s)
    type(mesh_t), intent(in) :: mesh
    character(len=:), allocatable, intent(in) :: name, key
    character(len=:), allocatable :: s
    if (allocated(key)) then
      s = key
    else if (.not. allocated(name)) then
      s = ''
    else if (mesh%ignore_case) then
      s = unquoted_key(name)
    else
      s = name
    end if
  end function set_key
end module raccord_mesh
