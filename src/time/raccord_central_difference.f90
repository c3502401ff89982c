!> Explicit central-difference integration with lumped mass (method brief,
!> section 2):
!>
!>   v(n+1/2) = v(n-1/2) + dt M^-1 (f_ext(n) - f_int(u(n)) - C v(n))          (CD-1)
!>   u(n+1)   = u(n) + dt v(n+1/2)                                             (CD-2)
!>
!> with C = alpha M (alpha per body, so per node) and v(n) = (v(n-1/2) +
!> v(n+1/2))/2, which makes the damping term semi-implicit and keeps it
!> unconditionally stable:
!>   v(n+1/2) = [(1 - alpha dt/2) v(n-1/2) + dt M^-1 (f_ext - f_int)] / (1 + alpha dt/2).
!> The first step starts from v(0) with a half step (dt/2).
!>
!> Contact (forward-increment Lagrange multipliers) enters between the
!> predictor (CD-1, CD-2 without contact forces) and `advance_state`, by
!> correcting u_next and v (method brief, section 3).
module raccord_central_difference
  use raccord_kinds, only: wp, i8
  use raccord_model, only: model_t, amplitude_at
  use raccord_state, only: state_t
  use raccord_elastic_block, only: add_internal_force
  implicit none
  private

  public :: compute_forces, predict_motion, update_energy, advance_state

