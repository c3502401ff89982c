!> Contact surfaces in a results file: each one a grid of line elements on
!> its nodes, with per frame its deformed coordinates and its per-node
!> values (doc/output-format.md, "Contact surfaces"). The datasets live
!> under the surface's own group, <base>/<prefix>connectivity once and
!> <base>/frame_NNNNNN/<prefix>xy and <field> per frame; the XDMF
!> references them (raccord_xdmf).
submodule (raccord_results) raccord_results_surface
  implicit none

contains

  !> Add a surface named `name` (its grid's name in the XDMF):
  !> conn(nen, nseg) its segments as 1-based indices into its nnode nodes
  !> (nen 2, or 3: ends then middle), written 0-based to
  !> <base>/<prefix>connectivity unless a resumed file has it already;
  !> fields(:) the scalar values each frame gives. Before the first frame
  !> after results_write_mesh, or after results_resume.
  module subroutine results_add_surface(res, name, base, prefix, conn, nnode, fields, err)
    type(results_t), intent(inout) :: res
    character(len=*), intent(in) :: name, base, prefix
    integer, intent(in) :: conn(:,:)
    integer, intent(in) :: nnode
    character(len=*), intent(in) :: fields(:)
    type(error_t), intent(inout) :: err
    type(xdmf_surface_t), allocatable :: grown(:)
    type(xdmf_surface_t) :: s
    integer :: k
    if (.not. usable(res, 'results_add_surface', err)) return
    if (res%in_frame) then
      call raise_error(err, EXIT_INTERNAL, 'results_add_surface: surface "' // name // '" added inside a frame')
      return
    end if
    if (size(conn, 1) /= 2 .and. size(conn, 1) /= 3) then
      call raise_error(err, EXIT_INTERNAL, 'results_add_surface: surface "' // name // '" has ' // &
        str(size(conn, 1)) // ' nodes per segment, expected 2 or 3')
      return
    end if
    if (size(conn) > 0) then
      if (minval(conn) < 1 .or. maxval(conn) > nnode) then
        call raise_error(err, EXIT_INTERNAL, 'results_add_surface: surface "' // name // &
          '" refers to nodes outside 1..' // str(nnode))
        return
      end if
    end if
    do k = 1, size(fields)
      call check_name(fields(k), 'surface field', err)
    end do
    if (err%failed()) return
    s%name = trim(name)
    s%frame_base = absolute(base)
    s%conn_path = s%frame_base // '/' // trim(prefix) // 'connectivity'
    s%geometry = trim(prefix) // 'xy'
    allocate(s%fields(size(fields)))
    s%fields = fields
    s%nen = size(conn, 1)
    s%nseg = size(conn, 2)
    s%nnode = nnode
    if (.not. h5_link_exists(res%file, s%conn_path)) then
      call h5_write_int(res%file, s%conn_path, conn - 1, res%where, err)
      if (err%failed()) return
    end if
    allocate(grown(size(res%surfaces) + 1))
    do k = 1, size(res%surfaces)
      grown(k) = res%surfaces(k)
    end do
    grown(size(grown)) = s
    call move_alloc(grown, res%surfaces)
  end subroutine results_add_surface

  !> Write surface isurf's deformed coordinates xy(2, nnode) and values
  !> values(nnode, nfield) (one column per field given to results_add_surface)
  !> in the current frame. Surfaces come in the order they were added.
  module subroutine results_write_surface_frame(res, isurf, xy, values, err)
    type(results_t), intent(inout) :: res
    integer, intent(in) :: isurf
    real(wp), intent(in) :: xy(:,:), values(:,:)
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: group
    integer :: k
    if (.not. usable(res, 'results_write_surface_frame', err)) return
    if (.not. res%in_frame) then
      call raise_error(err, EXIT_INTERNAL, 'results_write_surface_frame: called outside a frame')
      return
    end if
    if (isurf /= res%frames(res%nframe)%nsurf + 1 .or. isurf > size(res%surfaces)) then
      call raise_error(err, EXIT_INTERNAL, 'results_write_surface_frame: surface ' // str(isurf) // &
        ' written out of order (' // str(res%frames(res%nframe)%nsurf) // ' done, ' // &
        str(size(res%surfaces)) // ' added)')
      return
    end if
    associate (s => res%surfaces(isurf))
      if (size(xy, 1) /= 2 .or. size(xy, 2) /= s%nnode .or. size(values, 2) /= size(s%fields) .or. &
        size(values, 1) /= s%nnode) then
        call raise_error(err, EXIT_INTERNAL, 'results_write_surface_frame: surface "' // s%name // &
          '" expects xy(2, ' // str(s%nnode) // ') and values(' // str(s%nnode) // ', ' // &
          str(size(s%fields)) // ')')
        return
      end if
      group = s%frame_base // '/frame_' // frame_label(res%nframe - 1) // '/'
      call h5_write_real(res%file, group // s%geometry, xy, res%where, err)
      do k = 1, size(s%fields)
        call h5_write_real(res%file, group // trim(s%fields(k)), values(:, k), res%where, err)
      end do
    end associate
    if (err%failed()) return
    res%frames(res%nframe)%nsurf = isurf
  end subroutine results_write_surface_frame
end submodule raccord_results_surface
