!> The lines of an Abaqus / CalculiX .inp file (module header of
!> raccord_abaqus_reader): comments and blank lines skipped, a line ending
!> with a comma joined with the next, each logical line handed to the
!> keyword or the data reader. Moved verbatim from raccord_abaqus_reader.
submodule (raccord_abaqus_reader) raccord_abaqus_lines
  implicit none

contains

  module procedure read_inp_file
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
  end procedure read_inp_file

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

  !> At most 60 characters of a text of the file, for a message.
  module procedure clip
    r = clipped(s, 60)
  end procedure clip

  module procedure loc_text
    s = d%files(sl%ifile)%path // ':' // str(sl%line)
  end procedure loc_text
end submodule raccord_abaqus_lines
