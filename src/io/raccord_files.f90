!> Small file-system helpers (rename, mkdir -p, exists, delete, size, truncate).
!>
!> Fortran 2008 has no rename or mkdir, so these call the POSIX C library
!> through ISO_C_BINDING interfaces; no C shim is needed. The one
!> non-standard symbol is glibc's/musl's `__errno_location`, the function
!> behind the C `errno` macro: it gives the reason for a failure, which a
!> message needs to say how to fix it.
module raccord_files
  use, intrinsic :: iso_c_binding, only: c_int, c_char, c_ptr, c_null_char, c_associated, &
    c_f_pointer, c_long, c_size_t, c_int8_t
  use raccord_kinds, only: i8
  use raccord_error, only: error_t, raise_error, EXIT_IO
  use raccord_crc32, only: crc32_t, crc_add, crc_value
  implicit none
  private

  public :: rename_file, make_directory, file_exists, delete_file, file_size, truncate_file
  public :: write_failure_reason, crc_of_file, broken_link, relative_note, is_directory

  !> access(2) mode "does the file exist".
  integer(c_int), parameter :: F_OK = 0_c_int
  !> Permissions for new directories; the process umask still applies,
  !> as for `mkdir -p`.
  integer(c_int), parameter :: DIR_MODE = int(o'777', c_int)
  !> access(2) mode "may this process write there".
  integer(c_int), parameter :: W_OK = 2_c_int
  !> Longest C error text copied from strerror.
  integer, parameter :: MAX_ERRTEXT = 256

  interface
    function c_rename(from, to) bind(C, name='rename') result(rc)
      import :: c_int, c_char
      character(kind=c_char), intent(in) :: from(*), to(*)
      integer(c_int) :: rc
    end function c_rename

    function c_mkdir(path, mode) bind(C, name='mkdir') result(rc)
      import :: c_int, c_char
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int), value :: mode    ! mode_t is a 32-bit unsigned int on Linux
      integer(c_int) :: rc
    end function c_mkdir

    function c_access(path, mode) bind(C, name='access') result(rc)
      import :: c_int, c_char
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int), value :: mode
      integer(c_int) :: rc
    end function c_access

    ! ssize_t is a 64-bit long on the 64-bit Linux targets raccord builds for.
    function c_readlink(path, buf, size) bind(C, name='readlink') result(n)
      import :: c_char, c_size_t, c_long
      character(kind=c_char), intent(in) :: path(*)
      character(kind=c_char), intent(out) :: buf(*)
      integer(c_size_t), value :: size
      integer(c_long) :: n
    end function c_readlink

    function c_unlink(path) bind(C, name='unlink') result(rc)
      import :: c_int, c_char
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int) :: rc
    end function c_unlink

    ! off_t is a 64-bit long on the 64-bit Linux targets raccord builds for.
    function c_truncate(path, length) bind(C, name='truncate') result(rc)
      import :: c_int, c_char, c_long
      character(kind=c_char), intent(in) :: path(*)
      integer(c_long), value :: length
      integer(c_int) :: rc
    end function c_truncate

    function c_fopen(path, mode) bind(C, name='fopen') result(fp)
      import :: c_char, c_ptr
      character(kind=c_char), intent(in) :: path(*), mode(*)
      type(c_ptr) :: fp
    end function c_fopen

    function c_fwrite(buf, size, n, fp) bind(C, name='fwrite') result(written)
      import :: c_char, c_ptr, c_size_t
      character(kind=c_char), intent(in) :: buf(*)
      integer(c_size_t), value :: size, n
      type(c_ptr), value :: fp
      integer(c_size_t) :: written
    end function c_fwrite

    function c_fread(buf, size, n, fp) bind(C, name='fread') result(got)
      import :: c_ptr, c_size_t, c_int8_t
      integer(c_int8_t), intent(out) :: buf(*)
      integer(c_size_t), value :: size, n
      type(c_ptr), value :: fp
      integer(c_size_t) :: got
    end function c_fread

    function c_fflush(fp) bind(C, name='fflush') result(rc)
      import :: c_int, c_ptr
      type(c_ptr), value :: fp
      integer(c_int) :: rc
    end function c_fflush

    function c_fclose(fp) bind(C, name='fclose') result(rc)
      import :: c_int, c_ptr
      type(c_ptr), value :: fp
      integer(c_int) :: rc
    end function c_fclose

    function c_strerror(errnum) bind(C, name='strerror') result(text)
      import :: c_int, c_ptr
      integer(c_int), value :: errnum
      type(c_ptr) :: text
    end function c_strerror

    function c_errno_location() bind(C, name='__errno_location') result(p)
      import :: c_ptr
      type(c_ptr) :: p
    end function c_errno_location
  end interface

