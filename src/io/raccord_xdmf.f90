!> The XDMF (eXtensible Data Model and Format, version 3) light-data file
!> that lets ParaView read a raccord HDF5 results file.
!>
!> Layout (doc/output-format.md, "XDMF"): a temporal collection with one
!> spatial collection per frame, holding one uniform grid per element
!> block. Every grid shares the node coordinates /mesh/x (GeometryType XY)
!> and the frame's nodal datasets; the heavy data stay in HDF5 and are
!> referenced as "file.h5:/path". Without frames, one spatial collection
!> shows the mesh alone.
module raccord_xdmf
  use raccord_kinds, only: wp
  use raccord_error, only: error_t, raise_error, EXIT_IO
  use raccord_strings, only: str
  implicit none
  private

  public :: write_xdmf, frame_label

  !> One element block as referenced by the XDMF.
  type, public :: xdmf_block_t
    character(len=:), allocatable :: name
    character(len=:), allocatable :: conn_path   !< HDF5 path of the (nel, nen) 0-based connectivity
    integer :: nen = 0
    integer :: nel = 0
  end type xdmf_block_t

  !> One nodal field of a frame.
  type, public :: xdmf_field_t
    character(len=:), allocatable :: name
    character(len=:), allocatable :: path        !< HDF5 dataset path
    character(len=:), allocatable :: kind        !< XDMF AttributeType: Scalar, Vector or Matrix
    integer :: ncomp = 1                         !< components stored (1: a 1D dataset)
  end type xdmf_field_t

  !> One output frame.
  type, public :: xdmf_frame_t
    real(wp) :: time = 0.0_wp
    integer :: nfield = 0
    type(xdmf_field_t), allocatable :: fields(:)
  end type xdmf_frame_t

