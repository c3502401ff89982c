!> Line-level reading of Gmsh MSH sections, both versions: the next data
!> line of a section split into fields, a count line, the closing $End
!> line, a skipped section, and integer and real fields with messages
!> naming file, line and field (Gmsh reference manual, "MSH file format").
module raccord_gmsh_lines
  use raccord_kinds, only: wp
  use raccord_error, only: error_t, raise_error, EXIT_INPUT
  use raccord_strings, only: str
  use raccord_text_reader, only: text_file_t, read_line, here, split_fields, parse_int, parse_real, &
    check_count, int_fault
  implicit none
  private

  public :: next_data_line, read_count, expect_end, skip_section, get_int, get_real, clip

contains

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
end module raccord_gmsh_lines
