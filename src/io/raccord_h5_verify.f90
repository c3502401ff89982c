!> Read back every group and dataset under an HDF5 location, so that the
!> library checks what it protects: the metadata checksums of the file
!> format raccord writes (h5_create_file) and the Fletcher32 checksum of
!> each dataset chunk. A restart runs it on the results file it continues
!> and raccord --verify on any raccord file (issue #18: a damaged .h5.part
!> was continued into results that differed from an uninterrupted run).
module raccord_h5_verify
  use, intrinsic :: iso_c_binding, only: c_loc, c_int8_t, c_ptr
  use hdf5, only: hid_t, hsize_t, size_t, h5gn_members_f, h5gget_obj_info_idx_f, h5dopen_f, h5dclose_f, &
    h5dget_type_f, h5dget_space_f, h5dread_f, h5tget_size_f, h5tclose_f, h5sclose_f, &
    h5aexists_f, H5G_GROUP_F, H5G_DATASET_F, &
    h5sget_simple_extent_ndims_f, h5sget_simple_extent_dims_f, h5sselect_hyperslab_f, h5screate_simple_f, &
    H5S_SELECT_SET_F
  use raccord_crc32, only: crc32_t, crc_add, crc_value, crc_hex
  use raccord_h5_read, only: h5_read_attr_text
  use raccord_kinds, only: i8
  use raccord_error, only: error_t, raise_error, EXIT_INPUT
  use raccord_strings, only: str
  implicit none
  private

  !> Longest object name taken from a group listing.
  integer, parameter :: NAME_LEN = 256
  !> Deepest group nesting walked (raccord's files are a few levels deep).
  integer, parameter :: MAX_DEPTH = 16
  !> Largest read of one dataset at once (bytes); larger ones go by slabs.
  integer(i8), parameter :: SLAB_BYTES = 16_i8*1024_i8*1024_i8
  !> Highest dataset rank read by slabs (raccord writes rank 1 and 2).
  integer, parameter :: MAX_RANK = 8

  public :: h5_verify_tree, h5_read_raw

contains

  !> Walk the group `group` (e.g. '/') of the open file or group loc and
  !> read every dataset in it; the first object that fails raises
  !> EXIT_INPUT naming it and `where`. Returns the number of datasets read.
  recursive subroutine h5_verify_tree(loc, group, where, ndata, err, depth)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: group, where
    integer, intent(inout) :: ndata
    type(error_t), intent(inout) :: err
    integer, intent(in), optional :: depth
    integer :: nmembers, k, obj_type, hdferr, level
    character(len=NAME_LEN) :: name
    character(len=:), allocatable :: path
    level = 0
    if (present(depth)) level = depth
    if (err%failed()) return
    if (level > MAX_DEPTH) then
      call raise_error(err, EXIT_INPUT, where // ' is damaged: groups nested deeper than ' // &
        'raccord writes them under ' // group)
      return
    end if
    call h5gn_members_f(loc, group, nmembers, hdferr)
    if (hdferr /= 0) then
      call raise_error(err, EXIT_INPUT, where // ' is damaged: the group ' // group // ' cannot be listed')
      return
    end if
    do k = 0, nmembers - 1
      call h5gget_obj_info_idx_f(loc, group, k, name, obj_type, hdferr)
      if (hdferr /= 0) then
        call raise_error(err, EXIT_INPUT, where // ' is damaged: member ' // str(k) // ' of the group ' // &
          group // ' cannot be read')
        return
      end if
      if (group == '/') then
        path = '/' // trim(name)
      else
        path = group // '/' // trim(name)
      end if
      if (obj_type == H5G_GROUP_F) then
        call h5_verify_tree(loc, path, where, ndata, err, level + 1)
      else if (obj_type == H5G_DATASET_F) then
        call read_dataset(loc, path, where, err)
        ndata = ndata + 1
      end if
      if (err%failed()) return
    end do
  end subroutine h5_verify_tree

  !> Read a whole dataset in its file type (no conversion): a checksum
  !> failure, or a damaged layout, makes the read fail. A large array (the
  !> history of a long run) is read in slabs of its slowest dimension, so
  !> the memory of a check does not grow with the file.
  subroutine read_dataset(loc, path, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    type(error_t), intent(inout) :: err
    integer(c_int8_t), allocatable :: bytes(:)
    logical :: ok, large
    call read_in_slabs(loc, path, large, ok)
    if (.not. large) call h5_read_raw(loc, path, bytes, ok)
    if (.not. ok) call raise_error(err, EXIT_INPUT, where // ' is damaged: the dataset ' // path // &
      ' cannot be read back (checksum or layout error)')
  end subroutine read_dataset

  !> Read a dataset of more than SLAB_BYTES bytes slab by slab (large =
  !> .true., ok = every read worked); a smaller one is left to h5_read_raw
  !> (large = .false.).
  subroutine read_in_slabs(loc, path, large, ok)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path
    logical, intent(out) :: large, ok
    integer(hid_t) :: dset, dtype, fspace, mspace
    integer(size_t) :: tsize
    integer(hsize_t) :: dims(MAX_RANK), maxdims(MAX_RANK), offset(MAX_RANK), count(MAX_RANK), start, n
    integer(i8) :: row_bytes, rows
    integer(c_int8_t), allocatable, target :: buf(:)
    type(c_ptr) :: ptr
    integer :: hdferr, cerr, rank, stat
    large = .false.
    ok = .false.
    call h5dopen_f(loc, path, dset, hdferr)
    if (hdferr /= 0) return
    dtype = -1
    fspace = -1
    steps: block
      call h5dget_type_f(dset, dtype, hdferr)
      if (hdferr /= 0) exit steps
      call h5tget_size_f(dtype, tsize, hdferr)
      if (hdferr /= 0 .or. tsize <= 0) exit steps
      call h5dget_space_f(dset, fspace, hdferr)
      if (hdferr /= 0) exit steps
      call h5sget_simple_extent_ndims_f(fspace, rank, hdferr)
      if (hdferr /= 0 .or. rank < 1 .or. rank > MAX_RANK) exit steps
      call h5sget_simple_extent_dims_f(fspace, dims(1:rank), maxdims(1:rank), hdferr)
      if (hdferr < 0) exit steps
      ! Fortran order: dims(rank) is the slowest dimension (h5dump's first)
      row_bytes = int(tsize, i8)
      if (rank > 1) row_bytes = row_bytes*int(product(dims(1:rank-1)), i8)
      if (row_bytes > SLAB_BYTES .or. row_bytes*int(dims(rank), i8) <= SLAB_BYTES) exit steps
      large = .true.
      rows = SLAB_BYTES/row_bytes
      allocate(buf(rows*row_bytes), stat=stat)
      if (stat /= 0) exit steps
      offset = 0
      count(1:rank) = dims(1:rank)
      start = 0
      do while (start < dims(rank))
        n = min(int(rows, hsize_t), dims(rank) - start)
        offset(rank) = start
        count(rank) = n
        call h5sselect_hyperslab_f(fspace, H5S_SELECT_SET_F, offset(1:rank), count(1:rank), hdferr)
        if (hdferr /= 0) exit steps
        call h5screate_simple_f(rank, count(1:rank), mspace, hdferr)
        if (hdferr /= 0) exit steps
        ptr = c_loc(buf)
        call h5dread_f(dset, dtype, ptr, hdferr, mem_space_id=mspace, file_space_id=fspace)
        call h5sclose_f(mspace, cerr)
        if (hdferr /= 0) exit steps
        start = start + n
      end do
      ok = .true.
    end block steps
    if (fspace /= -1) call h5sclose_f(fspace, cerr)
    if (dtype /= -1) call h5tclose_f(dtype, cerr)
    call h5dclose_f(dset, cerr)
  end subroutine read_in_slabs

  !> The stored bytes of a whole dataset (file type, no conversion), with
  !> the library's checksums checked and, for a text, its crc32 attribute.
  !> ok is false when anything fails (bytes then unallocated or partial).
  subroutine h5_read_raw(loc, path, bytes, ok)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path
    integer(c_int8_t), allocatable, target, intent(out) :: bytes(:)
    logical, intent(out) :: ok
    integer(hid_t) :: dset, dtype, space
    integer(size_t) :: tsize
    integer(hsize_t) :: npoints
    type(c_ptr) :: ptr
    integer :: hdferr, cerr, stat
    integer(i8), parameter :: max_bytes = 2_i8**34
    ok = .false.
    call h5dopen_f(loc, path, dset, hdferr)
    if (hdferr /= 0) return
    steps: block
      call h5dget_type_f(dset, dtype, hdferr)
      if (hdferr /= 0) exit steps
      call h5tget_size_f(dtype, tsize, hdferr)
      if (hdferr /= 0) then
        call h5tclose_f(dtype, cerr)
        exit steps
      end if
      call h5dget_space_f(dset, space, hdferr)
      if (hdferr == 0) then
        call dataspace_points(space, npoints, hdferr)
        call h5sclose_f(space, cerr)
      end if
      ! the sizes come from the file: checked before they size a buffer
      if (hdferr /= 0 .or. npoints < 0 .or. tsize <= 0 .or. &
          int(npoints, i8) > max_bytes/max(1_i8, int(tsize, i8))) then
        call h5tclose_f(dtype, cerr)
        exit steps
      end if
      allocate(bytes(int(npoints, i8)*int(tsize, i8)), stat=stat)
      if (stat /= 0) then
        call h5tclose_f(dtype, cerr)
        exit steps
      end if
      if (npoints > 0) then
        ptr = c_loc(bytes)
        call h5dread_f(dset, dtype, ptr, hdferr)
      end if
      call h5tclose_f(dtype, cerr)
      ok = hdferr == 0
      if (ok) call check_text_crc(dset, bytes, ok)
    end block steps
    call h5dclose_f(dset, cerr)
  end subroutine h5_read_raw

  !> Number of points of a dataspace: 1 for a scalar, the product of the
  !> dims otherwise, 0 for an empty growing dataset (which
  !> h5sget_simple_extent_npoints_f reports as a failure: a results file
  !> without frames, or an empty history, was taken for damaged).
  subroutine dataspace_points(space, npoints, hdferr)
    integer(hid_t), intent(in) :: space
    integer(hsize_t), intent(out) :: npoints
    integer, intent(out) :: hdferr
    integer(hsize_t) :: dims(MAX_RANK), maxdims(MAX_RANK)
    integer :: rank, k
    npoints = 0
    call h5sget_simple_extent_ndims_f(space, rank, hdferr)
    if (hdferr /= 0 .or. rank < 0 .or. rank > MAX_RANK) then
      hdferr = -1
      return
    end if
    if (rank == 0) then
      npoints = 1
      return
    end if
    call h5sget_simple_extent_dims_f(space, dims(1:rank), maxdims(1:rank), hdferr)
    if (hdferr < 0) return
    hdferr = 0
    ! the dims come from the file: a product past 2**62 is refused, not wrapped
    npoints = 1
    do k = 1, rank
      if (dims(k) > 0 .and. npoints > huge(npoints)/4/dims(k)) then
        hdferr = -1
        return
      end if
      npoints = npoints*dims(k)
    end do
  end subroutine dataspace_points

  !> A text dataset carries its CRC-32 as the attribute crc32
  !> (h5_write_text): the bytes read must have it.
  subroutine check_text_crc(dset, bytes, ok)
    integer(hid_t), intent(in) :: dset
    integer(c_int8_t), intent(in) :: bytes(:)
    logical, intent(inout) :: ok
    logical :: there
    integer :: hdferr
    character(len=:), allocatable :: stored
    type(crc32_t) :: crc
    type(error_t) :: aerr
    call h5aexists_f(dset, 'crc32', there, hdferr)
    if (hdferr /= 0) then
      ok = .false.
      return
    end if
    if (.not. there) return
    call h5_read_attr_text(dset, 'crc32', stored, 'the dataset', aerr)
    if (aerr%failed()) then
      ok = .false.
      return
    end if
    call crc_add(crc, bytes)
    ok = stored == crc_hex(crc_value(crc))
  end subroutine check_text_crc
end module raccord_h5_verify
