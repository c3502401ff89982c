!> Resuming a results file: reopen stem.h5.part of a stopped run, cut it
!> back to the checkpoint and rebuild what the XDMF needs
!> (doc/output-format.md, "Checkpoint file").
submodule (raccord_results) raccord_results_resume
  implicit none

contains

  !> Reopen stem.h5.part of a suspended or killed run and go on with it, in
  !> place of results_open and results_write_mesh: keep its first nframe
  !> frames and drop any later one (written after the checkpoint the run
  !> resumes from), rebuild the record the XDMF needs (the mesh blocks as
  !> results_write_mesh got them; each frame with the nodal fields named in
  !> fields(:) with ncomps(:) components, as results_write_nodal got them),
  !> and set /status back to 'running'. A missing or unreadable file is
  !> EXIT_INPUT: the checkpoint cannot be used without it.
  module subroutine results_resume(res, stem, nnode, blocks, fields, ncomps, nframe, err)
    type(results_t), intent(inout) :: res
    character(len=*), intent(in) :: stem
    integer, intent(in) :: nnode
    type(result_block_t), intent(in) :: blocks(:)
    character(len=*), intent(in) :: fields(:)
    integer, intent(in) :: ncomps(:), nframe
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: fmt
    integer(hsize_t), allocatable :: dims(:)
    real(wp), allocatable :: times(:)
    integer :: hdferr, had, f, k
    if (err%failed()) return
    if (res%is_open) then
      call raise_error(err, EXIT_INTERNAL, 'results_resume: results file "' // res%part_name // '" is already open')
      return
    end if
    res = results_t()
    res%stem = trim(stem)
    res%part_name = res%stem // '.h5.part'
    res%where = 'results file "' // res%part_name // '"'
    if (.not. file_exists(res%part_name)) then
      call raise_error(err, EXIT_INPUT, 'cannot resume: ' // res%where // ' is missing (deleted, or the run ' // &
        'was started again); run the scene afresh without --restart')
      return
    end if
    call h5_acquire(err)
    if (err%failed()) return
    call h5fopen_f(res%part_name, H5F_ACC_RDWR_F, res%file, hdferr)
    if (hdferr /= 0) then
      call raise_error(err, EXIT_INPUT, 'cannot reopen ' // res%where // ' to resume (not HDF5, or damaged ' // &
        'by a hard kill while it was written); run the scene afresh without --restart')
      call h5_release(err)
      return
    end if
    res%is_open = .true.
    allocate(res%frames(max(8, nframe + 8)), res%surfaces(0))
    ! Checks before any change: a refused file is closed untouched.
    call h5_read_attr_text(res%file, 'format', fmt, res%where, err)
    if (.not. err%failed()) then
      if (fmt /= 'raccord results') call raise_error(err, EXIT_INPUT, res%where // &
        ' is not a raccord results file (format "' // fmt // '")')
    end if
    if (.not. err%failed()) call h5_dims(res%file, '/mesh/x', dims, res%where, err)
    if (.not. err%failed()) then
      if (size(dims) /= 2) dims = [0_hsize_t, 0_hsize_t]
      if (dims(2) /= int(nnode, hsize_t)) call raise_error(err, EXIT_INPUT, res%where // ' holds a mesh of ' // &
        str(int(dims(2))) // ' nodes, the model has ' // str(nnode) // '; it belongs to another run')
    end if
    if (err%failed()) then
      call h5fclose_f(res%file, hdferr)
      call h5_release(err)
      res = results_t()
      return
    end if
    call set_layout(res, nnode, blocks)
    ! Frames: keep 0 .. nframe-1, drop the later ones (also a half-written one).
    call h5_truncate_growing(res%file, '/frames/times', nframe, had, res%where, err)
    call h5_truncate_growing(res%file, '/frames/steps', nframe, had, res%where, err)
    if (err%failed()) return
    f = nframe
    do while (h5_link_exists(res%file, '/frames/' // frame_label(f)))
      call h5_delete_link(res%file, '/frames/' // frame_label(f), res%where, err)
      if (err%failed()) return
      f = f + 1
    end do
    allocate(times(nframe))
    call h5_read_real(res%file, '/frames/times', times, res%where, err)
    if (err%failed()) return
    do f = 1, nframe
      res%frames(f)%time = times(f)
      res%frames(f)%nfield = size(fields)
      ! Frames before the checkpoint were complete, with every surface
      ! (the run adds them again with results_add_surface).
      res%frames(f)%nsurf = huge(1)
      allocate(res%frames(f)%fields(max(4, size(fields))))
      do k = 1, size(fields)
        res%frames(f)%fields(k) = nodal_field(fields(k), ncomps(k), f - 1)
      end do
    end do
    res%nframe = nframe
    call results_set_text(res, 'status', 'running', err)
    call flush_file(res, 'the resumed file', err)
  end subroutine results_resume

end submodule raccord_results_resume
