!> When the time loop stops to write a checkpoint (doc/hpc.md, section 10):
!> periodically every &run checkpoint_every steps; and, with exit 5, on a
!> stop signal (raccord_signals) or when the wall-clock limit is near.
!>
!> The limit counts wall seconds from the start of the process (what a batch
!> scheduler counts). "Near" means that the next step and the checkpoint
!> might not fit before it:
!>   elapsed + 2 t_step + t_write >= limit,
!> with t_step the longest step seen so far in this process (a step that
!> writes a result frame included) and t_write the longest checkpoint write
!> so far, or t_step before the first one (a frame, written at step 0, is
!> larger than a checkpoint). The estimate is measured, not guessed, and
!> errs on the early side.
module raccord_run_control
  use raccord_kinds, only: wp, i8
  use raccord_strings, only: str
  use raccord_signals, only: stop_signal, signal_name
  implicit none
  private

  type, public :: run_control_t
    real(wp) :: limit = 0.0_wp                    !< wall seconds; 0 = no limit
    character(len=:), allocatable :: limit_source !< where the limit came from, for messages
    integer(i8) :: every = 0                      !< steps between periodic checkpoints; 0 = none
    integer(i8) :: clock_start = 0, clock_rate = 1, clock_last = 0
    real(wp) :: step_max = 0.0_wp                 !< longest step in this process [s]
    real(wp) :: write_max = 0.0_wp                !< longest checkpoint write [s]
    integer :: checkpoints = 0                    !< checkpoints written by this process
  end type run_control_t

  public :: start_run_control, set_run_limits, note_step, must_stop, stop_reason, checkpoint_due, &
    note_checkpoint, elapsed_seconds

contains

  !> Start the clock (at the start of the process).
  subroutine start_run_control(ctl)
    type(run_control_t), intent(out) :: ctl
    call system_clock(ctl%clock_start, ctl%clock_rate)
    ctl%clock_last = ctl%clock_start
  end subroutine start_run_control

  !> The wall-clock limit (0 = none) and the checkpoint interval in steps.
  subroutine set_run_limits(ctl, limit, source, every)
    type(run_control_t), intent(inout) :: ctl
    real(wp), intent(in) :: limit
    character(len=*), intent(in) :: source
    integer, intent(in) :: every
    ctl%limit = max(0.0_wp, limit)
    ctl%limit_source = source
    ctl%every = int(max(0, every), i8)
  end subroutine set_run_limits

  !> A step ended: measure it. The first call measures from the start of
  !> the time loop (note_step is called once just before it).
  subroutine note_step(ctl)
    type(run_control_t), intent(inout) :: ctl
    integer(i8) :: now
    call system_clock(now)
    ctl%step_max = max(ctl%step_max, real(now - ctl%clock_last, wp)/real(ctl%clock_rate, wp))
    ctl%clock_last = now
  end subroutine note_step

  !> The run must stop now, with a checkpoint: a stop signal came, or the
  !> wall-clock limit is near. Cheap and allocation-free: called every step.
  logical function must_stop(ctl)
    type(run_control_t), intent(in) :: ctl
    must_stop = stop_signal() /= 0
    if (must_stop .or. ctl%limit <= 0.0_wp) return
    must_stop = elapsed_seconds(ctl) + margin_seconds(ctl) >= ctl%limit
  end function must_stop

  !> Why must_stop is true, for the log and the results' /status.
  function stop_reason(ctl) result(reason)
    type(run_control_t), intent(in) :: ctl
    character(len=:), allocatable :: reason
    real(wp) :: elapsed, margin
    reason = ''
    if (stop_signal() /= 0) then
      reason = signal_name(stop_signal()) // ' received'
      return
    end if
    if (ctl%limit <= 0.0_wp) return
    elapsed = elapsed_seconds(ctl)
    margin = margin_seconds(ctl)
    if (elapsed + margin >= ctl%limit) reason = 'wall-clock limit ' // str(ctl%limit, 6) // ' s (' // &
      ctl%limit_source // ') near: ' // str(elapsed, 4) // ' s elapsed, next step and checkpoint take up to ' // &
      str(margin, 3) // ' s'
  end function stop_reason

  !> 2 t_step + t_write (t_step before the first checkpoint).
  pure real(wp) function margin_seconds(ctl)
    type(run_control_t), intent(in) :: ctl
    margin_seconds = 2.0_wp*ctl%step_max + merge(ctl%write_max, ctl%step_max, ctl%checkpoints > 0)
  end function margin_seconds

  !> A periodic checkpoint is due at the start of this step.
  pure logical function checkpoint_due(ctl, step)
    type(run_control_t), intent(in) :: ctl
    integer(i8), intent(in) :: step
    checkpoint_due = .false.
    if (ctl%every > 0) checkpoint_due = mod(step, ctl%every) == 0
  end function checkpoint_due

  !> A checkpoint was written, taking `seconds`; the step clock restarts
  !> after it so the write does not count as a step.
  subroutine note_checkpoint(ctl, seconds)
    type(run_control_t), intent(inout) :: ctl
    real(wp), intent(in) :: seconds
    ctl%write_max = max(ctl%write_max, seconds)
    ctl%checkpoints = ctl%checkpoints + 1
    call system_clock(ctl%clock_last)
  end subroutine note_checkpoint

  !> Wall seconds since start_run_control.
  real(wp) function elapsed_seconds(ctl)
    type(run_control_t), intent(in) :: ctl
    integer(i8) :: now
    call system_clock(now)
    elapsed_seconds = real(now - ctl%clock_start, wp)/real(ctl%clock_rate, wp)
  end function elapsed_seconds
end module raccord_run_control
