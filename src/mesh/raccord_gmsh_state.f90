!> What the Gmsh reader has learnt from a file's sections (its version,
!> physical names, entities), the element types it reads, and how one
!> element goes into the draft with its physical groups: the part both
!> versions' section readers (raccord_gmsh_v41, raccord_gmsh_v22) share.
module raccord_gmsh_state
  use raccord_kinds, only: i8
  use raccord_error, only: error_t, raise_error, EXIT_INPUT
  use raccord_strings, only: str
  use raccord_mesh, only: ELEM_Q4, ELEM_Q8
  use raccord_int_map, only: int_map_t, map_insert, map_get, pair_key
  use raccord_text_reader, only: text_file_t, here
  use raccord_mesh_draft, only: mesh_draft_t, add_element, add_group, add_member, add_draft_surface, &
    add_edge_by_nodes
  implicit none
  private

  public :: gmsh_state_t, name_holder_t
  public :: GMSH_LINE2, GMSH_QUAD4, GMSH_LINE3, GMSH_POINT, GMSH_QUAD8
  public :: take_element, physical_name, tag_key, gmsh_nodes, refuse_type

  integer, parameter :: GMSH_LINE2 = 1, GMSH_QUAD4 = 3, GMSH_LINE3 = 8, GMSH_POINT = 15, GMSH_QUAD8 = 16

  !> What the reader has learnt so far from the file's sections.
  type :: gmsh_state_t
    integer :: version = 0                    !< 41 or 22 once $MeshFormat is read
    integer :: ifile = 0
    logical :: seen_nodes = .false., seen_elements = .false.
    ! $PhysicalNames
    integer :: nname = 0
    integer, allocatable :: name_dim(:), name_tag(:)
    type(name_holder_t), allocatable :: names(:)
    !> (dim, tag) -> entry of names (tag_key), and per dimension the name
    !> -> entry (text_key): each element finds its groups' names, and each
    !> line is checked against the others, in O(1), not O(names)
    type(int_map_t) :: tag_index, name_index(0:2)
    ! $Entities (4.1): physical tags of entity (dim, tag), stored as a flat
    ! list of (dim, entity, physical) triples; entities are few.
    integer :: nent = 0
    integer, allocatable :: ent(:,:)          !< (3, nent)
    !> every entity of $Entities, with or without physical tags: tag_key(dim,
    !> tag) -> the line that defines it (an element block must name one)
    logical :: seen_entities = .false.
    type(int_map_t) :: entity_line
    ! 2.2: repeats of one element for several physical groups
    type(int_map_t) :: seen_quads
    !> every element id read so far (points, lines, quadrilaterals: one
    !> numbering in a Gmsh file) -> the line that defined it
    type(int_map_t) :: element_line
    !> the sections skipped as carrying no mesh data, for the log
    character(len=:), allocatable :: skipped
  end type gmsh_state_t

  type :: name_holder_t
    character(len=:), allocatable :: s
  end type name_holder_t

