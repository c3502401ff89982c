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

  recursive subroutine read_inp_file(path, d, st, depth, err)
    character(len=*), intent(in) :: path
    type(mesh_draft_t), intent(inout) :: d
    type(abaqus_state_t), intent(inout) :: st
    integer, intent(in) :: depth
    type(error_t), intent(inout) :: err
    type(text_file_t) :: tf
    type(source_line_t) :: sl
    character(len=:), allocatable :: pending, buf, grown
    integer :: ifile, pending_no, nb
    logical :: eof, have_pending

    call open_text_file(tf, path, err)
    if (err%failed()) return
    st%bytes_read = st%bytes_read + max(0_i8, tf%bytes)
    call add_file(d, path, ifile)
    have_pending = .false.
    pending_no = 0
    lines: do
      ! one logical line: a raw line plus the lines its trailing commas join
      if (have_pending) then
        sl%text = pending
        sl%line = pending_no
        have_pending = .false.
      else
        call next_raw_line(tf, sl%text, eof, err)
        if (err%failed() .or. eof) exit lines
        sl%line = tf%line_no
      end if
      sl%ifile = ifile
      if (ends_with_comma(sl%text)) then
        ! The joined text grows in a buffer of doubling size (nb in use):
        ! joining by concatenation copied it at every line, and data of
        ! 10^5 lines each ending with a comma took minutes.
        nb = len(sl%text)
        allocate(character(len=max(256, 2*nb)) :: buf)
        buf(1:nb) = sl%text
        do while (ends_with_comma(buf(1:nb)))
          call next_raw_line(tf, pending, eof, err)
          if (err%failed()) exit lines
          if (eof) exit
          if (pending(1:1) == '*') then
            ! a keyword cannot continue a line: the comma was only trailing
            have_pending = .true.
            pending_no = tf%line_no
            exit
          end if
          if (nb + 1 + len(pending) > len(buf)) then
            allocate(character(len=2*(nb + 1 + len(pending))) :: grown)
            grown(1:nb) = buf(1:nb)
            call move_alloc(grown, buf)
          end if
          buf(nb + 1:nb + 1 + len(pending)) = ' ' // pending
          nb = nb + 1 + len(pending)
        end do
        sl%text = buf(1:nb)
        deallocate(buf)
      end if
      if (sl%text(1:1) == '*') then
        call take_keyword(sl, path, d, st, depth, err)
      else
        call take_data(sl, d, st, err)
      end if
      if (err%failed()) exit lines
    end do lines
    call close_text_file(tf)
  end subroutine read_inp_file

  !> Next line that is neither blank nor a ** comment, left-adjusted and trimmed.
  subroutine next_raw_line(tf, text, eof, err)
    type(text_file_t), intent(inout) :: tf
    character(len=:), allocatable, intent(out) :: text
    logical, intent(out) :: eof
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: line
    do
      call read_line(tf, line, eof, err)
      if (err%failed() .or. eof) then
        text = ''
        eof = .true.
        return
      end if
      text = trim(adjustl(line))
      if (len(text) == 0) cycle
      if (len(text) >= 2) then
        if (text(1:2) == '**') cycle
      end if
      return
    end do
  end subroutine next_raw_line

  pure logical function ends_with_comma(s)
    character(len=*), intent(in) :: s
    ends_with_comma = .false.
    if (len_trim(s) > 0) ends_with_comma = s(len_trim(s):len_trim(s)) == ','
  end function ends_with_comma

  !> A keyword line opens a block (or includes a file).
  recursive subroutine take_keyword(sl, path, d, st, depth, err)
    type(source_line_t), intent(in) :: sl
    character(len=*), intent(in) :: path
    type(mesh_draft_t), intent(inout) :: d
    type(abaqus_state_t), intent(inout) :: st
    integer, intent(in) :: depth
    type(error_t), intent(inout) :: err
    integer, allocatable :: f(:), l(:)
    integer :: nf, k
    character(len=:), allocatable :: kw, at, name, typ, inc
    logical :: found, quoted

    call split_fields(sl%text, ',', f, l, nf)
    ! blanks on a keyword line are ignored (Abaqus, "Input syntax rules"):
    ! *N SET is *NSET
    kw = lower(unquoted_key(sl%text(2:l(1))))
    at = loc_text(d, sl)

    ! a '*' with no keyword after it (a comment is '**'): skipped as an
    ! unknown keyword, the data lines after it with it
    if (len(kw) == 0) then
      call raise_error(err, EXIT_INPUT, at // ': a keyword line without a keyword ("' // clip(trim(sl%text)) // &
        '"): write the keyword after the *, or ** for a comment line')
      return
    end if
    ! Parts and instances (Abaqus/CAE's default) place each part by its
    ! instance's translation and rotation, and number each part from 1;
    ! read flat, the geometry would be silently wrong. Refused.
    if (kw == 'part' .or. kw == 'instance' .or. kw == 'assembly') then
      call raise_error(err, EXIT_INPUT, at // ': *' // clip(sl%text(2:l(1))) // ': parts, instances and ' // &
        'assemblies are not read (instance transformations would be lost): write a flat input file ' // &
        '(Abaqus/CAE: Model > Edit Attributes > Do not use parts and assemblies in input files)')
      return
    end if
    ! Their closers: with *Part, *Instance and *Assembly refused above, an
    ! *End Part here closes nothing (a file cut out of a CAE export, its
    ! parts' nodes maybe lost with the cut); it was read past without a word.
    if (kw == 'endpart' .or. kw == 'endinstance' .or. kw == 'endassembly') then
      call raise_error(err, EXIT_INPUT, at // ': *' // clip(trim(adjustl(sl%text(2:l(1))))) // ' closes a *' // &
        clip(trim(adjustl(sl%text(index(lower(sl%text(1:l(1))), 'd') + 1:l(1))))) // ' that the file does ' // &
        'not open: remove the line (and check that no nodes or elements were lost where the file was cut)')
      return
    end if
    ! (a loop: gfortran's findloc missed a shorter character scalar)
    do k = 1, size(GEOMETRY_KEYWORDS)
      if (kw /= trim(GEOMETRY_KEYWORDS(k))) cycle
      call raise_error(err, EXIT_INPUT, at // ': *' // clip(trim(adjustl(sl%text(2:l(1))))) // ' ' // &
        trim(GEOMETRY_WHAT(k)) // ', which raccord does not read (the mesh would lack those nodes or elements, ' // &
        'or hold them elsewhere): write the input with every node and element listed in global x, y ' // &
        '(Abaqus/CAE and CalculiX cgx, send all abq, write it so)')
      return
    end do
    ! the keywords whose parameters raccord reads: each one once, and the
    ! named ones with their value (get_param takes the first of two and
    ! skips one without '=': ELSET=a, ELSET=b read as a, a bare ELSET as
    ! no set at all)
    do k = 1, size(MESH_KEYWORDS)
      if (kw /= trim(MESH_KEYWORDS(k))) cycle
      call check_params(sl%text, f, l, nf, at, err)
      if (err%failed()) return
    end do
    if (kw == 'include') then
      ! textual inclusion: the current block goes on into the included file,
      ! which may hold just its data lines
      call get_param(sl%text, f, l, nf, 'input', inc, found)
      if (.not. found .or. len(inc) == 0) then
        call raise_error(err, EXIT_INPUT, at // ': *INCLUDE needs INPUT=file')
        return
      end if
      if (depth >= MAX_INCLUDE_DEPTH) then
        call raise_error(err, EXIT_INPUT, at // ': *INCLUDE nested more than ' // str(MAX_INCLUDE_DEPTH) // &
          ' deep: does a file include itself?')
        return
      end if
      if (inc(1:1) /= '/') then
        k = index(path, '/', back=.true.)
        inc = path(1:k) // inc
      end if
      call read_inp_file(inc, d, st, depth + 1, err)
      if (err%failed()) then
        if (allocated(err%message)) err%message = err%message // ' (included from ' // at // ')'
      end if
      return
    end if

    st%keyword = '*' // clip(trim(adjustl(sl%text(2:l(1)))))
    st%set = 0
    st%surf = 0
    st%generate = has_flag(sl%text, f, l, nf, 'generate')

    if (kw == 'node' .or. kw == 'element' .or. kw == 'nset' .or. kw == 'elset') then
      call get_param(sl%text, f, l, nf, 'input', inc, found)
      if (found) then
        call raise_error(err, EXIT_INPUT, at // ': INPUT= on ' // st%keyword // ' is not supported: ' // &
          'write the data lines after the keyword, or use *INCLUDE, INPUT=' // clip(inc) // ' on the next line')
        return
      end if
    end if

    select case (kw)
    case ('node')
      st%block = BLK_NODE
      ! SYSTEM=C or S: the data lines hold cylindrical or spherical
      ! coordinates (Abaqus), which were read as x, y without a word
      call get_param(sl%text, f, l, nf, 'system', typ, found)
      if (found .and. lower(typ) /= 'r') then
        call raise_error(err, EXIT_INPUT, at // ': *NODE, SYSTEM=' // clip(typ) // ' gives the nodes in ' // &
          'cylindrical (C) or spherical (S) coordinates, which raccord does not convert: write the nodes in ' // &
          'Cartesian x, y (SYSTEM=R, the default)')
        return
      end if
      call get_param(sl%text, f, l, nf, 'nset', name, found, quoted)
      if (found) call add_named_group(d%nsets, d%nnset, d%nset_index, name, quoted, at // ': NSET=', st%set, err)
      if (err%failed()) return
    case ('element')
      st%block = BLK_ELEMENT
      call get_param(sl%text, f, l, nf, 'type', typ, found)
      if (.not. found) then
        call raise_error(err, EXIT_INPUT, at // ': *ELEMENT needs TYPE= (CPE4, CPS4, CAX4, CPE8, CPS8 or CAX8)')
        return
      end if
      call element_type(lower(typ), st%etype, st%nen, found)
      if (.not. found) then
        call raise_error(err, EXIT_INPUT, at // ': element TYPE=' // clip(typ) // ' is not supported; raccord ' // &
          'reads CPE4, CPS4, CAX4, CPE8, CPS8, CAX8 (and their R variants): ' // type_hint(lower(typ)))
        return
      end if
      if (index(lower(typ), 'cax') == 1) then
        if (.not. allocated(d%axi_types)) d%axi_types = ''
        if (index(d%axi_types, typ) == 0) d%axi_types = d%axi_types // merge(', ', '  ', len(d%axi_types) > 0) // typ
        d%axi_types = trim(adjustl(d%axi_types))
      end if
      if (lower(typ(len(typ):)) == 'r' .and. index(st%reduced, typ) == 0) then
        if (len(st%reduced) > 0) st%reduced = st%reduced // ', '
        st%reduced = st%reduced // typ
      end if
      call get_param(sl%text, f, l, nf, 'elset', name, found, quoted)
      if (found) call add_named_group(d%esets, d%neset, d%eset_index, name, quoted, at // ': ELSET=', st%set, err)
      if (err%failed()) return
    case ('nset', 'elset')
      call get_param(sl%text, f, l, nf, kw, name, found, quoted)
      if (.not. found .or. len(name) == 0) then
        call raise_error(err, EXIT_INPUT, at // ': ' // st%keyword // ' needs its name: ' // &
          st%keyword // ', ' // kw // '=name')
        return
      end if
      if (kw == 'nset') then
        ! *NSET, ELSET=...: the nodes of an element set, without data
        ! lines; read as an empty set, it was "set is empty" at the deck
        call get_param(sl%text, f, l, nf, 'elset', typ, found)
        if (found) then
          call raise_error(err, EXIT_INPUT, at // ': ' // st%keyword // ', ELSET=' // clip(typ) // ' (the ' // &
            'nodes of an element set) is not read: list the node ids on data lines after *NSET, NSET=' // &
            clip(name) // ', or use a *SURFACE on the elements'' faces')
          return
        end if
        st%block = BLK_NSET
        call add_named_group(d%nsets, d%nnset, d%nset_index, name, quoted, at // ': ' // st%keyword // ', NSET=', &
          st%set, err)
      else
        st%block = BLK_ELSET
        call add_named_group(d%esets, d%neset, d%eset_index, name, quoted, at // ': ' // st%keyword // ', ELSET=', &
          st%set, err)
      end if
      if (err%failed()) return
    case ('surface')
      st%block = BLK_SURFACE
      call get_param(sl%text, f, l, nf, 'name', name, found, quoted)
      if (.not. found .or. len(name) == 0) then
        call raise_error(err, EXIT_INPUT, at // ': *SURFACE needs its name: *SURFACE, NAME=name, TYPE=ELEMENT')
        return
      end if
      call get_param(sl%text, f, l, nf, 'type', typ, found)
      if (found .and. lower(typ) /= 'element') then
        call raise_error(err, EXIT_INPUT, at // ': *SURFACE, TYPE=' // clip(typ) // ' is not supported: ' // &
          'use TYPE=ELEMENT with "element-or-elset, S1..S4" lines (or a *NSET for a node set)')
        return
      end if
      if (.not. label_ok(name, quoted)) then
        call raise_error(err, EXIT_INPUT, at // ': *SURFACE, NAME="' // clip(name) // &
          '" is no label: give the surface a name of letters, digits or underscores')
        return
      end if
      call add_draft_surface(d, name, label_key(name, quoted), st%surf)
    case default
      ! Abaqus takes a keyword cut short (*ELEM for *ELEMENT) when no other
      ! keyword starts so; skipped here, its data lines would be lost
      ! unnoticed: refused, naming the keyword in full
      do k = 1, size(MESH_KEYWORDS)
        if (len(kw) < 3 .or. len(kw) >= len_trim(MESH_KEYWORDS(k))) cycle
        if (kw /= MESH_KEYWORDS(k)(1:len(kw))) cycle
        call raise_error(err, EXIT_INPUT, at // ': *' // clip(trim(adjustl(sl%text(2:l(1))))) // &
          ' reads as *' // unquoted_key(MESH_KEYWORDS(k)) // ' cut short; raccord reads keywords in full: ' // &
          'write *' // unquoted_key(MESH_KEYWORDS(k)))
        return
      end do
      st%block = BLK_SKIP
      if (index(', ' // lower(st%ignored) // ', ', ', ' // lower(st%keyword) // ', ') == 0) then
        if (len(st%ignored) > 0) st%ignored = st%ignored // ', '
        st%ignored = st%ignored // st%keyword
      end if
    end select
  end subroutine take_keyword

  !> A data line of the current block.
  subroutine take_data(sl, d, st, err)
    type(source_line_t), intent(in) :: sl
    type(mesh_draft_t), intent(inout) :: d
    type(abaqus_state_t), intent(inout) :: st
    type(error_t), intent(inout) :: err
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
  end subroutine take_data

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

  !> raccord element type and node count of an Abaqus element type.
  pure subroutine element_type(typ, etype, nen, found)
    character(len=*), intent(in) :: typ
    integer, intent(out) :: etype, nen
    logical, intent(out) :: found
    found = .true.
    select case (typ)
    case ('cpe4', 'cps4', 'cpe4r', 'cps4r', 'cax4', 'cax4r')
      etype = ELEM_Q4
      nen = 4
    case ('cpe8', 'cps8', 'cpe8r', 'cps8r', 'cax8', 'cax8r')
      etype = ELEM_Q8
      nen = 8
    case default
      etype = 0
      nen = 0
      found = .false.
    end select
  end subroutine element_type

  pure function type_hint(typ) result(s)
    character(len=*), intent(in) :: typ
    character(len=:), allocatable :: s
    if (index(typ, 'cpe3') == 1 .or. index(typ, 'cps3') == 1 .or. index(typ, 'cpe6') == 1 .or. &
        index(typ, 'cps6') == 1) then
      s = 'remesh with quadrilaterals'
    else if (index(typ, 'cax') == 1) then
      s = 'axisymmetric elements are read as CAX4, CAX8 (and CAX4R, CAX8R); remesh with those'
    else
      s = 'remesh with 4- or 8-node plane quadrilaterals'
    end if
  end function type_hint

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

  !> Index of the set of label `name` (label_key: its case ignored unless
  !> it was quoted), created empty when absent. A name that is no label
  !> (empty, or blanks only) is refused.
  subroutine add_named_group(groups, n, index, name, quoted, at, k, err)
    type(draft_group_t), allocatable, intent(inout) :: groups(:)
    integer, intent(inout) :: n
    type(int_map_t), intent(inout) :: index
    character(len=*), intent(in) :: name, at
    logical, intent(in) :: quoted
    integer, intent(out) :: k
    type(error_t), intent(inout) :: err
    k = 0
    if (.not. label_ok(name, quoted)) then
      call raise_error(err, EXIT_INPUT, at // '"' // clip(name) // '" is no label: give the set a name of ' // &
        'letters, digits or underscores')
      return
    end if
    call add_group(groups, n, index, name, label_key(name, quoted), k)
  end subroutine add_named_group

  !> A label has a character other than blanks (quoted) or than blanks and
  !> quotes (unquoted: Abaqus ignores its blanks).
  pure logical function label_ok(name, quoted)
    character(len=*), intent(in) :: name
    logical, intent(in) :: quoted
    if (quoted) then
      label_ok = len_trim(name) > 0
    else
      label_ok = verify(name, ' "' // achar(9)) > 0
    end if
  end function label_ok

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

  !> At most 60 characters of a text of the file, for a message.
  pure function clip(s) result(r)
    character(len=*), intent(in) :: s
    character(len=:), allocatable :: r
    r = clipped(s, 60)
  end function clip

  !> Value of parameter key (lower case) on a keyword line; quotes removed.
  subroutine get_param(text, f, l, nf, key, value, found, quoted)
    character(len=*), intent(in) :: text, key
    integer, intent(in) :: f(:), l(:), nf
    character(len=:), allocatable, intent(out) :: value
    logical, intent(out) :: found
    logical, intent(out), optional :: quoted   !< the value was in double quotes
    integer :: k, eq
    found = .false.
    value = ''
    if (present(quoted)) quoted = .false.
    do k = 2, nf
      if (f(k) > l(k)) cycle
      eq = index(text(f(k):l(k)), '=')
      if (eq == 0) cycle
      if (lower(trim(text(f(k):f(k) + eq - 2))) /= key) cycle
      value = trim(adjustl(text(f(k) + eq:l(k))))
      if (len(value) >= 2) then
        if (value(1:1) == '"' .and. value(len(value):len(value)) == '"') then
          value = value(2:len(value) - 1)
          if (present(quoted)) quoted = .true.
        end if
      end if
      found = .true.
      return
    end do
  end subroutine get_param

  !> A keyword line's parameters: each name at most once, and the names
  !> that take a value (VALUE_PARAMS) with one. Names are compared as
  !> Abaqus does, without regard to case and blanks.
  subroutine check_params(text, f, l, nf, at, err)
    character(len=*), intent(in) :: text, at
    integer, intent(in) :: f(:), l(:), nf
    type(error_t), intent(inout) :: err
    character(len=*), parameter :: VALUE_PARAMS(6) = [character(len=6) :: 'nset', 'elset', 'type', 'name', &
      'input', 'system']
    integer :: k, j
    character(len=:), allocatable :: name, other
    do k = 2, nf
      if (f(k) > l(k)) cycle
      name = param_name(text(f(k):l(k)))
      if (len(name) == 0) cycle
      if (index(text(f(k):l(k)), '=') == 0 .and. any(VALUE_PARAMS == name)) then
        call raise_error(err, EXIT_INPUT, at // ': parameter ' // clip(trim(adjustl(text(f(k):l(k))))) // &
          ' has no value: write ' // unquoted_key(name) // '=' // merge('file', 'name', name == 'input') // &
          ' (a name without its value was read as no ' // unquoted_key(name) // ' at all)')
        return
      end if
      do j = k + 1, nf
        if (f(j) > l(j)) cycle
        other = param_name(text(f(j):l(j)))
        if (other /= name) cycle
        call raise_error(err, EXIT_INPUT, at // ': parameter ' // unquoted_key(name) // ' is given twice (' // &
          clip(trim(adjustl(text(f(k):l(k))))) // ' and ' // clip(trim(adjustl(text(f(j):l(j))))) // &
          '); only the first was read: give it once')
        return
      end do
    end do
  contains
    !> The parameter's name, lower case, without blanks (before any '=').
    pure function param_name(field) result(key)
      character(len=*), intent(in) :: field
      character(len=:), allocatable :: key
      integer :: eq
      eq = index(field, '=')
      if (eq == 0) eq = len(field) + 1
      key = lower(unquoted_key(field(1:eq - 1)))
    end function param_name
  end subroutine check_params

  !> True when a keyword line carries the bare parameter key (lower case).
  logical function has_flag(text, f, l, nf, key)
    character(len=*), intent(in) :: text, key
    integer, intent(in) :: f(:), l(:), nf
    integer :: k
    has_flag = .false.
    do k = 2, nf
      if (f(k) > l(k)) cycle
      if (lower(text(f(k):l(k))) == key) has_flag = .true.
    end do
  end function has_flag

  function loc_text(d, sl) result(s)
    type(mesh_draft_t), intent(in) :: d
    type(source_line_t), intent(in) :: sl
    character(len=:), allocatable :: s
    s = d%files(sl%ifile)%path // ':' // str(sl%line)
  end function loc_text

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
end module raccord_abaqus_reader
