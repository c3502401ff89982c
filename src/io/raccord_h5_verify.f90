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
    h5sget_simple_extent_npoints_f, h5aexists_f, H5G_GROUP_F, H5G_DATASET_F
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
  !> failure, or a damaged layout, makes the read fail.
  subroutine read_dataset(loc, path, where, err)
    integer(hid_t), intent(in) :: loc
    character(len=*), intent(in) :: path, where
    type(error_t), intent(inout) :: err
    integer(c_int8_t), allocatable :: bytes(:)
    logical :: ok
    call h5_read_raw(loc, path, bytes, ok)
    if (.not. ok) call raise_error(err, EXIT_INPUT, where // ' is damaged: the dataset ' // path // &
      ' cannot be read back (checksum or layout error)')
  end subroutine read_dataset

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
        call h5sget_simple_extent_npoints_f(space, npoints, hdferr)
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
