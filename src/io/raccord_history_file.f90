!> Time-history file: plain text columns for gnuplot, one row per output
!> time. Format (doc/output-format.md, "History file"):
!>
!>     # raccord history
!>     # 1 time
!>     # 2 kinetic_energy
!>     ...
!>       1.0000000000000000E-003  2.5000000000000000E+001 ...
!>
!> so `plot 'run.hist' using 1:2` works and the header says what column 2
!> is. Like the results file it is written as path.part and renamed on
!> close: path when complete, path with '.incomplete' before the extension
!> otherwise (run.hist -> run.incomplete.hist).
module raccord_history_file
  use raccord_kinds, only: wp, i8
  use raccord_error, only: error_t, raise_error, EXIT_IO, EXIT_INTERNAL, EXIT_INPUT
  use raccord_strings, only: str
  use raccord_files, only: rename_file, delete_file, make_directory, file_size, truncate_file, file_exists
  implicit none
  private

  public :: history_open, history_write, history_close, incomplete_name
  public :: history_bytes, history_suspend, history_resume
  public :: ROW_FORMAT

  !> Width of one column: es24.16e3 (17 significant digits, enough to
  !> read back the same real64) plus a separating blank.
  character(len=*), parameter :: ROW_FORMAT = '(*(1x,es24.16e3))'

  !> An open history file.
  type, public :: history_file_t
    private
    logical :: is_open = .false.
    integer :: unit = -1
    integer :: ncol = 0
    character(len=:), allocatable :: path
  end type history_file_t

