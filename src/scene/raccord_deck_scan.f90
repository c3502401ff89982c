!> Scanner for scene decks: splits a file of namelist groups into blocks,
!> one per group, and finds the keys of each block with their line numbers.
!>
!> Why not let the namelist read do it: gfortran's namelist errors name
!> neither the line nor the key, and a namelist read on a file stops at the
!> first group of the expected name, so unknown groups or keys and a missing
!> '/' would pass unseen or give a cryptic message. The scanner knows the
!> syntax well enough to report those with the file, line, group and key;
!> raccord_deck then reads each key's values with an internal namelist read.
!>
!> Syntax handled: '&name' opens a group, '/' (or '&end') closes it; text in '...' or
!> "..." (a doubled quote stands for itself) is opaque, so '/', '!' and '='
!> inside quotes are data; '!' outside quotes starts a comment to the end of
!> the line; a key is a name, optionally subscripted, followed by '='.
module raccord_deck_scan
  use, intrinsic :: iso_fortran_env, only: iostat_end, iostat_eor
  use raccord_kinds, only: i8
  use raccord_error, only: error_t, raise_error, EXIT_INPUT
  use raccord_strings, only: str, lower, first_control, control_name
  use raccord_files, only: broken_link, relative_note
  implicit none
  private

  public :: scan_deck, is_name_char, join_names

  !> One key = value item of a block.
  type, public :: deck_key_t
    character(len=:), allocatable :: name       !< lower case, without subscript
    integer :: line = 0                         !< line of the key in the deck
    integer :: first = 0                        !< position of the key in the block text
    integer :: last = 0                         !< last position of its values
    integer :: value_first = 0                  !< first position after '='
    logical :: subscripted = .false.            !< key(i) or key(i:j)
  end type deck_key_t

  !> One group of the deck.
  type, public :: deck_block_t
    character(len=:), allocatable :: group      !< lower case, without '&'
    integer :: line = 0                         !< line of '&group'
    character(len=:), allocatable :: text       !< the group's body, comments blanked, lines joined by a blank
    character(len=:), allocatable :: mask       !< text with quoted characters replaced by 'x'
    integer, allocatable :: line_of(:)          !< deck line of each character of text
    !> while the group is open: characters of text, mask and line_of in use
    !> (the three grow by doubling, and are cut to ntext when it closes)
    integer :: ntext = 0
    type(deck_key_t), allocatable :: keys(:)
  contains
    procedure :: find => block_find
    procedure :: item => block_item
    procedure :: value_text => block_value_text
    procedure :: item_text => block_item_text
    procedure :: key_line => block_key_line
  end type deck_block_t

