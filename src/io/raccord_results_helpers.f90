!> Small checks and names shared by raccord_results and its submodules
!> (separate module procedures, so that every submodule links to one copy).
submodule (raccord_results) raccord_results_helpers
  implicit none

contains

  !> A path made absolute ('a/b' -> '/a/b'), trailing blanks removed.
  module pure function absolute(path) result(s)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: s
    s = trim(adjustl(path))
    if (len(s) == 0) then
      s = '/'
    else if (s(1:1) /= '/') then
      s = '/' // s
    end if
  end function absolute

  !> File part of a path ('out/run' -> 'run').
  module pure function base_name(path) result(s)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: s
    s = path(index(path, '/', back=.true.) + 1:)
  end function base_name

  !> A name becomes one HDF5 link: not empty, no '/'.
  module subroutine check_name(name, what, err)
    character(len=*), intent(in) :: name, what
    type(error_t), intent(inout) :: err
    if (len_trim(name) == 0 .or. index(name, '/') > 0 .or. trim(name) == '.') then
      call raise_error(err, EXIT_INPUT, 'invalid ' // what // ' name "' // trim(name) &
        // '" for the results file: use a non-empty name without "/"')
    end if
  end subroutine check_name

  !> Flush to disk so that a killed run keeps everything written so far.
  module subroutine flush_file(res, what, err)
    type(results_t), intent(in) :: res
    character(len=*), intent(in) :: what
    type(error_t), intent(inout) :: err
    integer :: hdferr
    if (err%failed()) return
    call h5fflush_f(res%file, H5F_SCOPE_GLOBAL_F, hdferr)
    if (hdferr /= 0) call raise_error(err, EXIT_IO, 'cannot flush ' // what // ' to ' // res%where &
      // ' (disk full?)')
  end subroutine flush_file

  !> How a nodal field of ncomp components is stored in frame `frame`
  !> (0-based): path, XDMF kind, stored components.
  module pure function nodal_field(name, ncomp, frame) result(field)
    character(len=*), intent(in) :: name
    integer, intent(in) :: ncomp, frame
    type(xdmf_field_t) :: field
    field%name = trim(name)
    field%path = '/frames/' // frame_label(frame) // '/' // field%name
    select case (ncomp)
    case (1)
      field%kind = 'Scalar'
      field%ncomp = 1
    case (2)
      field%kind = 'Vector'
      field%ncomp = 3
    case default
      ! Matrix: a plain multi-component array; stress (sxx, syy, sxy, szz)
      ! is neither a 3-vector nor a full tensor.
      field%kind = 'Matrix'
      field%ncomp = ncomp
    end select
  end function nodal_field

  !> Record the blocks as the XDMF references them and the node order they
  !> imply (raccord_node_order); sets res%nnode.
  module subroutine set_layout(res, nnode, blocks)
    type(results_t), intent(inout) :: res
    integer, intent(in) :: nnode
    type(result_block_t), intent(in) :: blocks(:)
    integer, allocatable :: start(:), nodes(:), first(:), count(:)
    integer :: b, nb
    nb = size(blocks)
    allocate(start(nb + 1), first(nb), count(nb))
    start(1) = 1
    do b = 1, nb
      start(b + 1) = start(b) + size(blocks(b)%conn)
    end do
    allocate(nodes(start(nb + 1) - 1))
    do b = 1, nb
      nodes(start(b):start(b + 1) - 1) = reshape(blocks(b)%conn, [size(blocks(b)%conn)])
    end do
    if (allocated(res%order)) deallocate(res%order, res%row)
    allocate(res%order(nnode), res%row(nnode))
    call node_order(nnode, start, nodes, res%order, res%row, first, count)
    if (allocated(res%blocks)) deallocate(res%blocks)
    allocate(res%blocks(nb))
    do b = 1, nb
      res%blocks(b)%name = blocks(b)%name
      res%blocks(b)%conn_path = '/mesh/blocks/' // blocks(b)%name // '/connectivity'
      res%blocks(b)%local_path = '/mesh/blocks/' // blocks(b)%name // '/local_connectivity'
      res%blocks(b)%nen = blocks(b)%nen
      res%blocks(b)%nel = size(blocks(b)%conn, 2)
      res%blocks(b)%first = first(b) - 1
      res%blocks(b)%count = count(b)
    end do
    res%nnode = nnode
  end subroutine set_layout

  !> True when the results file is open; otherwise an error naming the caller.
  module logical function usable(res, caller, err)
    type(results_t), intent(in) :: res
    character(len=*), intent(in) :: caller
    type(error_t), intent(inout) :: err
    usable = .false.
    if (err%failed()) return
    if (.not. res%is_open) then
      call raise_error(err, EXIT_INTERNAL, caller // ': the results file is not open (call results_open)')
      return
    end if
    usable = .true.
  end function usable
end submodule raccord_results_helpers
