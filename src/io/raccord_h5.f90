!> Error-checked HDF5 helpers used by raccord_results: library open/close,
!> datasets and attributes written in one call, groups created on demand.
!>
!> Every helper checks each HDF5 call's hdferr and raises EXIT_IO with the
!> file name (`where`) and the object being written, so the caller only adds
!> what it was doing. Arrays keep Fortran order: a Fortran array a(m, n) is
!> an HDF5 dataset of dims (n, m) as h5dump and h5py show it.
module raccord_h5
  use hdf5, only: hid_t, hsize_t, size_t, h5open_f, h5close_f, h5eset_auto_f, &
    h5gcreate_f, h5gclose_f, h5lexists_f, h5ldelete_f, &
    h5screate_simple_f, h5screate_f, h5sclose_f, h5sselect_hyperslab_f, &
    h5dcreate_f, h5dopen_f, h5dwrite_f, h5dclose_f, h5dset_extent_f, h5dget_space_f, &
    h5acreate_f, h5awrite_f, h5aclose_f, &
    h5tcopy_f, h5tset_size_f, h5tset_strpad_f, h5tclose_f, &
    h5pcreate_f, h5pset_chunk_f, h5pclose_f, h5pset_fletcher32_f, h5pset_libver_bounds_f, h5fcreate_f, &
    H5T_NATIVE_DOUBLE, H5T_NATIVE_INTEGER, H5T_NATIVE_CHARACTER, H5T_STR_NULLPAD_F, &
    H5S_SCALAR_F, H5S_UNLIMITED_F, H5S_SELECT_SET_F, H5P_DATASET_CREATE_F, H5P_FILE_ACCESS_F, &
    H5F_ACC_TRUNC_F, H5F_LIBVER_V110_F, H5F_LIBVER_LATEST_F, H5P_DEFAULT_F
  use, intrinsic :: iso_c_binding, only: c_ptr, c_loc
  use, intrinsic :: iso_fortran_env, only: int64
  use hdf5, only: h5kind_to_type, H5_INTEGER_KIND
  use raccord_kinds, only: wp, i8
  use raccord_error, only: error_t, raise_error, EXIT_IO
  use raccord_crc32, only: crc32_t, crc_add, crc_value, crc_hex
  implicit none
  private

  public :: h5_acquire, h5_release, h5_create_file
  public :: h5_ensure_groups, h5_link_exists, h5_delete_link
  public :: h5_write_real, h5_write_int, h5_write_text
  public :: h5_attr_real, h5_attr_int, h5_attr_i8, h5_attr_text, h5_attr_text_list
  public :: h5_create_growing, h5_append_real, h5_append_int, h5_append_i8, h5_truncate_growing

  !> Write a real(wp) dataset of rank 1 or 2.
  interface h5_write_real
    module procedure write_real_1d, write_real_2d
  end interface h5_write_real

  !> Write an integer dataset of rank 1 or 2.
  interface h5_write_int
    module procedure write_int_1d, write_int_2d
  end interface h5_write_int

  !> Chunk length of growing 1D datasets (frame times and steps).
  integer(hsize_t), parameter :: GROW_CHUNK = 64

  !> Number of open users of the HDF5 library. This is module state on
  !> purpose: h5open_f/h5close_f are process-wide, and several results
  !> files (or a test reading them back) may be open at once, so the library
  !> is closed only when the last user releases it.
  integer :: users = 0

