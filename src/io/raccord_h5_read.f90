!> Error-checked HDF5 reading (the checkpoint and a resumed results file),
!> and 64-bit integer datasets. Companion of raccord_h5 (writing).
!>
!> A read names the file (`where`) and the dataset in its message, and
!> checks the stored shape against the one the caller expects, so a file
!> of another run or a damaged one gives a message instead of garbage.
!> Missing or unreadable objects are EXIT_INPUT: what is read is an input
!> of the run (the checkpoint); the caller may re-raise with its own code.
module raccord_h5_read
  use, intrinsic :: iso_c_binding, only: c_loc, c_ptr
  use, intrinsic :: iso_fortran_env, only: int64
  use hdf5, only: hid_t, hsize_t, size_t, h5fopen_f, H5F_ACC_RDONLY_F, h5dopen_f, h5dclose_f, h5dread_f, &
    h5dwrite_f, h5dget_space_f, &
    h5dget_type_f, h5sclose_f, h5sget_simple_extent_ndims_f, h5sget_simple_extent_dims_f, &
    h5tget_size_f, h5tclose_f, h5tcopy_f, h5tset_size_f, h5tset_strpad_f, h5aopen_f, h5aread_f, h5aclose_f, &
    h5aget_type_f, h5screate_simple_f, h5dcreate_f, h5kind_to_type, &
    H5T_NATIVE_DOUBLE, H5T_NATIVE_INTEGER, H5T_NATIVE_CHARACTER, H5T_STR_NULLPAD_F, H5_INTEGER_KIND
  use raccord_kinds, only: wp, i8
  use raccord_error, only: error_t, raise_error, EXIT_INPUT, EXIT_IO
  use raccord_h5, only: h5_link_exists, h5_ensure_groups, h5_acquire, h5_release
  use raccord_files, only: file_exists, is_directory, broken_link, relative_note
  implicit none
  private

  public :: h5_read_real, h5_read_int, h5_read_i8, h5_read_text, h5_read_attr_text, h5_read_attr_int, h5_write_i8, &
    h5_dims, h5_open_input

  !> Longest text attribute read (raccord writes a few dozen characters).
  integer(size_t), parameter :: MAX_ATTR_TEXT = 65536
  !> Longest text dataset read (the echoed scene: kilobytes, a few MB with
  !> long amplitude tables).
  integer(size_t), parameter :: MAX_TEXT = 256_size_t*1024_size_t*1024_size_t

  !> Read a real(wp) dataset of rank 1 or 2 into an array of the expected shape.
  interface h5_read_real
    module procedure read_real_1d, read_real_2d
  end interface h5_read_real

