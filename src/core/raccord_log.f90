!> Run log: every message carries its level and caller, goes to the run's
!> log file (when one is open, each line with its local time stamp) and to
!> standard output or error. Standard output is flushed after every line,
!> so that a batch job's redirected output shows the progress as it goes.
!>
!> The log is the one piece of module state in raccord: a run has one log,
!> and threading it through every call would hide the algorithm.
module raccord_log
  use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
  use raccord_host, only: time_stamp
  implicit none
  private

  integer, parameter, public :: LEVEL_DEBUG = 0, LEVEL_INFO = 1, LEVEL_WARN = 2, LEVEL_ERROR = 3

  public :: log_open, log_close, log_set_level, log_level, log_set_quiet
  public :: log_debug, log_info, log_warn, log_error, log_raw, log_unit

  integer :: file_unit = -1
  integer :: threshold = LEVEL_INFO
  logical :: quiet = .false.

contains

  !> Open (replace, or with append = .true. continue) the log file.
  !> Returns iostat and a message on failure.
  subroutine log_open(path, stat, msg, append)
    character(len=*), intent(in) :: path
    integer, intent(out) :: stat
    character(len=*), intent(out) :: msg
    logical, intent(in), optional :: append
    logical :: keep
    msg = ''
    keep = .false.
    if (present(append)) keep = append
    if (file_unit /= -1) call log_close()
    if (keep) then
      open(newunit=file_unit, file=path, status='unknown', position='append', action='write', iostat=stat, &
        iomsg=msg)
    else
      open(newunit=file_unit, file=path, status='replace', action='write', iostat=stat, iomsg=msg)
    end if
    if (stat /= 0) file_unit = -1
  end subroutine log_open

  subroutine log_close()
    if (file_unit /= -1) close(file_unit)
    file_unit = -1
  end subroutine log_close

  !> Lowest level that is printed (LEVEL_DEBUG shows everything).
  subroutine log_set_level(level)
    integer, intent(in) :: level
    threshold = level
  end subroutine log_set_level

  !> The level set by log_set_level.
  integer function log_level()
    log_level = threshold
  end function log_level

  !> Quiet: informational lines go to the log file only.
  subroutine log_set_quiet(flag)
    logical, intent(in) :: flag
    quiet = flag
  end subroutine log_set_quiet

  !> Unit of the open log file, or -1.
  integer function log_unit()
    log_unit = file_unit
  end function log_unit

  subroutine log_debug(caller, text)
    character(len=*), intent(in) :: caller, text
    call emit(LEVEL_DEBUG, caller, text)
  end subroutine log_debug

  subroutine log_info(caller, text)
    character(len=*), intent(in) :: caller, text
    call emit(LEVEL_INFO, caller, text)
  end subroutine log_info

  subroutine log_warn(caller, text)
    character(len=*), intent(in) :: caller, text
    call emit(LEVEL_WARN, caller, text)
  end subroutine log_warn

  subroutine log_error(caller, text)
    character(len=*), intent(in) :: caller, text
    call emit(LEVEL_ERROR, caller, text)
  end subroutine log_error

  !> A line without level or caller (tables, echoed scene), to stdout and file.
  subroutine log_raw(text)
    character(len=*), intent(in) :: text
    if (.not. quiet) then
      write(output_unit, '(a)') text
      flush(output_unit)
    end if
    if (file_unit /= -1) write(file_unit, '(a)') text
  end subroutine log_raw

  subroutine emit(level, caller, text)
    integer, intent(in) :: level
    character(len=*), intent(in) :: caller, text
    character(len=7), parameter :: tag(0:3) = ['debug  ', 'info   ', 'WARNING', 'ERROR  ']
    character(len=:), allocatable :: line
    if (level < threshold) return
    line = trim(tag(level)) // ' [' // caller // '] ' // text
    if (level >= LEVEL_WARN) then
      write(error_unit, '(a)') line
      ! Before anything the runtime prints on the way out (ERROR STOP, a
      ! backtrace): a job script looks for raccord's own line first.
      flush(error_unit)
    else if (.not. quiet) then
      write(output_unit, '(a)') line
      flush(output_unit)
    end if
    if (file_unit /= -1) then
      write(file_unit, '(a)') time_stamp() // ' ' // line
      flush(file_unit)
    end if
  end subroutine emit
end module raccord_log
