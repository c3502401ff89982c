!> raccord_bench: timings of the explicit time step on in-memory structured
!> meshes (doc/performance.md).
!>
!>   raccord_bench [--type q4|q8|all] [--kinematics small|finite|all|axi|small-axi]
!>                 [--material elastic|j2|all] [--threads T]
!>                 [--min-time SECONDS] [--repeat N] [NEL ...]
!>
!> --kinematics finite times the finite-strain neo-Hooke kernel (type column
!> Q4f / Q8f; Q4 with mean dilatation, as a scene gets by default); all
!> times each small-strain case and then its finite-strain twin, back to back.
!> --kinematics axi times the small-strain axisymmetric kernel (type Q4a /
!> Q8a, raccord_axi_kernel) on the same mesh read as an r-z section (x = r,
!> the clamped side on the axis); small-axi times each plane-strain case and
!> then its axisymmetric twin, back to back.
!> --material j2 times the J2 elastoplastic kernels instead (type Q4p, Q4pf,
!> ...; mean dilatation, sigma_y0 = 100 MPa so that part of the kernel
!> phase's field yields; not with axi); all times the elastic case, then
!> its j2 twin.
!>
!> NEL are element counts (1e4, 100000, ...; default 1e4 1e5 1e6), rounded to
!> a square nx x nx mesh. Each case runs two phases, each on 1 thread and
!> then on T threads (default: OMP_NUM_THREADS if set, else every core the
!> OpenMP runtime sees; T = 1: serial only):
!>   1. kernel: add_internal_force alone on one elastic block;
!>   2. step: a clamped plate model (build_model) marched with the time loop
!>      of the program: compute_forces, predict_motion, update_energy,
!>      advance_state (raccord_central_difference).
!> Each timing is repeated in N rounds (each timing at least SECONDS long);
!> a round times 1 thread and then T threads back to back, so that a change
!> in the machine's load (other processes, a neighbour on the host) hits
!> both alike. A line per thread count gives the min and the median in ns
!> per element per call / step, the step's split into forces / predictor /
!> rest (medians), the speed-up over
!> 1 thread (the median over the rounds of the ratio of the two
!> back-to-back timings), the peak memory (VmHWM) of each phase and the relative energy balance after the steps. The header gives
!> the load average, for the speed-up is only meaningful on a quiet machine.
program raccord_bench
  use raccord_kinds, only: wp, i8
  use raccord_error, only: error_t
  use raccord_mesh, only: ELEM_Q4, ELEM_Q8, element_name
  use raccord_elastic_block, only: elastic_block_t, init_elastic_block, add_internal_force, make_finite, &
    block_watch_t, init_watch, make_axisymmetric, make_plastic, block_plastic_t, init_plastic
  use raccord_material, only: MAT_NEO_HOOKE, MAT_J2, VOL_FULL, VOL_MEAN, KIN_SMALL, KIN_FINITE
  use raccord_plasticity, only: j2_t, h_ebar
  use raccord_model, only: model_t, set_model_threads
  use raccord_state, only: state_t, init_state
  use raccord_central_difference, only: compute_forces, predict_motion, update_energy, advance_state
  use raccord_bench_util, only: structured_mesh, plate_model, wall_time, peak_memory_kib, reset_peak_memory, &
    median, load_average, use_cpu_clock
  !$ use omp_lib, only: omp_get_num_procs
  use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
  implicit none

  integer, parameter :: max_sizes = 16, max_repeat = 99
  integer :: nsizes, ntypes, types(2), it, is, stat, nrep, nthreads, kin, kin0, kin1, kin_step, mat, mat0, mat1
  integer(i8) :: sizes(max_sizes)
  real(wp) :: min_time

  call parse_command_line(types, ntypes, sizes, nsizes, min_time, nrep, nthreads, kin0, kin1, kin_step, mat0, mat1, &
    stat)
  if (stat /= 0) stop 1   ! (the message is printed above; ERROR STOP would add a backtrace)

  write(output_unit, '(a)') '# raccord_bench: ns per element per call (kernel) / per step (step),'
  write(output_unit, '(a, i0, a)') '# min and median of ', nrep, &
    ' rounds; step split: forces / predictor / rest'
  write(output_unit, '(a, i0, a)') '# threads: 1 and ', nthreads, ' (OpenMP; colour-ordered groups of ' // &
    '32-element chunks, per-node loops in 64 fixed segments)'
  write(output_unit, '(a)') '# each round times 1 thread and then the other count back to back; ' // &
    'spd = median over the rounds of time(1 thread)/time(this line)'
  write(output_unit, '(a)') '# load average (1, 5, 15 min) at start: ' // load_average()
  if (use_cpu_clock) write(output_unit, '(a)') '# clock: process CPU time (--clock cpu), not wall time'
  write(output_unit, '(a4, a9, a9, a4, a7, 4a9, 3a8, 2a6, 2a9, a7, a10)') 'type', 'elements', 'nodes', 'thr', &
    'steps', 'kern_min', 'kern_med', 'step_min', 'step_med', 'forces', 'predict', 'rest', 'spd_k', 'spd_s', &
    'MiB_kern', 'MiB_step', 'B/elem', 'balance'
  cases: do it = 1, ntypes
    do is = 1, nsizes
      do kin = kin0, kin1, kin_step
        do mat = mat0, mat1
          if (mat == 2 .and. kin == 3) cycle     ! j2 is not built in axisymmetry
          call run_case(types(it), kin == 2, kin == 3, mat == 2, sizes(is), min_time, nrep, nthreads)
        end do
      end do
    end do
  end do cases
  write(output_unit, '(a)') '# load average (1, 5, 15 min) at end: ' // load_average()

contains

  subroutine usage()
    write(output_unit, '(a)') 'usage: raccord_bench [--type q4|q8|all] [--kinematics small|finite|all|axi|small-axi] ' // &
      '[--material elastic|j2|all] [--threads T] [--clock wall|cpu] [--min-time SECONDS] [--repeat N] [NEL ...]'
    write(output_unit, '(a)') '  --kinematics: small strain (default), finite strain (neo-Hooke; type Q4f, Q8f) or both;'
    write(output_unit, '(a)') '    axi: small-strain axisymmetric (type Q4a, Q8a); small-axi: plane strain, then axisymmetric'
    write(output_unit, '(a)') '  --material: elastic (default), J2 plasticity (type Q4p, Q4pf, ...; not with axi) or both'
    write(output_unit, '(a)') '  NEL: element counts (default 1e4 1e5 1e6), each rounded to a square mesh'
    write(output_unit, '(a)') '  --threads: the thread count compared with 1 (default OMP_NUM_THREADS if set, ' // &
      'else the cores)'
    write(output_unit, '(a)') '  --clock: wall (default) or cpu (the process CPU time of one thread, the default ' // &
      'thread count then; leaves out the waits of a loaded machine)'
    write(output_unit, '(a)') '  --min-time: least duration of one timing (default 0.3 s); --repeat: timings (default 5)'
    write(output_unit, '(a)') '  --cpu-time: the same as --clock cpu'
  end subroutine usage

  subroutine parse_command_line(types, ntypes, sizes, nsizes, min_time, nrep, nthreads, kin0, kin1, kin_step, &
      mat0, mat1, stat)
    integer, intent(out) :: types(2), ntypes, nsizes, nrep, nthreads, kin0, kin1, kin_step, mat0, mat1, stat
    integer(i8), intent(out) :: sizes(:)
    real(wp), intent(out) :: min_time
    character(len=64) :: arg
    integer :: k, nargs, ios, length, env_stat
    real(wp) :: v
    logical :: threads_given
    threads_given = .false.
    types = [ELEM_Q4, ELEM_Q8]
    ntypes = 2
    kin0 = 1
    kin1 = 1
    kin_step = 1
    mat0 = 1
    mat1 = 1
    nsizes = 0
    min_time = 0.3_wp
    nrep = 5
    stat = 0
    nthreads = 1
    !$ nthreads = omp_get_num_procs()
    call get_environment_variable('OMP_NUM_THREADS', arg, length=length, status=env_stat)
    if (env_stat == 0 .and. length > 0) then
      read(arg, *, iostat=ios) k
      if (ios == 0 .and. k >= 1) nthreads = k
    end if
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
      case ('--kinematics')
        k = k + 1
        call get_command_argument(k, arg)
        select case (trim(arg))
        case ('small'); kin0 = 1; kin1 = 1
        case ('finite'); kin0 = 2; kin1 = 2
        case ('all'); kin0 = 1; kin1 = 2
        case ('axi'); kin0 = 3; kin1 = 3
        case ('small-axi'); kin0 = 1; kin1 = 3; kin_step = 2
        case default
          write(error_unit, '(a)') 'raccord_bench: --kinematics takes small, finite, all, axi or small-axi, got "' // &
            trim(arg) // '"'
          stat = 1
          return
        end select
      case ('--material')
        k = k + 1
        call get_command_argument(k, arg)
        select case (trim(arg))
        case ('elastic'); mat0 = 1; mat1 = 1
        case ('j2'); mat0 = 2; mat1 = 2
        case ('all'); mat0 = 1; mat1 = 2
        case default
          write(error_unit, '(a)') 'raccord_bench: --material takes elastic, j2 or all, got "' // trim(arg) // '"'
          stat = 1
          return
        end select
      case ('--clock')
        k = k + 1
        call get_command_argument(k, arg)
        select case (trim(arg))
        case ('wall'); use_cpu_clock = .false.
        case ('cpu'); use_cpu_clock = .true.
        case default
          write(error_unit, '(a)') 'raccord_bench: --clock takes wall or cpu, got "' // trim(arg) // '"'
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
      case ('--threads')
        k = k + 1
        call get_command_argument(k, arg)
        read(arg, *, iostat=ios) nthreads
        threads_given = .true.
        if (ios /= 0 .or. nthreads < 1) then
          write(error_unit, '(a)') 'raccord_bench: --threads takes a positive integer, got "' // trim(arg) // '"'
          stat = 1
          return
        end if
      case ('--cpu-time')
        use_cpu_clock = .true.
      case ('--repeat')
        k = k + 1
        call get_command_argument(k, arg)
        read(arg, *, iostat=ios) nrep
        if (ios /= 0 .or. nrep < 1 .or. nrep > max_repeat) then
          write(error_unit, '(a)') 'raccord_bench: --repeat takes an integer in 1..99, got "' // trim(arg) // '"'
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
    ! --clock cpu times one thread: without --threads it takes one (the
    ! default team of all processors, or OMP_NUM_THREADS, is the wall
    ! clock's); with --threads N > 1 it is refused.
    if (use_cpu_clock .and. .not. threads_given) nthreads = 1
    if (use_cpu_clock .and. nthreads /= 1) then
      write(error_unit, '(a)') 'raccord_bench: --clock cpu adds up the CPU time of all threads; give --threads 1 with it'
      stat = 1
    end if
  end subroutine parse_command_line

  !> One case: the mesh, the kernel phase on a block, then the step phase
  !> on a model built from the same mesh, each on 1 and nthreads threads;
  !> one output line per thread count.
  subroutine run_case(etype, finite, axi, plastic, nel_wanted, min_time, nrep, nthreads)
    integer, intent(in) :: etype, nrep, nthreads
    logical, intent(in) :: finite, axi, plastic
    integer(i8), intent(in) :: nel_wanted
    real(wp), intent(in) :: min_time
    type(elastic_block_t), allocatable :: blk
    type(model_t) :: model
    type(error_t) :: err
    real(wp), allocatable :: x(:,:)
    integer, allocatable :: conn(:,:)
    integer :: nx, stat, nel, nnode, nthr(2), nt, k
    integer(i8) :: steps(2)
    real(wp) :: kern(max_repeat, 2), step(max_repeat, 2), split(3, max_repeat, 2), mem_kern, mem_step, balance
    real(wp) :: ceil_spd, t_alone, t_each, yshare(2, 2)
    character(len=:), allocatable :: label

    label = element_name(etype) // trim(merge('p', ' ', plastic)) // trim(merge('f', ' ', finite)) // &
      trim(merge('a', ' ', axi))
    nthr = [1, nthreads]
    nt = 2
    if (nthreads == 1) nt = 1
    call reset_peak_memory()
    nx = max(1, nint(sqrt(real(nel_wanted, wp))))
    call structured_mesh(etype, nx, nx, x, conn, stat)
    if (stat /= 0) then
      write(error_unit, '(a)') 'raccord_bench: cannot allocate a mesh of ' // element_name(etype) // ' elements'
      return
    end if
    nel = size(conn, 2)
    nnode = size(x, 2)

    ! phase 1: the kernel alone
    allocate(blk)
    call init_elastic_block(blk, etype, conn, x, 2.1e11_wp, 0.3_wp, .false., 1.0_wp, err)
    if (plastic .and. .not. err%failed()) then
      call make_plastic(blk, x, merge(KIN_FINITE, KIN_SMALL, finite), j2_t(1.0e8_wp, 2.1e9_wp), VOL_MEAN, &
        7800.0_wp, err)
    else if (finite .and. .not. err%failed()) then
      call make_finite(blk, x, MAT_NEO_HOOKE, merge(VOL_MEAN, VOL_FULL, etype == ELEM_Q4), 7800.0_wp, err)
    end if
    if (axi .and. .not. err%failed()) call make_axisymmetric(blk, x, err)
    if (err%failed()) then
      write(error_unit, '(a)') 'raccord_bench: ' // err%message
      return
    end if
    call bench_internal_force(blk, x, nthr(1:nt), min_time, nrep, kern, yshare(:, 1))
    mem_kern = real(peak_memory_kib(), wp)/1024.0_wp
    deallocate(blk)

    ! phase 2: whole steps of the plate model
    call reset_peak_memory()
    call plate_model(etype, x, conn, model, err, finite, axi, plastic)
    if (err%failed()) then
      write(error_unit, '(a)') 'raccord_bench: ' // err%message
      return
    end if
    call bench_step(model, nthr(1:nt), min_time, nrep, steps, step, split, balance, yshare(:, 2))
    mem_step = real(peak_memory_kib(), wp)/1024.0_wp
    ! phase 3: what the machine gives T serial runs at once
    if (nt > 1) call bench_ceiling(model, nthreads, min_time, nrep, ceil_spd, t_alone, t_each)

    do k = 1, nt
      write(output_unit, '(a4, i9, i9, i4, i7, 4f9.1, 3f8.1, 2f6.2, 2f9.1, f7.0, es10.1)') &
        label, &
        nel, nnode, nthr(k), steps(k), minval(kern(1:nrep, k)), median(kern(1:nrep, k)), &
        minval(step(1:nrep, k)), median(step(1:nrep, k)), median(split(1, 1:nrep, k)), &
        median(split(2, 1:nrep, k)), median(split(3, 1:nrep, k)), &
        median(kern(1:nrep, 1)/kern(1:nrep, k)), median(step(1:nrep, 1)/step(1:nrep, k)), &
        mem_kern, mem_step, mem_kern*1048576.0_wp/real(nel, wp), balance
    end do
    if (plastic) write(output_unit, '(a, 4(f0.2, a))') '# ' // label // ' at the end: elements yielded (ebar > 0) ', &
      yshare(1, 1), ' % (kernel), ', yshare(1, 2), ' % (step); chunks never yielded ', yshare(2, 1), ' %, ', &
      yshare(2, 2), ' %'
    ! The threaded step against T serial runs at once: the throughput of
    ! each (one step per t_each/T ns per element between them) is what the
    ! hardware gives when every core is busy, whatever the serial time.
    if (nt > 1) write(output_unit, '(a, i0, a, i0, a, f0.2, a, f0.1, a, f0.1, a, f0.2, a, i0, a)') &
      '# ceiling ' // label // ' ', &
      nel, ': ', nthreads, ' serial runs at once give ', ceil_spd, &
      'x the throughput of one (', t_each, ' ns per element and step each, ', t_alone, &
      ' alone); the threaded step runs at ', t_each/(real(nthreads, wp)*median(step(1:nrep, nt))), &
      ' of their joint throughput (', nrep, ' rounds, medians)'
    flush(output_unit)
  end subroutine run_case

  !> Time add_internal_force (each node reset by the group that touches it
  !> first, fresh = .true., as compute_forces does) on each thread count of
  !> nthr: nrep rounds, each timing every count in turn (back to back, so
  !> that a change of the machine's load hits both alike), each timing
  !> repeating the call until min_time has passed (at least 3 calls, after
  !> one warm-up call); ns(r, k) ns per element per call.
  subroutine bench_internal_force(blk, x, nthr, min_time, nrep, ns, yshare)
    type(elastic_block_t), intent(inout) :: blk
    real(wp), intent(in) :: x(:,:), min_time
    integer, intent(in) :: nthr(:), nrep
    real(wp), intent(out) :: ns(:,:)
    !> j2: per cent of the elements yielded and of the chunks never yielded
    real(wp), intent(out) :: yshare(2)
    real(wp), allocatable :: u(:,:), f(:,:)
    real(wp) :: t0, t
    integer :: calls, r, k
    type(block_watch_t) :: watch
    type(block_plastic_t) :: plastic
    call init_watch(blk, watch)
    if (blk%material == MAT_J2) call init_plastic(blk, plastic)
    allocate(u(2, size(x, 2)), f(2, size(x, 2)))
    u(1, :) = 1.0e-3_wp*sin(x(1, :) + 0.3_wp*x(2, :))
    u(2, :) = 1.0e-3_wp*cos(0.7_wp*x(1, :) - x(2, :))
    f = 0.0_wp
    do k = 1, size(nthr)
      blk%nthreads = nthr(k)
      call add_internal_force(blk, u, f, fresh=.true., watch=watch, plastic=plastic)
    end do
    repetitions: do r = 1, nrep
      thread_counts: do k = 1, size(nthr)
        blk%nthreads = nthr(k)
        calls = 0
        t0 = wall_time()
        do
          ! as compute_forces calls it (a finite block also reports its
          ! energy, smallest J and stable-step estimate)
          call add_internal_force(blk, u, f, fresh=.true., watch=watch, monitor=.true., plastic=plastic)
          calls = calls + 1
          t = wall_time() - t0
          if (calls >= 3 .and. t >= min_time) exit
        end do
        ns(r, k) = 1.0e9_wp*t/(real(calls, wp)*real(blk%nel, wp))
      end do thread_counts
    end do repetitions
    yshare = 0.0_wp
    if (blk%material == MAT_J2) yshare = yield_share(plastic, blk%nel)
    ! keep the result alive so the calls cannot be optimised away
    if (.not. (abs(sum(f)) < huge(1.0_wp))) write(output_unit, '(a)') '# non-finite internal force'
  end subroutine bench_internal_force

  !> March the model at 0.9 of the stable step with the program's step
  !> sequence, on each thread count of nthr in turn: nrep rounds, each
  !> timing every count back to back for at least min_time (at least 3
  !> steps); one state marches on through all of them (the results do not
  !> depend on the thread count). ns(r, k) ns per element per step in
  !> total and split(:, r, k) into compute_forces, predict_motion and
  !> update_energy + advance_state; steps(k) the steps timed on nthr(k).
  !> balance: the relative energy balance at the end (round-off for this
  !> undamped linear model, so a wrong kernel shows up here).
  subroutine bench_step(model, nthr, min_time, nrep, steps, ns, split, balance, yshare)
    type(model_t), intent(inout) :: model
    integer, intent(in) :: nthr(:), nrep
    real(wp), intent(in) :: min_time
    integer(i8), intent(out) :: steps(:)
    real(wp), intent(out) :: ns(:,:), split(:,:,:), balance
    !> j2: per cent of the elements yielded and of the chunks never yielded
    real(wp), intent(out) :: yshare(2)
    type(state_t) :: state
    real(wp) :: t0, t1, t2, t3, tf, tp, tr, scale
    integer :: r, n, k

    call init_state(model, 0.9_wp*2.0_wp/sqrt(model%w2_bound), 0_i8, state)
    ! step 0 (as the program's start_march); then each step n is
    ! forces, predictor and energy at t(n), and the move to n+1
    call march(model, state, 1)
    steps = 0
    repetitions: do r = 1, nrep
      thread_counts: do k = 1, size(nthr)
        call set_model_threads(model, nthr(k))
        tf = 0.0_wp
        tp = 0.0_wp
        tr = 0.0_wp
        n = 0
        time_steps: do
          t0 = wall_time()
          call compute_forces(model, state)
          t1 = wall_time()
          call predict_motion(model, state)
          t2 = wall_time()
          call update_energy(model, state)
          call advance_state(state)
          t3 = wall_time()
          tf = tf + (t1 - t0)
          tp = tp + (t2 - t1)
          tr = tr + (t3 - t2)
          n = n + 1
          if (n >= 3 .and. tf + tp + tr >= min_time) exit
        end do time_steps
        steps(k) = steps(k) + n
        scale = 1.0e9_wp/(real(n, wp)*real(model%nelem, wp))
        ns(r, k) = (tf + tp + tr)*scale
        split(:, r, k) = [tf, tp, tr]*scale
      end do thread_counts
    end do repetitions
    balance = state%energy%balance/max(state%energy%scale, tiny(1.0_wp))
    yshare = 0.0_wp
    if (allocated(state%plastic(1, 1)%h)) yshare = yield_share(state%plastic(1, 1), model%nelem)
  end subroutine bench_step

  !> Per cent of the nel elements with ebar > 0 at a Gauss point, and of the
  !> chunks still virgin (their internal variables all 0: the small-strain
  !> kernel skips their return while they stay elastic).
  function yield_share(plastic, nel) result(share)
    type(block_plastic_t), intent(in) :: plastic
    integer, intent(in) :: nel
    real(wp) :: share(2)
    integer :: ic, il, ny
    ! (loops: no temporary to add to the phase's peak memory)
    ny = 0
    do ic = 1, size(plastic%h, 4)
      do il = 1, size(plastic%h, 1)
        if (any(plastic%h(il, h_ebar, :, ic) > 0.0_wp)) ny = ny + 1
      end do
    end do
    share(1) = 100.0_wp*real(ny, wp)/real(nel, wp)
    share(2) = 100.0_wp*real(count(plastic%virgin), wp)/real(size(plastic%virgin), wp)
  end function yield_share

  !> The machine's ceiling for the step's speed-up: T serial runs of the
  !> same model at once (one per thread, each on its own copy of the model),
  !> against one run alone. If the T runs together do T times the steps of
  !> one alone, the hardware scales; if they are slower each, the shared
  !> memory system (bandwidth, caches) caps any threading of the step too.
  !> Rounds as in bench_step (alone, then together, back to back); the
  !> results: ceil_spd the median of T t_alone/t_together, t_alone and
  !> t_each the medians in ns per element and step.
  subroutine bench_ceiling(model, nthreads, min_time, nrep, ceil_spd, t_alone, t_each)
    type(model_t), intent(in) :: model
    integer, intent(in) :: nthreads, nrep
    real(wp), intent(in) :: min_time
    real(wp), intent(out) :: ceil_spd, t_alone, t_each
    type(model_t), allocatable :: copies(:)
    type(state_t), allocatable :: states(:)
    real(wp) :: alone(max_repeat), each(max_repeat), dt, t0, t, scale
    integer :: r, n, k
    allocate(copies(nthreads), states(nthreads))
    dt = 0.9_wp*2.0_wp/sqrt(model%w2_bound)
    do k = 1, nthreads
      copies(k) = model
      call set_model_threads(copies(k), 1)
      call init_state(copies(k), dt, 0_i8, states(k))
    end do
    do r = 1, nrep
      ! one run alone, as many steps as fill min_time (at least 3)
      n = 0
      t0 = wall_time()
      do
        call march(copies(1), states(1), 1)
        n = n + 1
        t = wall_time() - t0
        if (n >= 3 .and. t >= min_time) exit
      end do
      scale = 1.0e9_wp/(real(n, wp)*real(model%nelem, wp))
      alone(r) = t*scale
      ! the same number of steps on every copy at once
      t0 = wall_time()
      !$omp parallel do num_threads(nthreads) schedule(static, 1) default(none) shared(copies, states, n, nthreads)
      do k = 1, nthreads
        call march(copies(k), states(k), n)
      end do
      !$omp end parallel do
      each(r) = (wall_time() - t0)*scale
    end do
    ceil_spd = median(real(nthreads, wp)*alone(1:nrep)/each(1:nrep))
    t_alone = median(alone(1:nrep))
    t_each = median(each(1:nrep))
  end subroutine bench_ceiling

  !> nsteps steps of the program's sequence on model m, state st.
  subroutine march(m, st, nsteps)
    type(model_t), intent(in) :: m
    type(state_t), intent(inout) :: st
    integer, intent(in) :: nsteps
    integer :: j
    do j = 1, nsteps
      call compute_forces(m, st)
      call predict_motion(m, st)
      call update_energy(m, st)
      call advance_state(st)
    end do
  end subroutine march
end program raccord_bench
