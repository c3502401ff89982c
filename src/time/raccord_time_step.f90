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
  implicit none
  private

  !> The time discretisation of a run.
  type, public :: time_plan_t
    real(wp) :: dt_stable = 0.0_wp     !< 2/omega_max bound
    real(wp) :: dt = 0.0_wp            !< step used
    integer(i8) :: nsteps = 0          !< steps to t_end
    real(wp) :: t_end = 0.0_wp
  end type time_plan_t

  public :: choose_time_step

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

  !> The step count t_end/dt must be a finite number that fits the step
  !> counter: above 2^53 the times n*dt of successive steps can no longer be
  !> told apart in double precision (and above 2^63 the count overflowed to
  !> one step of a dt far above the stable one).
  subroutine check_step_count(scene, ratio, dt, dt_stable, err)
    type(scene_t), intent(in) :: scene
    real(wp), intent(in) :: ratio, dt, dt_stable
    type(error_t), intent(inout) :: err
    real(wp), parameter :: max_steps = 2.0_wp**53
    if (ieee_is_finite(ratio) .and. ratio <= max_steps) return
    call raise_error(err, EXIT_INPUT, 'scene ' // scene%path // ': &time t_end = ' // str(scene%time%t_end) // &
      ' with a step of ' // str(dt) // ' (stable step ' // str(dt_stable) // ') needs ' // str(ratio) // &
      ' steps, more than the 2^53 = ' // str(max_steps) // ' a run can count: shorten t_end')
  end subroutine check_step_count
end module raccord_time_step
