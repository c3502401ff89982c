!> The MSH 4.1 sections: $Entities (the physical groups of each point,
!> curve and surface), and $Nodes and $Elements in entity blocks, each
!> element block taking the groups of its entity (Gmsh reference manual,
!> "MSH file format", version 4.1).
module raccord_gmsh_v41
  use raccord_kinds, only: wp
  use raccord_error, only: error_t, raise_error, EXIT_INPUT
  use raccord_strings, only: str
  use raccord_int_map, only: map_init, map_insert, map_get
  use raccord_text_reader, only: text_file_t, here, check_count
  use raccord_mesh_draft, only: mesh_draft_t, add_node
  use raccord_gmsh_state, only: gmsh_state_t, GMSH_LINE2, GMSH_QUAD4, GMSH_LINE3, GMSH_QUAD8, &
    take_element, tag_key, gmsh_nodes, refuse_type
  use raccord_gmsh_lines, only: next_data_line, expect_end, get_int, get_real
  implicit none
  private

  public :: read_entities, read_nodes_41, read_elements_41

contains

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
        call take_element(tf, st, d, id, gtype, nodes(1:nn), phys, err)
        if (err%failed()) return
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
end module raccord_gmsh_v41
