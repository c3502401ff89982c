!> What a run writes while it runs: result frames (HDF5 + XDMF), the
!> time-history table (plain text and HDF5), progress lines in the log.
!> This module opens, resumes and closes the outputs and writes those due
!> at a step; its parts: raccord_output_state (what the open outputs
!> hold), raccord_output_frame (one frame), raccord_output_history (rows
!> into /history), raccord_output_profiles (contact profile text files),
!> raccord_output_progress (the progress line).
module raccord_output
  use raccord_kinds, only: wp, i8
  use raccord_error, only: error_t, raise_error, EXIT_IO, EXIT_INPUT
  use raccord_log, only: log_info, log_raw
  use raccord_strings, only: str, append_text
  use raccord_model, only: model_t
  use raccord_state, only: state_t
  use raccord_time_step, only: time_plan_t
  use raccord_scene, only: scene_t
  use raccord_results, only: results_t, results_open, results_write_mesh, results_write_node_set, &
    results_set_text, results_close, results_suspend, results_resume, results_has, results_delete, &
    results_flush, results_verify, results_create_table, results_truncate_table
  use raccord_history_file, only: history_open, history_write, history_close, history_bytes, &
    history_suspend, history_resume
  use raccord_contact_pair, only: contact_pair_t
  use raccord_files, only: file_size, truncate_file
  use raccord_h5_superblock, only: h5_clear_write_flags
  use raccord_deck, only: write_scene
  use raccord_history_columns, only: history_columns, history_width, fill_history_row
  use raccord_output_state, only: output_t, output_mark_t, HISTORY_BLOCK_ROWS, HISTORY_BLOCK_VALUES, &
    SURFACE_FIELDS
  use raccord_output_history, only: flush_history, check_history_room
  use raccord_output_profiles, only: open_profiles, close_profiles, profile_name
  use raccord_output_frame, only: write_frame, add_contact_surfaces, result_blocks, check_frame_count
  use raccord_output_progress, only: log_progress, eta_seconds, wall_seconds
  implicit none
  private

  public :: output_t, output_mark_t
  public :: open_outputs, write_due_outputs, close_outputs, wall_seconds
  public :: mark_outputs, suspend_outputs, resume_outputs, history_width, eta_seconds

