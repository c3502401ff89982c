!> Messages about the mesh's set and surface names, for the lookups of the
!> deck's names (raccord_model_build, raccord_contact_surface): what a
!> name that is not of the kind asked for is instead, the near miss by
!> case in a Gmsh mesh (whose names compare exactly), and the names of one
!> kind, listed up to MAX_LISTED. Lookups themselves are raccord_mesh's
!> find_* (doc/mesh-formats.md, "Set and surface names").
module raccord_mesh_names
  use raccord_strings, only: str, lower
  use raccord_mesh, only: mesh_t, find_node_set, find_elem_set, find_surface
  implicit none
  private

  public :: set_names, not_found_text, kind_text

  !> Names listed in a message; the others are counted.
  integer, parameter :: MAX_LISTED = 20

contains

  !> What a set of one kind ('node', 'elem', 'surface') is in the mesh's
  !> format, e.g. "a surface (Gmsh: a physical curve, dimension 1)".
  pure function kind_text(mesh, kind) result(s)
    type(mesh_t), intent(in) :: mesh
    character(len=*), intent(in) :: kind
    character(len=:), allocatable :: s
    select case (kind)
    case ('node')
      if (mesh%ignore_case) then
        s = 'a node set (Abaqus: *NSET or NSET= on *NODE)'
      else
        s = 'a node set (Gmsh: a physical point, dimension 0, or curve)'
      end if
    case ('elem')
      if (mesh%ignore_case) then
        s = 'an element set (Abaqus: *ELSET or ELSET= on *ELEMENT)'
      else
        s = 'an element set (Gmsh: a physical surface, dimension 2)'
      end if
    case default
      if (mesh%ignore_case) then
        s = 'a surface (Abaqus: *SURFACE, TYPE=ELEMENT)'
      else
        s = 'a surface (Gmsh: a physical curve, dimension 1)'
      end if
    end select
  end function kind_text

  !> Why `name` gives no set of kind `want` ('node', 'elem', 'surface', or
  !> 'node_or_surface' for a boundary condition), as the text that follows
  !> "<want> '<name>' ": either "is not ... in mesh M: it is <kinds>" or
  !> "not found in mesh M" (with the near miss by case in a Gmsh mesh),
  !> then "; <kind>s there: <names>".
  function not_found_text(mesh, name, want) result(s)
    type(mesh_t), intent(in) :: mesh
    character(len=*), intent(in) :: name, want
    character(len=:), allocatable :: s, other, list_kind
    logical :: is_node, is_elem, is_surf

    is_surf = find_surface(mesh, name) /= 0
    is_elem = find_elem_set(mesh, name) /= 0
    ! every surface also gives the node set of its name
    is_node = find_node_set(mesh, name) /= 0 .and. .not. is_surf
    other = ''
    select case (want)
    case ('elem')
      if (is_surf) other = kind_text(mesh, 'surface')
      if (is_node) other = kind_text(mesh, 'node')
      list_kind = 'elem'
    case ('node_or_surface')
      if (is_elem) other = kind_text(mesh, 'elem')
      list_kind = 'node'
    case default
      if (is_node) other = kind_text(mesh, 'node')
      if (is_elem) other = join(other, kind_text(mesh, 'elem'))
      list_kind = want
    end select
    if (len(other) > 0) then
      s = 'is not ' // want_text(want) // ' in mesh ' // source(mesh) // ': it is ' // other
    else
      s = 'not found in mesh ' // source(mesh) // case_hint(mesh, name)
    end if
    s = s // '; ' // plural(list_kind) // ' there: ' // set_names(mesh, list_kind)
  end function not_found_text

  pure function want_text(want) result(s)
    character(len=*), intent(in) :: want
    character(len=:), allocatable :: s
    select case (want)
    case ('node'); s = 'a node set'
    case ('elem'); s = 'an element set'
    case ('node_or_surface'); s = 'a node set or surface'
    case default; s = 'a surface'
    end select
  end function want_text

  pure function plural(kind) result(s)
    character(len=*), intent(in) :: kind
    character(len=:), allocatable :: s
    select case (kind)
    case ('node'); s = 'node sets'
    case ('elem'); s = 'element sets'
    case default; s = 'surfaces'
    end select
  end function plural

  pure function join(a, b) result(s)
    character(len=*), intent(in) :: a, b
    character(len=:), allocatable :: s
    if (len(a) == 0) then
      s = b
    else
      s = a // ' and ' // b
    end if
  end function join

  pure function source(mesh) result(s)
    type(mesh_t), intent(in) :: mesh
    character(len=:), allocatable :: s
    s = '(built in memory)'
    if (allocated(mesh%source)) s = mesh%source
  end function source

  !> A Gmsh mesh compares names exactly: a name of the mesh that differs
  !> from `name` only by case is named, with its kind. '' when none (and
  !> always for an Abaqus mesh, whose lookups ignore case).
  function case_hint(mesh, name) result(s)
    type(mesh_t), intent(in) :: mesh
    character(len=*), intent(in) :: name
    character(len=:), allocatable :: s
    character(len=:), allocatable :: key
    integer :: k
    s = ''
    if (mesh%ignore_case) return
    key = lower(trim(name))
    if (allocated(mesh%surfaces)) then
      do k = 1, size(mesh%surfaces)
        if (lower(mesh%surfaces(k)%name) /= key) cycle
        s = hint(mesh%surfaces(k)%name, kind_text(mesh, 'surface'))
        return
      end do
    end if
    if (allocated(mesh%esets)) then
      do k = 1, size(mesh%esets)
        if (lower(mesh%esets(k)%name) /= key) cycle
        s = hint(mesh%esets(k)%name, kind_text(mesh, 'elem'))
        return
      end do
    end if
    if (allocated(mesh%nsets)) then
      do k = 1, size(mesh%nsets)
        if (lower(mesh%nsets(k)%name) /= key) cycle
        s = hint(mesh%nsets(k)%name, kind_text(mesh, 'node'))
        return
      end do
    end if
  contains
    function hint(found, what) result(h)
      character(len=*), intent(in) :: found, what
      character(len=:), allocatable :: h
      h = ' (Gmsh names are case-sensitive: the mesh has ''' // found // ''', ' // what // &
        '; write the name as the mesh spells it)'
    end function hint
  end function case_hint

  !> Comma-separated names of the mesh's sets of one kind ('node', 'elem',
  !> 'surface'), the first MAX_LISTED of them and the count of the others.
  function set_names(mesh, kind) result(s)
    type(mesh_t), intent(in) :: mesh
    character(len=*), intent(in) :: kind
    character(len=:), allocatable :: s
    integer :: k, n
    s = ''
    n = 0
    select case (kind)
    case ('node')
      if (allocated(mesh%nsets)) then
        n = size(mesh%nsets)
        do k = 1, min(n, MAX_LISTED)
          s = s // merge(', ', '  ', k > 1) // mesh%nsets(k)%name
        end do
      end if
    case ('elem')
      if (allocated(mesh%esets)) then
        n = size(mesh%esets)
        do k = 1, min(n, MAX_LISTED)
          s = s // merge(', ', '  ', k > 1) // mesh%esets(k)%name
        end do
      end if
    case default
      if (allocated(mesh%surfaces)) then
        n = size(mesh%surfaces)
        do k = 1, min(n, MAX_LISTED)
          s = s // merge(', ', '  ', k > 1) // mesh%surfaces(k)%name
        end do
      end if
    end select
    s = trim(adjustl(s))
    if (n > MAX_LISTED) s = s // ', ... (' // str(n - MAX_LISTED) // ' more)'
    if (len(s) == 0) s = '(none)'
    ! The Gmsh reader names a physical group that $PhysicalNames does not
    ! name by its tag: say so, or "5, 6" reads like a mistake of raccord's.
    if (has_number_name(s)) s = s // ' (numbers: Gmsh physical groups ' // &
      'without a name in $PhysicalNames; name them in the .geo, e.g. Physical Surface("plate") = {1};, ' // &
      'or write the number in the deck)'
  end function set_names

  !> One of the comma-separated names of list s is a number.
  pure logical function has_number_name(s) result(yes)
    character(len=*), intent(in) :: s
    integer :: a, b
    yes = .false.
    a = 1
    do while (a <= len(s))
      b = index(s(a:), ',')
      if (b == 0) then
        b = len(s) + 1
      else
        b = a + b - 1
      end if
      if (len_trim(s(a:b - 1)) > 0) then
        if (verify(trim(adjustl(s(a:b - 1))), '0123456789') == 0) yes = .true.
      end if
      a = b + 1
    end do
  end function has_number_name
end module raccord_mesh_names
