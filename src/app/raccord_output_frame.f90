!> One result frame (doc/output-format.md, "Frames"): the nodal fields,
!> the j2 fields, and each contact pair's surface grids and text profile
!> block; the results' mesh blocks and contact surfaces they refer to;
!> and the check, before the first step, that the frames the run will
!> write can be numbered, recorded and stored.
module raccord_output_frame
  use raccord_kinds, only: wp, i8
  use raccord_error, only: error_t, raise_error, EXIT_IO, EXIT_INPUT
  use raccord_strings, only: str
  use raccord_mesh, only: nodes_per_element
  use raccord_model, only: model_t
  use raccord_state, only: state_t
  use raccord_time_step, only: time_plan_t
  use raccord_scene, only: scene_t
  use raccord_elastic_block, only: add_nodal_stress, add_nodal_plastic
  use raccord_material, only: MAT_J2
  use raccord_results, only: result_block_t, results_begin_frame, results_write_nodal, results_end_frame, &
    results_add_surface, results_write_surface_frame, results_write_array
  use raccord_contact_pair, only: contact_pair_t
  use raccord_contact_surface, only: contact_surface_t
  use raccord_multiplier_solver, only: ST_OPEN
  use raccord_machine, only: free_disk_bytes, physical_memory_bytes
  use raccord_paths, only: path_dir
  use raccord_output_state, only: output_t, SURFACE_FIELDS
  use raccord_output_history, only: flush_history
  use raccord_output_profiles, only: profile_name
  implicit none
  private

  public :: write_frame, add_contact_surfaces, result_blocks, check_frame_count

