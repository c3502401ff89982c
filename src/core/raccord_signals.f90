!> Stop requests by signal: SIGTERM and SIGUSR1 ask the run to write a
!> checkpoint at the next step boundary and exit 5 (doc/hpc.md, section 10).
!> Slurm sends SIGUSR1 before the time limit when the job asks for it
!> (#SBATCH --signal=B:USR1@120) and SIGTERM when the limit is reached,
!> 30 s (KillWait) before SIGKILL.
!>
!> The handler is a bind(C) Fortran procedure installed with the C
!> library's signal(): it only stores the signal number in a volatile
!> integer, which is all a signal handler may safely do; the time loop
!> reads it once per step (stop_signal). glibc's signal() has BSD
!> semantics: the handler stays installed and interrupted system calls
!> are restarted (SA_RESTART), so file I/O in progress is not disturbed.
!> No C shim is needed. The signal numbers are those of Linux (x86-64,
!> aarch64, ppc64le, riscv64 share them), the platforms raccord builds on.
!>
!> Like the log, this is module state on purpose: a signal belongs to the
!> process, not to any one object.
module raccord_signals
  use, intrinsic :: iso_c_binding, only: c_int, c_funptr, c_funloc, c_intptr_t
  use raccord_error, only: error_t, raise_error, EXIT_INTERNAL
  implicit none
  private

  public :: install_stop_signals, stop_signal, signal_name

  integer(c_int), parameter, public :: SIGTERM = 15_c_int
  integer(c_int), parameter, public :: SIGUSR1 = 10_c_int

  !> Number of the last stop signal received, 0 if none.
  integer(c_int), volatile :: caught = 0_c_int

  interface
    function c_signal(signum, handler) bind(C, name='signal') result(previous)
      import :: c_int, c_funptr
      integer(c_int), value :: signum
      type(c_funptr), value :: handler
      type(c_funptr) :: previous
    end function c_signal
  end interface

contains

  !> Route SIGTERM and SIGUSR1 to the flag. A failure (SIG_ERR) is an
  !> internal error: signal() fails only for invalid numbers.
  subroutine install_stop_signals(err)
    type(error_t), intent(inout) :: err
    integer(c_int) :: k
    integer(c_int), parameter :: signals(2) = [SIGTERM, SIGUSR1]
    type(c_funptr) :: previous
    do k = 1, size(signals)
      previous = c_signal(signals(k), c_funloc(on_stop_signal))
      ! SIG_ERR is (void (*)(int)) -1.
      if (transfer(previous, 0_c_intptr_t) == -1_c_intptr_t) then
        call raise_error(err, EXIT_INTERNAL, 'cannot install the handler of signal ' // signal_name(signals(k)))
        return
      end if
    end do
  end subroutine install_stop_signals

  !> The stop signal received so far (SIGTERM or SIGUSR1), 0 if none.
  integer function stop_signal()
    stop_signal = int(caught)
  end function stop_signal

  !> 'SIGTERM', 'SIGUSR1' or 'signal N'.
  function signal_name(signum) result(name)
    integer, intent(in) :: signum
    character(len=:), allocatable :: name
    character(len=12) :: buf
    select case (signum)
    case (int(SIGTERM))
      name = 'SIGTERM'
    case (int(SIGUSR1))
      name = 'SIGUSR1'
    case default
      write(buf, '(i0)') signum
      name = 'signal ' // trim(buf)
    end select
  end function signal_name

  !> The handler: remember the signal, nothing else (async-signal-safe).
  subroutine on_stop_signal(signum) bind(C)
    integer(c_int), value :: signum
    caught = signum
  end subroutine on_stop_signal
end module raccord_signals
