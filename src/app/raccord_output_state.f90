!> What a run's outputs hold while it runs: the open results, history
!> and profile files, the history rows not yet in the results file, the
!> frame scratch sized once, the progress clock (output_t); and where they
!> stand at a checkpoint (output_mark_t). The modules that write them
!> (raccord_output and its parts) share these.
module raccord_output_state
  use raccord_kinds, only: wp, i8
  use raccord_results, only: results_t
  use raccord_history_file, only: history_file_t
  use raccord_history_columns, only: HISTORY_COL_LEN
  implicit none
  private

  public :: HISTORY_BLOCK_ROWS, HISTORY_BLOCK_VALUES, SURFACE_FIELDS

  !> History rows kept in memory before they are appended to /history of
  !> the results file (and rows per chunk of it): the memory of the history
  !> is one such block, whatever the number of steps (issue #18). Fewer rows
  !> when there are many columns, so a block stays within 256 KiB.
  integer, parameter :: HISTORY_BLOCK_ROWS = 256
  integer, parameter :: HISTORY_BLOCK_VALUES = 32768

  !> Per-node values of a contact pair's slave surface grid in the results
  !> (doc/output-format.md, "Contact surfaces"), in the columns of
  !> write_contact_frame's values array.
  character(len=*), parameter :: SURFACE_FIELDS(7) = [character(len=14) :: 'pressure', 'shear', 'gap', &
    'slip_increment', 'status', 'lambda_n', 'lambda_t']

  type, public :: output_t
    character(len=:), allocatable :: stem
    type(results_t) :: res
    type(history_file_t) :: hist
    logical :: is_open = .false.
    logical :: stress = .true.
    real(wp) :: frame_interval = 0.0_wp
    integer :: frames_written = 0
    integer(i8) :: history_every = 1
    character(len=HISTORY_COL_LEN), allocatable :: columns(:)
    real(wp), allocatable :: row(:)
    real(wp), allocatable :: block(:,:)        !< (ncol, rows) history rows not yet in /history
    integer :: nbuf = 0                         !< rows held in block
    integer(i8) :: nrow = 0                     !< rows appended to /history of the results file
    real(wp), allocatable :: s_node(:,:), wsum(:), r_node(:,:)   !< frame scratch, sized once
    !> Contact frame scratch, sized once for the largest surfaces: deformed
    !> slave and master coordinates, slave values (one column per SURFACE_FIELDS).
    real(wp), allocatable :: surf_xy(:,:), surf_xm(:,:), surf_values(:,:), surf_none(:,:)
    integer(i8) :: clock_start = 0, clock_rate = 1, clock_last = 0
    integer(i8) :: first_step = -1              !< first step of this process (a restart's is > 0)
    real(wp) :: progress_seconds = 10.0_wp
    integer, allocatable :: profile_unit(:)     !< per contact pair: text profiles, one block per frame
    character(len=:), allocatable :: profile_path
  end type output_t

  !> Where the outputs stand at a checkpoint: what a restarted run needs to
  !> go on with the same files as if it had never stopped.
  type, public :: output_mark_t
    integer :: frames_written = 0
    integer(i8) :: nrow = 0                     !< rows of /history in the results file
    integer :: ncol = 0                         !< its columns
    integer(i8) :: history_bytes = 0            !< length of <stem>.history.txt.part
    integer(i8), allocatable :: profile_bytes(:) !< length of each <stem>.contact<k>.txt.part
  end type output_mark_t
end module raccord_output_state