contains

  !> Create the result files (under temporary names) and write the mesh.
  subroutine open_outputs(out, scene, model, plan, pairs, stem, err)
    type(output_t), intent(out) :: out
    type(scene_t), intent(in) :: scene
    type(model_t), intent(in) :: model
    type(time_plan_t), intent(in) :: plan
    type(contact_pair_t), intent(in) :: pairs(:)
    character(len=*), intent(in) :: stem
    type(error_t), intent(inout) :: err
    integer :: k

    call prepare_outputs(out, scene, model, plan, pairs, stem, err)
    if (err%failed()) return
    call check_history_room(out, scene, plan, stem, err)
    if (err%failed()) return
    call check_frame_count(scene, model, plan, pairs, stem, err)
    if (err%failed()) return
    call results_open(out%res, stem, err)
    if (err%failed()) return
    out%is_open = .true.
    call results_write_mesh(out%res, model%x, result_blocks(model), err)
    if (err%failed()) return
    do k = 1, size(model%supports)
      ! Several &boundary groups may act on one node set (one component
      ! each): the set is written once, under its name.
      if (set_written_before(model, k)) cycle
      call results_write_node_set(out%res, model%supports(k)%set, model%supports(k)%nodes, err)
      if (err%failed()) return
    end do
    call add_contact_surfaces(out, pairs, err)
    if (err%failed()) return
    call keep_resolved_scene(scene, stem, out%res, err)
    if (err%failed()) return
    call results_create_table(out%res, '/history', out%columns, size(out%block, 2), err)
    if (err%failed()) return
    call history_open(out%hist, stem // '.history.txt', out%columns, err)
    if (err%failed()) return
    call open_profiles(out, pairs, err)
    if (err%failed()) return
    call system_clock(out%clock_start, out%clock_rate)
    out%clock_last = out%clock_start
  end subroutine open_outputs

  !> True when a support before the k-th acts on the same node set.
  logical function set_written_before(model, k)
    type(model_t), intent(in) :: model
    integer, intent(in) :: k
    integer :: j
    set_written_before = .false.
    do j = 1, k - 1
      if (model%supports(j)%set == model%supports(k)%set) set_written_before = .true.
    end do
  end function set_written_before

  !> Settings and scratch of the outputs, for a new or a resumed run.
  subroutine prepare_outputs(out, scene, model, plan, pairs, stem, err)
    type(output_t), intent(out) :: out
    type(scene_t), intent(in) :: scene
    type(model_t), intent(in) :: model
    type(time_plan_t), intent(in) :: plan
    type(contact_pair_t), intent(in) :: pairs(:)
    character(len=*), intent(in) :: stem
    type(error_t), intent(inout) :: err
    integer :: k, ns, nm, stat
    out%stem = stem
    out%stress = scene%output%stress
    out%frame_interval = plan%t_end/real(max(1, scene%output%frames), wp)
    out%progress_seconds = scene%output%progress_seconds
    out%history_every = int(scene%output%history_every, i8)
    if (out%history_every <= 0) out%history_every = max(1_i8, plan%nsteps/1000_i8)
    call history_columns(model, pairs, out%columns)
    ! The history goes to the results file in blocks of rows as the run
    ! goes on (flush_history): nothing here is sized by the number of steps.
    allocate(out%row(size(out%columns)), out%block(size(out%columns), &
      max(1, min(HISTORY_BLOCK_ROWS, HISTORY_BLOCK_VALUES/size(out%columns)))), stat=stat)
    if (stat == 0) allocate(out%s_node(4, model%nnode), out%wsum(model%nnode), out%r_node(2, model%nnode), stat=stat)
    ns = 0
    nm = 0
    do k = 1, size(pairs)
      ns = max(ns, pairs(k)%slave%nnode)
      nm = max(nm, pairs(k)%master%nnode)
    end do
    if (stat == 0) allocate(out%surf_xy(2, ns), out%surf_xm(2, nm), out%surf_values(ns, size(SURFACE_FIELDS)), &
      out%surf_none(nm, 0), stat=stat)
    if (stat /= 0) call raise_error(err, EXIT_INPUT, 'not enough memory for the output scratch of ' // stem // &
      ' (' // str(model%nnode) // ' nodes)')
  end subroutine prepare_outputs

  !> Flush every output and record where each stands, for a checkpoint.
  subroutine mark_outputs(out, mark, err)
    type(output_t), intent(inout) :: out
    type(output_mark_t), intent(out) :: mark
    type(error_t), intent(inout) :: err
    integer :: k, ios
    call flush_history(out, err)
    if (err%failed()) return
    call results_flush(out%res, err)
    if (err%failed()) return
    mark%frames_written = out%frames_written
    mark%nrow = out%nrow
    mark%ncol = size(out%columns)
    mark%history_bytes = history_bytes(out%hist)
    allocate(mark%profile_bytes(size(out%profile_unit)))
    do k = 1, size(out%profile_unit)
      flush(out%profile_unit(k), iostat=ios)
      if (ios /= 0) call raise_error(err, EXIT_IO, 'cannot flush ' // profile_name(out, k) // '.part (disk full?)')
      mark%profile_bytes(k) = file_size(profile_name(out, k) // '.part')
    end do
    if (mark%history_bytes < 0 .or. any(mark%profile_bytes < 0)) &
      call raise_error(err, EXIT_IO, 'cannot measure the running output files of ' // out%stem)
  end subroutine mark_outputs

  !> Close every output but keep the .part names: the run stopped at a
  !> checkpoint, and resume_outputs goes on with the same files. /status
  !> of the results file says why it stopped.
  subroutine suspend_outputs(out, reason, err)
    type(output_t), intent(inout) :: out
    character(len=*), intent(in) :: reason
    type(error_t), intent(inout) :: err
    integer :: k
    if (.not. out%is_open) return
    out%is_open = .false.
    call history_suspend(out%hist, err)
    call results_suspend(out%res, reason, err)
    do k = 1, size(out%profile_unit)
      close(out%profile_unit(k))
    end do
  end subroutine suspend_outputs

  !> Reopen the outputs of a stopped run where its checkpoint left them
  !> (mark): results, history and contact profiles are cut back to that
  !> point (a run killed after its last checkpoint wrote more) and continued.
  subroutine resume_outputs(out, scene, model, plan, pairs, stem, mark, err)
    type(output_t), intent(out) :: out
    type(scene_t), intent(in) :: scene
    type(model_t), intent(in) :: model
    type(time_plan_t), intent(in) :: plan
    type(contact_pair_t), intent(in) :: pairs(:)
    character(len=*), intent(in) :: stem
    type(output_mark_t), intent(in) :: mark
    type(error_t), intent(inout) :: err
    character(len=32), allocatable :: fields(:)
    integer, allocatable :: ncomps(:)
    character(len=:), allocatable :: path
    character(len=16) :: tag
    character(len=256) :: msg
    integer :: k, n, ios
    integer(i8) :: bytes
    logical :: cleared, ok

    call prepare_outputs(out, scene, model, plan, pairs, stem, err)
    if (err%failed()) return
    ! Every running file must be there before any is touched: a refused
    ! resume leaves them as they were.
    if (size(mark%profile_bytes) /= size(pairs)) then
      call raise_error(err, EXIT_INPUT, 'the checkpoint of ' // stem // ' has ' // str(size(mark%profile_bytes)) // &
        ' contact profiles, the scene ' // str(size(pairs)) // ' contact pairs')
      return
    end if
    do k = 0, size(pairs)
      if (k == 0) then
        path = stem // '.history.txt.part'
        bytes = mark%history_bytes
      else
        path = profile_name(out, k) // '.part'
        bytes = mark%profile_bytes(k)
      end if
      ! file_size is -1 for a missing file.
      if (file_size(path) < max(bytes, 0_i8)) then
        call raise_error(err, EXIT_INPUT, 'cannot resume: ' // path // ' is missing or shorter than at the ' // &
          'checkpoint; run the scene afresh without --restart')
        return
      end if
    end do
    ! The fields write_frame writes, in its order.
    fields = [character(len=32) :: 'displacement', 'velocity', 'reaction']
    ncomps = [2, 2, 2]
    if (out%stress) then
      fields = [character(len=32) :: fields, 'stress']
      ncomps = [ncomps, 4]
      if (model%has_finite) then
        fields = [character(len=32) :: fields, 'strain']
        ncomps = [ncomps, 4]
      end if
      if (model%has_plastic) then
        fields = [character(len=32) :: fields, 'equivalent_plastic_strain', 'yielded']
        ncomps = [ncomps, 1, 1]
      end if
    end if
    ! A run killed while writing leaves the file marked open for writing
    ! (raccord_h5_superblock); this run holds the stem's lock, so it is not.
    call h5_clear_write_flags(stem // '.h5.part', cleared, ok)
    if (cleared) call log_info('restart', stem // '.h5.part was left marked as open for writing (the run ' // &
      'was killed): mark cleared')
    call results_resume(out%res, stem, model%nnode, result_blocks(model), fields, ncomps, mark%frames_written, err)
    if (err%failed()) return
    call results_verify(out%res, err)     ! checksums of what is continued
    if (err%failed()) return
    out%is_open = .true.
    ! /history: the rows up to the checkpoint (a killed run may have added more)
    call results_truncate_table(out%res, '/history', size(out%columns), mark%nrow, err)
    if (err%failed()) return
    call add_contact_surfaces(out, pairs, err)
    if (err%failed()) return
    do k = 1, size(pairs)
      n = mark%frames_written
      do
        write(tag, '(i6.6)') n
        path = '/contact/pair_' // str(k) // '/frame_' // trim(tag)
        if (.not. results_has(out%res, path)) exit
        call results_delete(out%res, path, err)
        if (err%failed()) return
        n = n + 1
      end do
    end do
    call history_resume(out%hist, stem // '.history.txt', size(out%columns), mark%history_bytes, err)
    if (err%failed()) return
    allocate(out%profile_unit(size(pairs)))
    do k = 1, size(pairs)
      path = profile_name(out, k) // '.part'
      call truncate_file(path, mark%profile_bytes(k), err)
      if (err%failed()) return
      open(newunit=out%profile_unit(k), file=path, status='old', position='append', action='write', &
        iostat=ios, iomsg=msg)
      if (ios /= 0) then
        call raise_error(err, EXIT_IO, 'cannot reopen ' // path // ': ' // trim(msg))
        return
      end if
    end do
    out%frames_written = mark%frames_written
    out%nrow = mark%nrow
    call system_clock(out%clock_start, out%clock_rate)
    out%clock_last = out%clock_start
  end subroutine resume_outputs

  !> The resolved scene (every key with its final value) beside the
  !> results as <stem>.scene.nml, and as text in the HDF5 file (/scene, with
  !> /scene_path the deck it came from), so a result file carries its inputs.
  subroutine keep_resolved_scene(scene, stem, res, err)
    type(scene_t), intent(in) :: scene
    character(len=*), intent(in) :: stem
    type(results_t), intent(inout) :: res
    type(error_t), intent(inout) :: err
    integer :: unit, ios, n
    character(len=1024) :: line
    character(len=256) :: msg
    character(len=:), allocatable :: text, buf
    open(newunit=unit, file=stem // '.scene.nml', status='replace', action='readwrite', iostat=ios, iomsg=msg)
    if (ios /= 0) then
      call raise_error(err, EXIT_IO, 'cannot write ' // stem // '.scene.nml: ' // trim(msg))
      return
    end if
    call write_scene(scene, unit, err)
    if (err%failed()) return
    rewind(unit)
    ! buf(1:n) grows by doubling (append_text), linear in the echo's size
    n = 0
    do
      read(unit, '(a)', iostat=ios) line
      if (ios /= 0) exit
      call append_text(buf, n, trim(line) // new_line('a'))
    end do
    close(unit)
    text = ''
    if (n > 0) text = buf(1:n)
    call results_set_text(res, 'scene', text, err)
    if (err%failed()) return
    call results_set_text(res, 'scene_path', scene%path, err)
  end subroutine keep_resolved_scene

  !> History line, result frame and progress line when they are due at the
  !> state's step (always at the first and last step).
  subroutine write_due_outputs(out, model, state, pairs, err)
    type(output_t), intent(inout) :: out
    type(model_t), intent(in) :: model
    type(state_t), intent(in) :: state
    type(contact_pair_t), intent(in) :: pairs(:)
    type(error_t), intent(inout) :: err
    logical :: last
    integer(i8) :: now

    last = state%step == state%nsteps
    if (out%first_step < 0) out%first_step = state%step
    if (mod(state%step, out%history_every) == 0 .or. last) then
      call fill_history_row(model, state, pairs, out%row)
      call history_write(out%hist, out%row, err)
      if (err%failed()) return
      out%nbuf = out%nbuf + 1
      out%block(:, out%nbuf) = out%row
      if (out%nbuf == size(out%block, 2)) call flush_history(out, err)
      if (err%failed()) return
    end if
    ! Frame k is due at the first step whose time reaches k * interval.
    if (state%time >= (real(out%frames_written, wp) - 1.0e-9_wp)*out%frame_interval .or. last) then
      call write_frame(out, model, state, pairs, err)
      if (err%failed()) return
    end if
    call system_clock(now)
    if (real(now - out%clock_last, wp)/real(out%clock_rate, wp) >= out%progress_seconds) then
      out%clock_last = now
      call log_progress(out, state)
    end if
  end subroutine write_due_outputs

  !> Close every file: complete -> final names; otherwise the files are
  !> renamed *.incomplete.* with the reason inside, never passed off as complete.
  subroutine close_outputs(out, complete, reason, err)
    type(output_t), intent(inout) :: out
    logical, intent(in) :: complete
    character(len=*), intent(in) :: reason
    type(error_t), intent(inout) :: err
    type(error_t) :: e1, e2, e3
    logical :: ok
    if (.not. out%is_open) return
    out%is_open = .false.
    ! Each file is closed even when another failed, so none is left open.
    call flush_history(out, e1)
    ok = complete .and. .not. e1%failed()
    call history_close(out%hist, ok, e2)
    ok = ok .and. .not. e2%failed()
    call results_close(out%res, ok, e3, reason)
    ok = ok .and. .not. e3%failed()
    call close_profiles(out, ok, e3)
    if (e1%failed()) call raise_error(err, e1%code, e1%message)
    if (e2%failed()) call raise_error(err, e2%code, e2%message)
    if (e3%failed()) call raise_error(err, e3%code, e3%message)
    if (ok) call log_raw('results: ' // out%stem // '.h5, ' // out%stem // &
      '.xmf (ParaView), ' // out%stem // '.meshio.xmf (meshio), ' // out%stem // '.history.txt (gnuplot)')
  end subroutine close_outputs
end module raccord_output
