!> Reader for Gmsh MSH files, ASCII versions 4.1 and 2.2.
!>
!> Format reference: Gmsh reference manual, section "MSH file format"
!> (4.1) and its "Legacy formats" appendix (2.2). What raccord takes:
!> - 4-node (type 3) and 8-node (type 16) quadrilaterals -> Q4 / Q8;
!> - physical surfaces -> element sets; physical curves (line elements,
!>   types 1 and 8) -> surfaces and node sets; physical points (type 15)
!>   -> node sets. An unnamed physical group is named by its tag.
!> In 4.1 an element's physical groups are those of its entity ($Entities);
!> in 2.2 each element line carries one physical tag, and an element in
!> several groups is written once per group under a new id, so a repeat
!> of an element (same nodes in the same order) is merged back into one.
!> Sections raccord does not use ($NodeData, $Comments, ...) are skipped and
!> named in the log; $Periodic (a constraint raccord cannot apply) warns.
!> This module is the loop over the sections; the sections are read by
!> raccord_gmsh_header (both versions), raccord_gmsh_v41 and
!> raccord_gmsh_v22, on raccord_gmsh_state and raccord_gmsh_lines.
module raccord_gmsh_reader
  use raccord_error, only: error_t, raise_error, EXIT_INPUT
  use raccord_log, only: log_info, log_warn
  use raccord_strings, only: str
  use raccord_int_map, only: map_init
  use raccord_text_reader, only: text_file_t, open_text_file, close_text_file, read_line, here
  use raccord_mesh_draft, only: mesh_draft_t, add_file
  use raccord_gmsh_state, only: gmsh_state_t
  use raccord_gmsh_lines, only: skip_section, clip
  use raccord_gmsh_header, only: read_mesh_format, read_physical_names
  use raccord_gmsh_v41, only: read_entities, read_nodes_41, read_elements_41
  use raccord_gmsh_v22, only: read_nodes_22, read_elements_22
  implicit none
  private

  public :: read_gmsh

contains

  !> Read a Gmsh MSH 4.1 or 2.2 ASCII file into the draft.
  subroutine read_gmsh(path, d, err)
    character(len=*), intent(in) :: path
    type(mesh_draft_t), intent(inout) :: d
    type(error_t), intent(inout) :: err
    type(text_file_t) :: tf
    type(gmsh_state_t) :: st
    character(len=:), allocatable :: line, t
    logical :: eof

    d%format_name = 'gmsh'
    call open_text_file(tf, path, err)
    if (err%failed()) return
    call add_file(d, path, st%ifile)
    allocate(st%name_dim(0), st%name_tag(0), st%names(0), st%ent(3, 0))
    call map_init(st%seen_quads, 1024)
    call map_init(st%element_line, 1024)
    st%skipped = ''

    sections: do
      call read_line(tf, line, eof, err)
      if (err%failed() .or. eof) exit sections
      t = trim(adjustl(line))
      if (len(t) == 0) cycle sections
      if (st%version == 0 .and. t /= '$MeshFormat') then
        call raise_error(err, EXIT_INPUT, here(tf) // ': expected "$MeshFormat" at the start of a Gmsh ' // &
          'mesh file, found "' // clip(t) // '": is this a .msh file written by Gmsh?')
        exit sections
      end if
      if (t(1:1) /= '$') then
        call raise_error(err, EXIT_INPUT, here(tf) // ': expected a section header such as "$Nodes", found "' // &
          clip(t) // '": the previous section holds more data than its count says, or the file was edited')
        exit sections
      end if
      select case (t)
      case ('$MeshFormat')
        call read_mesh_format(tf, st, err)
      case ('$PhysicalNames')
        call read_physical_names(tf, st, err)
      case ('$Entities')
        if (st%version == 41) then
          call read_entities(tf, st, err)
        else
          call skip_section(tf, 'Entities', err)
        end if
      case ('$Nodes')
        st%seen_nodes = .true.
        if (st%version == 41) then
          call read_nodes_41(tf, st, d, err)
        else
          call read_nodes_22(tf, st, d, err)
        end if
      case ('$Elements')
        st%seen_elements = .true.
        if (st%version == 41) then
          call read_elements_41(tf, st, d, err)
        else
          call read_elements_22(tf, st, d, err)
        end if
      case default
        if (t == '$PartitionedEntities') then
          ! partitioned entities hide the physical groups of the elements
          call raise_error(err, EXIT_INPUT, here(tf) // ': the mesh is partitioned; raccord reads whole ' // &
            'meshes: save it unpartitioned (mesh without ' // &
            'PartitionMesh, or UnpartitionMesh before saving)')
        else if (t(1:min(4, len(t))) == '$End') then
          call raise_error(err, EXIT_INPUT, here(tf) // ': "' // t // '" closes no open section: ' // &
            'the file was edited or concatenated; re-export the mesh')
        else
          if (t == '$Periodic') then
            ! Gmsh's periodic node pairs: a constraint raccord has no way to apply
            call log_warn('read_gmsh', here(tf) // ': the $Periodic section (periodic node pairs of ' // &
              'Periodic Curve/Surface) is not applied: raccord has no periodic constraints, so the two ' // &
              'sides move independently; tie them with the scene''s boundary conditions or remove the ' // &
              'periodicity from the .geo')
          else if (index(', ' // st%skipped // ',', ', ' // t(2:) // ',') == 0) then
            ! named once in the log, however often the section comes
            if (len(st%skipped) > 0) st%skipped = st%skipped // ', '
            st%skipped = st%skipped // t(2:)
          end if
          call skip_section(tf, t(2:), err)
        end if
      end select
      if (err%failed()) exit sections
    end do sections
    call close_text_file(tf)
    if (err%failed()) return

    if (st%version == 0) then
      call raise_error(err, EXIT_INPUT, path // ' is empty: expected a Gmsh mesh starting with $MeshFormat')
    else if (.not. (st%seen_nodes .and. st%seen_elements)) then
      call raise_error(err, EXIT_INPUT, path // ' has no $Nodes or no $Elements section (file ends at line ' // &
        str(tf%line_no) // '): the file is truncated or holds only geometry; mesh and save it again (gmsh -2)')
    end if
    if (err%failed()) return
    if (len(st%skipped) > 0) call log_info('read_gmsh', path // ': skipped sections that carry no mesh ' // &
      'data raccord uses (results, comments, ...): ' // st%skipped)
  end subroutine read_gmsh
end module raccord_gmsh_reader
