!> What a run writes while it runs: result frames (HDF5 + XDMF), the
!> time-history table (plain text and HDF5), progress lines in the log.
module raccord_output
  use raccord_kinds, only: wp, i8
  use raccord_error, only: error_t, raise_error, EXIT_IO, EXIT_INPUT
  use raccord_log, only: log_info, log_raw, log_warn
  use raccord_strings, only: str, append_text
  use raccord_mesh, only: nodes_per_element
  use raccord_model, only: model_t
  use raccord_state, only: state_t
  use raccord_time_step, only: time_plan_t
  use raccord_scene, only: scene_t
  use raccord_elastic_block, only: add_nodal_stress, add_nodal_plastic
  use raccord_material, only: MAT_J2
  use raccord_results, only: results_t, result_block_t, results_open, results_write_mesh, &
    results_write_node_set, results_begin_frame, results_write_nodal, results_end_frame, &
    results_set_text, results_close, results_suspend, results_resume, results_has, &
    results_delete, results_flush, results_add_surface, results_write_surface_frame, results_verify, &
    results_create_table, results_append_table, results_truncate_table
  use raccord_history_file, only: history_file_t, history_open, history_write, history_close, history_bytes, &
    history_suspend, history_resume
  use raccord_contact_pair, only: contact_pair_t
  use raccord_contact_surface, only: contact_surface_t
  use raccord_multiplier_solver, only: ST_OPEN
  use raccord_results, only: results_write_array
  use raccord_files, only: rename_file, file_size, truncate_file
  use raccord_h5_superblock, only: h5_clear_write_flags
  use raccord_deck, only: write_scene
  use raccord_machine, only: free_disk_bytes, physical_memory_bytes
  use raccord_paths, only: path_dir
  use raccord_history_columns, only: HISTORY_COL_LEN, history_columns, history_width, fill_history_row
  implicit none
  private

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

  !> Result frames are due by time (&output frames over t_end), at most one
  !> per step: min(frames, steps) + 2 of them (frames + 2 with a variable
  !> step, whose step count is an estimate). Their number is checked before
  !> the run: the results file numbers frames with six digits (/frames/NNNNNN),
  !> each keeps a record of about FRAME_RECORD_BYTES for the XDMF written at
  !> the end (refused beyond an eighth of the memory), and their data above
  !> a GiB must fit in the whole file system of the output folder.
  subroutine check_frame_count(scene, model, plan, pairs, stem, err)
    type(scene_t), intent(in) :: scene
    type(model_t), intent(in) :: model
    type(time_plan_t), intent(in) :: plan
    type(contact_pair_t), intent(in) :: pairs(:)
    character(len=*), intent(in) :: stem
    type(error_t), intent(inout) :: err
    integer(i8), parameter :: MAX_FRAMES = 999999, FRAME_RECORD_BYTES = 1024, GIB = 1024_i8**3
    integer(i8) :: nframe, frame_bytes, free, total, budget
    integer :: k
    character(len=:), allocatable :: folder, what
    nframe = int(scene%output%frames, i8) + 2
    if (.not. model%has_finite) nframe = min(nframe, plan%nsteps + 2)
    ! values per node: displacement, velocity, reaction (3 stored each), stress and strain (4)
    frame_bytes = 4096_i8 + 8_i8*int(model%nnode, i8)*17_i8
    do k = 1, size(pairs)
      frame_bytes = frame_bytes + 8_i8*(9_i8*pairs(k)%slave%nnode + 2_i8*pairs(k)%master%nnode)
    end do
    what = 'scene ' // scene%path // ': &output frames = ' // str(scene%output%frames) // ' over ' // &
      str(plan%nsteps) // ' steps makes up to ' // str(nframe) // ' result frames'
    budget = physical_memory_bytes()/8_i8
    if (nframe > MAX_FRAMES) then
      call raise_error(err, EXIT_INPUT, what // ', more than the ' // str(MAX_FRAMES) // ' a results file ' // &
        'numbers (six digits): set frames <= ' // str(MAX_FRAMES - 2))
      return
    end if
    if (nframe > budget/FRAME_RECORD_BYTES) then
      call raise_error(err, EXIT_INPUT, what // ', whose records for the XDMF take more than the ' // &
        str(real(budget, wp)/1.0e9_wp, 3) // ' GB (an eighth of this machine''s memory) they may: set frames <= ' // &
        str(budget/FRAME_RECORD_BYTES - 2))
      return
    end if
    folder = path_dir(stem)
    if (len(folder) == 0) folder = '.'
    free = free_disk_bytes(folder, total)
    if (free < 0 .or. total <= 0) return
    if (nframe <= total/frame_bytes .or. nframe <= GIB/frame_bytes) return
    call raise_error(err, EXIT_INPUT, what // ' of about ' // str(real(frame_bytes, wp)/1.0e6_wp, 3) // &
      ' MB, more than the whole file system of ' // folder // ' holds (' // str(real(total, wp)/1.0e9_wp, 3) // &
      ' GB): set frames <= ' // str(max(1_i8, total/frame_bytes - 2)))
  end subroutine check_frame_count

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

  !> The element blocks of the results file, one per body block.
  function result_blocks(model) result(blocks)
    type(model_t), intent(in) :: model
    type(result_block_t), allocatable :: blocks(:)
    integer :: ib, k, nblk
    nblk = 0
    do ib = 1, size(model%bodies)
      nblk = nblk + size(model%bodies(ib)%blocks)
    end do
    allocate(blocks(nblk))
    nblk = 0
    do ib = 1, size(model%bodies)
      do k = 1, size(model%bodies(ib)%blocks)
        nblk = nblk + 1
        blocks(nblk)%name = model%bodies(ib)%name
        if (size(model%bodies(ib)%blocks) > 1) blocks(nblk)%name = blocks(nblk)%name // '_' // str(k)
        blocks(nblk)%nen = nodes_per_element(model%bodies(ib)%blocks(k)%etype)
        blocks(nblk)%conn = model%bodies(ib)%blocks(k)%conn
      end do
    end do
  end function result_blocks


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

  !> Each pair's slave surface (with the contact values) and master
  !> surface (coordinates only) as surface grids of the results, named
  !> contact<k>_<surface>.
  subroutine add_contact_surfaces(out, pairs, err)
    type(output_t), intent(inout) :: out
    type(contact_pair_t), intent(in) :: pairs(:)
    type(error_t), intent(inout) :: err
    character(len=0), parameter :: none(0) = [character(len=0) ::]
    integer :: k
    do k = 1, size(pairs)
      associate (sl => pairs(k)%slave, ma => pairs(k)%master)
        call results_add_surface(out%res, 'contact' // str(k) // '_' // sl%name, '/contact/pair_' // str(k), '', &
          surface_segments(sl), sl%nnode, SURFACE_FIELDS, err)
        call results_add_surface(out%res, 'contact' // str(k) // '_' // ma%name, '/contact/pair_' // str(k), &
          'master_', surface_segments(ma), ma%nnode, none, err)
      end associate
      if (err%failed()) return
    end do
  end subroutine add_contact_surfaces

  !> Segments of a surface as indices into its node list (ends, then the
  !> middle node of a quadratic edge).
  function surface_segments(surf) result(conn)
    type(contact_surface_t), intent(in) :: surf
    integer, allocatable :: conn(:,:)
    integer :: i, j, k
    allocate(conn(surf%nen_seg, surf%nseg))
    do k = 1, surf%nseg
      do j = 1, surf%nen_seg
        conn(j, k) = 0
        do i = 1, surf%nnode
          if (surf%node(i) == surf%seg(j, k)) conn(j, k) = i
        end do
      end do
    end do
  end function surface_segments

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


  !> One text file per contact pair, <stem>.contact<k>.txt: a block per
  !> frame (gnuplot `index`), a line per slave node.
  subroutine open_profiles(out, pairs, err)
    type(output_t), intent(inout) :: out
    type(contact_pair_t), intent(in) :: pairs(:)
    type(error_t), intent(inout) :: err
    integer :: k, ios
    character(len=256) :: msg
    allocate(out%profile_unit(size(pairs)))
    do k = 1, size(pairs)
      open(newunit=out%profile_unit(k), file=profile_name(out, k) // '.part', status='replace', &
        action='write', iostat=ios, iomsg=msg)
      if (ios /= 0) then
        call raise_error(err, EXIT_IO, 'cannot write ' // profile_name(out, k) // '.part: ' // trim(msg))
        return
      end if
      write(out%profile_unit(k), '(a)') '# raccord contact profile, pair ' // str(k) // ': slave ' // &
        pairs(k)%slave%name // ', master ' // pairs(k)%master%name
      write(out%profile_unit(k), '(a)') '# one block per frame (gnuplot: index k); stresses = weighted ' // &
        'multiplier / tributary length, pressure positive in compression'
      write(out%profile_unit(k), '(a)') '# columns: 1 s0 (reference arc length)  2 x  3 y  4 gap  ' // &
        '5 pressure  6 shear  7 status (0 open, 1 stick, 2 slip)  8 slip_increment  9 lambda_n  10 lambda_t'
    end do
  end subroutine open_profiles

  function profile_name(out, k) result(path)
    type(output_t), intent(in) :: out
    integer, intent(in) :: k
    character(len=:), allocatable :: path
    path = out%stem // '.contact' // str(k) // '.txt'
  end function profile_name

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


  !> One result frame at t(n): displacement, velocity v(n), reactions, and
  !> nodal stress averaged over the elements around each node.
  subroutine write_frame(out, model, state, pairs, err)
    type(output_t), intent(inout) :: out
    type(model_t), intent(in) :: model
    type(state_t), intent(in) :: state
    type(contact_pair_t), intent(in) :: pairs(:)
    type(error_t), intent(inout) :: err
    integer :: ib, k, j

    call results_begin_frame(out%res, state%step, state%time, err)
    if (err%failed()) return
    call results_write_nodal(out%res, 'displacement', state%u, err)
    if (err%failed()) return
    call results_write_nodal(out%res, 'velocity', state%v_mid, err)
    if (err%failed()) return
    out%r_node = 0.0_wp
    do j = 1, model%ncdof
      out%r_node(model%cdof_comp(j), model%cdof_node(j)) = state%reaction(j)
    end do
    call results_write_nodal(out%res, 'reaction', out%r_node, err)
    if (err%failed()) return
    if (out%stress) then
      out%s_node = 0.0_wp
      out%wsum = 0.0_wp
      do ib = 1, size(model%bodies)
        do k = 1, size(model%bodies(ib)%blocks)
          call add_nodal_stress(model%bodies(ib)%blocks(k), state%u, out%s_node, out%wsum, &
            plastic=state%plastic(k, ib))
        end do
      end do
      do j = 1, model%nnode
        if (out%wsum(j) > 0.0_wp) out%s_node(:, j) = out%s_node(:, j)/out%wsum(j)
      end do
      call results_write_nodal(out%res, 'stress', out%s_node, err)
      if (err%failed()) return
      ! With a finite-strain body, the strain too: logarithmic in finite
      ! bodies, small strain in the others (doc/output-format.md).
      if (model%has_finite) then
        out%s_node = 0.0_wp
        out%wsum = 0.0_wp
        do ib = 1, size(model%bodies)
          do k = 1, size(model%bodies(ib)%blocks)
            call add_nodal_stress(model%bodies(ib)%blocks(k), state%u, out%s_node, out%wsum, strain=.true.)
          end do
        end do
        do j = 1, model%nnode
          if (out%wsum(j) > 0.0_wp) out%s_node(:, j) = out%s_node(:, j)/out%wsum(j)
        end do
        call results_write_nodal(out%res, 'strain', out%s_node, err)
        if (err%failed()) return
      end if
      if (model%has_plastic) then
        call write_plastic_fields(out, model, state, err)
        if (err%failed()) return
      end if
    end if
    do k = 1, size(pairs)
      call write_contact_frame(out, k, pairs(k), model, state, err)
      if (err%failed()) return
    end do
    ! the history so far goes with the frame, so a killed run keeps both
    call flush_history(out, err)
    if (err%failed()) return
    call results_end_frame(out%res, err)
    if (err%failed()) return
    out%frames_written = out%frames_written + 1
  end subroutine write_frame

  !> The j2 bodies' nodal fields (doc/output-format.md):
  !> equivalent_plastic_strain, the mean over each element's Gauss points
  !> averaged at the nodes, and yielded, at each node the fraction of its
  !> elements whose return was plastic at this frame's forces (0 at the
  !> nodes of other bodies).
  subroutine write_plastic_fields(out, model, state, err)
    type(output_t), intent(inout) :: out
    type(model_t), intent(in) :: model
    type(state_t), intent(in) :: state
    type(error_t), intent(inout) :: err
    integer :: ib, k, j
    out%s_node = 0.0_wp
    out%r_node = 0.0_wp
    out%wsum = 0.0_wp
    do ib = 1, size(model%bodies)
      do k = 1, size(model%bodies(ib)%blocks)
        if (model%bodies(ib)%blocks(k)%material /= MAT_J2) cycle
        call add_nodal_plastic(model%bodies(ib)%blocks(k), state%plastic(k, ib), state%watch(k, ib), &
          out%s_node(1:1, :), &
          out%r_node(1:1, :), out%wsum)
      end do
    end do
    do j = 1, model%nnode
      if (out%wsum(j) > 0.0_wp) then
        out%s_node(1, j) = out%s_node(1, j)/out%wsum(j)
        out%r_node(1, j) = out%r_node(1, j)/out%wsum(j)
      end if
    end do
    call results_write_nodal(out%res, 'equivalent_plastic_strain', out%s_node(1:1, :), err)
    if (err%failed()) return
    call results_write_nodal(out%res, 'yielded', out%r_node(1:1, :), err)
  end subroutine write_plastic_fields

  !> Contact profile of pair k at this frame: HDF5 arrays under
  !> /contact/pair_<k>/frame_<n>/ (the slave and master surface grids, and
  !> s0 and the pair's force) and a block of the text profile.
  subroutine write_contact_frame(out, k, pair, model, state, err)
    type(output_t), intent(inout) :: out
    integer, intent(in) :: k
    type(contact_pair_t), intent(in) :: pair
    type(model_t), intent(in) :: model
    type(state_t), intent(in) :: state
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: base
    character(len=16) :: tag
    integer :: i, p, ios, ns, nm
    write(tag, '(i6.6)') out%frames_written
    base = '/contact/pair_' // str(k) // '/frame_' // trim(tag) // '/'
    ns = pair%slave%nnode
    nm = pair%master%nnode
    associate (xy => out%surf_xy(:, 1:ns), xm => out%surf_xm(:, 1:nm), values => out%surf_values(1:ns, :))
    do i = 1, pair%slave%nnode
      p = pair%slave%node(i)
      xy(:, i) = model%x(:, p) + state%u(:, p)
    end do
    do i = 1, pair%master%nnode
      p = pair%master%node(i)
      xm(:, i) = model%x(:, p) + state%u(:, p)
    end do
    ! Columns in the order of SURFACE_FIELDS; the gap of an open node is
    ! written as 0 (as in the text profile: it is not computed there).
    values(:, 1) = pair%pressure
    values(:, 2) = pair%shear
    values(:, 3) = merge(pair%gap, 0.0_wp, pair%status /= ST_OPEN)
    values(:, 4) = pair%slip
    values(:, 5) = real(pair%status, wp)
    values(:, 6) = pair%lam_n
    values(:, 7) = pair%lam_t
    call results_write_array(out%res, base // 's0', pair%slave%s0, err)
    call results_write_array(out%res, base // 'force', pair%force, err)
    call results_write_surface_frame(out%res, 2*k - 1, xy, values, err)
    call results_write_surface_frame(out%res, 2*k, xm, out%surf_none(1:nm, :), err)
    if (err%failed()) return
    write(out%profile_unit(k), '(a,i0,a,es24.16,a,i0)', iostat=ios) '# frame ', out%frames_written, '  time ', &
      state%time, '  step ', state%step
    do i = 1, pair%slave%nnode
      write(out%profile_unit(k), '(6es24.16,i3,3es24.16)', iostat=ios) pair%slave%s0(i), xy(:, i), &
        merge(pair%gap(i), 0.0_wp, pair%status(i) /= ST_OPEN), pair%pressure(i), pair%shear(i), pair%status(i), &
        pair%slip(i), pair%lam_n(i), pair%lam_t(i)
    end do
    write(out%profile_unit(k), '(/)', iostat=ios)
    end associate
    if (ios /= 0) call raise_error(err, EXIT_IO, 'cannot write ' // profile_name(out, k) // '.part')
  end subroutine write_contact_frame

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

  !> Close the profile files: final name when complete, *.incomplete.txt otherwise.
  subroutine close_profiles(out, complete, err)
    type(output_t), intent(inout) :: out
    logical, intent(in) :: complete
    type(error_t), intent(inout) :: err
    integer :: k
    character(len=:), allocatable :: final
    if (.not. allocated(out%profile_unit)) return
    do k = 1, size(out%profile_unit)
      close(out%profile_unit(k))
      final = profile_name(out, k)
      if (.not. complete) final = out%stem // '.contact' // str(k) // '.incomplete.txt'
      call rename_file(profile_name(out, k) // '.part', final, err)
    end do
  end subroutine close_profiles
end module raccord_output
