!> Closing a results file: final /status, the XDMF files, and the renames
!> that say whether the run completed (doc/output-format.md, "File names").
submodule (raccord_results) raccord_results_close
  implicit none

contains

  !> Finish the file. complete = .true.: /status = 'complete', write the
  !> XDMF, close, rename to stem.h5 and stem.xmf. complete = .false. (or any
  !> failure while closing): /status = 'incomplete: ' // reason and the
  !> names stem.incomplete.h5 / stem.incomplete.xmf. A frame still open is
  !> ended first. Closing a results_t that is not open does nothing, so
  !> error paths may always call it.
  module subroutine results_close(res, complete, err, reason)
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
        call delete_file(res%stem // '.meshio.xmf.part')
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
    if (have_xmf) call rename_file(res%stem // '.meshio.xmf.part', xmf_final(1:len(xmf_final) - 4) // '.meshio.xmf', cerr)
    if (cerr%failed()) then
      call prefix_error(cerr, 'while closing ' // res%where)
      call raise_error(err, cerr%code, cerr%message)
    end if
    res = results_t()
  end subroutine results_close

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
    call write_xdmf(xmf_part, h5_name, max(res%nnode, 0), res%blocks, res%surfaces, res%frames, res%nframe, werr)
    if (.not. werr%failed()) call write_meshio_index(res%stem // '.meshio.xmf.part', h5_name, max(res%nnode, 0), &
      res%blocks, res%frames, res%nframe, werr)
    written = .not. werr%failed()
    if (.not. written) then
      call delete_file(xmf_part)
      call delete_file(res%stem // '.meshio.xmf.part')
      call raise_error(err, werr%code, werr%message)
    end if
  end subroutine write_light_data

end submodule raccord_results_close
