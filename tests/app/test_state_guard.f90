!> The check of the predicted motion before the contact search
!> (raccord_state_guard, prediction_finite): false for a NaN or an
!> infinity in any component of any node, first, last or between (the
!> loop counts them over the whole array, no early exit), true for finite
!> values up to huge.
program test_state_guard
  use raccord_check, only: failure_t, new_test, run_tests, check
  implicit none

  call run_tests('state_guard', [ &
    new_test('finite values, huge included: finite', test_finite), &
    new_test('one NaN or infinity anywhere: not finite', test_non_finite)])

contains

  subroutine test_finite(failure)
    use raccord_kinds, only: wp
    use raccord_state, only: state_t
    use raccord_state_guard, only: prediction_finite
    type(failure_t), allocatable, intent(out) :: failure
    type(state_t) :: state
    allocate(state%u_next(2, 37))
    state%u_next = 1.0e-3_wp
    state%u_next(1, 5) = huge(1.0_wp)
    state%u_next(2, 9) = -huge(1.0_wp)
    state%u_next(2, 11) = tiny(1.0_wp)
    call check(failure, prediction_finite(state), 'finite displacements, +-huge and tiny among them')
  end subroutine test_finite

  subroutine test_non_finite(failure)
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, ieee_negative_inf
    use raccord_kinds, only: wp
    use raccord_state, only: state_t
    use raccord_state_guard, only: prediction_finite
    type(failure_t), allocatable, intent(out) :: failure
    type(state_t) :: state
    real(wp) :: bad(3)
    integer :: b, i, c
    bad = [ieee_value(1.0_wp, ieee_quiet_nan), ieee_value(1.0_wp, ieee_positive_inf), &
      ieee_value(1.0_wp, ieee_negative_inf)]
    allocate(state%u_next(2, 37))
    do b = 1, 3
      do i = 1, 37, 6
        do c = 1, 2
          state%u_next = 1.0e-3_wp
          state%u_next(c, i) = bad(b)
          call check(failure, .not. prediction_finite(state), 'a non-finite value at one node')
          if (allocated(failure)) return
        end do
      end do
      ! The last node too (the vectorised loop's remainder).
      state%u_next = 1.0e-3_wp
      state%u_next(2, 37) = bad(b)
      call check(failure, .not. prediction_finite(state), 'a non-finite value at the last node')
      if (allocated(failure)) return
    end do
  end subroutine test_non_finite
end program test_state_guard
