!> Scene deck reader, the groups that say how the run goes rather than what
!> is simulated: &run (name, output folder, wall-clock limit, checkpoints),
!> &time (duration, step, damping) and &output (what is written, how often).
!> Split from raccord_deck, which calls these; messages follow its form
!>   <deck>:<line>: &<group>: <what is wrong>; <how to fix it>
module raccord_deck_run
  use raccord_kinds, only: wp, path_len
  use raccord_error, only: error_t
  use raccord_strings, only: str
  use raccord_deck_scan, only: deck_block_t
  use raccord_deck_checks, only: check_keys, unreadable, bad_value, missing_key, check_length, check_finite, UNSET
  use raccord_scene, only: run_spec_t, time_spec_t, output_spec_t
  implicit none
  private

  public :: read_run, read_time, read_output

  !> Keys of each group, in the order the documentation and the echo use.
  character(len=*), parameter :: RUN_KEYS(*) = [character(len=16) :: 'title', 'output_dir', 'wall_clock', &
    'checkpoint_every']
  character(len=*), parameter :: TIME_KEYS(*) = [character(len=19) :: 't_end', 'dt', 'safety', 'damping', &
    'mass_scaling_dt', 'mass_scaling_factor', 'added_mass_warn', 'kinetic_ratio_warn', 'kinetic_check_from']
  character(len=*), parameter :: OUTPUT_KEYS(*) = [character(len=16) :: 'frames', 'history_every', &
    'progress_seconds', 'stress']

