!> Located messages of the scene deck reader: every check that turns a bad
!> group or key into "<deck>:<line>: &<group> '<name>': <what is wrong>;
!> <how to fix it>" (error code EXIT_INPUT), for raccord_deck.
module raccord_deck_checks
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use raccord_kinds, only: wp
  use raccord_error, only: error_t, raise_error, EXIT_INPUT
  use raccord_strings, only: str, lower, clipped, text_flaw
  use raccord_deck_scan, only: deck_block_t, join_names
  use raccord_scene, only: MAX_TABLE
  implicit none
  private

  !> Keys whose value is text and so must be quoted in namelist input.
  character(len=*), parameter :: TEXT_KEYS(*) = [character(len=16) :: 'title', 'output_dir', 'file', &
    'format', 'name', 'elset', 'hypothesis', 'set', 'type', 'components', 'amplitude', 'slave', 'master', &
    'method', 'multiplier', 'kinematics', 'material', 'volumetric', 'conditions', 'edge_multipliers']

  !> Text keys that hold a path or free text, not a name: they may be in
  !> any encoding (a file name on disk), but hold no control characters.
  character(len=*), parameter :: PATH_KEYS(*) = [character(len=16) :: 'title', 'output_dir', 'file']

  !> Keys that take a list of reals (velocity(2) = ... sets one entry).
  character(len=*), parameter :: ARRAY_KEYS(*) = [character(len=16) :: 'velocity', 'body_force', 'value', 'time']

  !> Keys that take a logical, and the forms of a logical value they take.
  character(len=*), parameter :: LOGICAL_KEYS(*) = [character(len=16) :: 'stress']
  character(len=*), parameter :: LOGICAL_WORDS(*) = [character(len=7) :: '.true.', '.false.', 't', 'f', &
    '.t.', '.f.', 'true', 'false']

  public :: head, check_keys, unreadable, bad_value, missing_key, check_length, check_finite

  !> Characters of a value quoted in a message (a longer one is cut).
  integer, parameter :: MAX_ECHO = 80

  !> Sentinel of required real keys: no deck sets a real to -huge.
  real(wp), parameter, public :: UNSET = -huge(1.0_wp)

