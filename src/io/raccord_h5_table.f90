!> Growing tables: a real dataset of a fixed number of columns whose rows
!> are appended in blocks while a run goes on (the time history, issue #18:
!> it was kept in memory for the whole run, sized from the planned step
!> count, and lost the rows of a variable-step run beyond that count).
!>
!> A Fortran table(ncol, nrow) is stored as dims (nrow, ncol) as h5dump and
!> h5py show them, with an unlimited row count: chunked (chunk_rows rows of
!> all columns per chunk) and with the Fletcher32 checksum on each chunk,
!> like every other array raccord writes (raccord_h5). Memory is one block
!> of rows, whatever the number of rows in the file.
module raccord_h5_table
  use hdf5, only: hid_t, hsize_t, h5screate_simple_f, h5sclose_f, h5sselect_hyperslab_f, &
    h5sget_simple_extent_ndims_f, h5sget_simple_extent_dims_f, &
    h5dcreate_f, h5dopen_f, h5dwrite_f, h5dclose_f, h5dset_extent_f, h5dget_space_f, &
    h5pcreate_f, h5pset_chunk_f, h5pclose_f, h5pset_fletcher32_f, &
    H5T_NATIVE_DOUBLE, H5S_UNLIMITED_F, H5S_SELECT_SET_F, H5P_DATASET_CREATE_F
  use raccord_kinds, only: wp, i8
  use raccord_error, only: error_t, raise_error, EXIT_IO, EXIT_INPUT
  use raccord_h5, only: h5_ensure_groups, h5_link_exists
  implicit none
  private

  public :: h5_create_table, h5_append_rows, h5_truncate_rows

