!> Reader for the Abaqus / CalculiX .inp subset that describes a 2D mesh.
!>
!> Read: *NODE (id, x, y[, z]); *ELEMENT, TYPE=CPE4|CPS4|CPE8|CPS8 (and the
!> R variants, read as fully integrated; CAX4, CAX8 and their R variants
!> read as Q4/Q8 too, the deck's hypothesis deciding axisymmetry); *NSET and *ELSET (ids, set names,
!> or GENERATE ranges); *SURFACE, TYPE=ELEMENT with "elset-or-element, Sn"
!> faces; *INCLUDE, INPUT=file (textual, relative to the including file).
!> Other keywords are material, step or load data and are skipped: the
!> scene deck gives those; a keyword cut short that would read as one of
!> those above (*ELEM) is refused. Blanks on a keyword line are ignored. Keywords and parameters are case-insensitive;
!> set and surface names are Abaqus labels (raccord_mesh's label_key):
!> read without regard to case and blanks unless in double quotes, where
!> they are taken as written, so "top" and top (the label TOP) are two
!> sets; a set keeps the spelling of its first definition for messages.
!> A line ending with a comma continues on the next line.
!> Reference: Abaqus Keywords Reference Guide (input syntax rules) and the
!> CalculiX CrunchiX user's manual, section 8 (input deck format).
module raccord_abaqus_reader
  use raccord_kinds, only: wp, i8
  use raccord_error, only: error_t, raise_error, EXIT_INPUT
  use raccord_log, only: log_info
  use raccord_strings, only: str, lower, clipped
  use raccord_mesh, only: ELEM_Q4, ELEM_Q8, label_key, unquoted_key
  use raccord_int_map, only: int_map_t
  use raccord_text_reader, only: text_file_t, open_text_file, close_text_file, read_line, &
    split_fields, parse_int, parse_real, int_fault, beyond_int_range
  use raccord_mesh_draft, only: mesh_draft_t, draft_group_t, add_file, add_node, add_element, find_group, &
    add_group, add_member, add_draft_surface, find_draft_surface, add_edge_by_side
  implicit none
  private

  public :: read_abaqus

  integer, parameter :: BLK_NONE = 0, BLK_SKIP = 1, BLK_NODE = 2, BLK_ELEMENT = 3, BLK_NSET = 4, &
    BLK_ELSET = 5, BLK_SURFACE = 6
  !> The keywords whose data lines raccord reads (or follows), in full.
  character(len=*), parameter :: MESH_KEYWORDS(6) = [character(len=7) :: 'node', 'element', 'nset', &
    'elset', 'surface', 'include']
  !> Keywords that make or move nodes or elements, which raccord does not
  !> read: skipped as "no mesh data", the mesh read lacked their nodes and
  !> elements, or held the nodes where they are not. Refused, with what each does.
  character(len=*), parameter :: GEOMETRY_KEYWORDS(7) = [character(len=6) :: 'system', 'ngen', 'nfill', &
    'ncopy', 'nmap', 'elgen', 'elcopy']
  character(len=*), parameter :: GEOMETRY_WHAT(7) = [character(len=64) :: &
    'places the nodes that follow in a local coordinate system', 'generates nodes along a line', &
    'fills in nodes between two node sets', 'copies nodes', 'maps nodes to other coordinates', &
    'generates elements from a master element', 'copies elements']
  !> *INCLUDE nesting beyond this is taken for a file including itself.
  integer, parameter :: MAX_INCLUDE_DEPTH = 10
  character(len=*), parameter :: caller = 'read_abaqus'

  !> The keyword block the data lines belong to; it carries over *INCLUDE,
  !> whose file may hold just the data lines of the including block.
  type :: abaqus_state_t
    integer :: block = BLK_NONE
    character(len=:), allocatable :: keyword    !< as written, for messages
    integer :: etype = 0, nen = 0
    integer :: set = 0                         !< set filled by the block (NSET=, ELSET=), 0 if none
    integer :: surf = 0
    logical :: generate = .false.
    integer(i8) :: bytes_read = 0              !< sizes of the files opened so far (bounds GENERATE ranges)
    character(len=:), allocatable :: ignored   !< keywords skipped, for one log line
    character(len=:), allocatable :: reduced   !< reduced-integration types met
  end type abaqus_state_t

  !> A logical line: its text and where it starts.
  type :: source_line_t
    character(len=:), allocatable :: text
    integer :: ifile = 0, line = 0
  end type source_line_t

  ! The file's lines and their continuations (raccord_abaqus_lines), the
  ! keyword lines (raccord_abaqus_keywords) and the data lines
  ! (raccord_abaqus_data) are read in submodules of this one.
  interface
    !> Read one file of the input (the top one or an *INCLUDE), logical
    !> line by logical line (raccord_abaqus_lines).
    recursive module subroutine read_inp_file(path, d, st, depth, err)
      character(len=*), intent(in) :: path
      type(mesh_draft_t), intent(inout) :: d
      type(abaqus_state_t), intent(inout) :: st
      integer, intent(in) :: depth
      type(error_t), intent(inout) :: err
    end subroutine read_inp_file

    !> A keyword line opens a block (or includes a file).
    recursive module subroutine take_keyword(sl, path, d, st, depth, err)
      type(source_line_t), intent(in) :: sl
      character(len=*), intent(in) :: path
      type(mesh_draft_t), intent(inout) :: d
      type(abaqus_state_t), intent(inout) :: st
      integer, intent(in) :: depth
      type(error_t), intent(inout) :: err
    end subroutine take_keyword

    !> A data line of the current block.
    module subroutine take_data(sl, d, st, err)
      type(source_line_t), intent(in) :: sl
      type(mesh_draft_t), intent(inout) :: d
      type(abaqus_state_t), intent(inout) :: st
      type(error_t), intent(inout) :: err
    end subroutine take_data

    ! Used by the submodules, so separate module procedures, defined in
    ! raccord_abaqus_lines (gfortran emits no symbol for a private
    ! procedure of this module that its submodules call).
    !> At most 60 characters of a text of the file, for a message.
    pure module function clip(s) result(r)
      character(len=*), intent(in) :: s
      character(len=:), allocatable :: r
    end function clip

    module function loc_text(d, sl) result(s)
      type(mesh_draft_t), intent(in) :: d
      type(source_line_t), intent(in) :: sl
      character(len=:), allocatable :: s
    end function loc_text
  end interface

contains

  !> Read an .inp file (and its includes) into the draft.
  subroutine read_abaqus(path, d, err)
    character(len=*), intent(in) :: path
    type(mesh_draft_t), intent(inout) :: d
    type(error_t), intent(inout) :: err
    type(abaqus_state_t) :: st
    d%format_name = 'abaqus'
    st%ignored = ''
    st%reduced = ''
    st%keyword = ''
    call read_inp_file(path, d, st, 0, err)
    if (err%failed()) return
    if (len(st%ignored) > 0) call log_info(caller, 'skipped keywords that carry no mesh data (the scene ' // &
      'deck gives materials, steps and loads): ' // st%ignored)
    if (len(st%reduced) > 0) call log_info(caller, 'element types ' // st%reduced // ' read as Q4/Q8: ' // &
      'raccord integrates fully (2x2 / 3x3 Gauss points), there is no reduced integration')
  end subroutine read_abaqus

end module raccord_abaqus_reader
