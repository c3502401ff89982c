!> One run at a time per output stem: a lock on <stem>.lock.
!>
!> Two runs started into the same folder with the same scene name wrote the
!> same .part files: one failed and the other reported success with a file
!> that could not be opened. A run now takes an exclusive flock(2) on
!> <stem>.lock before it writes anything there, and a second run is refused
!> while the first holds it. The kernel drops the lock when the process
!> ends in any way (SIGKILL included), so a killed run leaves no stale lock:
!> the file it leaves behind is taken by the next run.
module raccord_run_lock
  use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
  use raccord_error, only: error_t, raise_error, EXIT_IO
  use raccord_files, only: write_failure_reason
  implicit none
  private

  integer(c_int), parameter :: LOCK_EX = 2_c_int, LOCK_NB = 4_c_int
  integer(c_int), parameter :: LOCK_MODE = int(o'644', c_int)

  interface
    function c_creat(path, mode) bind(C, name='creat') result(fd)
      import :: c_int, c_char
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int), value :: mode
      integer(c_int) :: fd
    end function c_creat
    function c_flock(fd, operation) bind(C, name='flock') result(rc)
      import :: c_int
      integer(c_int), value :: fd, operation
      integer(c_int) :: rc
    end function c_flock
    function c_close(fd) bind(C, name='close') result(rc)
      import :: c_int
      integer(c_int), value :: fd
      integer(c_int) :: rc
    end function c_close
    function c_unlink(path) bind(C, name='unlink') result(rc)
      import :: c_int, c_char
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int) :: rc
    end function c_unlink
  end interface

  !> The lock this process holds (one run per process).
  integer(c_int), save :: held_fd = -1
  character(len=:), allocatable, save :: held_path

  public :: take_run_lock, drop_run_lock, run_lock_name

contains

  !> The lock file of a run's stem.
  pure function run_lock_name(stem) result(name)
    character(len=*), intent(in) :: stem
    character(len=:), allocatable :: name
    name = stem // '.lock'
  end function run_lock_name

  !> Take the lock of stem (its folder must exist), or fail with EXIT_IO
  !> when another run holds it or the file cannot be made.
  subroutine take_run_lock(stem, err)
    character(len=*), intent(in) :: stem
    type(error_t), intent(inout) :: err
    integer(c_int) :: fd, rc
    character(len=:), allocatable :: path
    if (held_fd >= 0) return
    path = run_lock_name(stem)
    fd = c_creat(path // c_null_char, LOCK_MODE)
    if (fd < 0) then
      call raise_error(err, EXIT_IO, 'cannot create the run lock ' // path // ': ' // &
        write_failure_reason(path_folder(path)))
      return
    end if
    if (c_flock(fd, ior(LOCK_EX, LOCK_NB)) /= 0) then
      rc = c_close(fd)
      call raise_error(err, EXIT_IO, 'another raccord run is writing ' // stem // '.* (it holds ' // path // &
        '): wait until it ends, or give this run another output folder (--output DIR)')
      return
    end if
    held_fd = fd
    held_path = path
  end subroutine take_run_lock

  !> The folder part of a path ('.' when it has none).
  pure function path_folder(path) result(dir)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: dir
    integer :: k
    k = index(path, '/', back=.true.)
    dir = '.'
    if (k > 1) dir = path(1:k-1)
    if (k == 1) dir = '/'
  end function path_folder

  !> Remove the lock file and release the lock (at the end of the run).
  subroutine drop_run_lock()
    integer(c_int) :: rc
    if (held_fd < 0) return
    rc = c_unlink(held_path // c_null_char)
    rc = c_close(held_fd)
    held_fd = -1
  end subroutine drop_run_lock
end module raccord_run_lock
