!> Node-to-segment contact with forward-increment Lagrange multipliers
!> against closed forms: impact of two identical bars (1D waves), the
!> contact patch test, a block pressed then pulled sideways (Coulomb), and
!> loading then unloading to separation.
program test_contact_nts
  use raccord_kinds, only: wp
  use raccord_check, only: failure_t, new_test, run_tests, check, check_close
  use raccord_error, only: error_t
  use raccord_mesh, only: mesh_t, ELEM_Q4, ELEM_Q8, find_node_set
  use raccord_scene, only: scene_t, BC_FIXED, BC_DISPLACEMENT, BC_PRESSURE, BC_TRACTION, METHOD_NTS, MULT_P1
  use two_bar_impact, only: check_two_bar_impact
  use raccord_model, only: model_t
  use raccord_model_build, only: build_model
  use raccord_time_step, only: time_plan_t, choose_time_step
  use raccord_state, only: state_t, init_state
  use raccord_central_difference, only: advance_state
  use raccord_contact_pair, only: contact_pair_t, init_contact_pairs
  use raccord_multiplier_solver, only: ST_OPEN, ST_SLIP
  use raccord_test_meshes, only: rect_mesh, join_meshes
  use dynamics_support, only: one_body_scene, add_bc, add_amplitude, add_body, add_pair, contact_step, &
    two_body_scene, prepare_contact
  implicit none

  call run_tests('contact_nts', [ &
    new_test('two bars impact: no penetration, momentum, duration 2L/c, no energy gain', test_impact), &
    new_test('patch test, matching meshes: uniform pressure to round-off (Q4)', test_patch_matching_q4), &
    new_test('patch test, matching meshes: uniform pressure to round-off (Q8)', test_patch_matching_q8), &
    new_test('patch test, non-matching meshes: error recorded and bounded', test_patch_nonmatching), &
    new_test('block pressed then pulled, mu = 0.3: stick below mu N, slide at mu N', test_pull_friction), &
    new_test('block pressed then pulled, mu = 0: slides, no tangential force', test_pull_frictionless), &
    new_test('loading then unloading to separation: multipliers back to zero', test_unload)])

