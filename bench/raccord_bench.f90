!> raccord_bench: timings of the hot loops on in-memory structured meshes.
!>
!>   raccord_bench [--type q4|q8|all] [--min-time SECONDS] [NEL ...]
!>
!> NEL are element counts (1e4, 100000, ...; default 1e4 1e5 1e6), rounded to
!> a square nx x nx mesh. Each case prints elements, nodes, calls, ns per
!> element per call and the case's peak memory (VmHWM). Phases are separate
!> subroutines so further timings (a whole explicit step) slot in as new
!> bench_* routines called from the case loop.
program raccord_bench
  use raccord_kinds, only: wp, i8
  use raccord_error, only: error_t
  use raccord_mesh, only: ELEM_Q4, ELEM_Q8, element_name
  use raccord_elastic_block, only: elastic_block_t, init_elastic_block, add_internal_force
  use raccord_bench_util, only: structured_mesh, wall_time, peak_memory_kib, reset_peak_memory
  use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
  implicit none

  integer, parameter :: max_sizes = 16
  integer :: nsizes, ntypes, types(2), it, is, stat
  integer(i8) :: sizes(max_sizes)
  real(wp) :: min_time

  call parse_command_line(types, ntypes, sizes, nsizes, min_time, stat)
  if (stat /= 0) error stop 1

  write(output_unit, '(a)') '# raccord_bench: add_internal_force, one core'
  write(output_unit, '(a4, a11, a11, a8, a14, a14)') 'type', 'elements', 'nodes', 'calls', &
    'ns/elem/call', 'VmHWM_MiB'
  cases: do it = 1, ntypes
    do is = 1, nsizes
      call run_case(types(it), sizes(is), min_time)
    end do
  end do cases

contains

  subroutine usage()
    write(output_unit, '(a)') 'usage: raccord_bench [--type q4|q8|all] [--min-time SECONDS] [NEL ...]'
    write(output_unit, '(a)') '  NEL: element counts (default 1e4 1e5 1e6), each rounded to a square mesh'
  end subroutine usage

  subroutine parse_command_line(types, ntypes, sizes, nsizes, min_time, stat)
    integer, intent(out) :: types(2), ntypes, nsizes, stat
    integer(i8), intent(out) :: sizes(:)
    real(wp), intent(out) :: min_time
    character(len=64) :: arg
    integer :: k, nargs, ios
    real(wp) :: v
    types = [ELEM_Q4, ELEM_Q8]
    ntypes = 2
    nsizes = 0
    min_time = 1.0_wp
    stat = 0
    nargs = command_argument_count()
    k = 0
    do while (k < nargs)
      k = k + 1
      call get_command_argument(k, arg)
      select case (trim(arg))
      case ('-h', '--help')
        call usage()
        stop
      case ('--type')
        k = k + 1
        call get_command_argument(k, arg)
        select case (trim(arg))
        case ('q4', 'Q4'); types(1) = ELEM_Q4; ntypes = 1
        case ('q8', 'Q8'); types(1) = ELEM_Q8; ntypes = 1
        case ('all'); ntypes = 2
        case default
          write(error_unit, '(a)') 'raccord_bench: --type takes q4, q8 or all, got "' // trim(arg) // '"'
          stat = 1
          return
        end select
      case ('--min-time')
        k = k + 1
        call get_command_argument(k, arg)
        read(arg, *, iostat=ios) min_time
        if (ios /= 0 .or. .not. (min_time > 0.0_wp)) then
          write(error_unit, '(a)') 'raccord_bench: --min-time takes a positive number of seconds, got "' // &
            trim(arg) // '"'
          stat = 1
          return
        end if
      case default
        read(arg, *, iostat=ios) v
        if (ios /= 0 .or. .not. (v >= 1.0_wp) .or. nsizes >= size(sizes)) then
          write(error_unit, '(a)') 'raccord_bench: bad argument "' // trim(arg) // '"'
          call usage()
          stat = 1
          return
        end if
        nsizes = nsizes + 1
        sizes(nsizes) = nint(v, i8)
      end select
    end do
    if (nsizes == 0) then
      nsizes = 3
      sizes(1:3) = [10000_i8, 100000_i8, 1000000_i8]
    end if
  end subroutine parse_command_line

  !> Build the mesh and the block of one case, then time its phases.
  subroutine run_case(etype, nel_wanted, min_time)
    integer, intent(in) :: etype
    integer(i8), intent(in) :: nel_wanted
    real(wp), intent(in) :: min_time
    type(elastic_block_t) :: blk
    type(error_t) :: err
    real(wp), allocatable :: x(:,:)
    integer, allocatable :: conn(:,:)
    integer :: nx, stat, calls
    real(wp) :: ns
    call reset_peak_memory()
    nx = max(1, nint(sqrt(real(nel_wanted, wp))))
    call structured_mesh(etype, nx, nx, x, conn, stat)
    if (stat /= 0) then
      write(error_unit, '(a)') 'raccord_bench: cannot allocate a mesh of ' // element_name(etype) // ' elements'
      return
    end if
    call init_elastic_block(blk, etype, conn, x, 2.1e5_wp, 0.3_wp, .false., 1.0_wp, err)
    if (err%failed()) then
      write(error_unit, '(a)') 'raccord_bench: ' // err%message
      return
    end if
    deallocate(conn)
    call bench_internal_force(blk, x, min_time, calls, ns)
    write(output_unit, '(a4, i11, i11, i8, f14.2, f14.1)') element_name(etype), blk%nel, size(x, 2), calls, ns, &
      real(peak_memory_kib(), wp)/1024.0_wp
    flush(output_unit)
  end subroutine run_case

  !> Time add_internal_force: repeat until min_time has passed (at least 3
  !> calls after one warm-up call); ns per element per call.
  subroutine bench_internal_force(blk, x, min_time, calls, ns)
    type(elastic_block_t), intent(in) :: blk
    real(wp), intent(in) :: x(:,:), min_time
    integer, intent(out) :: calls
    real(wp), intent(out) :: ns
    real(wp), allocatable :: u(:,:), f(:,:)
    real(wp) :: t0, t
    allocate(u(2, size(x, 2)), f(2, size(x, 2)))
    u(1, :) = 1.0e-3_wp*sin(x(1, :) + 0.3_wp*x(2, :))
    u(2, :) = 1.0e-3_wp*cos(0.7_wp*x(1, :) - x(2, :))
    f = 0.0_wp
    call add_internal_force(blk, u, f)
    calls = 0
    t0 = wall_time()
    do
      f = 0.0_wp
      call add_internal_force(blk, u, f)
      calls = calls + 1
      t = wall_time() - t0
      if (calls >= 3 .and. t >= min_time) exit
    end do
    ! keep the result alive so the calls cannot be optimised away
    if (.not. (abs(sum(f)) < huge(1.0_wp))) write(output_unit, '(a)') '# non-finite internal force'
    ns = 1.0e9_wp*t/(real(calls, wp)*real(blk%nel, wp))
  end subroutine bench_internal_force
end program raccord_bench
