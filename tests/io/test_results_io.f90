!> Results files: the HDF5 layout read back with the HDF5 API, the XDMF's
!> references, the .part / .incomplete naming, the history file, and the
!> file-system helpers' errors.
!>
!> The complete run is left in out_complete/ for the xdmf_wellformed test.
program test_results_io
  use raccord_check, only: failure_t, new_test, run_tests, check, check_close, fail_now
  implicit none

  call run_tests('results_io', [ &
    new_test('files: mkdir -p, exists, delete', test_files_ok), &
    new_test('files: errors name the path', test_files_errors), &
    new_test('results: .part only while open', test_part_while_open), &
    new_test('results: complete close and layout', test_complete_layout), &
    new_test('results: XDMF references exist', test_xdmf_references), &
    new_test('results: incomplete close', test_incomplete), &
    new_test('results: node order, body grids, surfaces', test_order_surfaces), &
    new_test('results: misuse and bad paths', test_results_errors), &
    new_test('results: growing table in blocks, cut back', test_growing_table), &
    new_test('results: a step past 2**31 is kept', test_long_step), &
    new_test('history: header, rows, names', test_history)])

contains

  ! --- fixtures ------------------------------------------------------------

  !> 14 nodes: a 2-element Q4 block "left" and a 1-element Q8 block "right".
  subroutine small_mesh(x, blocks)
    use raccord_kinds, only: wp
    use raccord_results, only: result_block_t
    real(wp), allocatable, intent(out) :: x(:,:)
    type(result_block_t), allocatable, intent(out) :: blocks(:)
    x = reshape([0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 2.0_wp, 0.0_wp, &
                 0.0_wp, 1.0_wp, 1.0_wp, 1.0_wp, 2.0_wp, 1.0_wp, &
                 3.0_wp, 0.0_wp, 4.0_wp, 0.0_wp, 4.0_wp, 1.0_wp, 3.0_wp, 1.0_wp, &
                 3.5_wp, 0.0_wp, 4.0_wp, 0.5_wp, 3.5_wp, 1.0_wp, 3.0_wp, 0.5_wp], [2, 14])
    allocate(blocks(2))
    blocks(1)%name = 'left'
    blocks(1)%nen = 4
    blocks(1)%conn = reshape([1, 2, 5, 4, 2, 3, 6, 5], [4, 2])
    blocks(2)%name = 'right'
    blocks(2)%nen = 8
    blocks(2)%conn = reshape([7, 8, 9, 10, 11, 12, 13, 14], [8, 1])
  end subroutine small_mesh

  !> Field values of frame f (0-based): displacement, stress, a scalar.
  subroutine frame_fields(f, x, u, s, p)
    use raccord_kinds, only: wp
    integer, intent(in) :: f
    real(wp), intent(in) :: x(:,:)
    real(wp), allocatable, intent(out) :: u(:,:), s(:,:), p(:,:)
    integer :: i, c
    allocate(u(2, size(x, 2)), s(4, size(x, 2)), p(1, size(x, 2)))
    do i = 1, size(x, 2)
      u(1, i) = 0.01_wp*(f + 1)*x(1, i)
      u(2, i) = -0.02_wp*(f + 1)*x(2, i) + 1.0e-17_wp*i
      do c = 1, 4
        s(c, i) = 100.0_wp*c + i + 1000.0_wp*f
      end do
      p(1, i) = f + 0.1_wp*i
    end do
  end subroutine frame_fields

  !> Write out_complete/run with 3 frames; close if `close_it`.
  subroutine write_complete_run(res, close_it, err)
    use raccord_kinds, only: wp
    use raccord_error, only: error_t
    use raccord_results, only: results_t, result_block_t, results_open, results_write_mesh, &
      results_write_node_set, results_begin_frame, results_write_nodal, results_end_frame, &
      results_write_array, results_write_table, results_set_text, results_close
    type(results_t), intent(inout) :: res
    logical, intent(in) :: close_it
    type(error_t), intent(inout) :: err
    real(wp), allocatable :: x(:,:), u(:,:), s(:,:), p(:,:), table(:,:)
    type(result_block_t), allocatable :: blocks(:)
    integer :: f, r
    call small_mesh(x, blocks)
    call results_open(res, 'out_complete/run', err)
    call results_set_text(res, 'version', 'raccord test 0.0', err)
    call results_write_mesh(res, x, blocks, err)
    call results_write_node_set(res, 'bottom', [1, 2, 3, 7, 8, 11], err)
    do f = 0, 2
      call frame_fields(f, x, u, s, p)
      call results_begin_frame(res, 10*f, 0.5_wp*f, err)
      call results_write_nodal(res, 'displacement', u, err)
      call results_write_nodal(res, 'stress', s, err)
      call results_write_nodal(res, 'pressure', p, err)
      call results_end_frame(res, err)
    end do
    call results_write_array(res, '/contact/pair_1/frame_000012/gap', [1.0_wp, -2.0_wp, 3.5_wp], err)
    call results_write_array(res, 'contact/pair_1/normals', reshape([1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], [2, 2]), err)
    allocate(table(3, 4))
    do r = 1, 4
      table(:, r) = [0.25_wp*r, 1.0_wp*r*r, -1.0_wp*r]
    end do
    call results_write_table(res, '/history', [character(len=16) :: 'time', 'kinetic_energy', 'work'], table, err)
    if (close_it) call results_close(res, .true., err)
  end subroutine write_complete_run

  ! --- tests -------------------------------------------------------------

  subroutine test_files_ok(failure)
    use raccord_error, only: error_t
    use raccord_files, only: make_directory, file_exists, delete_file, rename_file
    type(failure_t), allocatable, intent(out) :: failure
    type(error_t) :: err
    integer :: u
    call make_directory('tmp_files/a/b//c', err)
    call check(failure, .not. err%failed(), 'make_directory nested: ' // message(err))
    call check(failure, file_exists('tmp_files/a/b/c'), 'nested folder exists')
    call make_directory('tmp_files/a/b/c', err)
    call check(failure, .not. err%failed(), 'make_directory on an existing folder is fine: ' // message(err))
    open(newunit=u, file='tmp_files/a/f.txt', status='replace', action='write')
    write(u, '(a)') 'x'
    close(u)
    call rename_file('tmp_files/a/f.txt', 'tmp_files/a/g.txt', err)
    call check(failure, .not. err%failed(), 'rename_file: ' // message(err))
    call check(failure, file_exists('tmp_files/a/g.txt') .and. .not. file_exists('tmp_files/a/f.txt'), &
      'rename moved the file')
    call delete_file('tmp_files/a/g.txt')
    call check(failure, .not. file_exists('tmp_files/a/g.txt'), 'delete_file removed the file')
    call delete_file('tmp_files/a/g.txt')   ! absent: must be silent
    call check(failure, .not. file_exists('tmp_files/nothing/here'), 'file_exists on a missing path')
  end subroutine test_files_ok

  subroutine test_files_errors(failure)
    use raccord_error, only: error_t, EXIT_IO
    use raccord_files, only: make_directory, rename_file
    type(failure_t), allocatable, intent(out) :: failure
    type(error_t) :: err
    integer :: u
    ! A regular file where a folder should be: fails even for root.
    call make_directory('tmp_errors', err)
    open(newunit=u, file='tmp_errors/plain', status='replace', action='write')
    close(u)
    call make_directory('tmp_errors/plain/sub/dir', err)
    call check(failure, err%code == EXIT_IO, 'make_directory under a file gives EXIT_IO')
    call check(failure, index(message(err), 'tmp_errors/plain/sub/dir') > 0, &
      'mkdir message names the path: ' // message(err))
    call check(failure, index(message(err), 'not a directory') > 0, &
      'mkdir message gives the reason: ' // message(err))
    call err%clear()
    call make_directory('tmp_errors/plain', err)
    call check(failure, err%code == EXIT_IO, 'make_directory on an existing regular file gives EXIT_IO')
    call err%clear()
    call rename_file('tmp_errors/missing', 'tmp_errors/other', err)
    call check(failure, err%code == EXIT_IO, 'rename of a missing file gives EXIT_IO')
    call check(failure, index(message(err), 'tmp_errors/missing') > 0 .and. &
      index(message(err), 'tmp_errors/other') > 0, 'rename message names both paths: ' // message(err))
    call check(failure, index(message(err), 'No such file') > 0, 'rename message gives the reason: ' // message(err))
    call err%clear()
    call rename_file('tmp_errors/plain', 'tmp_errors/plain/below', err)
    call check(failure, err%code == EXIT_IO, 'rename to a path under a file gives EXIT_IO')
  end subroutine test_files_errors

  subroutine test_part_while_open(failure)
    use raccord_error, only: error_t
    use raccord_files, only: file_exists
    use raccord_results, only: results_t, results_close
    type(failure_t), allocatable, intent(out) :: failure
    type(results_t) :: res
    type(error_t) :: err
    call write_complete_run(res, .false., err)
    call check(failure, .not. err%failed(), 'writing the run: ' // message(err))
    call check(failure, file_exists('out_complete/run.h5.part'), 'run.h5.part exists while open')
    call check(failure, .not. file_exists('out_complete/run.h5'), 'no run.h5 while open')
    call check(failure, .not. file_exists('out_complete/run.xmf'), 'no run.xmf while open')
    call check(failure, .not. file_exists('out_complete/run.incomplete.h5'), 'no incomplete file while open')
    call results_close(res, .true., err)
    call check(failure, .not. err%failed(), 'close: ' // message(err))
    call check(failure, file_exists('out_complete/run.h5'), 'run.h5 after a complete close')
    call check(failure, file_exists('out_complete/run.xmf'), 'run.xmf after a complete close')
    call check(failure, .not. file_exists('out_complete/run.h5.part'), 'run.h5.part gone after close')
    call check(failure, .not. file_exists('out_complete/run.xmf.part'), 'run.xmf.part gone after close')
  end subroutine test_part_while_open

  subroutine test_complete_layout(failure)
    use raccord_kinds, only: wp
    use raccord_error, only: error_t
    use raccord_results, only: results_t, result_block_t
    use raccord_h5, only: h5_acquire, h5_release
    use hdf5, only: hid_t, h5fopen_f, h5fclose_f, H5F_ACC_RDONLY_F
    type(failure_t), allocatable, intent(out) :: failure
    type(results_t) :: res
    type(error_t) :: err
    integer(hid_t) :: file
    integer :: hdferr, f, i
    real(wp), allocatable :: x(:,:), u(:,:), s(:,:), p(:,:), got2(:,:), got1(:)
    integer, allocatable :: igot2(:,:), igot1(:)
    type(result_block_t), allocatable :: blocks(:)
    character(len=:), allocatable :: text
    character(len=16) :: label
    call write_complete_run(res, .true., err)
    call check(failure, .not. err%failed(), 'writing the run: ' // message(err))
    if (allocated(failure)) return
    call small_mesh(x, blocks)
    call h5_acquire(err)
    call h5fopen_f('out_complete/run.h5', H5F_ACC_RDONLY_F, file, hdferr)
    if (hdferr /= 0) then
      call fail_now(failure, 'cannot open out_complete/run.h5')
      return
    end if
    ! Shapes as the Fortran API reports them (h5dump shows them reversed).
    call read_real_2d(file, '/mesh/x', got2, failure)
    if (allocated(failure)) goto 99
    call check(failure, all(shape(got2) == [2, 14]), '/mesh/x shape (2, 14) in Fortran order')
    if (allocated(failure)) goto 99
    call check(failure, all(got2 == x), '/mesh/x values')
    call read_int_2d(file, '/mesh/blocks/left/connectivity', igot2, failure)
    if (allocated(failure)) goto 99
    call check(failure, all(shape(igot2) == [4, 2]), 'left connectivity shape (4, 2)')
    if (allocated(failure)) goto 99
    call check(failure, all(igot2 == blocks(1)%conn - 1), 'left connectivity is 0-based')
    call read_int_2d(file, '/mesh/blocks/right/connectivity', igot2, failure)
    if (allocated(failure)) goto 99
    call check(failure, all(shape(igot2) == [8, 1]), 'right connectivity shape (8, 1)')
    if (allocated(failure)) goto 99
    call check(failure, all(igot2(:, 1) == [6, 7, 8, 9, 10, 11, 12, 13]), 'right connectivity values')
    call check(failure, read_int_attr(file, '/mesh/blocks/right', 'nen') == 8, 'right nen attribute')
    call read_int_1d(file, '/mesh/node_sets/bottom', igot1, failure)
    if (allocated(failure)) goto 99
    call check(failure, size(igot1) == 6, 'node set size')
    if (allocated(failure)) goto 99
    call check(failure, all(igot1 == [0, 1, 2, 6, 7, 10]), 'node set is 0-based')
    call read_real_1d(file, '/frames/times', got1, failure)
    if (allocated(failure)) goto 99
    call check(failure, size(got1) == 3, '/frames/times has 3 entries, got ' // itoa(size(got1)))
    if (allocated(failure)) goto 99
    call check(failure, all(got1 == [0.0_wp, 0.5_wp, 1.0_wp]), '/frames/times values')
    call read_int_1d(file, '/frames/steps', igot1, failure)
    if (allocated(failure)) goto 99
    call check(failure, size(igot1) == 3, '/frames/steps size')
    if (allocated(failure)) goto 99
    call check(failure, all(igot1 == [0, 10, 20]), '/frames/steps values')
    do f = 0, 2
      write(label, '(a,i6.6)') '/frames/', f
      call frame_fields(f, x, u, s, p)
      call check_close(failure, read_real_attr(file, trim(label), 'time'), 0.5_wp*f, 'frame time attribute')
      call check(failure, read_int_attr(file, trim(label), 'step') == 10*f, 'frame step attribute')
      call read_real_2d(file, trim(label) // '/displacement', got2, failure)
      if (allocated(failure)) goto 99
      call check(failure, all(shape(got2) == [3, 14]), 'displacement padded to 3 components')
      if (allocated(failure)) goto 99
      call check(failure, all(got2(1:2, :) == u) .and. all(got2(3, :) == 0.0_wp), &
        'displacement values (bit-exact) and zero z in ' // trim(label))
      call check(failure, read_int_attr(file, trim(label) // '/displacement', 'ncomp') == 2, &
        'displacement ncomp attribute')
      call read_real_2d(file, trim(label) // '/stress', got2, failure)
      if (allocated(failure)) goto 99
      call check(failure, all(shape(got2) == [4, 14]), 'stress shape (4, 14)')
      if (allocated(failure)) goto 99
      call check(failure, all(got2 == s), 'stress values')
      call read_real_1d(file, trim(label) // '/pressure', got1, failure)
      if (allocated(failure)) goto 99
      call check(failure, size(got1) == 14, 'scalar field is 1D of nnode')
      if (allocated(failure)) goto 99
      call check(failure, all(got1 == p(1, :)), 'scalar field values')
    end do
    call read_real_1d(file, '/contact/pair_1/frame_000012/gap', got1, failure)
    if (allocated(failure)) goto 99
    call check(failure, size(got1) == 3, 'gap array size')
    if (allocated(failure)) goto 99
    call check(failure, all(got1 == [1.0_wp, -2.0_wp, 3.5_wp]), 'gap array values (intermediate groups created)')
    call read_real_2d(file, '/contact/pair_1/normals', got2, failure)
    if (allocated(failure)) goto 99
    call check(failure, all(shape(got2) == [2, 2]), 'relative path written under the root')
    call read_real_2d(file, '/history', got2, failure)
    if (allocated(failure)) goto 99
    call check(failure, all(shape(got2) == [3, 4]), 'table shape (ncol 3, nrow 4) in Fortran order')
    if (allocated(failure)) goto 99
    do i = 1, 4
      call check(failure, all(got2(:, i) == [0.25_wp*i, 1.0_wp*i*i, -1.0_wp*i]), 'table row ' // itoa(i))
    end do
    call check(failure, read_attr_text_item(file, '/history', 'columns', 2) == 'kinetic_energy', &
      'table column names: got "' // read_attr_text_item(file, '/history', 'columns', 2) // '"')
    call check(failure, read_attr_text_item(file, '/history', 'columns', 3) == 'work', 'third column name')
    text = read_text(file, '/status')
    call check(failure, text == 'complete', '/status is "complete", got "' // text // '"')
    text = read_text(file, '/version')
    call check(failure, text == 'raccord test 0.0', '/version text, got "' // text // '"')
    call check(failure, read_int_attr(file, '/', 'format_version') == 2, 'format_version attribute')
    ! The blocks' nodes are contiguous already: identity order, one range each.
    call read_int_2d(file, '/mesh/blocks/right/local_connectivity', igot2, failure)
    if (allocated(failure)) goto 99
    call check(failure, all(igot2(:, 1) == [0, 1, 2, 3, 4, 5, 6, 7]), 'right local connectivity from its first row')
    call check(failure, read_int_attr(file, '/mesh/blocks/right', 'first_row') == 6, 'right first_row')
    call check(failure, read_int_attr(file, '/mesh/blocks/right', 'row_count') == 8, 'right row_count')
99  call h5fclose_f(file, hdferr)
    call h5_release(err)
  end subroutine test_complete_layout

  !> Every DataItem of run.xmf points at run.h5 and an object that exists;
  !> every frame and field is referenced.
  subroutine test_xdmf_references(failure)
    use raccord_error, only: error_t
    use raccord_results, only: results_t
    use raccord_h5, only: h5_acquire, h5_release
    use hdf5, only: hid_t, h5fopen_f, h5fclose_f, H5F_ACC_RDONLY_F
    type(failure_t), allocatable, intent(out) :: failure
    type(results_t) :: res
    type(error_t) :: err
    character(len=:), allocatable :: xml
    integer(hid_t) :: file
    integer :: hdferr, f
    character(len=64) :: path
    call write_complete_run(res, .true., err)
    call check(failure, .not. err%failed(), 'writing the run: ' // message(err))
    if (allocated(failure)) return
    xml = read_whole('out_complete/run.xmf')
    call check(failure, count_of(xml, '<Time ') == 3, 'three time steps in the XDMF, got ' &
      // itoa(count_of(xml, '<Time ')))
    call check(failure, count_of(xml, 'CollectionType="Temporal"') == 1, 'one temporal collection')
    call check(failure, count_of(xml, 'TopologyType="Quadrilateral_8"') == 3, 'Q8 grid in each frame')
    call check(failure, count_of(xml, 'TopologyType="Quadrilateral"') == 3, 'Q4 grid in each frame')
    call check(failure, count_of(xml, 'GeometryType="XY"') == 6, 'XY geometry for each grid')
    call check(failure, count_of(xml, 'AttributeType="Vector"') == 6, 'displacement as a vector')
    call check(failure, count_of(xml, '<Xdmf') == 1 .and. count_of(xml, '</Xdmf>') == 1, 'one Xdmf element')
    do f = 0, 2
      ! Each block grid takes its own rows: left 0..5, right 6..13 of 14.
      write(path, '(a,i6.6,a)') 'run.h5:/frames/', f, '/displacement|0 0:1 1:6 3:14 3<'
      call check(failure, count_of(xml, trim(path)) == 1, 'XDMF references ' // trim(path))
      write(path, '(a,i6.6,a)') 'run.h5:/frames/', f, '/stress|6 0:1 1:8 4:14 4<'
      call check(failure, count_of(xml, trim(path)) == 1, 'XDMF references ' // trim(path))
      write(path, '(a,i6.6,a)') 'run.h5:/frames/', f, '/pressure|6:1:8:14<'
      call check(failure, count_of(xml, trim(path)) == 1, 'XDMF references ' // trim(path))
    end do
    call check(failure, count_of(xml, 'run.h5:/mesh/x|6 0:1 1:8 2:14 2<') == 3, 'right block geometry: its 8 rows')
    call check(failure, count_of(xml, 'run.h5:/mesh/blocks/right/local_connectivity<') == 3, 'right block referenced')
    call h5_acquire(err)
    call h5fopen_f('out_complete/run.h5', H5F_ACC_RDONLY_F, file, hdferr)
    if (hdferr /= 0) then
      call fail_now(failure, 'cannot open out_complete/run.h5')
    else
      call check_data_items(failure, xml, 'run.h5', file)
      call h5fclose_f(file, hdferr)
    end if
    call h5_release(err)
  end subroutine test_xdmf_references

  subroutine test_incomplete(failure)
    use raccord_kinds, only: wp
    use raccord_error, only: error_t
    use raccord_files, only: file_exists
    use raccord_results, only: results_t, result_block_t, results_open, results_write_mesh, &
      results_begin_frame, results_write_nodal, results_end_frame, results_close
    use raccord_h5, only: h5_acquire, h5_release
    use hdf5, only: hid_t, h5fopen_f, h5fclose_f, H5F_ACC_RDONLY_F
    type(failure_t), allocatable, intent(out) :: failure
    type(results_t) :: res
    type(error_t) :: err
    real(wp), allocatable :: x(:,:), u(:,:), s(:,:), p(:,:), got1(:)
    type(result_block_t), allocatable :: blocks(:)
    character(len=:), allocatable :: text, xml
    integer(hid_t) :: file
    integer :: hdferr
    ! A complete run first: an incomplete rerun must remove its results.
    call write_complete_run(res, .false., err)
    call results_close(res, .true., err)
    call check(failure, .not. err%failed() .and. file_exists('out_complete/run.h5'), 'setup run')
    if (allocated(failure)) return
    call small_mesh(x, blocks)
    call results_open(res, 'out_complete/run', err)
    call check(failure, .not. file_exists('out_complete/run.h5'), 'opening removed the stale run.h5')
    call check(failure, .not. file_exists('out_complete/run.xmf'), 'opening removed the stale run.xmf')
    call results_write_mesh(res, x, blocks, err)
    call frame_fields(0, x, u, s, p)
    call results_begin_frame(res, 1, 0.125_wp, err)
    call results_write_nodal(res, 'displacement', u, err)
    call results_end_frame(res, err)
    call results_begin_frame(res, 2, 0.25_wp, err)     ! left open: the run "fails" here
    call results_write_nodal(res, 'displacement', u, err)
    call check(failure, .not. err%failed(), 'writing: ' // message(err))
    call results_close(res, .false., err, reason='NaN in the velocity at step 2')
    call check(failure, .not. err%failed(), 'incomplete close: ' // message(err))
    call check(failure, file_exists('out_complete/run.incomplete.h5'), 'run.incomplete.h5 exists')
    call check(failure, file_exists('out_complete/run.incomplete.xmf'), 'run.incomplete.xmf exists')
    call check(failure, .not. file_exists('out_complete/run.h5'), 'no run.h5 after an incomplete close')
    call check(failure, .not. file_exists('out_complete/run.xmf'), 'no run.xmf after an incomplete close')
    call check(failure, .not. file_exists('out_complete/run.h5.part'), 'no .part after close')
    if (allocated(failure)) return
    xml = read_whole('out_complete/run.incomplete.xmf')
    call check(failure, count_of(xml, 'run.incomplete.h5:/frames/000001/displacement|') == 2, &
      'the incomplete XDMF names run.incomplete.h5 and keeps the last frame')
    call check(failure, count_of(xml, 'run.h5:') == 0, 'the incomplete XDMF never names run.h5')
    call h5_acquire(err)
    call h5fopen_f('out_complete/run.incomplete.h5', H5F_ACC_RDONLY_F, file, hdferr)
    if (hdferr /= 0) then
      call fail_now(failure, 'cannot open run.incomplete.h5')
    else
      text = read_text(file, '/status')
      call check(failure, text == 'incomplete: NaN in the velocity at step 2', 'status text, got "' // text // '"')
      call read_real_1d(file, '/frames/times', got1, failure)
      if (.not. allocated(failure)) call check(failure, size(got1) == 2, &
        'the frame left open was ended on close')
      call check_data_items(failure, xml, 'run.incomplete.h5', file)
      call h5fclose_f(file, hdferr)
    end if
    call h5_release(err)
    ! Restore the complete run for the xdmf_wellformed test.
    call write_complete_run(res, .true., err)
  end subroutine test_incomplete

  !> Blocks whose nodes interleave in the model, a node in no block, and a
  !> contact surface: rows grouped by block, every dataset mapped back,
  !> the XDMF's hyperslabs and surface grid, the meshio index.
  subroutine test_order_surfaces(failure)
    use raccord_kinds, only: wp
    use raccord_error, only: error_t, EXIT_INTERNAL
    use raccord_files, only: file_exists
    use raccord_results, only: results_t, result_block_t, results_open, results_write_mesh, &
      results_write_node_set, results_begin_frame, results_write_nodal, results_end_frame, results_close, &
      results_add_surface, results_write_surface_frame
    use raccord_h5, only: h5_acquire, h5_release
    use hdf5, only: hid_t, h5fopen_f, h5fclose_f, H5F_ACC_RDONLY_F
    type(failure_t), allocatable, intent(out) :: failure
    type(results_t) :: res
    type(error_t) :: err
    real(wp) :: x(2, 9), u(2, 9), xy(2, 3), vals(3, 2)
    real(wp), allocatable :: got2(:,:), got1(:)
    integer, allocatable :: igot2(:,:), igot1(:)
    type(result_block_t) :: blocks(2)
    integer, parameter :: order(9) = [2, 4, 6, 8, 1, 3, 5, 7, 9]
    character(len=:), allocatable :: xml
    integer(hid_t) :: file
    integer :: i, hdferr
    do i = 1, 9
      x(:, i) = [real(i, wp), -0.5_wp*i]
      u(:, i) = [1.0e-3_wp*i, 2.0e-3_wp*i*i]
    end do
    blocks(1)%name = 'A'
    blocks(1)%nen = 4
    blocks(1)%conn = reshape([2, 4, 6, 8], [4, 1])
    blocks(2)%name = 'B'
    blocks(2)%nen = 4
    blocks(2)%conn = reshape([1, 3, 5, 7], [4, 1])
    xy = reshape([0.0_wp, 1.0_wp, 0.5_wp, 1.1_wp, 1.0_wp, 1.2_wp], [2, 3])
    vals = reshape([10.0_wp, 20.0_wp, 30.0_wp, -1.0_wp, -2.0_wp, -3.0_wp], [3, 2])
    call results_open(res, 'out_order/run2', err)
    call results_write_mesh(res, x, blocks, err)
    call results_write_node_set(res, 'pair', [1, 2], err)
    call results_add_surface(res, 'contact1_top', '/contact/pair_1', '', reshape([1, 2, 2, 3], [2, 2]), 3, &
      [character(len=8) :: 'pressure', 'gap'], err)
    call results_begin_frame(res, 0, 0.25_wp, err)
    call results_write_nodal(res, 'u', u, err)
    call check(failure, .not. err%failed(), 'writing: ' // message(err))
    call results_write_surface_frame(res, 2, xy, vals, err)
    call check(failure, err%code == EXIT_INTERNAL, 'a surface written out of order is refused')
    call err%clear()
    call results_write_surface_frame(res, 1, xy, vals, err)
    call results_end_frame(res, err)
    call results_close(res, .true., err)
    call check(failure, .not. err%failed(), 'writing and closing: ' // message(err))
    call check(failure, file_exists('out_order/run2.meshio.xmf'), 'the meshio index is written')
    if (allocated(failure)) return
    call h5_acquire(err)
    call h5fopen_f('out_order/run2.h5', H5F_ACC_RDONLY_F, file, hdferr)
    if (hdferr /= 0) then
      call fail_now(failure, 'cannot open out_order/run2.h5')
      return
    end if
    call read_real_2d(file, '/mesh/x', got2, failure)
    if (allocated(failure)) goto 99
    call check(failure, all(got2 == x(:, order)), '/mesh/x rows: block A, block B, then the free node')
    call read_int_1d(file, '/mesh/node_index', igot1, failure)
    if (allocated(failure)) goto 99
    call check(failure, all(igot1 == order - 1), '/mesh/node_index maps rows to model nodes')
    call read_int_2d(file, '/mesh/blocks/B/connectivity', igot2, failure)
    if (allocated(failure)) goto 99
    call check(failure, all(igot2(:, 1) == [4, 5, 6, 7]), 'B connectivity in rows')
    call read_int_2d(file, '/mesh/blocks/B/local_connectivity', igot2, failure)
    if (allocated(failure)) goto 99
    call check(failure, all(igot2(:, 1) == [0, 1, 2, 3]), 'B local connectivity')
    call check(failure, read_int_attr(file, '/mesh/blocks/B', 'first_row') == 4, 'B first_row')
    call read_int_1d(file, '/mesh/node_sets/pair', igot1, failure)
    if (allocated(failure)) goto 99
    call check(failure, all(igot1 == [4, 0]), 'node set in rows')
    call read_real_2d(file, '/frames/000000/u', got2, failure)
    if (allocated(failure)) goto 99
    call check(failure, all(got2(1:2, :) == u(:, order)), 'nodal field in rows')
    call read_int_2d(file, '/contact/pair_1/connectivity', igot2, failure)
    if (allocated(failure)) goto 99
    call check(failure, all(igot2 == reshape([0, 1, 1, 2], [2, 2])), 'surface connectivity 0-based')
    call read_real_2d(file, '/contact/pair_1/frame_000000/xy', got2, failure)
    if (allocated(failure)) goto 99
    call check(failure, all(got2 == xy), 'surface coordinates')
    call read_real_1d(file, '/contact/pair_1/frame_000000/gap', got1, failure)
    if (allocated(failure)) goto 99
    call check(failure, all(got1 == vals(:, 2)), 'surface field gap')
    xml = read_whole('out_order/run2.xmf')
    call check(failure, count_of(xml, 'run2.h5:/mesh/x|4 0:1 1:4 2:9 2<') == 1, 'B geometry: rows 4..7 of 9')
    call check(failure, count_of(xml, 'TopologyType="Polyline"') == 1, 'the surface grid has line elements')
    call check(failure, count_of(xml, 'run2.h5:/contact/pair_1/frame_000000/pressure<') == 1, &
      'the surface grid has the pressure')
    call check_data_items(failure, xml, 'run2.h5', file)
    xml = read_whole('out_order/run2.meshio.xmf')
    call check(failure, count_of(xml, '<Topology') == 2 .and. count_of(xml, 'run2.h5:/mesh/x<') == 1 .and. &
      count_of(xml, 'run2.h5:/frames/000000/u<') == 1, 'meshio index: whole mesh, one topology per block, the field')
    call check_data_items(failure, xml, 'run2.h5', file)
99  call h5fclose_f(file, hdferr)
    call h5_release(err)
  end subroutine test_order_surfaces

  subroutine test_results_errors(failure)
    use raccord_kinds, only: wp
    use raccord_error, only: error_t, EXIT_IO, EXIT_INTERNAL, EXIT_INPUT
    use raccord_files, only: make_directory
    use raccord_results, only: results_t, result_block_t, results_open, results_write_mesh, &
      results_begin_frame, results_write_nodal, results_write_array, results_close
    type(failure_t), allocatable, intent(out) :: failure
    type(results_t) :: res
    type(error_t) :: err
    real(wp), allocatable :: x(:,:)
    type(result_block_t), allocatable :: blocks(:)
    integer :: u
    call make_directory('tmp_results_err', err)
    open(newunit=u, file='tmp_results_err/plain', status='replace', action='write')
    close(u)
    call results_open(res, 'tmp_results_err/plain/run', err)
    call check(failure, err%code == EXIT_IO, 'results_open under a regular file gives EXIT_IO')
    call check(failure, index(message(err), 'tmp_results_err/plain') > 0, 'message names the path: ' // message(err))
    call results_close(res, .false., err)     ! not open: must do nothing
    call err%clear()
    call results_write_array(res, '/a', [1.0_wp], err)
    call check(failure, err%code == EXIT_INTERNAL, 'writing to a closed results file is an internal error')
    call err%clear()

    call small_mesh(x, blocks)
    call results_open(res, 'tmp_results_err/run', err)
    call results_begin_frame(res, 0, 0.0_wp, err)
    call check(failure, err%code == EXIT_INTERNAL, 'a frame before the mesh is refused')
    call err%clear()
    blocks(2)%name = 'left'
    call results_write_mesh(res, x, blocks, err)
    call check(failure, err%code == EXIT_INPUT, 'duplicate block names are refused')
    call err%clear()
    blocks(2)%name = 'right'
    blocks(2)%conn(3, 1) = 15
    call results_write_mesh(res, x, blocks, err)
    call check(failure, err%code == EXIT_INTERNAL, 'connectivity beyond nnode is refused')
    call err%clear()
    blocks(2)%conn(3, 1) = 9
    call results_write_mesh(res, x, blocks, err)
    call check(failure, .not. err%failed(), 'mesh: ' // message(err))
    call results_begin_frame(res, 0, 0.0_wp, err)
    call results_write_nodal(res, 'u', x(:, 1:13), err)
    call check(failure, err%code == EXIT_INTERNAL, 'nodal field with the wrong node count is refused')
    call err%clear()
    call results_write_nodal(res, 'u', x, err)
    call results_write_nodal(res, 'u', x, err)
    call check(failure, err%code == EXIT_IO, 'writing a dataset twice gives EXIT_IO')
    call check(failure, index(message(err), '/frames/000000/u') > 0 .and. &
      index(message(err), 'tmp_results_err/run.h5.part') > 0, 'message names dataset and file: ' // message(err))
    call err%clear()
    call results_close(res, .false., err, reason='test')
    call check(failure, .not. err%failed(), 'close after errors: ' // message(err))
  end subroutine test_results_errors

  !> A growing table (the history of a run, issue #18): rows appended in
  !> blocks across chunk boundaries read back in order; cut back to a row
  !> count and continued as a resumed run does; a longer cut, a table of
  !> another width or a missing one is refused with EXIT_INPUT.
  subroutine test_growing_table(failure)
    use raccord_kinds, only: wp, i8
    use raccord_error, only: error_t, EXIT_INPUT
    use raccord_results, only: results_t, results_open, results_close, results_create_table, &
      results_append_table, results_truncate_table
    use raccord_h5, only: h5_acquire, h5_release
    use raccord_h5_verify, only: h5_verify_tree
    use hdf5, only: hid_t, h5fopen_f, h5fclose_f, H5F_ACC_RDONLY_F
    type(failure_t), allocatable, intent(out) :: failure
    type(results_t) :: res
    type(error_t) :: err, e2
    real(wp) :: rows(3, 20)
    real(wp), allocatable :: got(:,:)
    integer(hid_t) :: file
    integer :: r, hdferr, ndata
    do r = 1, 20
      rows(:, r) = [0.5_wp*r, real(r, wp), -1.0e-3_wp*r*r]
    end do
    call results_open(res, 'out_table/run', err)
    call results_create_table(res, '/history', [character(len=8) :: 'time', 'step', 'energy'], 4, err)
    call results_append_table(res, '/history', rows(:, 1:3), err)     ! inside the first chunk
    call results_append_table(res, '/history', rows(:, 4:12), err)    ! across two chunk boundaries
    call results_append_table(res, '/history', rows(:, 13:12), err)   ! nothing
    call check(failure, .not. err%failed(), 'appending: ' // message(err))
    ! a resumed run: cut back to 7 rows, then go on with rows 8..10
    call results_truncate_table(res, '/history', 3, 7_i8, err)
    call results_append_table(res, '/history', rows(:, 8:10), err)
    call check(failure, .not. err%failed(), 'cut back and continued: ' // message(err))
    call results_truncate_table(res, '/history', 3, 11_i8, e2)
    call check(failure, e2%code == EXIT_INPUT .and. index(e2%message, '10 rows, fewer than the 11') > 0, &
      'a cut to more rows than there are is refused: ' // message(e2))
    call e2%clear()
    call results_truncate_table(res, '/history', 4, 5_i8, e2)
    call check(failure, e2%code == EXIT_INPUT .and. index(e2%message, 'not a table of 4 columns') > 0, &
      'a table of another width is refused: ' // message(e2))
    call e2%clear()
    call results_truncate_table(res, '/nothing', 3, 0_i8, e2)
    call check(failure, e2%code == EXIT_INPUT .and. index(e2%message, 'has no table "/nothing"') > 0, &
      'a missing table is refused: ' // message(e2))
    call results_close(res, .true., err)
    call check(failure, .not. err%failed(), 'close: ' // message(err))
    if (allocated(failure)) return
    call h5_acquire(err)
    call h5fopen_f('out_table/run.h5', H5F_ACC_RDONLY_F, file, hdferr)
    if (hdferr /= 0) then
      call fail_now(failure, 'cannot open out_table/run.h5')
      return
    end if
    call read_real_2d(file, '/history', got, failure)
    if (.not. allocated(failure)) then
      call check(failure, size(got, 1) == 3 .and. size(got, 2) == 10, '/history is 10 rows of 3: (' // &
        itoa(size(got, 1)) // ', ' // itoa(size(got, 2)) // ')')
      if (.not. allocated(failure)) call check(failure, all(got == rows(:, 1:10)), '/history holds rows 1..10 in order')
    end if
    ndata = 0
    call h5_verify_tree(file, '/', 'out_table/run.h5', ndata, err)
    call check(failure, .not. err%failed(), 'the file verifies: ' // message(err))
    call h5fclose_f(file, hdferr)
    call h5_release(err)
  end subroutine test_growing_table

  !> A run may take more than 2**31 steps (up to 2**53): a frame's step is
  !> stored as a 64-bit integer, in /frames/steps and in its attribute (it
  !> was converted to a default integer and wrapped, issue #18).
  subroutine test_long_step(failure)
    use, intrinsic :: iso_c_binding, only: c_ptr, c_loc
    use, intrinsic :: iso_fortran_env, only: int64
    use raccord_kinds, only: wp, i8
    use raccord_error, only: error_t
    use raccord_results, only: results_t, result_block_t, results_open, results_write_mesh, &
      results_begin_frame, results_write_nodal, results_end_frame, results_close
    use raccord_h5, only: h5_acquire, h5_release
    use hdf5, only: hid_t, hsize_t, h5fopen_f, h5fclose_f, h5dopen_f, h5dread_f, h5dclose_f, h5aopen_by_name_f, &
      h5aread_f, h5aclose_f, h5kind_to_type, H5F_ACC_RDONLY_F, H5_INTEGER_KIND
    type(failure_t), allocatable, intent(out) :: failure
    type(results_t) :: res
    type(error_t) :: err
    real(wp), allocatable :: x(:,:)
    type(result_block_t), allocatable :: blocks(:)
    integer(i8), parameter :: big = 3000000000_i8
    integer(i8), target :: steps(2), attr_step(1)
    integer(hid_t) :: file, dset, attr
    type(c_ptr) :: ptr
    integer :: hdferr
    call small_mesh(x, blocks)
    call results_open(res, 'out_long/run', err)
    call results_write_mesh(res, x, blocks, err)
    call results_begin_frame(res, 0, 0.0_wp, err)
    call results_write_nodal(res, 'displacement', 0.0_wp*x, err)
    call results_end_frame(res, err)
    call results_begin_frame(res, big, 1.0_wp, err)
    call results_write_nodal(res, 'displacement', 0.0_wp*x, err)
    call results_end_frame(res, err)
    call results_close(res, .true., err)
    call check(failure, .not. err%failed(), 'writing: ' // message(err))
    if (allocated(failure)) return
    call h5_acquire(err)
    call h5fopen_f('out_long/run.h5', H5F_ACC_RDONLY_F, file, hdferr)
    steps = -1
    attr_step = -1
    call h5dopen_f(file, '/frames/steps', dset, hdferr)
    ptr = c_loc(steps)
    if (hdferr == 0) call h5dread_f(dset, h5kind_to_type(int64, H5_INTEGER_KIND), ptr, hdferr)
    call h5dclose_f(dset, hdferr)
    call h5aopen_by_name_f(file, '/frames/000001', 'step', attr, hdferr)
    ptr = c_loc(attr_step)
    if (hdferr == 0) call h5aread_f(attr, h5kind_to_type(int64, H5_INTEGER_KIND), ptr, hdferr)
    call h5aclose_f(attr, hdferr)
    call h5fclose_f(file, hdferr)
    call h5_release(err)
    call check(failure, steps(1) == 0 .and. steps(2) == big, '/frames/steps = [0, 3000000000]')
    call check(failure, attr_step(1) == big, 'the step attribute of frame 000001 is 3000000000')
  end subroutine test_long_step

  subroutine test_history(failure)
    use raccord_kinds, only: wp
    use raccord_error, only: error_t, EXIT_INTERNAL
    use raccord_files, only: file_exists
    use raccord_history_file, only: history_file_t, history_open, history_write, history_close, &
      incomplete_name
    type(failure_t), allocatable, intent(out) :: failure
    type(history_file_t) :: h
    type(error_t) :: err
    real(wp) :: rows(3, 3), got(3)
    character(len=200) :: line
    integer :: u, ios, r
    rows = reshape([0.0_wp, 1.0_wp/3.0_wp, -1.0e-300_wp, &
                    1.0e-3_wp, 2.5e25_wp, 0.1_wp, &
                    2.0e-3_wp, -7.0_wp, huge(1.0_wp)], [3, 3])
    call history_open(h, 'hist_out/run.hist', [character(len=16) :: 'time', 'kinetic_energy', 'gap_min'], err)
    do r = 1, 3
      call history_write(h, rows(:, r), err)
    end do
    call check(failure, .not. err%failed(), 'writing: ' // message(err))
    call check(failure, file_exists('hist_out/run.hist.part') .and. .not. file_exists('hist_out/run.hist'), &
      'only the .part file exists while open')
    call history_write(h, [1.0_wp], err)
    call check(failure, err%code == EXIT_INTERNAL, 'a short row is refused')
    call err%clear()
    call history_close(h, .true., err)
    call check(failure, .not. err%failed(), 'close: ' // message(err))
    call check(failure, file_exists('hist_out/run.hist') .and. .not. file_exists('hist_out/run.hist.part'), &
      'renamed to run.hist on a complete close')
    if (allocated(failure)) return
    open(newunit=u, file='hist_out/run.hist', status='old', action='read', iostat=ios)
    call check(failure, ios == 0, 'reopen run.hist')
    if (allocated(failure)) return
    read(u, '(a)') line
    call check(failure, line == '# raccord history', 'first header line, got "' // trim(line) // '"')
    read(u, '(a)') line
    call check(failure, line == '# 1 time', 'column 1 header, got "' // trim(line) // '"')
    read(u, '(a)') line
    call check(failure, line == '# 2 kinetic_energy', 'column 2 header, got "' // trim(line) // '"')
    read(u, '(a)') line
    call check(failure, line == '# 3 gap_min', 'column 3 header, got "' // trim(line) // '"')
    do r = 1, 3
      read(u, *, iostat=ios) got
      call check(failure, ios == 0, 'row ' // itoa(r) // ' parses')
      call check(failure, all(got == rows(:, r)), 'row ' // itoa(r) // ' reads back bit-exact')
    end do
    read(u, '(a)', iostat=ios) line
    call check(failure, ios /= 0, 'nothing after the last row')
    close(u)
    ! Incomplete close.
    call history_open(h, 'hist_out/run.hist', [character(len=4) :: 'time'], err)
    call check(failure, .not. file_exists('hist_out/run.hist'), 'opening removes the stale history')
    call history_write(h, [1.0_wp], err)
    call history_close(h, .false., err)
    call check(failure, .not. err%failed(), 'incomplete close: ' // message(err))
    call check(failure, file_exists('hist_out/run.incomplete.hist') .and. .not. file_exists('hist_out/run.hist'), &
      'renamed to run.incomplete.hist')
    call check(failure, incomplete_name('a.b/hist') == 'a.b/hist.incomplete', 'no extension: appended')
    call check(failure, incomplete_name('out/.hist') == 'out/.hist.incomplete', 'hidden file: appended')
    call check(failure, incomplete_name('out/r.dat') == 'out/r.incomplete.dat', 'extension kept last')
  end subroutine test_history

  ! --- helpers -------------------------------------------------------------

  function message(err) result(s)
    use raccord_error, only: error_t
    type(error_t), intent(in) :: err
    character(len=:), allocatable :: s
    s = '(no error)'
    if (allocated(err%message)) s = err%message
  end function message

  pure function itoa(i) result(s)
    integer, intent(in) :: i
    character(len=:), allocatable :: s
    character(len=16) :: buf
    write(buf, '(i0)') i
    s = trim(buf)
  end function itoa

  !> Non-overlapping occurrences of `what` in `text`.
  pure integer function count_of(text, what)
    character(len=*), intent(in) :: text, what
    integer :: k, at
    count_of = 0
    k = 1
    do
      at = index(text(k:), what)
      if (at == 0) exit
      count_of = count_of + 1
      k = k + at - 1 + len(what)
      if (k > len(text)) exit
    end do
  end function count_of

  !> A text file as one string, lines joined with newlines.
  function read_whole(path) result(s)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: s
    character(len=4096) :: line
    integer :: u, ios
    s = ''
    open(newunit=u, file=path, status='old', action='read', iostat=ios)
    if (ios /= 0) return
    do
      read(u, '(a)', iostat=ios) line
      if (ios /= 0) exit
      s = s // trim(line) // new_line('a')
    end do
    close(u)
  end function read_whole

  !> Each <DataItem ...>file:path</DataItem> must name `h5name` and an
  !> object that exists in `file`.
  subroutine check_data_items(failure, xml, h5name, file)
    use hdf5, only: hid_t, h5lexists_f, h5oexists_by_name_f
    type(failure_t), allocatable, intent(inout) :: failure
    character(len=*), intent(in) :: xml, h5name
    integer(hid_t), intent(in) :: file
    integer :: k, open_tag, gt, close_tag, colon, nitem, hdferr, c
    character(len=:), allocatable :: content, path
    logical :: exists
    nitem = 0
    k = 1
    do
      open_tag = index(xml(k:), '<DataItem')
      if (open_tag == 0) exit
      open_tag = k + open_tag - 1
      gt = open_tag + index(xml(open_tag:), '>') - 1
      close_tag = gt + index(xml(gt:), '</DataItem>') - 1
      if (close_tag < gt) then
        call fail_now(failure, 'unterminated DataItem')
        return
      end if
      content = adjustl(xml(gt + 1:close_tag - 1))
      content = trim(content)
      colon = index(content, ':')
      call check(failure, colon > 0, 'DataItem without file:path: "' // content // '"')
      if (allocated(failure)) return
      call check(failure, content(1:colon - 1) == h5name, 'DataItem names "' // content(1:colon - 1) &
        // '", expected "' // h5name // '"')
      path = content(colon + 1:)
      ! A hyperslab "path|start:stride:count:dims" names the dataset before '|'.
      if (index(path, '|') > 0) path = path(1:index(path, '|') - 1)
      ! Every link on the path, then the object itself.
      exists = .true.
      do c = 2, len(path) + 1
        if (c <= len(path)) then
          if (path(c:c) /= '/') cycle
        end if
        call h5lexists_f(file, path(1:c - 1), exists, hdferr)
        if (hdferr /= 0 .or. .not. exists) exit
      end do
      if (exists .and. hdferr == 0) call h5oexists_by_name_f(file, path, exists, hdferr)
      call check(failure, exists .and. hdferr == 0, 'XDMF references missing object "' // path // '"')
      nitem = nitem + 1
      k = close_tag + 1
    end do
    call check(failure, nitem > 0, 'no DataItem found in the XDMF')
  end subroutine check_data_items

  subroutine read_real_2d(file, path, a, failure)
    use raccord_kinds, only: wp
    use hdf5, only: hid_t, hsize_t, h5dopen_f, h5dread_f, h5dclose_f, H5T_NATIVE_DOUBLE
    integer(hid_t), intent(in) :: file
    character(len=*), intent(in) :: path
    real(wp), allocatable, intent(out) :: a(:,:)
    type(failure_t), allocatable, intent(inout) :: failure
    integer(hid_t) :: dset
    integer(hsize_t) :: dims(2)
    integer :: hdferr
    call dataset_dims(file, path, 2, dims, failure)
    if (allocated(failure)) return
    allocate(a(dims(1), dims(2)))
    call h5dopen_f(file, path, dset, hdferr)
    call h5dread_f(dset, H5T_NATIVE_DOUBLE, a, dims, hdferr)
    call check(failure, hdferr == 0, 'read ' // path)
    call h5dclose_f(dset, hdferr)
  end subroutine read_real_2d

  subroutine read_real_1d(file, path, a, failure)
    use raccord_kinds, only: wp
    use hdf5, only: hid_t, hsize_t, h5dopen_f, h5dread_f, h5dclose_f, H5T_NATIVE_DOUBLE
    integer(hid_t), intent(in) :: file
    character(len=*), intent(in) :: path
    real(wp), allocatable, intent(out) :: a(:)
    type(failure_t), allocatable, intent(inout) :: failure
    integer(hid_t) :: dset
    integer(hsize_t) :: dims(1)
    integer :: hdferr
    call dataset_dims(file, path, 1, dims, failure)
    if (allocated(failure)) return
    allocate(a(dims(1)))
    call h5dopen_f(file, path, dset, hdferr)
    call h5dread_f(dset, H5T_NATIVE_DOUBLE, a, dims, hdferr)
    call check(failure, hdferr == 0, 'read ' // path)
    call h5dclose_f(dset, hdferr)
  end subroutine read_real_1d

  subroutine read_int_2d(file, path, a, failure)
    use hdf5, only: hid_t, hsize_t, h5dopen_f, h5dread_f, h5dclose_f, H5T_NATIVE_INTEGER
    integer(hid_t), intent(in) :: file
    character(len=*), intent(in) :: path
    integer, allocatable, intent(out) :: a(:,:)
    type(failure_t), allocatable, intent(inout) :: failure
    integer(hid_t) :: dset
    integer(hsize_t) :: dims(2)
    integer :: hdferr
    call dataset_dims(file, path, 2, dims, failure)
    if (allocated(failure)) return
    allocate(a(dims(1), dims(2)))
    call h5dopen_f(file, path, dset, hdferr)
    call h5dread_f(dset, H5T_NATIVE_INTEGER, a, dims, hdferr)
    call check(failure, hdferr == 0, 'read ' // path)
    call h5dclose_f(dset, hdferr)
  end subroutine read_int_2d

  subroutine read_int_1d(file, path, a, failure)
    use hdf5, only: hid_t, hsize_t, h5dopen_f, h5dread_f, h5dclose_f, H5T_NATIVE_INTEGER
    integer(hid_t), intent(in) :: file
    character(len=*), intent(in) :: path
    integer, allocatable, intent(out) :: a(:)
    type(failure_t), allocatable, intent(inout) :: failure
    integer(hid_t) :: dset
    integer(hsize_t) :: dims(1)
    integer :: hdferr
    call dataset_dims(file, path, 1, dims, failure)
    if (allocated(failure)) return
    allocate(a(dims(1)))
    call h5dopen_f(file, path, dset, hdferr)
    call h5dread_f(dset, H5T_NATIVE_INTEGER, a, dims, hdferr)
    call check(failure, hdferr == 0, 'read ' // path)
    call h5dclose_f(dset, hdferr)
  end subroutine read_int_1d

  !> Dimensions of a dataset in Fortran order, with its rank checked.
  subroutine dataset_dims(file, path, rank, dims, failure)
    use hdf5, only: hid_t, hsize_t, h5dopen_f, h5dclose_f, h5dget_space_f, h5sclose_f, &
      h5sget_simple_extent_ndims_f, h5sget_simple_extent_dims_f
    integer(hid_t), intent(in) :: file
    character(len=*), intent(in) :: path
    integer, intent(in) :: rank
    integer(hsize_t), intent(out) :: dims(rank)
    type(failure_t), allocatable, intent(inout) :: failure
    integer(hid_t) :: dset, space
    integer(hsize_t) :: maxdims(rank)
    integer :: hdferr, got_rank
    dims = 0
    call h5dopen_f(file, path, dset, hdferr)
    if (hdferr /= 0) then
      call fail_now(failure, 'dataset ' // path // ' is missing')
      return
    end if
    call h5dget_space_f(dset, space, hdferr)
    call h5sget_simple_extent_ndims_f(space, got_rank, hdferr)
    call check(failure, got_rank == rank, path // ' has rank ' // itoa(got_rank) // ', expected ' // itoa(rank))
    if (.not. allocated(failure)) call h5sget_simple_extent_dims_f(space, dims, maxdims, hdferr)
    call h5sclose_f(space, hdferr)
    call h5dclose_f(dset, hdferr)
  end subroutine dataset_dims

  integer function read_int_attr(file, obj, name) result(v)
    use hdf5, only: hid_t, hsize_t, h5aopen_by_name_f, h5aread_f, h5aclose_f, H5T_NATIVE_INTEGER
    integer(hid_t), intent(in) :: file
    character(len=*), intent(in) :: obj, name
    integer(hid_t) :: attr
    integer :: hdferr
    v = -huge(1)
    call h5aopen_by_name_f(file, obj, name, attr, hdferr)
    if (hdferr /= 0) return
    call h5aread_f(attr, H5T_NATIVE_INTEGER, v, [1_hsize_t], hdferr)
    call h5aclose_f(attr, hdferr)
  end function read_int_attr

  function read_real_attr(file, obj, name) result(v)
    use raccord_kinds, only: wp
    use hdf5, only: hid_t, hsize_t, h5aopen_by_name_f, h5aread_f, h5aclose_f, H5T_NATIVE_DOUBLE
    integer(hid_t), intent(in) :: file
    character(len=*), intent(in) :: obj, name
    real(wp) :: v
    integer(hid_t) :: attr
    integer :: hdferr
    v = -huge(1.0_wp)
    call h5aopen_by_name_f(file, obj, name, attr, hdferr)
    if (hdferr /= 0) return
    call h5aread_f(attr, H5T_NATIVE_DOUBLE, v, [1_hsize_t], hdferr)
    call h5aclose_f(attr, hdferr)
  end function read_real_attr

  !> Item `item` of a 1D string attribute, NULs removed.
  function read_attr_text_item(file, obj, name, item) result(s)
    use hdf5, only: hid_t, hsize_t, size_t, h5aopen_by_name_f, h5aread_f, h5aclose_f, h5aget_type_f, &
      h5tget_size_f, h5tclose_f, h5aget_space_f, h5sget_simple_extent_npoints_f, h5sclose_f
    integer(hid_t), intent(in) :: file
    character(len=*), intent(in) :: obj, name
    integer, intent(in) :: item
    character(len=:), allocatable :: s
    character(len=:), allocatable :: buf(:)
    integer(hid_t) :: attr, atype, space
    integer(size_t) :: width
    integer(hsize_t) :: n
    integer :: hdferr
    s = '(missing)'
    call h5aopen_by_name_f(file, obj, name, attr, hdferr)
    if (hdferr /= 0) return
    call h5aget_space_f(attr, space, hdferr)
    call h5sget_simple_extent_npoints_f(space, n, hdferr)
    call h5sclose_f(space, hdferr)
    call h5aget_type_f(attr, atype, hdferr)
    call h5tget_size_f(atype, width, hdferr)
    allocate(character(len=width) :: buf(n))
    call h5aread_f(attr, atype, buf, [n], hdferr)
    if (hdferr == 0 .and. item <= n) s = strip_nul(buf(item))
    call h5tclose_f(atype, hdferr)
    call h5aclose_f(attr, hdferr)
  end function read_attr_text_item

  !> A scalar string dataset, NULs removed.
  function read_text(file, path) result(s)
    use hdf5, only: hid_t, hsize_t, size_t, h5dopen_f, h5dread_f, h5dclose_f, h5dget_type_f, &
      h5tget_size_f, h5tclose_f
    integer(hid_t), intent(in) :: file
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: s, buf
    integer(hid_t) :: dset, dtype
    integer(size_t) :: width
    integer :: hdferr
    s = '(missing)'
    call h5dopen_f(file, path, dset, hdferr)
    if (hdferr /= 0) return
    call h5dget_type_f(dset, dtype, hdferr)
    call h5tget_size_f(dtype, width, hdferr)
    allocate(character(len=width) :: buf)
    call h5dread_f(dset, dtype, buf, [1_hsize_t], hdferr)
    if (hdferr == 0) s = strip_nul(buf)
    call h5tclose_f(dtype, hdferr)
    call h5dclose_f(dset, hdferr)
  end function read_text

  pure function strip_nul(t) result(s)
    character(len=*), intent(in) :: t
    character(len=:), allocatable :: s
    integer :: n
    n = index(t, achar(0)) - 1
    if (n < 0) n = len(t)
    s = t(1:n)
  end function strip_nul
end program test_results_io
