!> Small string helpers: number formatting, case folding, trimming.
module raccord_strings
  use raccord_kinds, only: wp, i8
  implicit none
  private

  public :: str, lower, starts_with, ends_with

  !> Convert a number to its shortest readable text.
  interface str
    module procedure str_int, str_i8, str_real, str_logical
  end interface str

contains

  pure function str_int(i) result(s)
    integer, intent(in) :: i
    character(len=:), allocatable :: s
    character(len=24) :: buf
    write(buf, '(i0)') i
    s = trim(buf)
  end function str_int

  pure function str_i8(i) result(s)
    integer(i8), intent(in) :: i
    character(len=:), allocatable :: s
    character(len=24) :: buf
    write(buf, '(i0)') i
    s = trim(buf)
  end function str_i8

  !> Real to text with `digits` significant digits (default 6), no padding.
  pure function str_real(x, digits) result(s)
    real(wp), intent(in) :: x
    integer, intent(in), optional :: digits
    character(len=:), allocatable :: s
    character(len=40) :: buf
    character(len=20) :: fmt
    integer :: d
    d = 6
    if (present(digits)) d = max(1, min(17, digits))
    write(fmt, '(a,i0,a,i0,a)') '(es', d + 8, '.', d - 1, ')'
    write(buf, fmt) x
    s = trim(adjustl(buf))
  end function str_real

  pure function str_logical(l) result(s)
    logical, intent(in) :: l
    character(len=:), allocatable :: s
    if (l) then
      s = 'true'
    else
      s = 'false'
    end if
  end function str_logical

  !> Lower-case copy of an ASCII string.
  pure function lower(s) result(r)
    character(len=*), intent(in) :: s
    character(len=len(s)) :: r
    integer :: k, c
    r = s
    do k = 1, len(s)
      c = iachar(s(k:k))
      if (c >= iachar('A') .and. c <= iachar('Z')) r(k:k) = achar(c + 32)
    end do
  end function lower

  pure logical function starts_with(s, prefix)
    character(len=*), intent(in) :: s, prefix
    starts_with = .false.
    if (len(s) < len(prefix)) return
    starts_with = s(1:len(prefix)) == prefix
  end function starts_with

  pure logical function ends_with(s, suffix)
    character(len=*), intent(in) :: s, suffix
    ends_with = .false.
    if (len(s) < len(suffix)) return
    ends_with = s(len(s)-len(suffix)+1:) == suffix
  end function ends_with
end module raccord_strings
