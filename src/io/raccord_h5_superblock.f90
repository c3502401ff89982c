!> Clear the "open for writing" mark of an HDF5 file that a killed run left.
!>
!> The HDF5 1.10 file format (h5_create_file: needed for checksummed chunk
!> indexes) keeps file consistency flags in its version 3 superblock: the
!> library sets them while the file is open for writing and clears them on
!> close. A run killed with SIGKILL leaves them set, and the library then
!> refuses to open the file ("may use h5clear"). A restart continues such a
!> file: it holds the run's lock (raccord_run_lock), so no process writes
!> the file, and it clears the flags as `h5clear -s` does.
!>
!> Superblock version 2 and 3 (HDF5 file format specification, "Version 2
!> Superblock"): signature (8 bytes), version, size of offsets, size of
!> lengths, file consistency flags (1 byte each), four addresses, then a
!> checksum of everything before it (Jenkins' lookup3 hash, as HDF5's
!> H5_checksum_lookup3 with initial value 0). The stored checksum is
!> checked before anything is written: a superblock that does not match it
!> is left alone (the open then fails and the restart is refused).
module raccord_h5_superblock
  use, intrinsic :: iso_fortran_env, only: int8
  use raccord_kinds, only: i8
  implicit none
  private

  integer(i8), parameter :: MASK32 = int(z'FFFFFFFF', i8)
  integer(int8), parameter :: SIGNATURE(8) = int([137, 72, 68, 70, 13, 10, 26, 10] - &
    merge(256, 0, [137, 72, 68, 70, 13, 10, 26, 10] > 127), int8)

  public :: h5_clear_write_flags, lookup3

contains

  !> Clear the consistency flags of the HDF5 file at path when they are
  !> set. cleared: they were set and are now clear; ok: false when the
  !> file could not be read or its superblock is not one this handles
  !> with a matching checksum (the file is then left unchanged).
  subroutine h5_clear_write_flags(path, cleared, ok)
    character(len=*), intent(in) :: path
    logical, intent(out) :: cleared, ok
    integer(int8) :: head(12), rest(44)
    integer(int8), allocatable :: block(:)
    integer :: u, ios, n_addr, nblock
    integer(i8) :: stored, sum
    cleared = .false.
    ok = .false.
    open(newunit=u, file=path, status='old', action='readwrite', access='stream', form='unformatted', &
      iostat=ios)
    if (ios /= 0) return
    steps: block
      read(u, pos=1, iostat=ios) head
      if (ios /= 0) exit steps
      if (any(head(1:8) /= SIGNATURE)) exit steps
      if (head(9) /= 2 .and. head(9) /= 3) exit steps
      n_addr = head(10)                     ! size of offsets
      if (n_addr /= 4 .and. n_addr /= 8) exit steps
      nblock = 12 + 4*n_addr                ! bytes before the checksum
      allocate(block(nblock))
      read(u, pos=1, iostat=ios) block, rest(1:4)
      if (ios /= 0) exit steps
      stored = bytes_le(rest(1:4))
      if (lookup3(block) /= stored) exit steps
      ok = .true.
      if (block(12) == 0) exit steps
      block(12) = 0
      sum = lookup3(block)
      write(u, pos=12, iostat=ios) block(12)
      if (ios == 0) write(u, pos=nblock + 1, iostat=ios) le_bytes(sum)
      ok = ios == 0
      cleared = ok
    end block steps
    close(u)
  end subroutine h5_clear_write_flags

  !> Bob Jenkins' lookup3 hashlittle() of a byte string with initial value
  !> 0, as a value 0 .. 2^32-1 (HDF5's metadata checksum).
  pure function lookup3(key) result(c)
    integer(int8), intent(in) :: key(:)
    integer(i8) :: a, b, c
    integer :: n, k
    n = size(key)
    a = iand(int(z'DEADBEEF', i8) + int(n, i8), MASK32)
    b = a
    c = a
    k = 0
    do while (n > 12)
      a = add(a, word(key, k + 1, 4))
      b = add(b, word(key, k + 5, 4))
      c = add(c, word(key, k + 9, 4))
      call mix(a, b, c)
      n = n - 12
      k = k + 12
    end do
    if (n == 0) return
    ! the last 1..12 bytes, little-endian, missing bytes as zero
    a = add(a, word(key, k + 1, min(4, n)))
    if (n > 4) b = add(b, word(key, k + 5, min(4, n - 4)))
    if (n > 8) c = add(c, word(key, k + 9, n - 8))
    call final(a, b, c)
  end function lookup3

  pure subroutine mix(a, b, c)
    integer(i8), intent(inout) :: a, b, c
    a = sub(a, c); a = ieor(a, rot(c, 4)); c = add(c, b)
    b = sub(b, a); b = ieor(b, rot(a, 6)); a = add(a, c)
    c = sub(c, b); c = ieor(c, rot(b, 8)); b = add(b, a)
    a = sub(a, c); a = ieor(a, rot(c, 16)); c = add(c, b)
    b = sub(b, a); b = ieor(b, rot(a, 19)); a = add(a, c)
    c = sub(c, b); c = ieor(c, rot(b, 4)); b = add(b, a)
  end subroutine mix

  pure subroutine final(a, b, c)
    integer(i8), intent(inout) :: a, b, c
    c = ieor(c, b); c = sub(c, rot(b, 14))
    a = ieor(a, c); a = sub(a, rot(c, 11))
    b = ieor(b, a); b = sub(b, rot(a, 25))
    c = ieor(c, b); c = sub(c, rot(b, 16))
    a = ieor(a, c); a = sub(a, rot(c, 4))
    b = ieor(b, a); b = sub(b, rot(a, 14))
    c = ieor(c, b); c = sub(c, rot(b, 24))
  end subroutine final

  !> 32-bit unsigned arithmetic on values 0 .. 2^32-1 held in integer(i8).
  pure integer(i8) function add(x, y)
    integer(i8), intent(in) :: x, y
    add = iand(x + y, MASK32)
  end function add

  pure integer(i8) function sub(x, y)
    integer(i8), intent(in) :: x, y
    sub = iand(x - y + 4294967296_i8, MASK32)
  end function sub

  pure integer(i8) function rot(x, k)
    integer(i8), intent(in) :: x
    integer, intent(in) :: k
    rot = iand(ior(shiftl(x, k), shiftr(x, 32 - k)), MASK32)
  end function rot

  !> Up to 4 bytes from position first, little-endian.
  pure integer(i8) function word(key, first, count)
    integer(int8), intent(in) :: key(:)
    integer, intent(in) :: first, count
    integer :: j
    word = 0
    do j = count - 1, 0, -1
      word = ior(shiftl(word, 8), iand(int(key(first + j), i8), 255_i8))
    end do
  end function word

  pure integer(i8) function bytes_le(b4)
    integer(int8), intent(in) :: b4(4)
    bytes_le = word(b4, 1, 4)
  end function bytes_le

  pure function le_bytes(v) result(b4)
    integer(i8), intent(in) :: v
    integer(int8) :: b4(4)
    integer :: j, byte
    do j = 1, 4
      byte = int(iand(shiftr(v, 8*(j - 1)), 255_i8))
      if (byte > 127) byte = byte - 256
      b4(j) = int(byte, int8)
    end do
  end function le_bytes
end module raccord_h5_superblock
