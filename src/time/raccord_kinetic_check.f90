!> The quasi-static check of a mass-scaled run (issue #19; the usual check
!> of explicit quasi-static analyses): the kinetic energy should stay a
!> small fraction of the internal energy while the load acts. Each step
!> after the start-up (t >= kinetic_check_from * t_end) compares
!>   r(n) = E_kin(n) / max_{m <= n} E_int(m)                               (KC-1)
!> with &time kinetic_ratio_warn. The running maximum keeps the unloading
!> of a load cycle (E_int back to 0) from counting as dynamic; the
!> start-up is skipped because a body set in motion carries kinetic energy
!> before it has stored any. The first passage is a warning in the log
!> naming the time and the ratio; the largest ratio is reported at the end.
!> The energies are those of the scaled system (raccord_mass_scaling).
!> It only reports: the run and its results are the same with it or not.
module raccord_kinetic_check
  use raccord_kinds, only: wp
  use raccord_log, only: log_info, log_warn
  use raccord_strings, only: str
  use raccord_state, only: state_t
  implicit none
  private

  !> What the check has seen so far.
  type, public :: kinetic_check_t
    logical :: active = .false.
    real(wp) :: limit = 0.0_wp            !< kinetic_ratio_warn
    real(wp) :: t_from = 0.0_wp           !< start of the check [time]
    real(wp) :: internal_max = 0.0_wp     !< largest internal energy so far
    real(wp) :: ratio_max = 0.0_wp        !< largest (KC-1) seen
    real(wp) :: t_max = 0.0_wp            !< its time
    logical :: warned = .false.
  end type kinetic_check_t

  public :: init_kinetic_check, watch_kinetic_energy, report_kinetic_check
  public :: kinetic_check_record, restore_kinetic_check

  !> Length of the record a checkpoint keeps (kinetic_check_record).
  integer, parameter, public :: KINETIC_CHECK_LENGTH = 4

contains

  !> Active when the model is mass scaled and the limit is positive.
  subroutine init_kinetic_check(check, scaled, limit, from, t_end)
    type(kinetic_check_t), intent(out) :: check
    logical, intent(in) :: scaled
    real(wp), intent(in) :: limit, from, t_end
    check%active = scaled .and. limit > 0.0_wp
    check%limit = limit
    check%t_from = from*t_end
  end subroutine init_kinetic_check

  !> (KC-1) at t(n), after the energy account of the step.
  subroutine watch_kinetic_energy(check, state)
    type(kinetic_check_t), intent(inout) :: check
    type(state_t), intent(in) :: state
    real(wp) :: r
    check%internal_max = max(check%internal_max, state%energy%internal)
    if (state%time < check%t_from .or. .not. (check%internal_max > 0.0_wp)) return
    r = state%energy%kinetic/check%internal_max
    if (r > check%ratio_max) then
      check%ratio_max = r
      check%t_max = state%time
    end if
    if (r > check%limit .and. .not. check%warned) then
      check%warned = .true.
      call log_warn('kinetic_check', 'quasi-static check failed at t = ' // str(state%time, 6) // ' (step ' // &
        str(state%step) // '): kinetic energy ' // str(state%energy%kinetic, 4) // ' is ' // str(r, 3) // &
        ' of the internal energy ' // str(check%internal_max, 4) // ', above &time kinetic_ratio_warn = ' // &
        str(check%limit, 3) // ': inertia matters in this run, so the mass scaling changes the answer; ' // &
        'lower mass_scaling_dt / mass_scaling_factor or load more slowly')
    end if
  end subroutine watch_kinetic_energy

  !> What the check has seen, for a checkpoint: a restarted run goes on
  !> with the running maximum (KC-1) and the warning of the run before.
  pure function kinetic_check_record(check) result(r)
    type(kinetic_check_t), intent(in) :: check
    real(wp) :: r(KINETIC_CHECK_LENGTH)
    r = [check%internal_max, check%ratio_max, check%t_max, merge(1.0_wp, 0.0_wp, check%warned)]
  end function kinetic_check_record

  !> The inverse of kinetic_check_record, after init_kinetic_check.
  subroutine restore_kinetic_check(check, r)
    type(kinetic_check_t), intent(inout) :: check
    real(wp), intent(in) :: r(KINETIC_CHECK_LENGTH)
    check%internal_max = r(1)
    check%ratio_max = r(2)
    check%t_max = r(3)
    check%warned = r(4) > 0.5_wp
  end subroutine restore_kinetic_check

  !> The largest ratio of the run, at its end.
  subroutine report_kinetic_check(check)
    type(kinetic_check_t), intent(in) :: check
    if (.not. check%active) return
    call log_info('kinetic_check', 'quasi-static check: largest kinetic / internal energy ' // &
      str(check%ratio_max, 3) // ' at t = ' // str(check%t_max, 6) // ' (limit ' // str(check%limit, 3) // &
      ', from t = ' // str(check%t_from, 6) // '): ' // trim(merge('exceeded', 'passed  ', check%warned)))
  end subroutine report_kinetic_check
end module raccord_kinetic_check
