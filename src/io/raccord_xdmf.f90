!> The XDMF (eXtensible Data Model and Format, version 3) light-data files
!> that let ParaView and meshio read a raccord HDF5 results file.
!>
!> stem.xmf (doc/output-format.md, "XDMF"): a temporal collection with one
!> spatial collection per frame, holding one uniform grid per element block
!> and one per contact surface. A block grid takes its body's own rows of
!> /mesh/x and of the frame's nodal datasets as hyperslabs (the results file
!> stores each block's nodes contiguously, raccord_node_order); a surface
!> grid has line elements on the surface nodes, the deformed surface
!> coordinates of the frame and its per-node contact values. Without
!> frames, one spatial collection shows the mesh alone.
!>
!> stem.meshio.xmf ("meshio index"): the shape meshio's XDMF time-series
!> reader accepts: one uniform grid with the whole mesh (every node, one
!> Topology per block), then a temporal collection of grids holding only a
!> Time and the frame's nodal fields.
!>
!> The heavy data stay in HDF5 and are referenced as "file.h5:/path".
module raccord_xdmf
  use raccord_kinds, only: wp
  use raccord_error, only: error_t, raise_error, EXIT_IO
  use raccord_strings, only: str
  implicit none
  private

  public :: write_xdmf, write_meshio_index, frame_label

  !> One element block as referenced by the XDMF.
  type, public :: xdmf_block_t
    character(len=:), allocatable :: name
    character(len=:), allocatable :: conn_path   !< HDF5 path of the (nel, nen) 0-based rows of /mesh/x
    character(len=:), allocatable :: local_path  !< the same, 0-based from the block's first row
    integer :: nen = 0
    integer :: nel = 0
    integer :: first = 0                         !< 0-based first row of /mesh/x of this block
    integer :: count = 0                         !< rows of this block
  end type xdmf_block_t

  !> One contact surface: line elements on its nodes; per frame, its
  !> deformed coordinates and scalar values at <frame_base>/frame_NNNNNN/.
  type, public :: xdmf_surface_t
    character(len=:), allocatable :: name
    character(len=:), allocatable :: conn_path   !< (nseg, nen) 0-based surface node indices
    character(len=:), allocatable :: frame_base  !< group holding frame_NNNNNN/
    character(len=:), allocatable :: geometry    !< dataset name of the (n, 2) coordinates in a frame
    character(len=32), allocatable :: fields(:)  !< scalar dataset names in a frame
    integer :: nen = 2                           !< 2 (straight) or 3 (quadratic: ends, then middle)
    integer :: nseg = 0
    integer :: nnode = 0
  end type xdmf_surface_t

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
    integer :: nsurf = 0                         !< surfaces 1..nsurf have their data in this frame
  end type xdmf_frame_t

