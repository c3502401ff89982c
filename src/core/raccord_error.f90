!> Error status returned upward by library code; only the main program stops.
!>
!> Every library procedure that can fail takes `type(error_t), intent(inout) :: err`
!> (or intent(out)) and returns at once with `err%code /= 0` and a message that
!> says what went wrong, where (file, line, group, key) and how to fix it.
!> The codes double as the process exit codes documented in doc/user-guide.md.
module raccord_error
  implicit none
  private

  integer, parameter, public :: EXIT_OK = 0           !< success
  integer, parameter, public :: EXIT_USAGE = 1        !< bad command line
  integer, parameter, public :: EXIT_INPUT = 2        !< bad scene deck, mesh or parameter
  integer, parameter, public :: EXIT_NUMERIC = 3      !< numerical failure (NaN, non-convergence, instability)
  integer, parameter, public :: EXIT_IO = 4           !< file system failure while writing results
  integer, parameter, public :: EXIT_WALLCLOCK = 5    !< stopped at the wall-clock limit, checkpoint written
  integer, parameter, public :: EXIT_INTERNAL = 70    !< a bug: an internal consistency check failed

  !> An error status: code 0 means no error.
  type, public :: error_t
    integer :: code = EXIT_OK
    character(len=:), allocatable :: message
  contains
    procedure :: failed => error_failed
    procedure :: clear => error_clear
  end type error_t

  public :: raise_error, prefix_error

contains

  !> True when the status holds an error.
  pure logical function error_failed(self)
    class(error_t), intent(in) :: self
    error_failed = self%code /= EXIT_OK
  end function error_failed

  !> Reset the status to "no error".
  subroutine error_clear(self)
    class(error_t), intent(inout) :: self
    self%code = EXIT_OK
    if (allocated(self%message)) deallocate(self%message)
  end subroutine error_clear

  !> Set an error with its code and message (the first error wins: a later
  !> raise on a failed status is ignored so the root cause is reported).
  subroutine raise_error(err, code, message)
    type(error_t), intent(inout) :: err
    integer, intent(in) :: code
    character(len=*), intent(in) :: message
    if (err%failed()) return
    err%code = code
    err%message = message
  end subroutine raise_error

  !> Put context in front of an existing message ("while reading mesh X: ...").
  subroutine prefix_error(err, context)
    type(error_t), intent(inout) :: err
    character(len=*), intent(in) :: context
    if (.not. err%failed()) return
    if (allocated(err%message)) then
      err%message = context // ': ' // err%message
    else
      err%message = context
    end if
  end subroutine prefix_error
end module raccord_error
