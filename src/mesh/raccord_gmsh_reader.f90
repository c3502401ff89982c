!> Reader for Gmsh MSH files, ASCII versions 4.1 and 2.2.
!>
!> Format reference: Gmsh reference manual, section "MSH file format"
!> (4.1) and its "Legacy formats" appendix (2.2). What raccord takes:
!> - 4-node (type 3) and 8-node (type 16) quadrilaterals -> Q4 / Q8;
!> - physical surfaces -> element sets; physical curves (line elements,
!>   types 1 and 8) -> surfaces and node sets; physical points (type 15)
!>   -> node sets. An unnamed physical group is named by its tag.
!> In 4.1 an element's physical groups are those of its entity ($Entities);
!> in 2.2 each element line carries one physical tag, and an element in
!> several groups is written once per group under a new id, so a repeat
!> of an element (same nodes in the same order) is merged back into one.
!> Sections raccord does not use ($Periodic, $NodeData, ...) are skipped.
module raccord_gmsh_reader
  use raccord_kinds, only: wp, i8
  use raccord_error, only: error_t, raise_error, EXIT_INPUT
  use raccord_strings, only: str
  use raccord_mesh, only: ELEM_Q4, ELEM_Q8
  use raccord_int_map, only: int_map_t, map_init, map_insert, map_get, pair_key, text_key
  use raccord_text_reader, only: text_file_t, open_text_file, close_text_file, read_line, here, &
    split_fields, parse_int, parse_real, check_count, int_fault
  use raccord_mesh_draft, only: mesh_draft_t, add_file, add_node, add_element, add_group, add_member, &
    add_draft_surface, add_edge_by_nodes
  implicit none
  private

  public :: read_gmsh

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
  end type gmsh_state_t

  type :: name_holder_t
    character(len=:), allocatable :: s
  end type name_holder_t

