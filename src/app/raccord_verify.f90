!> raccord --verify FILE: check a results file (.h5, .h5.part) or a
!> checkpoint (.checkpoint.h5) without running anything.
!>
!> Every dataset is read back (raccord_h5_verify: HDF5's metadata checksums,
!> Fletcher32 on each array, the crc32 attribute of each text). For a
!> checkpoint, its own CRC-32 (/crc32, raccord_checkpoint) is recomputed
!> from the stored bytes of the datasets it covers, in the order it was
!> written, and the running text files beside it (<stem>.history.txt.part,
!> <stem>.contact<k>.txt.part) are checked against /output/file_crc. The
!> file is opened read-only and never changed.
module raccord_verify
  use, intrinsic :: iso_c_binding, only: c_int8_t
  use hdf5, only: hid_t, h5fclose_f
  use raccord_kinds, only: i8
  use raccord_error, only: error_t, raise_error, EXIT_INPUT
  use raccord_strings, only: str
  use raccord_crc32, only: crc32_t, crc_add, crc_value
  use raccord_files, only: file_exists, crc_of_file
  use raccord_h5, only: h5_release, h5_link_exists
  use raccord_h5_read, only: h5_read_attr_text, h5_read_attr_int, h5_open_input
  use raccord_checkpoint, only: CHECKPOINT_FORMAT_VERSION
  use raccord_h5_verify, only: h5_verify_tree, h5_read_raw
  implicit none
  private

  public :: verify_file

contains

  !> Verify the file at path; report says what was checked (on success).
  subroutine verify_file(path, report, err)
    character(len=*), intent(in) :: path
    character(len=:), allocatable, intent(out) :: report
    type(error_t), intent(inout) :: err
    integer(hid_t) :: file
    integer :: hdferr, ndata, version
    character(len=:), allocatable :: where, fmt, extra
    type(error_t) :: cerr
    report = ''
    where = 'file "' // path // '"'
    call h5_open_input(path, where, 'give a raccord .h5 or .checkpoint.h5 file', ', or still marked open ' // &
      'for writing (a run is writing it, or was killed: raccord --restart clears the mark of its results file)', &
      file, err)
    if (err%failed()) return
    call h5_read_attr_text(file, 'format', fmt, where, err)
    if (err%failed()) then
      call err%clear()
      fmt = '(no format attribute)'
    end if
    ndata = 0
    call h5_verify_tree(file, '/', where, ndata, err)
    extra = ''
    if (.not. err%failed() .and. fmt == 'raccord checkpoint') then
      ! the checksum covers the datasets of this layout only
      call h5_read_attr_int(file, 'format_version', version, where, err)
      if (.not. err%failed() .and. version /= CHECKPOINT_FORMAT_VERSION) call raise_error(err, EXIT_INPUT, &
        where // ' reads back, but it is a checkpoint of format version ' // str(version) // ', this raccord ' // &
        'writes and reads version ' // str(CHECKPOINT_FORMAT_VERSION))
      if (.not. err%failed()) call verify_checkpoint_crc(file, path, extra, err)
    end if
    call h5fclose_f(file, hdferr)
    call h5_release(cerr)
    if (err%failed()) return
    if (fmt /= 'raccord results' .and. fmt /= 'raccord checkpoint') then
      call raise_error(err, EXIT_INPUT, where // ' reads back, but it is not a raccord file (format ' // fmt // ')')
      return
    end if
    report = path // ': ' // fmt // ', intact: ' // str(ndata) // ' datasets read back, checksums match' // extra
  end subroutine verify_file

  !> The checkpoint's /crc32 against its datasets, and /output/file_crc
  !> against the running text files beside it.
  subroutine verify_checkpoint_crc(file, path, extra, err)
    integer(hid_t), intent(in) :: file
    character(len=*), intent(in) :: path
    character(len=:), allocatable, intent(inout) :: extra
    type(error_t), intent(inout) :: err
    character(len=*), parameter :: suffix = '.checkpoint.h5'
    type(crc32_t) :: c
    integer(c_int8_t), allocatable :: bytes(:)
    integer(i8), allocatable :: file_crc(:), counters(:)
    integer(i8) :: stored(1), now
    integer :: k, npair
    character(len=:), allocatable :: g, stem, name
    logical :: ok
    npair = 0
    do while (h5_link_exists(file, '/contact/pair_' // str(npair + 1)))
      npair = npair + 1
    end do
    call add(c, '/scene')
    call add(c, '/scene_path')
    call add(c, '/state/counters')
    call add(c, '/state/time_dt')
    call add(c, '/state/u')
    call add(c, '/state/u_prev')
    call add(c, '/state/v')
    call add(c, '/state/energy')
    do k = 1, npair
      g = '/contact/pair_' // str(k) // '/'
      call add(c, g // 'status')
      call add(c, g // 'sigma')
      call add(c, g // 'counters')
      call add(c, g // 'residual_max')
      call add(c, g // 'profile_bytes')
    end do
    call add(c, '/output/counters')
    call add(c, '/output/file_crc')
    if (err%failed()) return
    call raw_i8('/crc32', stored, 1)
    if (err%failed()) return
    now = crc_value(c)
    if (now /= stored(1)) then
      call raise_error(err, EXIT_INPUT, '"' // path // '" is damaged: its CRC-32 is ' // str(now) // &
        ', it was written with ' // str(stored(1)))
      return
    end if
    ! The running text files, when the stopped run's .part files are there.
    allocate(file_crc(1 + npair), counters(4))
    call raw_i8('/output/file_crc', file_crc, 1 + npair)
    call raw_i8('/output/counters', counters, 4)
    if (err%failed()) return
    stem = path
    if (len(path) > len(suffix)) stem = path(1:len(path) - len(suffix))
    do k = 0, npair
      if (k == 0) then
        name = stem // '.history.txt.part'
        now = crc_of_file(name, counters(3))
      else
        name = stem // '.contact' // str(k) // '.txt.part'
        call raw_i8('/contact/pair_' // str(k) // '/profile_bytes', stored, 1)
        if (err%failed()) return
        now = crc_of_file(name, stored(1))
      end if
      if (.not. file_exists(name)) then
        extra = extra // '; ' // name // ' is missing (a restart needs it)'
      else if (now /= file_crc(1 + k)) then
        call raise_error(err, EXIT_INPUT, name // ' is damaged or shorter than ' // path // ' recorded')
        return
      else
        extra = extra // '; ' // name // ' matches'
      end if
    end do
  contains
    subroutine add(crc, dset)
      type(crc32_t), intent(inout) :: crc
      character(len=*), intent(in) :: dset
      if (err%failed()) return
      call h5_read_raw(file, dset, bytes, ok)
      if (.not. ok) then
        call raise_error(err, EXIT_INPUT, '"' // path // '" is damaged or incomplete: ' // dset // &
          ' cannot be read')
        return
      end if
      call crc_add(crc, bytes)
    end subroutine add
    subroutine raw_i8(dset, values, n)
      character(len=*), intent(in) :: dset
      integer, intent(in) :: n
      integer(i8), intent(out) :: values(n)
      values = 0
      if (err%failed()) return
      call h5_read_raw(file, dset, bytes, ok)
      if (ok) ok = size(bytes) == 8*n
      if (.not. ok) then
        call raise_error(err, EXIT_INPUT, '"' // path // '" is damaged or incomplete: ' // dset // &
          ' cannot be read as ' // str(n) // ' 64-bit integers')
        return
      end if
      values = transfer(bytes, values)
    end subroutine raw_i8
  end subroutine verify_checkpoint_crc
end module raccord_verify