contains

  !> Rename (move) a file, replacing `to` if it exists (POSIX rename:
  !> atomic on one file system, which is why results are written under a
  !> temporary name and renamed when complete).
  subroutine rename_file(from, to, err)
    character(len=*), intent(in) :: from, to
    type(error_t), intent(inout) :: err
    if (c_rename(c_path(from), c_path(to)) /= 0) then
      call raise_error(err, EXIT_IO, 'cannot rename "' // trim(from) // '" to "' // trim(to) &
        // '": ' // last_error_text() // '; check that both paths are on a writable file system')
    end if
  end subroutine rename_file

  !> Create a directory and its missing parents (`mkdir -p`); an existing
  !> directory is fine. An empty path means the current directory.
  subroutine make_directory(path, err)
    character(len=*), intent(in) :: path
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: p
    integer :: k
    p = trim(path)
    if (len(p) == 0) return
    ! Create each prefix that ends before a '/', then the whole path.
    do k = 2, len(p)
      if (p(k:k) == '/' .and. p(k-1:k-1) /= '/') then
        call make_one(p(1:k-1), p, err)
        if (err%failed()) return
      end if
    end do
    call make_one(p, p, err)
  end subroutine make_directory

  !> True when something exists at the path (file, directory or other).
  logical function file_exists(path)
    character(len=*), intent(in) :: path
    file_exists = c_access(c_path(path), F_OK) == 0
  end function file_exists

  !> A symbolic link that leads nowhere: true, with the link's target as
  !> the link holds it (readlink(2); a relative target is relative to the
  !> link's folder), when nothing exists at `path` once the links are
  !> followed (the target is missing, or the links form a loop) but
  !> `path` itself is a link. False for a file, a folder, a link that
  !> resolves and a path where nothing is at all. Lets a message say
  !> "broken link to X" where "does not exist" would send the user to
  !> look for a file that is plainly there in `ls`.
  logical function broken_link(path, target)
    character(len=*), intent(in) :: path
    character(len=:), allocatable, intent(out) :: target
    integer, parameter :: MAX_TARGET = 4096
    character(kind=c_char) :: buf(MAX_TARGET)
    integer(c_long) :: n
    integer :: k
    broken_link = .false.
    target = ''
    if (file_exists(path)) return
    n = c_readlink(c_path(path), buf, int(MAX_TARGET, c_size_t))
    if (n < 0) return
    target = repeat(' ', int(n))
    do k = 1, int(n)
      target(k:k) = buf(k)
    end do
    broken_link = .true.
  end function broken_link

  !> " (relative to the link's folder)" for a link target that is not an
  !> absolute path, '' for one that is: where a message quotes a target.
  pure function relative_note(target) result(s)
    character(len=*), intent(in) :: target
    character(len=:), allocatable :: s
    s = ' (relative to the link''s folder)'
    if (len(target) > 0) then
      if (target(1:1) == '/') s = ''
    end if
  end function relative_note

  !> Delete a file; nothing happens (and no error) if it does not exist,
  !> because callers use it to clear stale outputs.
  subroutine delete_file(path)
    character(len=*), intent(in) :: path
    integer(c_int) :: rc
    rc = c_unlink(c_path(path))
  end subroutine delete_file

  !> Size of a file in bytes, -1 when it does not exist or cannot be asked.
  integer(i8) function file_size(path)
    character(len=*), intent(in) :: path
    integer(i8) :: n
    integer :: ios
    logical :: there
    file_size = -1
    inquire(file=path, exist=there, iostat=ios)
    if (ios /= 0 .or. .not. there) return
    inquire(file=path, size=n, iostat=ios)
    if (ios == 0) file_size = n
  end function file_size

  !> Cut a file to `bytes` bytes (POSIX truncate): a restarted run drops
  !> what a killed run wrote after its checkpoint.
  subroutine truncate_file(path, bytes, err)
    character(len=*), intent(in) :: path
    integer(i8), intent(in) :: bytes
    type(error_t), intent(inout) :: err
    if (c_truncate(c_path(path), int(bytes, c_long)) /= 0) then
      call raise_error(err, EXIT_IO, 'cannot truncate "' // trim(path) // '" to ' // trim(i8_text(bytes)) &
        // ' bytes: ' // last_error_text())
    end if
  end subroutine truncate_file

  !> Why a file could not be written in a folder, found out after the fact
  !> (HDF5 does not pass the system's reason on): the folder is missing, or
  !> not writable, or a probe of 64 KiB written and flushed there fails with
  !> the system's own words (a full disk: "No space left on device").
  function write_failure_reason(folder, takes_writes) result(reason)
    character(len=*), intent(in) :: folder
    logical, intent(out), optional :: takes_writes   !< the probe write went through
    character(len=:), allocatable :: reason, dir, probe
    character(kind=c_char, len=1024) :: block
    type(c_ptr) :: fp
    integer(c_int) :: rc
    integer :: k
    logical :: failed
    dir = trim(folder)
    if (len(dir) == 0) dir = '.'
    if (present(takes_writes)) takes_writes = .false.
    if (.not. is_directory(dir)) then
      reason = 'the folder "' // dir // '" does not exist (or is not a folder)'
      return
    end if
    if (c_access(c_path(dir), W_OK) /= 0) then
      reason = 'the folder "' // dir // '" is not writable: ' // last_error_text()
      return
    end if
    ! C stdio, not a Fortran unit: gfortran's FLUSH and CLOSE do not report
    ! a write the disk refused, fflush(3) does, with errno.
    probe = dir // '/.raccord-write-probe'
    reason = ''
    fp = c_fopen(c_path(probe), c_path('w'))
    if (.not. c_associated(fp)) then
      reason = 'cannot create a file in "' // dir // '": ' // last_error_text()
      return
    end if
    block = repeat('0', len(block))
    do k = 1, 64
      if (c_fwrite(block, 1_c_size_t, int(len(block), c_size_t), fp) /= int(len(block), c_size_t)) exit
    end do
    ! (the flush only after all 64 writes took: two tests, since Fortran's
    ! .or. need not evaluate, or skip, either operand)
    failed = k <= 64
    if (.not. failed) failed = c_fflush(fp) /= 0
    if (failed) reason = 'writing in "' // dir // '" fails: ' // last_error_text() // &
      ' (full disk or quota?): free some space or write elsewhere (--output)'
    rc = c_fclose(fp)
    rc = c_unlink(c_path(probe))
    if (len(reason) == 0) then
      reason = 'the folder "' // dir // '" takes a 64 KiB test file, so the failure may have passed (was ' // &
        'the disk nearly full?)'
      if (present(takes_writes)) takes_writes = .true.
    end if
  end function write_failure_reason

  !> CRC-32 of the first `bytes` bytes of a file, or -1 when it cannot be
  !> read or is shorter. Read through C stdio: the file may be open on a
  !> Fortran unit of this run (a running history), which a second Fortran
  !> unit may not open.
  function crc_of_file(path, bytes) result(crc)
    character(len=*), intent(in) :: path
    integer(i8), intent(in) :: bytes
    integer(i8) :: crc
    integer, parameter :: block = 65536
    integer(c_int8_t), allocatable :: buf(:)
    type(crc32_t) :: c
    type(c_ptr) :: fp
    integer(i8) :: done, n
    integer(c_size_t) :: got
    integer(c_int) :: rc
    crc = -1
    if (bytes < 0) return
    fp = c_fopen(c_path(path), c_path('rb'))
    if (.not. c_associated(fp)) return
    allocate(buf(block))
    done = 0
    do while (done < bytes)
      n = min(int(block, i8), bytes - done)
      got = c_fread(buf, 1_c_size_t, int(n, c_size_t), fp)
      if (got /= int(n, c_size_t)) exit
      call crc_add(c, buf(1:n))
      done = done + n
    end do
    rc = c_fclose(fp)
    if (done == bytes) crc = crc_value(c)
  end function crc_of_file

  ! --- private -----------------------------------------------------------

  !> One level of make_directory: create `dir`, a prefix of `target`.
  subroutine make_one(dir, target, err)
    character(len=*), intent(in) :: dir, target
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: reason
    if (is_directory(dir)) return
    if (c_mkdir(c_path(dir), DIR_MODE) == 0) return
    reason = last_error_text()
    ! Another process may have created it between the test and mkdir.
    if (is_directory(dir)) return
    if (file_exists(dir)) reason = 'it exists and is not a directory'
    if (dir == target) then
      call raise_error(err, EXIT_IO, 'cannot create directory "' // target // '": ' // reason &
        // '; check the path and that its parent is a writable directory')
    else
      call raise_error(err, EXIT_IO, 'cannot create directory "' // target // '": "' // dir &
        // '": ' // reason // '; check the path and that its parent is a writable directory')
    end if
  end subroutine make_one

  !> A path is a directory when "path/." exists (ENOTDIR otherwise), which
  !> avoids the platform-specific layout of struct stat.
  logical function is_directory(path)
    character(len=*), intent(in) :: path
    is_directory = c_access(c_path(path // '/.'), F_OK) == 0
  end function is_directory

  !> Null-terminated copy of a Fortran path, trailing blanks removed.
  pure function c_path(path) result(s)
    character(len=*), intent(in) :: path
    character(kind=c_char, len=:), allocatable :: s
    s = trim(path) // c_null_char
  end function c_path

  !> strerror(errno) as a Fortran string, read right after the failed call.
  function last_error_text() result(text)
    character(len=:), allocatable :: text
    integer(c_int), pointer :: errno
    character(kind=c_char), pointer :: chars(:)
    type(c_ptr) :: p
    integer :: n, code
    character(len=16) :: buf
    code = 0
    p = c_errno_location()
    if (c_associated(p)) then
      call c_f_pointer(p, errno)
      code = errno
    end if
    write(buf, '(i0)') code
    text = 'error ' // trim(buf)
    p = c_strerror(int(code, c_int))
    if (.not. c_associated(p)) return
    call c_f_pointer(p, chars, [MAX_ERRTEXT])
    n = 0
    do while (n < MAX_ERRTEXT)
      if (chars(n + 1) == c_null_char) exit
      n = n + 1
    end do
    if (n == 0) return
    deallocate(text)
    allocate(character(len=n) :: text)
    do while (n > 0)
      text(n:n) = chars(n)
      n = n - 1
    end do
  end function last_error_text

  pure function i8_text(n) result(s)
    integer(i8), intent(in) :: n
    character(len=24) :: s
    write(s, '(i0)') n
  end function i8_text
end module raccord_files
