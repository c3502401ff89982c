!> Checkpoint of a run: everything the time loop needs to go on from a step
!> boundary as if it had never stopped, in <stem>.checkpoint.h5 (layout in
!> doc/output-format.md, "Checkpoint file").
!>
!> The checkpoint is taken after advance_state, at the start of step n, when
!> the state of the explicit scheme is u(n), u(n-1) and v(n-1/2) (the rest
!> of state_t is recomputed by the step from these and the model: forces,
!> predictor, reactions, amplitudes), the running energy account (E-1, E-2),
!> and of each contact pair the status and slip direction of every slave
!> node, which warm-start the next multiplier solve (the sets of paper
!> eq. 19), plus its convergence counters. The outputs are recorded by
!> where they stand (output_mark_t). Reals are stored as IEEE doubles, so
!> a restart continues with bit-identical data.
!>
!> The file is written as <stem>.checkpoint.h5.part and renamed, so a
!> checkpoint that exists is complete; a killed write leaves the previous
!> checkpoint in place.
module raccord_checkpoint
  use hdf5, only: hid_t, h5fclose_f
  use raccord_kinds, only: wp, i8
  use raccord_error, only: error_t, raise_error, EXIT_IO, EXIT_INPUT
  use raccord_strings, only: str, append_text
  use raccord_log, only: log_warn
  use raccord_version, only: raccord_version_string
  use raccord_scene, only: scene_t
  use raccord_deck, only: write_scene
  use raccord_paths, only: absolute_path, path_dir
  use raccord_state, only: state_t
  use raccord_elastic_block, only: settle_plastic
  use raccord_contact_pair, only: contact_pair_t
  use raccord_output, only: output_mark_t
  use raccord_files, only: rename_file, delete_file, file_exists, write_failure_reason, crc_of_file
  use raccord_h5, only: h5_acquire, h5_release, h5_create_file, h5_write_real, h5_write_int, h5_write_text, h5_attr_text, &
    h5_attr_int, h5_link_exists
  use raccord_crc32, only: crc32_t, crc_add, crc_value, crc_hex
  use raccord_mesh, only: mesh_t
  use raccord_h5_read, only: h5_read_real, h5_read_int, h5_read_i8, h5_read_text, h5_read_attr_text, h5_write_i8, &
    h5_read_attr_int, h5_open_input
  implicit none
  private

  public :: checkpoint_name, write_checkpoint, read_checkpoint, checkpoint_scene_path, scene_identity

  !> Version of the checkpoint layout; a checkpoint of another version is refused.
  !> 4: /scene ends with the mesh line of mesh_identity.
  integer, parameter, public :: CHECKPOINT_FORMAT_VERSION = 4
  character(len=*), parameter :: FORMAT_NAME = 'raccord checkpoint'
  !> Keys that do not change the results: a restart may change them.
  character(len=*), parameter :: FREE_KEYS(*) = [character(len=20) :: 'output_dir', 'wall_clock', &
    'checkpoint_every', 'progress_seconds']

