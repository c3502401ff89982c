!> The keyword lines of an Abaqus / CalculiX .inp file (module header of
!> raccord_abaqus_reader): which block a keyword opens, its parameters,
!> *INCLUDE, and the keywords refused. Moved verbatim from
!> raccord_abaqus_reader.
submodule (raccord_abaqus_reader) raccord_abaqus_keywords
  implicit none

contains

  !> A keyword line opens a block (or includes a file).
  module procedure take_keyword
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
  end procedure take_keyword

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
end submodule raccord_abaqus_keywords
