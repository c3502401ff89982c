!> Messages about the mesh's set and surface names, for the lookups of the
!> deck's names (raccord_model_build, raccord_contact_surface): what a
!> name that is not of the kind asked for is instead, the near miss by
!> case in a Gmsh mesh (whose names compare exactly) or of a quoted Abaqus
!> label (which keeps its case), and the names of one kind, listed up to
!> MAX_LISTED (a quoted Abaqus label in its double quotes). Lookups themselves are raccord_mesh's
!> find_* (doc/mesh-formats.md, "Set and surface names").
module raccord_mesh_names
  use raccord_strings, only: str, lower, clipped
  use raccord_mesh, only: mesh_t, find_node_set, find_elem_set, find_surface, case_kept, unquoted_key
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

  !> A Gmsh mesh compares names exactly, and so does an Abaqus mesh for a
  !> label given in double quotes: a name of the mesh that differs from
  !> `name` only by case (for Abaqus: by case or blanks, a quoted label) is
  !> named, with its kind. '' when none.
  function case_hint(mesh, name) result(s)
    type(mesh_t), intent(in) :: mesh
    character(len=*), intent(in) :: name
    character(len=:), allocatable :: s
    integer :: k
    s = ''
    if (allocated(mesh%surfaces)) then
      do k = 1, size(mesh%surfaces)
        if (.not. near(mesh%surfaces(k)%name, mesh%surfaces(k)%key)) cycle
        s = hint(mesh%surfaces(k)%name, kind_text(mesh, 'surface'))
        return
      end do
    end if
    if (allocated(mesh%esets)) then
      do k = 1, size(mesh%esets)
        if (.not. near(mesh%esets(k)%name, mesh%esets(k)%key)) cycle
        s = hint(mesh%esets(k)%name, kind_text(mesh, 'elem'))
        return
      end do
    end if
    if (allocated(mesh%nsets)) then
      do k = 1, size(mesh%nsets)
        if (.not. near(mesh%nsets(k)%name, mesh%nsets(k)%key)) cycle
        s = hint(mesh%nsets(k)%name, kind_text(mesh, 'node'))
        return
      end do
    end if
  contains
    !> The set (of that spelling and key) is a near miss of `name`.
    logical function near(set_name, key)
      character(len=:), allocatable, intent(in) :: set_name, key
      near = .false.
      if (.not. allocated(set_name)) return
      if (mesh%ignore_case) then
        if (.not. allocated(key)) return
        near = case_kept(key) .and. unquoted_key(key) == unquoted_key(trim(name))
      else
        near = lower(set_name) == lower(trim(name))
      end if
    end function near
    function hint(found, what) result(h)
      character(len=*), intent(in) :: found, what
      character(len=:), allocatable :: h
      if (mesh%ignore_case) then
        h = ' (Abaqus keeps the case of a label in double quotes: the mesh has "' // clipped(found, 60) // '", ' // &
          what // '; write it in the deck in that case, ''' // clipped(found, 60) // ''')'
      else
        h = ' (Gmsh names are case-sensitive: the mesh has ''' // clipped(found, 60) // ''', ' // what // &
          '; write the name as the mesh spells it)'
      end if
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
          s = s // merge(', ', '  ', k > 1) // listed(mesh, mesh%nsets(k)%name, mesh%nsets(k)%key)
        end do
      end if
    case ('elem')
      if (allocated(mesh%esets)) then
        n = size(mesh%esets)
        do k = 1, min(n, MAX_LISTED)
          s = s // merge(', ', '  ', k > 1) // listed(mesh, mesh%esets(k)%name, mesh%esets(k)%key)
        end do
      end if
    case default
      if (allocated(mesh%surfaces)) then
        n = size(mesh%surfaces)
        do k = 1, min(n, MAX_LISTED)
          s = s // merge(', ', '  ', k > 1) // listed(mesh, mesh%surfaces(k)%name, mesh%surfaces(k)%key)
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

  !> A set's name as listed: a quoted Abaqus label (one whose case counts)
  !> in its double quotes, so that "top" and top (TOP) read apart.
  pure function listed(mesh, name, key) result(s)
    type(mesh_t), intent(in) :: mesh
    character(len=:), allocatable, intent(in) :: name, key
    character(len=:), allocatable :: s
    s = ''
    if (allocated(name)) s = clipped(name, 60)
    if (.not. mesh%ignore_case .or. .not. allocated(key)) return
    if (case_kept(key)) s = '"' // s // '"'
  end function listed

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