contains

  !> Create path.part (and its folder) and write the header. Stale `path`
  !> and its .incomplete twin from an earlier run are deleted.
  subroutine history_open(h, path, names, err)
    type(history_file_t), intent(inout) :: h
    character(len=*), intent(in) :: path
    character(len=*), intent(in) :: names(:)
    type(error_t), intent(inout) :: err
    integer :: ios, k, slash
    character(len=256) :: msg
    if (err%failed()) return
    if (h%is_open) then
      call raise_error(err, EXIT_INTERNAL, 'history_open: history file "' // h%path // '" is already open')
      return
    end if
    if (len_trim(path) == 0 .or. size(names) == 0) then
      call raise_error(err, EXIT_INPUT, 'history_open: empty history file name or no columns')
      return
    end if
    h%path = trim(path)
    h%ncol = size(names)
    slash = index(h%path, '/', back=.true.)
    if (slash > 1) call make_directory(h%path(1:slash-1), err)
    if (err%failed()) return
    open(newunit=h%unit, file=h%path // '.part', status='replace', action='write', &
      form='formatted', iostat=ios, iomsg=msg)
    if (ios /= 0) then
      call raise_error(err, EXIT_IO, 'cannot create history file "' // h%path // '.part": ' // trim(msg))
      return
    end if
    h%is_open = .true.
    call delete_file(h%path)
    call delete_file(incomplete_name(h%path))
    write(h%unit, '(a)', iostat=ios) '# raccord history'
    do k = 1, size(names)
      if (ios == 0) write(h%unit, '(a,i0,1x,a)', iostat=ios) '# ', k, trim(names(k))
    end do
    if (ios == 0) flush(h%unit, iostat=ios)
    if (ios /= 0) call raise_error(err, EXIT_IO, 'cannot write the header of history file "' &
      // h%path // '.part" (disk full?)')
  end subroutine history_open

  !> Append one row (one value per column) and flush, so a killed run
  !> keeps every row written.
  subroutine history_write(h, row, err)
    type(history_file_t), intent(inout) :: h
    real(wp), intent(in) :: row(:)
    type(error_t), intent(inout) :: err
    integer :: ios
    if (err%failed()) return
    if (.not. h%is_open) then
      call raise_error(err, EXIT_INTERNAL, 'history_write: the history file is not open')
      return
    end if
    if (size(row) /= h%ncol) then
      call raise_error(err, EXIT_INTERNAL, 'history_write: row of ' // str(size(row)) &
        // ' values for ' // str(h%ncol) // ' columns in "' // h%path // '.part"')
      return
    end if
    write(h%unit, ROW_FORMAT, iostat=ios) row
    if (ios == 0) flush(h%unit, iostat=ios)
    if (ios /= 0) call raise_error(err, EXIT_IO, 'cannot write a row to history file "' &
      // h%path // '.part" (disk full?)')
  end subroutine history_write

  !> Bytes written so far to path.part (every row is flushed): where a
  !> checkpoint records the file's end, so a resumed run can cut it there.
  integer(i8) function history_bytes(h)
    type(history_file_t), intent(in) :: h
    history_bytes = -1
    if (.not. h%is_open) return
    history_bytes = file_size(h%path // '.part')
  end function history_bytes

  !> Close and keep the name path.part: the run stopped at a checkpoint
  !> and history_resume goes on with the file.
  subroutine history_suspend(h, err)
    type(history_file_t), intent(inout) :: h
    type(error_t), intent(inout) :: err
    integer :: ios
    character(len=256) :: msg
    if (.not. h%is_open) return
    close(h%unit, iostat=ios, iomsg=msg)
    if (ios /= 0) call raise_error(err, EXIT_IO, 'cannot close history file "' // h%path // '.part": ' // trim(msg))
    h = history_file_t()
  end subroutine history_suspend

  !> Reopen path.part of a stopped run, cut to `bytes` (its length at the
  !> checkpoint: rows a killed run wrote later are dropped), to append.
  subroutine history_resume(h, path, ncol, bytes, err)
    type(history_file_t), intent(inout) :: h
    character(len=*), intent(in) :: path
    integer, intent(in) :: ncol
    integer(i8), intent(in) :: bytes
    type(error_t), intent(inout) :: err
    integer :: ios
    character(len=256) :: msg
    if (err%failed()) return
    h%path = trim(path)
    h%ncol = ncol
    if (.not. file_exists(h%path // '.part')) then
      call raise_error(err, EXIT_INPUT, 'cannot resume: history file "' // h%path // '.part" is missing; ' // &
        'run the scene afresh without --restart')
      return
    end if
    if (file_size(h%path // '.part') < bytes) then
      call raise_error(err, EXIT_INPUT, 'cannot resume: history file "' // h%path // '.part" is shorter than ' // &
        'at the checkpoint; run the scene afresh without --restart')
      return
    end if
    call truncate_file(h%path // '.part', bytes, err)
    if (err%failed()) return
    open(newunit=h%unit, file=h%path // '.part', status='old', position='append', action='write', &
      form='formatted', iostat=ios, iomsg=msg)
    if (ios /= 0) then
      call raise_error(err, EXIT_IO, 'cannot reopen history file "' // h%path // '.part": ' // trim(msg))
      return
    end if
    h%is_open = .true.
  end subroutine history_resume

  !> Close and rename path.part to path (complete) or to its .incomplete
  !> name. Closing a file that is not open does nothing.
  subroutine history_close(h, complete, err)
    type(history_file_t), intent(inout) :: h
    logical, intent(in) :: complete
    type(error_t), intent(inout) :: err
    integer :: ios
    character(len=256) :: msg
    type(error_t) :: cerr
    logical :: done
    if (.not. h%is_open) return
    done = complete
    close(h%unit, iostat=ios, iomsg=msg)
    if (ios /= 0) then
      call raise_error(cerr, EXIT_IO, 'cannot close history file "' // h%path // '.part": ' // trim(msg))
      done = .false.
    end if
    if (done) then
      call rename_file(h%path // '.part', h%path, cerr)
    else
      call rename_file(h%path // '.part', incomplete_name(h%path), cerr)
    end if
    if (cerr%failed()) call raise_error(err, cerr%code, cerr%message)
    h = history_file_t()
  end subroutine history_close

  !> The name of an incomplete file: '.incomplete' before the extension of
  !> the file part ('out/run.hist' -> 'out/run.incomplete.hist'), or at the
  !> end when there is none ('out/hist' -> 'out/hist.incomplete').
  pure function incomplete_name(path) result(s)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: s
    integer :: dot, slash
    slash = index(path, '/', back=.true.)
    dot = index(path, '.', back=.true.)
    ! A leading dot ('.hist') names a hidden file, not an extension.
    if (dot > slash + 1) then
      s = path(1:dot-1) // '.incomplete' // path(dot:)
    else
      s = path // '.incomplete'
    end if
  end function incomplete_name
end module raccord_history_file