contains

  !> Set up an in-memory contact run; a failure names the setup error.
  subroutine prepare(scene, mesh, model, pairs, plan, state, failure)
    type(scene_t), intent(inout) :: scene
    type(mesh_t), intent(in) :: mesh
    type(model_t), intent(out) :: model
    type(contact_pair_t), allocatable, intent(out) :: pairs(:)
    type(time_plan_t), intent(out) :: plan
    type(state_t), intent(out) :: state
    type(failure_t), allocatable, intent(inout) :: failure
    type(error_t) :: err
    call prepare_contact(scene, mesh, model, pairs, plan, state, err)
    if (err%failed()) call check(failure, .false., 'setup failed: ' // err%message)
  end subroutine prepare

  !> Two identical bars meet (tests/contact/two_bar_impact.f90).
  subroutine test_impact(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call check_two_bar_impact(failure, METHOD_NTS, MULT_P1, 1, 1)
  end subroutine test_impact

  !> Two stacked blocks, pressure p on top, damped to the static state:
  !> the exact solution is uniform stress -p, so every slave node carries
  !> the pressure p.
  subroutine patch_case(failure, etype, na, nb, err_rel)
    type(failure_t), allocatable, intent(out) :: failure
    integer, intent(in) :: etype, na, nb
    real(wp), intent(out) :: err_rel
    real(wp), parameter :: e = 1000.0_wp, nu = 0.3_wp, rho = 1.0e-6_wp, p = 1.0_wp
    type(mesh_t) :: ma, mb, mesh
    type(scene_t) :: scene
    type(model_t) :: model
    type(contact_pair_t), allocatable :: pairs(:)
    type(time_plan_t) :: plan
    type(state_t) :: state
    type(error_t) :: err
    real(wp) :: omega1, t_end, p_mean, resultant_err

    call rect_mesh(ma, etype, na, 2, 1.0_wp, 0.5_wp)
    call rect_mesh(mb, etype, nb, 2, 1.0_wp, 0.5_wp, y0=0.5_wp)
    ! Lowest mode ~ a quarter wave through the 1.0 high stack.
    omega1 = 0.5_wp*3.14159265_wp*sqrt(e/rho)/1.0_wp
    t_end = 400.0_wp/omega1
    call two_body_scene(ma, mb, mesh, scene, e, nu, rho, .false., t_end)
    scene%time%damping = 2.0_wp*omega1
    call add_bc(scene, 'a_bottom', BC_FIXED, comp=[.false., .true.])
    call add_bc(scene, 'a_left', BC_FIXED, comp=[.true., .false.])
    call add_bc(scene, 'b_left', BC_FIXED, comp=[.true., .false.])
    call add_bc(scene, 'b_top', BC_PRESSURE, pressure=p)
    call add_pair(scene, 'b_bottom', 'a_top', METHOD_NTS, 0.0_wp)
    call prepare(scene, mesh, model, pairs, plan, state, failure)
    if (allocated(failure)) return
    do
      call contact_step(model, pairs, state, err)
      if (err%failed() .or. state%step == state%nsteps) exit
      call advance_state(state)
    end do
    call check(failure, .not. err%failed(), 'contact step failed')
    if (allocated(failure)) return
    ! Uniform: every slave node's contact stress equals their mean (stress =
    ! nodal force / current tributary length); equilibrium: the resultant
    ! equals the applied load p * width.
    p_mean = sum(pairs(1)%pressure)/pairs(1)%slave%nnode
    err_rel = maxval(abs(pairs(1)%pressure - p_mean))/p
    resultant_err = abs(pairs(1)%force(2) - p*1.0_wp)/p   ! the master pushes the upper block up
    call check(failure, resultant_err < 1.0e-8_wp, 'vertical contact resultant on the upper block differs from p w')
    call check(failure, all(pairs(1)%status /= ST_OPEN), 'a slave node is open under uniform pressure')
    call check(failure, abs(state%energy%balance) < 1.0e-10_wp*state%energy%scale, 'energy balance not exact')
  end subroutine patch_case

  subroutine test_patch_matching_q4(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp) :: err_rel
    call patch_case(failure, ELEM_Q4, 6, 6, err_rel)
    if (allocated(failure)) return
    write(*, '(a,es10.3)') '        max |p - mean p|/p0 = ', err_rel
    call check(failure, err_rel < 1.0e-8_wp, 'contact pressure not uniform on matching meshes')
  end subroutine test_patch_matching_q4

  subroutine test_patch_matching_q8(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp) :: err_rel
    call patch_case(failure, ELEM_Q8, 3, 3, err_rel)
    if (allocated(failure)) return
    write(*, '(a,es10.3)') '        max |p - mean p|/p0 = ', err_rel
    call check(failure, err_rel < 1.0e-8_wp, 'contact pressure not uniform on matching Q8 meshes')
  end subroutine test_patch_matching_q8

  !> Node-to-segment fails the patch test on non-matching meshes (method
  !> brief section 4): the error is recorded, and must stay bounded.
  subroutine test_patch_nonmatching(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp) :: err_rel
    call patch_case(failure, ELEM_Q4, 9, 4, err_rel)
    if (allocated(failure)) return
    write(*, '(a,es10.3)') '        non-matching 9:4, max |p - mean p|/p0 = ', err_rel
    call check(failure, err_rel < 1.0_wp, 'pressure error on non-matching meshes is not bounded by p0')
  end subroutine test_patch_nonmatching

  !> A block on a wider block: pressure p on its top (ramped, then held),
  !> then a traction q on its side ramped from 0 to 2 mu p H/H... The pull
  !> Q = q * h must be carried by friction while Q < mu N and the block
  !> slides with friction force mu N once Q > mu N.
  subroutine pull_case(failure, mu)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp), intent(in) :: mu
    real(wp), parameter :: e = 1000.0_wp, nu = 0.3_wp, rho = 1.0e-6_wp, p = 1.0_wp
    type(mesh_t) :: ma, mb, mesh
    type(scene_t) :: scene
    type(model_t) :: model
    type(contact_pair_t), allocatable :: pairs(:)
    type(time_plan_t) :: plan
    type(state_t) :: state
    type(error_t) :: err
    real(wp) :: omega1, t1, t2, t_end, q_max, n_force, slide_before, slide_after, ratio_worst, ux0
    integer :: kb, ka, i
    integer, allocatable :: under(:)
    real(wp), parameter :: wb = 1.0_wp, hb = 0.5_wp

    call rect_mesh(ma, ELEM_Q4, 16, 2, 4.0_wp, 0.5_wp, x0=-2.0_wp)
    call rect_mesh(mb, ELEM_Q4, 6, 3, wb, hb, x0=-0.5_wp, y0=0.5_wp)
    omega1 = 0.5_wp*3.14159265_wp*sqrt(e/rho)/1.0_wp
    t1 = 60.0_wp/omega1
    t2 = 2.0_wp*t1
    t_end = 3.0_wp*t1
    q_max = 2.0_wp*mu*p*wb/hb
    if (mu == 0.0_wp) q_max = 0.2_wp*p*wb/hb
    call two_body_scene(ma, mb, mesh, scene, e, nu, rho, .false., t_end)
    scene%time%damping = 2.0_wp*omega1
    call add_amplitude(scene, 'press', [0.0_wp, t1], [0.0_wp, 1.0_wp])
    ! Pull: zero until t1, then up to q_max at t_end (crosses mu N at t2).
    call add_amplitude(scene, 'pull', [0.0_wp, t1, t_end], [0.0_wp, 0.0_wp, 1.0_wp])
    call add_bc(scene, 'a_bottom', BC_FIXED, comp=[.true., .true.])
    call add_bc(scene, 'b_top', BC_PRESSURE, pressure=p, amplitude='press')
    call add_bc(scene, 'b_left', BC_TRACTION, value=[q_max, 0.0_wp], amplitude='pull')
    call add_pair(scene, 'b_bottom', 'a_top', METHOD_NTS, mu)
    call prepare(scene, mesh, model, pairs, plan, state, failure)
    if (allocated(failure)) return
    kb = find_node_set(mesh, 'b_bottom')
    ka = find_node_set(mesh, 'a_top')
    ! Master nodes under the block: slip is b_bottom's motion relative to them.
    under = pack(mesh%nsets(ka)%nodes, abs(mesh%x(1, mesh%nsets(ka)%nodes)) <= 0.5_wp*wb + 1.0e-9_wp)
    n_force = p*wb
    slide_before = 0.0_wp
    ratio_worst = 0.0_wp
    ux0 = 0.0_wp
    do
      call contact_step(model, pairs, state, err)
      if (err%failed()) exit
      if (abs(state%time - t1) < 0.5_wp*state%dt) ux0 = relative_mean(state%u, mesh%nsets(kb)%nodes, under)
      ! Coulomb at every node and step: |shear| <= mu pressure.
      if (pairs(1)%nactive > 0) ratio_worst = max(ratio_worst, maxval(abs(pairs(1)%shear) - mu*pairs(1)%pressure))
      ! Stick phase: pull below 0.8 mu N (t < t1 + 0.8 (t2 - t1)).
      if (mu > 0.0_wp .and. state%time < t1 + 0.8_wp*(t2 - t1)) &
        slide_before = relative_mean(state%u, mesh%nsets(kb)%nodes, under) - ux0
      if (state%step == state%nsteps) exit
      call advance_state(state)
    end do
    call check(failure, .not. err%failed(), 'contact step failed')
    if (allocated(failure)) return
    slide_after = relative_mean(state%u, mesh%nsets(kb)%nodes, under) - ux0
    write(*, '(a,f5.2,a,es10.3,a,es10.3,a,es12.4,a,es10.3)') '        mu = ', mu, ': slide at 0.8 mu N ', &
      slide_before, ', at the end ', slide_after, ', friction/(mu N) ', &
      abs(pairs(1)%tangent_sum)/max(mu*pairs(1)%normal_sum, tiny(1.0_wp)), ', worst |tau| - mu p ', ratio_worst
    call check(failure, ratio_worst <= 1.0e-9_wp*p, 'Coulomb cone violated at some node')
    call check_close(failure, pairs(1)%normal_sum, n_force, 'normal force = p w', rel_tol=0.01_wp)
    if (mu > 0.0_wp) then
      call check(failure, abs(slide_before) < 0.01_wp*abs(slide_after), 'block slid before the pull reached mu N')
      call check(failure, all(pairs(1)%status == ST_SLIP), 'not every node slips once the pull exceeds mu N')
      call check_close(failure, abs(pairs(1)%tangent_sum), mu*pairs(1)%normal_sum, 'friction force = mu N', &
        rel_tol=0.01_wp)
    else
      call check(failure, maxval(abs(pairs(1)%shear)) == 0.0_wp, 'frictionless pair carried shear')
      call check(failure, slide_after > 1.0e-3_wp, 'frictionless block did not slide')
    end if
    call check(failure, abs(state%energy%balance) < 1.0e-10_wp*state%energy%scale, 'energy balance not exact')
    call check(failure, state%energy%friction >= 0.0_wp, 'friction did positive work')
    i = 0
  end subroutine pull_case

  !> Mean x displacement of the nodes `top` relative to the nodes `under`.
  real(wp) function relative_mean(u, top, under)
    real(wp), intent(in) :: u(:,:)
    integer, intent(in) :: top(:), under(:)
    relative_mean = sum(u(1, top))/size(top) - sum(u(1, under))/size(under)
  end function relative_mean

  subroutine test_pull_friction(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call pull_case(failure, 0.3_wp)
  end subroutine test_pull_friction

  subroutine test_pull_frictionless(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call pull_case(failure, 0.0_wp)
  end subroutine test_pull_frictionless

  !> The upper block is pushed down by its top, then lifted above its
  !> start: every multiplier returns to zero and the surfaces part.
  subroutine test_unload(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp), parameter :: e = 1000.0_wp, nu = 0.3_wp, rho = 1.0e-6_wp
    type(mesh_t) :: ma, mb, mesh
    type(scene_t) :: scene
    type(model_t) :: model
    type(contact_pair_t), allocatable :: pairs(:)
    type(time_plan_t) :: plan
    type(state_t) :: state
    type(error_t) :: err
    real(wp) :: omega1, t1, peak
    integer :: i, ka, kb

    call rect_mesh(ma, ELEM_Q4, 8, 2, 1.0_wp, 0.5_wp)
    call rect_mesh(mb, ELEM_Q4, 5, 2, 1.0_wp, 0.5_wp, y0=0.5_wp)
    omega1 = 0.5_wp*3.14159265_wp*sqrt(e/rho)
    t1 = 40.0_wp/omega1
    call two_body_scene(ma, mb, mesh, scene, e, nu, rho, .false., 3.0_wp*t1)
    scene%time%damping = 2.0_wp*omega1
    call add_amplitude(scene, 'cycle', [0.0_wp, t1, 2.0_wp*t1, 3.0_wp*t1], [0.0_wp, 1.0_wp, -0.5_wp, -0.5_wp])
    call add_bc(scene, 'a_bottom', BC_FIXED, comp=[.true., .true.])
    call add_bc(scene, 'b_top', BC_DISPLACEMENT, comp=[.true., .true.], value=[0.0_wp, -0.01_wp], amplitude='cycle')
    call add_pair(scene, 'b_bottom', 'a_top', METHOD_NTS, 0.2_wp)
    call prepare(scene, mesh, model, pairs, plan, state, failure)
    if (allocated(failure)) return
    peak = 0.0_wp
    do
      call contact_step(model, pairs, state, err)
      if (err%failed()) exit
      peak = max(peak, pairs(1)%normal_sum)
      if (state%step == state%nsteps) exit
      call advance_state(state)
    end do
    call check(failure, .not. err%failed(), 'contact step failed')
    if (allocated(failure)) return
    ka = find_node_set(mesh, 'a_top')
    kb = find_node_set(mesh, 'b_bottom')
    write(*, '(a,es10.3,a,es10.3)') '        peak normal force ', peak, ', final ', pairs(1)%normal_sum
    call check(failure, peak > 0.0_wp, 'no contact force while pressed')
    call check(failure, all(pairs(1)%status == ST_OPEN), 'a node still in contact after lifting')
    call check(failure, all(pairs(1)%lam_n == 0.0_wp) .and. all(pairs(1)%lam_t == 0.0_wp), 'multipliers not zero')
    call check(failure, minval(mesh%x(2, mesh%nsets(kb)%nodes) + state%u(2, mesh%nsets(kb)%nodes)) > &
      maxval(mesh%x(2, mesh%nsets(ka)%nodes) + state%u(2, mesh%nsets(ka)%nodes)), 'surfaces not apart')
    call check(failure, abs(state%energy%balance) < 1.0e-10_wp*state%energy%scale, 'energy balance not exact')
    i = 0
  end subroutine test_unload
end program test_contact_nts
