!> raccord: explicit 2D finite elements for frictional contact between
!> deformable bodies, with contact enforced by Lagrange multipliers one step
!> ahead (Baillet & Sassi, C. R. Mecanique 331 (2003); Carpenter, Taylor &
!> Katona, IJNME 32 (1991)).
!>
!> The program reads like the algorithm: read the scene and the mesh, build
!> the model, choose the stable step, then march in time with the central
!> difference scheme. Each step: forces at t(n), predictor to t(n+1), contact
!> correction at t(n+1) (forward increment), energy account, outputs.
program raccord_main
  use, intrinsic :: iso_fortran_env, only: output_unit
  use, intrinsic :: iso_c_binding, only: c_int
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use raccord_kinds, only: wp, i8
  use raccord_error, only: error_t, raise_error, EXIT_OK, EXIT_USAGE, EXIT_INPUT, EXIT_NUMERIC, EXIT_IO, &
    EXIT_WALLCLOCK, EXIT_INTERNAL
  use raccord_log, only: log_open, log_close, log_info, log_warn, log_debug, log_error, log_raw, log_set_quiet, log_set_level, &
    LEVEL_DEBUG, log_unit
  use raccord_strings, only: str
  use raccord_version, only: raccord_version_string
  use raccord_host, only: host_name
  use raccord_signals, only: install_stop_signals
  use raccord_cli, only: cli_t, parse_command_line, usage_text
  use raccord_scene, only: scene_t
  use raccord_deck, only: read_scene, write_scene
  use raccord_paths, only: path_dir, path_base, absolute_path, normal_path
  use raccord_mesh, only: mesh_t
  use raccord_mesh_io, only: read_mesh
  use raccord_model, only: model_t
  use raccord_model_build, only: build_model
  use raccord_time_step, only: time_plan_t, choose_time_step, adapt_time_step, check_deformation
  use raccord_state_guard, only: prediction_finite
  use raccord_state, only: state_t, init_state
  use raccord_central_difference, only: compute_forces, predict_motion, update_energy, advance_state
  use raccord_contact_pair, only: contact_pair_t, init_contact_pairs, enforce_contact
  use raccord_contact_energy, only: contact_energy_watch_t, watch_contact_energy, report_contact_energy, &
    contact_watch_record, restore_contact_watch, CONTACT_WATCH_LENGTH
  use raccord_run_report, only: report_plan, report_summary, run_stem
  use raccord_output, only: output_t, output_mark_t, open_outputs, write_due_outputs, close_outputs, &
    mark_outputs, suspend_outputs, resume_outputs, history_width
  use raccord_checkpoint, only: checkpoint_name, write_checkpoint, read_checkpoint, checkpoint_scene_path
  use raccord_run_control, only: run_control_t, start_run_control, set_run_limits, note_step, must_stop, &
    stop_reason, checkpoint_due, note_checkpoint
  use raccord_files, only: make_directory, file_exists, delete_file, write_failure_reason
  use raccord_run_lock, only: take_run_lock, drop_run_lock
  use raccord_threads, only: wait_passively_if_oversubscribed
  use raccord_verify, only: verify_file
  use raccord_kinetic_check, only: kinetic_check_t, init_kinetic_check, watch_kinetic_energy, report_kinetic_check, &
    kinetic_check_record, restore_kinetic_check, KINETIC_CHECK_LENGTH
  implicit none

  interface
    ! POSIX _exit: leave without running atexit handlers.
    subroutine c_exit(status) bind(C, name='_exit')
      import :: c_int
      integer(c_int), value :: status
    end subroutine c_exit
    ! C exit: leave with a status, running the exit-time cleanup (the
    ! Fortran units, the HDF5 library) as a STOP would, but printing
    ! nothing: gfortran's ERROR STOP adds its own line and a backtrace.
    subroutine c_exit_clean(status) bind(C, name='exit')
      import :: c_int
      integer(c_int), value :: status
    end subroutine c_exit_clean
  end interface

  type(cli_t) :: cli
  type(scene_t) :: scene
  type(mesh_t) :: mesh
  type(model_t) :: model
  type(time_plan_t) :: plan
  type(state_t) :: state
  type(output_t) :: out
  type(run_control_t) :: control
  type(contact_pair_t), allocatable :: pairs(:)
  type(contact_energy_watch_t) :: contact_watch   ! energy given by contact (warns once)
  type(error_t) :: err
  character(len=:), allocatable :: stem, why, recorded_scene
  logical :: restart
  integer(i8) :: first_step
  type(kinetic_check_t) :: kcheck            ! quasi-static check of a mass-scaled run
  real(wp), allocatable :: watch_record(:)   ! the watchers' record of a checkpoint (restart)

  ! Phase 0: what the user asked for; stop signals ask for a checkpoint.
  call wait_passively_if_oversubscribed()    ! may restart the program (raccord_threads)
  call start_run_control(control)
  call parse_command_line(cli, err)
  if (err%failed()) call finish(err)
  if (cli%help) then
    write(output_unit, '(a)') usage_text()
    stop
  end if
  if (cli%version) then
    write(output_unit, '(a)') 'raccord ' // raccord_version_string
    stop
  end if
  if (allocated(cli%verify_path)) call verify_only()
  if (cli%quiet) call log_set_quiet(.true.)
  if (cli%verbose) call log_set_level(LEVEL_DEBUG)
  restart = allocated(cli%restart_path)
  if (.not. cli%check) call install_stop_signals(err)
  if (err%failed()) call finish(err)

  ! Phase 1: the scene deck, and the run's folder and log. A restart goes
  ! on in the checkpoint's folder, with the deck it was written for unless
  ! another is given.
  if (restart) then
    call checkpoint_scene_path(cli%restart_path, recorded_scene, err)   ! also checks the file
    if (err%failed()) call finish(err)
    if (.not. allocated(cli%scene_path)) then
      cli%scene_path = recorded_scene
      ! the deck the checkpoint records, moved or deleted since: say where
      ! the path came from and how to give the deck
      if (.not. file_exists(recorded_scene)) then
        call raise_error(err, EXIT_INPUT, 'restart: ' // cli%restart_path // ' was written for the deck ' // &
          recorded_scene // ', which no longer exists; give the deck after the checkpoint: raccord --restart ' // &
          cli%restart_path // ' DECK')
        call finish(err)
      end if
    end if
  end if
  call read_scene(cli%scene_path, scene, err)
  if (err%failed()) call finish(err)
  if (allocated(cli%output_dir)) scene%run%output_dir = cli%output_dir
  if (restart) call place_restart()
  stem = run_stem(scene)
  call keep_inputs(scene%path, 'scene deck')
  call keep_inputs(scene%mesh%file, 'mesh file')
  if (.not. cli%check) call open_run_folder()

  ! Phase 2: the mesh; phase 3: the discrete model (paper section 3: bodies,
  ! lumped masses, supports Gamma_u, loads Gamma_g).
  call read_mesh(scene%mesh%file, mesh, err, scene%mesh%format, scene%mesh%scale)
  if (err%failed()) call finish(err)
  call build_model(scene, mesh, model, err)
  if (err%failed()) call finish(err)
  call init_contact_pairs(scene, mesh, model, pairs, err)    ! slave/master chains (paper section 3)
  if (err%failed()) call finish(err)

  ! Phase 4: the stable time step (dt <= 2/omega_max) and the plan.
  call choose_time_step(scene, model, plan, err)
  if (err%failed()) call finish(err)
  call report_plan(scene, mesh, model, plan, pairs)
  if (cli%check) then
    call write_scene(scene, output_unit)
    stop
  end if

  ! Phase 5: march in time, from t = 0 or from the checkpoint.
  call init_state(model, plan%dt, plan%nsteps, state)
  state%t_end = plan%t_end
  state%safety = scene%time%safety
  if (restart) then
    call resume_run()
  else
    call open_outputs(out, scene, model, plan, pairs, stem, err)
    if (err%failed()) call finish(err)
  end if
  first_step = state%step
  call init_kinetic_check(kcheck, model%scaling%active, scene%time%kinetic_ratio_warn, &
    scene%time%kinetic_check_from, plan%t_end)
  if (allocated(watch_record)) then          ! a restart goes on with what the watchers saw
    call restore_kinetic_check(kcheck, watch_record(1:KINETIC_CHECK_LENGTH))
    call restore_contact_watch(contact_watch, watch_record(KINETIC_CHECK_LENGTH+1:))
  end if
  if (model%has_body_force) state%f_ext = model%f_body
  call start_limits()

  time_steps: do
    call compute_forces(model, state)        ! f_int(u(n)), f_ext(t(n))
    if (model%has_finite) then
      ! Finite strain: no inverted element, and the stable step of the
      ! deformed mesh (a variable step, raccord_time_step).
      call check_deformation(model, state, err)
      if (err%failed()) call finish(err)
      call adapt_time_step(model, state, err)
      if (err%failed()) call finish(err)
    end if
    call predict_motion(model, state)        ! (CD-1), (CD-2): v(n+1/2), u*(n+1); reactions
    ! A non-finite prediction stops before the contact search sizes its
    ! bins from it (raccord_state_guard).
    if (size(pairs) > 0) then
      if (.not. prediction_finite(state)) call stop_non_finite('non-finite predicted displacement')
    end if
    ! Forward increment: the multipliers lambda(n) make the contact and
    ! friction conditions (paper eq. 19) hold at t(n+1); u(n+1) and v(n+1/2)
    ! are corrected. A scene without contact pairs skips it.
    if (size(pairs) > 0) call enforce_contact(pairs, model, state, err)
    if (err%failed()) call finish(err)
    call update_energy(model, state)         ! energy account at t(n)
    call watch_contact_energy(pairs, state, contact_watch)
    call guard_finite()
    if (kcheck%active) call watch_kinetic_energy(kcheck, state)
    call write_due_outputs(out, model, state, pairs, err)
    if (err%failed()) call finish(err)
    if (state%step == state%nsteps) exit time_steps
    call advance_state(state)                ! n <- n+1
    ! Step boundary: the state is u(n), u(n-1), v(n-1/2) and the energy
    ! account; a checkpoint here continues bit for bit.
    call note_step(control)
    if (must_stop(control)) then
      why = stop_reason(control)
      call save_checkpoint()
      call stop_at_checkpoint(why)
    end if
    if (checkpoint_due(control, state%step)) call save_checkpoint()
  end do time_steps

  ! Phase 6: close the results under their final names; the checkpoint of
  ! this run is no longer needed.
  call close_outputs(out, .true., '', err)
  if (err%failed()) call finish(err)
  call delete_file(checkpoint_name(stem))
  call report_summary(model, state, out, pairs, first_step)
  call report_kinetic_check(kcheck)
  call report_contact_energy(pairs, state, contact_watch)
  call log_debug('raccord', 'longest step ' // str(control%step_max, 3) // ' s, longest checkpoint write ' // &
    str(control%write_max, 3) // ' s (' // str(control%checkpoints) // ' checkpoints)')
  call drop_run_lock()
  call log_close()

contains

  !> A restart writes where the checkpoint is: its folder is the output
  !> folder and its name, <stem>.checkpoint.h5, names the run, which must be
  !> the deck's (the running results files carry that name).
  subroutine place_restart()
    character(len=*), parameter :: suffix = '.checkpoint.h5'
    character(len=:), allocatable :: p, dir, name
    p = cli%restart_path     ! ends in suffix (parse_command_line)
    dir = path_dir(p)
    name = path_base(p(1:len(p)-len(suffix)))
    if (allocated(cli%output_dir)) then
      if (absolute_path(trim_slash(cli%output_dir)) /= absolute_path(dir)) then
        call raise_error(err, EXIT_USAGE, '--output ' // cli%output_dir // ' is not the folder of the checkpoint ' // &
          p // ': a restart writes where its checkpoint is; leave --output out or make them agree')
        call finish(err)
      end if
    end if
    scene%run%output_dir = dir
    if (path_base(run_stem(scene)) /= name) then
      call raise_error(err, EXIT_INPUT, 'restart refused: ' // p // ' belongs to the run ''' // name // &
        ''', but scene ' // scene%path // ' names its run ''' // path_base(run_stem(scene)) // &
        '''; give the deck the checkpoint was written for')
      call finish(err)
    end if
  end subroutine place_restart

  pure function trim_slash(path) result(s)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: s
    s = path
    do while (len(s) > 1)
      if (s(len(s):len(s)) /= '/') exit
      s = s(1:len(s)-1)
    end do
  end function trim_slash

  !> Restore the state, contact sets and energies from the checkpoint and
  !> reopen the running result files where it left them.
  subroutine resume_run()
    type(output_mark_t) :: mark
    allocate(watch_record(KINETIC_CHECK_LENGTH + CONTACT_WATCH_LENGTH))
    call read_checkpoint(cli%restart_path, scene, mesh, state, pairs, history_width(model, pairs), mark, watch_record, err)
    if (err%failed()) call finish(err)
    call resume_outputs(out, scene, model, plan, pairs, stem, mark, err)
    if (err%failed()) call finish(err)
    call log_info('raccord', 'restart from ' // cli%restart_path // ' at step ' // str(state%step) // &
      ', t = ' // str(state%time) // ' (' // str(mark%frames_written) // ' frames, ' // str(mark%nrow) // &
      ' history rows kept)')
  end subroutine resume_run

  !> Wall-clock limit (command line, environment, then scene) and the
  !> periodic checkpoints; a fresh run removes the checkpoint of an
  !> earlier run of the same name, which its new files make useless.
  subroutine start_limits()
    if (cli%wall_clock > 0.0_wp) then
      call set_run_limits(control, cli%wall_clock, cli%wall_clock_source, scene%run%checkpoint_every)
    else
      call set_run_limits(control, scene%run%wall_clock, '&run wall_clock', scene%run%checkpoint_every)
    end if
    if (control%limit > 0.0_wp) call log_info('raccord', 'wall-clock limit ' // str(control%limit, 6) // &
      ' s (' // control%limit_source // '): a checkpoint is written and the run stops (exit 5) before it')
    if (restart) then
      continue
    else if (file_exists(checkpoint_name(stem))) then
      call log_warn('raccord', 'starting from t = 0: the checkpoint ' // checkpoint_name(stem) // &
        ' of an earlier run is deleted (raccord --restart continues a run instead)')
      call delete_file(checkpoint_name(stem))
    end if
    call note_step(control)
  end subroutine start_limits

  !> Write the checkpoint at this step boundary (outputs flushed first, so
  !> that what it records of them is on disk).
  subroutine save_checkpoint()
    type(output_mark_t) :: mark
    integer(i8) :: c0, c1, rate
    call system_clock(c0, rate)
    call mark_outputs(out, mark, err)
    if (err%failed()) call finish(err)
    call write_checkpoint(stem, scene, mesh, state, pairs, mark, &
      [kinetic_check_record(kcheck), contact_watch_record(contact_watch)], err)
    if (err%failed()) call finish(err)
    call system_clock(c1)
    call note_checkpoint(control, real(c1 - c0, wp)/real(rate, wp))
    call log_info('raccord', 'checkpoint ' // checkpoint_name(stem) // ' at step ' // str(state%step) // &
      ', t = ' // str(state%time) // ' (' // str(real(c1 - c0, wp)/real(rate, wp), 3) // ' s)')
  end subroutine save_checkpoint

  !> Stop after a checkpoint: the running files stay *.part (never
  !> complete-looking), exit 5.
  subroutine stop_at_checkpoint(reason)
    character(len=*), intent(in) :: reason
    type(error_t) :: serr
    call suspend_outputs(out, 'suspended at step ' // str(state%step) // ' (' // reason // '); continue with ' // &
      'raccord --restart ' // checkpoint_name(stem), serr)
    if (serr%failed()) call finish(serr)
    call log_info('raccord', 'stopped at step ' // str(state%step) // ' of ' // str(state%nsteps) // ', t = ' // &
      str(state%time) // ': ' // reason)
    call log_info('raccord', 'continue with: raccord --restart ' // checkpoint_name(stem))
    call drop_run_lock()
    call log_close()
    ! Exit 5 is not an error: no ERROR STOP text or backtrace on stderr.
    ! Every file is closed and the HDF5 library released by now.
    flush(output_unit)
    call c_exit(int(EXIT_WALLCLOCK, c_int))
  end subroutine stop_at_checkpoint

  !> An input file that the run would write over (the deck plate.log
  !> beside -o .: the log replaced it) is refused before anything is
  !> written: its folder is the output folder and its name is one of the
  !> run's files, <stem>.log, .lock, .h5, .xmf, .meshio.xmf, .history.txt,
  !> .scene.nml, .checkpoint.h5 or .contact<k>.txt, complete, .part or
  !> .incomplete (doc/output-format.md).
  subroutine keep_inputs(path, what)
    character(len=*), intent(in) :: path, what
    character(len=*), parameter :: outputs(8) = [character(len=13) :: 'log', 'lock', 'h5', 'xmf', &
      'meshio.xmf', 'history.txt', 'scene.nml', 'checkpoint.h5']
    character(len=:), allocatable :: base, rest
    integer :: k
    logical :: clash
    if (len_trim(path) == 0) return
    if (normal_path(path_dir(path)) /= normal_path(path_dir(stem))) return
    base = path_base(stem) // '.'
    rest = path_base(path)
    if (len(rest) <= len(base)) return
    if (rest(1:len(base)) /= base) return
    rest = rest(len(base) + 1:)
    ! the .part and .incomplete forms of a file
    if (len(rest) > 5) then
      if (rest(len(rest) - 4:) == '.part') rest = rest(1:len(rest) - 5)
    end if
    k = index(rest, 'incomplete.')
    if (k > 0) rest = rest(1:k - 1) // rest(k + 11:)
    k = index(rest, '.incomplete')
    if (k > 0) rest = rest(1:k - 1) // rest(k + 11:)
    clash = any(outputs == rest)
    if (.not. clash .and. len(rest) > 11) then
      if (rest(1:7) == 'contact' .and. rest(len(rest) - 3:) == '.txt') &
        clash = verify(rest(8:len(rest) - 4), '0123456789') == 0
    end if
    if (.not. clash) return
    call raise_error(err, EXIT_INPUT, 'the ' // what // ' ' // path // ' has the name of a file this run ' // &
      'writes into ' // path_dir(stem) // ' (' // path_base(stem) // '.*, doc/output-format.md) and would be ' // &
      'overwritten: rename it, or write the results elsewhere with -o DIR')
    call finish(err)
  end subroutine keep_inputs

  !> Create the output folder and open the log file in it (a restart
  !> appends to the log of the run it continues).
  subroutine open_run_folder()
    integer :: stat
    character(len=512) :: msg
    call make_directory(scene%run%output_dir, err)
    if (err%failed()) call finish(err)
    ! One run per output stem: a second run into the same folder and name
    ! is refused before it touches the first one's files (log included).
    call take_run_lock(stem, err)
    if (err%failed()) call finish(err)
    call log_open(stem // '.log', stat, msg, append=restart)
    if (stat /= 0) then
      call raise_error(err, EXIT_IO, 'cannot write the log file ' // stem // '.log: ' // trim(msg))
      call finish(err)
    end if
    call log_info('raccord', 'raccord ' // raccord_version_string // ', scene ' // scene%path // ', host ' // host_name())
    ! The resolved scene, every key with its final value, in the run log.
    call write_scene(scene, log_unit())
  end subroutine open_run_folder

  !> NaN/Inf guard: the energies sum over every node, so a non-finite value
  !> anywhere shows in them. Stop with the step, time and worst node.
  subroutine guard_finite()
    if (ieee_is_finite(state%energy%kinetic) .and. ieee_is_finite(state%energy%internal)) return
    call stop_non_finite('non-finite energy')
  end subroutine guard_finite

  !> Stop with exit 3: `what` at the step and time, and the first
  !> non-finite (or fastest) node.
  subroutine stop_non_finite(what)
    character(len=*), intent(in) :: what
    integer :: i, worst
    real(wp) :: vmax
    character(len=:), allocatable :: hint
    worst = 0
    vmax = -1.0_wp
    do i = 1, model%nnode
      if (.not. (ieee_is_finite(state%v(1, i)) .and. ieee_is_finite(state%v(2, i)))) then
        worst = i
        exit
      end if
      if (abs(state%v(1, i)) + abs(state%v(2, i)) > vmax) then
        vmax = abs(state%v(1, i)) + abs(state%v(2, i))
        worst = i
      end if
    end do
    ! At step 0 nothing has been integrated yet: the scene's own numbers
    ! overflow (an initial velocity of 1e300 squares to Inf), not the step.
    if (state%step == 0) then
      hint = '. The initial state already overflows, before any time step: the scene''s magnitudes ' // &
        '(&body velocity, loads, body_force, material data) are too large for double precision; check ' // &
        'their values and units.'
    else
      hint = '. The run is unstable: reduce &time safety or dt, check the material data and loads.'
    end if
    call raise_error(err, EXIT_NUMERIC, what // ' at step ' // str(state%step) // ', t = ' // &
      str(state%time) // '; first non-finite (or fastest) node: ' // str(mesh%node_id(max(1, worst))) // hint)
    call finish(err)
  end subroutine stop_non_finite

  !> raccord --verify FILE: check the file, print what was checked, exit
  !> 0 (intact) or with the error (2: damaged).
  subroutine verify_only()
    character(len=:), allocatable :: report
    call verify_file(cli%verify_path, report, err)
    if (err%failed()) call finish(err)
    write(output_unit, '(a)') report
    stop
  end subroutine verify_only

  !> Stop on an error: close any open result files as incomplete, log the
  !> message, exit with the error's code.
  subroutine finish(e)
    type(error_t), intent(in) :: e
    type(error_t) :: close_err
    character(len=:), allocatable :: message, probe
    logical :: takes_writes
    if (.not. e%failed()) return
    message = e%message
    ! A write that failed during the run: say what the file system says
    ! (a full disk) when a probe write into the output folder fails too.
    if (e%code == EXIT_IO .and. allocated(scene%run%output_dir)) then
      probe = write_failure_reason(scene%run%output_dir, takes_writes)
      if (.not. takes_writes .and. index(message, probe) == 0) message = message // ' [' // probe // ']'
    end if
    call close_outputs(out, .false., message, close_err)
    call log_error('raccord', message)
    if (e%code /= EXIT_USAGE .and. e%code /= EXIT_INPUT) &
      call log_error('raccord', 'run stopped; result files (if any) are marked incomplete')
    if (close_err%failed()) call log_error('raccord', close_err%message)
    call drop_run_lock()
    call log_close()
    ! A result file that could not be closed (full disk) is still in the
    ! HDF5 library's list of open files, and the library's exit-time cleanup
    ! crashes on it (SIGSEGV instead of our exit code). Our own files are
    ! flushed and closed by now, so leave without that cleanup.
    if (close_err%failed() .or. e%code == EXIT_IO) then
      flush(output_unit)
      call c_exit(int(e%code, c_int))
    end if
    ! The message above is the whole report: exit with the error's code
    ! (doc/user-guide.md, exit codes) and no runtime text after it.
    flush(output_unit)
    select case (e%code)
    case (EXIT_USAGE, EXIT_INPUT, EXIT_NUMERIC, EXIT_IO, EXIT_WALLCLOCK)
      call c_exit_clean(int(e%code, c_int))
    case (EXIT_OK)
      stop
    case default
      call c_exit_clean(int(EXIT_INTERNAL, c_int))
    end select
  end subroutine finish
end program raccord_main
