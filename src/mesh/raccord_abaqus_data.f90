!> The data lines of an Abaqus / CalculiX .inp file (module header of
!> raccord_abaqus_reader): nodes, elements, set entries and GENERATE
!> ranges, surface faces. Moved verbatim from raccord_abaqus_reader.
submodule (raccord_abaqus_reader) raccord_abaqus_data
  implicit none

contains

  !> A data line of the current block.
  module procedure take_data
    integer, allocatable :: f(:), l(:)
    integer :: nf, id, k, a
    integer :: conn(8)
    real(wp) :: xy(2), z
    character(len=:), allocatable :: at

    at = loc_text(d, sl)
    call split_fields(sl%text, ',', f, l, nf)
    select case (st%block)
    case (BLK_NONE)
      call raise_error(err, EXIT_INPUT, at // ': data line before any keyword: start the file with a ' // &
        'keyword line such as *NODE')
    case (BLK_SKIP)
      return
    case (BLK_NODE)
      if (nf < 3 .or. nf > 4) then
        call raise_error(err, EXIT_INPUT, at // ': a *NODE line is "id, x, y[, z]", found ' // str(nf) // ' fields')
        return
      end if
      call field_int(sl, d, f, l, 1, 'node id', id, err)
      call field_real(sl, d, f, l, 2, 'x', xy(1), err)
      call field_real(sl, d, f, l, 3, 'y', xy(2), err)
      z = 0.0_wp
      ! an empty fourth field is z = 0, as Abaqus reads empty fields
      if (nf == 4) then
        if (f(4) <= l(4)) then
          if (len_trim(sl%text(f(4):l(4))) > 0) call field_real(sl, d, f, l, 4, 'z', z, err)
        end if
      end if
      if (err%failed()) return
      call add_node(d, id, xy, sl%ifile, sl%line, z)
      if (st%set > 0) call add_member(d%nsets(st%set), id, sl%ifile, sl%line)
    case (BLK_ELEMENT)
      if (nf /= 1 + st%nen) then
        call raise_error(err, EXIT_INPUT, at // ': an element of ' // st%keyword // ' needs its id and ' // &
          str(st%nen) // ' node ids, found ' // str(nf) // ' fields (continue a long line with a trailing comma)')
        return
      end if
      call field_int(sl, d, f, l, 1, 'element id', id, err)
      do a = 1, st%nen
        call field_int(sl, d, f, l, 1 + a, 'node id', conn(a), err)
      end do
      if (err%failed()) return
      call add_element(d, id, st%etype, conn(1:st%nen), sl%ifile, sl%line)
      if (st%set > 0) call add_member(d%esets(st%set), id, sl%ifile, sl%line)
    case (BLK_NSET, BLK_ELSET)
      if (st%generate) then
        call take_generate(sl, d, st, f, l, nf, err)
        return
      end if
      do k = 1, nf
        if (f(k) > l(k)) cycle
        call take_set_entry(sl, d, st, sl%text(f(k):l(k)), err)
        if (err%failed()) return
      end do
    case (BLK_SURFACE)
      call take_face(sl, d, st, f, l, nf, err)
    end select
  end procedure take_data

  !> "first, last[, step]" of a GENERATE set.
  subroutine take_generate(sl, d, st, f, l, nf, err)
    type(source_line_t), intent(in) :: sl
    type(mesh_draft_t), intent(inout) :: d
    type(abaqus_state_t), intent(in) :: st
    integer, intent(in) :: f(:), l(:), nf
    type(error_t), intent(inout) :: err
    integer :: first, last, step, id
    integer(i8) :: count, most
    integer(i8), parameter :: min_range = 10000000_i8
    if (nf < 2 .or. nf > 3) then
      call raise_error(err, EXIT_INPUT, loc_text(d, sl) // ': a GENERATE line is "first, last[, step]", found ' // &
        str(nf) // ' fields')
      return
    end if
    step = 1
    call field_int(sl, d, f, l, 1, 'first id', first, err)
    call field_int(sl, d, f, l, 2, 'last id', last, err)
    if (nf == 3) call field_int(sl, d, f, l, 3, 'step', step, err)
    if (err%failed()) return
    if (step <= 0 .or. last < first) then
      call raise_error(err, EXIT_INPUT, loc_text(d, sl) // ': GENERATE needs first <= last and step > 0, found ' // &
        str(first) // ', ' // str(last) // ', ' // str(step))
      return
    end if
    ! Every generated id must be a node or element defined in the files,
    ! each on a line of its own: a range longer than the items read so far
    ! and the bytes of the files can hold is a damaged count, refused before
    ! it is expanded (a range of two billion once ran out of memory). Files
    ! included later may hold the items: ranges up to min_range ids (some
    ! hundred MB at most) are always expanded.
    count = (int(last, i8) - int(first, i8))/int(step, i8) + 1_i8
    if (st%block == BLK_NSET) then
      most = max(int(d%nnode, i8), st%bytes_read/2_i8, min_range)
    else
      most = max(int(d%nelem, i8), st%bytes_read/2_i8, min_range)
    end if
    if (count > most) then
      call raise_error(err, EXIT_INPUT, loc_text(d, sl) // ': GENERATE ' // str(first) // ', ' // str(last) // &
        ', ' // str(step) // ' makes ' // str(count) // ' ids, more than the ' // str(most) // &
        ' a range may hold here (the larger of the items and lines read so far and 10^7): check the range')
      return
    end if
    do id = first, last, step
      if (st%block == BLK_NSET) then
        call add_member(d%nsets(st%set), id, sl%ifile, sl%line)
      else
        call add_member(d%esets(st%set), id, sl%ifile, sl%line)
      end if
    end do
  end subroutine take_generate

  !> One entry of an *NSET / *ELSET line: an id, or the name of a set of the
  !> same kind defined earlier (its members are copied in).
  subroutine take_set_entry(sl, d, st, entry, err)
    type(source_line_t), intent(in) :: sl
    type(mesh_draft_t), intent(inout) :: d
    type(abaqus_state_t), intent(in) :: st
    character(len=*), intent(in) :: entry
    type(error_t), intent(inout) :: err
    integer :: id, k, m
    integer, allocatable :: ids(:)
    logical :: ok
    call parse_int(entry, id, ok)
    ! Digits that do not fit an integer are an id (a set's label starts
    ! with a letter), not a set name: said so, as for the ids of *NODE and
    ! *ELEMENT, where "neither a node id nor a node set" was the message.
    if (.not. ok .and. beyond_int_range(entry)) then
      call raise_error(err, EXIT_INPUT, loc_text(d, sl) // ': the id ' // shown(entry) // ' in ' // st%keyword // &
        ' is ' // int_fault(entry) // ': check the entry, or renumber the mesh with ids below 2^31')
      return
    end if
    if (st%block == BLK_NSET) then
      if (ok) then
        call add_member(d%nsets(st%set), id, sl%ifile, sl%line)
        return
      end if
      k = find_group(d%nsets, d%nnset, d%nset_index, entry_key(entry))
      if (k == 0) then
        call raise_error(err, EXIT_INPUT, loc_text(d, sl) // ': ' // shown(entry) // ' in ' // st%keyword // &
          ' is neither a node id nor a node set defined above' // kind_note(d, entry, 'node') // &
          ': define the set with *NSET before this line')
        return
      end if
      ids = d%nsets(k)%id(1:d%nsets(k)%n)      ! copy: the target may be this very set
      do m = 1, size(ids)
        call add_member(d%nsets(st%set), ids(m), sl%ifile, sl%line)
      end do
    else
      if (ok) then
        call add_member(d%esets(st%set), id, sl%ifile, sl%line)
        return
      end if
      k = find_group(d%esets, d%neset, d%eset_index, entry_key(entry))
      if (k == 0) then
        call raise_error(err, EXIT_INPUT, loc_text(d, sl) // ': ' // shown(entry) // ' in ' // st%keyword // &
          ' is neither an element id nor an element set defined above' // kind_note(d, entry, 'elem') // &
          ': define the set with *ELSET (or ELSET= on *ELEMENT) before this line')
        return
      end if
      ids = d%esets(k)%id(1:d%esets(k)%n)
      do m = 1, size(ids)
        call add_member(d%esets(st%set), ids(m), sl%ifile, sl%line)
      end do
    end if
  end subroutine take_set_entry

  !> "element-or-elset, Sn" of an element-based *SURFACE.
  subroutine take_face(sl, d, st, f, l, nf, err)
    type(source_line_t), intent(in) :: sl
    type(mesh_draft_t), intent(inout) :: d
    type(abaqus_state_t), intent(in) :: st
    integer, intent(in) :: f(:), l(:), nf
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: at, target, face
    integer :: side, id, k, m
    integer, allocatable :: ids(:)
    logical :: ok
    at = loc_text(d, sl)
    if (nf /= 2) then
      call raise_error(err, EXIT_INPUT, at // ': a *SURFACE line is "element-or-elset, S1..S4", found ' // &
        str(nf) // ' field(s): give the face of each element (raccord does not guess free faces)')
      return
    end if
    target = sl%text(f(1):l(1))
    face = lower(sl%text(f(2):l(2)))
    side = 0
    select case (face)
    case ('s1'); side = 1
    case ('s2'); side = 2
    case ('s3'); side = 3
    case ('s4'); side = 4
    case default
      call raise_error(err, EXIT_INPUT, at // ': face "' // clip(sl%text(f(2):l(2))) // '" is not a side of a ' // &
        'quadrilateral: use S1 (nodes 1-2), S2 (2-3), S3 (3-4) or S4 (4-1)')
      return
    end select
    call parse_int(target, id, ok)
    if (ok) then
      call add_edge_by_side(d%surfaces(st%surf), id, side, sl%ifile, sl%line)
      return
    end if
    k = find_group(d%esets, d%neset, d%eset_index, entry_key(target))
    if (k == 0) then
      call raise_error(err, EXIT_INPUT, at // ': *SURFACE "' // clip(d%surfaces(st%surf)%name) // &
        '" uses element set ' // shown(target) // ', which is undefined' // kind_note(d, target, 'elem') // &
        ': define it with *ELSET (or ELSET= on *ELEMENT) before the surface, or correct the name')
      return
    end if
    ids = d%esets(k)%id(1:d%esets(k)%n)
    do m = 1, size(ids)
      call add_edge_by_side(d%surfaces(st%surf), ids(m), side, sl%ifile, sl%line)
    end do
  end subroutine take_face

  !> What else `name` is, when it is not a set of the kind wanted ('node' or
  !> 'elem'): ' ("x" is an element set here)', or for a quoted name the
  !> unquoted set of its letters ("disc_row" when the set is DISC_ROW), or
  !> '' (raccord_mesh_names does the same for the deck's names).
  function kind_note(d, name, want) result(s)
    type(mesh_draft_t), intent(in) :: d
    character(len=*), intent(in) :: name, want
    character(len=:), allocatable :: s
    character(len=:), allocatable :: key
    integer :: k
    s = ''
    if (want == 'node') then
      if (d%neset > 0) then
        if (find_group(d%esets, d%neset, d%eset_index, entry_key(name)) > 0) &
          s = ' (' // shown(name) // ' is an element set here)'
      end if
    else
      if (d%nnset > 0) then
        if (find_group(d%nsets, d%nnset, d%nset_index, entry_key(name)) > 0) &
          s = ' (' // shown(name) // ' is a node set here)'
      end if
    end if
    if (len(s) == 0 .and. find_draft_surface(d, entry_key(name)) > 0) s = ' (' // shown(name) // ' is a surface here)'
    ! a quoted name in another case than the unquoted set it may mean
    key = entry_key(name)
    if (len(s) > 0 .or. key == unquoted_key(key)) return
    k = 0
    if (want == 'node' .and. d%nnset > 0) k = find_group(d%nsets, d%nnset, d%nset_index, unquoted_key(key))
    if (want /= 'node' .and. d%neset > 0) k = find_group(d%esets, d%neset, d%eset_index, unquoted_key(key))
    if (k > 0) s = ' (in double quotes a label keeps its case; the set here is the unquoted label ' // &
      clip(unquoted_key(key)) // ': write it without the quotes)'
  end function kind_note

  !> The label an entry of a data line names: "x" in double quotes as
  !> written, anything else as an unquoted label (label_key).
  pure function entry_key(entry) result(key)
    character(len=*), intent(in) :: entry
    character(len=:), allocatable :: key
    integer :: n
    n = len_trim(entry)
    key = label_key(entry(1:n), .false.)
    if (n >= 2) then
      if (entry(1:1) == '"' .and. entry(n:n) == '"') key = label_key(entry(2:n - 1), .true.)
    end if
  end function entry_key

  !> An entry of a data line for a message: in double quotes, once.
  pure function shown(entry) result(s)
    character(len=*), intent(in) :: entry
    character(len=:), allocatable :: s
    integer :: n
    n = len_trim(entry)
    s = '"' // clip(entry(1:n)) // '"'
    if (n >= 2) then
      if (entry(1:1) == '"' .and. entry(n:n) == '"') s = '"' // clip(entry(2:n - 1)) // '"'
    end if
  end function shown

  subroutine field_int(sl, d, f, l, k, what, value, err)
    type(source_line_t), intent(in) :: sl
    type(mesh_draft_t), intent(in) :: d
    integer, intent(in) :: f(:), l(:), k
    character(len=*), intent(in) :: what
    integer, intent(out) :: value
    type(error_t), intent(inout) :: err
    logical :: ok
    value = 0
    if (err%failed()) return
    ok = .false.
    if (f(k) <= l(k)) call parse_int(sl%text(f(k):l(k)), value, ok)
    if (.not. ok) call raise_error(err, EXIT_INPUT, loc_text(d, sl) // ': field ' // str(k) // ' (' // what // &
      ') is "' // clip(sl%text(f(k):l(k))) // '", ' // int_fault(sl%text(f(k):l(k))))
  end subroutine field_int

  subroutine field_real(sl, d, f, l, k, what, value, err)
    type(source_line_t), intent(in) :: sl
    type(mesh_draft_t), intent(in) :: d
    integer, intent(in) :: f(:), l(:), k
    character(len=*), intent(in) :: what
    real(wp), intent(out) :: value
    type(error_t), intent(inout) :: err
    logical :: ok
    value = 0.0_wp
    if (err%failed()) return
    ok = .false.
    if (f(k) <= l(k)) call parse_real(sl%text(f(k):l(k)), value, ok)
    if (.not. ok) call raise_error(err, EXIT_INPUT, loc_text(d, sl) // ': field ' // str(k) // ' (' // what // &
      ') is "' // clip(sl%text(f(k):l(k))) // '", not a number')
  end subroutine field_real
end submodule raccord_abaqus_data
