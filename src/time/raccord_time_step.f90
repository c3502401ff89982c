!> Choice of the time step: the stable step of the central-difference
!> scheme, dt <= 2/omega_max, with omega_max^2 bounded above by the largest
!> element eigenvalue of (Ke, Me) (element eigenvalue theorem; method brief
!> section 2). Lagrange-multiplier contact adds no stiffness, so contact does
!> not shrink the step.
module raccord_time_step
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use raccord_kinds, only: wp, i8
  use raccord_error, only: error_t, raise_error, EXIT_INPUT
  use raccord_strings, only: str
  use raccord_model, only: model_t
  use raccord_scene, only: scene_t
  use raccord_state, only: state_t
  use raccord_material, only: KIN_FINITE, MAT_SVK
  use raccord_elastic_block, only: watch_w2, watch_inverted
  use raccord_finite_kernel, only: block_chunk_len => fin_chunk_len
  use raccord_error, only: EXIT_NUMERIC
  implicit none
  private

  !> The time discretisation of a run.
  type, public :: time_plan_t
    real(wp) :: dt_stable = 0.0_wp     !< 2/omega_max bound
    real(wp) :: dt = 0.0_wp            !< step used
    integer(i8) :: nsteps = 0          !< steps to t_end
    real(wp) :: t_end = 0.0_wp
  end type time_plan_t

  public :: choose_time_step, adapt_time_step, check_deformation

