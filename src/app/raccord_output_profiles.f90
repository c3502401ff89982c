!> The contact profile text files, one per contact pair,
!> <stem>.contact<k>.txt (doc/output-format.md): opened under .part names
!> with their header, and given their final (or .incomplete) names at the end.
module raccord_output_profiles
  use raccord_error, only: error_t, raise_error, EXIT_IO
  use raccord_strings, only: str
  use raccord_contact_pair, only: contact_pair_t
  use raccord_files, only: rename_file
  use raccord_output_state, only: output_t
  implicit none
  private

  public :: open_profiles, close_profiles, profile_name

contains

  !> One text file per contact pair, <stem>.contact<k>.txt: a block per
  !> frame (gnuplot `index`), a line per slave node.
  subroutine open_profiles(out, pairs, err)
    type(output_t), intent(inout) :: out
    type(contact_pair_t), intent(in) :: pairs(:)
    type(error_t), intent(inout) :: err
    integer :: k, ios
    character(len=256) :: msg
    allocate(out%profile_unit(size(pairs)))
    do k = 1, size(pairs)
      open(newunit=out%profile_unit(k), file=profile_name(out, k) // '.part', status='replace', &
        action='write', iostat=ios, iomsg=msg)
      if (ios /= 0) then
        call raise_error(err, EXIT_IO, 'cannot write ' // profile_name(out, k) // '.part: ' // trim(msg))
        return
      end if
      write(out%profile_unit(k), '(a)') '# raccord contact profile, pair ' // str(k) // ': slave ' // &
        pairs(k)%slave%name // ', master ' // pairs(k)%master%name
      write(out%profile_unit(k), '(a)') '# one block per frame (gnuplot: index k); stresses = weighted ' // &
        'multiplier / tributary length, pressure positive in compression'
      write(out%profile_unit(k), '(a)') '# columns: 1 s0 (reference arc length)  2 x  3 y  4 gap  ' // &
        '5 pressure  6 shear  7 status (0 open, 1 stick, 2 slip)  8 slip_increment  9 lambda_n  10 lambda_t'
    end do
  end subroutine open_profiles

  function profile_name(out, k) result(path)
    type(output_t), intent(in) :: out
    integer, intent(in) :: k
    character(len=:), allocatable :: path
    path = out%stem // '.contact' // str(k) // '.txt'
  end function profile_name

  !> Close the profile files: final name when complete, *.incomplete.txt otherwise.
  subroutine close_profiles(out, complete, err)
    type(output_t), intent(inout) :: out
    logical, intent(in) :: complete
    type(error_t), intent(inout) :: err
    integer :: k
    character(len=:), allocatable :: final
    if (.not. allocated(out%profile_unit)) return
    do k = 1, size(out%profile_unit)
      close(out%profile_unit(k))
      final = profile_name(out, k)
      if (.not. complete) final = out%stem // '.contact' // str(k) // '.incomplete.txt'
      call rename_file(profile_name(out, k) // '.part', final, err)
    end do
  end subroutine close_profiles
end module raccord_output_profiles