contains

  !> Index of the first key called name in the block, 0 when absent.
  pure integer function block_find(self, name) result(k)
    class(deck_block_t), intent(in) :: self
    character(len=*), intent(in) :: name
    do k = 1, size(self%keys)
      if (self%keys(k)%name == name) return
    end do
    k = 0
  end function block_find

  !> The k-th item as its own namelist record, "&group key = values /",
  !> ready for an internal namelist read.
  pure function block_item(self, k) result(record)
    class(deck_block_t), intent(in) :: self
    integer, intent(in) :: k
    character(len=:), allocatable :: record
    record = '&' // self%group // ' ' // trim(self%text(self%keys(k)%first:self%keys(k)%last)) // ' /'
  end function block_item

  !> The values of the k-th item as written (for messages).
  pure function block_value_text(self, k) result(text)
    class(deck_block_t), intent(in) :: self
    integer, intent(in) :: k
    character(len=:), allocatable :: text
    text = unlisted(self%text(self%keys(k)%value_first:self%keys(k)%last))
  end function block_value_text

  !> The k-th item as written, subscript included (for messages).
  pure function block_item_text(self, k) result(text)
    class(deck_block_t), intent(in) :: self
    integer, intent(in) :: k
    character(len=:), allocatable :: text
    text = unlisted(self%text(self%keys(k)%first:self%keys(k)%last))
  end function block_item_text

  !> Text trimmed, without the separator that may end it (not part of it).
  pure function unlisted(raw) result(text)
    character(len=*), intent(in) :: raw
    character(len=:), allocatable :: text
    integer :: n
    text = trim(adjustl(raw))
    n = len(text)
    if (n > 0) then
      if (text(n:n) == ',') text = trim(text(1:n-1))
    end if
  end function unlisted

  !> Line of the first key called name, or of the group when the key is absent
  !> (a missing required key is reported where its group starts).
  pure integer function block_key_line(self, name) result(line)
    class(deck_block_t), intent(in) :: self
    character(len=*), intent(in) :: name
    integer :: k
    k = self%find(name)
    if (k > 0) then
      line = self%keys(k)%line
    else
      line = self%line
    end if
  end function block_key_line

  pure logical function is_name_char(c)
    character(len=1), intent(in) :: c
    is_name_char = (c >= 'a' .and. c <= 'z') .or. (c >= 'A' .and. c <= 'Z') &
      .or. (c >= '0' .and. c <= '9') .or. c == '_'
  end function is_name_char

  pure logical function is_letter(c)
    character(len=1), intent(in) :: c
    is_letter = (c >= 'a' .and. c <= 'z') .or. (c >= 'A' .and. c <= 'Z')
  end function is_letter

  !> Read the deck at path and split it into blocks. Group names are checked
  !> against known_groups here, so that an unknown group is reported at its
  !> line before anything else is read.
  subroutine scan_deck(path, known_groups, blocks, err)
    character(len=*), intent(in) :: path
    character(len=*), intent(in) :: known_groups(:)
    type(deck_block_t), allocatable, intent(out) :: blocks(:)
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: line, seg_text, seg_mask, name, hint, target
    character(len=256) :: msg
    character(len=1) :: c, quote
    integer :: u, ios, lnum, i, j, nblock, ns
    logical :: in_group, in_quote, at_end, is_folder, exists
    integer(i8) :: nbytes
    type(deck_block_t), allocatable :: grown(:)

    allocate(blocks(16))
    nblock = 0
    msg = ''
    ! A folder opens and reads as an empty file: say what it is.
    inquire(file=path // '/.', exist=is_folder)
    if (is_folder) then
      call raise_error(err, EXIT_INPUT, path // ': is a folder, not a scene deck; give the deck file ' // &
        '(e.g. ' // path // '/NAME.nml)')
      return
    end if
    ! A pipe (FIFO) without a writer would block the open for ever, a
    ! device (/dev/zero) read without end: both have size 0, as an empty
    ! deck has, and are refused before they are opened.
    inquire(file=path, exist=exists, size=nbytes)
    if (.not. exists .and. broken_link(path, target)) then
      call raise_error(err, EXIT_INPUT, path // ': the scene deck is a broken symbolic link: it points to "' // &
        target // '"' // relative_note(target) // ', which does not exist (or is a loop of links); ' // &
        'mend the link or give the deck''s own path')
      return
    end if
    if (exists .and. nbytes == 0) then
      call raise_error(err, EXIT_INPUT, path // ': the scene deck is empty (0 bytes), or is a pipe or device, ' // &
        'which raccord does not read; give the deck file (doc/scene-reference.md)')
      return
    end if
    open(newunit=u, file=path, status='old', action='read', iostat=ios, iomsg=msg)
    if (ios /= 0) then
      call raise_error(err, EXIT_INPUT, path // ': cannot open the scene deck (' // trim(msg) // &
        '); check the path and the file''s permissions')
      return
    end if

    in_group = .false.
    in_quote = .false.
    quote = ''''
    lnum = 0
    lines: do
      call read_line(u, line, at_end, ios, msg)
      if (ios /= 0) then
        call raise_error(err, EXIT_INPUT, path // ':' // str(lnum + 1) // ': cannot read the line (' // &
          trim(msg) // '); save the deck as plain text')
        exit lines
      end if
      if (at_end) exit lines
      lnum = lnum + 1
      ! UTF-16 (Windows Notepad's "Unicode") puts a NUL byte beside every
      ! ASCII character: the deck read as text outside any group.
      if (index(line, achar(0)) > 0) then
        call raise_error(err, EXIT_INPUT, path // ':' // str(lnum) // ': the line holds NUL bytes: the deck is ' // &
          'saved as UTF-16 ("Unicode") or is not text; save it as plain text (UTF-8 or ASCII)')
        exit lines
      end if
      ! Other control characters (a form feed, an escape pasted from a
      ! terminal) are invisible in an editor: a form feed before '&time'
      ! read as "text outside a group: '&time'". Tabs and the CR of CRLF
      ! line ends are blanks.
      i = first_control(line, cr_ok=.true.)
      if (i > 0) then
        call raise_error(err, EXIT_INPUT, path // ':' // str(lnum) // ': column ' // str(i) // ' holds a ' // &
          'control character, ' // control_name(iachar(line(i:i))) // ', which an editor does not show; ' // &
          'delete it (the deck is plain text: letters, digits, blanks, tabs)')
        exit lines
      end if
      ! A UTF-8 byte-order mark (editors on Windows save one) is no text.
      if (lnum == 1 .and. len(line) >= 3) then
        if (line(1:3) == achar(239) // achar(187) // achar(191)) line = line(4:)
      end if
      ! The segment of this line that belongs to the open group, as text and
      ! mask: seg_text(1:ns), seg_mask(1:ns). Each character of the line adds
      ! at most one to them, so buffers of the line's length (plus the blank
      ! that joins lines) hold them, and the scan stays linear in the line:
      ! appending one character at a time to a growing string copied the
      ! whole segment each time, and a deck line of 10^5 to 10^6 characters
      ! (the line limit of read_line) took minutes.
      if (allocated(seg_text)) deallocate(seg_text, seg_mask)
      allocate(character(len=len(line) + 1) :: seg_text, seg_mask)
      ns = 0
      i = 1
      chars: do while (i <= len(line))
        c = line(i:i)
        if (.not. in_group) then
          if (c == ' ' .or. c == achar(9)) then
            i = i + 1
            cycle chars
          end if
          if (c == '!') exit chars
          if (c == '/' .and. nblock > 0) then
            call raise_error(err, EXIT_INPUT, path // ':' // str(lnum) // ': ''/'' closes a group, but no ' // &
              'group is open here (&' // blocks(nblock)%group // ' of line ' // str(blocks(nblock)%line) // &
              ' was closed before); remove this ''/''')
            exit lines
          end if
          if (c /= '&') then
            call raise_error(err, EXIT_INPUT, path // ':' // str(lnum) // ': text outside a group: ''' // &
              shorten(line(i:)) // '''; put every key = value between &group and ''/'' (or comment it out with ''!'')')
            exit lines
          end if
          j = i + 1
          do while (j <= len(line))
            if (.not. is_name_char(line(j:j))) exit
            j = j + 1
          end do
          name = lower(line(i+1:j-1))
          if (len(name) == 0) then
            call raise_error(err, EXIT_INPUT, path // ':' // str(lnum) // ': ''&'' without a group name; ' // &
              'write the group name right after it, e.g. &mesh')
            exit lines
          end if
          if (name == 'end') then
            call raise_error(err, EXIT_INPUT, path // ':' // str(lnum) // ': ''&end'' closes a group, but no ' // &
              'group is open here (the last one was closed before); remove the ''&end''')
            exit lines
          end if
          if (.not. any(known_groups == name)) then
            call raise_error(err, EXIT_INPUT, path // ':' // str(lnum) // ': unknown group ''&' // shorten(name) // &
              ''' (known groups: ' // join_names(known_groups) // '); check the spelling')
            exit lines
          end if
          if (nblock == size(blocks)) then
            allocate(grown(2*nblock))
            grown(1:nblock) = blocks
            call move_alloc(grown, blocks)
          end if
          nblock = nblock + 1
          blocks(nblock)%group = name
          blocks(nblock)%line = lnum
          allocate(character(len=256) :: blocks(nblock)%text, blocks(nblock)%mask)
          allocate(blocks(nblock)%line_of(256))
          blocks(nblock)%ntext = 0
          in_group = .true.
          i = j
          cycle chars
        end if

        if (in_quote) then
          call put(c, c)
          if (c == quote) then
            if (i < len(line)) then
              if (line(i+1:i+1) == quote) then
                ! A doubled quote is a quote character inside the string.
                seg_mask(ns:ns) = 'x'
                call put(c, 'x')
                i = i + 2
                cycle chars
              end if
            end if
            in_quote = .false.
          else
            seg_mask(ns:ns) = 'x'
          end if
          i = i + 1
          cycle chars
        end if

        select case (c)
        case ('!')
          exit chars
        case ('''', '"')
          in_quote = .true.
          quote = c
          call put(c, c)
        case ('/')
          call end_group()
          if (err%failed()) exit lines
        case ('&')
          ! '&end' closes a group as '/' does (an older namelist form,
          ! which gfortran reads too)
          if (i + 3 <= len(line)) then
            if (lower(line(i+1:i+3)) == 'end') then
              j = i + 4
              if (j > len(line)) then
                c = ' '
              else
                c = line(j:j)
              end if
              if (.not. is_name_char(c)) then
                call end_group()
                if (err%failed()) exit lines
                i = j
                cycle chars
              end if
            end if
          end if
          if (i < len(line)) then
            if (is_letter(line(i+1:i+1))) then
              call raise_error(err, EXIT_INPUT, path // ':' // str(blocks(nblock)%line) // ': &' // &
                blocks(nblock)%group // ': the group is not closed by ''/'' before line ' // str(lnum) // &
                '; end the group with ''/'' on its own line')
              exit lines
            end if
          end if
          call put(c, c)
        case (achar(9))
          call put(' ', ' ')
        case default
          call put(c, c)
        end select
        i = i + 1
      end do chars

      if (in_quote) then
        ! a typographic closing quote (a word processor's) does not close it
        hint = ''
        if (index(line, achar(226) // achar(128) // achar(153)) > 0 .or. &
            index(line, achar(226) // achar(128) // achar(157)) > 0 .or. &
            scan(line, achar(146) // achar(148)) > 0) &
          hint = '; the line holds a typographic closing quote, which is not a quote for Fortran'
        call raise_error(err, EXIT_INPUT, path // ':' // str(lnum) // ': &' // blocks(nblock)%group // &
          ': a string opened with ' // quote // ' is not closed on this line; close it with ' // quote // &
          ' (write a quote inside a string twice)' // hint)
        exit lines
      end if
      ! Lines are joined by a blank, so a value never runs into the next line.
      if (in_group) then
        call put(' ', ' ')
        call append_segment(blocks(nblock), seg_text(1:ns), seg_mask(1:ns), lnum)
      end if
    end do lines
    close(u, iostat=ios)

    if (.not. err%failed() .and. in_group) then
      call raise_error(err, EXIT_INPUT, path // ':' // str(blocks(nblock)%line) // ': &' // &
        blocks(nblock)%group // ': the group is not closed by ''/'' before the end of the file; ' // &
        'end the group with ''/'' on its own line')
    end if
    if (err%failed()) nblock = 0
    ! Through a copy: gfortran 12 mishandles a self-assignment that shrinks
    ! an array of types with allocatable components (blocks = blocks(1:n)).
    allocate(grown(nblock))
    grown(1:nblock) = blocks(1:nblock)
    call move_alloc(grown, blocks)

  contains

    !> One character of the line into the segment, as text and mask.
    subroutine put(t, m)
      character(len=1), intent(in) :: t, m
      ns = ns + 1
      seg_text(ns:ns) = t
      seg_mask(ns:ns) = m
    end subroutine put

    !> The group's closer ('/' or '&end'): the line's last segment into the
    !> block, the block closed and its keys found (err set on a bad key).
    subroutine end_group()
      call append_segment(blocks(nblock), seg_text(1:ns), seg_mask(1:ns), lnum)
      ns = 0
      in_group = .false.
      call close_block(blocks(nblock))
      call find_keys(path, blocks(nblock), err)
    end subroutine end_group
  end subroutine scan_deck

  !> Read one line of any length; at_end is set at the end of the file.
  subroutine read_line(u, line, at_end, ios, msg)
    integer, intent(in) :: u
    character(len=:), allocatable, intent(out) :: line
    logical, intent(out) :: at_end
    integer, intent(out) :: ios
    character(len=*), intent(inout) :: msg
    character(len=4096) :: buf
    integer, parameter :: max_line = 1000000
    integer :: n
    line = ''
    at_end = .false.
    do
      read(u, '(a)', advance='no', size=n, iostat=ios, iomsg=msg) buf
      if (ios > 0) return
      line = line // buf(1:n)
      ! A line has a length limit: /dev/zero or a binary file given as the
      ! deck would otherwise be read into memory without end.
      if (len(line) > max_line) then
        ios = 1
        msg = 'a line longer than ' // str(max_line) // ' characters: not a text deck'
        return
      end if
      if (ios == iostat_eor) exit
      if (ios == iostat_end) then
        ! A last line without a newline still counts as a line.
        at_end = len(line) == 0
        ios = 0
        if (at_end) return
        exit
      end if
    end do
    ios = 0
    ! Decks written on Windows end their lines with CR LF.
    n = len(line)
    if (n > 0) then
      if (line(n:n) == achar(13)) line = line(1:n-1)
    end if
  end subroutine read_line

  !> Append a line's segment to the open block. text, mask and line_of
  !> grow by doubling (block%ntext in use), so a group of 10^5 lines reads
  !> in linear time: appending by concatenation copied the whole group at
  !> each line.
  subroutine append_segment(block, seg_text, seg_mask, lnum)
    type(deck_block_t), intent(inout) :: block
    character(len=*), intent(in) :: seg_text, seg_mask
    integer, intent(in) :: lnum
    character(len=:), allocatable :: t, m
    integer, allocatable :: lines(:)
    integer :: n, cap
    n = block%ntext
    cap = len(block%text)
    if (n + len(seg_text) > cap) then
      do while (n + len(seg_text) > cap)
        cap = 2*cap
      end do
      allocate(character(len=cap) :: t, m)
      allocate(lines(cap))
      t(1:n) = block%text(1:n)
      m(1:n) = block%mask(1:n)
      lines(1:n) = block%line_of(1:n)
      call move_alloc(t, block%text)
      call move_alloc(m, block%mask)
      call move_alloc(lines, block%line_of)
    end if
    block%text(n + 1:n + len(seg_text)) = seg_text
    block%mask(n + 1:n + len(seg_text)) = seg_mask
    block%line_of(n + 1:n + len(seg_text)) = lnum
    block%ntext = n + len(seg_text)
  end subroutine append_segment

  !> A closed block: text, mask and line_of cut to the characters in use.
  subroutine close_block(block)
    type(deck_block_t), intent(inout) :: block
    integer :: n
    n = block%ntext
    block%text = block%text(1:n)
    block%mask = block%mask(1:n)
    block%line_of = block%line_of(1:n)
  end subroutine close_block

  !> Find the keys of a closed block: each '=' outside quotes ends a key
  !> designator "name" or "name(subscript)". The values of a key run up to
  !> the next key, so each item can be read on its own.
  subroutine find_keys(path, block, err)
    character(len=*), intent(in) :: path
    type(deck_block_t), intent(inout) :: block
    type(error_t), intent(inout) :: err
    type(deck_key_t), allocatable :: keys(:)
    character(len=:), allocatable :: here
    integer :: p, q, s, e, depth, nkey, k

    here = path // ':'
    ! one key per '=' outside quotes (an array of the block's length, as
    ! before, was some 80 bytes per character of the group)
    nkey = 0
    do p = 1, len(block%mask)
      if (block%mask(p:p) == '=') nkey = nkey + 1
    end do
    allocate(keys(nkey))
    nkey = 0
    do p = 1, len(block%mask)
      if (block%mask(p:p) /= '=') cycle
      q = p - 1
      call skip_blanks_back(block%mask, q)
      nkey = nkey + 1
      keys(nkey)%subscripted = .false.
      if (q >= 1) then
        if (block%mask(q:q) == ')') then
          depth = 0
          do while (q >= 1)
            if (block%mask(q:q) == ')') depth = depth + 1
            if (block%mask(q:q) == '(') depth = depth - 1
            if (depth == 0) exit
            q = q - 1
          end do
          q = q - 1
          call skip_blanks_back(block%mask, q)
          keys(nkey)%subscripted = .true.
        end if
      end if
      e = q
      do while (q >= 1)
        if (.not. is_name_char(block%mask(q:q))) exit
        q = q - 1
      end do
      s = q + 1
      if (s > e) then
        call raise_error(err, EXIT_INPUT, here // str(block%line_of(p)) // ': &' // block%group // &
          ': ''='' without a key name before it; write key = value')
        return
      end if
      if (s > 1) then
        ! name%part: a component of a derived type, which no key is
        if (block%mask(s-1:s-1) == '%') then
          q = s - 2
          do while (q >= 1)
            if (.not. is_name_char(block%mask(q:q))) exit
            q = q - 1
          end do
          call raise_error(err, EXIT_INPUT, here // str(block%line_of(s)) // ': &' // block%group // &
            ': key ''' // shorten(lower(block%mask(q+1:e))) // ''' names a component (name%part); the keys ' // &
            'are plain names: write ' // shorten(lower(block%mask(q+1:s-2))) // ' = value')
          return
        end if
        if (block%mask(s-1:s-1) /= ' ' .and. block%mask(s-1:s-1) /= ',') then
          call raise_error(err, EXIT_INPUT, here // str(block%line_of(s)) // ': &' // block%group // &
            ': key ''' // shorten(lower(block%mask(s:e))) // ''' runs into the text before it (''' // &
            trim(adjustl(block%text(max(1, s-12):s-1))) // '''); separate items with a comma or a blank')
          return
        end if
      end if
      keys(nkey)%name = lower(block%mask(s:e))
      keys(nkey)%line = block%line_of(s)
      keys(nkey)%first = s
      keys(nkey)%value_first = p + 1
    end do

    if (nkey == 0) then
      if (len_trim(block%text) > 0) then
        call raise_error(err, EXIT_INPUT, here // str(block%line) // ': &' // block%group // &
          ': expected key = value items, found ''' // shorten(adjustl(block%text)) // '''')
      end if
      allocate(block%keys(0))
      return
    end if
    if (len_trim(block%text(1:keys(1)%first-1)) > 0) then
      call raise_error(err, EXIT_INPUT, here // str(block%line) // ': &' // block%group // &
        ': text before the first key: ''' // shorten(adjustl(block%text(1:keys(1)%first-1))) // &
        '''; write only key = value items in a group')
      return
    end if
    do k = 1, nkey
      if (k < nkey) then
        keys(k)%last = keys(k+1)%first - 1
      else
        keys(k)%last = len(block%text)
      end if
      if (verify(block%mask(keys(k)%value_first:keys(k)%last), ' ,') == 0) then
        call raise_error(err, EXIT_INPUT, here // str(keys(k)%line) // ': &' // block%group // &
          ': key ''' // keys(k)%name // ''' has no value; write ' // keys(k)%name // &
          ' = <value> or remove the key to use its default')
        return
      end if
    end do
    block%keys = keys(1:nkey)
  end subroutine find_keys

  pure subroutine skip_blanks_back(s, q)
    character(len=*), intent(in) :: s
    integer, intent(inout) :: q
    do while (q >= 1)
      if (s(q:q) /= ' ') exit
      q = q - 1
    end do
  end subroutine skip_blanks_back

  !> Names joined by ', ' (for "known ..." lists in messages).
  pure function join_names(names) result(s)
    character(len=*), intent(in) :: names(:)
    character(len=:), allocatable :: s
    integer :: k
    s = ''
    do k = 1, size(names)
      if (k > 1) s = s // ', '
      s = s // trim(names(k))
    end do
  end function join_names

  !> A piece of deck text short enough to quote in a message.
  pure function shorten(text) result(s)
    character(len=*), intent(in) :: text
    character(len=:), allocatable :: s
    s = trim(text)
    if (len(s) > 40) s = s(1:37) // '...'
  end function shorten
end module raccord_deck_scan
