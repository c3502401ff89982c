!> Results file: one HDF5 file with the mesh, node sets, output frames of
!> nodal fields and any other arrays, plus an XDMF file so ParaView can
!> open it. Layout and conventions: doc/output-format.md.
!>
!> A run that fails must never leave a file that looks complete: the data
!> go to stem.h5.part while the run goes on (flushed after every frame, so
!> a killed run keeps its frames), and results_close renames the pair to
!> stem.h5 / stem.xmf only when the run says it is complete, otherwise to
!> stem.incomplete.h5 / stem.incomplete.xmf with the reason in /status.
!>
!> Usage: results_open, results_write_mesh (once), then per output frame
!> results_begin_frame, results_write_nodal (per field), results_end_frame;
!> results_write_array / _table / _node_set / results_set_text at any time
!> while open; results_close last, also after an error.
!> A run that stops at a checkpoint calls results_suspend instead (the file
!> stays stem.h5.part); the restarted run calls results_resume in place of
!> results_open and results_write_mesh, and goes on with the next frame.
module raccord_results
  use hdf5, only: hid_t, hsize_t, h5fopen_f, h5fclose_f, h5fflush_f, h5gcreate_f, h5gclose_f, &
    h5dopen_f, h5dclose_f, H5F_ACC_RDWR_F, H5F_SCOPE_GLOBAL_F
  use raccord_kinds, only: wp
  use raccord_error, only: error_t, raise_error, prefix_error, EXIT_IO, EXIT_INPUT, EXIT_INTERNAL
  use raccord_strings, only: str
  use raccord_files, only: make_directory, rename_file, delete_file, file_exists, write_failure_reason
  use raccord_h5_verify, only: h5_verify_tree
  use raccord_h5, only: h5_acquire, h5_release, h5_create_file, h5_delete_link, h5_link_exists, &
    h5_write_real, h5_write_int, h5_write_text, h5_attr_real, h5_attr_int, h5_attr_text, &
    h5_attr_text_list, h5_create_growing, h5_append_real, h5_append_int, h5_truncate_growing
  use raccord_h5_read, only: h5_read_real, h5_read_attr_text, h5_dims
  use raccord_xdmf, only: xdmf_block_t, xdmf_field_t, xdmf_frame_t, write_xdmf, frame_label
  implicit none
  private

  public :: results_open, results_write_mesh, results_write_node_set, results_verify
  public :: results_begin_frame, results_write_nodal, results_end_frame
  public :: results_write_array, results_write_table, results_set_text, results_close
  public :: results_suspend, results_resume, results_has, results_delete, results_flush

  !> Version of the file layout, stored as the root attribute format_version;
  !> bump it when doc/output-format.md changes incompatibly.
  integer, parameter, public :: RESULTS_FORMAT_VERSION = 1

  !> One body's elements for the mesh section.
  type, public :: result_block_t
    character(len=:), allocatable :: name
    integer :: nen = 4                        !< 4 (Q4) or 8 (Q8: corners, then mid-sides)
    integer, allocatable :: conn(:,:)         !< (nen, nel) 1-based node indices
  end type result_block_t

  !> An open results file. Components are private: the HDF5 handles and the
  !> record of what was written (needed for the XDMF) stay inside.
  type, public :: results_t
    private
    logical :: is_open = .false.
    character(len=:), allocatable :: stem
    character(len=:), allocatable :: part_name     !< stem.h5.part, the file being written
    character(len=:), allocatable :: where         !< "file ..." for messages
    integer(hid_t) :: file = -1
    integer :: nnode = -1                          !< -1 until the mesh is written
    type(xdmf_block_t), allocatable :: blocks(:)
    logical :: in_frame = .false.
    integer :: nframe = 0                          !< frames begun
    integer :: step = 0                            !< step of the current frame
    type(xdmf_frame_t), allocatable :: frames(:)
  end type results_t

  !> Write a real(wp) array of rank 1 or 2 at an HDF5 path.
  interface results_write_array
    module procedure write_array_1d, write_array_2d
  end interface results_write_array

