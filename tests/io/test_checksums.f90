!> The checksums behind issue #18's damage checks and the thread-count
!> parser: CRC-32 (raccord_crc32) and Jenkins' lookup3 (raccord_h5_superblock)
!> against their published check values, a one-bit change caught by both,
!> a CRC built in pieces equal to the CRC of the whole, and OMP_NUM_THREADS
!> values read as raccord_threads reads them.
program test_checksums
  use, intrinsic :: iso_fortran_env, only: int8
  use raccord_kinds, only: wp, i8
  use raccord_strings, only: str
  use raccord_check, only: failure_t, new_test, run_tests, check
  use raccord_crc32, only: crc32_t, crc_add, crc_value, crc_hex
  use raccord_h5_superblock, only: lookup3
  use raccord_threads, only: parse_thread_count
  implicit none

  call run_tests('checksums', [ &
    new_test('CRC-32 of "123456789" is CBF43926 (the check value of the IEEE polynomial)', test_crc_check_value), &
    new_test('CRC-32 of a real array, added whole or in two pieces, is the same; one flipped bit changes it', &
      test_crc_pieces), &
    new_test('lookup3 of "" is DEADBEEF and of "Four score and seven years ago" 17770551 (lookup3.c)', &
      test_lookup3), &
    new_test('OMP_NUM_THREADS values: good, absurd, not numbers', test_thread_counts)])

contains

  function bytes_of(text) result(b)
    character(len=*), intent(in) :: text
    integer(int8), allocatable :: b(:)
    integer :: k
    allocate(b(len(text)))
    do k = 1, len(text)
      b(k) = int(transfer(text(k:k), 0_int8), int8)
    end do
  end function bytes_of

  subroutine test_crc_check_value(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(crc32_t) :: c, empty
    call crc_add(c, '123456789')
    call check(failure, crc_hex(crc_value(c)) == 'CBF43926', 'CRC-32 of "123456789" is ' // crc_hex(crc_value(c)))
    if (allocated(failure)) return
    call check(failure, crc_value(empty) == 0_i8, 'CRC-32 of nothing is ' // str(crc_value(empty)) // ', not 0')
  end subroutine test_crc_check_value

  subroutine test_crc_pieces(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(crc32_t) :: whole, parts, flipped
    real(wp) :: x(50), y(50)
    integer(i8) :: bits
    integer :: k
    x = [(sin(real(k, wp)), k = 1, 50)]
    call crc_add(whole, x)
    call crc_add(parts, x(1:17))
    call crc_add(parts, x(18:50))
    call check(failure, crc_value(whole) == crc_value(parts), 'in pieces ' // crc_hex(crc_value(parts)) // &
      ', whole ' // crc_hex(crc_value(whole)))
    if (allocated(failure)) return
    y = x
    bits = transfer(y(23), bits)
    y(23) = transfer(ieor(bits, 1_i8), y(23))
    call crc_add(flipped, y)
    call check(failure, crc_value(flipped) /= crc_value(whole), 'one flipped bit left the CRC-32 unchanged')
  end subroutine test_crc_pieces

  subroutine test_lookup3(failure)
    type(failure_t), allocatable, intent(out) :: failure
    integer(int8), allocatable :: none(:), text(:)
    integer(i8) :: h
    allocate(none(0))
    h = lookup3(none)
    call check(failure, h == int(z'DEADBEEF', i8), 'lookup3 of "" is ' // crc_hex(h))
    if (allocated(failure)) return
    text = bytes_of('Four score and seven years ago')
    h = lookup3(text)
    call check(failure, h == int(z'17770551', i8), 'lookup3 of "Four score and seven years ago" is ' // crc_hex(h))
    if (allocated(failure)) return
    text(5) = int(ieor(int(text(5)), 4), int8)
    call check(failure, lookup3(text) /= h, 'one changed bit left lookup3 unchanged')
  end subroutine test_lookup3

  subroutine test_thread_counts(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect(failure, '4', 4, .true.)
    call expect(failure, ' 3 ', 3, .true.)
    call expect(failure, '8,4', 8, .true.)
    call expect(failure, '000012', 12, .true.)
    call expect(failure, '99999999999', 1, .false.)
    call expect(failure, '18446744073709551617', 1, .false.)
    call expect(failure, '0', 1, .false.)
    call expect(failure, '-2', 1, .false.)
    call expect(failure, 'abc', 1, .false.)
    call expect(failure, '2.5', 1, .false.)
    call expect(failure, ',4', 1, .false.)
  end subroutine test_thread_counts

  !> parse_thread_count(text) gives n_expected, with no complaint when good.
  subroutine expect(failure, text, n_expected, good)
    type(failure_t), allocatable, intent(inout) :: failure
    character(len=*), intent(in) :: text
    integer, intent(in) :: n_expected
    logical, intent(in) :: good
    integer :: n
    character(len=:), allocatable :: why
    if (allocated(failure)) return
    call parse_thread_count(text, n, why)
    call check(failure, n == n_expected .and. ((len(why) == 0) .eqv. good), 'OMP_NUM_THREADS = "' // text // &
      '" read as ' // str(n) // ' (' // why // '), expected ' // str(n_expected))
  end subroutine expect
end program test_checksums
