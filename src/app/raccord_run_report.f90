!> What a run tells its user before and after it marches: the resolved
!> model, the active effects, the time step, the cost estimate, and the
!> closing summary.
module raccord_run_report
  use raccord_kinds, only: wp, i8
  use raccord_log, only: log_raw, log_info, log_level, log_set_level, LEVEL_ERROR
  use raccord_error, only: error_t
  use raccord_strings, only: str
  use raccord_mesh, only: mesh_t, element_name
  use raccord_model, only: model_t
  use raccord_scene, only: scene_t, body_spec_t
  use raccord_state, only: state_t
  use raccord_time_step, only: time_plan_t
  use raccord_output, only: output_t, wall_seconds
  use raccord_contact_pair, only: contact_pair_t, search_summary
  use raccord_step_trial, only: step_cost_t, measure_step_cost
  use raccord_scene, only: METHOD_NTS, MULT_P0, MULT_P1, MULT_DUAL
  use raccord_material, only: KIN_FINITE, MAT_J2, kinematics_name, material_name, volumetric_name
  implicit none
  private

  public :: report_plan, report_summary, run_stem

contains

  !> Path stem of the run's files: <output_dir>/<deck file name without extension>.
  function run_stem(scene) result(stem)
    type(scene_t), intent(in) :: scene
    character(len=:), allocatable :: stem
    integer :: slash, dot
    character(len=:), allocatable :: base
    slash = index(scene%path, '/', back=.true.)
    base = scene%path(slash+1:)
    dot = index(base, '.', back=.true.)
    if (dot > 1) base = base(1:dot-1)
    stem = scene%run%output_dir // '/' // base
  end function run_stem

  !> The model, its effects and the time plan, with a measured cost estimate.
  subroutine report_plan(scene, mesh, model, plan, pairs)
    type(scene_t), intent(in) :: scene
    type(mesh_t), intent(in) :: mesh
    type(model_t), intent(in) :: model
    type(time_plan_t), intent(in) :: plan
    type(contact_pair_t), intent(in) :: pairs(:)
    integer :: ib, k, nq4, nq8
    integer(i8) :: every
    real(wp) :: c, setup, base, contact_mean
    type(step_cost_t) :: cost
    character(len=:), allocatable :: range, reach
    character(len=:), allocatable :: effects

    if (len_trim(scene%run%title) > 0) then
      call log_raw('scene   ' // scene%path // '  (' // trim(scene%run%title) // ')')
    else
      call log_raw('scene   ' // scene%path)
    end if
    call log_raw('mesh    ' // mesh%source // ': ' // str(mesh%nnode) // ' nodes, ' // str(mesh%nelem) // ' elements')
    do ib = 1, size(model%bodies)
      associate (b => model%bodies(ib), s => scene%bodies(ib))
        c = sqrt(s%young/s%density)
        call log_raw('body    ' // b%name // ': ' // str(size(b%elems)) // ' elements (' // &
          block_types(b) // '), E = ' // str(s%young, 4) // ', nu = ' // str(s%poisson, 3) // &
          ', rho = ' // str(s%density, 4) // ', ' // &
          merge('axisymmetric', merge('plane stress', 'plane strain', s%plane_stress), s%axisymmetric) // &
          ', ' // kinematics_name(s%kinematics) // ' strain, ' // material_name(s%material) // &
          finite_detail(b) // plastic_detail(s) // &
          ', mass = ' // str(b%mass, 4) // ', sqrt(E/rho) = ' // str(c, 4) // ', damping alpha = ' // &
          str(merge(s%damping, scene%time%damping, s%damping >= 0.0_wp), 4))
      end associate
    end do
    do k = 1, size(model%supports)
      call log_raw('support ' // model%supports(k)%set // ': ' // &
        trim(merge('driven displacement', 'fixed              ', model%supports(k)%driven)) // ', ' // &
        str(count(model%cdof_support == k)) // ' constrained dofs')
    end do
    do k = 1, size(model%loads)
      call log_raw('load    ' // model%loads(k)%set // ': total force at amplitude 1 = (' // &
        str(sum(model%loads(k)%force(1, :)), 4) // ', ' // str(sum(model%loads(k)%force(2, :)), 4) // ')')
    end do

    ! Active effects: the step loop does the work of these and no other.
    nq4 = 0
    nq8 = 0
    do ib = 1, size(model%bodies)
      do k = 1, size(model%bodies(ib)%blocks)
        if (element_name(model%bodies(ib)%blocks(k)%etype) == 'Q4') then
          nq4 = nq4 + model%bodies(ib)%blocks(k)%nel
        else
          nq8 = nq8 + model%bodies(ib)%blocks(k)%nel
        end if
      end do
    end do
    effects = 'elasticity (' // str(nq4) // ' Q4 + ' // str(nq8) // ' Q8)'
    if (model%has_supports) effects = effects // ', supports (' // str(model%ncdof) // ' dofs)'
    if (model%has_loads) effects = effects // ', surface loads (' // str(size(model%loads)) // ')'
    if (model%has_body_force) effects = effects // ', body force'
    if (model%has_damping) effects = effects // ', mass damping (alpha up to ' // str(maxval(model%alpha), 4) // ')'
    do k = 1, size(pairs)
      call log_raw('contact pair ' // str(k) // ': slave ' // pairs(k)%slave%name // ' (' // &
        str(pairs(k)%slave%nnode) // ' nodes), master ' // pairs(k)%master%name // ' (' // &
        str(pairs(k)%master%nseg) // ' segments), ' // matching_text(pairs(k)) // ', mu = ' // &
        str(pairs(k)%mu, 4) // ', search distance ' // &
        str(pairs(k)%reach, 4))
    end do
    if (size(pairs) == 0) then
      effects = effects // ', contact pairs: none'
    else
      effects = effects // ', contact pairs: ' // str(size(pairs))
      if (any(pairs%mu > 0.0_wp)) effects = effects // ' (with friction)'
    end if
    call log_raw('effects ' // effects)

    call log_raw('time    t_end = ' // str(plan%t_end, 6) // ', stable dt = ' // str(plan%dt_stable, 6) // &
      ', dt = ' // str(plan%dt, 6) // ' (' // str(100.0_wp*plan%dt/plan%dt_stable, 3) // ' % of stable), ' // &
      str(plan%nsteps) // ' steps')
    if (model%has_finite) call log_raw('time    finite strain: the step follows the deforming mesh ' // &
      '(current length and wave speed, at most the dt above); the step count is an estimate')
    if (model%scaling%active) call report_mass_scaling(scene, model, plan)
    cost = measure_step_cost(model, plan, pairs, scene%run%output_dir)
    ! What the run does before its first step (reading, building, this
    ! trial): the processor time of this process so far.
    call cpu_time(setup)
    ! The contact work per step is timed in the contact zone of t = 0 and
    ! with every slave node the prescribed motion can reach in contact
    ! (raccord_step_trial); the estimate takes their mean, the range both.
    contact_mean = 0.5_wp*(cost%contact + cost%contact_engaged)
    ! History rows as raccord_output writes them: every history_every
    ! steps (0: about 1000 rows) and at the first and last step.
    every = int(scene%output%history_every, i8)
    if (every <= 0) every = max(1_i8, plan%nsteps/1000_i8)
    associate (n => real(plan%nsteps, wp), frames => real(scene%output%frames + 1, wp), &
        rows => real(plan%nsteps/every + 2_i8, wp))
      base = setup + cost%element*n + cost%frame*frames + cost%history*rows
      call log_raw('cost    about ' // str(1.0e9_wp*cost%element/real(max(1, model%nelem), wp), 3) // &
        ' ns per element per step, timed here over ' // str(cost%steps) // ' trial steps (' // &
        trim(merge('wall     ', 'processor', model%nthreads > 1)) // ' time)')
      range = ''
      if (size(pairs) > 0) then
        reach = 'those the prescribed motion can reach'
        if (.not. cost%motion_bounded) reach = 'all that face a master segment: loads have no bound'
        call log_raw('cost    contact ' // str(1.0e6_wp*cost%contact, 3) // ' us per step in the contact ' // &
          'zone of t = 0, ' // str(1.0e6_wp*cost%contact_engaged, 3) // ' us with ' // str(cost%engaged) // &
          ' of ' // str(cost%slave_nodes) // ' slave nodes in contact (' // reach // ')')
        range = ', between ' // str(base + cost%contact*n, 3) // ' and ' // &
          str(base + cost%contact_engaged*n, 3) // ' s'
      end if
      call log_raw('cost    estimated run time ' // str(base + contact_mean*n, 3) // ' s (setup ' // &
        str(setup, 3) // ' s, elements ' // str(cost%element*n, 3) // ' s, contact ' // &
        str(contact_mean*n, 3) // ' s, history ' // str(cost%history*rows, 3) // ' s, output ' // &
        str(cost%frame*frames, 3) // ' s)' // range)
    end associate
  end subroutine report_plan

  !> Mass scaling in the plan (raccord_mass_scaling): target, unscaled and
  !> scaled step and step count, and per body the scaled elements and the
  !> added mass.
  subroutine report_mass_scaling(scene, model, plan)
    type(scene_t), intent(in) :: scene
    type(model_t), intent(in) :: model
    type(time_plan_t), intent(in) :: plan
    real(wp) :: dt0, added
    integer(i8) :: n0
    integer :: ib
    dt0 = scene%time%safety*2.0_wp/sqrt(model%scaling%w2_unscaled)
    n0 = max(1_i8, ceiling(plan%t_end/dt0, i8))
    call log_raw('mass    scaling to dt = ' // str(model%scaling%dt_target, 6) // ': unscaled dt ' // &
      str(dt0, 6) // ' and ' // str(n0) // ' steps -> dt ' // str(plan%dt, 6) // ' and ' // str(plan%nsteps) // &
      ' steps (' // str(real(n0, wp)/real(max(1_i8, plan%nsteps), wp), 4) // ' x fewer); kinetic and internal ' // &
      'energy and the balance are those of the scaled system')
    do ib = 1, size(model%bodies)
      associate (b => model%bodies(ib))
        added = 0.0_wp
        if (b%mass_unscaled > 0.0_wp) added = (b%mass - b%mass_unscaled)/b%mass_unscaled
        call log_raw('mass    body ' // b%name // ': ' // str(b%nscaled) // ' of ' // str(size(b%elems)) // &
          ' elements scaled (density factor up to ' // str(b%scale_max, 4) // '), added mass ' // &
          str(100.0_wp*added, 4) // ' % of ' // str(b%mass_unscaled, 4) // &
          trim(merge(' (above added_mass_warn)', '                        ', added > scene%time%added_mass_warn)))
      end associate
    end do
    if (scene%time%kinetic_ratio_warn > 0.0_wp) call log_raw('mass    quasi-static check: a warning when the ' // &
      'kinetic energy passes ' // str(100.0_wp*scene%time%kinetic_ratio_warn, 4) // ' % of the largest internal ' // &
      'energy so far, from t = ' // str(scene%time%kinetic_check_from*plan%t_end, 6) // ' on')
  end subroutine report_mass_scaling

  !> The matching and the multiplier space of a pair, as the plan names
  !> them (doc/theory-contact.md, doc/theory-contact-mortar.md).
  function matching_text(pair) result(s)
    type(contact_pair_t), intent(in) :: pair
    character(len=:), allocatable :: s
    if (pair%method == METHOD_NTS) then
      s = 'node-to-segment matching, multipliers at the slave nodes'
      return
    end if
    select case (pair%multiplier)
    case (MULT_P0)
      s = 'mortar matching, P0 multipliers (constant per slave segment)'
    case (MULT_P1)
      s = 'mortar matching, P1 multipliers (linear, at the slave nodes)'
    case (MULT_DUAL)
      s = 'mortar matching, dual multipliers'
    case default
      s = 'mortar matching, multiplier space ' // str(pair%multiplier)
    end select
    if (pair%mortar%corners .and. pair%slave%nen_seg == 3) then
      ! edge_multipliers = 'corners' (doc/theory-contact-mortar.md, section 1)
      select case (pair%multiplier)
      case (MULT_P0)
        s = 'mortar matching, P0 multipliers (constant on each half of a quadratic slave edge, at its corners)'
      case (MULT_P1)
        s = 'mortar matching, P1 multipliers (linear over each quadratic slave edge, at its corners)'
      end select
    end if
    ! edge_multipliers = 'tangential_corners' (doc/reproduction.md, "The Q8
    ! stick zigzag: tangential corner multipliers")
    if (pair%mortar%tcorners .and. pair%slave%nen_seg == 3) s = s // &
      ', the tangential ones at the corners of each quadratic slave edge only'
    if (pair%weighted) s = s // ', rows along the master''s normal, conditions on each weighted gap'
  end function matching_text

  !> ' (Q4 mean_dilatation)' and the like for a finite-strain or j2 body's blocks.
  function finite_detail(b) result(s)
    use raccord_model, only: body_t
    type(body_t), intent(in) :: b
    character(len=:), allocatable :: s
    integer :: k
    s = ''
    if (b%blocks(1)%kinematics /= KIN_FINITE .and. b%blocks(1)%material /= MAT_J2) return
    s = ' ('
    do k = 1, size(b%blocks)
      if (k > 1) s = s // ', '
      s = s // element_name(b%blocks(k)%etype) // ' ' // volumetric_name(b%blocks(k)%volumetric)
    end do
    s = s // ')'
  end function finite_detail

  function block_types(b) result(s)
    use raccord_model, only: body_t
    type(body_t), intent(in) :: b
    character(len=:), allocatable :: s
    integer :: k
    s = ''
    do k = 1, size(b%blocks)
      if (k > 1) s = s // '+'
      s = s // element_name(b%blocks(k)%etype)
    end do
  end function block_types

  !> ', j2: sigma_y0 = ..., H = ...' for an elastoplastic body, else ''.
  function plastic_detail(s) result(t)
    type(body_spec_t), intent(in) :: s
    character(len=:), allocatable :: t
    t = ''
    if (s%material == MAT_J2) t = ', sigma_y0 = ' // str(s%yield_stress, 4) // ', H = ' // str(s%hardening, 4)
  end function plastic_detail

  !> Wall time, speed and the final energy balance.
  !> first_step: the step this process started from (0, or the step of
  !> the checkpoint a restart continued); timings cover this process only.
  subroutine report_summary(model, state, out, pairs, first_step)
    type(model_t), intent(in) :: model
    type(state_t), intent(in) :: state
    type(output_t), intent(in) :: out
    type(contact_pair_t), intent(in) :: pairs(:)
    integer(i8), intent(in) :: first_step
    real(wp) :: wall, rate, tb, ts
    integer(i8) :: cnt, nrun
    integer :: k
    wall = wall_seconds(out)
    nrun = state%step + 1 - first_step
    if (first_step > 0) call log_info('raccord', 'restarted run: steps ' // str(first_step) // ' to ' // &
      str(state%step) // ' in this process; timings below are for them')
    call log_info('raccord', 'done: ' // str(state%step) // ' steps in ' // str(wall, 4) // ' s (' // &
      str(1.0e9_wp*wall/real(max(1_i8, nrun), wp)/real(max(1, model%nelem), wp), 3) // &
      ' ns per element per step, output included)')
    call log_info('raccord', 'energy: kinetic ' // str(state%energy%kinetic, 6) // ', internal ' // &
      str(state%energy%internal, 6) // ', external work ' // str(state%energy%external, 6) // &
      ', damping ' // str(state%energy%damping, 6) // '; balance error ' // str(state%energy%balance, 3) // &
      ' (' // str(state%energy%balance/max(state%energy%scale, tiny(1.0_wp)), 3) // ' of the largest energy)')
    if (size(pairs) > 0) call log_info('raccord', 'contact work ' // str(state%energy%contact, 6) // &
      ' (of which friction ' // str(state%energy%friction, 6) // ')')
    if (model%has_plastic) call log_info('raccord', 'plastic work ' // str(state%energy%plastic, 6) // &
      ' (j2 bodies: dissipated, and stored by hardening)')
    call system_clock(cnt, rate)
    do k = 1, size(pairs)
      tb = real(pairs(k)%clock_build, wp)/rate
      ts = real(pairs(k)%clock_solve, wp)/rate
      call log_info('raccord', 'contact pair ' // str(k) // ' (' // pairs(k)%name // '): search and matching ' // &
        str(tb, 3) // ' s (' // str(100.0_wp*tb/max(wall, tiny(1.0_wp)), 3) // ' %), multiplier solve ' // &
        str(ts, 3) // ' s (' // str(100.0_wp*ts/max(wall, tiny(1.0_wp)), 3) // ' %); ' // &
        str(real(pairs(k)%iterations_total, wp)/real(max(1_i8, pairs(k)%steps), wp), 3) // &
        ' active-set iterations per step, largest residual ' // str(pairs(k)%residual_max, 3) // ', ' // &
        str(pairs(k)%failed_total) // ' unconverged steps')
      call log_info('raccord', 'contact pair ' // str(k) // ' search: ' // search_summary(pairs(k)))
    end do
  end subroutine report_summary
end module raccord_run_report
