!> CRC-32 checksums (the IEEE 802.3 / zlib polynomial, reflected form
!> 0xEDB88320; initial value and final XOR 0xFFFFFFFF), so that a damaged
!> checkpoint or running output file is refused instead of continued.
!>
!> A checksum is built up in a crc32_t with crc_add over the bytes of each
!> value in turn (reals and integers by their stored bytes, which is what a
!> file holds); crc_value gives the result in 0 .. 2^32-1. The values are
!> kept in integer(i8) so that no arithmetic overflows.
module raccord_crc32
  use, intrinsic :: iso_fortran_env, only: int8
  use raccord_kinds, only: wp, i8
  implicit none
  private

  integer(i8), parameter :: MASK32 = int(z'FFFFFFFF', i8)
  integer(i8), parameter :: POLY = int(z'EDB88320', i8)

  !> A checksum under construction.
  type, public :: crc32_t
    integer(i8) :: reg = MASK32     !< the register, before the final XOR
  end type crc32_t

  interface crc_add
    module procedure add_bytes, add_real_1d, add_real_2d, add_int_1d, add_i8_1d, add_text
  end interface crc_add

  integer(i8), save :: table(0:255) = 0
  logical, save :: table_ready = .false.

  public :: crc_add, crc_value, crc_hex

contains

  !> The checksum of everything added so far.
  pure integer(i8) function crc_value(c)
    type(crc32_t), intent(in) :: c
    crc_value = ieor(c%reg, MASK32)
  end function crc_value

  !> A checksum as 8 hexadecimal digits (an attribute stores it as text).
  pure function crc_hex(crc) result(s)
    integer(i8), intent(in) :: crc
    character(len=8) :: s
    write(s, '(z8.8)') crc
  end function crc_hex

  subroutine add_bytes(c, bytes)
    type(crc32_t), intent(inout) :: c
    integer(int8), intent(in) :: bytes(:)
    integer :: k
    integer(i8) :: b
    call make_table()
    do k = 1, size(bytes)
      b = iand(int(bytes(k), i8), 255_i8)
      c%reg = ieor(table(int(iand(ieor(c%reg, b), 255_i8))), shiftr(c%reg, 8))
    end do
  end subroutine add_bytes

  subroutine add_real_1d(c, x)
    type(crc32_t), intent(inout) :: c
    real(wp), intent(in) :: x(:)
    if (size(x) > 0) call add_bytes(c, transfer(x, [0_int8]))
  end subroutine add_real_1d

  subroutine add_real_2d(c, x)
    type(crc32_t), intent(inout) :: c
    real(wp), intent(in) :: x(:,:)
    if (size(x) > 0) call add_bytes(c, transfer(x, [0_int8]))
  end subroutine add_real_2d

  subroutine add_int_1d(c, x)
    type(crc32_t), intent(inout) :: c
    integer, intent(in) :: x(:)
    if (size(x) > 0) call add_bytes(c, transfer(x, [0_int8]))
  end subroutine add_int_1d

  subroutine add_i8_1d(c, x)
    type(crc32_t), intent(inout) :: c
    integer(i8), intent(in) :: x(:)
    if (size(x) > 0) call add_bytes(c, transfer(x, [0_int8]))
  end subroutine add_i8_1d

  subroutine add_text(c, text)
    type(crc32_t), intent(inout) :: c
    character(len=*), intent(in) :: text
    if (len(text) > 0) call add_bytes(c, transfer(text, [0_int8]))
  end subroutine add_text

  !> The byte table of the reflected polynomial, made once.
  subroutine make_table()
    integer :: n, k
    integer(i8) :: r
    if (table_ready) return
    do n = 0, 255
      r = int(n, i8)
      do k = 1, 8
        if (iand(r, 1_i8) /= 0) then
          r = ieor(shiftr(r, 1), POLY)
        else
          r = shiftr(r, 1)
        end if
      end do
      table(n) = r
    end do
    table_ready = .true.
  end subroutine make_table
end module raccord_crc32
