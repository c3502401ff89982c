!> What the machine has: its physical memory, against which sizes taken
!> from the input are checked before anything is allocated (issue #18:
!> a table sized by the step count once asked for 12 GB).
module raccord_machine
  use, intrinsic :: iso_c_binding, only: c_int, c_long
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
  end interface

  public :: physical_memory_bytes

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
end module raccord_machine
