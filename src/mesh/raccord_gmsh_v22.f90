!> The MSH 2.2 sections ("Legacy formats" appendix of the Gmsh reference
!> manual): $Nodes as 'id x y z' lines, $Elements as 'id type ntags
!> tags... nodes...' lines, one physical tag per line (an element in
!> several groups is repeated under new ids and merged back by
!> take_element).
module raccord_gmsh_v22
  use raccord_kinds, only: wp
  use raccord_error, only: error_t, raise_error, EXIT_INPUT
  use raccord_strings, only: str
  use raccord_text_reader, only: text_file_t, here
  use raccord_mesh_draft, only: mesh_draft_t, add_node
  use raccord_gmsh_state, only: gmsh_state_t, take_element, gmsh_nodes, refuse_type
  use raccord_gmsh_lines, only: next_data_line, read_count, expect_end, get_int, get_real
  implicit none
  private

  public :: read_nodes_22, read_elements_22

contains

  !> "$Nodes" (2.2): count, then 'id x y z' lines.
  subroutine read_nodes_22(tf, st, d, err)
    type(text_file_t), intent(inout) :: tf
    type(gmsh_state_t), intent(in) :: st
    type(mesh_draft_t), intent(inout) :: d
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: line
    integer, allocatable :: f(:), l(:)
    integer :: nf, n, k, id
    real(wp) :: xy(2), z
    call read_count(tf, 'Nodes', 'the number of nodes', n, err)
    if (err%failed()) return
    do k = 1, n
      call next_data_line(tf, 'Nodes', 'node', k, n, line, f, l, nf, err)
      if (err%failed()) return
      call get_int(tf, line, f, l, 1, 'node id', id, err)
      call get_real(tf, line, f, l, 2, 'x', xy(1), err)
      call get_real(tf, line, f, l, 3, 'y', xy(2), err)
      z = 0.0_wp
      if (nf >= 4) call get_real(tf, line, f, l, 4, 'z', z, err)
      if (err%failed()) return
      call add_node(d, id, xy, st%ifile, tf%line_no, z)
    end do
    call expect_end(tf, 'Nodes', err)
  end subroutine read_nodes_22

  !> "$Elements" (2.2): count, then 'id type ntags tags... nodes...' lines.
  subroutine read_elements_22(tf, st, d, err)
    type(text_file_t), intent(inout) :: tf
    type(gmsh_state_t), intent(inout) :: st
    type(mesh_draft_t), intent(inout) :: d
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: line
    integer, allocatable :: f(:), l(:)
    integer :: nf, n, k, a, id, gtype, ntag, nn, phys
    integer :: nodes(8)
    call read_count(tf, 'Elements', 'the number of elements', n, err)
    if (err%failed()) return
    do k = 1, n
      call next_data_line(tf, 'Elements', 'element', k, n, line, f, l, nf, err)
      if (err%failed()) return
      call get_int(tf, line, f, l, 1, 'element id', id, err)
      call get_int(tf, line, f, l, 2, 'element type', gtype, err)
      call get_int(tf, line, f, l, 3, 'number of tags', ntag, err)
      if (err%failed()) return
      nn = gmsh_nodes(gtype)
      if (nn == 0) then
        call refuse_type(tf, gtype, err)
        return
      end if
      if (ntag < 0 .or. nf /= 3 + ntag + nn) then
        call raise_error(err, EXIT_INPUT, here(tf) // ': element ' // str(id) // ' of type ' // str(gtype) // &
          ' with ' // str(ntag) // ' tags needs ' // str(3 + ntag + nn) // ' fields, found ' // str(nf) // &
          ': re-export the mesh')
        return
      end if
      ! tags: physical group, elementary entity, [partitions]; only the first matters
      phys = 0
      if (ntag >= 1) call get_int(tf, line, f, l, 4, 'physical tag', phys, err)
      do a = 1, nn
        call get_int(tf, line, f, l, 3 + ntag + a, 'node id', nodes(a), err)
      end do
      if (err%failed()) return
      if (phys /= 0) then
        call take_element(tf, st, d, id, gtype, nodes(1:nn), [phys], err)
      else
        call take_element(tf, st, d, id, gtype, nodes(1:nn), [integer ::], err)
      end if
      if (err%failed()) return
    end do
    call expect_end(tf, 'Elements', err)
  end subroutine read_elements_22
end module raccord_gmsh_v22