contains

  !> Read a Gmsh MSH 4.1 or 2.2 ASCII file into the draft.
  subroutine read_gmsh(path, d, err)
    character(len=*), intent(in) :: path
    type(mesh_draft_t), intent(inout) :: d
    type(error_t), intent(inout) :: err
    type(text_file_t) :: tf
    type(gmsh_state_t) :: st
    character(len=:), allocatable :: line, t
    logical :: eof

    d%format_name = 'gmsh'
    call open_text_file(tf, path, err)
    if (err%failed()) return
    call add_file(d, path, st%ifile)
    allocate(st%name_dim(0), st%name_tag(0), st%names(0), st%ent(3, 0))
    call map_init(st%seen_quads, 1024)

    sections: do
      call read_line(tf, line, eof, err)
      if (err%failed() .or. eof) exit sections
      t = trim(adjustl(line))
      if (len(t) == 0) cycle sections
      if (st%version == 0 .and. t /= '$MeshFormat') then
        call raise_error(err, EXIT_INPUT, here(tf) // ': expected "$MeshFormat" at the start of a Gmsh ' // &
          'mesh file, found "' // clip(t) // '": is this a .msh file written by Gmsh?')
        exit sections
      end if
      if (t(1:1) /= '$') then
        call raise_error(err, EXIT_INPUT, here(tf) // ': expected a section header such as "$Nodes", found "' // &
          clip(t) // '": the previous section holds more data than its count says, or the file was edited')
        exit sections
      end if
      select case (t)
      case ('$MeshFormat')
        call read_mesh_format(tf, st, err)
      case ('$PhysicalNames')
        call read_physical_names(tf, st, err)
      case ('$Entities')
        if (st%version == 41) then
          call read_entities(tf, st, err)
        else
          call skip_section(tf, 'Entities', err)
        end if
      case ('$Nodes')
        st%seen_nodes = .true.
        if (st%version == 41) then
          call read_nodes_41(tf, st, d, err)
        else
          call read_nodes_22(tf, st, d, err)
        end if
      case ('$Elements')
        st%seen_elements = .true.
        if (st%version == 41) then
          call read_elements_41(tf, st, d, err)
        else
          call read_elements_22(tf, st, d, err)
        end if
      case default
        if (t == '$PartitionedEntities') then
          ! partitioned entities hide the physical groups of the elements
          call raise_error(err, EXIT_INPUT, here(tf) // ': the mesh is partitioned; raccord reads whole ' // &
            'meshes: save it unpartitioned (mesh without ' // &
            'PartitionMesh, or UnpartitionMesh before saving)')
        else if (t(1:min(4, len(t))) == '$End') then
          call raise_error(err, EXIT_INPUT, here(tf) // ': "' // t // '" closes no open section: ' // &
            'the file was edited or concatenated; re-export the mesh')
        else
          call skip_section(tf, t(2:), err)
        end if
      end select
      if (err%failed()) exit sections
    end do sections
    call close_text_file(tf)
    if (err%failed()) return

    if (st%version == 0) then
      call raise_error(err, EXIT_INPUT, path // ' is empty: expected a Gmsh mesh starting with $MeshFormat')
    else if (.not. (st%seen_nodes .and. st%seen_elements)) then
      call raise_error(err, EXIT_INPUT, path // ' has no $Nodes or no $Elements section (file ends at line ' // &
        str(tf%line_no) // '): the file is truncated or holds only geometry; mesh and save it again (gmsh -2)')
    end if
  end subroutine read_gmsh

  !> "$MeshFormat": version, file type (0 ASCII, 1 binary), data size.
  subroutine read_mesh_format(tf, st, err)
    type(text_file_t), intent(inout) :: tf
    type(gmsh_state_t), intent(inout) :: st
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: line, v
    integer, allocatable :: f(:), l(:)
    integer :: nf, ftype
    call next_data_line(tf, 'MeshFormat', 'the version line', 0, 0, line, f, l, nf, err)
    if (err%failed()) return
    if (nf < 3) then
      call raise_error(err, EXIT_INPUT, here(tf) // ': the $MeshFormat line needs "version file-type ' // &
        'data-size", found "' // clip(line) // '"')
      return
    end if
    v = line(f(1):l(1))
    if (v == '4.1') then
      st%version = 41
    else if (v(1:min(2, len(v))) == '2.') then
      st%version = 22
    else
      call raise_error(err, EXIT_INPUT, here(tf) // ': MSH version ' // v // ' is not read by raccord: ' // &
        'save as version 4.1 or 2.2 ASCII (Mesh.MshFileVersion = 4.1, or gmsh -format msh41)')
      return
    end if
    call get_int(tf, line, f, l, 2, 'file type', ftype, err)
    if (err%failed()) return
    if (ftype /= 0) then
      call raise_error(err, EXIT_INPUT, here(tf) // ': the mesh is saved in binary; raccord reads ' // &
        'ASCII meshes only: save as ASCII (Mesh.Binary = 0, or gmsh -bin 0)')
      return
    end if
    call expect_end(tf, 'MeshFormat', err)
  end subroutine read_mesh_format

  !> "$PhysicalNames": count, then lines 'dim tag "name"'.
  subroutine read_physical_names(tf, st, err)
    type(text_file_t), intent(inout) :: tf
    type(gmsh_state_t), intent(inout) :: st
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: line
    integer, allocatable :: f(:), l(:)
    integer :: nf, n, k, j, dim, tag, q1, q2, prev
    call read_count(tf, 'PhysicalNames', 'the number of names', n, err)
    if (err%failed()) return
    deallocate(st%name_dim, st%name_tag, st%names)
    allocate(st%name_dim(n), st%name_tag(n), st%names(n))
    call map_init(st%tag_index, n)
    do j = 0, 2
      call map_init(st%name_index(j), n)
    end do
    do k = 1, n
      call next_data_line(tf, 'PhysicalNames', 'name', k, n, line, f, l, nf, err)
      if (err%failed()) return
      call get_int(tf, line, f, l, 1, 'dimension', dim, err)
      call get_int(tf, line, f, l, 2, 'physical tag', tag, err)
      if (err%failed()) return
      q1 = index(line, '"')
      q2 = index(line, '"', back=.true.)
      ! A name the deck cannot reach would leave its group under its tag,
      ! and the deck's set "not found" far from the cause: refused here.
      if (dim < 0 .or. dim > 2) then
        call raise_error(err, EXIT_INPUT, here(tf) // ': physical group ' // str(tag) // ' has dimension ' // &
          str(dim) // '; a 2D mesh has groups of dimension 0 (points), 1 (curves) and 2 (surfaces): ' // &
          'mesh in 2D (gmsh -2) with the groups on points, curves and surfaces')
        return
      end if
      if (q1 == 0 .or. q2 == q1) then
        call raise_error(err, EXIT_INPUT, here(tf) // ': the name of physical group ' // str(tag) // &
          ' is not in double quotes (a line is: dimension tag "name"); re-export the mesh from Gmsh')
        return
      end if
      if (q2 == q1 + 1 .or. len_trim(line(q1 + 1:max(q1, q2 - 1))) == 0) then
        call raise_error(err, EXIT_INPUT, here(tf) // ': physical group ' // str(tag) // ' has an empty ' // &
          'name ""; give it a name in the .geo (Physical Curve("name") = {...};) or drop the line')
        return
      end if
      st%name_dim(k) = dim
      st%name_tag(k) = tag
      st%names(k)%s = line(q1 + 1:q2 - 1)
      j = map_get(st%tag_index, tag_key(dim, tag))
      if (j > 0) then
        if (st%name_dim(j) == dim .and. st%name_tag(j) == tag) then
          call raise_error(err, EXIT_INPUT, here(tf) // ': physical group ' // str(tag) // ' of dimension ' // &
            str(dim) // ' is named a second time ("' // clip(st%names(j)%s) // '" and "' // clip(st%names(k)%s) // &
            '"); keep one line per group')
          return
        end if
      end if
      call map_insert(st%tag_index, tag_key(dim, tag), k, prev)
      j = map_get(st%name_index(dim), text_key(st%names(k)%s))
      if (j > 0) then
        if (st%names(j)%s == st%names(k)%s) then
          call raise_error(err, EXIT_INPUT, here(tf) // ': the name "' // clip(st%names(k)%s) // '" is given to ' // &
            'two physical groups of dimension ' // str(dim) // ' (tags ' // str(st%name_tag(j)) // ' and ' // &
            str(tag) // '); a set name must be unique: rename one, or put both in one group')
          return
        end if
      end if
      call map_insert(st%name_index(dim), text_key(st%names(k)%s), k, prev)
    end do
    st%nname = n
    call expect_end(tf, 'PhysicalNames', err)
  end subroutine read_physical_names

  !> "$Entities" (4.1): which physical groups each point, curve and surface
  !> belongs to. Bounding boxes and boundary entities are not needed.
  subroutine read_entities(tf, st, err)
    type(text_file_t), intent(inout) :: tf
    type(gmsh_state_t), intent(inout) :: st
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: line
    integer, allocatable :: f(:), l(:), tmp(:,:)
    integer :: nf, counts(4), dim, k, tag, nphys, first, p, phys, prev
    call next_data_line(tf, 'Entities', 'the entity counts', 0, 0, line, f, l, nf, err)
    if (err%failed()) return
    do k = 1, 4
      call get_int(tf, line, f, l, k, 'entity count', counts(k), err)
    end do
    if (err%failed()) return
    st%seen_entities = .true.
    call map_init(st%entity_line, 16)
    do dim = 0, 3
      do k = 1, counts(dim + 1)
        call next_data_line(tf, 'Entities', 'entity of dimension ' // str(dim), k, counts(dim + 1), &
          line, f, l, nf, err)
        if (err%failed()) return
        call get_int(tf, line, f, l, 1, 'entity tag', tag, err)
        if (err%failed()) return
        ! Gmsh entity tags are positive and unique per dimension: a second
        ! definition would give the elements of its blocks the physical
        ! groups of both lines
        if (tag <= 0) then
          call raise_error(err, EXIT_INPUT, here(tf) // ': entity tag ' // str(tag) // ' (dimension ' // &
            str(dim) // ') is not positive; Gmsh tags start at 1: the file is damaged, re-export the mesh')
          return
        end if
        call map_insert(st%entity_line, tag_key(dim, tag), tf%line_no, prev)
        if (prev /= 0) then
          call raise_error(err, EXIT_INPUT, here(tf) // ': entity ' // str(tag) // ' of dimension ' // &
            str(dim) // ' is defined a second time (first at line ' // str(prev) // '); each ' // &
            'point, curve and surface is listed once: the file was edited or concatenated, re-export the mesh')
          return
        end if
        ! a point has x y z, the others a bounding box, before the physical count
        first = 5
        if (dim > 0) first = 8
        call get_int(tf, line, f, l, first, 'number of physical tags', nphys, err)
        if (err%failed()) return
        do p = 1, nphys
          call get_int(tf, line, f, l, first + p, 'physical tag', phys, err)
          if (err%failed()) return
          if (dim == 3) cycle
          if (st%nent == size(st%ent, 2)) then
            allocate(tmp(3, max(16, 2*st%nent)))
            tmp(:, 1:st%nent) = st%ent(:, 1:st%nent)
            call move_alloc(tmp, st%ent)
          end if
          st%nent = st%nent + 1
          st%ent(:, st%nent) = [dim, tag, phys]
        end do
        ! Curves and surfaces end with their bounding entities: a count and
        ! that many tags. A line whose counts do not add up has a wrong
        ! physical count, and its tags would be read as the wrong groups.
        if (dim > 0) then
          call get_int(tf, line, f, l, first + nphys + 1, 'number of bounding entities', p, err)
          if (err%failed()) return
          if (nf /= first + nphys + 1 + p) then
            call raise_error(err, EXIT_INPUT, here(tf) // ': entity ' // str(tag) // ' of dimension ' // &
              str(dim) // ' declares ' // str(nphys) // ' physical tag(s) and ' // str(p) // &
              ' bounding entities, but the line has ' // str(nf) // ' fields instead of ' // &
              str(first + nphys + 1 + p) // ': the file is damaged, re-export the mesh')
            return
          end if
        end if
      end do
    end do
    call expect_end(tf, 'Entities', err)
  end subroutine read_entities

  !> "$Nodes" (4.1): blocks of node tags followed by their coordinates.
  subroutine read_nodes_41(tf, st, d, err)
    type(text_file_t), intent(inout) :: tf
    type(gmsh_state_t), intent(in) :: st
    type(mesh_draft_t), intent(inout) :: d
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: line
    integer, allocatable :: f(:), l(:), tags(:), tag_line(:)
    integer :: nf, nblock, ntotal, nread, b, n, k, header_line, parametric
    real(wp) :: xy(2), z
    call next_data_line(tf, 'Nodes', 'the block and node counts', 0, 0, line, f, l, nf, err)
    if (err%failed()) return
    header_line = tf%line_no
    call get_int(tf, line, f, l, 1, 'number of blocks', nblock, err)
    call get_int(tf, line, f, l, 2, 'number of nodes', ntotal, err)
    if (err%failed()) return
    nread = 0
    do b = 1, nblock
      call next_data_line(tf, 'Nodes', 'block', b, nblock, line, f, l, nf, err)
      if (err%failed()) return
      call get_int(tf, line, f, l, 3, 'parametric flag', parametric, err)
      call get_int(tf, line, f, l, 4, 'number of nodes in block', n, err)
      call check_count(tf, n, 2, 'the number of nodes in block ' // str(b), err)
      if (err%failed()) return
      allocate(tags(n), tag_line(n))
      do k = 1, n
        call next_data_line(tf, 'Nodes', 'node tag', k, n, &
          line, f, l, nf, err)
        if (err%failed()) return
        call get_int(tf, line, f, l, 1, 'node tag', tags(k), err)
        if (err%failed()) return
        tag_line(k) = tf%line_no
      end do
      do k = 1, n
        call next_data_line(tf, 'Nodes', 'node coordinates', k, n, &
          line, f, l, nf, err)
        if (err%failed()) return
        call get_real(tf, line, f, l, 1, 'x', xy(1), err)
        call get_real(tf, line, f, l, 2, 'y', xy(2), err)
        z = 0.0_wp
        if (nf >= 3) call get_real(tf, line, f, l, 3, 'z', z, err)
        if (err%failed()) return
        call add_node(d, tags(k), xy, st%ifile, tag_line(k), z)
      end do
      nread = nread + n
      deallocate(tags, tag_line)
    end do
    if (nread /= ntotal) then
      call raise_error(err, EXIT_INPUT, tf%path // ':' // str(header_line) // ': $Nodes announces ' // &
        str(ntotal) // ' nodes but its blocks hold ' // str(nread) // &
        ': the counts do not match the data; re-export the mesh')
      return
    end if
    call expect_end(tf, 'Nodes', err)
  end subroutine read_nodes_41

  !> "$Nodes" (2.2): count, then 'id x y z' lines.
  subroutine read_nodes_22(tf, st, d, err)
    type(text_file_t), intent(inout) :: tf
    type(gmsh_state_t), intent(in) :: st
    type(mesh_draft_t), intent(inout) :: d
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: line
    integer, allocatable :: f(:), l(:)
    integer :: nf, n, k, id
    real(wp) :: xy(2), z
    call read_count(tf, 'Nodes', 'the number of nodes', n, err)
    if (err%failed()) return
    do k = 1, n
      call next_data_line(tf, 'Nodes', 'node', k, n, line, f, l, nf, err)
      if (err%failed()) return
      call get_int(tf, line, f, l, 1, 'node id', id, err)
      call get_real(tf, line, f, l, 2, 'x', xy(1), err)
      call get_real(tf, line, f, l, 3, 'y', xy(2), err)
      z = 0.0_wp
      if (nf >= 4) call get_real(tf, line, f, l, 4, 'z', z, err)
      if (err%failed()) return
      call add_node(d, id, xy, st%ifile, tf%line_no, z)
    end do
    call expect_end(tf, 'Nodes', err)
  end subroutine read_nodes_22

  !> "$Elements" (4.1): blocks of one element type on one entity.
  subroutine read_elements_41(tf, st, d, err)
    type(text_file_t), intent(inout) :: tf
    type(gmsh_state_t), intent(inout) :: st
    type(mesh_draft_t), intent(inout) :: d
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: line
    integer, allocatable :: f(:), l(:), phys(:)
    integer :: nf, nblock, ntotal, nread, b, n, k, a, header_line, edim, etag, gtype, nn, id
    integer :: nodes(8)
    call next_data_line(tf, 'Elements', 'the block and element counts', 0, 0, line, f, l, nf, err)
    if (err%failed()) return
    header_line = tf%line_no
    call get_int(tf, line, f, l, 1, 'number of blocks', nblock, err)
    call get_int(tf, line, f, l, 2, 'number of elements', ntotal, err)
    if (err%failed()) return
    nread = 0
    do b = 1, nblock
      call next_data_line(tf, 'Elements', 'block', b, nblock, line, f, l, nf, err)
      if (err%failed()) return
      call get_int(tf, line, f, l, 1, 'entity dimension', edim, err)
      call get_int(tf, line, f, l, 2, 'entity tag', etag, err)
      call get_int(tf, line, f, l, 3, 'element type', gtype, err)
      call get_int(tf, line, f, l, 4, 'number of elements in block', n, err)
      call check_count(tf, n, 1, 'the number of elements in block ' // str(b), err)
      if (err%failed()) return
      nn = gmsh_nodes(gtype)
      if (nn == 0) then
        call refuse_type(tf, gtype, err)
        return
      end if
      call check_block_entity(tf, st, edim, etag, gtype, err)
      if (err%failed()) return
      phys = pack(st%ent(3, 1:st%nent), st%ent(1, 1:st%nent) == edim .and. st%ent(2, 1:st%nent) == etag)
      do k = 1, n
        call next_data_line(tf, 'Elements', 'element', k, n, &
          line, f, l, nf, err)
        if (err%failed()) return
        if (nf /= 1 + nn) then
          call raise_error(err, EXIT_INPUT, here(tf) // ': an element of type ' // str(gtype) // ' needs its tag ' // &
            'and ' // str(nn) // ' node tags, found ' // str(nf) // ' fields: re-export the mesh')
          return
        end if
        call get_int(tf, line, f, l, 1, 'element tag', id, err)
        do a = 1, nn
          call get_int(tf, line, f, l, 1 + a, 'node tag', nodes(a), err)
        end do
        if (err%failed()) return
        call take_element(tf, st, d, id, gtype, nodes(1:nn), phys)
      end do
      nread = nread + n
    end do
    if (nread /= ntotal) then
      call raise_error(err, EXIT_INPUT, tf%path // ':' // str(header_line) // ': $Elements announces ' // &
        str(ntotal) // ' elements but its blocks hold ' // str(nread) // &
        ': the counts do not match the data; re-export the mesh')
      return
    end if
    call expect_end(tf, 'Elements', err)
  end subroutine read_elements_41

  !> A 4.1 element block takes the physical groups of its entity (edim,
  !> etag): the entity must be one of $Entities (above the block), and of
  !> the element type's dimension (a quadrilateral on a surface, a line on
  !> a curve, a point on a point); otherwise its elements would fall in
  !> no group, or in the groups of another dimension under their tags,
  !> and the deck's sets go "not found" far from the cause.
  subroutine check_block_entity(tf, st, edim, etag, gtype, err)
    type(text_file_t), intent(in) :: tf
    type(gmsh_state_t), intent(in) :: st
    integer, intent(in) :: edim, etag, gtype
    type(error_t), intent(inout) :: err
    integer :: tdim
    select case (gtype)
    case (GMSH_QUAD4, GMSH_QUAD8); tdim = 2
    case (GMSH_LINE2, GMSH_LINE3); tdim = 1
    case default;                  tdim = 0
    end select
    if (edim /= tdim) then
      call raise_error(err, EXIT_INPUT, here(tf) // ': a block of elements of type ' // str(gtype) // &
        ' (dimension ' // str(tdim) // ') on an entity of dimension ' // str(edim) // ' (field 1 of the ' // &
        'block line): each block holds the elements of one entity of their own dimension; the file ' // &
        'is damaged, re-export the mesh')
      return
    end if
    if (.not. st%seen_entities) then
      call raise_error(err, EXIT_INPUT, here(tf) // ': this element block belongs to entity ' // &
        str(etag) // ' of dimension ' // str(edim) // ', but no $Entities section comes before ' // &
        '$Elements: MSH 4.1 keeps the physical groups in $Entities; re-export the mesh from Gmsh')
      return
    end if
    if (etag <= 0) then
      call raise_error(err, EXIT_INPUT, here(tf) // ': element block on entity tag ' // str(etag) // &
        ' (field 2 of the block line): Gmsh tags start at 1; the file is damaged, re-export the mesh')
      return
    end if
    if (map_get(st%entity_line, tag_key(edim, etag)) == 0) then
      call raise_error(err, EXIT_INPUT, here(tf) // ': this element block belongs to entity ' // &
        str(etag) // ' of dimension ' // str(edim) // ' (field 2 of the block line), which $Entities ' // &
        'does not define: its elements would be in no physical group; the file was edited, re-export the mesh')
    end if
  end subroutine check_block_entity

  !> "$Elements" (2.2): count, then 'id type ntags tags... nodes...' lines.
  subroutine read_elements_22(tf, st, d, err)
    type(text_file_t), intent(inout) :: tf
    type(gmsh_state_t), intent(inout) :: st
    type(mesh_draft_t), intent(inout) :: d
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: line
    integer, allocatable :: f(:), l(:)
    integer :: nf, n, k, a, id, gtype, ntag, nn, phys
    integer :: nodes(8)
    call read_count(tf, 'Elements', 'the number of elements', n, err)
    if (err%failed()) return
    do k = 1, n
      call next_data_line(tf, 'Elements', 'element', k, n, line, f, l, nf, err)
      if (err%failed()) return
      call get_int(tf, line, f, l, 1, 'element id', id, err)
      call get_int(tf, line, f, l, 2, 'element type', gtype, err)
      call get_int(tf, line, f, l, 3, 'number of tags', ntag, err)
      if (err%failed()) return
      nn = gmsh_nodes(gtype)
      if (nn == 0) then
        call refuse_type(tf, gtype, err)
        return
      end if
      if (ntag < 0 .or. nf /= 3 + ntag + nn) then
        call raise_error(err, EXIT_INPUT, here(tf) // ': element ' // str(id) // ' of type ' // str(gtype) // &
          ' with ' // str(ntag) // ' tags needs ' // str(3 + ntag + nn) // ' fields, found ' // str(nf) // &
          ': re-export the mesh')
        return
      end if
      ! tags: physical group, elementary entity, [partitions]; only the first matters
      phys = 0
      if (ntag >= 1) call get_int(tf, line, f, l, 4, 'physical tag', phys, err)
      do a = 1, nn
        call get_int(tf, line, f, l, 3 + ntag + a, 'node id', nodes(a), err)
      end do
      if (err%failed()) return
      if (phys /= 0) then
        call take_element(tf, st, d, id, gtype, nodes(1:nn), [phys])
      else
        call take_element(tf, st, d, id, gtype, nodes(1:nn), [integer ::])
      end if
    end do
    call expect_end(tf, 'Elements', err)
  end subroutine read_elements_22

  !> Put one element into the draft and its physical groups.
  subroutine take_element(tf, st, d, id, gtype, nodes, phys)
    type(text_file_t), intent(in) :: tf
    type(gmsh_state_t), intent(inout) :: st
    type(mesh_draft_t), intent(inout) :: d
    integer, intent(in) :: id, gtype, nodes(:), phys(:)
    integer :: p, k, a, existing, target_id, ends(3)
    character(len=:), allocatable :: name
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

  !> Next line of a section's data, split at blanks. The end of the file or
  !> the next "$" line here means the counts promise more than the file holds.
  !> What is expected is "what" or, with n > 0, "what k of n" (built only
  !> for a message: this runs once per line of the file).
  subroutine next_data_line(tf, section, what, k, n, line, f, l, nf, err)
    type(text_file_t), intent(inout) :: tf
    character(len=*), intent(in) :: section, what
    integer, intent(in) :: k, n
    character(len=:), allocatable, intent(out) :: line
    integer, allocatable, intent(out) :: f(:), l(:)
    integer, intent(out) :: nf
    type(error_t), intent(inout) :: err
    logical :: eof
    nf = 0
    call read_line(tf, line, eof, err)
    if (err%failed()) return
    if (eof) then
      call raise_error(err, EXIT_INPUT, tf%path // ': the file ends inside $' // section // ' (after line ' // &
        str(tf%line_no) // ', expecting ' // expected(what, k, n) // ') and $End' // section // ' is missing: ' // &
        'the file is truncated; re-export the mesh')
      return
    end if
    if (len_trim(line) > 0) then
      if (adjustl(line) == '$End' // section .or. line(1:1) == '$') then
        call raise_error(err, EXIT_INPUT, here(tf) // ': $' // section // ' ends before ' // expected(what, k, n) // &
          ': the counts in the section do not match its data; re-export the mesh')
        return
      end if
    end if
    call split_fields(line, ' ', f, l, nf)
    ! Keep exactly the fields the line has: get_int/get_real test the field
    ! number against size(f), and a short (truncated) line must fail there
    ! rather than read the buffer's unused slots.
    f = f(1:nf)
    l = l(1:nf)
    if (nf == 0) then
      call raise_error(err, EXIT_INPUT, here(tf) // ': empty line in $' // section // ' where ' // &
        expected(what, k, n) // ' was expected: re-export the mesh')
    end if
  end subroutine next_data_line

  pure function expected(what, k, n) result(s)
    character(len=*), intent(in) :: what
    integer, intent(in) :: k, n
    character(len=:), allocatable :: s
    if (n > 0) then
      s = what // ' ' // str(k) // ' of ' // str(n)
    else
      s = what
    end if
  end function expected

  !> A section whose first data line is a single count.
  subroutine read_count(tf, section, what, n, err)
    type(text_file_t), intent(inout) :: tf
    character(len=*), intent(in) :: section, what
    integer, intent(out) :: n
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: line
    integer, allocatable :: f(:), l(:)
    integer :: nf
    n = 0
    call next_data_line(tf, section, what, 0, 0, line, f, l, nf, err)
    if (err%failed()) return
    call get_int(tf, line, f, l, 1, what, n, err)
    if (err%failed()) return
    call check_count(tf, n, 1, what, err)
  end subroutine read_count

  !> The line after a section's data must close it.
  subroutine expect_end(tf, section, err)
    type(text_file_t), intent(inout) :: tf
    character(len=*), intent(in) :: section
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: line
    logical :: eof
    do
      call read_line(tf, line, eof, err)
      if (err%failed()) return
      if (eof) then
        call raise_error(err, EXIT_INPUT, tf%path // ': the file ends after line ' // str(tf%line_no) // &
          ' without $End' // section // ': the file is truncated; re-export the mesh')
        return
      end if
      if (len_trim(line) > 0) exit
    end do
    if (trim(adjustl(line)) /= '$End' // section) then
      call raise_error(err, EXIT_INPUT, here(tf) // ': expected $End' // section // ', found "' // &
        clip(line) // '": $' // section // ' holds more data than its counts say; re-export the mesh')
    end if
  end subroutine expect_end

  !> Skip a section raccord does not use, up to its $End line.
  subroutine skip_section(tf, section, err)
    type(text_file_t), intent(inout) :: tf
    character(len=*), intent(in) :: section
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: line
    logical :: eof
    integer :: start
    start = tf%line_no
    do
      call read_line(tf, line, eof, err)
      if (err%failed()) return
      if (eof) then
        call raise_error(err, EXIT_INPUT, tf%path // ': section $' // section // ' opened at line ' // &
          str(start) // ' has no $End' // section // ': the file is truncated; re-export the mesh')
        return
      end if
      if (trim(adjustl(line)) == '$End' // section) return
    end do
  end subroutine skip_section

  !> Integer field k of a data line, or an error naming file, line and field.
  subroutine get_int(tf, line, f, l, k, what, value, err)
    type(text_file_t), intent(in) :: tf
    character(len=*), intent(in) :: line, what
    integer, intent(in) :: f(:), l(:), k
    integer, intent(out) :: value
    type(error_t), intent(inout) :: err
    logical :: ok
    value = 0
    if (err%failed()) return
    if (k > size(f) .or. k < 1) then
      call raise_error(err, EXIT_INPUT, here(tf) // ': the line ends before field ' // str(k) // ' (' // what // &
        '): "' // clip(line) // '"; the file is damaged, re-export the mesh')
      return
    end if
    if (f(k) > l(k)) ok = .false.
    if (f(k) <= l(k)) call parse_int(line(f(k):l(k)), value, ok)
    if (.not. ok) then
      call raise_error(err, EXIT_INPUT, here(tf) // ': field ' // str(k) // ' (' // what // ') is "' // &
        clip(line(f(k):l(k))) // '", ' // int_fault(line(f(k):l(k))) // ': the file is damaged, re-export the mesh')
    end if
  end subroutine get_int

  !> Real field k of a data line, or an error naming file, line and field.
  subroutine get_real(tf, line, f, l, k, what, value, err)
    type(text_file_t), intent(in) :: tf
    character(len=*), intent(in) :: line, what
    integer, intent(in) :: f(:), l(:), k
    real(wp), intent(out) :: value
    type(error_t), intent(inout) :: err
    logical :: ok
    value = 0.0_wp
    if (err%failed()) return
    if (k > size(f) .or. k < 1) then
      call raise_error(err, EXIT_INPUT, here(tf) // ': the line ends before field ' // str(k) // ' (' // what // &
        '): "' // clip(line) // '"; the file is damaged, re-export the mesh')
      return
    end if
    call parse_real(line(f(k):l(k)), value, ok)
    if (.not. ok) then
      call raise_error(err, EXIT_INPUT, here(tf) // ': field ' // str(k) // ' (' // what // ') is "' // &
        clip(line(f(k):l(k))) // '", not a number: the file is damaged, re-export the mesh')
    end if
  end subroutine get_real

  !> At most 60 characters of a line, for quoting it in a message.
  pure function clip(s) result(r)
    character(len=*), intent(in) :: s
    character(len=:), allocatable :: r
    if (len_trim(s) > 60) then
      r = s(1:57) // '...'
    else
      r = trim(s)
    end if
  end function clip
end module raccord_gmsh_reader
