!> Whether the predicted motion of a step is finite, checked before the
!> contact search of the step: the search sizes its bins from the extent
!> of the surfaces (raccord_contact_search), and a NaN or an infinity
!> there (an unstable run, an element turned inside out by a huge load)
!> would size them from garbage (one run took seconds per step and
!> gigabytes for three slave nodes). The energy guard of the time loop
!> (raccord_main, guard_finite) comes after the contact correction.
module raccord_state_guard
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use raccord_kinds, only: wp
  use raccord_state, only: state_t
  implicit none
  private

  public :: prediction_finite

contains

  !> Every component of the predicted displacement u(n+1) is finite (a
  !> loop, no temporary: it runs once per step).
  pure logical function prediction_finite(state) result(ok)
    type(state_t), intent(in) :: state
    integer :: i
    ok = .false.
    do i = 1, size(state%u_next, 2)
      if (.not. (ieee_is_finite(state%u_next(1, i)) .and. ieee_is_finite(state%u_next(2, i)))) return
    end do
    ok = .true.
  end function prediction_finite
end module raccord_state_guard
