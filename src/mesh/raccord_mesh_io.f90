!> Reading a mesh file: choose the reader by format, then run the checks
!> shared by every format (raccord_mesh_check). doc/mesh-formats.md says
!> what is read from each format and what is refused.
module raccord_mesh_io
  use raccord_kinds, only: wp
  use raccord_error, only: error_t, raise_error, prefix_error, EXIT_INPUT
  use raccord_log, only: log_info
  use raccord_strings, only: str, lower, ends_with
  use raccord_mesh, only: mesh_t, ELEM_Q4, ELEM_Q8
  use raccord_mesh_draft, only: mesh_draft_t
  use raccord_gmsh_reader, only: read_gmsh
  use raccord_abaqus_reader, only: read_abaqus
  use raccord_mesh_check, only: finalize_mesh
  implicit none
  private

  public :: read_mesh

contains

  !> Read a Gmsh (.msh, 4.1 or 2.2 ASCII) or Abaqus/CalculiX (.inp) mesh.
  !> format: 'auto' (default: by the extension .msh / .inp), 'gmsh' or 'abaqus'.
  !> scale: factor applied to the coordinates (default 1), e.g. 1000 for a
  !> mesh drawn in metres and a scene in millimetres.
  !> On failure err%code = EXIT_INPUT and the message names the file and
  !> line (or the element / node id) and how to fix it.
  subroutine read_mesh(path, mesh, err, format, scale)
    character(*), intent(in) :: path
    type(mesh_t), intent(out) :: mesh
    type(error_t), intent(inout) :: err
    character(*), intent(in), optional :: format
    real(wp), intent(in), optional :: scale
    character(len=:), allocatable :: fmt
    type(mesh_draft_t) :: draft
    real(wp) :: factor

    if (err%failed()) return
    mesh%source = path
    fmt = 'auto'
    if (present(format)) fmt = lower(trim(adjustl(format)))
    if (len(fmt) == 0) fmt = 'auto'
    factor = 1.0_wp
    if (present(scale)) factor = scale
    if (.not. (factor > 0.0_wp .and. factor <= huge(factor))) then
      call raise_error(err, EXIT_INPUT, 'mesh scale for ' // path // ' is ' // str(factor) // &
        ': it must be a positive finite factor')
      return
    end if

    if (fmt == 'auto') then
      if (ends_with(lower(path), '.msh')) then
        fmt = 'gmsh'
      else if (ends_with(lower(path), '.inp')) then
        fmt = 'abaqus'
      else
        call raise_error(err, EXIT_INPUT, 'cannot tell the format of mesh file ' // path // &
          ' from its extension: name it .msh (Gmsh) or .inp (Abaqus), or give format = ''gmsh'' or ''abaqus''')
        return
      end if
    end if

    select case (fmt)
    case ('gmsh')
      call read_gmsh(path, draft, err)
    case ('abaqus')
      call read_abaqus(path, draft, err)
    case default
      call raise_error(err, EXIT_INPUT, 'mesh format "' // fmt // '" is unknown: use ''auto'', ''gmsh'' or ''abaqus''')
      return
    end select
    if (err%failed()) then
      call prefix_error(err, 'reading mesh')
      return
    end if

    ! before the elements' checks, which would call an element of a mesh
    ! too large for double precision inverted
    call check_extent(path, factor, draft%x(:, 1:draft%nnode), err)
    if (err%failed()) return
    call finalize_mesh(draft, mesh, err)
    if (err%failed()) then
      call prefix_error(err, 'checking mesh')
      return
    end if
    if (factor /= 1.0_wp) mesh%x = factor*mesh%x

    call log_info('read_mesh', path // ': ' // str(mesh%nnode) // ' nodes, ' // str(mesh%nelem) // &
      ' elements (' // str(count(mesh%etype == ELEM_Q4)) // ' Q4, ' // str(count(mesh%etype == ELEM_Q8)) // &
      ' Q8), ' // str(size(mesh%esets)) // ' element sets, ' // str(size(mesh%nsets)) // ' node sets, ' // &
      str(size(mesh%surfaces)) // ' surfaces')
  end subroutine read_mesh

  !> The scaled mesh must keep its areas, masses and stiffnesses finite and
  !> non-zero in double precision: a size across between 1e-100 and 1e100
  !> (a scale of 1e200 made every area infinite, and the run then reported
  !> a model without stiffness), and coordinates of at most 1e100 (a node
  !> at 1e200 in the file itself was reported as an inverted element).
  !> x: the file's coordinates (2, nnode), before the factor.
  subroutine check_extent(path, factor, x, err)
    character(*), intent(in) :: path
    real(wp), intent(in) :: factor
    real(wp), intent(in) :: x(:,:)
    type(error_t), intent(inout) :: err
    real(wp), parameter :: smallest = 1.0e-100_wp, largest = 1.0e100_wp
    real(wp) :: across, reach
    character(len=:), allocatable :: what
    if (size(x, 2) == 0) return
    across = factor*max(maxval(x(1, :)) - minval(x(1, :)), maxval(x(2, :)) - minval(x(2, :)))
    reach = factor*maxval(abs(x))
    if (across >= smallest .and. across <= largest .and. reach <= largest) return
    what = 'mesh ' // path
    if (factor /= 1.0_wp) what = what // ' scaled by &mesh scale = ' // str(factor)
    if (across >= smallest .and. across <= largest) then
      call raise_error(err, EXIT_INPUT, what // ' has a node ' // str(reach) // ' from the origin, beyond 1e100 ' // &
        'where areas and stiffnesses stay finite in double precision: give the coordinates in other units ' // &
        '(or the factor from mesh units to deck units, &mesh scale), and the mesh near the origin')
    else
      call raise_error(err, EXIT_INPUT, what // ' is ' // str(across) // ' across, outside 1e-100 to 1e100 ' // &
        'where areas and stiffnesses stay finite in double precision: give the factor from mesh units to ' // &
        'deck units (e.g. scale = 1.0e3 for a mesh in m and a deck in mm)')
    end if
  end subroutine check_extent
end module raccord_mesh_io
