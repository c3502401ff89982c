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
!>
!> Threading (OpenMP, doc/performance.md "Threading"): the per-node loops
!> run over nseg fixed node segments shared among model%nthreads threads;
!> each energy sum is formed per segment and the nseg partial sums are
!> added in segment order. The segments depend on the node count only, so
!> the energies, like the forces (raccord_elastic_block), are bitwise the
!> same for any thread count. The constrained dofs, the loads and contact
!> stay serial.
module raccord_central_difference
  use raccord_kinds, only: wp, i8
  use raccord_model, only: model_t, amplitude_at, follower_load_force
  use raccord_state, only: state_t
  use raccord_elastic_block, only: add_internal_force, watch_energy, watch_dissipation, reports_energy
  use raccord_material, only: KIN_FINITE, MAT_J2
  implicit none
  private

  public :: compute_forces, predict_motion, update_energy, advance_state

  !> Fixed node segments of the per-node loops (independent of the thread
  !> count, so that the partial sums are too).
  integer, parameter :: nseg = 64
  !> Models with fewer nodes run the per-node loops on the calling thread
  !> (the same segments, so the same bits).
  integer, parameter :: min_parallel_nodes = 2048

contains

  !> First node of segment s of nnode nodes.
  pure integer function seg_first(s, nnode)
    integer, intent(in) :: s, nnode
    seg_first = int(int(s - 1, i8)*int(nnode, i8)/int(nseg, i8)) + 1
  end function seg_first

  !> Last node of segment s of nnode nodes.
  pure integer function seg_last(s, nnode)
    integer, intent(in) :: s, nnode
    seg_last = int(int(s, i8)*int(nnode, i8)/int(nseg, i8))
  end function seg_last

  !> Internal force K u(n) over every block, applied force at t(n). f_int
  !> is not zeroed first: each node is reset by the group that touches it
  !> first (build_model claims the nodes over the blocks in this order), so
  !> the step makes one pass over f_int instead of two. Nodes of no block
  !> keep the zero they started with.
  subroutine compute_forces(model, state)
    type(model_t), intent(in) :: model
    type(state_t), intent(inout) :: state
    integer :: ib, k, l

    do ib = 1, size(model%bodies)
      do k = 1, size(model%bodies(ib)%blocks)
        if (model%bodies(ib)%blocks(k)%material == MAT_J2) then
          ! j2: the return from the last step's internal variables, its
          ! stored energy and plastic work (finite strain: smallest J and step)
          call add_internal_force(model%bodies(ib)%blocks(k), state%u, state%f_int, fresh=.true., &
            watch=state%watch(k, ib), monitor=model%bodies(ib)%blocks(k)%kinematics == KIN_FINITE, &
            plastic=state%plastic(k, ib))
        else if (model%bodies(ib)%blocks(k)%kinematics == KIN_FINITE) then
          ! finite strain: also its stored energy, smallest J and stable-step estimate
          call add_internal_force(model%bodies(ib)%blocks(k), state%u, state%f_int, fresh=.true., &
            watch=state%watch(k, ib), monitor=.true.)
        else
          call add_internal_force(model%bodies(ib)%blocks(k), state%u, state%f_int, fresh=.true.)
        end if
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
          if (ld%follower) call follower_load_force(ld, model%x, state%u, state%load_force(l)%f)
          state%f_ext(:, ld%nodes) = state%f_ext(:, ld%nodes) + state%load_amp(l)*state%load_force(l)%f
        end associate
      end do
    end if
  end subroutine compute_forces

  !> Predictor (CD-1, CD-2) for free degrees of freedom, prescribed motion
  !> and reactions on the constrained ones, kinetic and internal energy at
  !> t(n) and the damping dissipation of the step. One parallel region:
  !> the free nodes by segments, the constrained dofs on one thread, then
  !> the damping sum by segments.
  subroutine predict_motion(model, state)
    type(model_t), intent(in) :: model
    type(state_t), intent(inout) :: state
    real(wp) :: part(4, nseg), dpart(nseg), sums(4), h, dt
    integer :: j
    logical :: first

    dt = state%dt
    first = state%step == 0
    h = dt
    ! variable step (method brief 5.3): v(n+1/2) = v(n-1/2) + dt_n a(n),
    ! dt_n = (dt(n-1/2) + dt(n+1/2))/2
    if (state%adaptive) h = 0.5_wp*(state%dt_prev + dt)
    if (first) h = 0.5_wp*dt
    part = 0.0_wp
    dpart = 0.0_wp
    sums = 0.0_wp

    ! Remember the old velocity of constrained dofs for their reactions.
    do j = 1, model%ncdof
      state%cdof_vold(j) = state%v(model%cdof_comp(j), model%cdof_node(j))
    end do

    ! On one thread (or a small model) no parallel region: the orphaned
    ! worksharing directives of predict_all then cost nothing, where a
    ! region with a false `if` makes a team of one whose barriers each make
    ! a futex system call in libgomp.
    if (model%nthreads > 1 .and. model%nnode >= min_parallel_nodes) then
      !$omp parallel num_threads(model%nthreads) default(shared)
      call predict_all(model, state, h, dt, first, part, dpart, sums)
      !$omp end parallel
    else
      call predict_all(model, state, h, dt, first, part, dpart, sums)
    end if

    associate (ke => sums(1), ie => sums(2), kh => sums(3), cross => sums(4))
      state%energy%kinetic = 0.5_wp*ke
      state%energy%internal = 0.5_wp*ie
      ! (E-1); a contact correction of u(n+1) and v(n+1/2) must update it at
      ! the nodes it moves.
      state%energy%discrete = 0.5_wp*(kh + cross)
    end associate
    if (model%has_finite .or. model%has_plastic) call finite_energy(model, state)
    if (model%has_damping) then
      ! Dissipation of the semi-implicit damping term over the step:
      ! alpha h v' M v with v the mean of the two half-step velocities
      ! (on the first half step, of v(0) and v(1/2)).
      state%energy%damping = state%energy%damping + h*sum_in_order(dpart)
    end if
  end subroutine predict_motion

  !> The per-node work of predict_motion, run by every thread of the team
  !> (or by the caller alone): the free nodes by segments, the constrained
  !> dofs on one thread, then the damping sum by segments.
  subroutine predict_all(model, state, h, dt, first, part, dpart, sums)
    type(model_t), intent(in) :: model
    type(state_t), intent(inout) :: state
    real(wp), intent(in) :: h, dt
    logical, intent(in) :: first
    real(wp), intent(inout) :: part(4, nseg), dpart(nseg), sums(4)
    integer :: s
    !$omp do schedule(static)
    free_nodes: do s = 1, nseg
      call predict_nodes(model, state, h, dt, first, seg_first(s, model%nnode), seg_last(s, model%nnode), &
        part(:, s))
    end do free_nodes
    !$omp end do
    !$omp single
    do s = 1, nseg
      sums = sums + part(:, s)
    end do
    call predict_constrained(model, state, h, dt, first, sums)
    !$omp end single
    if (model%has_damping) then
      !$omp do schedule(static)
      damped_nodes: do s = 1, nseg
        dpart(s) = damping_power(model, state, first, seg_first(s, model%nnode), seg_last(s, model%nnode))
      end do damped_nodes
      !$omp end do
    end if
  end subroutine predict_all

  !> (CD-1), (CD-2) at the nodes i0..i1 as if free, with the semi-implicit
  !> damping; part = this segment's sums of m v(n)^2, u(n)' f_int,
  !> m v(n+1/2)^2 and u(n+1)' f_int. The segment's arrays go to
  !> `free_motion` as explicit-shape arrays (contiguous, unit stride known
  !> to the compiler), so that its loops vectorise.
  subroutine predict_nodes(model, state, h, dt, first, i0, i1, part)
    type(model_t), intent(in) :: model
    type(state_t), intent(inout) :: state
    real(wp), intent(in) :: h, dt
    logical, intent(in) :: first
    integer, intent(in) :: i0, i1
    real(wp), intent(out) :: part(4)
    if (i1 < i0) then
      part = 0.0_wp
      return
    end if
    call free_motion(i1 - i0 + 1, h, dt, first, model%has_damping, model%has_loads .or. model%has_body_force, &
      model%alpha(i0:i1), model%minv(i0:i1), model%mass(i0:i1), state%u(:, i0:i1), state%f_int(:, i0:i1), &
      state%f_ext(:, i0:i1), state%v(:, i0:i1), state%v_mid(:, i0:i1), state%u_next(:, i0:i1), part)
  end subroutine predict_nodes

  !> The predictor's kernel on n nodes: (CD-1) with the semi-implicit
  !> damping,
  !>   v(n+1/2) = [(1 - c) v(n-1/2) + h M^-1 (f_ext - f_int)] / (1 + c),  c = alpha h/2,
  !> (CD-2) u(n+1) = u(n) + dt v(n+1/2), v(n) = (v(n-1/2) + v(n+1/2))/2 (on
  !> the first half step v(0)), and the four energy sums of predict_nodes.
  !> The nodes go by blocks of nl: the new velocities of a block in the
  !> loop of the scene's variant (damped or not, with applied forces or
  !> not: the unforced loop reads no f_ext, and 0 - x = -x), then one loop
  !> that stores the block and adds its terms to the sums, node l of the
  !> block into lane l. The lanes are added in order at the end. Every
  !> inner loop is branch-free and vectorises; the motion is the same
  !> arithmetic as a node-by-node loop, and the sums depend on the
  !> segments only, not on the thread count.
  pure subroutine free_motion(n, h, dt, first, damped, forced, alpha, minv, mass, u, f_int, f_ext, v, v_mid, &
      u_next, part)
    integer, intent(in) :: n
    real(wp), intent(in) :: h, dt
    logical, intent(in) :: first, damped, forced
    real(wp), intent(in) :: alpha(n), minv(n), mass(n), u(2, n), f_int(2, n), f_ext(2, n)
    real(wp), intent(inout) :: v(2, n)
    real(wp), intent(out) :: v_mid(2, n), u_next(2, n), part(4)
    integer, parameter :: nl = 8
    real(wp) :: ke(nl), ie(nl), kh(nl), cross(nl), vn(2, nl), vm(2, nl), c, un1, un2
    integer :: b, l, i, k, m

    ke = 0.0_wp
    ie = 0.0_wp
    kh = 0.0_wp
    cross = 0.0_wp
    do b = 0, n - 1, nl
      m = min(nl, n - b)
      ! (CD-1): v(n+1/2) of the block
      if (damped .and. forced) then
        do l = 1, m
          i = b + l
          c = 0.5_wp*alpha(i)*h
          vn(1, l) = ((1.0_wp - c)*v(1, i) + h*minv(i)*(f_ext(1, i) - f_int(1, i)))/(1.0_wp + c)
          vn(2, l) = ((1.0_wp - c)*v(2, i) + h*minv(i)*(f_ext(2, i) - f_int(2, i)))/(1.0_wp + c)
        end do
      else if (damped) then
        do l = 1, m
          i = b + l
          c = 0.5_wp*alpha(i)*h
          vn(1, l) = ((1.0_wp - c)*v(1, i) + h*minv(i)*(-f_int(1, i)))/(1.0_wp + c)
          vn(2, l) = ((1.0_wp - c)*v(2, i) + h*minv(i)*(-f_int(2, i)))/(1.0_wp + c)
        end do
      else if (forced) then
        do l = 1, m
          i = b + l
          vn(1, l) = v(1, i) + h*minv(i)*(f_ext(1, i) - f_int(1, i))
          vn(2, l) = v(2, i) + h*minv(i)*(f_ext(2, i) - f_int(2, i))
        end do
      else
        do l = 1, m
          i = b + l
          vn(1, l) = v(1, i) + h*minv(i)*(-f_int(1, i))
          vn(2, l) = v(2, i) + h*minv(i)*(-f_int(2, i))
        end do
      end if
      ! v(n): the mean of the half-step velocities, v(0) on the first step
      if (first) then
        do l = 1, m
          vm(1, l) = v(1, b + l)
          vm(2, l) = v(2, b + l)
        end do
      else
        do l = 1, m
          vm(1, l) = 0.5_wp*(v(1, b + l) + vn(1, l))
          vm(2, l) = 0.5_wp*(v(2, b + l) + vn(2, l))
        end do
      end if
      ! (CD-2), the stores and the sums' terms, node l in lane l
      do l = 1, m
        i = b + l
        un1 = u(1, i) + dt*vn(1, l)
        un2 = u(2, i) + dt*vn(2, l)
        v(1, i) = vn(1, l)
        v(2, i) = vn(2, l)
        v_mid(1, i) = vm(1, l)
        v_mid(2, i) = vm(2, l)
        u_next(1, i) = un1
        u_next(2, i) = un2
        ke(l) = ke(l) + mass(i)*(vm(1, l)**2 + vm(2, l)**2)
        ie(l) = ie(l) + (u(1, i)*f_int(1, i) + u(2, i)*f_int(2, i))
        kh(l) = kh(l) + mass(i)*(vn(1, l)**2 + vn(2, l)**2)
        cross(l) = cross(l) + (un1*f_int(1, i) + un2*f_int(2, i))
      end do
    end do
    part = 0.0_wp
    do k = 1, nl
      part(1) = part(1) + ke(k)
      part(2) = part(2) + ie(k)
      part(3) = part(3) + kh(k)
      part(4) = part(4) + cross(k)
    end do
  end subroutine free_motion

  !> Constrained dofs: velocity that lands exactly on the prescribed value
  !> at t(n+1); the reaction is the force that turns the free velocity into
  !> it: vc = vfree + h M^-1 r / (1 + c). sums (as predict_nodes) are
  !> corrected for the change at these dofs.
  subroutine predict_constrained(model, state, h, dt, first, sums)
    type(model_t), intent(in) :: model
    type(state_t), intent(inout) :: state
    real(wp), intent(in) :: h, dt
    logical, intent(in) :: first
    real(wp), intent(inout) :: sums(4)
    real(wp) :: c, tnext, target, vfree, vc, vm_c, m
    integer :: i, j, comp, s

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
      sums(1) = sums(1) + m*(vm_c**2 - state%v_mid(comp, i)**2)
      sums(3) = sums(3) + m*(vc**2 - vfree**2)
      sums(4) = sums(4) + (target - state%u_next(comp, i))*state%f_int(comp, i)
      state%reaction(j) = m*(1.0_wp + c)*(vc - vfree)/h
      state%v(comp, i) = vc
      state%v_mid(comp, i) = vm_c
      state%u_next(comp, i) = target
    end do
  end subroutine predict_constrained

  !> Finite-strain and j2 bodies (doc/theory-finite.md, "Energy";
  !> doc/theory-plasticity.md): their stored (elastic) energy W(u(n)) =
  !> sum_g W(F) c replaces 1/2 u(n)' f_int(n), the plastic work of the j2
  !> bodies' returns at u(n) is added to its own term, and (E-1)
  !> becomes H(n+1/2) = 1/2 v' M v + W(u(n)) + 1/2 f_int(n)' (u(n+1) - u(n)),
  !> which is (E-1) itself for a linear body. Its change over a step is the
  !> work of the forces up to the trapezoidal error of integrating W along
  !> the path: O(dt^2) over a run, not round-off.
  subroutine finite_energy(model, state)
    type(model_t), intent(in) :: model
    type(state_t), intent(inout) :: state
    real(wp) :: w, ie, wpl
    integer :: ib, k, j, i
    w = 0.0_wp
    wpl = 0.0_wp
    do ib = 1, size(model%bodies)
      do k = 1, size(model%bodies(ib)%blocks)
        if (reports_energy(model%bodies(ib)%blocks(k))) w = w + watch_energy(state%watch(k, ib))
        if (model%bodies(ib)%blocks(k)%material == MAT_J2) wpl = wpl + watch_dissipation(state%watch(k, ib))
      end do
    end do
    state%energy%plastic = state%energy%plastic + wpl
    ie = 0.0_wp
    do j = 1, size(model%finite_nodes)
      i = model%finite_nodes(j)
      ie = ie + state%u(1, i)*state%f_int(1, i) + state%u(2, i)*state%f_int(2, i)
    end do
    state%energy%internal = state%energy%internal + (w - 0.5_wp*ie)
    state%energy%discrete = state%energy%discrete + (w - 0.5_wp*ie)
  end subroutine finite_energy

  !> sum alpha m |v|^2 over the nodes i0..i1, v the mean of the two
  !> half-step velocities (on the first half step, of v(0) and v(1/2)).
  real(wp) function damping_power(model, state, first, i0, i1) result(p)
    type(model_t), intent(in) :: model
    type(state_t), intent(in) :: state
    logical, intent(in) :: first
    integer, intent(in) :: i0, i1
    integer :: i
    p = 0.0_wp
    if (i1 < i0) return
    if (first) then
      do i = i0, i1
        p = p + model%alpha(i)*model%mass(i)*(0.25_wp*sum((model%v0(:, i) + state%v(:, i))**2))
      end do
    else
      p = damping_sum(i1 - i0 + 1, model%alpha(i0:i1), model%mass(i0:i1), state%v_mid(:, i0:i1))
    end if
  end function damping_power

  !> sum alpha m |v|^2 over n nodes, in nl lanes as free_motion's sums
  !> (node l of a block of nl into lane l, the lanes added in order).
  pure real(wp) function damping_sum(n, alpha, mass, v) result(p)
    integer, intent(in) :: n
    real(wp), intent(in) :: alpha(n), mass(n), v(2, n)
    integer, parameter :: nl = 8
    real(wp) :: lane(nl)
    integer :: b, l, k
    lane = 0.0_wp
    do b = 0, n - 1, nl
      do l = 1, min(nl, n - b)
        lane(l) = lane(l) + alpha(b + l)*mass(b + l)*(v(1, b + l)**2 + v(2, b + l)**2)
      end do
    end do
    p = 0.0_wp
    do k = 1, nl
      p = p + lane(k)
    end do
  end function damping_sum

  !> Sum of the partial sums in index order (fixed, whatever the threads).
  pure real(wp) function sum_in_order(part) result(total)
    real(wp), intent(in) :: part(:)
    integer :: k
    total = 0.0_wp
    do k = 1, size(part)
      total = total + part(k)
    end do
  end function sum_in_order

  !> External work (E-2) of the forces at t(n) on the loaded and constrained
  !> dofs only, and the energy balance. The first step is a half step from
  !> v(0): there the work is (dt/4) f(0)' (v(0) + v(1/2)).
  subroutine update_energy(model, state)
    type(model_t), intent(in) :: model
    type(state_t), intent(inout) :: state
    real(wp) :: w, wl, wpart(nseg)
    integer :: j, i, comp, l, k, n, s

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
        wl = wl + state%load_force(l)%f(1, k)*increment(state, model, 1, n) + &
          state%load_force(l)%f(2, k)*increment(state, model, 2, n)
      end do
      w = w + state%load_amp(l)*wl
    end do
    if (model%has_body_force) then
      ! every node carries body force: by segments, as in predict_motion; on
      ! one thread no parallel region (a team of one still costs a futex call)
      if (model%nthreads > 1 .and. model%nnode >= min_parallel_nodes) then
        !$omp parallel do num_threads(model%nthreads) schedule(static) default(none) &
        !$omp   shared(model, state, wpart) private(s)
        do s = 1, nseg
          wpart(s) = body_force_work(model, state, s)
        end do
        !$omp end parallel do
      else
        do s = 1, nseg
          wpart(s) = body_force_work(model, state, s)
        end do
      end if
      w = w + sum_in_order(wpart)
    end if
    associate (e => state%energy)
      e%external = e%external + w
      if (state%step == 0) e%initial = e%kinetic
      e%balance = e%discrete + e%damping + e%contact + e%plastic - e%external - e%initial
      ! Every term of the balance sets the scale, so that a step-0 contact
      ! correction on bodies at rest has a scale to be relative to.
      e%scale = max(e%scale, abs(e%kinetic), abs(e%internal), abs(e%external), abs(e%initial), &
        abs(e%discrete), abs(e%contact), abs(e%damping), abs(e%plastic))
    end associate
  end subroutine update_energy

  !> Work (E-2) of the body forces on the nodes of segment s.
  pure real(wp) function body_force_work(model, state, s) result(w)
    type(model_t), intent(in) :: model
    type(state_t), intent(in) :: state
    integer, intent(in) :: s
    integer :: n
    w = 0.0_wp
    do n = seg_first(s, model%nnode), seg_last(s, model%nnode)
      w = w + model%f_body(1, n)*increment(state, model, 1, n) + &
        model%f_body(2, n)*increment(state, model, 2, n)
    end do
  end function body_force_work

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
    if (state%adaptive) then
      state%time = state%time + state%dt
      if (state%step == state%nsteps) state%time = state%t_end
    else
      state%time = real(state%step, wp)*state%dt
    end if
  end subroutine advance_state
end module raccord_central_difference