contains

  !> Write the XDMF file `path` for the HDF5 file named `h5name` (written
  !> as given: a name relative to the XDMF file's folder keeps the pair
  !> movable). nframe frames of `frames` are used.
  subroutine write_xdmf(path, h5name, nnode, blocks, surfaces, frames, nframe, err)
    character(len=*), intent(in) :: path, h5name
    integer, intent(in) :: nnode
    type(xdmf_block_t), intent(in) :: blocks(:)
    type(xdmf_surface_t), intent(in) :: surfaces(:)
    type(xdmf_frame_t), intent(in) :: frames(:)
    integer, intent(in) :: nframe
    type(error_t), intent(inout) :: err
    integer :: u, ios, f
    call open_xml(path, u, err)
    if (err%failed()) return
    ios = 0
    if (nframe == 0) then
      call put_frame(u, h5name, nnode, blocks, surfaces, 'mesh', .false., 0.0_wp, [xdmf_field_t ::], 0, ios)
    else
      call put(u, '    <Grid Name="frames" GridType="Collection" CollectionType="Temporal">', ios)
      do f = 1, nframe
        call put_frame(u, h5name, nnode, blocks, surfaces, 'frame_' // frame_label(f - 1), .true., &
          frames(f)%time, frames(f)%fields(1:frames(f)%nfield), frames(f)%nsurf, ios)
      end do
      call put(u, '    </Grid>', ios)
    end if
    call close_xml(path, u, ios, err)
  end subroutine write_xdmf

  !> Write the meshio index `path` (see the module header) for `h5name`.
  subroutine write_meshio_index(path, h5name, nnode, blocks, frames, nframe, err)
    character(len=*), intent(in) :: path, h5name
    integer, intent(in) :: nnode
    type(xdmf_block_t), intent(in) :: blocks(:)
    type(xdmf_frame_t), intent(in) :: frames(:)
    integer, intent(in) :: nframe
    type(error_t), intent(inout) :: err
    integer :: u, ios, f, b, k
    character(len=32) :: tbuf
    call open_xml(path, u, err)
    if (err%failed()) return
    ios = 0
    call put(u, '    <Grid Name="mesh" GridType="Uniform">', ios)
    call put(u, '      <Geometry GeometryType="XY">', ios)
    call put_item(u, h5name, '/mesh/x', str(nnode) // ' 2', 'Float', 8, ios)
    call put(u, '      </Geometry>', ios)
    do b = 1, size(blocks)
      call put(u, '      <Topology TopologyType="' // topology_name(blocks(b)%nen) // '" NumberOfElements="' &
        // str(blocks(b)%nel) // '">', ios)
      call put_item(u, h5name, blocks(b)%conn_path, str(blocks(b)%nel) // ' ' // str(blocks(b)%nen), &
        'Int', storage_size(0)/8, ios)
      call put(u, '      </Topology>', ios)
    end do
    call put(u, '    </Grid>', ios)
    call put(u, '    <Grid Name="frames" GridType="Collection" CollectionType="Temporal">', ios)
    do f = 1, nframe
      call put(u, '      <Grid Name="frame_' // frame_label(f - 1) // '" GridType="Uniform">', ios)
      write(tbuf, '(es24.16e3)') frames(f)%time
      call put(u, '        <Time Value="' // trim(adjustl(tbuf)) // '" />', ios)
      do k = 1, frames(f)%nfield
        associate (fd => frames(f)%fields(k))
          call put(u, '        <Attribute Name="' // escape(fd%name) // '" AttributeType="' // fd%kind &
            // '" Center="Node">', ios)
          call put_item(u, h5name, fd%path, field_dims(nnode, fd%ncomp), 'Float', 8, ios)
          call put(u, '        </Attribute>', ios)
        end associate
      end do
      call put(u, '      </Grid>', ios)
    end do
    call put(u, '    </Grid>', ios)
    call close_xml(path, u, ios, err)
  end subroutine write_meshio_index

  !> Six-digit, zero-padded frame number: the name of the frame's HDF5 group.
  pure function frame_label(index) result(s)
    integer, intent(in) :: index
    character(len=6) :: s
    write(s, '(i6.6)') index
  end function frame_label

  ! --- private -----------------------------------------------------------

  !> Create the file and write the XML header up to <Domain>.
  subroutine open_xml(path, u, err)
    character(len=*), intent(in) :: path
    integer, intent(out) :: u
    type(error_t), intent(inout) :: err
    integer :: ios
    character(len=256) :: msg
    open(newunit=u, file=path, status='replace', action='write', iostat=ios, iomsg=msg)
    if (ios /= 0) then
      call raise_error(err, EXIT_IO, 'cannot create XDMF file "' // path // '": ' // trim(msg))
      return
    end if
    call put(u, '<?xml version="1.0" ?>', ios)
    call put(u, '<Xdmf Version="3.0">', ios)
    call put(u, '  <Domain>', ios)
  end subroutine open_xml

  !> Close </Domain></Xdmf> and the file; a failed write deletes it.
  subroutine close_xml(path, u, ios, err)
    character(len=*), intent(in) :: path
    integer, intent(in) :: u
    integer, intent(inout) :: ios
    type(error_t), intent(inout) :: err
    character(len=256) :: msg
    call put(u, '  </Domain>', ios)
    call put(u, '</Xdmf>', ios)
    if (ios /= 0) then
      call raise_error(err, EXIT_IO, 'cannot write XDMF file "' // path // '" (disk full?)')
      close(u, status='delete', iostat=ios)
      return
    end if
    close(u, iostat=ios, iomsg=msg)
    if (ios /= 0) call raise_error(err, EXIT_IO, 'cannot close XDMF file "' // path // '": ' // trim(msg))
  end subroutine close_xml

  !> One spatial collection: one grid per block, all with the same nodal
  !> fields, then one grid per contact surface 1..nsurf.
  subroutine put_frame(u, h5name, nnode, blocks, surfaces, name, timed, time, fields, nsurf, ios)
    integer, intent(in) :: u, nnode, nsurf
    character(len=*), intent(in) :: h5name, name
    type(xdmf_block_t), intent(in) :: blocks(:)
    type(xdmf_surface_t), intent(in) :: surfaces(:)
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
      associate (bk => blocks(b))
        call put(u, '        <Grid Name="' // escape(bk%name) // '" GridType="Uniform">', ios)
        call put(u, '          <Topology TopologyType="' // topology_name(bk%nen) &
          // '" NumberOfElements="' // str(bk%nel) // '" NodesPerElement="' // str(bk%nen) // '">', ios)
        call put_item(u, h5name, bk%local_path, str(bk%nel) // ' ' // str(bk%nen), 'Int', storage_size(0)/8, ios)
        call put(u, '          </Topology>', ios)
        call put(u, '          <Geometry GeometryType="XY">', ios)
        call put_rows(u, h5name, '/mesh/x', nnode, 2, bk%first, bk%count, ios)
        call put(u, '          </Geometry>', ios)
        do k = 1, size(fields)
          call put(u, '          <Attribute Name="' // escape(fields(k)%name) // '" AttributeType="' &
            // fields(k)%kind // '" Center="Node">', ios)
          call put_rows(u, h5name, fields(k)%path, nnode, fields(k)%ncomp, bk%first, bk%count, ios)
          call put(u, '          </Attribute>', ios)
        end do
        call put(u, '        </Grid>', ios)
      end associate
    end do
    if (timed) then
      do k = 1, min(nsurf, size(surfaces))
        call put_surface(u, h5name, surfaces(k), name, ios)
      end do
    end if
    call put(u, '      </Grid>', ios)
  end subroutine put_frame

  !> A contact surface's grid in frame `frame_name` ("frame_NNNNNN").
  subroutine put_surface(u, h5name, s, frame_name, ios)
    integer, intent(in) :: u
    character(len=*), intent(in) :: h5name, frame_name
    type(xdmf_surface_t), intent(in) :: s
    integer, intent(inout) :: ios
    character(len=:), allocatable :: group
    integer :: k
    group = s%frame_base // '/' // frame_name // '/'
    call put(u, '        <Grid Name="' // escape(s%name) // '" GridType="Uniform">', ios)
    if (s%nen == 3) then
      call put(u, '          <Topology TopologyType="Edge_3" NumberOfElements="' // str(s%nseg) // '">', ios)
    else
      call put(u, '          <Topology TopologyType="Polyline" NumberOfElements="' // str(s%nseg) &
        // '" NodesPerElement="2">', ios)
    end if
    call put_item(u, h5name, s%conn_path, str(s%nseg) // ' ' // str(s%nen), 'Int', storage_size(0)/8, ios)
    call put(u, '          </Topology>', ios)
    call put(u, '          <Geometry GeometryType="XY">', ios)
    call put_item(u, h5name, group // s%geometry, str(s%nnode) // ' 2', 'Float', 8, ios)
    call put(u, '          </Geometry>', ios)
    do k = 1, size(s%fields)
      call put(u, '          <Attribute Name="' // escape(trim(s%fields(k))) // '" AttributeType="Scalar" ' &
        // 'Center="Node">', ios)
      call put_item(u, h5name, group // trim(s%fields(k)), str(s%nnode), 'Float', 8, ios)
      call put(u, '          </Attribute>', ios)
    end do
    call put(u, '        </Grid>', ios)
  end subroutine put_surface

  !> Rows first .. first+count-1 (0-based) of a dataset of nrow rows and
  !> ncol columns (ncol = 1: a 1D dataset): the dataset itself when that
  !> is all of it, otherwise a hyperslab in the form the Xdmf3 library
  !> (ParaView's Xdmf3ReaderS/T) reads: "file.h5:/path|start:stride:count:dims",
  !> each part one number per dimension, slowest first. (The XDMF 2
  !> ItemType="HyperSlab" element is not read by Xdmf3; this form is not
  !> read by ParaView's legacy "XDMF Reader": doc/output-format.md.)
  subroutine put_rows(u, h5name, h5path, nrow, ncol, first, count, ios)
    integer, intent(in) :: u, nrow, ncol, first, count
    character(len=*), intent(in) :: h5name, h5path
    integer, intent(inout) :: ios
    character(len=:), allocatable :: slab
    if (first == 0 .and. count == nrow) then
      call put_item(u, h5name, h5path, field_dims(nrow, ncol), 'Float', 8, ios)
      return
    end if
    if (ncol == 1) then
      slab = '|' // str(first) // ':1:' // str(count) // ':' // str(nrow)
    else
      slab = '|' // str(first) // ' 0:1 1:' // str(count) // ' ' // str(ncol) // ':' // str(nrow) // ' ' // str(ncol)
    end if
    call put_item(u, h5name, h5path // slab, field_dims(count, ncol), 'Float', 8, ios)
  end subroutine put_rows

  !> XDMF Dimensions of n rows of ncomp components ("n" for one).
  pure function field_dims(n, ncomp) result(s)
    integer, intent(in) :: n, ncomp
    character(len=:), allocatable :: s
    if (ncomp == 1) then
      s = str(n)
    else
      s = str(n) // ' ' // str(ncomp)
    end if
  end function field_dims

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
