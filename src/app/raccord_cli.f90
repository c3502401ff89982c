!> Command line of the raccord program.
module raccord_cli
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use raccord_kinds, only: wp
  use raccord_error, only: error_t, raise_error, EXIT_USAGE
  use raccord_strings, only: clipped
  implicit none
  private

  !> What the user asked for on the command line.
  type, public :: cli_t
    logical :: help = .false.
    logical :: version = .false.
    logical :: check = .false.         !< validate and report, do not run
    logical :: quiet = .false.         !< log to the file only (warnings still to stderr)
    logical :: verbose = .false.       !< debug messages
    character(len=:), allocatable :: scene_path
    character(len=:), allocatable :: output_dir   !< overrides &run output_dir when set
    character(len=:), allocatable :: restart_path !< checkpoint to continue from (--restart)
    character(len=:), allocatable :: verify_path  !< results or checkpoint file to check (--verify)
    real(wp) :: wall_clock = 0.0_wp              !< --wall-clock or RACCORD_WALLCLOCK_SECONDS; 0 = not given
    character(len=:), allocatable :: wall_clock_source  !< where wall_clock came from, for the log
  end type cli_t

  public :: parse_command_line, usage_text

contains

  subroutine parse_command_line(cli, err)
    type(cli_t), intent(out) :: cli
    type(error_t), intent(inout) :: err
    integer :: k, n, length, stat
    character(len=:), allocatable :: arg, value

    n = command_argument_count()
    k = 0
    do while (k < n)
      k = k + 1
      call get_command_argument(k, length=length)
      allocate(character(len=length) :: arg)
      call get_command_argument(k, arg)
      select case (arg)
      case ('-h', '--help')
        cli%help = .true.
      case ('-V', '--version')
        cli%version = .true.
      case ('--check')
        cli%check = .true.
      case ('-q', '--quiet')
        cli%quiet = .true.
      case ('-v', '--verbose')
        cli%verbose = .true.
      case ('-o', '--output')
        if (allocated(cli%output_dir)) then
          call given_twice(arg, cli%output_dir, err)
          return
        end if
        call option_value(k, n, arg, 'a folder: raccord --output DIR SCENE', cli%output_dir, err)
        if (err%failed()) return
        if (len_trim(cli%output_dir) == 0) then
          call raise_error(err, EXIT_USAGE, 'option ' // arg // ' is given an empty folder name: give a ' // &
            'folder (. for the current one)')
          return
        end if
      case ('--restart')
        if (allocated(cli%restart_path)) then
          call given_twice(arg, cli%restart_path, err)
          return
        end if
        call option_value(k, n, arg, 'a checkpoint: raccord --restart DIR/NAME.checkpoint.h5 [SCENE]', &
          cli%restart_path, err)
        if (err%failed()) return
        if (index(cli%restart_path, '.checkpoint.h5', back=.true.) /= len(cli%restart_path) - 13 .or. &
            len(cli%restart_path) <= 14) then
          call raise_error(err, EXIT_USAGE, '--restart ' // cli%restart_path // ': give the <name>.checkpoint.h5 ' // &
            'file a stopped run wrote')
          return
        end if
      case ('--verify')
        if (allocated(cli%verify_path)) then
          call given_twice(arg, cli%verify_path, err)
          return
        end if
        call option_value(k, n, arg, 'a results or checkpoint file: raccord --verify FILE', cli%verify_path, err)
        if (err%failed()) return
        if (len_trim(cli%verify_path) == 0) then
          call raise_error(err, EXIT_USAGE, 'option --verify is given an empty file name')
          return
        end if
      case ('--wall-clock')
        if (allocated(cli%wall_clock_source)) then
          call given_twice(arg, '', err)
          return
        end if
        call option_value(k, n, arg, 'seconds: raccord --wall-clock 3600 SCENE', value, err)
        if (err%failed()) return
        call read_seconds(value, 'option --wall-clock', cli%wall_clock, err)
        if (err%failed()) return
        cli%wall_clock_source = '--wall-clock'
      case default
        if (arg(1:1) == '-' .and. len(arg) > 1) then
          call raise_error(err, EXIT_USAGE, 'unknown option ''' // arg // '''; see raccord --help')
          return
        end if
        if (allocated(cli%scene_path)) then
          call raise_error(err, EXIT_USAGE, 'one scene per run: got ''' // cli%scene_path // ''' and ''' // &
            arg // ''' (run raccord once per scene, or use hpc/ sweep scripts)')
          return
        end if
        if (len_trim(arg) == 0) then
          call raise_error(err, EXIT_USAGE, 'an empty argument where the scene deck was expected: give ' // &
            'the path of the deck (raccord --help)')
          return
        end if
        cli%scene_path = arg
      end select
      deallocate(arg)
    end do
    if (cli%help .or. cli%version) return
    if (allocated(cli%verify_path)) then
      if (allocated(cli%scene_path) .or. allocated(cli%restart_path) .or. cli%check) then
        call raise_error(err, EXIT_USAGE, '--verify checks one file and runs nothing: give it alone ' // &
          '(raccord --verify FILE)')
      end if
      return
    end if
    if (.not. allocated(cli%scene_path) .and. .not. allocated(cli%restart_path)) then
      call raise_error(err, EXIT_USAGE, 'no scene given; usage: raccord [options] SCENE (raccord --help)')
      return
    end if
    if (cli%check .and. allocated(cli%restart_path)) then
      call raise_error(err, EXIT_USAGE, '--check and --restart do not go together: check the scene alone ' // &
        '(raccord --check SCENE)')
      return
    end if
    ! The job scripts pass the limit in the environment (doc/hpc.md).
    if (.not. allocated(cli%wall_clock_source)) then
      call get_environment_variable('RACCORD_WALLCLOCK_SECONDS', length=length, status=stat)
      if (stat == 0 .and. length > 0) then
        allocate(character(len=length) :: value)
        call get_environment_variable('RACCORD_WALLCLOCK_SECONDS', value)
        call read_seconds(value, 'environment variable RACCORD_WALLCLOCK_SECONDS', cli%wall_clock, err)
        if (err%failed()) return
        cli%wall_clock_source = 'RACCORD_WALLCLOCK_SECONDS'
      end if
    end if
  end subroutine parse_command_line

  !> The value after option `arg` (argument k+1), or a usage error.
  subroutine option_value(k, n, arg, needs, value, err)
    integer, intent(inout) :: k
    integer, intent(in) :: n
    character(len=*), intent(in) :: arg, needs
    character(len=:), allocatable, intent(out) :: value
    type(error_t), intent(inout) :: err
    integer :: length
    if (k == n) then
      call raise_error(err, EXIT_USAGE, 'option ' // arg // ' needs ' // needs)
      return
    end if
    k = k + 1
    call get_command_argument(k, length=length)
    allocate(character(len=length) :: value)
    call get_command_argument(k, value)
  end subroutine option_value

  !> A wall-clock limit in seconds: a finite number > 0.
  subroutine read_seconds(text, what, seconds, err)
    character(len=*), intent(in) :: text, what
    real(wp), intent(out) :: seconds
    type(error_t), intent(inout) :: err
    integer :: ios
    seconds = 0.0_wp
    read(text, *, iostat=ios) seconds
    if (ios == 0) then
      if (.not. ieee_is_finite(seconds)) ios = 1
    end if
    if (ios /= 0 .or. .not. (seconds > 0.0_wp)) then
      seconds = 0.0_wp
      call raise_error(err, EXIT_USAGE, what // ' = ''' // text // ''' is not a number of seconds > 0 ' // &
        '(e.g. 3600)')
    end if
  end subroutine read_seconds

  function usage_text() result(s)
    character(len=:), allocatable :: s
    character(len=*), parameter :: nl = new_line('a')
    s = 'usage: raccord [options] SCENE' // nl // &
      '       raccord [options] --restart CHECKPOINT [SCENE]' // nl // nl // &
      'Runs the scene deck SCENE (Fortran namelist groups; see doc/scene-reference.md):' // nl // &
      'explicit central-difference dynamics of 2D elastic bodies, with contact by' // nl // &
      'forward-increment Lagrange multipliers.' // nl // nl // &
      'options:' // nl // &
      '  --check         read and check the scene and mesh, print the resolved scene,' // nl // &
      '                  stable time step, steps, elements and estimated cost; do not run' // nl // &
      '  -o, --output DIR  write results to DIR (overrides &run output_dir; default' // nl // &
      '                  results/NAME, relative to the current folder, NAME = SCENE''s' // nl // &
      '                  file name without extension)' // nl // &
      '  --wall-clock S  stop after at most S wall seconds: write the checkpoint' // nl // &
      '                  DIR/NAME.checkpoint.h5 and exit 5 (default: environment variable' // nl // &
      '                  RACCORD_WALLCLOCK_SECONDS, else &run wall_clock; SIGTERM and' // nl // &
      '                  SIGUSR1 do the same at once)' // nl // &
      '  --restart CHECKPOINT  continue the run that wrote CHECKPOINT, with its results' // nl // &
      '                  files (SCENE defaults to the deck it was written for; it must' // nl // &
      '                  resolve to the same scene)' // nl // &
      '  --verify FILE   check a results (.h5, .h5.part) or checkpoint file: read back' // nl // &
      '                  every dataset and its checksums; exit 0 intact, 2 damaged' // nl // &
      '  -q, --quiet     progress and info to the log file only' // nl // &
      '  -v, --verbose   debug messages' // nl // &
      '  -V, --version   print the version' // nl // &
      '  -h, --help      this text' // nl // nl // &
      'environment:' // nl // &
      '  OMP_NUM_THREADS=N  run the element and node loops on N threads (default: serial;' // nl // &
      '                  the results are the same bit for bit with any N)' // nl // &
      '  RACCORD_WALLCLOCK_SECONDS=S  as --wall-clock S (the option wins)' // nl // nl // &
      'files: DIR/NAME.h5 and NAME.xmf (ParaView), NAME.meshio.xmf (meshio), NAME.history.txt,' // nl // &
      '  NAME.contact<k>.txt, NAME.scene.nml, NAME.log; *.part while running (doc/output-format.md)' // nl // nl // &
      'exit codes: 0 success, 1 bad command line, 2 bad scene or mesh, 3 numerical failure,' // nl // &
      '            4 file system failure, 5 stopped at the wall-clock limit or by SIGTERM or SIGUSR1,' // nl // &
      '            checkpoint written: continue with --restart (a checkpoint it refuses: 2)'
  end function usage_text

  !> An option that takes a value, given a second time: refused, since a
  !> job script that adds its own -o to a user's would otherwise have the
  !> last one win without a word.
  subroutine given_twice(arg, first, err)
    character(len=*), intent(in) :: arg, first
    type(error_t), intent(inout) :: err
    if (len(first) == 0) then
      call raise_error(err, EXIT_USAGE, 'option ' // arg // ' is given twice: give it once')
    else
      call raise_error(err, EXIT_USAGE, 'option ' // arg // ' is given twice (the first: ''' // &
        clipped(first, 80) // '''): give it once')
    end if
  end subroutine given_twice
end module raccord_cli
