!> The progress line of a running job in the log (step, share done,
!> time, time to go, energy balance) and the clock behind it.
module raccord_output_progress
  use raccord_kinds, only: wp, i8
  use raccord_log, only: log_info
  use raccord_state, only: state_t
  use raccord_output_state, only: output_t
  implicit none
  private

  public :: log_progress, eta_seconds, wall_seconds

contains

  subroutine log_progress(out, state)
    type(output_t), intent(in) :: out
    type(state_t), intent(in) :: state
    real(wp) :: elapsed, frac, eta
    character(len=160) :: line
    elapsed = wall_seconds(out)
    frac = real(state%step, wp)/real(max(1_i8, state%nsteps), wp)
    eta = eta_seconds(elapsed, out%first_step, state%step, state%nsteps)
    write(line, '(a,i0,a,i0,a,f5.1,a,es11.4,a,a,a,es9.2)') 'step ', state%step, '/', state%nsteps, ' (', &
      100.0_wp*frac, ' %)  t = ', state%time, '  ETA ', hms(eta), '  energy balance ', &
      state%energy%balance/max(state%energy%scale, tiny(1.0_wp))
    call log_info('progress', trim(line))
  end subroutine log_progress

  !> Time to go at the rate of this process: `elapsed` wall seconds for the
  !> steps first_step .. step, nsteps in all. After a restart first_step is
  !> the checkpoint's step: the steps done before it took no time here
  !> (counting them made the estimate 3-5 times too short). 0 before any
  !> step of this process is done.
  pure real(wp) function eta_seconds(elapsed, first_step, step, nsteps) result(eta)
    real(wp), intent(in) :: elapsed
    integer(i8), intent(in) :: first_step, step, nsteps
    eta = 0.0_wp
    if (step > first_step) eta = elapsed*real(nsteps - step, wp)/real(step - first_step, wp)
  end function eta_seconds

  !> Wall seconds since the outputs were opened.
  real(wp) function wall_seconds(out)
    type(output_t), intent(in) :: out
    integer(i8) :: now
    call system_clock(now)
    wall_seconds = real(now - out%clock_start, wp)/real(out%clock_rate, wp)
  end function wall_seconds

  pure function hms(seconds) result(s)
    real(wp), intent(in) :: seconds
    character(len=8) :: s
    integer :: t
    t = nint(seconds)
    write(s, '(i2.2,":",i2.2,":",i2.2)') min(99, t/3600), mod(t/60, 60), mod(t, 60)
  end function hms
end module raccord_output_progress
