!> Run a scene deck in-process for tests, with the phases and the step loop
!> of the main program (raccord_main) but no result files, so a test can
!> look at the model, the contact pairs and the state at the end.
module raccord_scene_runner
  use raccord_kinds, only: wp
  use raccord_error, only: error_t
  use raccord_scene, only: scene_t, METHOD_MORTAR
  use raccord_deck, only: read_scene
  use raccord_mesh, only: mesh_t
  use raccord_mesh_io, only: read_mesh
  use raccord_model, only: model_t
  use raccord_model_build, only: build_model
  use raccord_time_step, only: time_plan_t, choose_time_step, adapt_time_step, check_deformation
  use raccord_state, only: state_t, init_state
  use raccord_central_difference, only: compute_forces, predict_motion, update_energy, advance_state
  use raccord_contact_pair, only: contact_pair_t, init_contact_pairs, enforce_contact
  implicit none
  private

  !> Everything a finished run leaves.
  type, public :: scene_run_t
    type(scene_t) :: scene
    type(mesh_t) :: mesh
    type(model_t) :: model
    type(contact_pair_t), allocatable :: pairs(:)
    type(time_plan_t) :: plan
    type(state_t) :: state
    real(wp) :: worst_balance = 0.0_wp     !< largest |energy balance| / scale over the run
    real(wp) :: max_internal = 0.0_wp      !< largest internal energy over the run
    real(wp) :: min_contact_work = 0.0_wp  !< lowest contact work over the run (< 0: contact gave energy)
  end type scene_run_t

  public :: run_deck, prepare_deck, step_predict, step_finish

contains

  !> Run the deck at `path` (relative paths against RACCORD_SOURCE_DIR when
  !> set, except ./... paths, which stay relative to the working folder) to
  !> its end, or to t_stop when given. undamped_body names a body whose
  !> damping is set to 0 (a test's counter-case of a deck as shipped);
  !> multiplier (MULT_*) replaces the multiplier space of every mortar pair,
  !> weighted its conditions (.true.: 'weighted'; a test's variant of a
  !> shipped deck).
  subroutine run_deck(path, run, err, t_stop, undamped_body, multiplier, weighted)
    character(len=*), intent(in) :: path
    type(scene_run_t), intent(out) :: run
    type(error_t), intent(inout) :: err
    real(wp), intent(in), optional :: t_stop
    character(len=*), intent(in), optional :: undamped_body
    integer, intent(in), optional :: multiplier
    logical, intent(in), optional :: weighted
    call prepare_deck(path, run, err, undamped_body, multiplier, weighted)
    if (err%failed()) return
    do
      call step_predict(run, err)
      if (err%failed()) return
      call step_finish(run, err)
      if (err%failed()) return
      if (run%state%step == run%state%nsteps) exit
      if (present(t_stop)) then
        if (run%state%time >= t_stop - 0.5_wp*run%state%dt) exit
      end if
      call advance_state(run%state)
    end do
  end subroutine run_deck

  !> The phases of the program before its time loop: the scene, the mesh,
  !> the model, the contact pairs, the time plan and the state at t = 0.
  subroutine prepare_deck(path, run, err, undamped_body, multiplier, weighted)
    character(len=*), intent(in) :: path
    type(scene_run_t), intent(out) :: run
    type(error_t), intent(inout) :: err
    character(len=*), intent(in), optional :: undamped_body
    integer, intent(in), optional :: multiplier
    logical, intent(in), optional :: weighted
    character(len=512) :: root
    character(len=:), allocatable :: full
    integer :: length, stat, b
    call get_environment_variable('RACCORD_SOURCE_DIR', root, length, stat)
    full = path
    if (stat == 0 .and. path(1:1) /= '/' .and. index(path, './') /= 1) full = trim(root) // '/' // path
    call read_scene(full, run%scene, err)
    if (err%failed()) return
    if (present(undamped_body)) then
      do b = 1, size(run%scene%bodies)
        if (run%scene%bodies(b)%name == undamped_body) run%scene%bodies(b)%damping = 0.0_wp
      end do
    end if
    if (present(multiplier) .and. allocated(run%scene%contacts)) then
      do b = 1, size(run%scene%contacts)
        if (run%scene%contacts(b)%method == METHOD_MORTAR) run%scene%contacts(b)%multiplier = multiplier
      end do
    end if
    if (present(weighted) .and. allocated(run%scene%contacts)) then
      do b = 1, size(run%scene%contacts)
        if (run%scene%contacts(b)%method == METHOD_MORTAR) run%scene%contacts(b)%weighted = weighted
      end do
    end if
    call read_mesh(run%scene%mesh%file, run%mesh, err, run%scene%mesh%format, run%scene%mesh%scale)
    if (err%failed()) return
    call build_model(run%scene, run%mesh, run%model, err)
    if (err%failed()) return
    call init_contact_pairs(run%scene, run%mesh, run%model, run%pairs, err)
    if (err%failed()) return
    call choose_time_step(run%scene, run%model, run%plan, err)
    if (err%failed()) return
    call init_state(run%model, run%plan%dt, run%plan%nsteps, run%state)
    run%state%t_end = run%plan%t_end
    run%state%safety = run%scene%time%safety
    if (run%model%has_body_force) run%state%f_ext = run%model%f_body
  end subroutine prepare_deck

  !> First half of the program's step n: forces at t(n), with finite-strain
  !> bodies the inversion check and the step that follows the mesh, and the
  !> predictor. A test may change the predicted motion before step_finish.
  subroutine step_predict(run, err)
    type(scene_run_t), intent(inout) :: run
    type(error_t), intent(inout) :: err
    call compute_forces(run%model, run%state)
    if (run%model%has_finite) then
      call check_deformation(run%model, run%state, err)
      if (err%failed()) return
      call adapt_time_step(run%model, run%state, err)
      if (err%failed()) return
    end if
    call predict_motion(run%model, run%state)
  end subroutine step_predict

  !> Second half of step n: the contact correction, the energy account and
  !> the run's worst balance, largest internal energy and least contact work.
  subroutine step_finish(run, err)
    type(scene_run_t), intent(inout) :: run
    type(error_t), intent(inout) :: err
    associate (state => run%state)
      if (size(run%pairs) > 0) call enforce_contact(run%pairs, run%model, state, err)
      if (err%failed()) return
      call update_energy(run%model, state)
      ! Relative to the energies of the run; a step where all are zero has
      ! nothing to be relative to (its balance is then zero too).
      if (state%energy%scale > 0.0_wp) &
        run%worst_balance = max(run%worst_balance, abs(state%energy%balance)/state%energy%scale)
      run%max_internal = max(run%max_internal, state%energy%internal)
      run%min_contact_work = min(run%min_contact_work, state%energy%contact)
    end associate
  end subroutine step_finish
end module raccord_scene_runner
