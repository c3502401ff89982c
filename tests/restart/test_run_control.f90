!> When a run stops to write a checkpoint: the wall-clock margin
!> (elapsed + 2 t_step + t_write >= limit, raccord_run_control), periodic
!> checkpoints, stop signals caught by the bind(C) handler (raised here
!> with the C library's raise), and which scene keys a restart may change.
program test_run_control
  use raccord_check, only: failure_t, new_test, run_tests, check
  implicit none

  call run_tests('restart_run_control', [ &
    new_test('wall clock: stops when the next step and a checkpoint may not fit', test_margin), &
    new_test('wall clock: no limit never stops', test_no_limit), &
    new_test('periodic checkpoints at multiples of checkpoint_every', test_periodic), &
    new_test('scene identity ignores only the keys that do not change results', test_identity), &
    new_test('SIGUSR1 and SIGTERM set the stop flag (handler via signal())', test_signals)])

contains

  !> Pretend the process started `ago` seconds before now.
  subroutine set_elapsed(ctl, ago)
    use raccord_kinds, only: wp, i8
    use raccord_run_control, only: run_control_t
    type(run_control_t), intent(inout) :: ctl
    real(wp), intent(in) :: ago
    integer(i8) :: now
    call system_clock(now)
    ctl%clock_start = now - int(ago*real(ctl%clock_rate, wp), i8)
  end subroutine set_elapsed

  subroutine test_margin(failure)
    use raccord_kinds, only: wp
    use raccord_run_control, only: run_control_t, start_run_control, set_run_limits, stop_reason, note_checkpoint, &
      must_stop
    type(failure_t), allocatable, intent(out) :: failure
    type(run_control_t) :: ctl
    call start_run_control(ctl)
    call set_run_limits(ctl, 10.0_wp, 'test', 0)
    call set_elapsed(ctl, 9.5_wp)
    ! 9.5 s elapsed, steps of 0.1 s: 9.5 + 3 x 0.1 = 9.8 < 10, go on.
    ctl%step_max = 0.1_wp
    call check(failure, len(stop_reason(ctl)) == 0 .and. .not. must_stop(ctl), '9.5 s + 3 x 0.1 s < 10 s: must go on')
    ! Steps of 0.2 s: 9.5 + 0.6 >= 10, stop, and the reason says so.
    ctl%step_max = 0.2_wp
    call check(failure, must_stop(ctl), '9.5 s + 3 x 0.2 s >= 10 s: must_stop')
    call check(failure, index(stop_reason(ctl), 'wall-clock limit 10 s (test) near') == 1, &
      '9.5 s + 3 x 0.2 s >= 10 s: must stop; got "' // stop_reason(ctl) // '"')
    ! After a checkpoint that took 0.05 s, the write time is measured: 9.5 + 0.4 + 0.05 < 10.
    call note_checkpoint(ctl, 0.05_wp)
    call check(failure, len(stop_reason(ctl)) == 0, 'with a measured 0.05 s checkpoint: must go on')
    call note_checkpoint(ctl, 0.2_wp)
    call check(failure, len(stop_reason(ctl)) > 0, 'with a measured 0.2 s checkpoint: must stop')
  end subroutine test_margin

  subroutine test_no_limit(failure)
    use raccord_kinds, only: wp
    use raccord_run_control, only: run_control_t, start_run_control, set_run_limits, stop_reason
    type(failure_t), allocatable, intent(out) :: failure
    type(run_control_t) :: ctl
    call start_run_control(ctl)
    call set_run_limits(ctl, 0.0_wp, 'none', 0)
    call set_elapsed(ctl, 1.0e6_wp)
    ctl%step_max = 100.0_wp
    call check(failure, len(stop_reason(ctl)) == 0, 'limit 0 means none')
  end subroutine test_no_limit

  subroutine test_periodic(failure)
    use raccord_kinds, only: wp, i8
    use raccord_run_control, only: run_control_t, start_run_control, set_run_limits, checkpoint_due
    type(failure_t), allocatable, intent(out) :: failure
    type(run_control_t) :: ctl
    call start_run_control(ctl)
    call set_run_limits(ctl, 0.0_wp, 'none', 100)
    call check(failure, checkpoint_due(ctl, 100_i8) .and. checkpoint_due(ctl, 300_i8), 'due at 100 and 300')
    call check(failure, .not. (checkpoint_due(ctl, 150_i8) .or. checkpoint_due(ctl, 1_i8)), 'not due at 150 or 1')
    call set_run_limits(ctl, 0.0_wp, 'none', 0)
    call check(failure, .not. checkpoint_due(ctl, 100_i8), 'checkpoint_every = 0: never due')
  end subroutine test_periodic

  subroutine test_identity(failure)
    use raccord_kinds, only: wp
    use raccord_error, only: error_t
    use raccord_scene, only: scene_t
    use raccord_checkpoint, only: scene_identity
    type(failure_t), allocatable, intent(out) :: failure
    type(scene_t) :: a, b
    type(error_t) :: err
    character(len=:), allocatable :: ia, ib
    a%path = 'one/deck.nml'
    a%run%title = 'identity'
    a%run%output_dir = 'out/a'
    a%time%t_end = 1.0_wp
    allocate(a%bodies(0), a%bcs(0), a%amplitudes(0), a%contacts(0))
    b = a
    b%path = 'two/deck.nml'
    b%run%output_dir = 'elsewhere'
    b%run%wall_clock = 3600.0_wp
    b%run%checkpoint_every = 50
    b%output%progress_seconds = 1.0_wp
    ia = scene_identity(a, err)
    ib = scene_identity(b, err)
    call check(failure, .not. err%failed(), 'scene_identity failed')
    call check(failure, ia == ib, 'output_dir, wall_clock, checkpoint_every, progress_seconds, deck path ignored')
    call check(failure, index(ia, 't_end = 1.0') > 0 .and. index(ia, 'title') > 0, 'the identity holds the keys')
    b%time%t_end = 2.0_wp
    call check(failure, scene_identity(b, err) /= ia, 't_end changed: different identity')
    b = a
    b%output%frames = 7
    call check(failure, scene_identity(b, err) /= ia, 'frames changed: different identity')
  end subroutine test_identity

  subroutine test_signals(failure)
    use, intrinsic :: iso_c_binding, only: c_int
    use raccord_error, only: error_t
    use raccord_signals, only: install_stop_signals, stop_signal, signal_name, SIGTERM, SIGUSR1
    use raccord_run_control, only: run_control_t, start_run_control, stop_reason
    type(failure_t), allocatable, intent(out) :: failure
    type(error_t) :: err
    type(run_control_t) :: ctl
    interface
      function c_raise(sig) bind(C, name='raise') result(rc)
        import :: c_int
        integer(c_int), value :: sig
        integer(c_int) :: rc
      end function c_raise
    end interface
    call start_run_control(ctl)
    call check(failure, stop_signal() == 0, 'no signal yet')
    call install_stop_signals(err)
    call check(failure, .not. err%failed(), 'install_stop_signals failed')
    ! Without the handler SIGUSR1 would end this test process.
    call check(failure, c_raise(SIGUSR1) == 0, 'raise(SIGUSR1) failed')
    call check(failure, stop_signal() == int(SIGUSR1), 'SIGUSR1 not caught')
    call check(failure, stop_reason(ctl) == 'SIGUSR1 received', 'stop reason: "' // stop_reason(ctl) // '"')
    call check(failure, c_raise(SIGTERM) == 0, 'raise(SIGTERM) failed')
    call check(failure, stop_signal() == int(SIGTERM), 'SIGTERM not caught (the handler stays installed)')
    call check(failure, signal_name(int(SIGTERM)) == 'SIGTERM' .and. signal_name(3) == 'signal 3', 'signal names')
  end subroutine test_signals
end program test_run_control
