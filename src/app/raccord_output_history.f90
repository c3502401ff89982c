!> The run's time history on disk: the buffered rows appended to
!> /history of the results file, and the check, before the first step,
!> that the rows the run will write fit the output folder's file system.
module raccord_output_history
  use raccord_kinds, only: wp, i8
  use raccord_error, only: error_t, raise_error, EXIT_INPUT
  use raccord_log, only: log_warn
  use raccord_strings, only: str
  use raccord_time_step, only: time_plan_t
  use raccord_scene, only: scene_t
  use raccord_results, only: results_append_table
  use raccord_machine, only: free_disk_bytes
  use raccord_paths, only: path_dir
  use raccord_output_state, only: output_t
  implicit none
  private

  public :: flush_history, check_history_room

contains

  !> Append the buffered history rows to /history of the results file
  !> (when the block is full, at each frame, at a checkpoint and at the end).
  subroutine flush_history(out, err)
    type(output_t), intent(inout) :: out
    type(error_t), intent(inout) :: err
    if (out%nbuf == 0) return
    call results_append_table(out%res, '/history', out%block(:, 1:out%nbuf), err)
    if (err%failed()) return
    out%nrow = out%nrow + out%nbuf
    out%nbuf = 0
  end subroutine flush_history

  !> The history is streamed to disk, so its memory does not grow with the
  !> run, but its files do: rows = steps / history_every, each value about
  !> HISTORY_VALUE_BYTES in the text file and /history together. A history
  !> of more than a GiB and larger than the whole file system of the output
  !> folder is a scene that cannot run (refused, exit 2, before any step: it
  !> would end with a full disk after all its steps were computed); one
  !> larger than the free space only, or a small one on a tiny file system,
  !> is warned of (space may be freed while it runs; a full disk stops it
  !> with exit 4, its files kept as .incomplete). A variable step makes the
  !> planned count an estimate: the check is a lower bound.
  subroutine check_history_room(out, scene, plan, stem, err)
    type(output_t), intent(in) :: out
    type(scene_t), intent(in) :: scene
    type(time_plan_t), intent(in) :: plan
    character(len=*), intent(in) :: stem
    type(error_t), intent(inout) :: err
    integer(i8), parameter :: HISTORY_VALUE_BYTES = 33, GIB = 1024_i8**3
    integer(i8) :: rows, row_bytes, free, total, fit
    character(len=:), allocatable :: folder, what
    folder = path_dir(stem)
    if (len(folder) == 0) folder = '.'
    free = free_disk_bytes(folder, total)
    if (free < 0 .or. total <= 0) return
    rows = plan%nsteps/out%history_every + 2
    row_bytes = HISTORY_VALUE_BYTES*size(out%columns)
    if (rows <= free/row_bytes) return
    what = 'scene ' // scene%path // ': &output history_every = ' // str(out%history_every) // ' over ' // &
      str(plan%nsteps) // ' steps makes ' // str(rows) // ' history rows of ' // str(size(out%columns)) // &
      ' columns, about ' // str(real(rows, wp)*real(row_bytes, wp)/1.0e9_wp, 3) // ' GB in ' // stem // &
      '.history.txt and ' // stem // '.h5'
    if (rows <= total/row_bytes .or. rows <= GIB/row_bytes) then
      call log_warn('output', what // ', more than the ' // str(real(free, wp)/1.0e9_wp, 3) // ' GB free in ' // &
        folder // ': the run stops with a full disk (exit 4) unless space is freed')
      return
    end if
    fit = max(1_i8, total/row_bytes - 2)
    call raise_error(err, EXIT_INPUT, what // ', more than the whole file system of ' // folder // ' (' // &
      str(real(total, wp)/1.0e9_wp, 3) // ' GB): set history_every >= ' // str(plan%nsteps/fit + 1) // &
      ' (or 0 for 1000 rows)')
  end subroutine check_history_room
end module raccord_output_history
