!> Echo of a resolved scene as a deck: every key with its final value,
!> defaults included, in a form raccord_deck's read_scene accepts again.
!>
!> The echo goes to the run's folder so that a run can be repeated from it.
!> Reals are written with the fewest digits that read back to the same
!> number, so the echo is both readable and exact; paths are written as
!> stored (the mesh path absolute), so the echo reads from any folder.
module raccord_deck_write
  use raccord_kinds, only: wp
  use raccord_error, only: error_t, raise_error, EXIT_IO
  use raccord_strings, only: str
  use raccord_material, only: KIN_FINITE, MAT_J2, kinematics_name, material_name, volumetric_name
  use raccord_scene, only: scene_t, BC_FIXED, BC_DISPLACEMENT, BC_TRACTION, BC_PRESSURE, &
    METHOD_NTS, METHOD_MORTAR, multiplier_name
  implicit none
  private

  public :: write_scene, real_text

  !> Reals per line in the echo of an amplitude table.
  integer, parameter :: TABLE_PER_LINE = 6

contains

  !> Write the scene as a deck on an open formatted unit. A write failure
  !> is returned in err (EXIT_IO) when err is present, and stops the echo.
  subroutine write_scene(scene, unit, err)
    type(scene_t), intent(in) :: scene
    integer, intent(in) :: unit
    type(error_t), intent(inout), optional :: err
    character(len=256) :: msg
    integer :: ios, k

    ios = 0
    msg = ''
    call put(unit, '! Scene resolved by raccord from ' // text_or_empty(scene%path) // &
      ': every key with its final value.', ios, msg)
    call put(unit, '! Relative output_dir is relative to the current directory.', ios, msg)

    call put(unit, '&run', ios, msg)
    call put_text(unit, 'title', text_or_empty(scene%run%title), ios, msg)
    call put_text(unit, 'output_dir', text_or_empty(scene%run%output_dir), ios, msg)
    call put(unit, '  wall_clock = ' // real_text(scene%run%wall_clock), ios, msg)
    call put(unit, '  checkpoint_every = ' // str(scene%run%checkpoint_every), ios, msg)
    call put(unit, '/', ios, msg)

    call put(unit, '&mesh', ios, msg)
    call put_text(unit, 'file', text_or_empty(scene%mesh%file), ios, msg)
    call put_text(unit, 'format', text_or_empty(scene%mesh%format, 'auto'), ios, msg)
    call put(unit, '  scale = ' // real_text(scene%mesh%scale), ios, msg)
    call put(unit, '/', ios, msg)

    if (allocated(scene%bodies)) then
      do k = 1, size(scene%bodies)
        associate (b => scene%bodies(k))
          call put(unit, '&body', ios, msg)
          call put_text(unit, 'name', text_or_empty(b%name), ios, msg)
          call put_text(unit, 'elset', text_or_empty(b%elset), ios, msg)
          call put(unit, '  young = ' // real_text(b%young), ios, msg)
          call put(unit, '  poisson = ' // real_text(b%poisson), ios, msg)
          call put(unit, '  density = ' // real_text(b%density), ios, msg)
          if (b%axisymmetric) then
            call put_text(unit, 'hypothesis', 'axisymmetric', ios, msg)
          else if (b%plane_stress) then
            call put_text(unit, 'hypothesis', 'plane_stress', ios, msg)
          else
            call put_text(unit, 'hypothesis', 'plane_strain', ios, msg)
          end if
          call put_text(unit, 'kinematics', kinematics_name(b%kinematics), ios, msg)
          call put_text(unit, 'material', material_name(b%material), ios, msg)
          if (b%kinematics == KIN_FINITE .or. b%material == MAT_J2) &
            call put_text(unit, 'volumetric', volumetric_name(b%volumetric), ios, msg)
          if (b%material == MAT_J2) then
            call put(unit, '  yield_stress = ' // real_text(b%yield_stress), ios, msg)
            call put(unit, '  hardening = ' // real_text(b%hardening), ios, msg)
          end if
          if (.not. b%axisymmetric) call put(unit, '  thickness = ' // real_text(b%thickness), ios, msg)
          call put(unit, '  velocity = ' // reals_text(b%velocity), ios, msg)
          call put(unit, '  body_force = ' // reals_text(b%body_force), ios, msg)
          call put(unit, '  damping = ' // real_text(b%damping), ios, msg)
          call put(unit, '/', ios, msg)
        end associate
      end do
    end if

    ! Amplitudes before the boundaries that name them, for the reader's sake
    ! (the deck reader itself does not mind the order).
    if (allocated(scene%amplitudes)) then
      do k = 1, size(scene%amplitudes)
        associate (a => scene%amplitudes(k))
          call put(unit, '&amplitude', ios, msg)
          call put_text(unit, 'name', text_or_empty(a%name), ios, msg)
          call put_table(unit, 'time', a%t(1:a%npoint), ios, msg)
          call put_table(unit, 'value', a%a(1:a%npoint), ios, msg)
          call put(unit, '/', ios, msg)
        end associate
      end do
    end if

    ! A boundary echoes only the keys of its type: the reader refuses the others.
    if (allocated(scene%bcs)) then
      do k = 1, size(scene%bcs)
        associate (c => scene%bcs(k))
          call put(unit, '&boundary', ios, msg)
          call put_text(unit, 'set', text_or_empty(c%set), ios, msg)
          select case (c%kind)
          case (BC_FIXED)
            call put_text(unit, 'type', 'fixed', ios, msg)
            call put_text(unit, 'components', components_text(c%comp), ios, msg)
          case (BC_DISPLACEMENT)
            call put_text(unit, 'type', 'displacement', ios, msg)
            call put_text(unit, 'components', components_text(c%comp), ios, msg)
            call put(unit, '  value = ' // reals_text(c%value), ios, msg)
            call put_text(unit, 'amplitude', text_or_empty(c%amplitude), ios, msg)
          case (BC_TRACTION)
            call put_text(unit, 'type', 'traction', ios, msg)
            call put(unit, '  value = ' // reals_text(c%value), ios, msg)
            call put_text(unit, 'amplitude', text_or_empty(c%amplitude), ios, msg)
          case (BC_PRESSURE)
            call put_text(unit, 'type', 'pressure', ios, msg)
            call put(unit, '  pressure = ' // real_text(c%pressure), ios, msg)
            call put_text(unit, 'amplitude', text_or_empty(c%amplitude), ios, msg)
          case default
            ! An unset kind cannot come from read_scene; echo it so the reader names it.
            call put_text(unit, 'type', 'unknown_' // str(c%kind), ios, msg)
          end select
          call put(unit, '/', ios, msg)
        end associate
      end do
    end if

    call put(unit, '&time', ios, msg)
    call put(unit, '  t_end = ' // real_text(scene%time%t_end), ios, msg)
    call put(unit, '  dt = ' // real_text(scene%time%dt), ios, msg)
    call put(unit, '  safety = ' // real_text(scene%time%safety), ios, msg)
    call put(unit, '  damping = ' // real_text(scene%time%damping), ios, msg)
    if (scene%time%mass_scaling_dt > 0.0_wp .or. scene%time%mass_scaling_factor > 0.0_wp) then
      call put(unit, '  mass_scaling_dt = ' // real_text(scene%time%mass_scaling_dt), ios, msg)
      call put(unit, '  mass_scaling_factor = ' // real_text(scene%time%mass_scaling_factor), ios, msg)
      call put(unit, '  added_mass_warn = ' // real_text(scene%time%added_mass_warn), ios, msg)
      call put(unit, '  kinetic_ratio_warn = ' // real_text(scene%time%kinetic_ratio_warn), ios, msg)
      call put(unit, '  kinetic_check_from = ' // real_text(scene%time%kinetic_check_from), ios, msg)
    end if
    call put(unit, '/', ios, msg)

    call put(unit, '&output', ios, msg)
    call put(unit, '  frames = ' // str(scene%output%frames), ios, msg)
    call put(unit, '  history_every = ' // str(scene%output%history_every), ios, msg)
    call put(unit, '  progress_seconds = ' // real_text(scene%output%progress_seconds), ios, msg)
    if (scene%output%stress) then
      call put(unit, '  stress = .true.', ios, msg)
    else
      call put(unit, '  stress = .false.', ios, msg)
    end if
    call put(unit, '/', ios, msg)

    if (allocated(scene%contacts)) then
      do k = 1, size(scene%contacts)
        associate (p => scene%contacts(k))
          call put(unit, '&contact_pair', ios, msg)
          call put_text(unit, 'slave', text_or_empty(p%slave), ios, msg)
          call put_text(unit, 'master', text_or_empty(p%master), ios, msg)
          select case (p%method)
          case (METHOD_MORTAR)
            call put_text(unit, 'method', 'mortar', ios, msg)
          case (METHOD_NTS)
            call put_text(unit, 'method', 'node_to_segment', ios, msg)
          case default
            call put_text(unit, 'method', 'unknown_' // str(p%method), ios, msg)
          end select
          call put_text(unit, 'multiplier', multiplier_name(p%multiplier), ios, msg)
          call put_text(unit, 'conditions', trim(merge('weighted', 'nodal   ', p%weighted)), ios, msg)
          if (p%method == METHOD_MORTAR) &
            call put_text(unit, 'edge_multipliers', trim(merge('corners  ', 'all_nodes', p%corners)), ios, msg)
          call put(unit, '  friction = ' // real_text(p%friction), ios, msg)
          call put(unit, '  search_distance = ' // real_text(p%search_distance), ios, msg)
          call put(unit, '  tolerance = ' // real_text(p%tolerance), ios, msg)
          call put(unit, '  max_iterations = ' // str(p%max_iterations), ios, msg)
          call put(unit, '/', ios, msg)
        end associate
      end do
    end if

    if (ios /= 0 .and. present(err)) then
      call raise_error(err, EXIT_IO, 'cannot write the scene echo (' // trim(msg) // &
        '); check that the output folder is writable and the disk is not full')
    end if
  end subroutine write_scene

  !> Write one line unless an earlier write failed.
  subroutine put(unit, line, ios, msg)
    integer, intent(in) :: unit
    character(len=*), intent(in) :: line
    integer, intent(inout) :: ios
    character(len=*), intent(inout) :: msg
    if (ios /= 0) return
    write(unit, '(a)', iostat=ios, iomsg=msg) line
  end subroutine put

  subroutine put_text(unit, key, value, ios, msg)
    integer, intent(in) :: unit
    character(len=*), intent(in) :: key, value
    integer, intent(inout) :: ios
    character(len=*), intent(inout) :: msg
    call put(unit, '  ' // key // ' = ' // quoted(value), ios, msg)
  end subroutine put_text

  !> A table over several lines (namelist values may continue on the next line).
  subroutine put_table(unit, key, values, ios, msg)
    integer, intent(in) :: unit
    character(len=*), intent(in) :: key
    real(wp), intent(in) :: values(:)
    integer, intent(inout) :: ios
    character(len=*), intent(inout) :: msg
    character(len=:), allocatable :: line
    integer :: k
    line = '  ' // key // ' ='
    do k = 1, size(values)
      line = line // ' ' // real_text(values(k))
      if (k < size(values)) line = line // ','
      if (mod(k, TABLE_PER_LINE) == 0 .and. k < size(values)) then
        call put(unit, line, ios, msg)
        line = '   '
      end if
    end do
    call put(unit, line, ios, msg)
  end subroutine put_table

  !> Text in single quotes, a quote inside doubled (namelist convention).
  pure function quoted(s) result(q)
    character(len=*), intent(in) :: s
    character(len=:), allocatable :: q
    integer :: k
    q = ''''
    do k = 1, len(s)
      if (s(k:k) == '''') then
        q = q // ''''''
      else
        q = q // s(k:k)
      end if
    end do
    q = q // ''''
  end function quoted

  pure function text_or_empty(s, default) result(t)
    character(len=:), allocatable, intent(in) :: s
    character(len=*), intent(in), optional :: default
    character(len=:), allocatable :: t
    if (allocated(s)) then
      t = s
    else if (present(default)) then
      t = default
    else
      t = ''
    end if
  end function text_or_empty

  pure function components_text(comp) result(s)
    logical, intent(in) :: comp(2)
    character(len=:), allocatable :: s
    s = ''
    if (comp(1)) s = s // 'x'
    if (comp(2)) s = s // 'y'
  end function components_text

  function reals_text(x) result(s)
    real(wp), intent(in) :: x(:)
    character(len=:), allocatable :: s
    integer :: k
    s = ''
    do k = 1, size(x)
      if (k > 1) s = s // ', '
      s = s // real_text(x(k))
    end do
  end function reals_text

  !> The shortest text that reads back to exactly x: fixed notation for
  !> moderate magnitudes (70000.0, 0.9), scientific otherwise (2.7E-09).
  function real_text(x) result(s)
    real(wp), intent(in) :: x
    character(len=:), allocatable :: s
    character(len=48) :: buf
    character(len=24) :: fmt
    real(wp) :: y
    integer :: d, ios
    logical :: fixed
    if (x == 0.0_wp) then
      s = '0.0'
      return
    end if
    fixed = abs(x) >= 1.0e-3_wp .and. abs(x) < 1.0e8_wp
    ! d decimals: 17 significant digits always read back exactly in real64.
    do d = 1, 17
      if (fixed) then
        write(fmt, '(a,i0,a)') '(f0.', d, ')'
      else if (abs(x) < 1.0e-99_wp .or. abs(x) >= 1.0e100_wp) then
        write(fmt, '(a,i0,a,i0,a)') '(es', d + 10, '.', min(d, 16), 'e3)'
      else
        write(fmt, '(a,i0,a,i0,a)') '(es', d + 10, '.', min(d, 16), ')'
      end if
      write(buf, fmt, iostat=ios) x
      if (ios /= 0) cycle
      read(buf, *, iostat=ios) y
      if (ios == 0 .and. y == x) exit
    end do
    s = trim(adjustl(buf))
    ! Fixed notation may drop the leading zero ('.5'); put it back for readers.
    if (s(1:1) == '.') then
      s = '0' // s
    else if (len(s) >= 2) then
      if (s(1:2) == '-.') s = '-0' // s(2:)
    end if
  end function real_text
end module raccord_deck_write