contains

  !> dt = t_end / ceil(t_end / (safety*dt_stable)) when the scene leaves dt
  !> at 0, so the run ends exactly at t_end with dt <= safety*dt_stable;
  !> a fixed dt above dt_stable is refused with both figures.
  subroutine choose_time_step(scene, model, plan, err)
    type(scene_t), intent(in) :: scene
    type(model_t), intent(in) :: model
    type(time_plan_t), intent(out) :: plan
    type(error_t), intent(inout) :: err
    real(wp) :: target

    plan%t_end = scene%time%t_end
    if (.not. ieee_is_finite(model%w2_bound)) then
      call raise_error(err, EXIT_INPUT, 'scene ' // scene%path // ': the stable time step cannot be computed, ' // &
        'the largest element eigenvalue is ' // str(model%w2_bound) // ': check the &body young and density ' // &
        'and the &mesh scale (units of the mesh and the deck)')
      return
    end if
    if (model%w2_bound <= 0.0_wp) then
      call raise_error(err, EXIT_INPUT, 'scene ' // scene%path // ': the model has no stiffness ' // &
        '(no element in any &body); check the &body element sets.')
      return
    end if
    plan%dt_stable = 2.0_wp/sqrt(model%w2_bound)
    if (scene%time%dt > 0.0_wp) then
      if (scene%time%dt > plan%dt_stable) then
        call raise_error(err, EXIT_INPUT, 'scene ' // scene%path // ': &time dt = ' // str(scene%time%dt) // &
          ' exceeds the stable time step ' // str(plan%dt_stable) // ' of this mesh and material ' // &
          '(2/omega_max from the element eigenvalue bound). Set dt <= ' // str(plan%dt_stable) // &
          ', or dt = 0 to use safety * stable step.')
        return
      end if
      target = scene%time%dt
      call check_step_count(scene, plan%t_end/target, target, plan%dt_stable, err)
      if (err%failed()) return
      plan%nsteps = max(1_i8, nint(plan%t_end/target, i8))
      ! A fixed dt is kept as given; the run stops at the step nearest to t_end.
      plan%dt = target
    else
      target = scene%time%safety*plan%dt_stable
      call check_step_count(scene, plan%t_end/target, target, plan%dt_stable, err)
      if (err%failed()) return
      plan%nsteps = max(1_i8, ceiling(plan%t_end/target, i8))
      plan%dt = plan%t_end/real(plan%nsteps, wp)
    end if
  end subroutine choose_time_step

  !> Stable step on the deforming mesh (finite-strain bodies; method brief
  !> 5.1-5.3): after the forces at t(n), the next step is
  !>   dt(n+1/2) = (t_end - t(n)) / k,  k = ceil((t_end - t(n)) / target),
  !>   target = min(dt_plan, safety * 2 / omega_max(u(n))),
  !> omega_max^2 the largest of the small-strain bodies' fixed bound and the
  !> finite-strain blocks' current estimates 4 c^2 / L^2 (current length and
  !> wave speed). The run still ends exactly at t_end; nsteps becomes n + k.
  !> A step that collapses below 1e-6 of the plan's stops the run (exit 3):
  !> an element is about to invert. Does nothing without finite bodies.
  subroutine adapt_time_step(model, state, err)
    type(model_t), intent(in) :: model
    type(state_t), intent(inout) :: state
    type(error_t), intent(inout) :: err
    real(wp) :: w2, target, remaining
    integer(i8) :: k
    integer :: ib, kb
    if (.not. state%adaptive) return
    if (state%step >= state%nsteps) return
    w2 = model%w2_small
    do ib = 1, size(model%bodies)
      do kb = 1, size(model%bodies(ib)%blocks)
        if (model%bodies(ib)%blocks(kb)%kinematics == KIN_FINITE) w2 = max(w2, watch_w2(state%watch(kb, ib)))
      end do
    end do
    target = state%dt_plan
    if (w2 > 0.0_wp) target = min(target, state%safety*2.0_wp/sqrt(w2))
    if (.not. (target >= 1.0e-4_wp*state%dt_plan)) then
      call raise_error(err, EXIT_NUMERIC, 'the stable time step fell to ' // str(target) // ' at t = ' // &
        str(state%time) // ' (step ' // str(state%step) // '), below 1e-4 of the planned ' // str(state%dt_plan) // &
        ': ' // most_compressed(model, state) // ' is collapsing. Refine the mesh where the deformation ' // &
        'concentrates, lower the load or its rate, or check the supports')
      return
    end if
    remaining = state%t_end - state%time
    k = max(1_i8, ceiling(remaining/target, i8))
    state%dt_prev = state%dt
    state%dt = remaining/real(k, wp)
    state%nsteps = state%step + k
  end subroutine adapt_time_step

  !> 'element <id> of body '<name>' (J = <smallest J>)': the finite-strain
  !> element with the smallest J at the last forces.
  function most_compressed(model, state) result(s)
    type(model_t), intent(in) :: model
    type(state_t), intent(in) :: state
    character(len=:), allocatable :: s
    real(wp) :: jmin, jb
    integer :: ib, k, c, e
    s = 'an element'
    jmin = huge(1.0_wp)
    do ib = 1, size(model%bodies)
      do k = 1, size(model%bodies(ib)%blocks)
        if (model%bodies(ib)%blocks(k)%kinematics /= KIN_FINITE) cycle
        associate (w => state%watch(k, ib))
          c = minloc(w%jmin, 1)
          jb = w%jmin(c)
          if (jb < jmin .and. w%jmin_el(c) > 0) then
            jmin = jb
            e = (c - 1)*block_chunk_len + w%jmin_el(c)
            s = 'element ' // str(model%bodies(ib)%blocks(k)%ids(e)) // ' of body ''' // model%bodies(ib)%name // &
              ''' (J = ' // str(jb, 4) // ')'
          end if
        end associate
      end do
    end do
  end function most_compressed

  !> An inverted element (J <= 0 at a Gauss point) of a finite-strain body
  !> stops the run (exit 3), naming the element, its body and the time.
  subroutine check_deformation(model, state, err)
    type(model_t), intent(in) :: model
    type(state_t), intent(in) :: state
    type(error_t), intent(inout) :: err
    integer :: ib, k, e
    real(wp) :: jmin
    character(len=:), allocatable :: hint
    do ib = 1, size(model%bodies)
      do k = 1, size(model%bodies(ib)%blocks)
        if (model%bodies(ib)%blocks(k)%kinematics /= KIN_FINITE) cycle
        call watch_inverted(state%watch(k, ib), e, jmin)
        if (e == 0) cycle
        hint = ''
        if (model%bodies(ib)%blocks(k)%material == MAT_SVK) hint = ', or use neo_hooke: svk softens and ' // &
          'collapses in strong compression'
        call raise_error(err, EXIT_NUMERIC, 'element ' // str(model%bodies(ib)%blocks(k)%ids(e)) // &
          ' of body ''' // model%bodies(ib)%name // ''' inverted (J = ' // str(jmin, 4) // &
          ' <= 0 at a Gauss point) at t = ' // str(state%time) // ' (step ' // str(state%step) // &
          '). The deformation is beyond what the mesh can follow: refine it there, lower the load or ' // &
          'its rate, or make the softer surface the contact slave' // hint)
        return
      end do
    end do
  end subroutine check_deformation

  !> The step count t_end/dt must be a finite number that fits the step
  !> counter: above 2^53 the times n*dt of successive steps can no longer be
  !> told apart in double precision (and above 2^63 the count overflowed to
  !> one step of a dt far above the stable one).
  subroutine check_step_count(scene, ratio, dt, dt_stable, err)
    type(scene_t), intent(in) :: scene
    real(wp), intent(in) :: ratio, dt, dt_stable
    type(error_t), intent(inout) :: err
    real(wp), parameter :: max_steps = 2.0_wp**53
    character(len=:), allocatable :: fix
    if (ieee_is_finite(ratio) .and. ratio <= max_steps) return
    ! Say which of t_end, dt, safety or the stable step itself is off
    ! ("shorten t_end" alone misled when dt = 1e-320 or safety = 1e-300).
    if (scene%time%dt > 0.0_wp) then
      fix = 'shorten t_end, or give a larger &time dt (at most the stable step ' // str(dt_stable) // &
        '; dt = 0 takes safety * the stable step)'
    else if (scene%time%t_end / dt_stable <= max_steps) then
      fix = 'raise &time safety (now ' // str(scene%time%safety) // '; the default 0.9 is usual), or shorten t_end'
    else
      fix = 'shorten t_end (even safety = 1 would not do: if t_end is right, the stable step is too small for ' // &
        'it: check the units of young, density and &mesh scale, and the smallest element of the mesh)'
    end if
    call raise_error(err, EXIT_INPUT, 'scene ' // scene%path // ': &time t_end = ' // str(scene%time%t_end) // &
      ' with a step of ' // str(dt) // ' (stable step ' // str(dt_stable) // ') needs ' // str(ratio) // &
      ' steps, more than the 2^53 = ' // str(max_steps) // ' a run can count: ' // fix)
  end subroutine check_step_count
end module raccord_time_step