contains

  !> Result frames are due by time (&output frames over t_end), at most one
  !> per step: min(frames, steps) + 2 of them (frames + 2 with a variable
  !> step, whose step count is an estimate). Their number is checked before
  !> the run: the results file numbers frames with six digits (/frames/NNNNNN),
  !> each keeps a record of about FRAME_RECORD_BYTES for the XDMF written at
  !> the end (refused beyond an eighth of the memory), and their data above
  !> a GiB must fit in the whole file system of the output folder.
  subroutine check_frame_count(scene, model, plan, pairs, stem, err)
    type(scene_t), intent(in) :: scene
    type(model_t), intent(in) :: model
    type(time_plan_t), intent(in) :: plan
    type(contact_pair_t), intent(in) :: pairs(:)
    character(len=*), intent(in) :: stem
    type(error_t), intent(inout) :: err
    integer(i8), parameter :: MAX_FRAMES = 999999, FRAME_RECORD_BYTES = 1024, GIB = 1024_i8**3
    integer(i8) :: nframe, frame_bytes, free, total, budget
    integer :: k
    character(len=:), allocatable :: folder, what
    nframe = int(scene%output%frames, i8) + 2
    if (.not. model%has_finite) nframe = min(nframe, plan%nsteps + 2)
    ! values per node: displacement, velocity, reaction (3 stored each), stress and strain (4)
    frame_bytes = 4096_i8 + 8_i8*int(model%nnode, i8)*17_i8
    do k = 1, size(pairs)
      frame_bytes = frame_bytes + 8_i8*(9_i8*pairs(k)%slave%nnode + 2_i8*pairs(k)%master%nnode)
    end do
    what = 'scene ' // scene%path // ': &output frames = ' // str(scene%output%frames) // ' over ' // &
      str(plan%nsteps) // ' steps makes up to ' // str(nframe) // ' result frames'
    budget = physical_memory_bytes()/8_i8
    if (nframe > MAX_FRAMES) then
      call raise_error(err, EXIT_INPUT, what // ', more than the ' // str(MAX_FRAMES) // ' a results file ' // &
        'numbers (six digits): set frames <= ' // str(MAX_FRAMES - 2))
      return
    end if
    if (nframe > budget/FRAME_RECORD_BYTES) then
      call raise_error(err, EXIT_INPUT, what // ', whose records for the XDMF take more than the ' // &
        str(real(budget, wp)/1.0e9_wp, 3) // ' GB (an eighth of this machine''s memory) they may: set frames <= ' // &
        str(budget/FRAME_RECORD_BYTES - 2))
      return
    end if
    folder = path_dir(stem)
    if (len(folder) == 0) folder = '.'
    free = free_disk_bytes(folder, total)
    if (free < 0 .or. total <= 0) return
    if (nframe <= total/frame_bytes .or. nframe <= GIB/frame_bytes) return
    call raise_error(err, EXIT_INPUT, what // ' of about ' // str(real(frame_bytes, wp)/1.0e6_wp, 3) // &
      ' MB, more than the whole file system of ' // folder // ' holds (' // str(real(total, wp)/1.0e9_wp, 3) // &
      ' GB): set frames <= ' // str(max(1_i8, total/frame_bytes - 2)))
  end subroutine check_frame_count

  !> The element blocks of the results file, one per body block.
  function result_blocks(model) result(blocks)
    type(model_t), intent(in) :: model
    type(result_block_t), allocatable :: blocks(:)
    integer :: ib, k, nblk
    nblk = 0
    do ib = 1, size(model%bodies)
      nblk = nblk + size(model%bodies(ib)%blocks)
    end do
    allocate(blocks(nblk))
    nblk = 0
    do ib = 1, size(model%bodies)
      do k = 1, size(model%bodies(ib)%blocks)
        nblk = nblk + 1
        blocks(nblk)%name = model%bodies(ib)%name
        if (size(model%bodies(ib)%blocks) > 1) blocks(nblk)%name = blocks(nblk)%name // '_' // str(k)
        blocks(nblk)%nen = nodes_per_element(model%bodies(ib)%blocks(k)%etype)
        blocks(nblk)%conn = model%bodies(ib)%blocks(k)%conn
      end do
    end do
  end function result_blocks

  !> Each pair's slave surface (with the contact values) and master
  !> surface (coordinates only) as surface grids of the results, named
  !> contact<k>_<surface>.
  subroutine add_contact_surfaces(out, pairs, err)
    type(output_t), intent(inout) :: out
    type(contact_pair_t), intent(in) :: pairs(:)
    type(error_t), intent(inout) :: err
    character(len=0), parameter :: none(0) = [character(len=0) ::]
    integer :: k
    do k = 1, size(pairs)
      associate (sl => pairs(k)%slave, ma => pairs(k)%master)
        call results_add_surface(out%res, 'contact' // str(k) // '_' // sl%name, '/contact/pair_' // str(k), '', &
          surface_segments(sl), sl%nnode, SURFACE_FIELDS, err)
        call results_add_surface(out%res, 'contact' // str(k) // '_' // ma%name, '/contact/pair_' // str(k), &
          'master_', surface_segments(ma), ma%nnode, none, err)
      end associate
      if (err%failed()) return
    end do
  end subroutine add_contact_surfaces

  !> Segments of a surface as indices into its node list (ends, then the
  !> middle node of a quadratic edge).
  function surface_segments(surf) result(conn)
    type(contact_surface_t), intent(in) :: surf
    integer, allocatable :: conn(:,:)
    integer :: i, j, k
    allocate(conn(surf%nen_seg, surf%nseg))
    do k = 1, surf%nseg
      do j = 1, surf%nen_seg
        conn(j, k) = 0
        do i = 1, surf%nnode
          if (surf%node(i) == surf%seg(j, k)) conn(j, k) = i
        end do
      end do
    end do
  end function surface_segments

  !> One result frame at t(n): displacement, velocity v(n), reactions, and
  !> nodal stress averaged over the elements around each node.
  subroutine write_frame(out, model, state, pairs, err)
    type(output_t), intent(inout) :: out
    type(model_t), intent(in) :: model
    type(state_t), intent(in) :: state
    type(contact_pair_t), intent(in) :: pairs(:)
    type(error_t), intent(inout) :: err
    integer :: ib, k, j

    call results_begin_frame(out%res, state%step, state%time, err)
    if (err%failed()) return
    call results_write_nodal(out%res, 'displacement', state%u, err)
    if (err%failed()) return
    call results_write_nodal(out%res, 'velocity', state%v_mid, err)
    if (err%failed()) return
    out%r_node = 0.0_wp
    do j = 1, model%ncdof
      out%r_node(model%cdof_comp(j), model%cdof_node(j)) = state%reaction(j)
    end do
    call results_write_nodal(out%res, 'reaction', out%r_node, err)
    if (err%failed()) return
    if (out%stress) then
      out%s_node = 0.0_wp
      out%wsum = 0.0_wp
      do ib = 1, size(model%bodies)
        do k = 1, size(model%bodies(ib)%blocks)
          call add_nodal_stress(model%bodies(ib)%blocks(k), state%u, out%s_node, out%wsum, &
            plastic=state%plastic(k, ib))
        end do
      end do
      do j = 1, model%nnode
        if (out%wsum(j) > 0.0_wp) out%s_node(:, j) = out%s_node(:, j)/out%wsum(j)
      end do
      call results_write_nodal(out%res, 'stress', out%s_node, err)
      if (err%failed()) return
      ! With a finite-strain body, the strain too: logarithmic in finite
      ! bodies, small strain in the others (doc/output-format.md).
      if (model%has_finite) then
        out%s_node = 0.0_wp
        out%wsum = 0.0_wp
        do ib = 1, size(model%bodies)
          do k = 1, size(model%bodies(ib)%blocks)
            call add_nodal_stress(model%bodies(ib)%blocks(k), state%u, out%s_node, out%wsum, strain=.true.)
          end do
        end do
        do j = 1, model%nnode
          if (out%wsum(j) > 0.0_wp) out%s_node(:, j) = out%s_node(:, j)/out%wsum(j)
        end do
        call results_write_nodal(out%res, 'strain', out%s_node, err)
        if (err%failed()) return
      end if
      if (model%has_plastic) then
        call write_plastic_fields(out, model, state, err)
        if (err%failed()) return
      end if
    end if
    do k = 1, size(pairs)
      call write_contact_frame(out, k, pairs(k), model, state, err)
      if (err%failed()) return
    end do
    ! the history so far goes with the frame, so a killed run keeps both
    call flush_history(out, err)
    if (err%failed()) return
    call results_end_frame(out%res, err)
    if (err%failed()) return
    out%frames_written = out%frames_written + 1
  end subroutine write_frame

  !> The j2 bodies' nodal fields (doc/output-format.md):
  !> equivalent_plastic_strain, the mean over each element's Gauss points
  !> averaged at the nodes, and yielded, at each node the fraction of its
  !> elements whose return was plastic at this frame's forces (0 at the
  !> nodes of other bodies).
  subroutine write_plastic_fields(out, model, state, err)
    type(output_t), intent(inout) :: out
    type(model_t), intent(in) :: model
    type(state_t), intent(in) :: state
    type(error_t), intent(inout) :: err
    integer :: ib, k, j
    out%s_node = 0.0_wp
    out%r_node = 0.0_wp
    out%wsum = 0.0_wp
    do ib = 1, size(model%bodies)
      do k = 1, size(model%bodies(ib)%blocks)
        if (model%bodies(ib)%blocks(k)%material /= MAT_J2) cycle
        call add_nodal_plastic(model%bodies(ib)%blocks(k), state%plastic(k, ib), state%watch(k, ib), &
          out%s_node(1:1, :), &
          out%r_node(1:1, :), out%wsum)
      end do
    end do
    do j = 1, model%nnode
      if (out%wsum(j) > 0.0_wp) then
        out%s_node(1, j) = out%s_node(1, j)/out%wsum(j)
        out%r_node(1, j) = out%r_node(1, j)/out%wsum(j)
      end if
    end do
    call results_write_nodal(out%res, 'equivalent_plastic_strain', out%s_node(1:1, :), err)
    if (err%failed()) return
    call results_write_nodal(out%res, 'yielded', out%r_node(1:1, :), err)
  end subroutine write_plastic_fields

  !> Contact profile of pair k at this frame: HDF5 arrays under
  !> /contact/pair_<k>/frame_<n>/ (the slave and master surface grids, and
  !> s0 and the pair's force) and a block of the text profile.
  subroutine write_contact_frame(out, k, pair, model, state, err)
    type(output_t), intent(inout) :: out
    integer, intent(in) :: k
    type(contact_pair_t), intent(in) :: pair
    type(model_t), intent(in) :: model
    type(state_t), intent(in) :: state
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: base
    character(len=16) :: tag
    integer :: i, p, ios, ns, nm
    write(tag, '(i6.6)') out%frames_written
    base = '/contact/pair_' // str(k) // '/frame_' // trim(tag) // '/'
    ns = pair%slave%nnode
    nm = pair%master%nnode
    associate (xy => out%surf_xy(:, 1:ns), xm => out%surf_xm(:, 1:nm), values => out%surf_values(1:ns, :))
    do i = 1, pair%slave%nnode
      p = pair%slave%node(i)
      xy(:, i) = model%x(:, p) + state%u(:, p)
    end do
    do i = 1, pair%master%nnode
      p = pair%master%node(i)
      xm(:, i) = model%x(:, p) + state%u(:, p)
    end do
    ! Columns in the order of SURFACE_FIELDS; the gap of an open node is
    ! written as 0 (as in the text profile: it is not computed there).
    values(:, 1) = pair%pressure
    values(:, 2) = pair%shear
    values(:, 3) = merge(pair%gap, 0.0_wp, pair%status /= ST_OPEN)
    values(:, 4) = pair%slip
    values(:, 5) = real(pair%status, wp)
    values(:, 6) = pair%lam_n
    values(:, 7) = pair%lam_t
    call results_write_array(out%res, base // 's0', pair%slave%s0, err)
    call results_write_array(out%res, base // 'force', pair%force, err)
    call results_write_surface_frame(out%res, 2*k - 1, xy, values, err)
    call results_write_surface_frame(out%res, 2*k, xm, out%surf_none(1:nm, :), err)
    if (err%failed()) return
    write(out%profile_unit(k), '(a,i0,a,es24.16,a,i0)', iostat=ios) '# frame ', out%frames_written, '  time ', &
      state%time, '  step ', state%step
    do i = 1, pair%slave%nnode
      write(out%profile_unit(k), '(6es24.16,i3,3es24.16)', iostat=ios) pair%slave%s0(i), xy(:, i), &
        merge(pair%gap(i), 0.0_wp, pair%status(i) /= ST_OPEN), pair%pressure(i), pair%shear(i), pair%status(i), &
        pair%slip(i), pair%lam_n(i), pair%lam_t(i)
    end do
    write(out%profile_unit(k), '(/)', iostat=ios)
    end associate
    if (ios /= 0) call raise_error(err, EXIT_IO, 'cannot write ' // profile_name(out, k) // '.part')
  end subroutine write_contact_frame
end module raccord_output_frame