contains

  !> Open the HDF5 library for one more user (h5open_f on the first one)
  !> and silence HDF5's own error stack printout: our messages say which
  !> file and object failed.
  subroutine h5_acquire(err)
    type(error_t), intent(inout) :: err
    integer :: hdferr
    if (users == 0) then
      call h5open_f(hdferr)
      if (hdferr /= 0) then
        call raise_error(err, EXIT_IO, 'cannot initialise the HDF5 library (h5open_f failed)')
        return
      end if
      call h5eset_auto_f(0, hdferr)
    end if
    users = users + 1
  end subroutine h5_acquire

  !> Release one user; the last one closes the library (h5close_f).
  subroutine h5_release(err)
    type(error_t), intent(inout) :: err
    integer :: hdferr
    if (users <= 0) return
    users = users - 1
    if (users > 0) return
    call h5close_f(hdferr)
    if (hdferr /= 0) call raise_error(err, EXIT_IO, 'cannot close the HDF5 library (h5close_f failed)')
  end subroutine h5_release

  !> Create (truncate) a file whose metadata carries checksums: the file
  !> format of HDF5 1.10 (superblock v3, object headers v2, and chunk
  !> indexes with checksums; the 1.8 format still indexes chunks with
  !> version-1 B-trees, which have none), which HDF5 checks on every read.
  !> Readers need HDF5 1.10 or later. With the Fletcher32 filter on the datasets
  !> (create_dataset, h5_create_growing), a damaged byte anywhere in what a
  !> reader uses is found (issue #18) rather than read as a value.
  subroutine h5_create_file(path, file, hdferr)
    character(len=*), intent(in) :: path
    integer(hid_t), intent(out) :: file
    integer, intent(out) :: hdferr
    integer(hid_t) :: fapl
    integer :: cerr
    file = -1
    call h5pcreate_f(H5P_FILE_ACCESS_F, fapl, hdferr)
    if (hdferr /= 0) return
    call h5pset_libver_bounds_f(fapl, H5F_LIBVER_V110_F, H5F_LIBVER_LATEST_F, hdferr)
    if (hdferr == 0) call h5fcreate_f(path, H5F_ACC_TRUNC_F, file, hdferr, H5P_DEFAULT_F, fapl)
    call h5pclose_f(fapl, cerr)
    if (hdferr == 0) hdferr = cerr
  end subroutine h5_create_file

  !> True when every link of an absolute or relative path exists
  !> (h5lexists_f alone fails when an intermediate group is missing).
  logical function h5_link_exists(loc, path)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path
    integer :: k, hdferr
    logical :: exists
    h5_link_exists = .false.
    do k = 2, len(path) + 1
      if (k <= len(path)) then
        if (path(k:k) /= '/') cycle
      end if
      if (path(k-1:k-1) == '/') cycle
      call h5lexists_f(loc, path(1:k-1), exists, hdferr)
      if (hdferr /= 0 .or. .not. exists) return
    end do
    h5_link_exists = .true.
  end function h5_link_exists

  !> Create every missing group on the path to an object, i.e. all path
  !> components but the last ("/a/b/c" creates /a and /a/b).
  subroutine h5_ensure_groups(loc, path, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    type(error_t), intent(inout) :: err
    integer :: k, hdferr
    integer(hid_t) :: grp
    do k = 2, len(path)
      if (path(k:k) /= '/' .or. path(k-1:k-1) == '/') cycle
      if (h5_link_exists(loc, path(1:k-1))) cycle
      call h5gcreate_f(loc, path(1:k-1), grp, hdferr)
      if (hdferr /= 0) then
        call raise_error(err, EXIT_IO, 'cannot create group "' // path(1:k-1) // '" in ' // where)
        return
      end if
      call h5gclose_f(grp, hdferr)
      if (hdferr /= 0) then
        call raise_error(err, EXIT_IO, 'cannot close group "' // path(1:k-1) // '" in ' // where)
        return
      end if
    end do
  end subroutine h5_ensure_groups

  !> Remove a link if it exists (to replace a dataset such as /status).
  subroutine h5_delete_link(loc, path, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    type(error_t), intent(inout) :: err
    integer :: hdferr
    if (.not. h5_link_exists(loc, path)) return
    call h5ldelete_f(loc, path, hdferr)
    if (hdferr /= 0) call raise_error(err, EXIT_IO, 'cannot replace "' // path // '" in ' // where)
  end subroutine h5_delete_link

  ! --- datasets ----------------------------------------------------------

  subroutine write_real_1d(loc, path, values, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    real(wp), intent(in) :: values(:)
    type(error_t), intent(inout) :: err
    integer(hid_t) :: dset
    integer(hsize_t) :: dims(1)
    integer :: hdferr
    dims = shape(values, kind=hsize_t)
    call create_dataset(loc, path, H5T_NATIVE_DOUBLE, dims, dset, where, err)
    if (err%failed()) return
    call h5dwrite_f(dset, H5T_NATIVE_DOUBLE, values, dims, hdferr)
    call finish_dataset(dset, hdferr, path, where, err)
  end subroutine write_real_1d

  subroutine write_real_2d(loc, path, values, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    real(wp), intent(in) :: values(:,:)
    type(error_t), intent(inout) :: err
    integer(hid_t) :: dset
    integer(hsize_t) :: dims(2)
    integer :: hdferr
    dims = shape(values, kind=hsize_t)
    call create_dataset(loc, path, H5T_NATIVE_DOUBLE, dims, dset, where, err)
    if (err%failed()) return
    call h5dwrite_f(dset, H5T_NATIVE_DOUBLE, values, dims, hdferr)
    call finish_dataset(dset, hdferr, path, where, err)
  end subroutine write_real_2d

  subroutine write_int_1d(loc, path, values, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    integer, intent(in) :: values(:)
    type(error_t), intent(inout) :: err
    integer(hid_t) :: dset
    integer(hsize_t) :: dims(1)
    integer :: hdferr
    dims = shape(values, kind=hsize_t)
    call create_dataset(loc, path, H5T_NATIVE_INTEGER, dims, dset, where, err)
    if (err%failed()) return
    call h5dwrite_f(dset, H5T_NATIVE_INTEGER, values, dims, hdferr)
    call finish_dataset(dset, hdferr, path, where, err)
  end subroutine write_int_1d

  subroutine write_int_2d(loc, path, values, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    integer, intent(in) :: values(:,:)
    type(error_t), intent(inout) :: err
    integer(hid_t) :: dset
    integer(hsize_t) :: dims(2)
    integer :: hdferr
    dims = shape(values, kind=hsize_t)
    call create_dataset(loc, path, H5T_NATIVE_INTEGER, dims, dset, where, err)
    if (err%failed()) return
    call h5dwrite_f(dset, H5T_NATIVE_INTEGER, values, dims, hdferr)
    call finish_dataset(dset, hdferr, path, where, err)
  end subroutine write_int_2d

  !> A scalar fixed-length string dataset (for texts too long for an
  !> attribute, such as the echoed scene).
  subroutine h5_write_text(loc, path, text, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, text, where
    type(error_t), intent(inout) :: err
    integer(hid_t) :: dset, space, stype
    integer(hsize_t), parameter :: scalar_dims(1) = [1_hsize_t]
    integer :: hdferr
    type(crc32_t) :: crc
    call h5_ensure_groups(loc, path, where, err)
    if (err%failed()) return
    call string_type(len(text), stype, hdferr)
    if (hdferr /= 0) then
      call raise_error(err, EXIT_IO, 'cannot make a string type for "' // path // '" in ' // where)
      return
    end if
    call h5screate_f(H5S_SCALAR_F, space, hdferr)
    if (hdferr == 0) then
      call h5dcreate_f(loc, path, stype, space, dset, hdferr)
      if (hdferr == 0) then
        call h5dwrite_f(dset, stype, padded(text), scalar_dims, hdferr)
        if (hdferr /= 0) call raise_error(err, EXIT_IO, 'cannot write text "' // path // '" in ' // where)
        ! A scalar text cannot take the Fletcher32 filter (it needs
        ! chunks): its CRC-32 goes beside it, checked by raccord_h5_verify.
        call crc_add(crc, padded(text))
        call h5_attr_text(dset, 'crc32', crc_hex(crc_value(crc)), where, err)
        call h5dclose_f(dset, hdferr)
      else
        call raise_error(err, EXIT_IO, 'cannot create text dataset "' // path // '" in ' // where &
          // ' (does the name already exist?)')
      end if
      call h5sclose_f(space, hdferr)
    end if
    call h5tclose_f(stype, hdferr)
    if (hdferr /= 0) call raise_error(err, EXIT_IO, 'cannot write text "' // path // '" in ' // where)
  end subroutine h5_write_text

  ! --- growing 1D datasets (one entry per frame) ---------------------------

  !> Create an empty 1D dataset with unlimited length, so a killed run
  !> still has the entries of every frame it flushed: reals, or integers
  !> (64-bit with wide = .true.: step numbers, which pass 2**31 in a long run).
  subroutine h5_create_growing(loc, path, is_real, where, err, wide)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    logical, intent(in) :: is_real
    type(error_t), intent(inout) :: err
    logical, intent(in), optional :: wide
    integer(hid_t) :: space, dcpl, dset, dtype
    integer(hsize_t) :: dims(1), maxdims(1), chunk(1)
    integer :: hdferr
    dims = 0
    maxdims = H5S_UNLIMITED_F
    chunk = GROW_CHUNK
    dtype = H5T_NATIVE_INTEGER
    if (present(wide)) then
      if (wide) dtype = h5kind_to_type(int64, H5_INTEGER_KIND)
    end if
    if (is_real) dtype = H5T_NATIVE_DOUBLE
    call h5_ensure_groups(loc, path, where, err)
    if (err%failed()) return
    steps: block
      call h5screate_simple_f(1, dims, space, hdferr, maxdims)
      if (hdferr /= 0) exit steps
      call h5pcreate_f(H5P_DATASET_CREATE_F, dcpl, hdferr)
      if (hdferr /= 0) exit steps
      call h5pset_chunk_f(dcpl, 1, chunk, hdferr)
      if (hdferr /= 0) exit steps
      call h5pset_fletcher32_f(dcpl, hdferr)
      if (hdferr /= 0) exit steps
      call h5dcreate_f(loc, path, dtype, space, dset, hdferr, dcpl_id=dcpl)
      if (hdferr /= 0) exit steps
      call h5dclose_f(dset, hdferr)
      if (hdferr /= 0) exit steps
      call h5pclose_f(dcpl, hdferr)
      if (hdferr /= 0) exit steps
      call h5sclose_f(space, hdferr)
      if (hdferr /= 0) exit steps
      return
    end block steps
    call raise_error(err, EXIT_IO, 'cannot create growing dataset "' // path // '" in ' // where)
  end subroutine h5_create_growing

  !> Append one real value to a growing 1D dataset.
  subroutine h5_append_real(loc, path, value, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    real(wp), intent(in) :: value
    type(error_t), intent(inout) :: err
    integer(hid_t) :: dset, fspace, mspace
    integer(hsize_t) :: n
    integer :: hdferr
    call open_for_append(loc, path, dset, fspace, mspace, n, where, err)
    if (err%failed()) return
    call h5dwrite_f(dset, H5T_NATIVE_DOUBLE, [value], [1_hsize_t], hdferr, &
      mem_space_id=mspace, file_space_id=fspace)
    call close_after_append(dset, fspace, mspace, hdferr, path, where, err)
  end subroutine h5_append_real

  !> Append one integer to a growing 1D dataset.
  subroutine h5_append_int(loc, path, value, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    integer, intent(in) :: value
    type(error_t), intent(inout) :: err
    integer(hid_t) :: dset, fspace, mspace
    integer(hsize_t) :: n
    integer :: hdferr
    call open_for_append(loc, path, dset, fspace, mspace, n, where, err)
    if (err%failed()) return
    call h5dwrite_f(dset, H5T_NATIVE_INTEGER, [value], [1_hsize_t], hdferr, &
      mem_space_id=mspace, file_space_id=fspace)
    call close_after_append(dset, fspace, mspace, hdferr, path, where, err)
  end subroutine h5_append_int

  !> Append one 64-bit integer to a growing 1D dataset.
  subroutine h5_append_i8(loc, path, value, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    integer(i8), intent(in) :: value
    type(error_t), intent(inout) :: err
    integer(hid_t) :: dset, fspace, mspace
    integer(hsize_t) :: n
    integer(i8), target :: buf(1)
    type(c_ptr) :: ptr
    integer :: hdferr
    call open_for_append(loc, path, dset, fspace, mspace, n, where, err)
    if (err%failed()) return
    buf = value
    ptr = c_loc(buf)
    call h5dwrite_f(dset, h5kind_to_type(int64, H5_INTEGER_KIND), ptr, hdferr, &
      mem_space_id=mspace, file_space_id=fspace)
    call close_after_append(dset, fspace, mspace, hdferr, path, where, err)
  end subroutine h5_append_i8

  !> Cut a growing 1D dataset to its first n entries (a resumed run drops
  !> the frames a killed run wrote after its checkpoint). Returns the
  !> length it had in `had`; n larger than that is an error.
  subroutine h5_truncate_growing(loc, path, n, had, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    integer, intent(in) :: n
    integer, intent(out) :: had
    type(error_t), intent(inout) :: err
    integer(hid_t) :: dset, space
    integer(hsize_t) :: dims(1), maxdims(1)
    integer :: hdferr, rank
    had = -1
    call h5dopen_f(loc, path, dset, hdferr)
    if (hdferr /= 0) then
      call raise_error(err, EXIT_IO, 'cannot open dataset "' // path // '" in ' // where)
      return
    end if
    call h5dget_space_f(dset, space, hdferr)
    if (hdferr == 0) then
      call h5sget_dims(space, dims, maxdims, rank)
      call h5sclose_f(space, hdferr)
      if (rank /= 1) hdferr = -1
    end if
    if (hdferr == 0) then
      had = int(dims(1))
      if (n <= had) call h5dset_extent_f(dset, [int(n, hsize_t)], hdferr)
    end if
    call h5dclose_f(dset, rank)
    if (hdferr /= 0 .or. rank /= 0) then
      call raise_error(err, EXIT_IO, 'cannot shorten dataset "' // path // '" in ' // where)
    else if (n > had) then
      call raise_error(err, EXIT_IO, 'dataset "' // path // '" in ' // where // ' has ' // &
        trim(int_text(had)) // ' entries, fewer than the ' // trim(int_text(n)) // ' expected')
    end if
  end subroutine h5_truncate_growing

  ! --- attributes --------------------------------------------------------

  subroutine h5_attr_real(obj, name, value, where, err)
    integer(hid_t), intent(in) :: obj
    character(len=*), intent(in) :: name, where
    real(wp), intent(in) :: value
    type(error_t), intent(inout) :: err
    integer(hid_t) :: space, attr
    integer :: hdferr
    call h5screate_f(H5S_SCALAR_F, space, hdferr)
    if (hdferr == 0) call h5acreate_f(obj, name, H5T_NATIVE_DOUBLE, space, attr, hdferr)
    if (hdferr == 0) call h5awrite_f(attr, H5T_NATIVE_DOUBLE, value, [1_hsize_t], hdferr)
    if (hdferr == 0) call h5aclose_f(attr, hdferr)
    if (hdferr == 0) call h5sclose_f(space, hdferr)
    if (hdferr /= 0) call raise_error(err, EXIT_IO, 'cannot write attribute "' // name // '" in ' // where)
  end subroutine h5_attr_real

  subroutine h5_attr_int(obj, name, value, where, err)
    integer(hid_t), intent(in) :: obj
    character(len=*), intent(in) :: name, where
    integer, intent(in) :: value
    type(error_t), intent(inout) :: err
    integer(hid_t) :: space, attr
    integer :: hdferr
    call h5screate_f(H5S_SCALAR_F, space, hdferr)
    if (hdferr == 0) call h5acreate_f(obj, name, H5T_NATIVE_INTEGER, space, attr, hdferr)
    if (hdferr == 0) call h5awrite_f(attr, H5T_NATIVE_INTEGER, value, [1_hsize_t], hdferr)
    if (hdferr == 0) call h5aclose_f(attr, hdferr)
    if (hdferr == 0) call h5sclose_f(space, hdferr)
    if (hdferr /= 0) call raise_error(err, EXIT_IO, 'cannot write attribute "' // name // '" in ' // where)
  end subroutine h5_attr_int

  !> A scalar 64-bit integer attribute (a step number).
  subroutine h5_attr_i8(obj, name, value, where, err)
    integer(hid_t), intent(in) :: obj
    character(len=*), intent(in) :: name, where
    integer(i8), intent(in) :: value
    type(error_t), intent(inout) :: err
    integer(hid_t) :: space, attr, dtype
    integer(i8), target :: buf(1)
    type(c_ptr) :: ptr
    integer :: hdferr
    dtype = h5kind_to_type(int64, H5_INTEGER_KIND)
    buf = value
    ptr = c_loc(buf)
    call h5screate_f(H5S_SCALAR_F, space, hdferr)
    if (hdferr == 0) call h5acreate_f(obj, name, dtype, space, attr, hdferr)
    if (hdferr == 0) call h5awrite_f(attr, dtype, ptr, hdferr)
    if (hdferr == 0) call h5aclose_f(attr, hdferr)
    if (hdferr == 0) call h5sclose_f(space, hdferr)
    if (hdferr /= 0) call raise_error(err, EXIT_IO, 'cannot write attribute "' // name // '" in ' // where)
  end subroutine h5_attr_i8

  !> A scalar string attribute, null-padded so h5py reads it without
  !> trailing blanks.
  subroutine h5_attr_text(obj, name, text, where, err)
    integer(hid_t), intent(in) :: obj
    character(len=*), intent(in) :: name, text, where
    type(error_t), intent(inout) :: err
    integer(hid_t) :: space, attr, stype
    integer :: hdferr
    call string_type(len(text), stype, hdferr)
    if (hdferr == 0) call h5screate_f(H5S_SCALAR_F, space, hdferr)
    if (hdferr == 0) call h5acreate_f(obj, name, stype, space, attr, hdferr)
    if (hdferr == 0) call h5awrite_f(attr, stype, padded(text), [1_hsize_t], hdferr)
    if (hdferr == 0) call h5aclose_f(attr, hdferr)
    if (hdferr == 0) call h5sclose_f(space, hdferr)
    if (hdferr == 0) call h5tclose_f(stype, hdferr)
    if (hdferr /= 0) call raise_error(err, EXIT_IO, 'cannot write attribute "' // name // '" in ' // where)
  end subroutine h5_attr_text

  !> A 1D attribute of strings (column names), each trimmed and null-padded.
  subroutine h5_attr_text_list(obj, name, texts, where, err)
    integer(hid_t), intent(in) :: obj
    character(len=*), intent(in) :: name, texts(:), where
    type(error_t), intent(inout) :: err
    integer(hid_t) :: space, attr, stype
    integer(hsize_t) :: dims(1)
    character(len=:), allocatable :: buf(:)
    integer :: hdferr, k, width
    width = 1
    do k = 1, size(texts)
      width = max(width, len_trim(texts(k)))
    end do
    allocate(character(len=width) :: buf(size(texts)))
    do k = 1, size(texts)
      buf(k) = repeat(achar(0), width)
      buf(k)(1:len_trim(texts(k))) = trim(texts(k))
    end do
    dims = size(texts)
    call string_type(width, stype, hdferr)
    if (hdferr == 0) call h5screate_simple_f(1, dims, space, hdferr)
    if (hdferr == 0) call h5acreate_f(obj, name, stype, space, attr, hdferr)
    if (hdferr == 0) call h5awrite_f(attr, stype, buf, dims, hdferr)
    if (hdferr == 0) call h5aclose_f(attr, hdferr)
    if (hdferr == 0) call h5sclose_f(space, hdferr)
    if (hdferr == 0) call h5tclose_f(stype, hdferr)
    if (hdferr /= 0) call raise_error(err, EXIT_IO, 'cannot write attribute "' // name // '" in ' // where)
  end subroutine h5_attr_text_list

  ! --- private -----------------------------------------------------------

  !> Create the groups above `path` and an empty dataset there: one chunk
  !> with the Fletcher32 checksum filter (an empty or very large dataset
  !> stays contiguous, without it: a chunk holds at most 4 GB).
  subroutine create_dataset(loc, path, dtype, dims, dset, where, err)
    integer(hid_t), intent(in) :: loc, dtype
    character(len=*), intent(in) :: path, where
    integer(hsize_t), intent(in) :: dims(:)
    integer(hid_t), intent(out) :: dset
    type(error_t), intent(inout) :: err
    integer(hsize_t), parameter :: max_chunk_values = 2_hsize_t**28
    integer(hid_t) :: space, dcpl
    integer :: hdferr, cerr
    logical :: checked
    dset = -1
    call h5_ensure_groups(loc, path, where, err)
    if (err%failed()) return
    if (h5_link_exists(loc, path)) then
      call raise_error(err, EXIT_IO, 'cannot create dataset "' // path // '" in ' // where &
        // ': the name already exists (each dataset is written once)')
      return
    end if
    ! The Fortran API takes the Fortran shape and stores it reversed
    ! (slowest first), which is the layout h5dump and h5py show.
    checked = all(dims > 0) .and. product(dims) <= max_chunk_values
    call h5screate_simple_f(size(dims), dims, space, hdferr)
    if (hdferr == 0) then
      if (checked) then
        call h5pcreate_f(H5P_DATASET_CREATE_F, dcpl, hdferr)
        if (hdferr == 0) call h5pset_chunk_f(dcpl, size(dims), dims, hdferr)
        if (hdferr == 0) call h5pset_fletcher32_f(dcpl, hdferr)
        if (hdferr == 0) call h5dcreate_f(loc, path, dtype, space, dset, hdferr, dcpl_id=dcpl)
        call h5pclose_f(dcpl, cerr)
      else
        call h5dcreate_f(loc, path, dtype, space, dset, hdferr)
      end if
      if (hdferr /= 0) dset = -1
      call h5sclose_f(space, hdferr)
    end if
    if (dset == -1 .or. hdferr /= 0) then
      call raise_error(err, EXIT_IO, 'cannot create dataset "' // path // '" in ' // where)
    end if
  end subroutine create_dataset

  !> Check the write status and close the dataset.
  subroutine finish_dataset(dset, write_status, path, where, err)
    integer(hid_t), intent(in) :: dset
    integer, intent(in) :: write_status
    character(len=*), intent(in) :: path, where
    type(error_t), intent(inout) :: err
    integer :: hdferr
    if (write_status /= 0) call raise_error(err, EXIT_IO, 'cannot write dataset "' // path // '" in ' // where)
    call h5dclose_f(dset, hdferr)
    if (hdferr /= 0) call raise_error(err, EXIT_IO, 'cannot close dataset "' // path // '" in ' // where)
  end subroutine finish_dataset

  !> Grow a 1D dataset by one and select its new last entry.
  subroutine open_for_append(loc, path, dset, fspace, mspace, n, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    integer(hid_t), intent(out) :: dset, fspace, mspace
    integer(hsize_t), intent(out) :: n
    type(error_t), intent(inout) :: err
    integer(hsize_t) :: dims(1), maxdims(1)
    integer(hid_t) :: space
    integer :: hdferr, rank
    dset = -1
    fspace = -1
    mspace = -1
    n = 0
    steps: block
      call h5dopen_f(loc, path, dset, hdferr)
      if (hdferr /= 0) exit steps
      call h5dget_space_f(dset, space, hdferr)
      if (hdferr /= 0) exit steps
      call h5sget_dims(space, dims, maxdims, rank)
      call h5sclose_f(space, hdferr)
      if (rank /= 1 .or. hdferr /= 0) exit steps
      n = dims(1)
      call h5dset_extent_f(dset, [n + 1], hdferr)
      if (hdferr /= 0) exit steps
      call h5dget_space_f(dset, fspace, hdferr)
      if (hdferr /= 0) exit steps
      call h5sselect_hyperslab_f(fspace, H5S_SELECT_SET_F, [n], [1_hsize_t], hdferr)
      if (hdferr /= 0) exit steps
      call h5screate_simple_f(1, [1_hsize_t], mspace, hdferr)
      if (hdferr /= 0) exit steps
      return
    end block steps
    if (fspace /= -1) call h5sclose_f(fspace, hdferr)
    if (dset /= -1) call h5dclose_f(dset, hdferr)
    call raise_error(err, EXIT_IO, 'cannot extend dataset "' // path // '" in ' // where)
  end subroutine open_for_append

  subroutine close_after_append(dset, fspace, mspace, write_status, path, where, err)
    integer(hid_t), intent(in) :: dset, fspace, mspace
    integer, intent(in) :: write_status
    character(len=*), intent(in) :: path, where
    type(error_t), intent(inout) :: err
    integer :: e1, e2, e3
    call h5sclose_f(mspace, e1)
    call h5sclose_f(fspace, e2)
    call h5dclose_f(dset, e3)
    if (write_status /= 0 .or. e1 /= 0 .or. e2 /= 0 .or. e3 /= 0) &
      call raise_error(err, EXIT_IO, 'cannot append to dataset "' // path // '" in ' // where)
  end subroutine close_after_append

  !> Dimensions of a simple dataspace (rank 1 expected; -1 on failure).
  subroutine h5sget_dims(space, dims, maxdims, rank)
    use hdf5, only: h5sget_simple_extent_ndims_f, h5sget_simple_extent_dims_f
    integer(hid_t), intent(in) :: space
    integer(hsize_t), intent(out) :: dims(1), maxdims(1)
    integer, intent(out) :: rank
    integer :: hdferr
    dims = 0
    maxdims = 0
    call h5sget_simple_extent_ndims_f(space, rank, hdferr)
    if (hdferr /= 0 .or. rank /= 1) then
      rank = -1
      return
    end if
    call h5sget_simple_extent_dims_f(space, dims, maxdims, hdferr)
    if (hdferr < 0) rank = -1
  end subroutine h5sget_dims

  !> Fixed-length, null-padded string type of n characters (at least 1:
  !> HDF5 has no zero-length fixed strings).
  subroutine string_type(n, stype, hdferr)
    integer, intent(in) :: n
    integer(hid_t), intent(out) :: stype
    integer, intent(out) :: hdferr
    call h5tcopy_f(H5T_NATIVE_CHARACTER, stype, hdferr)
    if (hdferr /= 0) return
    call h5tset_size_f(stype, int(max(1, n), size_t), hdferr)
    if (hdferr /= 0) return
    call h5tset_strpad_f(stype, H5T_STR_NULLPAD_F, hdferr)
  end subroutine string_type

  !> The text itself, or one NUL for the empty text (see string_type).
  pure function padded(text) result(s)
    character(len=*), intent(in) :: text
    character(len=:), allocatable :: s
    if (len(text) == 0) then
      s = achar(0)
    else
      s = text
    end if
  end function padded

  pure function int_text(n) result(s)
    integer, intent(in) :: n
    character(len=16) :: s
    write(s, '(i0)') n
  end function int_text
end module raccord_h5