contains

  !> "<deck>:<line>: &<group> '<label>'", the head of every message on a group.
  pure function head(deck, blk, line, label) result(s)
    character(len=*), intent(in) :: deck, label
    type(deck_block_t), intent(in) :: blk
    integer, intent(in) :: line
    character(len=:), allocatable :: s
    s = deck // ':' // str(line) // ': &' // blk%group
    if (len(label) > 0) s = s // ' ''' // label // ''''
  end function head

  !> Keys are the group's own, text is quoted, and a key is not given twice.
  subroutine check_keys(deck, blk, known, label, err)
    character(len=*), intent(in) :: deck, label
    type(deck_block_t), intent(in) :: blk
    character(len=*), intent(in) :: known(:)
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: value, flaw
    integer :: k, j
    do k = 1, size(blk%keys)
      associate (key => blk%keys(k))
        if (.not. any(known == key%name)) then
          call raise_error(err, EXIT_INPUT, head(deck, blk, key%line, label) // ': unknown key ''' // &
            clipped(key%name, MAX_ECHO) // ''' (known keys: ' // join_names(known) // '); check the spelling')
          return
        end if
        ! A repeat count without a value (1*, 2*) is a null value: the key
        ! kept its default without a word (or a required key was "missing").
        if (only_nulls(blk%value_text(k))) then
          call raise_error(err, EXIT_INPUT, head(deck, blk, key%line, label) // ': key ''' // key%name // &
            ''' = ' // clipped(blk%value_text(k), MAX_ECHO) // ' has no value (a repeat count without a value ' // &
            'is a null value, which leaves the default); write ' // key%name // &
            ' = <value>, or remove the key to use its default')
          return
        end if
        if (any(TEXT_KEYS == key%name)) then
          value = blk%value_text(k)
          if (len(typographic_quote(value)) > 0) then
            call raise_error(err, EXIT_INPUT, head(deck, blk, key%line, label) // ': key ''' // key%name // &
              ''' = ' // clipped(value, MAX_ECHO) // ': the text is in typographic quotes (' // &
              typographic_quote(value) // ', as a word processor or a web page writes them), which Fortran ' // &
              'does not take for quotes; write ' // key%name // ' = ''' // clipped(unquoted(value), MAX_ECHO) // &
              ''' with the plain quote '' (or ")')
            return
          end if
          if (value(1:1) /= '''' .and. value(1:1) /= '"') then
            call raise_error(err, EXIT_INPUT, head(deck, blk, key%line, label) // ': key ''' // key%name // &
              ''' = ' // clipped(value, MAX_ECHO) // ': text must be in quotes; write ' // key%name // ' = ''' // &
              clipped(value, MAX_ECHO) // '''')
            return
          end if
          ! Names end up in the results' .xmf (XML): they must be UTF-8
          ! without control characters; paths and the title only the latter.
          flaw = text_flaw(value(2:max(1, len(value) - 1)), .not. any(PATH_KEYS == key%name))
          if (len(flaw) > 0) then
            call raise_error(err, EXIT_INPUT, head(deck, blk, key%line, label) // ': key ''' // key%name // &
              ''': in the text, ' // flaw // ', which the results'' .xmf (XML) cannot hold; retype the ' // &
              'text in plain ASCII, or save the deck as UTF-8')
            return
          end if
        end if
        ! Fortran reads any word that starts with t or f (after an
        ! optional '.') as a logical: stress = full was .false., stress =
        ! tensor .true. Only the forms of true and false are taken.
        if (any(LOGICAL_KEYS == key%name)) then
          value = lower(blk%value_text(k))
          if (.not. any(LOGICAL_WORDS == value)) then
            call raise_error(err, EXIT_INPUT, head(deck, blk, key%line, label) // ': key ''' // key%name // &
              ''' = ' // clipped(blk%value_text(k), MAX_ECHO) // ': not a logical value (Fortran would read ' // &
              'any word that starts with t as true and with f as false); write ' // key%name // &
              ' = .true. or ' // key%name // ' = .false.')
            return
          end if
        end if
        if (key%subscripted .and. .not. any(ARRAY_KEYS == key%name)) then
          call raise_error(err, EXIT_INPUT, head(deck, blk, key%line, label) // ': key ''' // key%name // &
            ''' (' // clipped(blk%item_text(k), MAX_ECHO) // '): a subscript applies only to the list keys (' // &
            join_names(ARRAY_KEYS) // '); ' // key%name // ' takes a single ' // &
            trim(merge('text  ', 'number', any(TEXT_KEYS == key%name))) // ': write ' // key%name // ' = ' // &
            trim(merge('''...''', '<x>  ', any(TEXT_KEYS == key%name))))
          return
        end if
        if (any(ARRAY_KEYS == key%name)) then
          call check_entries(deck, blk, k, label, err)
          if (err%failed()) return
        end if
        if (.not. key%subscripted) then
          do j = 1, k - 1
            if (blk%keys(j)%name /= key%name .or. blk%keys(j)%subscripted) cycle
            call raise_error(err, EXIT_INPUT, head(deck, blk, key%line, label) // ': key ''' // key%name // &
              ''' is given a second time (first at line ' // str(blk%keys(j)%line) // '); keep one')
            return
          end do
        end if
      end associate
    end do
  end subroutine check_keys

  !> Key k of a list key sets no entry that an earlier item of the same key
  !> set (velocity = 1.0, 2.0, velocity(1) = 5.0 kept 5.0 without a word).
  !> Which entries an item sets is found by reading it into a probe list, so
  !> that repeat counts (2*1.0), nulls (', 5.0') and sections (time(3:4))
  !> count as the namelist read counts them.
  subroutine check_entries(deck, blk, k, label, err)
    character(len=*), intent(in) :: deck, label
    type(deck_block_t), intent(in) :: blk
    integer, intent(in) :: k
    type(error_t), intent(inout) :: err
    logical :: mine(MAX_TABLE), theirs(MAX_TABLE)
    integer :: j, i
    mine = entries_set(blk, k)
    if (.not. any(mine)) return
    do j = 1, k - 1
      if (blk%keys(j)%name /= blk%keys(k)%name) cycle
      theirs = entries_set(blk, j)
      if (.not. any(mine .and. theirs)) cycle
      i = findloc(mine .and. theirs, .true., dim=1)
      call raise_error(err, EXIT_INPUT, head(deck, blk, blk%keys(k)%line, label) // ': key ''' // &
        blk%keys(k)%name // ''': entry ' // str(i) // ' is given twice (line ' // str(blk%keys(j)%line) // ': ' // &
        clipped(blk%item_text(j), MAX_ECHO) // '; line ' // str(blk%keys(k)%line) // ': ' // &
        clipped(blk%item_text(k), MAX_ECHO) // '); give each entry once')
      return
    end do
  end subroutine check_entries

  !> The entries of a list that item k sets (none if it does not read).
  function entries_set(blk, k) result(set)
    type(deck_block_t), intent(in) :: blk
    integer, intent(in) :: k
    logical :: set(MAX_TABLE)
    real(wp) :: a(MAX_TABLE)
    namelist /probe/ a
    character(len=:), allocatable :: record
    integer :: ios
    a = UNSET
    record = '&probe a' // blk%text(blk%keys(k)%first + len(blk%keys(k)%name):blk%keys(k)%last) // ' /'
    read(record, nml=probe, iostat=ios)
    set = a /= UNSET .and. ios == 0
  end function entries_set

  !> A value list made only of null values written as repeat counts
  !> ("1*", "2*, 1*"); an empty list is reported by the scanner.
  pure logical function only_nulls(text)
    character(len=*), intent(in) :: text
    integer :: k, digits
    logical :: star
    only_nulls = .false.
    digits = 0
    star = .false.
    do k = 1, len(text)
      select case (text(k:k))
      case ('0':'9')
        if (star) return
        digits = digits + 1
      case ('*')
        if (digits == 0 .or. star) return
        star = .true.
      case (' ', ',')
        if (digits > 0 .and. .not. star) return
        if (star) only_nulls = .true.
        digits = 0
        star = .false.
      case default
        only_nulls = .false.
        return
      end select
    end do
    if (digits > 0 .and. .not. star) then
      only_nulls = .false.
    else if (star) then
      only_nulls = .true.
    end if
  end function only_nulls

  !> The typographic quote a text starts with ('' if none): UTF-8 left and
  !> right single and double quotes, their Windows-1252 bytes, a backtick.
  pure function typographic_quote(value) result(q)
    character(len=*), intent(in) :: value
    character(len=:), allocatable :: q
    q = ''
    if (len(value) >= 3) then
      if (value(1:2) == achar(226) // achar(128) .and. iachar(value(3:3)) >= 152 .and. &
          iachar(value(3:3)) <= 159) then
        q = 'UTF-8 ' // value(1:3)
        return
      end if
    end if
    if (len(value) >= 1) then
      if (iachar(value(1:1)) >= 145 .and. iachar(value(1:1)) <= 148) then
        q = 'Windows-1252 byte ' // str(iachar(value(1:1)))
      else if (value(1:1) == '`') then
        q = '`'
      end if
    end if
  end function typographic_quote

  !> A text without the typographic quotes around it, for the fix.
  pure function unquoted(value) result(t)
    character(len=*), intent(in) :: value
    character(len=:), allocatable :: t
    integer :: n
    t = value
    if (len(t) >= 3) then
      if (t(1:2) == achar(226) // achar(128)) t = t(4:)
    end if
    if (len(t) >= 1) then
      if ((iachar(t(1:1)) >= 145 .and. iachar(t(1:1)) <= 148) .or. t(1:1) == '`') t = t(2:)
    end if
    n = len(t)
    if (n >= 3) then
      if (t(n-2:n-1) == achar(226) // achar(128)) t = t(1:n-3)
    end if
    n = len(t)
    if (n >= 1) then
      if ((iachar(t(n:n)) >= 145 .and. iachar(t(n:n)) <= 148) .or. t(n:n) == '`' .or. t(n:n) == '''') &
        t = t(1:n-1)
    end if
  end function unquoted

  !> The values of key k did not read as the key's type.
  subroutine unreadable(deck, blk, k, label, iomsg, err)
    character(len=*), intent(in) :: deck, label, iomsg
    type(deck_block_t), intent(in) :: blk
    integer, intent(in) :: k
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: item
    integer :: n
    ! Quote the item as written, subscript included (velocity(3) = 1.0).
    item = trim(adjustl(blk%text(blk%keys(k)%first:blk%keys(k)%last)))
    n = len(item)
    if (item(n:n) == ',') item = trim(item(1:n-1))
    call raise_error(err, EXIT_INPUT, head(deck, blk, blk%keys(k)%line, label) // ': key ''' // &
      blk%keys(k)%name // ''' (' // clipped(item, MAX_ECHO) // '): cannot read the value (' // trim(iomsg) // &
      '); give ' // expected_form(blk%group, blk%keys(k)%name))
  end subroutine unreadable

  !> What a key's value looks like, for messages.
  pure function expected_form(group, key) result(s)
    character(len=*), intent(in) :: group, key
    character(len=:), allocatable :: s
    if (any(TEXT_KEYS == key)) then
      s = 'text in quotes, e.g. ' // key // ' = ''...'''
    else if (group == 'amplitude') then
      s = 'a list of 1 to ' // str(MAX_TABLE) // ' real numbers, e.g. ' // key // ' = 0.0, 1.0'
    else if (key == 'velocity' .or. key == 'body_force' .or. key == 'value') then
      s = 'two real numbers (x, y), e.g. ' // key // ' = 0.0, -1.0'
    else if (key == 'frames' .or. key == 'history_every' .or. key == 'max_iterations' .or. &
             key == 'checkpoint_every') then
      s = 'a whole number from 0 to 2147483647, e.g. ' // key // ' = 20'
    else if (key == 'stress') then
      s = '.true. or .false.'
    else
      s = 'a real number, e.g. ' // key // ' = 1.0'
    end if
  end function expected_form

  !> A key's value is out of its range or not one of the allowed words.
  subroutine bad_value(deck, blk, label, key, problem, fix, err)
    character(len=*), intent(in) :: deck, label, key, problem, fix
    type(deck_block_t), intent(in) :: blk
    type(error_t), intent(inout) :: err
    integer :: k
    character(len=:), allocatable :: given
    k = blk%find(key)
    given = ''
    if (k > 0) given = ' = ' // clipped(blk%value_text(k), MAX_ECHO)
    call raise_error(err, EXIT_INPUT, head(deck, blk, blk%key_line(key), label) // ': key ''' // key // '''' // &
      given // ': ' // problem // '; ' // fix)
  end subroutine bad_value

  !> A required key is absent (reported at the line where the group starts).
  subroutine missing_key(deck, blk, label, key, example, err)
    character(len=*), intent(in) :: deck, label, key, example
    type(deck_block_t), intent(in) :: blk
    type(error_t), intent(inout) :: err
    call raise_error(err, EXIT_INPUT, head(deck, blk, blk%line, label) // ': required key ''' // key // &
      ''' is missing; add ' // example)
  end subroutine missing_key

  !> A text value that fills its whole buffer was probably cut short.
  subroutine check_length(deck, blk, label, key, value, err)
    character(len=*), intent(in) :: deck, label, key, value
    type(deck_block_t), intent(in) :: blk
    type(error_t), intent(inout) :: err
    if (len_trim(value) < len(value)) return
    call bad_value(deck, blk, label, key, 'the text is too long (at most ' // str(len(value) - 1) // &
      ' characters)', 'shorten it', err)
  end subroutine check_length

  !> NaN or infinity would pass or fail range checks by accident (and trap
  !> in debug builds), so they are refused first.
  subroutine check_finite(deck, blk, label, keys, values, err)
    character(len=*), intent(in) :: deck, label
    type(deck_block_t), intent(in) :: blk
    character(len=*), intent(in) :: keys(:)
    real(wp), intent(in) :: values(:)
    type(error_t), intent(inout) :: err
    integer :: k
    do k = 1, size(values)
      if (ieee_is_finite(values(k))) cycle
      call bad_value(deck, blk, label, trim(keys(k)), 'the value is not a finite number', &
        'give a finite real number', err)
      return
    end do
  end subroutine check_finite
end module raccord_deck_checks
