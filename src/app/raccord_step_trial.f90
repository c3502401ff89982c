!> The timed trial of the real step behind the plan's cost estimate
!> (`raccord --check`, the `cost` line; doc/hpc.md, "Sizing a job").
!>
!> The elastic work of a step does not change during a run, but the
!> contact work does: it grows with the number of slave nodes in contact
!> (the matching of their segments and the multiplier solve). So contact
!> is timed twice, on scratch copies of the state and the pairs:
!>   1. in the state at t = 0 (the contact zone the run starts with);
!>   2. in an engaged state: every slave node that the prescribed motion of
!>      the scene can bring onto the master is placed on it and approaches
!>      it at each step, so that it is active (the largest zone to expect).
!> The run's contact zone grows from the first towards the second and, in
!> a load cycle, back: the estimate takes the mean of the two and the plan
!> prints both as the range.
module raccord_step_trial
  use raccord_kinds, only: wp, i8
  use raccord_log, only: log_level, log_set_level, LEVEL_ERROR
  use raccord_error, only: error_t
  use raccord_model, only: model_t
  use raccord_state, only: state_t, init_state
  use raccord_time_step, only: time_plan_t, check_deformation
  use raccord_state_guard, only: prediction_finite
  use raccord_central_difference, only: compute_forces, predict_motion, update_energy, advance_state
  use raccord_elastic_block, only: add_nodal_stress
  use raccord_contact_pair, only: contact_pair_t, enforce_contact
  use raccord_history_columns, only: history_width, fill_history_row
  use raccord_history_file, only: ROW_FORMAT
  use hdf5, only: hid_t, h5fclose_f
  use raccord_h5, only: h5_acquire, h5_release, h5_create_file
  use raccord_h5_table, only: h5_create_table, h5_append_rows
  use raccord_files, only: is_directory, delete_file
  use raccord_output_state, only: HISTORY_BLOCK_ROWS, HISTORY_BLOCK_VALUES
  implicit none
  private

  public :: measure_step_cost

  !> Measured seconds of the parts of a step.
  type, public :: step_cost_t
    real(wp) :: element = 0.0_wp          !< forces, predictor, energy: per step
    real(wp) :: contact = 0.0_wp          !< search, matching, solve per step, contact zone of t = 0
    real(wp) :: contact_engaged = 0.0_wp  !< the same with the engaged slave nodes in contact
    real(wp) :: frame = 0.0_wp            !< one output frame's stress recovery
    !> one history row: its values (each support's reaction sums the
    !> constrained dofs: supports x dofs) and its text line, written and
    !> flushed as the run writes each row
    real(wp) :: history = 0.0_wp
    integer :: history_rows = 0           !< timed trial rows
    integer :: steps = 0                  !< timed trial steps (state at t = 0)
    integer :: engaged = 0                !< slave nodes placed in contact for the second trial
    integer :: slave_nodes = 0            !< slave surface nodes of all pairs
    logical :: motion_bounded = .false.   !< the engaged set is limited by the prescribed motion
  end type step_cost_t

  !> Trial length: at most this many timed steps, or this many seconds.
  integer, parameter :: trial_steps = 500, engaged_steps = 200
  real(wp), parameter :: trial_seconds = 0.5_wp, engaged_seconds = 0.25_wp
  !> History trial: at most this many rows, or this many seconds.
  integer, parameter :: history_trial_rows = 2000
  real(wp), parameter :: history_seconds = 0.1_wp
  !> How far an engaged slave node moves into the master per step, in
  !> units of the shortest segment of the pair's surfaces.
  real(wp), parameter :: approach = 1.0e-2_wp

