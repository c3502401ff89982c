!> Small string helpers: number formatting, case folding, trimming.
module raccord_strings
  use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite
  use raccord_kinds, only: wp, i8
  implicit none
  private

  public :: str, lower, starts_with, ends_with, clipped, text_flaw, append_text, first_control, control_name

  !> Convert a number to its shortest readable text.
  interface str
    module procedure str_int, str_i8, str_real, str_logical
  end interface str

contains

  !> Append piece to buf(1:n), growing buf by doubling: amortised linear,
  !> where buf = buf // piece copies the whole text at each call (quadratic
  !> over the lines of a long scene echo). The caller ends with buf(1:n).
  pure subroutine append_text(buf, n, piece)
    character(len=:), allocatable, intent(inout) :: buf
    integer, intent(inout) :: n
    character(len=*), intent(in) :: piece
    character(len=:), allocatable :: grown
    if (.not. allocated(buf)) then
      allocate(character(len=max(256, 2*len(piece))) :: buf)
      n = 0
    end if
    if (n + len(piece) > len(buf)) then
      allocate(character(len=2*(n + len(piece))) :: grown)
      grown(1:n) = buf(1:n)
      call move_alloc(grown, buf)
    end if
    buf(n + 1:n + len(piece)) = piece
    n = n + len(piece)
  end subroutine append_text

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

  !> Real to text with `digits` significant digits (default 6): plain
  !> decimal between 1e-3 and 1e6 ("0.0123", "89.9", "70000"), otherwise
  !> scientific ("1.97484e-07"); trailing zeros dropped.
  pure function str_real(x, digits) result(s)
    real(wp), intent(in) :: x
    integer, intent(in), optional :: digits
    character(len=:), allocatable :: s
    character(len=48) :: buf
    character(len=24) :: fmt
    integer :: d, decimals, e, k
    d = 6
    if (present(digits)) d = max(1, min(17, digits))
    if (x == 0.0_wp) then
      s = '0'
      return
    end if
    ! NaN and infinities print without an exponent, which the trimming
    ! below relies on (a NaN multiplier residual crashed the contact warning).
    if (ieee_is_nan(x)) then
      s = 'NaN'
      return
    else if (.not. ieee_is_finite(x)) then
      s = merge('+Inf', '-Inf', x > 0.0_wp)
      return
    end if
    if (abs(x) >= 1.0e-3_wp .and. abs(x) < 1.0e6_wp) then
      decimals = max(0, d - 1 - floor(log10(abs(x))))
      write(fmt, '(a,i0,a)') '(f40.', decimals, ')'
      write(buf, fmt) x
      s = trim(adjustl(buf))
      if (index(s, '.') > 0) then
        k = len(s)
        do while (s(k:k) == '0')
          k = k - 1
        end do
        if (s(k:k) == '.') k = k - 1
        s = s(1:k)
      end if
    else
      ! Three exponent digits: without them |x| >= 1e100 prints as 1.0+100.
      write(fmt, '(a,i0,a,i0,a)') '(es', d + 9, '.', d - 1, 'e3)'
      write(buf, fmt) x
      s = trim(adjustl(buf))
      ! Mantissa: drop trailing zeros; exponent: lower-case e, no leading zeros.
      e = index(s, 'E')
      k = e - 1
      do while (s(k:k) == '0')
        k = k - 1
      end do
      if (s(k:k) == '.') k = k - 1
      s = s(1:k) // 'e' // exponent_text(s(e+1:))
    end if
  end function str_real

  !> '+005' -> '+05', '-100' -> '-100': at least two digits, like C's printf.
  pure function exponent_text(e) result(s)
    character(len=*), intent(in) :: e
    character(len=:), allocatable :: s
    integer :: k
    k = 2
    do while (k < len(e) - 1 .and. e(k:k) == '0')
      k = k + 1
    end do
    s = e(1:1) // e(k:)
  end function exponent_text

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

  !> A text of the input quoted in a message, cut to at most n characters
  !> (n >= 4) with "..." and its full length, so that a value or name of a
  !> hundred thousand characters does not make the message as long.
  pure function clipped(s, n) result(r)
    character(len=*), intent(in) :: s
    integer, intent(in) :: n
    character(len=:), allocatable :: r
    if (len_trim(s) > n) then
      r = s(1:n - 3) // '... (' // str_int(len_trim(s)) // ' characters)'
    else
      r = trim(s)
    end if
  end function clipped
  !> What keeps a text from being written as a name in an XML file (the
  !> .xmf of the results): '' when it is UTF-8 without control characters
  !> (a tab is allowed), else what is wrong and at which byte. With
  !> utf8 = .false. only control characters are looked for (paths, titles).
  pure function text_flaw(s, utf8) result(r)
    character(len=*), intent(in) :: s
    logical, intent(in) :: utf8
    character(len=:), allocatable :: r
    integer :: k, b, n, j, c, lo, hi
    r = ''
    k = 1
    do while (k <= len(s))
      b = iachar(s(k:k))
      if ((b < 32 .and. b /= 9) .or. b == 127) then
        r = 'byte ' // str_int(k) // ' is a control character (code ' // str_int(b) // ')'
        return
      end if
      if (b < 128 .or. .not. utf8) then
        k = k + 1
        cycle
      end if
      ! A lead byte and the range of its first continuation byte (no
      ! overlong forms, no surrogates, nothing above U+10FFFF).
      lo = 128
      hi = 191
      select case (b)
      case (194:223)
        n = 1
      case (224)
        n = 2; lo = 160
      case (225:236, 238:239)
        n = 2
      case (237)
        n = 2; hi = 159
      case (240)
        n = 3; lo = 144
      case (241:243)
        n = 3
      case (244)
        n = 3; hi = 143
      case default
        n = 0
      end select
      if (n > 0 .and. k + n <= len(s)) then
        do j = 1, n
          c = iachar(s(k+j:k+j))
          if (c < lo .or. c > hi) then
            n = 0
            exit
          end if
          lo = 128
          hi = 191
        end do
      else
        n = 0
      end if
      if (n == 0) then
        r = 'byte ' // str_int(k) // ' (code ' // str_int(b) // ') is not UTF-8 (a Latin-1 or Windows-1252 ' // &
          'character?)'
        return
      end if
      k = k + n + 1
    end do
  end function text_flaw
  !> Position of the first control character of a text line (ASCII codes
  !> 1 to 31 and 127 other than the tab, and other than the carriage
  !> return when cr_ok), 0 when there is none. NUL (0) is left to the
  !> callers, whose message for it is about binary and UTF-16 files.
  pure integer function first_control(line, cr_ok) result(pos)
    character(len=*), intent(in) :: line
    logical, intent(in) :: cr_ok
    integer :: i, c
    pos = 0
    do i = 1, len(line)
      c = iachar(line(i:i))
      if (c >= 32 .and. c /= 127) cycle
      if (c == 0 .or. c == 9 .or. (c == 13 .and. cr_ok)) cycle
      pos = i
      return
    end do
  end function first_control

  !> A control character's name for a message: "form feed (0x0C)".
  pure function control_name(code) result(name)
    integer, intent(in) :: code
    character(len=:), allocatable :: name
    character(len=*), parameter :: HEX = '0123456789ABCDEF'
    select case (code)
    case (8); name = 'backspace'
    case (11); name = 'vertical tab'
    case (12); name = 'form feed'
    case (13); name = 'carriage return'
    case (27); name = 'escape'
    case (127); name = 'delete'
    case default; name = 'code'
    end select
    if (name == 'code') then
      name = 'code 0x' // HEX(code/16 + 1:code/16 + 1) // HEX(mod(code, 16) + 1:mod(code, 16) + 1)
    else
      name = name // ' (0x' // HEX(code/16 + 1:code/16 + 1) // HEX(mod(code, 16) + 1:mod(code, 16) + 1) // ')'
    end if
  end function control_name
end module raccord_strings
