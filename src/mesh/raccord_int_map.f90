!> Hash map from 64-bit integer keys to positive integer values.
!>
!> The mesh readers turn sparse file ids into internal indices and find the
!> element sides that share a corner pair; both must stay O(n) for meshes of
!> a million entities, so a sorted search is avoided. Open addressing with
!> linear probing; the table doubles when it is half full. Value 0 means
!> "absent", so only positive values may be stored.
module raccord_int_map
  use raccord_kinds, only: i8
  implicit none
  private

  public :: map_init, map_insert, map_get, pair_key, text_key

  !> Open-addressing table; capacity is a power of two.
  type, public :: int_map_t
    integer :: n = 0
    integer(i8), allocatable :: key(:)
    integer, allocatable :: val(:)          !< 0 marks an empty slot
  end type int_map_t

contains

  !> Empty map sized for about `expected` keys.
  subroutine map_init(map, expected)
    type(int_map_t), intent(out) :: map
    integer, intent(in) :: expected
    integer :: cap
    cap = 16
    do while (cap < 2*max(expected, 1))
      cap = 2*cap
    end do
    allocate(map%key(cap), map%val(cap))
    map%key = 0_i8
    map%val = 0
    map%n = 0
  end subroutine map_init

  !> Insert key -> val (val > 0). When the key is already present nothing is
  !> changed and its value is returned in `existing`; otherwise existing = 0.
  subroutine map_insert(map, key, val, existing)
    type(int_map_t), intent(inout) :: map
    integer(i8), intent(in) :: key
    integer, intent(in) :: val
    integer, intent(out) :: existing
    integer :: slot
    if (.not. allocated(map%key)) call map_init(map, 16)
    if (2*(map%n + 1) > size(map%key)) call grow(map)
    slot = find_slot(map, key)
    existing = map%val(slot)
    if (existing /= 0) return
    map%key(slot) = key
    map%val(slot) = val
    map%n = map%n + 1
  end subroutine map_insert

  !> Value stored for key, or 0.
  pure integer function map_get(map, key)
    type(int_map_t), intent(in) :: map
    integer(i8), intent(in) :: key
    map_get = 0
    if (.not. allocated(map%key)) return
    map_get = map%val(find_slot(map, key))
  end function map_get

  !> Order-independent key of two positive ids below 2**31 (an element side
  !> is the same side whichever element walks it).
  pure integer(i8) function pair_key(a, b)
    integer, intent(in) :: a, b
    pair_key = int(min(a, b), i8)*2147483648_i8 + int(max(a, b), i8)
  end function pair_key

  !> Slot holding key, or the empty slot where it would go.
  !> A key for a text (a set's label): two polynomial hashes modulo primes
  !> below 2^31 side by side, so that different texts rarely share one;
  !> users of the map compare the texts on a hit.
  pure integer(i8) function text_key(s)
    character(len=*), intent(in) :: s
    integer(i8), parameter :: p1 = 2147483629_i8, p2 = 2147483587_i8
    integer(i8) :: h1, h2
    integer :: k
    h1 = 7_i8
    h2 = 11_i8
    do k = 1, len(s)
      h1 = mod(h1*131_i8 + int(iachar(s(k:k)), i8), p1)
      h2 = mod(h2*257_i8 + int(iachar(s(k:k)), i8), p2)
    end do
    text_key = h1*2147483648_i8 + h2 + 1_i8
  end function text_key

  pure integer function find_slot(map, key) result(slot)
    type(int_map_t), intent(in) :: map
    integer(i8), intent(in) :: key
    integer(i8) :: h
    integer :: mask
    ! xorshift mixing spreads consecutive ids over the table without the
    ! integer overflow a multiplicative hash would need.
    h = key
    h = ieor(h, ishft(h, 13))
    h = ieor(h, ishft(h, -7))
    h = ieor(h, ishft(h, 17))
    mask = size(map%key) - 1
    slot = int(iand(h, int(mask, i8))) + 1
    do while (map%val(slot) /= 0)
      if (map%key(slot) == key) return
      slot = iand(slot, mask) + 1
    end do
  end function find_slot

  subroutine grow(map)
    type(int_map_t), intent(inout) :: map
    integer(i8), allocatable :: old_key(:)
    integer, allocatable :: old_val(:)
    integer :: k, slot
    call move_alloc(map%key, old_key)
    call move_alloc(map%val, old_val)
    allocate(map%key(2*size(old_key)), map%val(2*size(old_key)))
    map%key = 0_i8
    map%val = 0
    do k = 1, size(old_key)
      if (old_val(k) == 0) cycle
      slot = find_slot(map, old_key(k))
      map%key(slot) = old_key(k)
      map%val(slot) = old_val(k)
    end do
  end subroutine grow
end module raccord_int_map