contains

  !> Put one element into the draft and its physical groups. Gmsh numbers
  !> the points, lines and quadrilaterals of a file in one sequence (2.2
  !> too: an element repeated for a second physical group takes a new id),
  !> so an id met twice is refused here, whatever the two elements' types.
  subroutine take_element(tf, st, d, id, gtype, nodes, phys, err)
    type(text_file_t), intent(in) :: tf
    type(gmsh_state_t), intent(inout) :: st
    type(mesh_draft_t), intent(inout) :: d
    integer, intent(in) :: id, gtype, nodes(:), phys(:)
    type(error_t), intent(inout) :: err
    integer :: p, k, a, existing, target_id, ends(3)
    character(len=:), allocatable :: name
    call map_insert(st%element_line, int(id, i8), tf%line_no, existing)
    if (existing /= 0) then
      call raise_error(err, EXIT_INPUT, here(tf) // ': duplicate element id ' // str(id) // &
        ' (first defined at line ' // str(existing) // '): a Gmsh file numbers its points, lines and ' // &
        'quadrilaterals in one sequence, each id once; the file was edited or concatenated: re-export the mesh')
      return
    end if
    select case (gtype)
    case (GMSH_QUAD4, GMSH_QUAD8)
      target_id = id
      if (st%version == 22) then
        ! MSH 2.2 repeats an element once per physical group, under a new id
        call map_insert(st%seen_quads, pair_key(nodes(1), nodes(3)), d%nelem + 1, existing)
        if (existing /= 0) then
          if (all(d%conn(1:size(nodes), existing) == nodes)) then
            target_id = d%elem_id(existing)
          end if
        end if
        if (existing == 0 .or. target_id == id) then
          if (gtype == GMSH_QUAD4) then
            call add_element(d, id, ELEM_Q4, nodes, st%ifile, tf%line_no)
          else
            call add_element(d, id, ELEM_Q8, nodes, st%ifile, tf%line_no)
          end if
        end if
      else if (gtype == GMSH_QUAD4) then
        call add_element(d, id, ELEM_Q4, nodes, st%ifile, tf%line_no)
      else
        call add_element(d, id, ELEM_Q8, nodes, st%ifile, tf%line_no)
      end if
      do p = 1, size(phys)
        name = physical_name(st, 2, phys(p))
        call add_group(d%esets, d%neset, d%eset_index, name, name, k)
        call add_member(d%esets(k), target_id, st%ifile, tf%line_no)
      end do
    case (GMSH_LINE2, GMSH_LINE3)
      ends = 0
      ends(1:size(nodes)) = nodes     ! Gmsh order: the two ends, then the middle
      do p = 1, size(phys)
        name = physical_name(st, 1, phys(p))
        call add_draft_surface(d, name, name, k)
        call add_edge_by_nodes(d%surfaces(k), ends, st%ifile, tf%line_no)
        call add_group(d%nsets, d%nnset, d%nset_index, name, name, k)
        do a = 1, size(nodes)
          call add_member(d%nsets(k), nodes(a), st%ifile, tf%line_no)
        end do
      end do
    case (GMSH_POINT)
      do p = 1, size(phys)
        name = physical_name(st, 0, phys(p))
        call add_group(d%nsets, d%nnset, d%nset_index, name, name, k)
        call add_member(d%nsets(k), nodes(1), st%ifile, tf%line_no)
      end do
    end select
  end subroutine take_element

  !> Name of physical group (dim, tag): its $PhysicalNames entry or the tag.
  function physical_name(st, dim, tag) result(name)
    type(gmsh_state_t), intent(in) :: st
    integer, intent(in) :: dim, tag
    character(len=:), allocatable :: name
    integer :: k
    k = map_get(st%tag_index, tag_key(dim, tag))
    if (k > 0 .and. k <= st%nname) then
      name = st%names(k)%s
      return
    end if
    name = str(tag)
  end function physical_name

  !> Map key of physical group (dim, tag), dim 0..2.
  pure integer(i8) function tag_key(dim, tag)
    integer, intent(in) :: dim, tag
    tag_key = int(tag, i8)*4_i8 + int(dim, i8)
  end function tag_key

  !> Nodes of the element types raccord reads; 0 for the others.
  pure integer function gmsh_nodes(gtype)
    integer, intent(in) :: gtype
    select case (gtype)
    case (GMSH_LINE2); gmsh_nodes = 2
    case (GMSH_QUAD4); gmsh_nodes = 4
    case (GMSH_LINE3); gmsh_nodes = 3
    case (GMSH_POINT); gmsh_nodes = 1
    case (GMSH_QUAD8); gmsh_nodes = 8
    case default;      gmsh_nodes = 0
    end select
  end function gmsh_nodes

  !> Refuse an element type, saying what it is and how to get quadrilaterals.
  subroutine refuse_type(tf, gtype, err)
    type(text_file_t), intent(in) :: tf
    integer, intent(in) :: gtype
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: what, fix
    character(len=*), parameter :: quads = 'remesh with quadrilaterals: Recombine Surface{...}; ' // &
      '(or Mesh.RecombineAll = 1), with Mesh.SubdivisionAlgorithm = 1 if triangles remain; ' // &
      'for Q8 use Mesh.ElementOrder = 2 and Mesh.SecondOrderIncomplete = 1'
    fix = quads
    select case (gtype)
    case (2);  what = '3-node triangle'
    case (9);  what = '6-node triangle'
    case (20:25); what = 'high-order triangle'
    case (10)
      what = '9-node quadrilateral'
      fix = 'for Q8 use Mesh.SecondOrderIncomplete = 1 (8-node serendipity quadrilaterals)'
    case (36, 37, 38)
      what = 'high-order quadrilateral'
      fix = 'use Mesh.ElementOrder = 1 (Q4), or 2 with Mesh.SecondOrderIncomplete = 1 (Q8)'
    case (26:28)
      what = 'high-order line'
      fix = 'use Mesh.ElementOrder = 1 (Q4), or 2 with Mesh.SecondOrderIncomplete = 1 (Q8)'
    case (4:7, 11:14, 17:19, 29:35)
      what = '3D element'
      fix = 'raccord is 2D: mesh in 2D (gmsh -2) and put only surfaces, curves and points in physical groups'
    case default
      what = 'element type ' // str(gtype)
    end select
    call raise_error(err, EXIT_INPUT, here(tf) // ': element type ' // str(gtype) // ' (' // what // &
      ') is not supported; raccord reads 4-node (type 3) and 8-node (type 16) quadrilaterals, ' // &
      'with lines (1, 8) and points (15) for physical groups: ' // fix)
  end subroutine refuse_type
end module raccord_gmsh_state
