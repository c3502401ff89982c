!> Watch on the energy contact gives to the bodies (doc/theory-contact.md,
!> section 7). Forward-increment contact closes gaps perfectly inelastically
!> and so takes energy out; it puts energy in only where the constraint
!> rows do not follow the surfaces (a node pushed out of a surface it was
!> found inside of). Some of that is inherent to moving, curved, faceted
!> surfaces; growth is not. The energy given is
!>   E_given = -(W_c - W_c,0)
!> with W_c the contact work of the energy account and W_c,0 the work of
!> the first step when negative: contact at t = 0 can only push out an
!> overlap of the initial configuration (forward increment: the gap is
!> closed at t(1)), which the overlap warning reports on its own, and the
!> energy scale is then that of the push-out alone. The run warns once, in the log, when
!> E_given passes CONTACT_ENERGY_WARN times the energy scale (the largest
!> magnitude of any term of the energy account so far), and the summary
!> reports the largest fraction seen.
module raccord_contact_energy
  use raccord_kinds, only: wp
  use raccord_log, only: log_warn, log_info
  use raccord_strings, only: str
  use raccord_state, only: state_t
  use raccord_contact_pair, only: contact_pair_t
  use raccord_scene, only: METHOD_MORTAR
  implicit none
  private

  !> Fraction of the energy scale above which the run warns.
  real(wp), parameter, public :: CONTACT_ENERGY_WARN = 1.0e-2_wp

  !> What the watch has seen (kept by a checkpoint: contact_watch_record).
  type, public :: contact_energy_watch_t
    logical :: warned = .false.
    real(wp) :: worst = 0.0_wp        !< largest E_given / scale seen
    real(wp) :: worst_time = 0.0_wp   !< when
    real(wp) :: worst_given = 0.0_wp  !< E_given then
    real(wp) :: base = 0.0_wp         !< W_c,0: the first step's contact work, when negative
  end type contact_energy_watch_t

  public :: watch_contact_energy, report_contact_energy, contact_energy_given
  public :: contact_watch_record, restore_contact_watch

  !> Length of the record a checkpoint keeps (contact_watch_record).
  integer, parameter, public :: CONTACT_WATCH_LENGTH = 5

contains

  !> Energy contact has given to the bodies so far (E_given above; <= 0
  !> when contact has taken energy out).
  pure real(wp) function contact_energy_given(state, watch) result(given)
    type(state_t), intent(in) :: state
    type(contact_energy_watch_t), intent(in) :: watch
    given = -(state%energy%contact - watch%base)
  end function contact_energy_given

  !> After the energy account of a step: update the watch, warn the first
  !> time the threshold is passed.
  subroutine watch_contact_energy(pairs, state, watch)
    type(contact_pair_t), intent(in) :: pairs(:)
    type(state_t), intent(in) :: state
    type(contact_energy_watch_t), intent(inout) :: watch
    real(wp) :: given, frac
    if (size(pairs) == 0) return
    if (state%step == 0) watch%base = min(0.0_wp, state%energy%contact)
    if (state%energy%scale <= 0.0_wp) return
    given = contact_energy_given(state, watch)
    if (given <= 0.0_wp) return
    frac = given/state%energy%scale
    if (frac > watch%worst) then
      watch%worst = frac
      watch%worst_time = state%time
      watch%worst_given = given
    end if
    if (.not. watch%warned .and. frac > CONTACT_ENERGY_WARN) then
      watch%warned = .true.
      call log_warn('contact', 'contact has given the bodies ' // str(given, 3) // ' of energy by t = ' // &
        str(state%time) // ' (step ' // str(state%step) // '), ' // str(frac, 3) // ' of the energy scale ' // &
        str(state%energy%scale, 3) // ' (threshold ' // str(CONTACT_ENERGY_WARN, 2) // '). The energy ' // &
        'balance still closes: this energy is in the kinetic and internal energy and is not physical. ' // &
        'Refine the surfaces or make the finer or softer surface the slave' // trim(weighted_advice(pairs)) // &
        ' (doc/theory-contact.md, section 7).')
    end if
  end subroutine watch_contact_energy

  !> For a scene with a mortar pair under the paper's nodal conditions: the
  !> pair key that gives no energy from them (doc/scene-reference.md).
  function weighted_advice(pairs) result(s)
    type(contact_pair_t), intent(in) :: pairs(:)
    character(len=:), allocatable :: s
    integer :: k
    s = ''
    do k = 1, size(pairs)
      if (pairs(k)%method == METHOD_MORTAR .and. .not. pairs(k)%weighted) then
        s = '; for mortar pair ' // str(k) // ' (' // pairs(k)%name // '), conditions = ''weighted'' ' // &
          'takes out the energy of a curved or Q8 slave and of sliding'
        return
      end if
    end do
  end function weighted_advice

  !> What the watch has seen, for a checkpoint: a restarted run reports
  !> the largest energy given over the whole run, and warns once.
  pure function contact_watch_record(watch) result(r)
    type(contact_energy_watch_t), intent(in) :: watch
    real(wp) :: r(CONTACT_WATCH_LENGTH)
    r = [merge(1.0_wp, 0.0_wp, watch%warned), watch%worst, watch%worst_time, watch%worst_given, watch%base]
  end function contact_watch_record

  !> The inverse of contact_watch_record.
  subroutine restore_contact_watch(watch, r)
    type(contact_energy_watch_t), intent(inout) :: watch
    real(wp), intent(in) :: r(CONTACT_WATCH_LENGTH)
    watch%warned = r(1) > 0.5_wp
    watch%worst = r(2)
    watch%worst_time = r(3)
    watch%worst_given = r(4)
    watch%base = r(5)
  end subroutine restore_contact_watch

  !> The summary line (and the warning again if the threshold was passed).
  subroutine report_contact_energy(pairs, state, watch)
    type(contact_pair_t), intent(in) :: pairs(:)
    type(state_t), intent(in) :: state
    type(contact_energy_watch_t), intent(in) :: watch
    if (size(pairs) == 0) return
    if (watch%warned) then
      call log_warn('contact', 'contact gave the bodies energy: at most ' // str(watch%worst_given, 3) // &
        ' (' // str(watch%worst, 3) // ' of the energy scale, threshold ' // str(CONTACT_ENERGY_WARN, 2) // &
        ') at t = ' // str(watch%worst_time) // '; at the end ' // str(contact_energy_given(state, watch), 3) // &
        '. The results are suspect where it happened' // trim(weighted_advice(pairs)) // &
        ' (doc/theory-contact.md, section 7).')
    else
      call log_info('raccord', 'energy given by contact: at most ' // str(watch%worst, 3) // &
        ' of the energy scale (warning above ' // str(CONTACT_ENERGY_WARN, 2) // ')')
    end if
  end subroutine report_contact_energy
end module raccord_contact_energy
