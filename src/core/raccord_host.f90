!> Where and when a run happens, for the log: the host name (POSIX
!> gethostname) and a local time stamp (ISO 8601, to the second).
module raccord_host
  use, intrinsic :: iso_c_binding, only: c_char, c_int, c_size_t, c_null_char
  implicit none
  private

  public :: host_name, time_stamp

  interface
    !> POSIX: int gethostname(char *name, size_t len)
    integer(c_int) function c_gethostname(name, length) bind(C, name='gethostname')
      import :: c_char, c_int, c_size_t
      character(kind=c_char), intent(out) :: name(*)
      integer(c_size_t), value :: length
    end function c_gethostname
  end interface

contains

  !> The host's name, or 'unknown' when the system does not say.
  function host_name() result(s)
    character(len=:), allocatable :: s
    character(kind=c_char) :: buf(256)
    integer :: k
    buf = c_null_char
    if (c_gethostname(buf, int(size(buf) - 1, c_size_t)) /= 0) then
      s = 'unknown'
      return
    end if
    s = ''
    do k = 1, size(buf)
      if (buf(k) == c_null_char) exit
      s = s // buf(k)
    end do
    if (len(s) == 0) s = 'unknown'
  end function host_name

  !> Local date and time, e.g. 2026-11-25T12:07:37.
  function time_stamp() result(s)
    character(len=19) :: s
    integer :: v(8)
    call date_and_time(values=v)
    write(s, '(i4.4,"-",i2.2,"-",i2.2,"T",i2.2,":",i2.2,":",i2.2)') v(1), v(2), v(3), v(5), v(6), v(7)
  end function time_stamp
end module raccord_host
