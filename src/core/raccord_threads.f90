!> The number of threads a run uses, from OMP_NUM_THREADS, validated.
!>
!> The OpenMP runtime takes OMP_NUM_THREADS on trust: 99999999999 becomes
!> 1.2 billion threads (libgomp then aborts allocating them), and 1000 on two
!> cores makes every parallel region wait on threads that cannot run. Here
!> the value is read as text, a bad one is replaced by 1 with a warning, and
!> a count above the processors this process may run on is capped at that
!> number with a warning (doc/user-guide.md, "What raccord guarantees").
module raccord_threads
  use raccord_log, only: log_warn
  use raccord_strings, only: str
  implicit none
  private

  !> Longest thread count taken as a number; anything longer is absurd.
  integer, parameter :: max_digits = 6

  public :: requested_thread_count, parse_thread_count

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
