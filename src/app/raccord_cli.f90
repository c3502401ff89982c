!> Command line of the raccord program.
module raccord_cli
  use raccord_error, only: error_t, raise_error, EXIT_USAGE
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
  end type cli_t

  public :: parse_command_line, usage_text

contains

  subroutine parse_command_line(cli, err)
    type(cli_t), intent(out) :: cli
    type(error_t), intent(inout) :: err
    integer :: k, n, length
    character(len=:), allocatable :: arg

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
        if (k == n) then
          call raise_error(err, EXIT_USAGE, 'option ' // arg // ' needs a folder: raccord --output DIR SCENE')
          return
        end if
        k = k + 1
        call get_command_argument(k, length=length)
        allocate(character(len=length) :: cli%output_dir)
        call get_command_argument(k, cli%output_dir)
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
        cli%scene_path = arg
      end select
      deallocate(arg)
    end do
    if (.not. (cli%help .or. cli%version) .and. .not. allocated(cli%scene_path)) then
      call raise_error(err, EXIT_USAGE, 'no scene given; usage: raccord [options] SCENE (raccord --help)')
    end if
  end subroutine parse_command_line

  function usage_text() result(s)
    character(len=:), allocatable :: s
    character(len=*), parameter :: nl = new_line('a')
    s = 'usage: raccord [options] SCENE' // nl // nl // &
      'Runs the scene deck SCENE (Fortran namelist groups; see doc/scene-reference.md):' // nl // &
      'explicit central-difference dynamics of 2D elastic bodies, with contact by' // nl // &
      'forward-increment Lagrange multipliers.' // nl // nl // &
      'options:' // nl // &
      '  --check         read and check the scene and mesh, print the resolved scene,' // nl // &
      '                  stable time step, steps, elements and estimated cost; do not run' // nl // &
      '  -o, --output DIR  write results to DIR (overrides &run output_dir)' // nl // &
      '  -q, --quiet     progress and info to the log file only' // nl // &
      '  -v, --verbose   debug messages' // nl // &
      '  -V, --version   print the version' // nl // &
      '  -h, --help      this text' // nl // nl // &
      'exit codes: 0 success, 1 bad command line, 2 bad scene or mesh, 3 numerical failure,' // nl // &
      '            4 file system failure, 5 stopped at the wall-clock limit (checkpoint written)'
  end function usage_text
end module raccord_cli
