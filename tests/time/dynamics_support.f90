!> Helpers for the dynamics suites: a scene built in code, and the step
!> sequence of the main program (raccord_main's time loop) as a routine.
module dynamics_support
  use raccord_kinds, only: wp, i8
  use raccord_error, only: error_t
  use raccord_scene, only: scene_t, bc_spec_t, body_spec_t, amplitude_spec_t, contact_spec_t
  use raccord_model, only: model_t
  use raccord_state, only: state_t
  use raccord_central_difference, only: compute_forces, predict_motion, update_energy, advance_state
  use raccord_contact_pair, only: contact_pair_t, enforce_contact, init_contact_pairs
  use raccord_mesh, only: mesh_t
  use raccord_model_build, only: build_model
  use raccord_time_step, only: time_plan_t, choose_time_step
  use raccord_state, only: init_state
  use raccord_test_meshes, only: join_meshes
  implicit none
  private

  public :: one_body_scene, add_bc, add_amplitude, add_body, add_pair, start_march, march_to, march_steps
  public :: contact_step, two_body_scene, prepare_contact

contains

  !> A scene with one body on element set 'body' and no conditions yet.
  subroutine one_body_scene(scene, young, poisson, density, plane_stress, t_end)
    type(scene_t), intent(out) :: scene
    real(wp), intent(in) :: young, poisson, density, t_end
    logical, intent(in) :: plane_stress
    scene%path = 'in-memory scene'
    scene%dir = '.'
    scene%run%title = 'test'
    scene%run%output_dir = '.'
    allocate(scene%bodies(1))
    scene%bodies(1)%name = 'body'
    scene%bodies(1)%elset = 'body'
    scene%bodies(1)%young = young
    scene%bodies(1)%poisson = poisson
    scene%bodies(1)%density = density
    scene%bodies(1)%plane_stress = plane_stress
    allocate(scene%bcs(0), scene%amplitudes(0), scene%contacts(0))
    scene%time%t_end = t_end
  end subroutine one_body_scene

  !> Append a boundary condition.
  subroutine add_bc(scene, set, kind, comp, pressure, value, amplitude)
    type(scene_t), intent(inout) :: scene
    character(len=*), intent(in) :: set
    integer, intent(in) :: kind
    logical, intent(in), optional :: comp(2)
    real(wp), intent(in), optional :: pressure, value(2)
    character(len=*), intent(in), optional :: amplitude
    type(bc_spec_t) :: bc
    bc%set = set
    bc%kind = kind
    bc%amplitude = ''
    if (present(comp)) bc%comp = comp
    if (present(pressure)) bc%pressure = pressure
    if (present(value)) bc%value = value
    if (present(amplitude)) bc%amplitude = amplitude
    scene%bcs = [scene%bcs, bc]
  end subroutine add_bc

  !> Append a piecewise-linear amplitude table.
  subroutine add_amplitude(scene, name, t, a)
    type(scene_t), intent(inout) :: scene
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: t(:), a(:)
    type(amplitude_spec_t) :: amp
    amp%name = name
    amp%npoint = size(t)
    amp%t = t
    amp%a = a
    scene%amplitudes = [scene%amplitudes, amp]
  end subroutine add_amplitude

  !> Append a body on element set `elset`.
  subroutine add_body(scene, name, elset, young, poisson, density, plane_stress, velocity)
    type(scene_t), intent(inout) :: scene
    character(len=*), intent(in) :: name, elset
    real(wp), intent(in) :: young, poisson, density
    logical, intent(in) :: plane_stress
    real(wp), intent(in), optional :: velocity(2)
    type(body_spec_t) :: b
    b%name = name
    b%elset = elset
    b%young = young
    b%poisson = poisson
    b%density = density
    b%plane_stress = plane_stress
    if (present(velocity)) b%velocity = velocity
    scene%bodies = [scene%bodies, b]
  end subroutine add_body

  !> Append a contact pair.
  subroutine add_pair(scene, slave, master, method, friction)
    type(scene_t), intent(inout) :: scene
    character(len=*), intent(in) :: slave, master
    integer, intent(in) :: method
    real(wp), intent(in) :: friction
    type(contact_spec_t) :: c
    c%slave = slave
    c%master = master
    c%method = method
    c%friction = friction
    scene%contacts = [scene%contacts, c]
  end subroutine add_pair

  !> One step of the explicit scheme, as in the main program.
  subroutine one_step(model, state)
    type(model_t), intent(in) :: model
    type(state_t), intent(inout) :: state
    call compute_forces(model, state)
    call predict_motion(model, state)
    call update_energy(model, state)
  end subroutine one_step

  !> Scene of two bodies 'a' and 'b' (element sets 'a_body', 'b_body') from
  !> meshes ma and mb joined (their sets prefixed 'a_' and 'b_').
  subroutine two_body_scene(ma, mb, mesh, scene, young, nu, rho, plane_stress, t_end)
    type(mesh_t), intent(in) :: ma, mb
    type(mesh_t), intent(out) :: mesh
    type(scene_t), intent(out) :: scene
    real(wp), intent(in) :: young, nu, rho, t_end
    logical, intent(in) :: plane_stress
    call join_meshes(ma, 'a', mb, 'b', mesh)
    call one_body_scene(scene, young, nu, rho, plane_stress, t_end)
    scene%bodies(1)%name = 'a'
    scene%bodies(1)%elset = 'a_body'
    call add_body(scene, 'b', 'b_body', young, nu, rho, plane_stress)
  end subroutine two_body_scene

  !> Model, contact pairs, time plan and initial state of an in-memory scene.
  subroutine prepare_contact(scene, mesh, model, pairs, plan, state, err)
    type(scene_t), intent(inout) :: scene
    type(mesh_t), intent(in) :: mesh
    type(model_t), intent(out) :: model
    type(contact_pair_t), allocatable, intent(out) :: pairs(:)
    type(time_plan_t), intent(out) :: plan
    type(state_t), intent(out) :: state
    type(error_t), intent(inout) :: err
    call build_model(scene, mesh, model, err)
    if (.not. err%failed()) call init_contact_pairs(scene, mesh, model, pairs, err)
    if (.not. err%failed()) call choose_time_step(scene, model, plan, err)
    if (.not. err%failed()) call init_state(model, plan%dt, plan%nsteps, state)
  end subroutine prepare_contact

  !> One step with contact at t(n), as in the main program (the caller
  !> advances the state to n+1 between calls).
  subroutine contact_step(model, pairs, state, err)
    type(model_t), intent(in) :: model
    type(contact_pair_t), intent(inout) :: pairs(:)
    type(state_t), intent(inout) :: state
    type(error_t), intent(inout) :: err
    call compute_forces(model, state)
    call predict_motion(model, state)
    call enforce_contact(pairs, model, state, err)
    call update_energy(model, state)
  end subroutine contact_step

  !> Step 0: forces, predictor and energies at t = 0.
  subroutine start_march(model, state)
    type(model_t), intent(in) :: model
    type(state_t), intent(inout) :: state
    call one_step(model, state)
  end subroutine start_march

  !> March until t(n) is the step time nearest to `time` (forces, energies
  !> and reactions are those at t(n) on return).
  subroutine march_to(model, state, time)
    type(model_t), intent(in) :: model
    type(state_t), intent(inout) :: state
    real(wp), intent(in) :: time
    do while (state%time + 0.5_wp*state%dt < time)
      call advance_state(state)
      call one_step(model, state)
    end do
  end subroutine march_to

  !> March n steps, recording the relative energy balance at each.
  subroutine march_steps(model, state, n, balance)
    type(model_t), intent(in) :: model
    type(state_t), intent(inout) :: state
    integer, intent(in) :: n
    real(wp), intent(out) :: balance(:)
    integer :: k
    do k = 1, n
      call advance_state(state)
      call one_step(model, state)
      balance(k) = state%energy%balance/max(state%energy%scale, tiny(1.0_wp))
    end do
  end subroutine march_steps
end module dynamics_support
