!> The evolving state of an explicit run and its energy account.
module raccord_state
  use raccord_kinds, only: wp, i8
  use raccord_model, only: model_t
  use raccord_elastic_block, only: block_watch_t, init_watch, block_plastic_t, init_plastic, reports_energy
  use raccord_material, only: MAT_J2
  implicit none
  private

  !> Energy account (method brief section 2, doc/theory.md "Energy").
  !>
  !> kinetic and internal are the energies at t(n) a user expects. The
  !> balance is kept on the energy that central difference conserves
  !> exactly for a linear undamped system,
  !>   H(n+1/2) = 1/2 v(n+1/2)' M v(n+1/2) + 1/2 u(n)' K u(n+1),        (E-1)
  !> whose change over a step is the centred work of the forces at t(n),
  !>   W += f(n)' (u(n+1) - u(n-1)) / 2,                                (E-2)
  !> minus the damping dissipation dt alpha v(n)' M v(n). So the balance
  !> H + damping + contact - external - initial is zero to round-off in
  !> linear elasticity, and any drift is a real error, not a definition.
  type, public :: energy_t
    real(wp) :: kinetic = 0.0_wp          !< 1/2 v(n)' M v(n), v(n) = (v(n-1/2) + v(n+1/2))/2
    real(wp) :: internal = 0.0_wp         !< 1/2 u(n)' K u(n)
    real(wp) :: discrete = 0.0_wp         !< H(n+1/2) of (E-1)
    real(wp) :: external = 0.0_wp         !< work of loads, body forces and support reactions (E-2)
    real(wp) :: damping = 0.0_wp          !< dissipated by mass-proportional damping
    real(wp) :: contact = 0.0_wp          !< work done against contact forces (normal + friction)
    real(wp) :: friction = 0.0_wp         !< of which dissipated by friction
    real(wp) :: plastic = 0.0_wp          !< plastic work of the j2 bodies (dissipated + stored by hardening)
    real(wp) :: initial = 0.0_wp          !< kinetic energy at t = 0 (u(0) = 0)
    real(wp) :: balance = 0.0_wp          !< discrete + damping + contact + plastic - external - initial
    real(wp) :: scale = 0.0_wp            !< largest energy magnitude seen (for the relative error)
  end type energy_t

  !> State at step n: u(n), v(n+1/2) after the predictor, forces at t(n).
  !> The nodal forces of one surface load (2, size of its nodes).
  type, public :: load_force_t
    real(wp), allocatable :: f(:,:)
  end type load_force_t

  type, public :: state_t
    integer(i8) :: step = 0
    integer(i8) :: nsteps = 0
    real(wp) :: time = 0.0_wp
    real(wp) :: dt = 0.0_wp                 !< dt(n+1/2), the step from t(n) to t(n+1)
    !> Variable step (finite-strain bodies, raccord_time_step): dt(n-1/2),
    !> the plan's step (the largest allowed), t_end and the safety factor.
    logical :: adaptive = .false.
    real(wp) :: dt_prev = 0.0_wp, dt_plan = 0.0_wp, t_end = 0.0_wp, safety = 0.0_wp
    real(wp), allocatable :: u(:,:)         !< u(n)
    real(wp), allocatable :: u_next(:,:)    !< u(n+1), predicted then corrected by contact
    real(wp), allocatable :: u_prev(:,:)    !< u(n-1), for the work increments
    real(wp), allocatable :: v(:,:)         !< v(n-1/2) before, v(n+1/2) after the predictor
    real(wp), allocatable :: v_mid(:,:)     !< v(n) = mean of the two half-step velocities
    real(wp), allocatable :: f_int(:,:)     !< internal force K u(n)
    real(wp), allocatable :: f_ext(:,:)     !< applied force at t(n) (loads and body force)
    real(wp), allocatable :: reaction(:)    !< reaction at each constrained dof at t(n)
    real(wp), allocatable :: cdof_vold(:)   !< v(n-1/2) of each constrained dof (predictor scratch)
    real(wp), allocatable :: load_amp(:)    !< amplitude of each surface load at t(n)
    !> nodal forces of each surface load at amplitude 1 at t(n): the
    !> model's for a fixed load, recomputed on the deformed surface every
    !> step for a pressure on finite-strain bodies (follower_load_force)
    type(load_force_t), allocatable :: load_force(:)
    real(wp), allocatable :: support_amp(:) !< amplitude of each driven support at t(n+1) (0 if fixed)
    type(energy_t) :: energy
    !> (block, body): what each finite-strain block reported at the last
    !> forces (stored energy, smallest J, omega^2 estimate); unallocated
    !> arrays for small-strain blocks
    type(block_watch_t), allocatable :: watch(:,:)
    !> (block, body): the internal variables of each j2 block (unallocated
    !> arrays for the other blocks)
    type(block_plastic_t), allocatable :: plastic(:,:)
  end type state_t

  public :: init_state

contains

  !> Zero displacements, initial velocities, step 0.
  subroutine init_state(model, dt, nsteps, state)
    type(model_t), intent(in) :: model
    real(wp), intent(in) :: dt
    integer(i8), intent(in) :: nsteps
    type(state_t), intent(out) :: state
    integer :: n, ib, k
    n = model%nnode
    state%dt = dt
    state%nsteps = nsteps
    allocate(state%u(2, n), state%u_next(2, n), state%u_prev(2, n), source=0.0_wp)
    allocate(state%f_int(2, n), state%f_ext(2, n), source=0.0_wp)
    state%v = model%v0
    state%v_mid = model%v0
    allocate(state%reaction(model%ncdof), state%cdof_vold(model%ncdof), source=0.0_wp)
    allocate(state%load_amp(size(model%loads)), source=0.0_wp)
    allocate(state%load_force(size(model%loads)))
    do k = 1, size(model%loads)
      state%load_force(k)%f = model%loads(k)%force
    end do
    allocate(state%support_amp(size(model%supports)), source=0.0_wp)
    state%dt_prev = dt
    state%dt_plan = dt
    state%t_end = real(nsteps, wp)*dt
    state%adaptive = model%has_finite
    allocate(state%watch(2, size(model%bodies)), state%plastic(2, size(model%bodies)))
    do ib = 1, size(model%bodies)
      do k = 1, size(model%bodies(ib)%blocks)
        if (reports_energy(model%bodies(ib)%blocks(k))) &
          call init_watch(model%bodies(ib)%blocks(k), state%watch(k, ib))
        if (model%bodies(ib)%blocks(k)%material == MAT_J2) &
          call init_plastic(model%bodies(ib)%blocks(k), state%plastic(k, ib))
      end do
    end do
  end subroutine init_state
end module raccord_state