contains

  !> <stem>.checkpoint.h5
  pure function checkpoint_name(stem) result(path)
    character(len=*), intent(in) :: stem
    character(len=:), allocatable :: path
    path = stem // '.checkpoint.h5'
  end function checkpoint_name

  !> The resolved scene as a restart compares it: the echo of write_scene
  !> without comments and without the keys that do not change the results
  !> (output_dir, wall_clock, checkpoint_every, progress_seconds).
  function scene_identity(scene, err) result(text)
    type(scene_t), intent(in) :: scene
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: text
    integer :: unit, ios, k, n
    character(len=1024) :: line
    character(len=256) :: msg
    character(len=:), allocatable :: buf
    logical :: keep
    ! buf(1:n) grows by doubling (append_text): text = text // line copied
    ! the whole echo at each line, and a deck of 10^4 groups (an echo of
    ! 10^5 lines) spent most of a minute here before the first step
    n = 0
    text = ''
    open(newunit=unit, status='scratch', action='readwrite', form='formatted', iostat=ios, iomsg=msg)
    if (ios /= 0) then
      call raise_error(err, EXIT_IO, 'cannot open a scratch file for the scene echo: ' // trim(msg))
      return
    end if
    call write_scene(scene, unit, err)
    rewind(unit)
    do
      read(unit, '(a)', iostat=ios) line
      if (ios /= 0) exit
      keep = len_trim(line) > 0
      if (keep) keep = line(1:1) /= '!'
      do k = 1, size(FREE_KEYS)
        if (index(adjustl(line), trim(FREE_KEYS(k)) // ' =') == 1) keep = .false.
      end do
      if (keep) call append_text(buf, n, trim(line) // new_line('a'))
    end do
    close(unit)
    if (n > 0) text = buf(1:n)
  end function scene_identity

  !> The mesh as a restart compares it: the deck names the mesh file by its
  !> path only, and a mesh edited between the stop and the restart (a node
  !> moved, a set grown) would otherwise be taken silently, the run going on
  !> from a state of the old mesh. One line: counts and a CRC-32 of the
  !> coordinates (as read, before &mesh scale), ids, connectivity, sets and
  !> surfaces.
  function mesh_identity(mesh) result(text)
    type(mesh_t), intent(in) :: mesh
    character(len=:), allocatable :: text
    type(crc32_t) :: c
    integer :: k
    if (allocated(mesh%x)) call crc_add(c, mesh%x)
    if (allocated(mesh%node_id)) call crc_add(c, mesh%node_id)
    if (allocated(mesh%etype)) call crc_add(c, mesh%etype)
    if (allocated(mesh%conn)) call crc_add(c, reshape(mesh%conn, [size(mesh%conn)]))
    if (allocated(mesh%elem_id)) call crc_add(c, mesh%elem_id)
    if (allocated(mesh%nsets)) then
      do k = 1, size(mesh%nsets)
        call crc_add(c, mesh%nsets(k)%name)
        call crc_add(c, mesh%nsets(k)%nodes)
      end do
    end if
    if (allocated(mesh%esets)) then
      do k = 1, size(mesh%esets)
        call crc_add(c, mesh%esets(k)%name)
        call crc_add(c, mesh%esets(k)%elems)
      end do
    end if
    if (allocated(mesh%surfaces)) then
      do k = 1, size(mesh%surfaces)
        call crc_add(c, mesh%surfaces(k)%name)
        if (mesh%surfaces(k)%nedge > 0) call crc_add(c, reshape(mesh%surfaces(k)%edge(:, 1:mesh%surfaces(k)%nedge), &
          [size(mesh%surfaces(k)%edge, 1)*mesh%surfaces(k)%nedge]))
      end do
    end if
    text = 'mesh ' // str(mesh%nnode) // ' nodes, ' // str(mesh%nelem) // ' elements, CRC-32 ' // &
      crc_hex(crc_value(c)) // new_line('a')
  end function mesh_identity

  !> Write <stem>.checkpoint.h5 (via .part and rename).
  !> watch: the record of the run's watchers (the quasi-static check, the
  !> contact energy watch), kept so that a restarted run reports on the
  !> whole run; they only report, so it is not in the checksum.
  subroutine write_checkpoint(stem, scene, mesh, state, pairs, mark, watch, err)
    character(len=*), intent(in) :: stem
    type(scene_t), intent(in) :: scene
    type(mesh_t), intent(in) :: mesh
    type(state_t), intent(in) :: state
    type(contact_pair_t), intent(in) :: pairs(:)
    type(output_mark_t), intent(in) :: mark
    real(wp), intent(in) :: watch(:)
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: part, where, identity, g
    integer(hid_t) :: file
    integer :: hdferr, k, ib, kb
    integer(i8), allocatable :: file_crc(:)
    type(error_t) :: cerr

    if (err%failed()) return
    identity = scene_identity(scene, err) // mesh_identity(mesh)
    if (err%failed()) return
    part = checkpoint_name(stem) // '.part'
    where = 'checkpoint "' // part // '"'
    call h5_acquire(err)
    if (err%failed()) return
    call h5_create_file(part, file, hdferr)
    if (hdferr /= 0) then
      call raise_error(err, EXIT_IO, 'cannot create ' // where // ': ' // write_failure_reason(path_dir(part)))
      call h5_release(err)
      return
    end if
    call h5_attr_text(file, 'format', FORMAT_NAME, where, err)
    call h5_attr_int(file, 'format_version', CHECKPOINT_FORMAT_VERSION, where, err)
    call h5_attr_text(file, 'raccord_version', raccord_version_string, where, err)
    call h5_write_text(file, '/scene', identity, where, err)
    call h5_write_text(file, '/scene_path', absolute_path(scene%path), where, err)
    ! The scheme's state at the start of step n.
    call h5_write_i8(file, '/state/counters', [state%step, state%nsteps], where, err)
    call h5_write_real(file, '/state/time_dt', [state%time, state%dt], where, err)
    call h5_write_real(file, '/state/u', state%u, where, err)
    call h5_write_real(file, '/state/u_prev', state%u_prev, where, err)
    call h5_write_real(file, '/state/v', state%v, where, err)
    associate (e => state%energy)
      call h5_write_real(file, '/state/energy', [e%kinetic, e%internal, e%discrete, e%external, e%damping, &
        e%contact, e%friction, e%initial, e%balance, e%scale], where, err)
    end associate
    ! j2 bodies: plastic work and the internal variables after the last step
    if (allocated(state%plastic)) then
      if (any_plastic(state)) call h5_write_real(file, '/state/plastic_work', [state%energy%plastic], where, err)
      do ib = 1, size(state%plastic, 2)
        do kb = 1, size(state%plastic, 1)
          if (.not. allocated(state%plastic(kb, ib)%h)) cycle
          associate (h => state%plastic(kb, ib)%h)
            call h5_write_real(file, plastic_path(kb, ib), reshape(h, [size(h)/size(h, 4), size(h, 4)]), where, err)
          end associate
        end do
      end do
    end if
    ! Contact: the sets that warm-start the next solve, and the counters.
    do k = 1, size(pairs)
      g = '/contact/pair_' // str(k) // '/'
      call h5_write_int(file, g // 'status', pairs(k)%status, where, err)
      call h5_write_real(file, g // 'sigma', pairs(k)%sigma, where, err)
      call h5_write_i8(file, g // 'counters', [int(pairs(k)%failed_streak, i8), pairs(k)%failed_total, &
        pairs(k)%iterations_total, pairs(k)%steps], where, err)
      call h5_write_real(file, g // 'residual_max', [pairs(k)%residual_max], where, err)
      call h5_write_i8(file, g // 'profile_bytes', [mark%profile_bytes(k)], where, err)
      ! The feet that warm-start node-to-segment's projections (raccord_contact_verlet).
      call h5_write_int(file, g // 'foot_segment', pairs(k)%verlet%warm_seg, where, err)
      call h5_write_real(file, g // 'foot_t', pairs(k)%verlet%warm_t, where, err)
    end do
    call h5_write_real(file, '/watch', watch, where, err)
    ! Outputs: frames and history rows so far (the rows themselves are in
    ! /history of the results file), and the files' lengths.
    call h5_write_i8(file, '/output/counters', [int(mark%frames_written, i8), mark%nrow, &
      mark%history_bytes, int(mark%ncol, i8)], where, err)
    ! Checksums: of the running text files up to their recorded lengths,
    ! and of everything above (checkpoint_crc), verified by a restart.
    allocate(file_crc(1 + size(pairs)))
    file_crc(1) = crc_of_file(stem // '.history.txt.part', mark%history_bytes)
    do k = 1, size(pairs)
      file_crc(1 + k) = crc_of_file(stem // '.contact' // str(k) // '.txt.part', mark%profile_bytes(k))
    end do
    call h5_write_i8(file, '/output/file_crc', file_crc, where, err)
    call h5_write_i8(file, '/crc32', [checkpoint_crc(identity, absolute_path(scene%path), state, pairs, mark, &
      file_crc)], where, err)
    call h5fclose_f(file, hdferr)
    if (hdferr /= 0) call raise_error(err, EXIT_IO, 'cannot close ' // where // ' (disk full?)')
    call h5_release(cerr)
    if (err%failed()) then
      call delete_file(part)
      return
    end if
    call rename_file(part, checkpoint_name(stem), err)
  end subroutine write_checkpoint

  !> The absolute path of the deck a checkpoint was written for.
  subroutine checkpoint_scene_path(path, scene_path, err)
    character(len=*), intent(in) :: path
    character(len=:), allocatable, intent(out) :: scene_path
    type(error_t), intent(inout) :: err
    integer(hid_t) :: file
    character(len=:), allocatable :: where
    scene_path = ''
    where = 'checkpoint "' // path // '"'
    call open_checkpoint(path, file, err)
    if (err%failed()) return
    call h5_read_text(file, '/scene_path', scene_path, where, err)
    call close_checkpoint(file, where, err)
  end subroutine checkpoint_scene_path

  !> Read a checkpoint into a state and pairs made for the same scene
  !> (init_state, init_contact_pairs): refused with EXIT_INPUT when the
  !> scene differs (first differing line named), when the file is not a
  !> complete raccord checkpoint of this layout, or when its arrays do not
  !> fit the model. ncol: number of history columns of this scene.
  !> watch: the watchers' record of write_checkpoint, when it has the
  !> length of this scene's (else left unallocated: the watchers start anew).
  subroutine read_checkpoint(path, scene, mesh, state, pairs, ncol, mark, watch, err)
    character(len=*), intent(in) :: path
    type(scene_t), intent(in) :: scene
    type(mesh_t), intent(in) :: mesh
    type(state_t), intent(inout) :: state
    type(contact_pair_t), intent(inout) :: pairs(:)
    integer, intent(in) :: ncol
    type(output_mark_t), intent(out) :: mark
    real(wp), allocatable, intent(inout) :: watch(:)
    type(error_t), intent(inout) :: err
    integer(hid_t) :: file
    character(len=:), allocatable :: where, text, identity, g, scene_part, mesh_part
    integer(i8) :: counters(4), two(2), four(4), one(1)
    real(wp) :: td(2), en(10), r1(1)
    real(wp), allocatable :: flat(:,:)
    integer :: k, ib, kb

    where = 'checkpoint "' // path // '"'
    scene_part = scene_identity(scene, err)
    if (err%failed()) return
    mesh_part = mesh_identity(mesh)
    identity = scene_part // mesh_part
    call open_checkpoint(path, file, err)
    if (err%failed()) return
    steps: block
      call h5_read_attr_text(file, 'raccord_version', text, where, err)
      if (err%failed()) exit steps
      if (text /= raccord_version_string) call log_warn('checkpoint', where // ' was written by raccord ' // &
        text // ', this is ' // raccord_version_string // ': the results may differ in round-off from an ' // &
        'uninterrupted run')
      call h5_read_text(file, '/scene', text, where, err)
      if (err%failed()) exit steps
      if (text /= identity .and. index(text, scene_part) == 1) then
        call raise_error(err, EXIT_INPUT, 'restart refused: mesh ' // mesh%source // ' is not the one ' // &
          path // ' was written with (the checkpoint has "' // trim(text(len(scene_part) + 1:len(text) - 1)) // &
          '", the file now "' // mesh_part(1:len(mesh_part) - 1) // '"): it changed since the run ' // &
          'stopped. Restore it, or run afresh without --restart')
        exit steps
      else if (text /= identity) then
        call raise_error(err, EXIT_INPUT, 'restart refused: scene ' // scene%path // ' is not the one ' // &
          path // ' was written for; ' // first_difference(text, identity) // '. Restart with the same ' // &
          'scene, or run the changed scene afresh without --restart')
        exit steps
      end if
      call h5_read_i8(file, '/state/counters', two, where, err)
      call h5_read_real(file, '/state/time_dt', td, where, err)
      if (err%failed()) exit steps
      if (state%adaptive) then
        ! variable step (finite strain): the step count and the last step
        ! are the run's own, taken from the checkpoint
        state%nsteps = two(2)
        state%dt = td(2)
      else if (two(2) /= state%nsteps .or. td(2) /= state%dt) then
        call raise_error(err, EXIT_INPUT, 'restart refused: ' // where // ' has ' // str(two(2)) // &
          ' steps of dt = ' // str(td(2)) // ', this run plans ' // str(state%nsteps) // ' of dt = ' // &
          str(state%dt) // ' (another raccord build, or a changed mesh file?)')
        exit steps
      end if
      if (two(1) < 1 .or. two(1) > two(2)) then
        call raise_error(err, EXIT_INPUT, where // ' is damaged: step ' // str(two(1)) // ' of ' // str(two(2)))
        exit steps
      end if
      state%step = two(1)
      state%time = td(1)
      call h5_read_real(file, '/state/u', state%u, where, err)
      call h5_read_real(file, '/state/u_prev', state%u_prev, where, err)
      call h5_read_real(file, '/state/v', state%v, where, err)
      call h5_read_real(file, '/state/energy', en, where, err)
      if (err%failed()) exit steps
      associate (e => state%energy)
        e%kinetic = en(1); e%internal = en(2); e%discrete = en(3); e%external = en(4); e%damping = en(5)
        e%contact = en(6); e%friction = en(7); e%initial = en(8); e%balance = en(9); e%scale = en(10)
      end associate
      if (allocated(state%plastic)) then
        if (any_plastic(state)) then
          call h5_read_real(file, '/state/plastic_work', r1, where, err)
          if (err%failed()) exit steps
          state%energy%plastic = r1(1)
        end if
        do ib = 1, size(state%plastic, 2)
          do kb = 1, size(state%plastic, 1)
            if (.not. allocated(state%plastic(kb, ib)%h)) cycle
            associate (h => state%plastic(kb, ib)%h)
              allocate(flat(size(h)/size(h, 4), size(h, 4)))
              call h5_read_real(file, plastic_path(kb, ib), flat, where, err)
              if (err%failed()) exit steps
              h = reshape(flat, shape(h))
              deallocate(flat)
            end associate
            ! the chunks still virgin, from the internal variables read
            call settle_plastic(state%plastic(kb, ib))
          end do
        end do
      end if
      if (h5_link_exists(file, '/contact/pair_' // str(size(pairs) + 1))) then
        call raise_error(err, EXIT_INPUT, where // ' has more contact pairs than the scene (' // str(size(pairs)) // ')')
        exit steps
      end if
      allocate(mark%profile_bytes(size(pairs)))
      do k = 1, size(pairs)
        g = '/contact/pair_' // str(k) // '/'
        call h5_read_int(file, g // 'status', pairs(k)%status, where, err)
        call h5_read_real(file, g // 'sigma', pairs(k)%sigma, where, err)
        call h5_read_i8(file, g // 'counters', counters, where, err)
        call h5_read_real(file, g // 'residual_max', r1, where, err)
        call h5_read_i8(file, g // 'profile_bytes', one, where, err)
        ! Without them (an older checkpoint) the projections start cold: the
        ! same feet to round-off.
        if (h5_link_exists(file, g // 'foot_t')) then
          call h5_read_int(file, g // 'foot_segment', pairs(k)%verlet%warm_seg, where, err)
          call h5_read_real(file, g // 'foot_t', pairs(k)%verlet%warm_t, where, err)
        end if
        if (err%failed()) exit steps
        pairs(k)%failed_streak = int(counters(1))
        pairs(k)%failed_total = counters(2)
        pairs(k)%iterations_total = counters(3)
        pairs(k)%steps = counters(4)
        pairs(k)%residual_max = r1(1)
        mark%profile_bytes(k) = one(1)
      end do
      call h5_read_i8(file, '/output/counters', four, where, err)
      if (err%failed()) exit steps
      if (any(four < 0) .or. four(1) > huge(1)) then
        call raise_error(err, EXIT_INPUT, where // ' is damaged: output counters ' // str(four(1)) // ', ' // &
          str(four(2)) // ', ' // str(four(3)) // ', ' // str(four(4)))
        exit steps
      end if
      mark%frames_written = int(four(1))
      mark%nrow = four(2)
      mark%history_bytes = four(3)
      if (four(4) /= int(ncol, i8)) then
        call raise_error(err, EXIT_INPUT, where // ' has a history of ' // str(four(4)) // ' columns, the ' // &
          'scene makes ' // str(ncol) // '; run the scene afresh without --restart')
        exit steps
      end if
      mark%ncol = ncol
      ! (nested tests: gfortran may drop the call of an impure function
      ! in '.and.', -Wfunction-elimination; the query must run here)
      if (allocated(watch)) then
        if (h5_link_exists(file, '/watch')) then
          call h5_read_real(file, '/watch', watch, where, err)
          if (err%failed()) exit steps
        else
          deallocate(watch)
        end if
      end if
      call verify_checkpoint(file, path, identity, state, pairs, mark, err)
    end block steps
    call close_checkpoint(file, where, err)
  end subroutine read_checkpoint

  ! --- private -----------------------------------------------------------

  !> CRC-32 of what a checkpoint holds, in the order it is written.
  function checkpoint_crc(identity, scene_path, state, pairs, mark, file_crc) result(crc)
    character(len=*), intent(in) :: identity, scene_path
    type(state_t), intent(in) :: state
    type(contact_pair_t), intent(in) :: pairs(:)
    type(output_mark_t), intent(in) :: mark
    integer(i8), intent(in) :: file_crc(:)
    integer(i8) :: crc
    type(crc32_t) :: c
    integer :: k, ib, kb
    call crc_add(c, identity)
    call crc_add(c, scene_path)
    call crc_add(c, [state%step, state%nsteps])
    call crc_add(c, [state%time, state%dt])
    call crc_add(c, state%u)
    call crc_add(c, state%u_prev)
    call crc_add(c, state%v)
    associate (e => state%energy)
      call crc_add(c, [e%kinetic, e%internal, e%discrete, e%external, e%damping, e%contact, e%friction, &
        e%initial, e%balance, e%scale])
    end associate
    if (allocated(state%plastic)) then
      if (any_plastic(state)) call crc_add(c, [state%energy%plastic])
      do ib = 1, size(state%plastic, 2)
        do kb = 1, size(state%plastic, 1)
          if (.not. allocated(state%plastic(kb, ib)%h)) cycle
          associate (h => state%plastic(kb, ib)%h)
            call crc_add(c, reshape(h, [size(h)/size(h, 4), size(h, 4)]))
          end associate
        end do
      end do
    end if
    do k = 1, size(pairs)
      call crc_add(c, pairs(k)%status)
      call crc_add(c, pairs(k)%sigma)
      call crc_add(c, [int(pairs(k)%failed_streak, i8), pairs(k)%failed_total, pairs(k)%iterations_total, &
        pairs(k)%steps])
      call crc_add(c, [pairs(k)%residual_max])
      call crc_add(c, [mark%profile_bytes(k)])
    end do
    call crc_add(c, [int(mark%frames_written, i8), mark%nrow, mark%history_bytes, int(mark%ncol, i8)])
    call crc_add(c, file_crc)
    crc = crc_value(c)
  end function checkpoint_crc

  !> A checkpoint just read must have the checksum it was written with,
  !> and the running text files of its run must still hold, up to the
  !> lengths it recorded, the bytes they held then: a flipped or zeroed
  !> byte is refused (issue #18), not continued into results that differ
  !> from an uninterrupted run.
  subroutine verify_checkpoint(file, path, identity, state, pairs, mark, err)
    integer(hid_t), intent(in) :: file
    character(len=*), intent(in) :: path, identity
    type(state_t), intent(in) :: state
    type(contact_pair_t), intent(in) :: pairs(:)
    type(output_mark_t), intent(in) :: mark
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: where, scene_path, stem, name
    integer(i8), allocatable :: file_crc(:)
    integer(i8) :: stored(1), now
    integer :: k
    where = 'checkpoint "' // path // '"'
    stem = path(1:len(path) - len('.checkpoint.h5'))
    if (.not. h5_link_exists(file, '/crc32') .or. .not. h5_link_exists(file, '/output/file_crc')) then
      call raise_error(err, EXIT_INPUT, where // ' has no checksum (written by an older raccord, or damaged): ' // &
        'run the scene afresh without --restart')
      return
    end if
    allocate(file_crc(1 + size(pairs)))
    call h5_read_text(file, '/scene_path', scene_path, where, err)
    call h5_read_i8(file, '/output/file_crc', file_crc, where, err)
    call h5_read_i8(file, '/crc32', stored, where, err)
    if (err%failed()) return
    now = checkpoint_crc(identity, scene_path, state, pairs, mark, file_crc)
    if (now /= stored(1)) then
      call raise_error(err, EXIT_INPUT, 'restart refused: ' // where // ' is damaged (its CRC-32 checksum is ' // &
        str(now) // ', it was written with ' // str(stored(1)) // '): run the scene afresh without --restart')
      return
    end if
    do k = 0, size(pairs)
      if (k == 0) then
        name = stem // '.history.txt.part'
        now = crc_of_file(name, mark%history_bytes)
      else
        name = stem // '.contact' // str(k) // '.txt.part'
        now = crc_of_file(name, mark%profile_bytes(k))
      end if
      if (now /= file_crc(1 + k)) then
        call raise_error(err, EXIT_INPUT, 'restart refused: ' // name // ' is missing, shorter than its ' // &
          'checkpoint recorded, or damaged (its first bytes no longer have the checksum ' // where // &
          ' recorded): run the scene afresh without --restart')
        return
      end if
    end do
  end subroutine verify_checkpoint

  !> Open a checkpoint read-only and check its format and version.
  subroutine open_checkpoint(path, file, err)
    character(len=*), intent(in) :: path
    integer(hid_t), intent(out) :: file
    type(error_t), intent(inout) :: err
    character(len=:), allocatable :: where, fmt, version
    integer :: fv
    file = -1
    if (err%failed()) return
    where = 'checkpoint "' // path // '"'
    call h5_open_input(path, where, 'give the <stem>.checkpoint.h5 a stopped run wrote (a .part file is an ' // &
      'unfinished checkpoint and cannot be used), or run the scene afresh without --restart', '', file, err)
    if (err%failed()) return
    call h5_read_attr_text(file, 'format', fmt, where, err)
    if (.not. err%failed()) then
      if (fmt /= FORMAT_NAME) call raise_error(err, EXIT_INPUT, where // ' is not a raccord checkpoint (format "' // &
        fmt // '")')
    end if
    call h5_read_attr_int(file, 'format_version', fv, where, err)
    if (.not. err%failed()) then
      if (fv /= CHECKPOINT_FORMAT_VERSION) call raise_error(err, EXIT_INPUT, where // ' has the layout of ' // &
        'format version ' // str(fv) // ', this raccord reads version ' // str(CHECKPOINT_FORMAT_VERSION) // &
        ' only; run the scene afresh without --restart (or finish it with the raccord that wrote it)')
    end if
    if (.not. err%failed()) call h5_read_attr_text(file, 'raccord_version', version, where, err)
    if (.not. err%failed()) then
      if (.not. h5_link_exists(file, '/state/u')) call raise_error(err, EXIT_INPUT, where // ' is incomplete')
    end if

    if (err%failed()) call close_checkpoint(file, where, err)
  end subroutine open_checkpoint

  subroutine close_checkpoint(file, where, err)
    integer(hid_t), intent(inout) :: file
    character(len=*), intent(in) :: where
    type(error_t), intent(inout) :: err
    integer :: hdferr
    type(error_t) :: cerr
    if (file == -1) return
    call h5fclose_f(file, hdferr)
    if (hdferr /= 0) call raise_error(err, EXIT_IO, 'cannot close ' // where)
    file = -1
    call h5_release(cerr)
  end subroutine close_checkpoint

  !> "first difference: checkpoint 'a', scene 'b'" between two echoes.
  function first_difference(a, b) result(s)
    character(len=*), intent(in) :: a, b
    character(len=:), allocatable :: s
    integer :: ia, ib, ea, eb
    character(len=:), allocatable :: group, la, lb
    character(len=1), parameter :: nl = new_line('a')
    ia = 1
    ib = 1
    group = ''
    do
      ea = next_end(a, ia)
      eb = next_end(b, ib)
      if (ia > len(a) .and. ib > len(b)) then
        s = 'they differ'
        return
      end if
      if (a(ia:ea) /= b(ib:eb)) exit
      la = trim(adjustl(a(ia:ea)))
      if (len(la) > 0) then
        if (la(1:1) == '&') group = la
      end if
      ia = ea + 2
      ib = eb + 2
    end do
    la = trim(adjustl(a(ia:ea)))
    lb = trim(adjustl(b(ib:eb)))
    ! A key that one echo has and the other not (the mass-scaling keys are
    ! echoed only when given) meets the other's group end "/".
    if (la == '/') then
      s = 'first difference: the scene has "' // lb // '", which the checkpoint''s scene has not'
    else if (lb == '/') then
      s = 'first difference: the checkpoint''s scene has "' // la // '", which the scene has not'
    else
      s = 'first difference: the checkpoint has "' // la // '", the scene "' // lb // '"'
    end if
    if (len(group) > 0 .and. la(1:min(1, len(la))) /= '&') s = s // ' (in ' // group // ')'
  contains
    pure integer function next_end(t, i0) result(e)
      character(len=*), intent(in) :: t
      integer, intent(in) :: i0
      integer :: k
      if (i0 > len(t)) then
        e = i0 - 1
        return
      end if
      k = index(t(i0:), nl)
      if (k == 0) then
        e = len(t)
      else
        e = i0 + k - 2
      end if
    end function next_end
  end function first_difference
  !> Some block of the run is j2 (has internal variables).
  pure logical function any_plastic(state)
    type(state_t), intent(in) :: state
    integer :: ib, kb
    any_plastic = .false.
    do ib = 1, size(state%plastic, 2)
      do kb = 1, size(state%plastic, 1)
        if (allocated(state%plastic(kb, ib)%h)) any_plastic = .true.
      end do
    end do
  end function any_plastic

  !> Dataset of the internal variables of block kb of body ib.
  pure function plastic_path(kb, ib) result(p)
    integer, intent(in) :: kb, ib
    character(len=:), allocatable :: p
    p = '/state/plastic_body' // str(ib) // '_block' // str(kb)
  end function plastic_path
end module raccord_checkpoint
