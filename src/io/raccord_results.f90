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
!> Nodes are stored grouped by element block (raccord_node_order), so that
!> each body's grid in the XDMF is a hyperslab of the global arrays; callers
!> pass and get model order, the module permutes.
!>
!> Usage: results_open, results_write_mesh (once), results_add_surface (per
!> contact surface), then per output frame results_begin_frame,
!> results_write_nodal (per field), results_write_surface_frame (per
!> surface, in the order added), results_end_frame;
!> results_write_array / _table / _node_set / results_set_text at any time
!> while open; results_close last, also after an error.
!> A run that stops at a checkpoint calls results_suspend instead (the file
!> stays stem.h5.part); the restarted run calls results_resume in place of
!> results_open and results_write_mesh, and goes on with the next frame.
module raccord_results
  use hdf5, only: hid_t, hsize_t, h5fopen_f, h5fclose_f, h5fflush_f, h5gcreate_f, h5gclose_f, &
    h5dopen_f, h5dclose_f, H5F_ACC_RDWR_F, H5F_SCOPE_GLOBAL_F
  use raccord_kinds, only: wp, i8
  use raccord_error, only: error_t, raise_error, prefix_error, EXIT_IO, EXIT_INPUT, EXIT_INTERNAL
  use raccord_strings, only: str
  use raccord_files, only: make_directory, rename_file, delete_file, file_exists, write_failure_reason
  use raccord_h5_verify, only: h5_verify_tree
  use raccord_h5, only: h5_acquire, h5_release, h5_create_file, h5_delete_link, h5_link_exists, &
    h5_write_real, h5_write_int, h5_write_text, h5_attr_real, h5_attr_int, h5_attr_text, &
    h5_attr_text_list, h5_create_growing, h5_append_real, h5_append_i8, h5_truncate_growing, h5_attr_i8
  use raccord_h5_read, only: h5_read_real, h5_read_attr_text, h5_dims
  use raccord_h5_table, only: h5_create_table, h5_append_rows, h5_truncate_rows
  use raccord_xdmf, only: xdmf_block_t, xdmf_field_t, xdmf_frame_t, xdmf_surface_t, write_xdmf, &
    write_meshio_index, frame_label
  use raccord_node_order, only: node_order
  implicit none
  private

  public :: results_open, results_write_mesh, results_write_node_set, results_verify
  public :: results_begin_frame, results_write_nodal, results_end_frame
  public :: results_write_array, results_write_table, results_set_text, results_close
  public :: results_create_table, results_append_table, results_truncate_table
  public :: results_suspend, results_resume, results_has, results_delete, results_flush
  public :: results_add_surface, results_write_surface_frame

  !> Version of the file layout, stored as the root attribute format_version;
  !> bump it when doc/output-format.md changes incompatibly.
  integer, parameter, public :: RESULTS_FORMAT_VERSION = 2

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
    integer, allocatable :: order(:)               !< (nnode) model node stored at each row
    integer, allocatable :: row(:)                 !< (nnode) row of each model node
    real(wp), allocatable :: s1(:), s3(:,:), sn(:,:) !< nodal fields in row order, sized on first use
    type(xdmf_surface_t), allocatable :: surfaces(:)
    logical :: in_frame = .false.
    integer :: nframe = 0                          !< frames begun
    integer(i8) :: step = 0                        !< step of the current frame (64-bit: a long run passes 2**31)
    type(xdmf_frame_t), allocatable :: frames(:)
  end type results_t

  !> Start an output frame at a step given as a default or a 64-bit integer.
  interface results_begin_frame
    module procedure begin_frame_i8, begin_frame_int
  end interface results_begin_frame

  !> Write a real(wp) array of rank 1 or 2 at an HDF5 path.
  interface results_write_array
    module procedure write_array_1d, write_array_2d
  end interface results_write_array

  interface
    !> Reopen a suspended run's file (raccord_results_resume).
    module subroutine results_resume(res, stem, nnode, blocks, fields, ncomps, nframe, err)
      type(results_t), intent(inout) :: res
      character(len=*), intent(in) :: stem
      integer, intent(in) :: nnode
      type(result_block_t), intent(in) :: blocks(:)
      character(len=*), intent(in) :: fields(:)
      integer, intent(in) :: ncomps(:), nframe
      type(error_t), intent(inout) :: err
    end subroutine results_resume

    !> A path made absolute ('a/b' -> '/a/b'), trailing blanks removed.
    module pure function absolute(path) result(s)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: s
    end function absolute

    !> File part of a path ('out/run' -> 'run').
    module pure function base_name(path) result(s)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: s
    end function base_name

    !> A name becomes one HDF5 link: not empty, no '/'.
    module subroutine check_name(name, what, err)
      character(len=*), intent(in) :: name, what
      type(error_t), intent(inout) :: err
    end subroutine check_name

    !> Flush to disk so that a killed run keeps everything written so far.
    module subroutine flush_file(res, what, err)
      type(results_t), intent(in) :: res
      character(len=*), intent(in) :: what
      type(error_t), intent(inout) :: err
    end subroutine flush_file

    !> How a nodal field of ncomp components is stored in frame `frame`
    !> (0-based): path, XDMF kind, stored components.
    module pure function nodal_field(name, ncomp, frame) result(field)
      character(len=*), intent(in) :: name
      integer, intent(in) :: ncomp, frame
      type(xdmf_field_t) :: field
    end function nodal_field

    !> Record the blocks as the XDMF references them and the node order they
    !> imply (raccord_node_order); sets res%nnode.
    module subroutine set_layout(res, nnode, blocks)
      type(results_t), intent(inout) :: res
      integer, intent(in) :: nnode
      type(result_block_t), intent(in) :: blocks(:)
    end subroutine set_layout

    !> True when the results file is open; otherwise an error naming the caller.
    module logical function usable(res, caller, err)
      type(results_t), intent(in) :: res
      character(len=*), intent(in) :: caller
      type(error_t), intent(inout) :: err
    end function usable

    !> Finish the file (raccord_results_close).
    module subroutine results_close(res, complete, err, reason)
      type(results_t), intent(inout) :: res
      logical, intent(in) :: complete
      type(error_t), intent(inout) :: err
      character(len=*), intent(in), optional :: reason
    end subroutine results_close

    !> Add a contact surface grid (raccord_results_surface).
    module subroutine results_add_surface(res, name, base, prefix, conn, nnode, fields, err)
      type(results_t), intent(inout) :: res
      character(len=*), intent(in) :: name, base, prefix
      integer, intent(in) :: conn(:,:)
      integer, intent(in) :: nnode
      character(len=*), intent(in) :: fields(:)
      type(error_t), intent(inout) :: err
    end subroutine results_add_surface

    !> A surface's coordinates xy(2, n) and values(n, nfield) in the current
    !> frame (raccord_results_surface).
    module subroutine results_write_surface_frame(res, isurf, xy, values, err)
      type(results_t), intent(inout) :: res
      integer, intent(in) :: isurf
      real(wp), intent(in) :: xy(:,:), values(:,:)
      type(error_t), intent(inout) :: err
    end subroutine results_write_surface_frame
  end interface

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
    allocate(res%blocks(0), res%frames(8), res%surfaces(0))
    call delete_file(res%stem // '.h5')
    call delete_file(res%stem // '.xmf')
    call delete_file(res%stem // '.xmf.part')
    call delete_file(res%stem // '.meshio.xmf')
    call delete_file(res%stem // '.meshio.xmf.part')
    call delete_file(res%stem // '.incomplete.h5')
    call delete_file(res%stem // '.incomplete.xmf')
    call delete_file(res%stem // '.incomplete.meshio.xmf')
    root = res%file
    call h5_attr_text(root, 'format', 'raccord results', res%where, err)
    call h5_attr_int(root, 'format_version', RESULTS_FORMAT_VERSION, res%where, err)
    if (err%failed()) return
    call h5_write_text(root, '/status', 'running', res%where, err)
    call h5_create_growing(root, '/frames/times', .true., res%where, err)
    call h5_create_growing(root, '/frames/steps', .false., res%where, err, wide=.true.)
    call flush_file(res, 'the file header', err)
  end subroutine results_open

  !> Write node coordinates x(2, nnode) to /mesh/x in row order, the model
  !> index of each row to /mesh/node_index, and each block's 0-based rows
  !> to /mesh/blocks/<name>/connectivity (and, from the block's first row,
  !> local_connectivity; attributes first_row, row_count). Once per file.
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
    call set_layout(res, nnode, blocks)
    call h5_write_real(res%file, '/mesh/x', x(:, res%order), res%where, err)
    call h5_write_int(res%file, '/mesh/node_index', res%order - 1, res%where, err)
    if (err%failed()) return
    do b = 1, size(blocks)
      path = '/mesh/blocks/' // blocks(b)%name
      ! 0-based so XDMF readers use the datasets as they are.
      call h5_write_int(res%file, path // '/connectivity', rows_of(res%row, blocks(b)%conn) - 1, res%where, err)
      call h5_write_int(res%file, path // '/local_connectivity', rows_of(res%row, blocks(b)%conn) - 1 &
        - res%blocks(b)%first, res%where, err)
      if (err%failed()) return
      call h5gopen_checked(res, path, grp, err)
      if (err%failed()) return
      call h5_attr_int(grp, 'first_row', res%blocks(b)%first, res%where, err)
      call h5_attr_int(grp, 'row_count', res%blocks(b)%count, res%where, err)
      call h5_attr_int(grp, 'nen', blocks(b)%nen, res%where, err)
      call h5_attr_text(grp, 'topology', trim(merge('Quadrilateral_8', 'Quadrilateral  ', blocks(b)%nen == 8)), &
        res%where, err)
      call h5gclose_f(grp, hdferr)
      if (hdferr /= 0) call raise_error(err, EXIT_IO, 'cannot close group "' // path // '" in ' // res%where)
      if (err%failed()) return
    end do
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
    if (res%nnode >= 0) then
      call h5_write_int(res%file, '/mesh/node_sets/' // trim(name), res%row(nodes) - 1, res%where, err)
    else
      call h5_write_int(res%file, '/mesh/node_sets/' // trim(name), nodes - 1, res%where, err)
    end if
  end subroutine results_write_node_set

  !> Start output frame number nframe (group /frames/NNNNNN, six digits from
  !> 000000) with its step and time as attributes.
  subroutine begin_frame_i8(res, step, time, err)
    type(results_t), intent(inout) :: res
    integer(i8), intent(in) :: step
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
    call h5_attr_i8(grp, 'step', step, res%where, err)
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
    res%frames(res%nframe)%nsurf = 0
    allocate(res%frames(res%nframe)%fields(4))
    res%step = step
    res%in_frame = .true.
  end subroutine begin_frame_i8

  subroutine begin_frame_int(res, step, time, err)
    type(results_t), intent(inout) :: res
    integer, intent(in) :: step
    real(wp), intent(in) :: time
    type(error_t), intent(inout) :: err
    call begin_frame_i8(res, int(step, i8), time, err)
  end subroutine begin_frame_int

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
    ! In row order; the buffers are allocated at the first frame only.
    select case (ncomp)
    case (1)
      if (.not. allocated(res%s1)) allocate(res%s1(res%nnode))
      res%s1 = values(1, res%order)
      call h5_write_real(res%file, field%path, res%s1, res%where, err)
    case (2)
      if (.not. allocated(res%s3)) allocate(res%s3(3, res%nnode))
      res%s3(1:2, :) = values(:, res%order)
      res%s3(3, :) = 0.0_wp
      call h5_write_real(res%file, field%path, res%s3, res%where, err)
    case default
      if (allocated(res%sn)) then
        if (size(res%sn, 1) /= ncomp) deallocate(res%sn)
      end if
      if (.not. allocated(res%sn)) allocate(res%sn(ncomp, res%nnode))
      res%sn = values(:, res%order)
      call h5_write_real(res%file, field%path, res%sn, res%where, err)
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
    call h5_append_i8(res%file, '/frames/steps', res%step, res%where, err)
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

  !> Create an empty growing table at `path` (h5dump dims (0, ncol), rows
  !> unlimited, chunk_rows rows per chunk, raccord_h5_table) with the
  !> column names as its string-array attribute `columns`; rows are added
  !> with results_append_table while the run goes on.
  subroutine results_create_table(res, path, names, chunk_rows, err)
    type(results_t), intent(inout) :: res
    character(len=*), intent(in) :: path
    character(len=*), intent(in) :: names(:)
    integer, intent(in) :: chunk_rows
    type(error_t), intent(inout) :: err
    integer(hid_t) :: dset
    integer :: hdferr
    character(len=:), allocatable :: full
    if (.not. usable(res, 'results_create_table', err)) return
    full = absolute(path)
    call h5_create_table(res%file, full, size(names), chunk_rows, res%where, err)
    if (err%failed()) return
    call h5dopen_f(res%file, full, dset, hdferr)
    if (hdferr /= 0) then
      call raise_error(err, EXIT_IO, 'cannot reopen dataset "' // full // '" in ' // res%where)
      return
    end if
    call h5_attr_text_list(dset, 'columns', names, res%where, err)
    call h5dclose_f(dset, hdferr)
    if (hdferr /= 0) call raise_error(err, EXIT_IO, 'cannot close dataset "' // full // '" in ' // res%where)
  end subroutine results_create_table

  !> Append rows(ncol, n) to the growing table at `path`.
  subroutine results_append_table(res, path, rows, err)
    type(results_t), intent(inout) :: res
    character(len=*), intent(in) :: path
    real(wp), intent(in) :: rows(:,:)
    type(error_t), intent(inout) :: err
    if (.not. usable(res, 'results_append_table', err)) return
    call h5_append_rows(res%file, absolute(path), rows, res%where, err)
  end subroutine results_append_table

  !> Cut the growing table at `path` (ncol columns) back to nrow rows, for a
  !> resumed run; a missing table, another column count or fewer rows is
  !> EXIT_INPUT (the file does not belong to the checkpoint).
  subroutine results_truncate_table(res, path, ncol, nrow, err)
    type(results_t), intent(inout) :: res
    character(len=*), intent(in) :: path
    integer, intent(in) :: ncol
    integer(i8), intent(in) :: nrow
    type(error_t), intent(inout) :: err
    if (.not. usable(res, 'results_truncate_table', err)) return
    call h5_truncate_rows(res%file, absolute(path), ncol, nrow, res%where, err)
  end subroutine results_truncate_table

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

  !> row(conn), element by element (a vector subscript must be rank 1).
  pure function rows_of(row, conn) result(c)
    integer, intent(in) :: row(:), conn(:,:)
    integer :: c(size(conn, 1), size(conn, 2))
    integer :: i, j
    do j = 1, size(conn, 2)
      do i = 1, size(conn, 1)
        c(i, j) = row(conn(i, j))
      end do
    end do
  end function rows_of

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

  !> Folder part of a path ('out/run' -> 'out', 'run' -> '').
  pure function folder_of(path) result(s)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: s
    integer :: k
    k = index(path, '/', back=.true.)
    s = path(1:max(k - 1, 0))
  end function folder_of

end module raccord_results