contains

  !> Create an empty table of ncol columns at `path` (dims (0, ncol), rows
  !> unlimited), chunk_rows rows per chunk, Fletcher32 on each chunk.
  subroutine h5_create_table(loc, path, ncol, chunk_rows, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    integer, intent(in) :: ncol, chunk_rows
    type(error_t), intent(inout) :: err
    integer(hid_t) :: space, dcpl, dset
    integer(hsize_t) :: dims(2), maxdims(2), chunk(2)
    integer :: hdferr, cerr
    if (ncol < 1 .or. chunk_rows < 1) then
      call raise_error(err, EXIT_IO, 'cannot create table "' // path // '" in ' // where // ': no columns')
      return
    end if
    call h5_ensure_groups(loc, path, where, err)
    if (err%failed()) return
    if (h5_link_exists(loc, path)) then
      call raise_error(err, EXIT_IO, 'cannot create table "' // path // '" in ' // where &
        // ': the name already exists')
      return
    end if
    ! Fortran order: (columns, rows); HDF5 shows it reversed.
    dims = [int(ncol, hsize_t), 0_hsize_t]
    maxdims = [int(ncol, hsize_t), H5S_UNLIMITED_F]
    chunk = [int(ncol, hsize_t), int(chunk_rows, hsize_t)]
    space = -1
    dcpl = -1
    dset = -1
    steps: block
      call h5screate_simple_f(2, dims, space, hdferr, maxdims)
      if (hdferr /= 0) exit steps
      call h5pcreate_f(H5P_DATASET_CREATE_F, dcpl, hdferr)
      if (hdferr /= 0) exit steps
      call h5pset_chunk_f(dcpl, 2, chunk, hdferr)
      if (hdferr /= 0) exit steps
      call h5pset_fletcher32_f(dcpl, hdferr)
      if (hdferr /= 0) exit steps
      call h5dcreate_f(loc, path, H5T_NATIVE_DOUBLE, space, dset, hdferr, dcpl_id=dcpl)
      if (hdferr /= 0) dset = -1
    end block steps
    cerr = 0
    if (dset /= -1) call h5dclose_f(dset, cerr)
    if (dcpl /= -1) call h5pclose_f(dcpl, cerr)
    if (space /= -1) call h5sclose_f(space, cerr)
    if (hdferr /= 0 .or. cerr /= 0 .or. dset == -1) &
      call raise_error(err, EXIT_IO, 'cannot create table "' // path // '" in ' // where)
  end subroutine h5_create_table

  !> Append rows(ncol, n) after the table's last row.
  subroutine h5_append_rows(loc, path, rows, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    real(wp), intent(in) :: rows(:,:)
    type(error_t), intent(inout) :: err
    integer(hid_t) :: dset, fspace, mspace
    integer(hsize_t) :: dims(2), n
    integer :: hdferr, cerr
    if (size(rows, 2) == 0) return
    call open_table(loc, path, size(rows, 1), dset, dims, where, err)
    if (err%failed()) return
    n = size(rows, 2, kind=hsize_t)
    fspace = -1
    mspace = -1
    steps: block
      call h5dset_extent_f(dset, [dims(1), dims(2) + n], hdferr)
      if (hdferr /= 0) exit steps
      call h5dget_space_f(dset, fspace, hdferr)
      if (hdferr /= 0) exit steps
      call h5sselect_hyperslab_f(fspace, H5S_SELECT_SET_F, [0_hsize_t, dims(2)], [dims(1), n], hdferr)
      if (hdferr /= 0) exit steps
      call h5screate_simple_f(2, [dims(1), n], mspace, hdferr)
      if (hdferr /= 0) exit steps
      call h5dwrite_f(dset, H5T_NATIVE_DOUBLE, rows, [dims(1), n], hdferr, &
        mem_space_id=mspace, file_space_id=fspace)
    end block steps
    cerr = 0
    if (mspace /= -1) call h5sclose_f(mspace, cerr)
    if (fspace /= -1) call h5sclose_f(fspace, cerr)
    call h5dclose_f(dset, cerr)
    if (hdferr /= 0 .or. cerr /= 0) call raise_error(err, EXIT_IO, 'cannot append ' // int_text(int(n, i8)) // &
      ' rows to "' // path // '" in ' // where // ' (disk full?)')
  end subroutine h5_append_rows

  !> Cut the table to its first nrow rows (a resumed run drops the rows a
  !> killed run wrote after its checkpoint). A table of another column
  !> count, or with fewer rows than nrow, is EXIT_INPUT: the file does not
  !> belong to the checkpoint.
  subroutine h5_truncate_rows(loc, path, ncol, nrow, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    integer, intent(in) :: ncol
    integer(i8), intent(in) :: nrow
    type(error_t), intent(inout) :: err
    integer(hid_t) :: dset
    integer(hsize_t) :: dims(2)
    integer :: hdferr, cerr
    if (.not. h5_link_exists(loc, path)) then
      call raise_error(err, EXIT_INPUT, where // ' has no table "' // path // '" (written by an older raccord?); ' // &
        'run the scene afresh without --restart')
      return
    end if
    call open_table(loc, path, ncol, dset, dims, where, err)
    if (err%failed()) return
    hdferr = 0
    if (int(dims(2), i8) < nrow) then
      call raise_error(err, EXIT_INPUT, 'table "' // path // '" in ' // where // ' has ' // &
        int_text(int(dims(2), i8)) // ' rows, fewer than the ' // int_text(nrow) // ' of the checkpoint; ' // &
        'run the scene afresh without --restart')
    else if (int(dims(2), i8) > nrow) then
      call h5dset_extent_f(dset, [dims(1), int(nrow, hsize_t)], hdferr)
    end if
    call h5dclose_f(dset, cerr)
    if (hdferr /= 0 .or. cerr /= 0) call raise_error(err, EXIT_IO, 'cannot shorten table "' // path // &
      '" in ' // where)
  end subroutine h5_truncate_rows

  ! --- private -----------------------------------------------------------

  !> Open a table and get its Fortran dims (ncol, nrow); it must be rank 2
  !> with ncol columns (else EXIT_INPUT, the dataset is not this table).
  subroutine open_table(loc, path, ncol, dset, dims, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    integer, intent(in) :: ncol
    integer(hid_t), intent(out) :: dset
    integer(hsize_t), intent(out) :: dims(2)
    type(error_t), intent(inout) :: err
    integer(hid_t) :: space
    integer(hsize_t) :: maxdims(2)
    integer :: hdferr, rank, cerr
    dims = 0
    call h5dopen_f(loc, path, dset, hdferr)
    if (hdferr /= 0) then
      call raise_error(err, EXIT_IO, 'cannot open table "' // path // '" in ' // where)
      return
    end if
    rank = -1
    call h5dget_space_f(dset, space, hdferr)
    if (hdferr == 0) then
      call h5sget_simple_extent_ndims_f(space, rank, hdferr)
      if (hdferr == 0 .and. rank == 2) then
        call h5sget_simple_extent_dims_f(space, dims, maxdims, hdferr)
        if (hdferr > 0) hdferr = 0
      end if
      call h5sclose_f(space, cerr)
    end if
    if (hdferr /= 0 .or. rank /= 2 .or. dims(1) /= int(ncol, hsize_t)) then
      call h5dclose_f(dset, cerr)
      call raise_error(err, EXIT_INPUT, 'table "' // path // '" in ' // where // ' is not a table of ' // &
        int_text(int(ncol, i8)) // ' columns (damaged, or written for another scene)')
    end if
  end subroutine open_table

  pure function int_text(n) result(s)
    integer(i8), intent(in) :: n
    character(len=:), allocatable :: s
    character(len=24) :: buf
    write(buf, '(i0)') n
    s = trim(buf)
  end function int_text
end module raccord_h5_table