contains

  !> Create stem.h5.part (and its folder) and write the file header:
  !> root attributes format and format_version, /status = 'running', and
  !> the empty /frames/times and /frames/steps. Stale stem.h5, stem.xmf and
  !> stem.incomplete.* from an earlier run are deleted so they cannot be
  !> mistaken for this run's results.
  subroutine results_open(res, stem, err)
    type(results_t), intent(inout) :: res
    character(len=*), intent(in) :: stem
    type(error_t), intent(inout) :: err
    integer :: hdferr
    integer(hid_t) :: root
    if (err%failed()) return
    if (res%is_open) then
      call raise_error(err, EXIT_INTERNAL, 'results_open: results file "' // res%part_name &
        // '" is already open; close it first')
      return
    end if
    if (len_trim(stem) == 0) then
      call raise_error(err, EXIT_INPUT, 'results_open: empty output name; set the output stem in the scene')
      return
    end if
    res = results_t()
    res%stem = trim(stem)
    res%part_name = res%stem // '.h5.part'
    res%where = 'results file "' // res%part_name // '"'
    call make_directory(folder_of(res%stem), err)
    if (err%failed()) return
    call h5_acquire(err)
    if (err%failed()) return
    call h5_create_file(res%part_name, res%file, hdferr)
    if (hdferr /= 0) then
      call raise_error(err, EXIT_IO, 'cannot create ' // res%where // ': ' // &
        write_failure_reason(folder_of(res%stem)))
      call h5_release(err)
      return
    end if
    res%is_open = .true.
    allocate(res%blocks(0), res%frames(8))
    call delete_file(res%stem // '.h5')
    call delete_file(res%stem // '.xmf')
    call delete_file(res%stem // '.xmf.part')
    call delete_file(res%stem // '.incomplete.h5')
    call delete_file(res%stem // '.incomplete.xmf')
    root = res%file
    call h5_attr_text(root, 'format', 'raccord results', res%where, err)
    call h5_attr_int(root, 'format_version', RESULTS_FORMAT_VERSION, res%where, err)
    if (err%failed()) return
    call h5_write_text(root, '/status', 'running', res%where, err)
    call h5_create_growing(root, '/frames/times', .true., res%where, err)
    call h5_create_growing(root, '/frames/steps', .false., res%where, err)
    call flush_file(res, 'the file header', err)
  end subroutine results_open

  !> Write node coordinates x(2, nnode) to /mesh/x and each block's 0-based
  !> connectivity to /mesh/blocks/<name>/connectivity. Once per file.
  subroutine results_write_mesh(res, x, blocks, err)
    type(results_t), intent(inout) :: res
    real(wp), intent(in) :: x(:,:)
    type(result_block_t), intent(in) :: blocks(:)
    type(error_t), intent(inout) :: err
    integer :: b, nnode
    character(len=:), allocatable :: path
    integer(hid_t) :: grp
    integer :: hdferr
    if (.not. usable(res, 'results_write_mesh', err)) return
    if (res%nnode >= 0) then
      call raise_error(err, EXIT_INTERNAL, 'results_write_mesh: the mesh of ' // res%where &
        // ' was already written')
      return
    end if
    if (size(x, 1) /= 2) then
      call raise_error(err, EXIT_INTERNAL, 'results_write_mesh: x must be (2, nnode), got (' &
        // str(size(x, 1)) // ', ' // str(size(x, 2)) // ')')
      return
    end if
    nnode = size(x, 2)
    call check_blocks(blocks, nnode, err)
    if (err%failed()) return
    call h5_write_real(res%file, '/mesh/x', x, res%where, err)
    if (err%failed()) return
    deallocate(res%blocks)
    allocate(res%blocks(size(blocks)))
    do b = 1, size(blocks)
      path = '/mesh/blocks/' // blocks(b)%name
      ! 0-based so XDMF readers use the dataset as it is.
      call h5_write_int(res%file, path // '/connectivity', blocks(b)%conn - 1, res%where, err)
      if (err%failed()) return
      call h5gopen_checked(res, path, grp, err)
      if (err%failed()) return
      call h5_attr_int(grp, 'nen', blocks(b)%nen, res%where, err)
      call h5_attr_text(grp, 'topology', trim(merge('Quadrilateral_8', 'Quadrilateral  ', blocks(b)%nen == 8)), &
        res%where, err)
      call h5gclose_f(grp, hdferr)
      if (hdferr /= 0) call raise_error(err, EXIT_IO, 'cannot close group "' // path // '" in ' // res%where)
      if (err%failed()) return
      res%blocks(b)%name = blocks(b)%name
      res%blocks(b)%conn_path = path // '/connectivity'
      res%blocks(b)%nen = blocks(b)%nen
      res%blocks(b)%nel = size(blocks(b)%conn, 2)
    end do
    res%nnode = nnode
    call flush_file(res, 'the mesh', err)
  end subroutine results_write_mesh

  !> Write a named node set (1-based internal indices) as 0-based indices to
  !> /mesh/node_sets/<name>, for post-processing (e.g. reaction sums).
  subroutine results_write_node_set(res, name, nodes, err)
    type(results_t), intent(inout) :: res
    character(len=*), intent(in) :: name
    integer, intent(in) :: nodes(:)
    type(error_t), intent(inout) :: err
    if (.not. usable(res, 'results_write_node_set', err)) return
    call check_name(name, 'node set', err)
    if (err%failed()) return
    if (res%nnode >= 0 .and. size(nodes) > 0) then
      if (minval(nodes) < 1 .or. maxval(nodes) > res%nnode) then
        call raise_error(err, EXIT_INTERNAL, 'results_write_node_set: node set "' // name &
          // '" has indices outside 1..' // str(res%nnode))
        return
      end if
    end if
    call h5_write_int(res%file, '/mesh/node_sets/' // trim(name), nodes - 1, res%where, err)
  end subroutine results_write_node_set

  !> Start output frame number nframe (group /frames/NNNNNN, six digits from
  !> 000000) with its step and time as attributes.
  subroutine results_begin_frame(res, step, time, err)
    type(results_t), intent(inout) :: res
    integer, intent(in) :: step
    real(wp), intent(in) :: time
    type(error_t), intent(inout) :: err
    type(xdmf_frame_t), allocatable :: grown(:)
    character(len=:), allocatable :: path
    integer(hid_t) :: grp
    integer :: hdferr
    if (.not. usable(res, 'results_begin_frame', err)) return
    if (res%nnode < 0) then
      call raise_error(err, EXIT_INTERNAL, 'results_begin_frame: write the mesh of ' // res%where &
        // ' before the first frame')
      return
    end if
    if (res%in_frame) then
      call raise_error(err, EXIT_INTERNAL, 'results_begin_frame: frame ' // frame_label(res%nframe - 1) &
        // ' of ' // res%where // ' was not ended')
      return
    end if
    path = '/frames/' // frame_label(res%nframe)
    call h5gcreate_f(res%file, path, grp, hdferr)
    if (hdferr /= 0) then
      call raise_error(err, EXIT_IO, 'cannot create group "' // path // '" in ' // res%where)
      return
    end if
    call h5_attr_real(grp, 'time', time, res%where, err)
    call h5_attr_int(grp, 'step', step, res%where, err)
    call h5gclose_f(grp, hdferr)
    if (hdferr /= 0) call raise_error(err, EXIT_IO, 'cannot close group "' // path // '" in ' // res%where)
    if (err%failed()) return
    if (res%nframe == size(res%frames)) then
      allocate(grown(2*size(res%frames)))
      grown(1:res%nframe) = res%frames(1:res%nframe)
      call move_alloc(grown, res%frames)
    end if
    res%nframe = res%nframe + 1
    res%frames(res%nframe)%time = time
    res%frames(res%nframe)%nfield = 0
    allocate(res%frames(res%nframe)%fields(4))
    res%step = step
    res%in_frame = .true.
  end subroutine results_begin_frame

  !> Write a nodal field values(ncomp, nnode) of the current frame to
  !> /frames/NNNNNN/<name>. Stored as h5dump dims (nnode) for ncomp = 1,
  !> (nnode, 3) with a zero third component for ncomp = 2 (ParaView needs
  !> three components to warp by a vector), (nnode, ncomp) otherwise.
  subroutine results_write_nodal(res, name, values, err)
    type(results_t), intent(inout) :: res
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: values(:,:)
    type(error_t), intent(inout) :: err
    type(xdmf_field_t) :: field
    type(xdmf_field_t), allocatable :: grown(:)
    real(wp), allocatable :: padded(:,:)
    integer :: ncomp, k
    if (.not. usable(res, 'results_write_nodal', err)) return
    if (.not. res%in_frame) then
      call raise_error(err, EXIT_INTERNAL, 'results_write_nodal: field "' // name &
        // '" written outside a frame; call results_begin_frame first')
      return
    end if
    call check_name(name, 'nodal field', err)
    if (err%failed()) return
    ncomp = size(values, 1)
    if (size(values, 2) /= res%nnode .or. ncomp < 1) then
      call raise_error(err, EXIT_INTERNAL, 'results_write_nodal: field "' // name // '" is (' &
        // str(ncomp) // ', ' // str(size(values, 2)) // '), expected (ncomp >= 1, ' &
        // str(res%nnode) // ')')
      return
    end if
    field = nodal_field(name, ncomp, res%nframe - 1)
    select case (ncomp)
    case (1)
      call h5_write_real(res%file, field%path, values(1, :), res%where, err)
    case (2)
      allocate(padded(3, res%nnode))
      padded(1:2, :) = values
      padded(3, :) = 0.0_wp
      call h5_write_real(res%file, field%path, padded, res%where, err)
    case default
      call h5_write_real(res%file, field%path, values, res%where, err)
    end select
    if (err%failed()) return
    call dataset_attr_int(res, field%path, 'ncomp', ncomp, err)
    if (err%failed()) return
    associate (fr => res%frames(res%nframe))
      if (fr%nfield == size(fr%fields)) then
        allocate(grown(2*size(fr%fields)))
        do k = 1, fr%nfield
          grown(k) = fr%fields(k)
        end do
        call move_alloc(grown, fr%fields)
      end if
      fr%nfield = fr%nfield + 1
      fr%fields(fr%nfield) = field
    end associate
  end subroutine results_write_nodal

  !> How a nodal field of ncomp components is stored in frame `frame`
  !> (0-based): path, XDMF kind, stored components.
  pure function nodal_field(name, ncomp, frame) result(field)
    character(len=*), intent(in) :: name
    integer, intent(in) :: ncomp, frame
    type(xdmf_field_t) :: field
    field%name = trim(name)
    field%path = '/frames/' // frame_label(frame) // '/' // field%name
    select case (ncomp)
    case (1)
      field%kind = 'Scalar'
      field%ncomp = 1
    case (2)
      field%kind = 'Vector'
      field%ncomp = 3
    case default
      ! Matrix: a plain multi-component array; stress (sxx, syy, sxy, szz)
      ! is neither a 3-vector nor a full tensor.
      field%kind = 'Matrix'
      field%ncomp = ncomp
    end select
  end function nodal_field

  !> Stop writing for now: /status = reason (e.g. 'suspended at step N'),
  !> flush and close, and keep the name stem.h5.part so that the file never
  !> looks complete. results_resume goes on with it.
  subroutine results_suspend(res, reason, err)
    type(results_t), intent(inout) :: res
    character(len=*), intent(in) :: reason
    type(error_t), intent(inout) :: err
    type(error_t) :: cerr
    integer :: hdferr
    if (.not. res%is_open) return
    if (res%in_frame) call results_end_frame(res, cerr)
    call results_set_text(res, 'status', reason, cerr)
    call flush_file(res, 'the status', cerr)
    call h5fclose_f(res%file, hdferr)
    if (hdferr /= 0) call raise_error(cerr, EXIT_IO, 'cannot close ' // res%where // ' (disk full?)')
    res%is_open = .false.
    call h5_release(cerr)
    if (cerr%failed()) call raise_error(err, cerr%code, cerr%message)
    res = results_t()
  end subroutine results_suspend

  !> Reopen stem.h5.part of a suspended or killed run and go on with it, in
  !> place of results_open and results_write_mesh: keep its first nframe
  !> frames and drop any later one (written after the checkpoint the run
  !> resumes from), rebuild the record the XDMF needs (the mesh blocks as
  !> results_write_mesh got them; each frame with the nodal fields named in
  !> fields(:) with ncomps(:) components, as results_write_nodal got them),
  !> and set /status back to 'running'. A missing or unreadable file is
  !> EXIT_INPUT: the checkpoint cannot be used without it.
  subroutine results_resume(res, stem, nnode, blocks, fields, ncomps, nframe, err)
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
    integer :: hdferr, had, f, k, b
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
    allocate(res%blocks(size(blocks)), res%frames(max(8, nframe + 8)))
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
    res%nnode = nnode
    do b = 1, size(blocks)
      res%blocks(b)%name = blocks(b)%name
      res%blocks(b)%conn_path = '/mesh/blocks/' // blocks(b)%name // '/connectivity'
      res%blocks(b)%nen = blocks(b)%nen
      res%blocks(b)%nel = size(blocks(b)%conn, 2)
    end do
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
      allocate(res%frames(f)%fields(max(4, size(fields))))
      do k = 1, size(fields)
        res%frames(f)%fields(k) = nodal_field(fields(k), ncomps(k), f - 1)
      end do
    end do
    res%nframe = nframe
    call results_set_text(res, 'status', 'running', err)
    call flush_file(res, 'the resumed file', err)
  end subroutine results_resume

  !> Flush everything written so far to disk (before a checkpoint).
  subroutine results_flush(res, err)
    type(results_t), intent(in) :: res
    type(error_t), intent(inout) :: err
    if (.not. usable(res, 'results_flush', err)) return
    call flush_file(res, 'the results', err)
  end subroutine results_flush

  !> Read back everything in the open file (raccord_h5_verify): a restart
  !> checks the results it continues; a damaged one is refused (EXIT_INPUT).
  subroutine results_verify(res, err)
    type(results_t), intent(in) :: res
    type(error_t), intent(inout) :: err
    integer :: ndata
    if (.not. usable(res, 'results_verify', err)) return
    ndata = 0
    call h5_verify_tree(res%file, '/', res%where, ndata, err)
  end subroutine results_verify

  !> True when an object exists at `path` in the open file.
  logical function results_has(res, path)
    type(results_t), intent(in) :: res
    character(len=*), intent(in) :: path
    results_has = .false.
    if (.not. res%is_open) return
    results_has = h5_link_exists(res%file, absolute(path))
  end function results_has

  !> Remove the object at `path` (nothing if there is none).
  subroutine results_delete(res, path, err)
    type(results_t), intent(inout) :: res
    character(len=*), intent(in) :: path
    type(error_t), intent(inout) :: err
    if (.not. usable(res, 'results_delete', err)) return
    call h5_delete_link(res%file, absolute(path), res%where, err)
  end subroutine results_delete

  !> End the current frame: append its time and step to /frames/times and
  !> /frames/steps (so they list completed frames) and flush the file.
  subroutine results_end_frame(res, err)
    type(results_t), intent(inout) :: res
    type(error_t), intent(inout) :: err
    if (.not. usable(res, 'results_end_frame', err)) return
    if (.not. res%in_frame) then
      call raise_error(err, EXIT_INTERNAL, 'results_end_frame: no frame of ' // res%where // ' is open')
      return
    end if
    res%in_frame = .false.
    call h5_append_real(res%file, '/frames/times', res%frames(res%nframe)%time, res%where, err)
    call h5_append_int(res%file, '/frames/steps', res%step, res%where, err)
    call flush_file(res, 'frame ' // frame_label(res%nframe - 1), err)
  end subroutine results_end_frame

  !> Write a time-history table(ncol, nrow) at `path` (h5dump dims
  !> (nrow, ncol): one row per output time) with the column names as its
  !> string-array attribute `columns`.
  subroutine results_write_table(res, path, names, table, err)
    type(results_t), intent(inout) :: res
    character(len=*), intent(in) :: path
    character(len=*), intent(in) :: names(:)
    real(wp), intent(in) :: table(:,:)
    type(error_t), intent(inout) :: err
    integer(hid_t) :: dset
    integer :: hdferr
    character(len=:), allocatable :: full
    if (.not. usable(res, 'results_write_table', err)) return
    if (size(names) /= size(table, 1)) then
      call raise_error(err, EXIT_INTERNAL, 'results_write_table: ' // str(size(names)) &
        // ' column names for ' // str(size(table, 1)) // ' columns in "' // path // '"')
      return
    end if
    full = absolute(path)
    call h5_write_real(res%file, full, table, res%where, err)
    if (err%failed()) return
    call h5dopen_f(res%file, full, dset, hdferr)
    if (hdferr /= 0) then
      call raise_error(err, EXIT_IO, 'cannot reopen dataset "' // full // '" in ' // res%where)
      return
    end if
    call h5_attr_text_list(dset, 'columns', names, res%where, err)
    call h5dclose_f(dset, hdferr)
    if (hdferr /= 0) call raise_error(err, EXIT_IO, 'cannot close dataset "' // full // '" in ' // res%where)
  end subroutine results_write_table

  !> Store a text as a scalar string dataset: `name` alone goes under the
  !> root (/version, /scene, /status), a path starting with '/' is used as
  !> it is. An existing text of that name is replaced.
  subroutine results_set_text(res, name, text, err)
    type(results_t), intent(inout) :: res
    character(len=*), intent(in) :: name, text
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: full
    if (.not. usable(res, 'results_set_text', err)) return
    if (len_trim(name) == 0) then
      call raise_error(err, EXIT_INTERNAL, 'results_set_text: empty name in ' // res%where)
      return
    end if
    full = absolute(name)
    call h5_delete_link(res%file, full, res%where, err)
    call h5_write_text(res%file, full, text, res%where, err)
  end subroutine results_set_text

  !> Finish the file. complete = .true.: /status = 'complete', write the
  !> XDMF, close, rename to stem.h5 and stem.xmf. complete = .false. (or any
  !> failure while closing): /status = 'incomplete: ' // reason and the
  !> names stem.incomplete.h5 / stem.incomplete.xmf. A frame still open is
  !> ended first. Closing a results_t that is not open does nothing, so
  !> error paths may always call it.
  subroutine results_close(res, complete, err, reason)
    type(results_t), intent(inout) :: res
    logical, intent(in) :: complete
    type(error_t), intent(inout) :: err
    character(len=*), intent(in), optional :: reason
    type(error_t) :: cerr, step_err
    character(len=:), allocatable :: why, h5_final, xmf_final, xmf_part
    logical :: done, have_xmf
    integer :: hdferr
    if (.not. res%is_open) return
    why = 'no reason given'
    if (present(reason)) then
      if (len_trim(reason) > 0) why = trim(reason)
    end if
    xmf_part = res%stem // '.xmf.part'
    have_xmf = .false.
    if (res%in_frame) call results_end_frame(res, cerr)
    done = complete .and. .not. cerr%failed()

    ! Each step gets a fresh status so that one failure does not skip the
    ! rest: the file must still be closed and renamed.
    if (done) then
      call write_light_data(res, .true., xmf_part, step_err, have_xmf)
      if (.not. step_err%failed()) call results_set_text(res, 'status', 'complete', step_err)
      if (step_err%failed()) then
        done = .false.
        call raise_error(cerr, step_err%code, step_err%message)
      end if
    end if
    if (.not. done) then
      if (complete) why = 'closing failed: ' // cerr%message
      call step_err%clear()
      call results_set_text(res, 'status', 'incomplete: ' // why, step_err)
      if (step_err%failed()) call raise_error(cerr, step_err%code, step_err%message)
      call step_err%clear()
      call write_light_data(res, .false., xmf_part, step_err, have_xmf)
      if (step_err%failed()) call raise_error(cerr, step_err%code, step_err%message)
    end if

    call h5fclose_f(res%file, hdferr)
    if (hdferr /= 0) then
      call raise_error(cerr, EXIT_IO, 'cannot close ' // res%where // ' (disk full?)')
      if (done) then
        ! The XDMF names stem.h5, which will not exist: drop it.
        done = .false.
        call delete_file(xmf_part)
        have_xmf = .false.
      end if
    end if
    res%is_open = .false.
    call h5_release(cerr)

    if (done) then
      h5_final = res%stem // '.h5'
      xmf_final = res%stem // '.xmf'
    else
      h5_final = res%stem // '.incomplete.h5'
      xmf_final = res%stem // '.incomplete.xmf'
    end if
    call rename_file(res%part_name, h5_final, cerr)
    if (have_xmf) call rename_file(xmf_part, xmf_final, cerr)
    if (cerr%failed()) then
      call prefix_error(cerr, 'while closing ' // res%where)
      call raise_error(err, cerr%code, cerr%message)
    end if
    res = results_t()
  end subroutine results_close

  ! --- private -----------------------------------------------------------

  subroutine write_array_1d(res, path, values, err)
    type(results_t), intent(inout) :: res
    character(len=*), intent(in) :: path
    real(wp), intent(in) :: values(:)
    type(error_t), intent(inout) :: err
    if (.not. usable(res, 'results_write_array', err)) return
    call h5_write_real(res%file, absolute(path), values, res%where, err)
  end subroutine write_array_1d

  subroutine write_array_2d(res, path, values, err)
    type(results_t), intent(inout) :: res
    character(len=*), intent(in) :: path
    real(wp), intent(in) :: values(:,:)
    type(error_t), intent(inout) :: err
    if (.not. usable(res, 'results_write_array', err)) return
    call h5_write_real(res%file, absolute(path), values, res%where, err)
  end subroutine write_array_2d

  !> Write the XDMF to xmf_part for the final HDF5 name implied by `done`.
  subroutine write_light_data(res, done, xmf_part, err, written)
    type(results_t), intent(in) :: res
    logical, intent(in) :: done
    character(len=*), intent(in) :: xmf_part
    type(error_t), intent(inout) :: err
    logical, intent(out) :: written
    character(len=:), allocatable :: h5_name
    type(error_t) :: werr
    if (done) then
      h5_name = base_name(res%stem) // '.h5'
    else
      h5_name = base_name(res%stem) // '.incomplete.h5'
    end if
    call write_xdmf(xmf_part, h5_name, max(res%nnode, 0), res%blocks, res%frames, res%nframe, werr)
    written = .not. werr%failed()
    if (.not. written) then
      call delete_file(xmf_part)
      call raise_error(err, werr%code, werr%message)
    end if
  end subroutine write_light_data

  !> True when the results file is open; otherwise an error naming the caller.
  logical function usable(res, caller, err)
    type(results_t), intent(in) :: res
    character(len=*), intent(in) :: caller
    type(error_t), intent(inout) :: err
    usable = .false.
    if (err%failed()) return
    if (.not. res%is_open) then
      call raise_error(err, EXIT_INTERNAL, caller // ': the results file is not open (call results_open)')
      return
    end if
    usable = .true.
  end function usable

  !> Flush to disk so that a killed run keeps everything written so far.
  subroutine flush_file(res, what, err)
    type(results_t), intent(in) :: res
    character(len=*), intent(in) :: what
    type(error_t), intent(inout) :: err
    integer :: hdferr
    if (err%failed()) return
    call h5fflush_f(res%file, H5F_SCOPE_GLOBAL_F, hdferr)
    if (hdferr /= 0) call raise_error(err, EXIT_IO, 'cannot flush ' // what // ' to ' // res%where &
      // ' (disk full?)')
  end subroutine flush_file

  !> Blocks: valid unique names, nen 4 or 8, conn (nen, nel) within 1..nnode.
  subroutine check_blocks(blocks, nnode, err)
    type(result_block_t), intent(in) :: blocks(:)
    integer, intent(in) :: nnode
    type(error_t), intent(inout) :: err
    integer :: b, c
    do b = 1, size(blocks)
      if (.not. allocated(blocks(b)%name)) then
        call raise_error(err, EXIT_INTERNAL, 'results_write_mesh: block ' // str(b) // ' has no name')
        return
      end if
      call check_name(blocks(b)%name, 'element block', err)
      if (err%failed()) return
      do c = 1, b - 1
        if (blocks(c)%name == blocks(b)%name) then
          call raise_error(err, EXIT_INPUT, 'results_write_mesh: two blocks are named "' &
            // blocks(b)%name // '"; give each body its own name')
          return
        end if
      end do
      if (blocks(b)%nen /= 4 .and. blocks(b)%nen /= 8) then
        call raise_error(err, EXIT_INTERNAL, 'results_write_mesh: block "' // blocks(b)%name &
          // '" has nen = ' // str(blocks(b)%nen) // ', expected 4 (Q4) or 8 (Q8)')
        return
      end if
      if (.not. allocated(blocks(b)%conn)) then
        call raise_error(err, EXIT_INTERNAL, 'results_write_mesh: block "' // blocks(b)%name &
          // '" has no connectivity')
        return
      end if
      if (size(blocks(b)%conn, 1) /= blocks(b)%nen) then
        call raise_error(err, EXIT_INTERNAL, 'results_write_mesh: block "' // blocks(b)%name &
          // '" connectivity has ' // str(size(blocks(b)%conn, 1)) // ' rows, expected nen = ' &
          // str(blocks(b)%nen))
        return
      end if
      if (size(blocks(b)%conn) > 0) then
        if (minval(blocks(b)%conn) < 1 .or. maxval(blocks(b)%conn) > nnode) then
          call raise_error(err, EXIT_INTERNAL, 'results_write_mesh: block "' // blocks(b)%name &
            // '" refers to nodes outside 1..' // str(nnode))
          return
        end if
      end if
    end do
  end subroutine check_blocks

  !> A name becomes one HDF5 link: not empty, no '/'.
  subroutine check_name(name, what, err)
    character(len=*), intent(in) :: name, what
    type(error_t), intent(inout) :: err
    if (len_trim(name) == 0 .or. index(name, '/') > 0 .or. trim(name) == '.') then
      call raise_error(err, EXIT_INPUT, 'invalid ' // what // ' name "' // trim(name) &
        // '" for the results file: use a non-empty name without "/"')
    end if
  end subroutine check_name

  !> Put an integer attribute on an existing dataset.
  subroutine dataset_attr_int(res, path, name, value, err)
    type(results_t), intent(in) :: res
    character(len=*), intent(in) :: path, name
    integer, intent(in) :: value
    type(error_t), intent(inout) :: err
    integer(hid_t) :: dset
    integer :: hdferr
    call h5dopen_f(res%file, path, dset, hdferr)
    if (hdferr /= 0) then
      call raise_error(err, EXIT_IO, 'cannot reopen dataset "' // path // '" in ' // res%where)
      return
    end if
    call h5_attr_int(dset, name, value, res%where, err)
    call h5dclose_f(dset, hdferr)
    if (hdferr /= 0) call raise_error(err, EXIT_IO, 'cannot close dataset "' // path // '" in ' // res%where)
  end subroutine dataset_attr_int

  !> Open an existing group, with the error named.
  subroutine h5gopen_checked(res, path, grp, err)
    use hdf5, only: h5gopen_f
    type(results_t), intent(in) :: res
    character(len=*), intent(in) :: path
    integer(hid_t), intent(out) :: grp
    type(error_t), intent(inout) :: err
    integer :: hdferr
    call h5gopen_f(res%file, path, grp, hdferr)
    if (hdferr /= 0) call raise_error(err, EXIT_IO, 'cannot open group "' // path // '" in ' // res%where)
  end subroutine h5gopen_checked

  !> A path made absolute ('a/b' -> '/a/b'), trailing blanks removed.
  pure function absolute(path) result(s)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: s
    s = trim(adjustl(path))
    if (len(s) == 0) then
      s = '/'
    else if (s(1:1) /= '/') then
      s = '/' // s
    end if
  end function absolute

  !> Folder part of a path ('out/run' -> 'out', 'run' -> '').
  pure function folder_of(path) result(s)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: s
    integer :: k
    k = index(path, '/', back=.true.)
    s = path(1:max(k - 1, 0))
  end function folder_of

  !> File part of a path ('out/run' -> 'run').
  pure function base_name(path) result(s)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: s
    s = path(index(path, '/', back=.true.) + 1:)
  end function base_name
end module raccord_results