contains

  !> Seconds per step of the real step, from short trial runs on scratch
  !> copies of the state and the contact pairs: the elastic work (forces,
  !> predictor, energy) from t = 0; the contact work (search, matching,
  !> multipliers) from t = 0 and in the engaged state (module header); and
  !> the work of one output frame (the nodal stress recovery; the HDF5
  !> writes are not timed). The first step of a trial is not timed (first
  !> touch of the scratch arrays). The trials' messages (a first-step
  !> overlap, say) are held back: the run itself reports them. A serial run
  !> is timed in processor time, which other processes on the machine do
  !> not inflate: the estimate is then the run time on a core of its own (a
  !> batch job's); a threaded run is timed in wall time.
  function measure_step_cost(model, plan, pairs, dir) result(cost)
    type(model_t), intent(in) :: model
    type(time_plan_t), intent(in) :: plan
    type(contact_pair_t), intent(in) :: pairs(:)
    character(len=*), intent(in) :: dir      !< the run's output folder (its history files' disk)
    type(step_cost_t) :: cost
    type(state_t) :: scratch
    type(contact_pair_t), allocatable :: trial(:)
    type(error_t) :: err
    real(wp), allocatable :: s_node(:,:), wsum(:)
    real(wp) :: t0, t1, t2, t3, element_sec, contact_sec
    integer :: k, ib, level, nstep
    logical :: threaded
    level = log_level()
    call log_set_level(LEVEL_ERROR + 1)
    call init_state(model, plan%dt, plan%nsteps, scratch)
    if (model%has_body_force) scratch%f_ext = model%f_body
    trial = pairs
    threaded = model%nthreads > 1
    element_sec = 0.0_wp
    contact_sec = 0.0_wp
    nstep = 0
    do k = 0, int(min(int(trial_steps, i8), plan%nsteps))
      t0 = seconds_now(threaded)
      call compute_forces(model, scratch)
      ! A trial that inverts an element or blows up stops there: what was
      ! timed so far stands (the run itself stops with the message).
      if (model%has_finite) then
        call check_deformation(model, scratch, err)
        if (err%failed()) exit
      end if
      call predict_motion(model, scratch)
      if (.not. prediction_finite(scratch)) exit
      t1 = seconds_now(threaded)
      if (size(trial) > 0) call enforce_contact(trial, model, scratch, err)
      if (err%failed()) exit
      t2 = seconds_now(threaded)
      call update_energy(model, scratch)
      call advance_state(scratch)
      t3 = seconds_now(threaded)
      if (k == 0) cycle
      element_sec = element_sec + (t1 - t0) + (t3 - t2)
      contact_sec = contact_sec + (t2 - t1)
      nstep = nstep + 1
      if (element_sec + contact_sec > trial_seconds) exit
    end do
    cost%steps = nstep
    cost%element = element_sec/real(max(1, nstep), wp)
    cost%contact = contact_sec/real(max(1, nstep), wp)
    if (size(trial) == 0) cost%contact = 0.0_wp      ! only the clock's own cost was timed
    cost%contact_engaged = cost%contact
    if (size(pairs) > 0) call time_engaged_contact(model, plan, pairs, threaded, cost)

    allocate(s_node(4, model%nnode), wsum(model%nnode))
    s_node = 0.0_wp
    wsum = 0.0_wp
    t0 = seconds_now(threaded)
    do ib = 1, size(model%bodies)
      do k = 1, size(model%bodies(ib)%blocks)
        call add_nodal_stress(model%bodies(ib)%blocks(k), scratch%u, s_node, wsum, plastic=scratch%plastic(k, ib))
      end do
    end do
    t1 = seconds_now(threaded)
    cost%frame = t1 - t0
    call time_history_row(model, scratch, trial, threaded, dir, cost)
    call log_set_level(level)
  end function measure_step_cost

  !> Seconds per history row (raccord_output write_due_outputs): the
  !> row's values from the trial's state (fill_history_row, whose
  !> reactions sum the constrained dofs once per support), its line in
  !> the history file's format, written and flushed as the run flushes
  !> every row, and its copy in /history of the results file, appended in
  !> blocks of the run's size (flush_history). Both files are trial files
  !> in the run's output folder, on the disk the run writes to (they were
  !> a scratch file in TMPDIR, and the HDF5 copy was not timed), deleted
  !> afterwards; without the folder (--check before the run made it) the
  !> text goes to a scratch file and the HDF5 copy is left out. Left out
  !> before: a scene with many supports written at every step of 10^6
  !> steps ran ten times its estimate.
  subroutine time_history_row(model, state, pairs, threaded, dir, cost)
    type(model_t), intent(in) :: model
    type(state_t), intent(in) :: state
    type(contact_pair_t), intent(in) :: pairs(:)
    logical, intent(in) :: threaded
    character(len=*), intent(in) :: dir
    type(step_cost_t), intent(inout) :: cost
    real(wp), allocatable :: row(:), block(:,:)
    real(wp) :: t0, t1
    integer :: u, ios, n, nbuf, hdferr, cerr
    integer(hid_t) :: file
    logical :: opened, in_dir, h5ok, acquired
    character(len=:), allocatable :: text_name, h5_name
    type(error_t) :: err, rerr
    allocate(row(history_width(model, pairs)))
    allocate(block(size(row), max(1, min(HISTORY_BLOCK_ROWS, HISTORY_BLOCK_VALUES/max(1, size(row))))))
    in_dir = is_directory(dir)
    text_name = dir // '/.raccord-trial.history.txt.part'
    h5_name = dir // '/.raccord-trial.h5.part'
    if (in_dir) then
      open(newunit=u, file=text_name, status='replace', action='write', form='formatted', iostat=ios)
    else
      open(newunit=u, status='scratch', action='readwrite', form='formatted', iostat=ios)
    end if
    opened = ios == 0          ! without a file, the rows' values alone are timed
    h5ok = .false.
    acquired = .false.
    hdferr = -1
    if (in_dir) then
      call h5_acquire(err)
      acquired = .not. err%failed()
      if (acquired) then
        call h5_create_file(h5_name, file, hdferr)
        h5ok = hdferr == 0
        if (h5ok) call h5_create_table(file, '/history', size(row), size(block, 2), h5_name, err)
        h5ok = h5ok .and. .not. err%failed()
      end if
    end if
    n = 0
    nbuf = 0
    t0 = seconds_now(threaded)
    t1 = t0
    do while (n < history_trial_rows .and. t1 - t0 < history_seconds)
      call fill_history_row(model, state, pairs, row)
      if (ios == 0) write(u, ROW_FORMAT, iostat=ios) row
      if (ios == 0) flush(u, iostat=ios)
      if (h5ok) then
        nbuf = nbuf + 1
        block(:, nbuf) = row
        if (nbuf == size(block, 2)) then
          call h5_append_rows(file, '/history', block, h5_name, err)
          h5ok = .not. err%failed()
          nbuf = 0
        end if
      end if
      n = n + 1
      t1 = seconds_now(threaded)
    end do
    if (opened) then
      if (in_dir) then
        close(u, status='delete', iostat=ios)
      else
        close(u, iostat=ios)
      end if
    end if
    if (in_dir) then
      if (hdferr == 0) call h5fclose_f(file, cerr)
      if (acquired) call h5_release(rerr)
      call delete_file(h5_name)
      call delete_file(text_name)
    end if
    cost%history_rows = n
    cost%history = (t1 - t0)/real(max(1, n), wp)
  end subroutine time_history_row

  !> The contact work per step with the engaged slave nodes in contact
  !> (module header, 2.). The trial repeats one step of the run: every node
  !> at rest but the engaged slave nodes, which move `approach` into the
  !> master; the elastic forces are left out (the nodes were moved, not
  !> strained, and only the contact work is timed), so that each step
  !> solves the same contact problem with the warm start of the last, as
  !> the run does while its contact zone changes slowly.
  subroutine time_engaged_contact(model, plan, pairs, threaded, cost)
    type(model_t), intent(in) :: model
    type(time_plan_t), intent(in) :: plan
    type(contact_pair_t), intent(in) :: pairs(:)
    logical, intent(in) :: threaded
    type(step_cost_t), intent(inout) :: cost
    type(state_t) :: scratch
    type(contact_pair_t), allocatable :: trial(:)
    type(error_t) :: err
    real(wp), allocatable :: w(:,:)
    real(wp) :: motion, t1, t2, contact_sec
    integer :: k, nstep, n

    call init_state(model, plan%dt, plan%nsteps, scratch)
    scratch%step = 1                 ! a step of the run, not its first half step
    trial = pairs
    allocate(w(2, model%nnode))
    w = 0.0_wp
    motion = prescribed_motion(model, plan)
    cost%motion_bounded = motion < huge(1.0_wp)
    cost%engaged = 0
    cost%slave_nodes = 0
    do k = 1, size(trial)
      call engage_slave_nodes(trial(k), model, plan%dt, motion, scratch%u, w, n)
      cost%engaged = cost%engaged + n
      cost%slave_nodes = cost%slave_nodes + trial(k)%slave%nnode
    end do
    if (cost%engaged == 0) return

    contact_sec = 0.0_wp
    nstep = 0
    do k = 0, engaged_steps
      scratch%v = w
      call predict_motion(model, scratch)
      if (.not. prediction_finite(scratch)) exit
      t1 = seconds_now(threaded)
      call enforce_contact(trial, model, scratch, err)
      t2 = seconds_now(threaded)
      if (err%failed()) return              ! keep the estimate of t = 0
      if (k == 0) cycle
      contact_sec = contact_sec + (t2 - t1)
      nstep = nstep + 1
      if (contact_sec > engaged_seconds) exit
    end do
    cost%contact_engaged = max(cost%contact, contact_sec/real(max(1, nstep), wp))
  end subroutine time_engaged_contact

  !> Place on the master every slave node of `pair` that the prescribed
  !> motion can bring there: its nearest point on the master's chords is
  !> not beyond an end of an open master, and no farther than `motion`
  !> plus the search distance. Its displacement u moves it there, and w is the velocity
  !> that carries it `approach` h into the master in one step. Nodes
  !> whose two components are prescribed stay where they are.
  subroutine engage_slave_nodes(pair, model, dt, motion, u, w, n)
    type(contact_pair_t), intent(in) :: pair
    type(model_t), intent(in) :: model
    real(wp), intent(in) :: dt, motion
    real(wp), intent(inout) :: u(:,:), w(:,:)
    integer, intent(out) :: n
    real(wp) :: x(2), xa(2), t(2), p(2), pbest(2), xi, d, dbest, h, limit
    integer :: i, j, node, prev
    logical :: at_end

    n = 0
    h = min(pair%master%h_min, pair%slave%h_min)
    if (h <= 0.0_wp) return
    limit = huge(1.0_wp)
    if (motion < huge(1.0_wp)) limit = motion + pair%reach
    do i = 1, pair%slave%nnode
      node = pair%slave%node(i)
      if (all(model%minv_dof(:, node) == 0.0_wp)) cycle
      x = model%x(:, node) + u(:, node)
      dbest = huge(1.0_wp)
      at_end = .true.
      do j = 1, pair%master%nseg
        xa = model%x(:, pair%master%seg(1, j)) + u(:, pair%master%seg(1, j))
        t = model%x(:, pair%master%seg(2, j)) + u(:, pair%master%seg(2, j)) - xa
        xi = dot_product(x - xa, t)/max(dot_product(t, t), tiny(1.0_wp))
        p = xa + min(1.0_wp, max(0.0_wp, xi))*t
        d = norm2(x - p)
        if (d < dbest) then
          dbest = d
          pbest = p
          ! nearest at an end of an open master: the node is beyond it
          at_end = .not. pair%master%closed .and. ((j == 1 .and. xi <= 0.0_wp) .or. &
            (j == pair%master%nseg .and. xi >= 1.0_wp))
        end if
      end do
      if (at_end) cycle
      ! A node already on the master (or with no segment beside it) is
      ! left as it is: the trial of t = 0 has timed it.
      if (dbest > limit .or. dbest <= 1.0e-9_wp*h) cycle
      ! Two chain neighbours on one point (both nearest to one vertex of
      ! the master, or a slave surface folded over itself) would make a
      ! slave segment of length 0: the second stays where it is.
      if (i > 1) then
        prev = pair%slave%node(i - 1)
        if (norm2(model%x(:, prev) + u(:, prev) - pbest) <= 1.0e-3_wp*h) cycle
      end if
      w(:, node) = -approach*h/dt*(x - pbest)/dbest
      u(:, node) = pbest - model%x(:, node)
      n = n + 1
    end do
  end subroutine engage_slave_nodes

  !> The largest prescribed motion of the scene: driven displacements at
  !> their largest amplitude and initial velocities over the run. A scene
  !> with loads or a body force has no such bound (huge).
  real(wp) function prescribed_motion(model, plan) result(d)
    type(model_t), intent(in) :: model
    type(time_plan_t), intent(in) :: plan
    real(wp) :: amax
    integer :: k
    d = huge(1.0_wp)
    if (model%has_loads .or. model%has_body_force) return
    d = 0.0_wp
    do k = 1, size(model%supports)
      if (.not. model%supports(k)%driven) cycle
      amax = 1.0_wp
      if (model%supports(k)%amplitude > 0) amax = maxval(abs(model%amplitudes(model%supports(k)%amplitude)%a))
      d = max(d, norm2(model%supports(k)%value)*amax)
    end do
    if (allocated(model%v0)) then
      if (size(model%v0) > 0) d = max(d, sqrt(maxval(sum(model%v0**2, dim=1)))*plan%t_end)
    end if
  end function prescribed_motion

  !> Processor time of this process, or wall time when `wall`.
  real(wp) function seconds_now(wall) result(t)
    logical, intent(in) :: wall
    integer(i8) :: count, rate
    if (wall) then
      call system_clock(count, rate)
      t = real(count, wp)/real(rate, wp)
    else
      call cpu_time(t)
    end if
  end function seconds_now
end module raccord_step_trial