contains

  !> &run title, output_dir, wall_clock, checkpoint_every.
  subroutine read_run(deck, blk, stem, spec, err)
    character(len=*), intent(in) :: deck, stem
    type(deck_block_t), intent(in) :: blk
    type(run_spec_t), intent(inout) :: spec
    type(error_t), intent(inout) :: err
    character(len=path_len) :: title, output_dir
    real(wp) :: wall_clock
    integer :: checkpoint_every
    namelist /run/ title, output_dir, wall_clock, checkpoint_every
    character(len=:), allocatable :: record
    character(len=256) :: msg
    integer :: k, ios

    title = stem
    output_dir = ''
    wall_clock = spec%wall_clock
    checkpoint_every = spec%checkpoint_every
    call check_keys(deck, blk, RUN_KEYS, '', err)
    if (err%failed()) return
    do k = 1, size(blk%keys)
      record = blk%item(k)
      msg = ''
      read(record, nml=run, iostat=ios, iomsg=msg)
      if (ios /= 0) then
        call unreadable(deck, blk, k, '', msg, err)
        return
      end if
    end do
    call check_length(deck, blk, '', 'title', title, err)
    call check_length(deck, blk, '', 'output_dir', output_dir, err)
    call check_finite(deck, blk, '', ['wall_clock'], [wall_clock], err)
    if (err%failed()) return
    if (.not. (wall_clock >= 0.0_wp)) then
      call bad_value(deck, blk, '', 'wall_clock', 'the wall-clock limit must be >= 0', &
        'give the seconds the run may take before it writes a checkpoint and stops, or 0 for no limit', err)
    else if (checkpoint_every < 0) then
      call bad_value(deck, blk, '', 'checkpoint_every', 'the checkpoint interval must be >= 0', &
        'give the number of steps between checkpoints, or 0 for none', err)
    end if
    if (err%failed()) return
    spec%title = trim(title)
    spec%wall_clock = wall_clock
    spec%checkpoint_every = checkpoint_every
    ! Batch convention: a relative output folder is relative to the current
    ! directory (where the job runs), not to the deck.
    if (len_trim(output_dir) == 0) then
      spec%output_dir = 'results/' // stem
    else
      spec%output_dir = trim(output_dir)
    end if
  end subroutine read_run

  !> &time t_end, dt, safety, damping and the mass-scaling keys
  !> mass_scaling_dt, mass_scaling_factor, added_mass_warn,
  !> kinetic_ratio_warn, kinetic_check_from.
  subroutine read_time(deck, blk, spec, err)
    character(len=*), intent(in) :: deck
    type(deck_block_t), intent(in) :: blk
    type(time_spec_t), intent(out) :: spec
    type(error_t), intent(inout) :: err
    real(wp) :: t_end, dt, safety, damping
    real(wp) :: mass_scaling_dt, mass_scaling_factor, added_mass_warn, kinetic_ratio_warn, kinetic_check_from
    namelist /time/ t_end, dt, safety, damping, mass_scaling_dt, mass_scaling_factor, added_mass_warn, &
      kinetic_ratio_warn, kinetic_check_from
    character(len=:), allocatable :: record
    character(len=256) :: msg
    integer :: k, ios

    t_end = UNSET
    dt = spec%dt
    safety = spec%safety
    damping = spec%damping
    mass_scaling_dt = spec%mass_scaling_dt
    mass_scaling_factor = spec%mass_scaling_factor
    added_mass_warn = spec%added_mass_warn
    kinetic_ratio_warn = spec%kinetic_ratio_warn
    kinetic_check_from = spec%kinetic_check_from
    call check_keys(deck, blk, TIME_KEYS, '', err)
    if (err%failed()) return
    do k = 1, size(blk%keys)
      record = blk%item(k)
      msg = ''
      read(record, nml=time, iostat=ios, iomsg=msg)
      if (ios /= 0) then
        call unreadable(deck, blk, k, '', msg, err)
        return
      end if
    end do
    call check_finite(deck, blk, '', [character(len=19) :: 't_end', 'dt', 'safety', 'damping', 'mass_scaling_dt', &
      'mass_scaling_factor', 'added_mass_warn', 'kinetic_ratio_warn', 'kinetic_check_from'], &
      [t_end, dt, safety, damping, mass_scaling_dt, mass_scaling_factor, added_mass_warn, kinetic_ratio_warn, &
      kinetic_check_from], err)
    if (err%failed()) return

    if (t_end == UNSET) then
      call missing_key(deck, blk, '', 't_end', 't_end = <end time> (> 0)', err)
    else if (.not. (t_end > 0.0_wp)) then
      call bad_value(deck, blk, '', 't_end', 'the end time must be > 0', 'give the duration of the run', err)
    else if (.not. (dt >= 0.0_wp)) then
      call bad_value(deck, blk, '', 'dt', 'the time step must be >= 0', &
        'give a fixed step, or dt = 0 for safety times the stable step', err)
    else if (.not. (safety > 0.0_wp .and. safety <= 1.0_wp)) then
      call bad_value(deck, blk, '', 'safety', 'the safety factor must lie in (0, 1]', &
        'use e.g. safety = 0.9 (above 1 the explicit scheme is unstable)', err)
    else if (.not. (damping >= 0.0_wp)) then
      call bad_value(deck, blk, '', 'damping', 'the damping must be >= 0', &
        'give a mass-proportional damping alpha in 1/time, or 0 for none', err)
    else if (.not. (mass_scaling_dt >= 0.0_wp)) then
      call bad_value(deck, blk, '', 'mass_scaling_dt', 'the target step must be >= 0', &
        'give the step the run should take, or 0 for no mass scaling', err)
    else if (.not. (mass_scaling_factor == 0.0_wp .or. mass_scaling_factor >= 1.0_wp)) then
      call bad_value(deck, blk, '', 'mass_scaling_factor', 'the target factor must be >= 1 (or 0: none)', &
        'give the step the run should take as a multiple of the unscaled step, e.g. 5', err)
    else if (mass_scaling_dt > t_end) then
      call bad_value(deck, blk, '', 'mass_scaling_dt', 'the target step is longer than the run (t_end = ' // &
        str(t_end) // ')', 'give the step the run should take, at most t_end (a quasi-static run takes ' // &
        'hundreds of steps or more)', err)
    else if (mass_scaling_dt > 0.0_wp .and. mass_scaling_factor > 0.0_wp) then
      call bad_value(deck, blk, '', 'mass_scaling_factor', 'mass_scaling_dt and mass_scaling_factor are both given', &
        'give one of them: the target step itself, or as a factor of the unscaled step', err)
    else if (dt > 0.0_wp .and. (mass_scaling_dt > 0.0_wp .or. mass_scaling_factor > 0.0_wp)) then
      call bad_value(deck, blk, '', 'dt', 'a fixed dt and mass scaling are both given', &
        'leave dt out (0): with mass scaling the step is the target, mass_scaling_dt', err)
    else if (.not. (added_mass_warn >= 0.0_wp)) then
      call bad_value(deck, blk, '', 'added_mass_warn', 'the added-mass threshold must be >= 0', &
        'give a fraction of the body mass, e.g. 0.05 for 5 %', err)
    else if (.not. (kinetic_ratio_warn >= 0.0_wp)) then
      call bad_value(deck, blk, '', 'kinetic_ratio_warn', 'the kinetic-energy threshold must be >= 0', &
        'give a fraction of the internal energy, e.g. 0.05, or 0 for no check', err)
    else if (.not. (kinetic_check_from >= 0.0_wp .and. kinetic_check_from <= 1.0_wp)) then
      call bad_value(deck, blk, '', 'kinetic_check_from', 'the start of the kinetic-energy check must lie in [0, 1]', &
        'give a fraction of t_end, e.g. 0.2 to skip the start-up', err)
    end if
    if (err%failed()) return
    spec%mass_scaling_dt = mass_scaling_dt
    spec%mass_scaling_factor = mass_scaling_factor
    spec%added_mass_warn = added_mass_warn
    spec%kinetic_ratio_warn = kinetic_ratio_warn
    spec%kinetic_check_from = kinetic_check_from
    spec%t_end = t_end
    spec%dt = dt
    spec%safety = safety
    spec%damping = damping
  end subroutine read_time

  !> &output frames, history_every, progress_seconds, stress.
  subroutine read_output(deck, blk, spec, err)
    character(len=*), intent(in) :: deck
    type(deck_block_t), intent(in) :: blk
    type(output_spec_t), intent(out) :: spec
    type(error_t), intent(inout) :: err
    integer :: frames, history_every
    real(wp) :: progress_seconds
    logical :: stress
    namelist /output/ frames, history_every, progress_seconds, stress
    character(len=:), allocatable :: record
    character(len=256) :: msg
    integer :: k, ios

    frames = spec%frames
    history_every = spec%history_every
    progress_seconds = spec%progress_seconds
    stress = spec%stress
    call check_keys(deck, blk, OUTPUT_KEYS, '', err)
    if (err%failed()) return
    do k = 1, size(blk%keys)
      record = blk%item(k)
      msg = ''
      read(record, nml=output, iostat=ios, iomsg=msg)
      if (ios /= 0) then
        call unreadable(deck, blk, k, '', msg, err)
        return
      end if
    end do
    call check_finite(deck, blk, '', ['progress_seconds'], [progress_seconds], err)
    if (err%failed()) return

    if (frames < 0) then
      call bad_value(deck, blk, '', 'frames', 'the number of frames must be >= 0', &
        'give how many result frames to write over the run (0 = the initial state only)', err)
    else if (history_every < 0) then
      call bad_value(deck, blk, '', 'history_every', 'the history interval must be >= 0', &
        'give the number of steps between history lines, or 0 for about 1000 lines', err)
    else if (.not. (progress_seconds >= 0.0_wp)) then
      call bad_value(deck, blk, '', 'progress_seconds', 'the progress interval must be >= 0', &
        'give the wall-clock seconds between progress lines', err)
    end if
    if (err%failed()) return
    spec%frames = frames
    spec%history_every = history_every
    spec%progress_seconds = progress_seconds
    spec%stress = stress
  end subroutine read_output
end module raccord_deck_run
