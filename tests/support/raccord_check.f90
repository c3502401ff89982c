!> A small unit-test harness in the style of test-drive: a test is a
!> subroutine that returns an allocated failure when a check fails; a suite is
!> an array of named tests run by run_tests, which prints one line per test
!> and a closing "N passed, M failed" line, and stops non-zero on failure.
!>
!>   call run_tests('shape', [new_test('partition of unity', test_pu), ...])
!>
!> A test name given on the command line runs only the tests containing it.
module raccord_check
  use raccord_kinds, only: wp
  use, intrinsic :: iso_fortran_env, only: output_unit
  implicit none
  private

  public :: failure_t, unit_test_t, new_test, run_tests, check, check_close, fail_now

  !> Why a test failed.
  type :: failure_t
    character(len=:), allocatable :: message
  end type failure_t

  abstract interface
    subroutine test_procedure(failure)
      import :: failure_t
      type(failure_t), allocatable, intent(out) :: failure
    end subroutine test_procedure
  end interface

  type :: unit_test_t
    character(len=:), allocatable :: name
    procedure(test_procedure), pointer, nopass :: run => null()
  end type unit_test_t

  !> Check a condition: check(failure, condition, message).
  interface check
    module procedure check_logical
  end interface check

contains

  function new_test(name, proc) result(t)
    character(len=*), intent(in) :: name
    procedure(test_procedure) :: proc
    type(unit_test_t) :: t
    t%name = name
    t%run => proc
  end function new_test

  !> Record a failure unless the condition holds (the first failure is kept).
  subroutine check_logical(failure, condition, message)
    type(failure_t), allocatable, intent(inout) :: failure
    logical, intent(in) :: condition
    character(len=*), intent(in) :: message
    if (allocated(failure)) return
    if (.not. condition) then
      allocate(failure)
      failure%message = message
    end if
  end subroutine check_logical

  !> Record a failure now.
  subroutine fail_now(failure, message)
    type(failure_t), allocatable, intent(inout) :: failure
    character(len=*), intent(in) :: message
    call check_logical(failure, .false., message)
  end subroutine fail_now

  !> |actual - expected| <= max(abs_tol, rel_tol*|expected|), with both
  !> numbers in the failure message.
  subroutine check_close(failure, actual, expected, message, abs_tol, rel_tol)
    type(failure_t), allocatable, intent(inout) :: failure
    real(wp), intent(in) :: actual, expected
    character(len=*), intent(in) :: message
    real(wp), intent(in), optional :: abs_tol, rel_tol
    real(wp) :: atol, rtol, tol
    character(len=160) :: buf
    atol = 0.0_wp
    rtol = 1.0e-12_wp
    if (present(abs_tol)) atol = abs_tol
    if (present(rel_tol)) rtol = rel_tol
    if (present(abs_tol) .and. .not. present(rel_tol)) rtol = 0.0_wp
    tol = max(atol, rtol*abs(expected))
    if (allocated(failure)) return
    if (.not. (abs(actual - expected) <= tol)) then
      write(buf, '(a,es23.15,a,es23.15,a,es10.3,a,es10.3)') 'got ', actual, ', expected ', expected, &
        ', |diff| = ', abs(actual - expected), ' > tol ', tol
      call check_logical(failure, .false., message // ': ' // trim(buf))
    end if
  end subroutine check_close

  !> Run a suite; print per-test results and the closing count line.
  subroutine run_tests(suite, tests)
    character(len=*), intent(in) :: suite
    type(unit_test_t), intent(in) :: tests(:)
    type(failure_t), allocatable :: failure
    character(len=256) :: filter
    integer :: k, npass, nfail, nargs
    filter = ''
    nargs = command_argument_count()
    if (nargs >= 1) call get_command_argument(1, filter)
    npass = 0
    nfail = 0
    do k = 1, size(tests)
      if (len_trim(filter) > 0) then
        if (index(tests(k)%name, trim(filter)) == 0) cycle
      end if
      call tests(k)%run(failure)
      if (allocated(failure)) then
        nfail = nfail + 1
        write(output_unit, '(a)') '  FAIL  ' // suite // ': ' // tests(k)%name
        write(output_unit, '(a)') '        ' // failure%message
        deallocate(failure)
      else
        npass = npass + 1
        write(output_unit, '(a)') '  pass  ' // suite // ': ' // tests(k)%name
      end if
      flush(output_unit)
    end do
    write(output_unit, '(a,i0,a,i0,a)') suite // ': ', npass, ' passed, ', nfail, ' failed'
    if (nfail > 0) error stop 1
    if (npass == 0) then
      write(output_unit, '(a)') 'no test matched "' // trim(filter) // '"'
      error stop 1
    end if
  end subroutine run_tests
end module raccord_check
