!> What the machine has: its physical memory, against which sizes taken
!> from the input are checked before anything is allocated (issue #18:
!> a table sized by the step count once asked for 12 GB), and the free
!> space of a folder, against which outputs sized by the step count are
!> checked before a run starts.
module raccord_machine
  use, intrinsic :: iso_c_binding, only: c_int, c_long, c_char, c_null_char
  use raccord_kinds, only: i8
  implicit none
  private

  ! sysconf(3) names on Linux (glibc's bits/confname.h).
  integer(c_int), parameter :: SC_PAGESIZE = 30_c_int, SC_PHYS_PAGES = 85_c_int

  interface
    function c_sysconf(name) bind(C, name='sysconf') result(v)
      import :: c_int, c_long
      integer(c_int), value :: name
      integer(c_long) :: v
    end function c_sysconf

    ! statvfs(3): the buffer is larger than struct statvfs (11 longs and
    ! 6 ints on 64-bit Linux); f_frsize is its 2nd long, f_blocks its 3rd,
    ! f_bavail its 5th.
    function c_statvfs(path, buf) bind(C, name='statvfs') result(rc)
      import :: c_int, c_long, c_char
      character(kind=c_char), intent(in) :: path(*)
      integer(c_long), intent(out) :: buf(32)
      integer(c_int) :: rc
    end function c_statvfs
  end interface

  public :: physical_memory_bytes, free_disk_bytes

contains

  !> Physical memory in bytes (sysconf _SC_PHYS_PAGES * _SC_PAGESIZE), or
  !> 4 GiB when the system does not tell.
  function physical_memory_bytes() result(bytes)
    integer(i8) :: bytes
    integer(c_long) :: pages, page
    pages = c_sysconf(SC_PHYS_PAGES)
    page = c_sysconf(SC_PAGESIZE)
    if (pages > 0 .and. page > 0) then
      bytes = int(pages, i8)*int(page, i8)
    else
      bytes = 4_i8*1024_i8**3
    end if
  end function physical_memory_bytes

  !> Bytes an unprivileged process may still write in the file system of
  !> `path` (statvfs f_bavail * f_frsize) and, in `total`, its size
  !> (f_blocks * f_frsize); for a path that does not exist yet, those of the
  !> nearest existing folder above it; -1 when the system does not tell.
  function free_disk_bytes(path, total) result(bytes)
    character(len=*), intent(in) :: path
    integer(i8), intent(out), optional :: total
    integer(i8) :: bytes
    integer(c_long) :: buf(32)
    character(len=:), allocatable :: p
    integer :: k
    bytes = -1
    if (present(total)) total = -1
    p = trim(path)
    do
      if (len(p) == 0) p = '.'
      buf = 0
      if (c_statvfs(p // c_null_char, buf) == 0) exit
      if (p == '.' .or. p == '/') return
      k = index(p, '/', back=.true.)
      if (k == 1) then
        p = '/'
      else
        p = p(1:max(k - 1, 0))
      end if
    end do
    if (buf(2) <= 0) return
    bytes = times_block(buf(5))
    if (present(total)) total = times_block(buf(3))
  contains
    !> n blocks in bytes, capped at huge (no overflow).
    integer(i8) function times_block(n)
      integer(c_long), intent(in) :: n
      times_block = -1
      if (n < 0) return
      times_block = huge(1_i8)
      if (n <= huge(1_i8)/buf(2)) times_block = int(n, i8)*int(buf(2), i8)
    end function times_block
  end function free_disk_bytes
end module raccord_machine
