!> Whether the predicted motion of a step is finite, checked before the
!> contact search of the step: the search sizes its bins from the extent
!> of the surfaces (raccord_contact_search), and a NaN or an infinity
!> there (an unstable run, an element turned inside out by a huge load)
!> would size them from garbage (one run took seconds per step and
!> gigabytes for three slave nodes). The energy guard of the time loop
!> (raccord_main, guard_finite) comes after the contact correction.
module raccord_state_guard
  use raccord_kinds, only: wp
  use raccord_state, only: state_t
  implicit none
  private

  public :: prediction_finite

contains

  !> Every component of the predicted displacement u(n+1) is finite (a
  !> loop, no temporary: it runs once per step). No early exit: |u| <=
  !> huge is false for NaN and the infinities, and the count of those over
  !> the whole array is a reduction the compiler vectorises (the loop that
  !> stopped at the first one went component by component, 2 % of a
  !> contact run; doc/performance.md, "fifth pass").
  pure logical function prediction_finite(state) result(ok)
    type(state_t), intent(in) :: state
    ok = all_finite(size(state%u_next), state%u_next)
  end function prediction_finite

  !> The count over u as one contiguous vector (an explicit-shape dummy:
  !> the components' stride is then known to be 1; allocatable, so no
  !> copy).
  pure logical function all_finite(n, u) result(ok)
    integer, intent(in) :: n
    real(wp), intent(in) :: u(n)
    integer :: i, nbad
    nbad = 0
    do i = 1, n
      nbad = nbad + merge(0, 1, abs(u(i)) <= huge(1.0_wp))
    end do
    ok = nbad == 0
  end function all_finite
end module raccord_state_guard
