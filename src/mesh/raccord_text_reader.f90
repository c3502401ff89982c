!> Line-by-line reading of a text input file with the line number kept for
!> messages, and the field splitting and number parsing the mesh readers share.
!>
!> Lines may be of any length (Abaqus continuation, long Gmsh entity lines)
!> and may end in CR-LF (files written on Windows).
module raccord_text_reader
  use raccord_kinds, only: wp, i8
  use raccord_error, only: error_t, raise_error, EXIT_INPUT
  use raccord_strings, only: str, first_control, control_name
  use raccord_files, only: broken_link, relative_note
  implicit none
  private

  public :: open_text_file, close_text_file, read_line, here, check_count
  public :: split_fields, parse_int, parse_real, int_fault, beyond_int_range

  !> Longest line read (Gmsh and Abaqus lines are far shorter).
  integer, parameter :: MAX_LINE = 1000000

  !> An open text file and the number of the last line read.
  type, public :: text_file_t
    character(len=:), allocatable :: path
    integer :: unit = -1
    integer :: line_no = 0
    integer(i8) :: bytes = -1        !< size of the file when opened (-1: unknown)
    logical :: at_end = .false.      !< end of file reached: further reads return eof
  end type text_file_t

contains

  !> Open a file for reading; a missing or unreadable file is an input error.
  subroutine open_text_file(tf, path, err)
    type(text_file_t), intent(out) :: tf
    character(len=*), intent(in) :: path
    type(error_t), intent(inout) :: err
    integer :: ios
    character(len=512) :: msg
    logical :: exists, busy, folder
    integer(i8) :: nbytes
    character(len=:), allocatable :: target
    tf%path = path
    tf%line_no = 0
    inquire(file=path, exist=exists)
    if (.not. exists .and. broken_link(path, target)) then
      call raise_error(err, EXIT_INPUT, 'mesh file "' // path // '" is a broken symbolic link: it points to "' // &
        target // '"' // relative_note(target) // ', which does not exist (or is a loop of links): ' // &
        'mend the link or give the mesh file''s own path')
      return
    end if
    if (.not. exists) then
      call raise_error(err, EXIT_INPUT, 'mesh file "' // path // '" does not exist: check the path ' // &
        '(relative paths are taken from the scene deck''s folder)')
      return
    end if
    ! A folder, a pipe (FIFO) or a device (/dev/zero) is no mesh file: a
    ! pipe without a writer would block the open for ever, a device read
    ! without end. A folder's '.' exists; the others (and an empty file)
    ! have size 0, so they are refused before they are opened.
    inquire(file=path // '/.', exist=folder)
    if (folder) then
      call raise_error(err, EXIT_INPUT, 'mesh file "' // path // '" is a folder: give the mesh file in it')
      return
    end if
    inquire(file=path, size=nbytes)
    if (nbytes == 0) then
      call raise_error(err, EXIT_INPUT, 'mesh file "' // path // '" is empty (0 bytes), or is a pipe or ' // &
        'device, which raccord does not read: give a mesh file (Gmsh .msh or Abaqus .inp)')
      return
    end if
    ! A file this process is reading already (an Abaqus *INCLUDE cycle):
    ! named as such, not as the runtime's "File already opened in another unit".
    inquire(file=path, opened=busy)
    if (busy) then
      call raise_error(err, EXIT_INPUT, 'mesh file "' // path // '" is included while it is being read (a ' // &
        'file that includes itself, directly or through other files): remove that *INCLUDE')
      return
    end if
    open(newunit=tf%unit, file=path, status='old', action='read', form='formatted', &
      access='sequential', iostat=ios, iomsg=msg)
    if (ios /= 0) then
      tf%unit = -1
      call raise_error(err, EXIT_INPUT, 'cannot open mesh file "' // path // '": ' // trim(msg))
      return
    end if
    inquire(unit=tf%unit, size=tf%bytes)
  end subroutine open_text_file

  !> A count read from the file (items of `lines_each` lines each) must be
  !> >= 0 and fit in what the file can hold: every line takes at least two
  !> bytes (a character and its end of line). Checked before anything is
  !> allocated or looped over by that count.
  subroutine check_count(tf, n, lines_each, what, err)
    type(text_file_t), intent(in) :: tf
    integer, intent(in) :: n, lines_each
    character(len=*), intent(in) :: what
    type(error_t), intent(inout) :: err
    integer(i8) :: most
    if (n < 0) then
      call raise_error(err, EXIT_INPUT, here(tf) // ': ' // what // ' is negative (' // str(n) // &
        '): the file is damaged; re-export the mesh')
      return
    end if
    if (tf%bytes < 0) return
    most = tf%bytes/(2_i8*max(1, lines_each))
    if (int(n, i8) > most) then
      call raise_error(err, EXIT_INPUT, here(tf) // ': ' // what // ' is ' // str(n) // &
        ', but the file (' // str(tf%bytes) // ' bytes) can hold at most ' // str(most) // &
        ': the count is wrong, the file is damaged; re-export the mesh')
    end if
  end subroutine check_count

  subroutine close_text_file(tf)
    type(text_file_t), intent(inout) :: tf
    integer :: ios
    if (tf%unit /= -1) close(tf%unit, iostat=ios)
    tf%unit = -1
  end subroutine close_text_file

  !> "path:line" of the last line read, for messages.
  function here(tf) result(s)
    type(text_file_t), intent(in) :: tf
    character(len=:), allocatable :: s
    s = tf%path // ':' // str(tf%line_no)
  end function here

  !> Read the next line (without its end-of-line characters). At end of file
  !> eof is true and line is empty; a read failure raises an input error.
  subroutine read_line(tf, line, eof, err)
    type(text_file_t), intent(inout) :: tf
    character(len=:), allocatable, intent(out) :: line
    logical, intent(out) :: eof
    type(error_t), intent(inout) :: err
    character(len=4096) :: buf
    character(len=512) :: msg
    integer :: ios, nread, k
    line = ''
    eof = .false.
    ! A unit read past its end fails with a runtime message: once the end
    ! is met, every further call returns eof (a reader that looks for a
    ! continuation after a trailing comma on the last line asks again).
    if (tf%at_end) then
      eof = .true.
      return
    end if
    ! Non-advancing reads in chunks: a line has no length limit.
    do
      read(tf%unit, '(a)', advance='no', size=nread, iostat=ios, iomsg=msg) buf
      if (ios == 0) then
        line = line // buf(1:nread)
        ! /dev/zero or a binary file would otherwise be read without end
        if (len(line) > MAX_LINE) then
          call raise_error(err, EXIT_INPUT, tf%path // ':' // str(tf%line_no + 1) // ': a line longer than ' // &
            str(MAX_LINE) // ' characters: this is not a mesh text file')
          eof = .true.
          return
        end if
        cycle
      end if
      if (is_iostat_eor(ios)) then
        line = line // buf(1:nread)
        exit
      end if
      if (is_iostat_end(ios)) then
        tf%at_end = .true.
        ! a last line without its end of line is still a line
        line = line // buf(1:nread)
        if (len(line) > 0) exit
        eof = .true.
        return
      end if
      call raise_error(err, EXIT_INPUT, 'cannot read ' // tf%path // ' after line ' // str(tf%line_no) // &
        ': ' // trim(msg) // ' (is it a text file?)')
      eof = .true.
      return
    end do
    tf%line_no = tf%line_no + 1
    if (len(line) > 0) then
      if (line(len(line):len(line)) == achar(13)) line = line(1:len(line)-1)
    end if
    ! a UTF-8 byte-order mark that an editor put before the first line, as
    ! the deck reader drops it (it made "$MeshFormat" read as another word)
    if (tf%line_no == 1 .and. len(line) >= 3) then
      if (iachar(line(1:1)) == 239 .and. iachar(line(2:2)) == 187 .and. iachar(line(3:3)) == 191) &
        line = line(4:)
    end if
    ! A NUL byte is in no text file: a binary file (an .h5 given to
    ! *INCLUDE) had its lines skipped as data of a skipped keyword.
    if (index(line, achar(0)) > 0) then
      call raise_error(err, EXIT_INPUT, tf%path // ':' // str(tf%line_no) // ': a NUL byte: this is a binary ' // &
        'file, not a mesh text file (Gmsh .msh ASCII or Abaqus .inp)')
      eof = .true.
      return
    end if
    ! Other control characters are invisible in an editor and made the
    ! line read as something else: a form feed before "$Nodes" was "expected
    ! a section header such as "$Nodes", found "$Nodes"", one before
    ! *ELEMENT a node id. A carriage return left inside a line (old Mac
    ! line ends) is one of them.
    k = first_control(line, cr_ok=.false.)
    if (k > 0) then
      call raise_error(err, EXIT_INPUT, tf%path // ':' // str(tf%line_no) // ': column ' // str(k) // &
        ' holds a control character, ' // control_name(iachar(line(k:k))) // ', which an editor does not ' // &
        'show; delete it, or re-export the mesh as plain text (a binary file, with its NUL bytes and control ' // &
        'codes, is not a mesh text file)')
      eof = .true.
    end if
  end subroutine read_line

  !> Split a line into fields at any of the separator characters; runs of
  !> blanks count as one separator, and fields are returned trimmed as
  !> first/last character positions. With separators = ',' an empty field
  !> between two commas is kept (first > last); a trailing empty one is not.
  pure subroutine split_fields(line, separators, first, last, n)
    character(len=*), intent(in) :: line, separators
    integer, allocatable, intent(out) :: first(:), last(:)
    integer, intent(out) :: n
    integer :: k, start, stop_, cap
    logical :: blank_sep
    blank_sep = scan(separators, ' ') > 0
    cap = 8
    allocate(first(cap), last(cap))
    n = 0
    k = 1
    do while (k <= len(line))
      if (blank_sep) then
        ! skip the blanks and tabs that separate fields
        do while (k <= len(line))
          if (line(k:k) /= ' ' .and. line(k:k) /= achar(9)) exit
          k = k + 1
        end do
        if (k > len(line)) exit
      end if
      start = k
      do while (k <= len(line))
        if (index(separators, line(k:k)) > 0) exit
        if (blank_sep .and. line(k:k) == achar(9)) exit
        k = k + 1
      end do
      stop_ = k - 1
      k = k + 1                      ! step over the separator
      ! trim blanks around a comma-separated field
      do while (start <= stop_)
        if (line(start:start) /= ' ' .and. line(start:start) /= achar(9)) exit
        start = start + 1
      end do
      do while (stop_ >= start)
        if (line(stop_:stop_) /= ' ' .and. line(stop_:stop_) /= achar(9)) exit
        stop_ = stop_ - 1
      end do
      if (n == cap) call grow_pair(first, last, cap)
      n = n + 1
      first(n) = start
      last(n) = stop_
    end do
    ! a trailing separator does not open an empty last field
    if (n > 0 .and. .not. blank_sep) then
      if (first(n) > last(n) .and. len_trim(line) > 0) then
        if (index(separators, line(len_trim(line):len_trim(line))) > 0) n = n - 1
      end if
    end if
  end subroutine split_fields

  pure subroutine grow_pair(first, last, cap)
    integer, allocatable, intent(inout) :: first(:), last(:)
    integer, intent(inout) :: cap
    integer, allocatable :: tmp(:)
    allocate(tmp(2*cap))
    tmp(1:cap) = first
    call move_alloc(tmp, first)
    allocate(tmp(2*cap))
    tmp(1:cap) = last
    call move_alloc(tmp, last)
    cap = 2*cap
  end subroutine grow_pair

  !> Parse an integer field: optional sign and digits only (list-directed
  !> reading alone would accept "3*1" or "1/" and silently misread).
  subroutine parse_int(text, value, ok)
    character(len=*), intent(in) :: text
    integer, intent(out) :: value
    logical, intent(out) :: ok
    integer :: k, ios, first
    value = 0
    ok = .false.
    if (len(text) == 0) return
    first = 1
    if (text(1:1) == '-' .or. text(1:1) == '+') first = 2
    if (first > len(text) .or. len(text) - first + 1 > 10) return
    do k = first, len(text)
      if (text(k:k) < '0' .or. text(k:k) > '9') return
    end do
    read(text, *, iostat=ios) value
    ok = ios == 0
  end subroutine parse_int

  !> Why parse_int refused `text`: an integer's digits beyond the default
  !> integer's range (a Gmsh tag or Abaqus id of 2^31 or more), or no
  !> integer at all; for the readers' messages.
  pure function int_fault(text) result(s)
    character(len=*), intent(in) :: text
    character(len=:), allocatable :: s
    s = 'not an integer'
    if (beyond_int_range(text)) s = 'beyond the integer range of raccord''s ids and counts (-2147483648 to 2147483647)'
  end function int_fault

  !> An integer's text (optional sign, then digits only) that parse_int
  !> refused: its value does not fit the default integer (2^31 or more).
  pure logical function beyond_int_range(text)
    character(len=*), intent(in) :: text
    integer :: first, value, ios
    beyond_int_range = .false.
    first = 1
    if (len(text) > 0) then
      if (text(1:1) == '-' .or. text(1:1) == '+') first = 2
    end if
    if (first > len(text)) return
    if (verify(text(first:), '0123456789') /= 0) return
    ! digits that fit are an integer, not a fault
    if (len(text) - first + 1 <= 9) return
    read(text, *, iostat=ios) value
    beyond_int_range = ios /= 0 .or. len(text) - first + 1 > 10
  end function beyond_int_range

  !> Parse a real field: digits, sign, point and exponent letters only, then
  !> a finite value.
  subroutine parse_real(text, value, ok)
    character(len=*), intent(in) :: text
    real(wp), intent(out) :: value
    logical, intent(out) :: ok
    integer :: ios
    value = 0.0_wp
    ok = .false.
    if (len(text) == 0) return
    if (verify(text, '0123456789+-.eEdD') /= 0) return
    if (scan(text, '0123456789') == 0) return
    read(text, *, iostat=ios) value
    if (ios /= 0) return
    ! reject overflow to infinity; a NaN cannot pass the character check
    ok = abs(value) <= huge(value)
  end subroutine parse_real
end module raccord_text_reader
