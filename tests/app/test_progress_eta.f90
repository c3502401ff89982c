!> The progress line's time to go (raccord_output eta_seconds): the rate of
!> this process only, so that a restarted run does not count the steps done
!> before its checkpoint as done in no time.
program test_progress_eta
  use raccord_check, only: failure_t, new_test, run_tests, check, check_close
  implicit none

  call run_tests('progress_eta', [ &
    new_test('fresh run: elapsed * steps to go / steps done', test_fresh), &
    new_test('restart: only the steps of this process count', test_restart), &
    new_test('no step done yet: 0', test_none)])

contains

  subroutine test_fresh(failure)
    use raccord_kinds, only: wp, i8
    use raccord_output, only: eta_seconds
    type(failure_t), allocatable, intent(out) :: failure
    ! 250 of 1000 steps in 5 s: 750 to go at 50 steps/s.
    call check_close(failure, eta_seconds(5.0_wp, 0_i8, 250_i8, 1000_i8), 15.0_wp, 'eta of a fresh run')
  end subroutine test_fresh

  subroutine test_restart(failure)
    use raccord_kinds, only: wp, i8
    use raccord_output, only: eta_seconds
    type(failure_t), allocatable, intent(out) :: failure
    ! Restarted at step 800 of 1000; 100 steps in 10 s here: 100 to go, 10 s.
    ! Counting all 900 steps as done in these 10 s would give 1.1 s.
    call check_close(failure, eta_seconds(10.0_wp, 800_i8, 900_i8, 1000_i8), 10.0_wp, 'eta after a restart')
    call check_close(failure, eta_seconds(10.0_wp, 800_i8, 1000_i8, 1000_i8), 0.0_wp, 'nothing to go at the end', &
      abs_tol=0.0_wp)
  end subroutine test_restart

  subroutine test_none(failure)
    use raccord_kinds, only: wp, i8
    use raccord_output, only: eta_seconds
    type(failure_t), allocatable, intent(out) :: failure
    call check(failure, eta_seconds(3.0_wp, 800_i8, 800_i8, 1000_i8) == 0.0_wp, 'no step of this process yet: 0')
  end subroutine test_none
end program test_progress_eta
