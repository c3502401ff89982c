!> The number of threads a run uses, from OMP_NUM_THREADS, validated.
!>
!> The OpenMP runtime takes OMP_NUM_THREADS on trust: 99999999999 becomes
!> 1.2 billion threads (libgomp then aborts allocating them), and 1000 on two
!> cores makes every parallel region wait on threads that cannot run. Here
!> the value is read as text, a bad one is replaced by 1 with a warning, and
!> a count above the processors this process may run on is capped at that
!> number with a warning, the run then waiting passively instead of
!> spinning (doc/user-guide.md, "What raccord guarantees").
module raccord_threads
  use, intrinsic :: iso_c_binding, only: c_char, c_int, c_ptr, c_loc, c_null_char, c_null_ptr
  use raccord_log, only: log_warn
  use raccord_strings, only: str
  implicit none
  private

  !> A NUL-terminated argument for execv.
  type :: c_string_t
    character(kind=c_char, len=:), allocatable :: s
  end type c_string_t

  !> Longest thread count taken as a number; anything longer is absurd.
  integer, parameter :: max_digits = 6

  public :: requested_thread_count, parse_thread_count, wait_passively_if_oversubscribed

  interface
    function c_setenv(name, value, overwrite) bind(C, name='setenv') result(rc)
      import :: c_char, c_int
      character(kind=c_char), intent(in) :: name(*), value(*)
      integer(c_int), value :: overwrite
      integer(c_int) :: rc
    end function c_setenv
    function c_execv(path, argv) bind(C, name='execv') result(rc)
      import :: c_char, c_int, c_ptr
      character(kind=c_char), intent(in) :: path(*)
      type(c_ptr), intent(in) :: argv(*)
      integer(c_int) :: rc
    end function c_execv
  end interface

contains

  !> Threads a run asks for: OMP_NUM_THREADS (its first level for a nested
  !> list), 1 when unset or unusable, at most the available processors.
  !> The OpenMP runtime is told the same count. Always 1 without OpenMP.
  integer function requested_thread_count() result(n)
    !$ use omp_lib, only: omp_get_num_procs, omp_set_num_threads
    integer :: length, status, nprocs
    character(len=:), allocatable :: text, why
    n = 1
    call get_environment_variable('OMP_NUM_THREADS', length=length, status=status)
    if (status /= 0 .or. length == 0) return
    allocate(character(len=length) :: text)
    call get_environment_variable('OMP_NUM_THREADS', text)
    call parse_thread_count(text, n, why)
    if (len(why) > 0) call log_warn('threads', 'OMP_NUM_THREADS = ''' // clip(text) // ''' ' // why // &
      ': running on 1 thread; set OMP_NUM_THREADS to a whole number from 1 to the number of cores')
    nprocs = n
    !$ nprocs = max(1, omp_get_num_procs())
    if (n > nprocs) then
      call log_warn('threads', 'OMP_NUM_THREADS = ' // str(n) // ' is more than the ' // str(nprocs) // &
        ' processor(s) this run may use: running on ' // str(nprocs) // ' threads (more threads than ' // &
        'processors only wait on each other)')
      n = nprocs
    end if
    !$ call omp_set_num_threads(n)
  end function requested_thread_count

  !> More threads asked for than processors: the user shares the machine,
  !> where spinning threads (libgomp's default wait policy) burn the time
  !> slices the others need (1000 threads on 2 cores: minutes instead of
  !> 0.6 s). The wait policy is read once, when the OpenMP runtime starts,
  !> so the program restarts itself (execv of /proc/self/exe, same
  !> arguments) with OMP_WAIT_POLICY=PASSIVE; the count is then capped by
  !> requested_thread_count. Nothing happens when the user set
  !> OMP_WAIT_POLICY or GOMP_SPINCOUNT, when the count fits the processors,
  !> or without OpenMP; if execv fails, the run goes on as it is.
  !> Called first thing by the main program.
  subroutine wait_passively_if_oversubscribed()
    !$ use omp_lib, only: omp_get_num_procs
    integer :: length, status, n, k, nargs
    character(len=:), allocatable :: text, why
    type(c_string_t), allocatable, target :: args(:)
    type(c_ptr), allocatable :: argv(:)
    integer(c_int) :: rc
    logical :: threaded
    threaded = .false.
    !$ threaded = .true.
    if (.not. threaded) return
    call get_environment_variable('OMP_NUM_THREADS', length=length, status=status)
    if (status /= 0 .or. length == 0) return
    allocate(character(len=length) :: text)
    call get_environment_variable('OMP_NUM_THREADS', text)
    call parse_thread_count(text, n, why)
    if (len(why) > 0) return                 ! runs on 1 thread
    !$ if (n <= omp_get_num_procs()) return
    call get_environment_variable('OMP_WAIT_POLICY', length=length, status=status)
    if (status == 0) return
    call get_environment_variable('GOMP_SPINCOUNT', length=length, status=status)
    if (status == 0) return
    rc = c_setenv('OMP_WAIT_POLICY' // c_null_char, 'PASSIVE' // c_null_char, 0_c_int)
    if (rc /= 0) return
    nargs = command_argument_count()
    allocate(args(0:nargs), argv(0:nargs + 1))
    do k = 0, nargs
      call get_command_argument(k, length=length)
      allocate(character(len=length + 1) :: args(k)%s)
      call get_command_argument(k, args(k)%s(1:length))
      args(k)%s(length + 1:length + 1) = c_null_char
      argv(k) = c_loc(args(k)%s)
    end do
    argv(nargs + 1) = c_null_ptr
    rc = c_execv('/proc/self/exe' // c_null_char, argv)
  end subroutine wait_passively_if_oversubscribed

  !> The first entry of an OMP_NUM_THREADS value ("4" or "4,2"): a whole
  !> number >= 1. Otherwise n = 1 and why says what is wrong (empty when
  !> the value is good).
  subroutine parse_thread_count(text, n, why)
    character(len=*), intent(in) :: text
    integer, intent(out) :: n
    character(len=:), allocatable, intent(out) :: why
    character(len=:), allocatable :: first
    integer :: comma, ios
    n = 1
    why = ''
    comma = index(text, ',')
    if (comma > 0) then
      first = trim(adjustl(text(1:comma-1)))
    else
      first = trim(adjustl(text))
    end if
    if (len(first) == 0) then
      why = 'gives no number'
    else if (verify(first, '0123456789') /= 0) then
      why = 'is not a whole number'
    else if (len(first) - verify(first, '0', back=.false.) + 1 > max_digits .and. verify(first, '0') > 0) then
      why = 'is far too large'
    else if (verify(first, '0') == 0) then
      why = 'is zero'
    else
      read(first, *, iostat=ios) n
      if (ios /= 0) then
        n = 1
        why = 'cannot be read'
      end if
    end if
  end subroutine parse_thread_count

  !> At most 40 characters of a value, for a message.
  pure function clip(text) result(s)
    character(len=*), intent(in) :: text
    character(len=:), allocatable :: s
    if (len(text) > 40) then
      s = text(1:40) // '...'
    else
      s = text
    end if
  end function clip
end module raccord_threads