contains

  !> Open the HDF5 file an input names (a checkpoint to restart from, a
  !> file to verify) read-only, with the library acquired (h5_acquire):
  !> the caller closes the file and releases the library. A missing file,
  !> a broken link, a folder, an empty file, a pipe or a device (size 0:
  !> HDF5's open would block on a pipe for ever) and a file HDF5 cannot
  !> open are EXIT_INPUT errors
  !> naming `where` (e.g. 'checkpoint "x.checkpoint.h5"'), ending with the
  !> caller's `fix`; `open_note` adds to the cannot-open message why that
  !> may be. On an error, file = -1 and the library is released.
  subroutine h5_open_input(path, where, fix, open_note, file, err)
    character(len=*), intent(in) :: path, where, fix, open_note
    integer(hid_t), intent(out) :: file
    type(error_t), intent(inout) :: err
    integer :: hdferr
    integer(i8) :: nbytes
    type(error_t) :: cerr
    character(len=:), allocatable :: target
    file = -1
    if (err%failed()) return
    if (broken_link(path, target)) then
      call raise_error(err, EXIT_INPUT, where // ' is a broken symbolic link: it points to "' // target // '"' // &
        relative_note(target) // ', which does not exist (or is a loop of links); ' // fix)
      return
    end if
    if (.not. file_exists(path)) then
      call raise_error(err, EXIT_INPUT, 'no ' // where // '; ' // fix)
      return
    end if
    ! a folder has a size, and HDF5 says only that it cannot open it
    if (is_directory(path)) then
      call raise_error(err, EXIT_INPUT, where // ' is a folder, not a file; ' // fix)
      return
    end if
    inquire(file=path, size=nbytes)
    if (nbytes == 0) then
      call raise_error(err, EXIT_INPUT, where // ' is empty (0 bytes), or is a pipe or device: ' // fix)
      return
    end if
    call h5_acquire(err)
    if (err%failed()) return
    call h5fopen_f(path, H5F_ACC_RDONLY_F, file, hdferr)
    if (hdferr /= 0) then
      file = -1
      call raise_error(err, EXIT_INPUT, where // ' cannot be opened as HDF5: not an HDF5 file, or truncated ' // &
        'or damaged' // open_note // '; ' // fix)
      call h5_release(cerr)
    end if
  end subroutine h5_open_input

  !> Dimensions of a dataset in Fortran order (a(m, n) -> [m, n]).
  subroutine h5_dims(loc, path, dims, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    integer(hsize_t), allocatable, intent(out) :: dims(:)
    type(error_t), intent(inout) :: err
    integer(hid_t) :: dset
    allocate(dims(0))
    call open_dataset(loc, path, dset, where, err)
    if (err%failed()) return
    call dataset_dims(dset, dims, path, where, err)
    call close_dataset(dset, path, where, err)
  end subroutine h5_dims

  subroutine read_real_1d(loc, path, values, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    real(wp), intent(inout) :: values(:)
    type(error_t), intent(inout) :: err
    integer(hid_t) :: dset
    integer :: hdferr
    call open_checked(loc, path, shape(values, kind=hsize_t), dset, where, err)
    if (err%failed()) return
    call h5dread_f(dset, H5T_NATIVE_DOUBLE, values, shape(values, kind=hsize_t), hdferr)
    call read_done(dset, hdferr, path, where, err)
  end subroutine read_real_1d

  subroutine read_real_2d(loc, path, values, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    real(wp), intent(inout) :: values(:,:)
    type(error_t), intent(inout) :: err
    integer(hid_t) :: dset
    integer :: hdferr
    call open_checked(loc, path, shape(values, kind=hsize_t), dset, where, err)
    if (err%failed()) return
    call h5dread_f(dset, H5T_NATIVE_DOUBLE, values, shape(values, kind=hsize_t), hdferr)
    call read_done(dset, hdferr, path, where, err)
  end subroutine read_real_2d

  !> Read a default-integer 1D dataset of the expected length.
  subroutine h5_read_int(loc, path, values, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    integer, intent(inout) :: values(:)
    type(error_t), intent(inout) :: err
    integer(hid_t) :: dset
    integer :: hdferr
    call open_checked(loc, path, shape(values, kind=hsize_t), dset, where, err)
    if (err%failed()) return
    call h5dread_f(dset, H5T_NATIVE_INTEGER, values, shape(values, kind=hsize_t), hdferr)
    call read_done(dset, hdferr, path, where, err)
  end subroutine h5_read_int

  !> Read a 64-bit integer 1D dataset of the expected length.
  subroutine h5_read_i8(loc, path, values, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    integer(i8), intent(inout), target :: values(:)
    type(error_t), intent(inout) :: err
    integer(hid_t) :: dset
    integer :: hdferr
    type(c_ptr) :: buf
    call open_checked(loc, path, shape(values, kind=hsize_t), dset, where, err)
    if (err%failed()) return
    buf = c_loc(values)
    call h5dread_f(dset, h5kind_to_type(int64, H5_INTEGER_KIND), buf, hdferr)
    call read_done(dset, hdferr, path, where, err)
  end subroutine h5_read_i8

  !> Write a 64-bit integer 1D dataset (steps and counters of a long run).
  subroutine h5_write_i8(loc, path, values, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    integer(i8), intent(in), target :: values(:)
    type(error_t), intent(inout) :: err
    integer(hid_t) :: space, dset, dtype
    integer :: hdferr, e2
    type(c_ptr) :: buf
    call h5_ensure_groups(loc, path, where, err)
    if (err%failed()) return
    dtype = h5kind_to_type(int64, H5_INTEGER_KIND)
    call h5screate_simple_f(1, shape(values, kind=hsize_t), space, hdferr)
    if (hdferr /= 0) then
      call raise_error(err, EXIT_IO, 'cannot create dataset "' // path // '" in ' // where)
      return
    end if
    call h5dcreate_f(loc, path, dtype, space, dset, hdferr)
    if (hdferr == 0) then
      buf = c_loc(values)
      call h5dwrite_f(dset, dtype, buf, hdferr)
      call h5dclose_f(dset, e2)
      hdferr = max(abs(hdferr), abs(e2))
    end if
    call h5sclose_f(space, e2)
    if (hdferr /= 0 .or. e2 /= 0) call raise_error(err, EXIT_IO, 'cannot write dataset "' // path // '" in ' // where)
  end subroutine h5_write_i8

  !> Read a scalar fixed-length string dataset (as h5_write_text writes it),
  !> NUL padding removed.
  subroutine h5_read_text(loc, path, text, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    character(len=:), allocatable, intent(out) :: text
    type(error_t), intent(inout) :: err
    integer(hid_t) :: dset, ftype, mtype
    integer(size_t) :: n
    integer :: hdferr, e2
    text = ''
    call open_dataset(loc, path, dset, where, err)
    if (err%failed()) return
    call h5dget_type_f(dset, ftype, hdferr)
    if (hdferr == 0) call h5tget_size_f(ftype, n, hdferr)
    if (hdferr == 0) call h5tclose_f(ftype, hdferr)
    ! the length comes from the file: checked before it sizes the text
    if (hdferr == 0 .and. (n < 1 .or. n > MAX_TEXT)) then
      call close_dataset(dset, path, where, err)
      call raise_error(err, EXIT_INPUT, 'the text "' // path // '" in ' // where // ' declares ' // &
        trim(size_text(n)) // ' characters, more than the ' // trim(size_text(MAX_TEXT)) // &
        ' raccord writes: the file is damaged or not raccord''s')
      return
    end if
    if (hdferr == 0) then
      deallocate(text)
      allocate(character(len=int(n)) :: text)
      call h5tcopy_f(H5T_NATIVE_CHARACTER, mtype, hdferr)
      if (hdferr == 0) call h5tset_size_f(mtype, n, hdferr)
      if (hdferr == 0) call h5tset_strpad_f(mtype, H5T_STR_NULLPAD_F, hdferr)
      if (hdferr == 0) then
        call h5dread_f(dset, mtype, text, [1_hsize_t], hdferr)
        call h5tclose_f(mtype, e2)
      end if
    end if
    call read_done(dset, hdferr, path, where, err)
    if (err%failed()) return
    text = strip_nul(text)
  end subroutine h5_read_text

  !> Read a scalar string attribute of an object, NUL padding removed.
  subroutine h5_read_attr_text(obj, name, text, where, err)
    integer(hid_t), intent(in) :: obj
    character(len=*), intent(in) :: name, where
    character(len=:), allocatable, intent(out) :: text
    type(error_t), intent(inout) :: err
    integer(hid_t) :: attr, atype
    integer(size_t) :: n
    integer :: hdferr, e2
    text = ''
    call h5aopen_f(obj, name, attr, hdferr)
    if (hdferr /= 0) then
      call raise_error(err, EXIT_INPUT, 'no attribute "' // name // '" in ' // where)
      return
    end if
    call h5aget_type_f(attr, atype, hdferr)
    if (hdferr == 0) call h5tget_size_f(atype, n, hdferr)
    ! the length comes from the file: raccord's attributes are short texts
    if (hdferr == 0 .and. (n < 1 .or. n > MAX_ATTR_TEXT)) then
      call h5tclose_f(atype, e2)
      hdferr = -1
    end if
    if (hdferr == 0) then
      deallocate(text)
      allocate(character(len=int(n)) :: text)
      call h5aread_f(attr, atype, text, [1_hsize_t], hdferr)
      call h5tclose_f(atype, e2)
    end if
    call h5aclose_f(attr, e2)
    if (hdferr /= 0) then
      call raise_error(err, EXIT_INPUT, 'cannot read attribute "' // name // '" in ' // where)
      return
    end if
    text = strip_nul(text)
  end subroutine h5_read_attr_text

  !> Read a scalar integer attribute of an object.
  subroutine h5_read_attr_int(obj, name, value, where, err)
    integer(hid_t), intent(in) :: obj
    character(len=*), intent(in) :: name, where
    integer, intent(out) :: value
    type(error_t), intent(inout) :: err
    integer(hid_t) :: attr
    integer :: hdferr, e2
    value = 0
    call h5aopen_f(obj, name, attr, hdferr)
    if (hdferr /= 0) then
      call raise_error(err, EXIT_INPUT, 'no attribute "' // name // '" in ' // where)
      return
    end if
    call h5aread_f(attr, H5T_NATIVE_INTEGER, value, [1_hsize_t], hdferr)
    call h5aclose_f(attr, e2)
    if (hdferr /= 0) call raise_error(err, EXIT_INPUT, 'cannot read attribute "' // name // '" in ' // where)
  end subroutine h5_read_attr_int

  ! --- private -----------------------------------------------------------

  subroutine open_dataset(loc, path, dset, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    integer(hid_t), intent(out) :: dset
    type(error_t), intent(inout) :: err
    integer :: hdferr
    dset = -1
    if (err%failed()) return
    if (.not. h5_link_exists(loc, path)) then
      call raise_error(err, EXIT_INPUT, 'dataset "' // path // '" is missing in ' // where)
      return
    end if
    call h5dopen_f(loc, path, dset, hdferr)
    if (hdferr /= 0) then
      dset = -1
      call raise_error(err, EXIT_INPUT, 'cannot open dataset "' // path // '" in ' // where)
    end if
  end subroutine open_dataset

  !> Open a dataset and check that its shape is `expected` (Fortran order).
  subroutine open_checked(loc, path, expected, dset, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    integer(hsize_t), intent(in) :: expected(:)
    integer(hid_t), intent(out) :: dset
    type(error_t), intent(inout) :: err
    integer(hsize_t), allocatable :: dims(:)
    call open_dataset(loc, path, dset, where, err)
    if (err%failed()) return
    call dataset_dims(dset, dims, path, where, err)
    if (.not. err%failed()) then
      if (size(dims) /= size(expected)) then
        call raise_error(err, EXIT_INPUT, 'dataset "' // path // '" in ' // where // ' has rank ' // &
          itext(size(dims)) // ', expected ' // itext(size(expected)))
      else if (any(dims /= expected)) then
        call raise_error(err, EXIT_INPUT, 'dataset "' // path // '" in ' // where // ' has shape (' // &
          shape_text(dims) // '), expected (' // shape_text(expected) // '): written for another model?')
      end if
    end if
    if (err%failed()) call close_dataset(dset, path, where, err)
  end subroutine open_checked

  !> Dimensions of an open dataset, in Fortran order.
  subroutine dataset_dims(dset, dims, path, where, err)
    integer(hid_t), intent(in) :: dset
    integer(hsize_t), allocatable, intent(out) :: dims(:)
    character(len=*), intent(in) :: path, where
    type(error_t), intent(inout) :: err
    integer(hid_t) :: space
    integer(hsize_t), allocatable :: maxdims(:)
    integer :: rank, hdferr, e2
    allocate(dims(0))
    call h5dget_space_f(dset, space, hdferr)
    if (hdferr == 0) then
      call h5sget_simple_extent_ndims_f(space, rank, hdferr)
      if (hdferr == 0 .and. rank >= 0) then
        deallocate(dims)
        allocate(dims(rank), maxdims(rank))
        if (rank > 0) call h5sget_simple_extent_dims_f(space, dims, maxdims, hdferr)
        ! The Fortran API returns dims already in Fortran order.
        if (hdferr > 0) hdferr = 0
      end if
      call h5sclose_f(space, e2)
    end if
    if (hdferr /= 0) call raise_error(err, EXIT_INPUT, 'cannot read the shape of dataset "' // path // '" in ' // where)
  end subroutine dataset_dims

  subroutine read_done(dset, read_status, path, where, err)
    integer(hid_t), intent(in) :: dset
    integer, intent(in) :: read_status
    character(len=*), intent(in) :: path, where
    type(error_t), intent(inout) :: err
    if (read_status /= 0) call raise_error(err, EXIT_INPUT, 'cannot read dataset "' // path // '" in ' // where // &
      ' (damaged file?)')
    call close_dataset(dset, path, where, err)
  end subroutine read_done

  subroutine close_dataset(dset, path, where, err)
    integer(hid_t), intent(in) :: dset
    character(len=*), intent(in) :: path, where
    type(error_t), intent(inout) :: err
    integer :: hdferr
    if (dset == -1) return
    call h5dclose_f(dset, hdferr)
    if (hdferr /= 0) call raise_error(err, EXIT_IO, 'cannot close dataset "' // path // '" in ' // where)
  end subroutine close_dataset

  pure function strip_nul(s) result(t)
    character(len=*), intent(in) :: s
    character(len=:), allocatable :: t
    integer :: k
    k = index(s, achar(0))
    if (k > 0) then
      t = s(1:k-1)
    else
      t = s
    end if
  end function strip_nul

  pure function itext(n) result(s)
    integer, intent(in) :: n
    character(len=:), allocatable :: s
    character(len=16) :: buf
    write(buf, '(i0)') n
    s = trim(buf)
  end function itext

  pure function shape_text(dims) result(s)
    integer(hsize_t), intent(in) :: dims(:)
    character(len=:), allocatable :: s
    character(len=24) :: buf
    integer :: k
    s = ''
    do k = 1, size(dims)
      write(buf, '(i0)') dims(k)
      if (k > 1) s = s // ', '
      s = s // trim(buf)
    end do
  end function shape_text

  pure function size_text(n) result(s)
    integer(size_t), intent(in) :: n
    character(len=24) :: s
    write(s, '(i0)') n
  end function size_text
end module raccord_h5_read
