!> The sections both MSH versions share: $MeshFormat (version 4.1 or
!> 2.2, ASCII) and $PhysicalNames (the groups' names, each checked
!> against the others).
module raccord_gmsh_header
  use raccord_kinds, only: wp
  use raccord_error, only: error_t, raise_error, EXIT_INPUT
  use raccord_strings, only: str
  use raccord_int_map, only: map_init, map_insert, map_get, text_key
  use raccord_text_reader, only: text_file_t, here
  use raccord_gmsh_state, only: gmsh_state_t, tag_key
  use raccord_gmsh_lines, only: next_data_line, read_count, expect_end, get_int, clip
  implicit none
  private

  public :: read_mesh_format, read_physical_names

contains

  !> "$MeshFormat": version, file type (0 ASCII, 1 binary), data size.
  subroutine read_mesh_format(tf, st, err)
    type(text_file_t), intent(inout) :: tf
    type(gmsh_state_t), intent(inout) :: st
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: line, v
    integer, allocatable :: f(:), l(:)
    integer :: nf, ftype, ios, k
    real(wp) :: ver
    call next_data_line(tf, 'MeshFormat', 'the version line', 0, 0, line, f, l, nf, err)
    if (err%failed()) return
    if (nf < 3) then
      call raise_error(err, EXIT_INPUT, here(tf) // ': the $MeshFormat line needs "version file-type ' // &
        'data-size", found "' // clip(line) // '"')
      return
    end if
    v = line(f(1):l(1))
    ! The version is a number (Gmsh writes 4.1 and 2.2; "4.10" and "2.20"
    ! are the same versions): 4.1, or 2.x (2.0-2.2 share the element lines)
    ver = -1.0_wp
    if (verify(v, '0123456789.') == 0 .and. count([(v(k:k) == '.', k = 1, len(v))]) == 1 .and. &
        len(v) <= 20) then
      read (v, '(f20.0)', iostat=ios) ver
      if (ios /= 0) ver = -1.0_wp
    end if
    if (abs(ver - 4.1_wp) < 1.0e-9_wp) then
      st%version = 41
    else if (ver >= 2.0_wp .and. ver < 3.0_wp) then
      st%version = 22
    else
      call raise_error(err, EXIT_INPUT, here(tf) // ': MSH version ' // v // ' is not read by raccord: ' // &
        'save as version 4.1 or 2.2 ASCII (Mesh.MshFileVersion = 4.1, or gmsh -format msh41)')
      return
    end if
    call get_int(tf, line, f, l, 2, 'file type', ftype, err)
    if (err%failed()) return
    if (ftype /= 0) then
      call raise_error(err, EXIT_INPUT, here(tf) // ': the mesh is saved in binary; raccord reads ' // &
        'ASCII meshes only: save as ASCII (Mesh.Binary = 0, or gmsh -bin 0)')
      return
    end if
    call expect_end(tf, 'MeshFormat', err)
  end subroutine read_mesh_format

  !> "$PhysicalNames": count, then lines 'dim tag "name"'.
  subroutine read_physical_names(tf, st, err)
    type(text_file_t), intent(inout) :: tf
    type(gmsh_state_t), intent(inout) :: st
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: line
    integer, allocatable :: f(:), l(:)
    integer :: nf, n, k, j, dim, tag, q1, q2, prev
    call read_count(tf, 'PhysicalNames', 'the number of names', n, err)
    if (err%failed()) return
    deallocate(st%name_dim, st%name_tag, st%names)
    allocate(st%name_dim(n), st%name_tag(n), st%names(n))
    call map_init(st%tag_index, n)
    do j = 0, 2
      call map_init(st%name_index(j), n)
    end do
    do k = 1, n
      call next_data_line(tf, 'PhysicalNames', 'name', k, n, line, f, l, nf, err)
      if (err%failed()) return
      call get_int(tf, line, f, l, 1, 'dimension', dim, err)
      call get_int(tf, line, f, l, 2, 'physical tag', tag, err)
      if (err%failed()) return
      q1 = index(line, '"')
      q2 = index(line, '"', back=.true.)
      ! A name the deck cannot reach would leave its group under its tag,
      ! and the deck's set "not found" far from the cause: refused here.
      if (dim < 0 .or. dim > 2) then
        call raise_error(err, EXIT_INPUT, here(tf) // ': physical group ' // str(tag) // ' has dimension ' // &
          str(dim) // '; a 2D mesh has groups of dimension 0 (points), 1 (curves) and 2 (surfaces): ' // &
          'mesh in 2D (gmsh -2) with the groups on points, curves and surfaces')
        return
      end if
      if (q1 == 0 .or. q2 == q1) then
        call raise_error(err, EXIT_INPUT, here(tf) // ': the name of physical group ' // str(tag) // &
          ' is not in double quotes (a line is: dimension tag "name"); re-export the mesh from Gmsh')
        return
      end if
      if (q2 == q1 + 1 .or. len_trim(line(q1 + 1:max(q1, q2 - 1))) == 0) then
        call raise_error(err, EXIT_INPUT, here(tf) // ': physical group ' // str(tag) // ' has an empty ' // &
          'name ""; give it a name in the .geo (Physical Curve("name") = {...};) or drop the line')
        return
      end if
      st%name_dim(k) = dim
      st%name_tag(k) = tag
      st%names(k)%s = line(q1 + 1:q2 - 1)
      j = map_get(st%tag_index, tag_key(dim, tag))
      if (j > 0) then
        if (st%name_dim(j) == dim .and. st%name_tag(j) == tag) then
          call raise_error(err, EXIT_INPUT, here(tf) // ': physical group ' // str(tag) // ' of dimension ' // &
            str(dim) // ' is named a second time ("' // clip(st%names(j)%s) // '" and "' // clip(st%names(k)%s) // &
            '"); keep one line per group')
          return
        end if
      end if
      call map_insert(st%tag_index, tag_key(dim, tag), k, prev)
      j = map_get(st%name_index(dim), text_key(st%names(k)%s))
      if (j > 0) then
        if (st%names(j)%s == st%names(k)%s) then
          call raise_error(err, EXIT_INPUT, here(tf) // ': the name "' // clip(st%names(k)%s) // '" is given to ' // &
            'two physical groups of dimension ' // str(dim) // ' (tags ' // str(st%name_tag(j)) // ' and ' // &
            str(tag) // '); a set name must be unique: rename one, or put both in one group')
          return
        end if
      end if
      call map_insert(st%name_index(dim), text_key(st%names(k)%s), k, prev)
    end do
    st%nname = n
    call expect_end(tf, 'PhysicalNames', err)
  end subroutine read_physical_names
end module raccord_gmsh_header
