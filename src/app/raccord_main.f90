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
  use raccord_kinds, only: wp
  use raccord_error, only: error_t, raise_error, EXIT_OK, EXIT_USAGE, EXIT_INPUT, EXIT_NUMERIC, EXIT_IO, &
    EXIT_WALLCLOCK
  use raccord_log, only: log_open, log_close, log_info, log_error, log_raw, log_set_quiet, log_set_level, &
    LEVEL_DEBUG, log_unit
  use raccord_strings, only: str
  use raccord_version, only: raccord_version_string
  use raccord_cli, only: cli_t, parse_command_line, usage_text
  use raccord_scene, only: scene_t
  use raccord_deck, only: read_scene, write_scene
  use raccord_mesh, only: mesh_t
  use raccord_mesh_io, only: read_mesh
  use raccord_model, only: model_t
  use raccord_model_build, only: build_model
  use raccord_time_step, only: time_plan_t, choose_time_step
  use raccord_state, only: state_t, init_state
  use raccord_central_difference, only: compute_forces, predict_motion, update_energy, advance_state
  use raccord_contact_pair, only: contact_pair_t, init_contact_pairs, enforce_contact
  use raccord_run_report, only: report_plan, report_summary, run_stem
  use raccord_output, only: output_t, open_outputs, write_due_outputs, close_outputs
  use raccord_files, only: make_directory
  implicit none

  type(cli_t) :: cli
  type(scene_t) :: scene
  type(mesh_t) :: mesh
  type(model_t) :: model
  type(time_plan_t) :: plan
  type(state_t) :: state
  type(output_t) :: out
  type(contact_pair_t), allocatable :: pairs(:)
  type(error_t) :: err
  character(len=:), allocatable :: stem

  ! Phase 0: what the user asked for.
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
  if (cli%quiet) call log_set_quiet(.true.)
  if (cli%verbose) call log_set_level(LEVEL_DEBUG)

  ! Phase 1: the scene deck, and the run's folder and log.
  call read_scene(cli%scene_path, scene, err)
  if (err%failed()) call finish(err)
  if (allocated(cli%output_dir)) scene%run%output_dir = cli%output_dir
  stem = run_stem(scene)
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

  ! Phase 5: march in time.
  call init_state(model, plan%dt, plan%nsteps, state)
  call open_outputs(out, scene, model, plan, pairs, stem, err)
  if (err%failed()) call finish(err)
  if (model%has_body_force) state%f_ext = model%f_body

  time_steps: do
    call compute_forces(model, state)        ! f_int(u(n)), f_ext(t(n))
    call predict_motion(model, state)        ! (CD-1), (CD-2): v(n+1/2), u*(n+1); reactions
    ! Forward increment: the multipliers lambda(n) make the contact and
    ! friction conditions (paper eq. 19) hold at t(n+1); u(n+1) and v(n+1/2)
    ! are corrected. A scene without contact pairs skips it.
    if (size(pairs) > 0) call enforce_contact(pairs, model, state, err)
    if (err%failed()) call finish(err)
    call update_energy(model, state)         ! energy account at t(n)
    call guard_finite()
    call write_due_outputs(out, model, state, pairs, err)
    if (err%failed()) call finish(err)
    if (state%step == state%nsteps) exit time_steps
    call advance_state(state)                ! n <- n+1
  end do time_steps

  ! Phase 6: close the results under their final names.
  call close_outputs(out, .true., '', err)
  if (err%failed()) call finish(err)
  call report_summary(model, state, out, pairs)
  call log_close()

contains

  !> Create the output folder and open the log file in it.
  subroutine open_run_folder()
    integer :: stat
    character(len=512) :: msg
    call make_directory(scene%run%output_dir, err)
    if (err%failed()) call finish(err)
    call log_open(stem // '.log', stat, msg)
    if (stat /= 0) then
      call raise_error(err, EXIT_IO, 'cannot write the log file ' // stem // '.log: ' // trim(msg))
      call finish(err)
    end if
    call log_info('raccord', 'raccord ' // raccord_version_string // ', scene ' // scene%path)
    ! The resolved scene, every key with its final value, in the run log.
    call write_scene(scene, log_unit())
  end subroutine open_run_folder

  !> NaN/Inf guard: the energies sum over every node, so a non-finite value
  !> anywhere shows in them. Stop with the step, time and worst node.
  subroutine guard_finite()
    integer :: i, worst
    real(wp) :: vmax
    if (ieee_is_finite(state%energy%kinetic) .and. ieee_is_finite(state%energy%internal)) return
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
    call raise_error(err, EXIT_NUMERIC, 'non-finite energy at step ' // str(state%step) // ', t = ' // &
      str(state%time) // '; first non-finite (or fastest) node: ' // str(mesh%node_id(max(1, worst))) // &
      '. The run is unstable: reduce &time safety or dt, check the material data and loads.')
    call finish(err)
  end subroutine guard_finite

  !> Stop on an error: close any open result files as incomplete, log the
  !> message, exit with the error's code.
  subroutine finish(e)
    type(error_t), intent(in) :: e
    type(error_t) :: close_err
    interface
      ! POSIX _exit: leave without running atexit handlers.
      subroutine c_exit(status) bind(C, name='_exit')
        import :: c_int
        integer(c_int), value :: status
      end subroutine c_exit
    end interface
    if (.not. e%failed()) return
    call close_outputs(out, .false., e%message, close_err)
    call log_error('raccord', e%message)
    if (e%code /= EXIT_USAGE .and. e%code /= EXIT_INPUT) &
      call log_error('raccord', 'run stopped; result files (if any) are marked incomplete')
    if (close_err%failed()) call log_error('raccord', close_err%message)
    call log_close()
    ! A result file that could not be closed (full disk) is still in the
    ! HDF5 library's list of open files, and the library's exit-time cleanup
    ! crashes on it (SIGSEGV instead of our exit code). Our own files are
    ! flushed and closed by now, so leave without that cleanup.
    if (close_err%failed() .or. e%code == EXIT_IO) then
      flush(output_unit)
      call c_exit(int(e%code, c_int))
    end if
    select case (e%code)
    case (EXIT_USAGE);     error stop 1
    case (EXIT_INPUT);     error stop 2
    case (EXIT_NUMERIC);   error stop 3
    case (EXIT_IO);        error stop 4
    case (EXIT_WALLCLOCK); error stop 5
    case (EXIT_OK);        stop
    case default;          error stop 70
    end select
  end subroutine finish
end program raccord_main