contains

  !> Internal force K u(n) over every block, applied force at t(n).
  subroutine compute_forces(model, state)
    type(model_t), intent(in) :: model
    type(state_t), intent(inout) :: state
    integer :: ib, k, l

    state%f_int = 0.0_wp
    do ib = 1, size(model%bodies)
      do k = 1, size(model%bodies(ib)%blocks)
        call add_internal_force(model%bodies(ib)%blocks(k), state%u, state%f_int)
      end do
    end do

    ! f_ext holds the constant body force (set once in `prepare`); surface
    ! loads are reset and re-added at their nodes only.
    if (model%has_loads) then
      do l = 1, size(model%loads)
        associate (ld => model%loads(l))
          if (model%has_body_force) then
            state%f_ext(:, ld%nodes) = model%f_body(:, ld%nodes)
          else
            state%f_ext(:, ld%nodes) = 0.0_wp
          end if
        end associate
      end do
      do l = 1, size(model%loads)
        associate (ld => model%loads(l))
          state%load_amp(l) = amplitude_at(model, ld%amplitude, state%time)
          state%f_ext(:, ld%nodes) = state%f_ext(:, ld%nodes) + state%load_amp(l)*ld%force
        end associate
      end do
    end if
  end subroutine compute_forces

  !> Predictor (CD-1, CD-2) for free degrees of freedom, prescribed motion
  !> and reactions on the constrained ones, kinetic and internal energy at
  !> t(n) and the damping dissipation of the step, all in one pass.
  subroutine predict_motion(model, state)
    type(model_t), intent(in) :: model
    type(state_t), intent(inout) :: state
    real(wp) :: h, c, dt, ke, ie, kh, cross, vold(2), vnew(2), vm(2), tnext, target, vfree, vc, vm_c, m
    integer :: i, j, comp, s
    logical :: first

    dt = state%dt
    first = state%step == 0
    h = dt
    if (first) h = 0.5_wp*dt
    ke = 0.0_wp
    ie = 0.0_wp
    kh = 0.0_wp
    cross = 0.0_wp

    ! Remember the old velocity of constrained dofs for their reactions.
    do j = 1, model%ncdof
      state%cdof_vold(j) = state%v(model%cdof_comp(j), model%cdof_node(j))
    end do

    do i = 1, model%nnode
      vold = state%v(:, i)
      if (model%has_damping) then
        c = 0.5_wp*model%alpha(i)*h
        vnew = ((1.0_wp - c)*vold + h*model%minv(i)*(state%f_ext(:, i) - state%f_int(:, i)))/(1.0_wp + c)
      else
        vnew = vold + h*model%minv(i)*(state%f_ext(:, i) - state%f_int(:, i))
      end if
      if (first) then
        vm = vold
      else
        vm = 0.5_wp*(vold + vnew)
      end if
      state%v(:, i) = vnew
      state%v_mid(:, i) = vm
      state%u_next(:, i) = state%u(:, i) + dt*vnew
      ke = ke + model%mass(i)*(vm(1)**2 + vm(2)**2)
      ie = ie + state%u(1, i)*state%f_int(1, i) + state%u(2, i)*state%f_int(2, i)
      kh = kh + model%mass(i)*(vnew(1)**2 + vnew(2)**2)
      cross = cross + state%u_next(1, i)*state%f_int(1, i) + state%u_next(2, i)*state%f_int(2, i)
    end do

    ! Constrained dofs: velocity that lands exactly on the prescribed value
    ! at t(n+1); the reaction is the force that turns the free velocity into
    ! it: vc = vfree + h M^-1 r / (1 + c).
    ! The amplitude of each support at t(n+1), once per support.
    tnext = state%time + dt
    do s = 1, size(model%supports)
      state%support_amp(s) = 0.0_wp
      if (model%supports(s)%driven) state%support_amp(s) = amplitude_at(model, model%supports(s)%amplitude, tnext)
    end do
    do j = 1, model%ncdof
      i = model%cdof_node(j)
      comp = model%cdof_comp(j)
      s = model%cdof_support(j)
      target = model%supports(s)%value(comp)*state%support_amp(s)
      vfree = state%v(comp, i)
      vc = (target - state%u(comp, i))/dt
      m = model%mass(i)
      c = 0.5_wp*model%alpha(i)*h
      if (first) then
        vm_c = state%cdof_vold(j)
      else
        vm_c = 0.5_wp*(state%cdof_vold(j) + vc)
      end if
      ke = ke + m*(vm_c**2 - state%v_mid(comp, i)**2)
      kh = kh + m*(vc**2 - vfree**2)
      cross = cross + (target - state%u_next(comp, i))*state%f_int(comp, i)
      state%reaction(j) = m*(1.0_wp + c)*(vc - vfree)/h
      state%v(comp, i) = vc
      state%v_mid(comp, i) = vm_c
      state%u_next(comp, i) = target
    end do

    state%energy%kinetic = 0.5_wp*ke
    state%energy%internal = 0.5_wp*ie
    ! (E-1); a contact correction of u(n+1) and v(n+1/2) must update it at
    ! the nodes it moves.
    state%energy%discrete = 0.5_wp*(kh + cross)
    if (model%has_damping) then
      ! Dissipation of the semi-implicit damping term over the step:
      ! alpha h v' M v with v the mean of the two half-step velocities
      ! (on the first half step, of v(0) and v(1/2)).
      ke = 0.0_wp
      if (first) then
        do i = 1, model%nnode
          ke = ke + model%alpha(i)*model%mass(i)*(0.25_wp*sum((model%v0(:, i) + state%v(:, i))**2))
        end do
      else
        do i = 1, model%nnode
          ke = ke + model%alpha(i)*model%mass(i)*(state%v_mid(1, i)**2 + state%v_mid(2, i)**2)
        end do
      end if
      state%energy%damping = state%energy%damping + h*ke
    end if
  end subroutine predict_motion

  !> External work (E-2) of the forces at t(n) on the loaded and constrained
  !> dofs only, and the energy balance. The first step is a half step from
  !> v(0): there the work is (dt/4) f(0)' (v(0) + v(1/2)).
  subroutine update_energy(model, state)
    type(model_t), intent(in) :: model
    type(state_t), intent(inout) :: state
    real(wp) :: w, wl
    integer :: j, i, comp, l, k, n

    w = 0.0_wp
    do j = 1, model%ncdof
      i = model%cdof_node(j)
      comp = model%cdof_comp(j)
      w = w + state%reaction(j)*increment(state, model, comp, i)
    end do
    do l = 1, size(model%loads)
      wl = 0.0_wp
      do k = 1, size(model%loads(l)%nodes)
        n = model%loads(l)%nodes(k)
        wl = wl + model%loads(l)%force(1, k)*increment(state, model, 1, n) + &
          model%loads(l)%force(2, k)*increment(state, model, 2, n)
      end do
      w = w + state%load_amp(l)*wl
    end do
    if (model%has_body_force) then
      do n = 1, model%nnode
        w = w + model%f_body(1, n)*increment(state, model, 1, n) + model%f_body(2, n)*increment(state, model, 2, n)
      end do
    end if
    associate (e => state%energy)
      e%external = e%external + w
      if (state%step == 0) e%initial = e%kinetic
      e%balance = e%discrete + e%damping + e%contact - e%external - e%initial
      ! Every term of the balance sets the scale, so that a step-0 contact
      ! correction on bodies at rest has a scale to be relative to.
      e%scale = max(e%scale, abs(e%kinetic), abs(e%internal), abs(e%external), abs(e%initial), &
        abs(e%discrete), abs(e%contact), abs(e%damping))
    end associate
  end subroutine update_energy

  !> Displacement increment that multiplies a force at t(n) in (E-2):
  !> (u(n+1) - u(n-1))/2, or (dt/4)(v(0) + v(1/2)) on the first half step.
  pure real(wp) function increment(state, model, comp, i) result(du)
    type(state_t), intent(in) :: state
    type(model_t), intent(in) :: model
    integer, intent(in) :: comp, i
    if (state%step == 0) then
      du = 0.25_wp*state%dt*(model%v0(comp, i) + state%v(comp, i))
    else
      du = 0.5_wp*(state%u_next(comp, i) - state%u_prev(comp, i))
    end if
  end function increment

  !> Step n -> n+1: rotate the displacement buffers (no copy, no allocation).
  subroutine advance_state(state)
    type(state_t), intent(inout) :: state
    real(wp), allocatable :: spare(:,:)
    call move_alloc(state%u_prev, spare)
    call move_alloc(state%u, state%u_prev)
    call move_alloc(state%u_next, state%u)
    call move_alloc(spare, state%u_next)
    state%step = state%step + 1_i8
    state%time = real(state%step, wp)*state%dt
  end subroutine advance_state
end module raccord_central_difference