contains

  !> Write the XDMF file `path` for the HDF5 file named `h5name` (written
  !> as given: a name relative to the XDMF file's folder keeps the pair
  !> movable). nframe frames of `frames` are used.
  subroutine write_xdmf(path, h5name, nnode, blocks, frames, nframe, err)
    character(len=*), intent(in) :: path, h5name
    integer, intent(in) :: nnode
    type(xdmf_block_t), intent(in) :: blocks(:)
    type(xdmf_frame_t), intent(in) :: frames(:)
    integer, intent(in) :: nframe
    type(error_t), intent(inout) :: err
    integer :: u, ios, f
    character(len=256) :: msg
    open(newunit=u, file=path, status='replace', action='write', iostat=ios, iomsg=msg)
    if (ios /= 0) then
      call raise_error(err, EXIT_IO, 'cannot create XDMF file "' // path // '": ' // trim(msg))
      return
    end if
    call put(u, '<?xml version="1.0" ?>', ios)
    call put(u, '<Xdmf Version="3.0">', ios)
    call put(u, '  <Domain>', ios)
    if (nframe == 0) then
      call put_frame(u, h5name, nnode, blocks, 'mesh', .false., 0.0_wp, [xdmf_field_t ::], ios)
    else
      call put(u, '    <Grid Name="frames" GridType="Collection" CollectionType="Temporal">', ios)
      do f = 1, nframe
        call put_frame(u, h5name, nnode, blocks, 'frame_' // frame_label(f - 1), .true., &
          frames(f)%time, frames(f)%fields(1:frames(f)%nfield), ios)
      end do
      call put(u, '    </Grid>', ios)
    end if
    call put(u, '  </Domain>', ios)
    call put(u, '</Xdmf>', ios)
    if (ios /= 0) then
      call raise_error(err, EXIT_IO, 'cannot write XDMF file "' // path // '" (disk full?)')
      close(u, status='delete', iostat=ios)
      return
    end if
    close(u, iostat=ios, iomsg=msg)
    if (ios /= 0) call raise_error(err, EXIT_IO, 'cannot close XDMF file "' // path // '": ' // trim(msg))
  end subroutine write_xdmf

  !> Six-digit, zero-padded frame number: the name of the frame's HDF5 group.
  pure function frame_label(index) result(s)
    integer, intent(in) :: index
    character(len=6) :: s
    write(s, '(i6.6)') index
  end function frame_label

  ! --- private -----------------------------------------------------------

  !> One spatial collection: one grid per block, all with the same fields.
  subroutine put_frame(u, h5name, nnode, blocks, name, timed, time, fields, ios)
    integer, intent(in) :: u, nnode
    character(len=*), intent(in) :: h5name, name
    type(xdmf_block_t), intent(in) :: blocks(:)
    logical, intent(in) :: timed
    real(wp), intent(in) :: time
    type(xdmf_field_t), intent(in) :: fields(:)
    integer, intent(inout) :: ios
    integer :: b, k
    character(len=32) :: tbuf
    call put(u, '      <Grid Name="' // name // '" GridType="Collection" CollectionType="Spatial">', ios)
    if (timed) then
      write(tbuf, '(es24.16e3)') time
      call put(u, '        <Time Value="' // trim(adjustl(tbuf)) // '" />', ios)
    end if
    do b = 1, size(blocks)
      call put(u, '        <Grid Name="' // escape(blocks(b)%name) // '" GridType="Uniform">', ios)
      call put(u, '          <Topology TopologyType="' // topology_name(blocks(b)%nen) &
        // '" NumberOfElements="' // str(blocks(b)%nel) // '" NodesPerElement="' &
        // str(blocks(b)%nen) // '">', ios)
      call put_item(u, h5name, blocks(b)%conn_path, str(blocks(b)%nel) // ' ' // str(blocks(b)%nen), &
        'Int', storage_size(0)/8, ios)
      call put(u, '          </Topology>', ios)
      call put(u, '          <Geometry GeometryType="XY">', ios)
      call put_item(u, h5name, '/mesh/x', str(nnode) // ' 2', 'Float', 8, ios)
      call put(u, '          </Geometry>', ios)
      do k = 1, size(fields)
        call put(u, '          <Attribute Name="' // escape(fields(k)%name) // '" AttributeType="' &
          // fields(k)%kind // '" Center="Node">', ios)
        if (fields(k)%ncomp == 1) then
          call put_item(u, h5name, fields(k)%path, str(nnode), 'Float', 8, ios)
        else
          call put_item(u, h5name, fields(k)%path, str(nnode) // ' ' // str(fields(k)%ncomp), &
            'Float', 8, ios)
        end if
        call put(u, '          </Attribute>', ios)
      end do
      call put(u, '        </Grid>', ios)
    end do
    call put(u, '      </Grid>', ios)
  end subroutine put_frame

  !> A DataItem pointing at an HDF5 dataset ("file.h5:/path").
  subroutine put_item(u, h5name, h5path, dims, number_type, precision, ios)
    integer, intent(in) :: u, precision
    character(len=*), intent(in) :: h5name, h5path, dims, number_type
    integer, intent(inout) :: ios
    call put(u, '            <DataItem Dimensions="' // dims // '" NumberType="' // number_type &
      // '" Precision="' // str(precision) // '" Format="HDF">' // escape(h5name) // ':' &
      // escape(h5path) // '</DataItem>', ios)
  end subroutine put_item

  !> XDMF topology of a quadrilateral with nen nodes; XDMF's Quadrilateral_8
  !> has the corners then the mid-sides, the order of raccord_mesh.
  pure function topology_name(nen) result(s)
    integer, intent(in) :: nen
    character(len=:), allocatable :: s
    if (nen == 8) then
      s = 'Quadrilateral_8'
    else
      s = 'Quadrilateral'
    end if
  end function topology_name

  !> Write one line unless an earlier line failed (the first iostat is kept).
  subroutine put(u, line, ios)
    integer, intent(in) :: u
    character(len=*), intent(in) :: line
    integer, intent(inout) :: ios
    if (ios /= 0) return
    write(u, '(a)', iostat=ios) line
  end subroutine put

  !> Escape the XML special characters of a name or path.
  pure function escape(text) result(s)
    character(len=*), intent(in) :: text
    character(len=:), allocatable :: s
    integer :: k
    s = ''
    do k = 1, len(text)
      select case (text(k:k))
      case ('&'); s = s // '&amp;'
      case ('<'); s = s // '&lt;'
      case ('>'); s = s // '&gt;'
      case ('"'); s = s // '&quot;'
      case default; s = s // text(k:k)
      end select
    end do
  end function escape
end module raccord_xdmf
