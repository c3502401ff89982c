!> raccord_bench_ratio: the Q8 whole step per element against the Q4 one, on
!> the plate of raccord_bench (same mesh and model builder), in interleaved
!> rounds and in process CPU time, so that the ratio survives a loaded
!> machine better than wall-clock medians (doc/performance.md, "Q8 element
!> step").
!>
!>   raccord_bench_ratio [--rounds N] [NEL]
!>
!> NEL (default 1e5) is rounded to a square mesh, the same for both types.
!> Each round marches the Q4 plate and then the Q8 plate (the program's step
!> sequence compute_forces, predict_motion, update_energy, advance_state)
!> for about the same CPU time; the line printed gives the smallest ns per
!> element and step of each type, and the median and quartiles of the
!> per-round ratio Q8/Q4.
program raccord_bench_ratio
  use raccord_kinds, only: wp, i8
  use raccord_error, only: error_t
  use raccord_mesh, only: ELEM_Q4, ELEM_Q8
  use raccord_model, only: model_t
  use raccord_state, only: state_t, init_state
  use raccord_central_difference, only: compute_forces, predict_motion, update_energy, advance_state
  use raccord_bench_util, only: structured_mesh, plate_model, median, load_average
  use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
  implicit none
  integer, parameter :: max_rounds = 99
  type(model_t) :: model(2)
  type(state_t) :: state(2)
  type(error_t) :: err
  real(wp), allocatable :: x(:,:)
  integer, allocatable :: conn(:,:)
  integer, parameter :: etype(2) = [ELEM_Q4, ELEM_Q8]
  integer :: k, stat, r, j, nstep(2), nrounds, nx, nel, iarg
  integer(i8) :: nel_wanted
  real(wp) :: t0, t1, ns(2, max_rounds), ratio(max_rounds)
  character(len=64) :: arg

  nrounds = 15
  nel_wanted = 100000
  iarg = 1
  do while (iarg <= command_argument_count())
    call get_command_argument(iarg, arg)
    select case (arg)
    case ('--help', '-h')
      write(output_unit, '(a)') 'usage: raccord_bench_ratio [--rounds N] [NEL]', &
        '  Q8 against Q4 whole step per element, CPU time, interleaved rounds (default 15 rounds, NEL 1e5)'
      stop
    case ('--rounds')
      iarg = iarg + 1
      call get_command_argument(iarg, arg)
      read(arg, *, iostat=stat) nrounds
      if (stat /= 0 .or. nrounds < 1 .or. nrounds > max_rounds) call refuse('--rounds takes 1..99')
    case default
      read(arg, *, iostat=stat) nel_wanted
      if (stat /= 0 .or. nel_wanted < 1) call refuse('unknown argument ' // trim(arg) // '; see --help')
    end select
    iarg = iarg + 1
  end do

  nx = max(1, nint(sqrt(real(nel_wanted, wp))))
  nel = nx*nx
  do k = 1, 2
    call structured_mesh(etype(k), nx, nx, x, conn, stat)
    if (stat /= 0) call refuse('cannot allocate the mesh')
    call plate_model(etype(k), x, conn, model(k), err)
    if (err%failed()) call refuse(err%message)
    call init_state(model(k), 0.9_wp*2.0_wp/sqrt(model(k)%w2_bound), 0_i8, state(k))
  end do
  ! about 0.1 s of steps per type and round at ~20 (Q4) and ~80 (Q8) ns per element
  nstep = [max(3, nint(5.0e6_wp/nel)), max(3, nint(1.25e6_wp/nel))]
  write(output_unit, '(a)') '# raccord_bench_ratio: load average at start ' // load_average()
  do r = 1, nrounds
    do k = 1, 2
      call cpu_time(t0)
      do j = 1, nstep(k)
        call compute_forces(model(k), state(k))
        call predict_motion(model(k), state(k))
        call update_energy(model(k), state(k))
        call advance_state(state(k))
      end do
      call cpu_time(t1)
      ns(k, r) = 1.0e9_wp*(t1 - t0)/(real(nstep(k), wp)*real(nel, wp))
    end do
    ratio(r) = ns(2, r)/ns(1, r)
  end do
  call sort(ratio(1:nrounds))
  write(output_unit, '(a, i0, a, i0, a, 2f8.1, a, f6.2, a, 2f6.2, a)') '# ', nel, ' elements, ', nrounds, &
    ' rounds: min CPU ns/element/step Q4, Q8', minval(ns(1, 1:nrounds)), minval(ns(2, 1:nrounds)), &
    '; ratio Q8/Q4 median', median(ratio(1:nrounds)), ' (quartiles', ratio(max(1, (nrounds + 2)/4)), &
    ratio(max(1, (3*nrounds + 2)/4)), ')'
  write(output_unit, '(a)') '# load average at end ' // load_average()

contains

  subroutine refuse(msg)
    character(len=*), intent(in) :: msg
    write(error_unit, '(a)') 'raccord_bench_ratio: ' // msg
    stop 2   ! (the message is printed above; ERROR STOP would add a backtrace)
  end subroutine refuse

  pure subroutine sort(a)
    real(wp), intent(inout) :: a(:)
    integer :: i, j
    real(wp) :: t
    do i = 2, size(a)
      t = a(i)
      j = i - 1
      do while (j >= 1)
        if (a(j) <= t) exit
        a(j + 1) = a(j)
        j = j - 1
      end do
      a(j + 1) = t
    end do
  end subroutine sort
end program raccord_bench_ratio
