!> Tests of the scene deck reader (raccord_deck): a full deck read value by
!> value, the defaults of a minimal deck, the resolution of relative paths,
!> the round trip read -> write_scene -> read, and one test per kind of bad
!> deck, each checking the error code and that the message names the deck,
!> the line and the group, key or value at fault.
!>
!> Bad decks are written by the tests into the working directory as
!> scene_bad_<case>.nml, so each case reads in one place with its expectation.
program test_scene_deck
  use raccord_kinds, only: wp
  use raccord_error, only: error_t, EXIT_INPUT
  use raccord_strings, only: str, ends_with
  use raccord_scene, only: scene_t, BC_FIXED, BC_DISPLACEMENT, BC_TRACTION, BC_PRESSURE, &
    METHOD_NTS, METHOD_MORTAR, MULT_P1, MULT_DUAL
  use raccord_deck, only: read_scene, write_scene
  use raccord_paths, only: current_dir
  use raccord_check, only: failure_t, new_test, run_tests, check, check_close, fail_now
  implicit none

  integer, parameter :: FRAG_LEN = 40    !< longest expected message fragment
  character(len=1), parameter :: NL = achar(10)   !< line separator in generated decks

  call run_tests('scene_deck', [ &
      new_test('full deck: every value', test_full_deck), &
      new_test('minimal deck: defaults', test_minimal_defaults), &
      new_test('relative mesh path: against the deck folder', test_relative_mesh_path), &
      new_test('relative deck path: absolute mesh path, cwd-relative output', test_cwd_relative_deck), &
      new_test('round trip: full deck', test_roundtrip_full), &
      new_test('round trip: minimal deck', test_roundtrip_minimal), &
      new_test('echo: defaults written', test_echo_lists_defaults), &
      new_test('base of the bad decks reads', test_base_deck_reads), &
      new_test('bad: deck file missing', test_missing_deck_file), &
      new_test('bad: unknown group', bad_unknown_group), &
      new_test('bad: unknown key', bad_unknown_key), &
      new_test('bad: key line in multiline group', bad_key_line_in_multiline_group), &
      new_test('bad: malformed real quoted', bad_malformed_real_quoted), &
      new_test('bad: malformed real word', bad_malformed_real_word), &
      new_test('bad: malformed integer', bad_malformed_integer), &
      new_test('bad: malformed logical', bad_malformed_logical), &
      new_test('bad: text not quoted', bad_text_not_quoted), &
      new_test('bad: too many values', bad_too_many_values), &
      new_test('bad: subscript out of range', bad_subscript_out_of_range), &
      new_test('bad: key without value', bad_key_without_value), &
      new_test('bad: not finite', bad_not_finite), &
      new_test('bad: duplicate key', bad_duplicate_key), &
      new_test('bad: missing slash', bad_missing_slash), &
      new_test('bad: missing slash at end', bad_missing_slash_at_end), &
      new_test('bad: unclosed string', bad_unclosed_string), &
      new_test('bad: text outside group', bad_text_outside_group), &
      new_test('bad: duplicate mesh', bad_duplicate_mesh), &
      new_test('bad: duplicate time', bad_duplicate_time), &
      new_test('bad: duplicate run', bad_duplicate_run), &
      new_test('bad: duplicate output', bad_duplicate_output), &
      new_test('bad: missing mesh', bad_missing_mesh), &
      new_test('bad: missing time', bad_missing_time), &
      new_test('bad: missing body', bad_missing_body), &
      new_test('bad: mesh file missing', bad_mesh_file_missing), &
      new_test('bad: mesh format unknown', bad_mesh_format_unknown), &
      new_test('bad: mesh scale nonpositive', bad_mesh_scale_nonpositive), &
      new_test('bad: body name missing', bad_body_name_missing), &
      new_test('bad: young missing', bad_young_missing), &
      new_test('bad: young nonpositive', bad_young_nonpositive), &
      new_test('bad: poisson too high', bad_poisson_too_high), &
      new_test('bad: poisson too low', bad_poisson_too_low), &
      new_test('bad: density nonpositive', bad_density_nonpositive), &
      new_test('bad: thickness nonpositive', bad_thickness_nonpositive), &
      new_test('bad: body damping negative', bad_body_damping_negative), &
      new_test('body damping: own value, else the &time damping', test_body_damping), &
      new_test('bad: hypothesis unknown', bad_hypothesis_unknown), &
      new_test('bad: duplicate body name', bad_duplicate_body_name), &
      new_test('bad: t end missing', bad_t_end_missing), &
      new_test('bad: t end nonpositive', bad_t_end_nonpositive), &
      new_test('bad: dt negative', bad_dt_negative), &
      new_test('bad: safety above one', bad_safety_above_one), &
      new_test('bad: safety zero', bad_safety_zero), &
      new_test('bad: damping negative', bad_damping_negative), &
      new_test('bad: mass scaling factor below one', bad_mass_scaling_factor), &
      new_test('bad: mass scaling dt and factor both', bad_mass_scaling_both), &
      new_test('bad: mass scaling with a fixed dt', bad_mass_scaling_fixed_dt), &
      new_test('bad: frames negative', bad_frames_negative), &
      new_test('bad: bc set missing', bad_bc_set_missing), &
      new_test('bad: bc type missing', bad_bc_type_missing), &
      new_test('bad: bc type unknown', bad_bc_type_unknown), &
      new_test('bad: bc components unknown', bad_bc_components_unknown), &
      new_test('bad: bc components missing', bad_bc_components_missing), &
      new_test('bad: bc value missing', bad_bc_value_missing), &
      new_test('bad: bc pressure missing', bad_bc_pressure_missing), &
      new_test('bad: bc key not for type', bad_bc_key_not_for_type), &
      new_test('bad: bc amplitude undefined', bad_bc_amplitude_undefined), &
      new_test('bad: bc amplitude in another case', bad_bc_amplitude_case), &
      new_test('bad: amplitude not increasing', bad_amplitude_not_increasing), &
      new_test('bad: amplitude count mismatch', bad_amplitude_count_mismatch), &
      new_test('bad: amplitude no points', bad_amplitude_no_points), &
      new_test('bad: amplitude gap', bad_amplitude_gap), &
      new_test('bad: duplicate amplitude name', bad_duplicate_amplitude_name), &
      new_test('bad: contact master missing', bad_contact_master_missing), &
      new_test('bad: slave equals master', bad_slave_equals_master), &
      new_test('bad: method unknown', bad_method_unknown), &
      new_test('bad: multiplier unknown', bad_multiplier_unknown), &
      new_test('bad: contact conditions unknown', bad_conditions_unknown), &
      new_test('bad: conditions = weighted with node-to-segment', bad_conditions_nts), &
      new_test('bad: friction negative', bad_friction_negative), &
      new_test('bad: tolerance nonpositive', bad_tolerance_nonpositive), &
      new_test('bad: max iterations zero', bad_max_iterations_zero), &
      new_test('bad: overflowing value', bad_overflowing_value), &
      new_test('bad: run wall_clock negative', bad_wall_clock_negative), &
      new_test('bad: run checkpoint_every negative', bad_checkpoint_every_negative) &
      ])

contains

  ! ------------------------------------------------------------ helpers

  !> Folder of the test data (tests/data), from RACCORD_TEST_DATA.
  function data_dir() result(dir)
    character(len=:), allocatable :: dir
    character(len=4096) :: buf
    integer :: n, stat
    call get_environment_variable('RACCORD_TEST_DATA', buf, n, stat)
    if (stat /= 0) then
      dir = ''
    else
      dir = buf(1:n)
    end if
  end function data_dir

  !> Read a deck that must be good; the failure carries the reader's message.
  subroutine read_good(failure, path, scene)
    type(failure_t), allocatable, intent(inout) :: failure
    character(len=*), intent(in) :: path
    type(scene_t), intent(out) :: scene
    type(error_t) :: err
    call read_scene(path, scene, err)
    if (err%failed()) then
      if (allocated(err%message)) then
        call fail_now(failure, 'reading ' // path // ' failed: ' // err%message)
      else
        call fail_now(failure, 'reading ' // path // ' failed without a message')
      end if
    end if
  end subroutine read_good

  subroutine check_text(failure, actual, expected, what)
    type(failure_t), allocatable, intent(inout) :: failure
    character(len=:), allocatable, intent(in) :: actual
    character(len=*), intent(in) :: expected, what
    if (.not. allocated(actual)) then
      call fail_now(failure, what // ': not set, expected ''' // expected // '''')
    else
      call check(failure, actual == expected .and. len(actual) == len(expected), &
        what // ': got ''' // actual // ''', expected ''' // expected // '''')
    end if
  end subroutine check_text

  !> Write a deck given as one string whose lines are separated by NL
  !> (one string per deck keeps each case's lines together, of any length).
  subroutine write_lines(failure, path, text)
    type(failure_t), allocatable, intent(inout) :: failure
    character(len=*), intent(in) :: path
    character(len=*), intent(in) :: text
    character(len=256) :: msg
    integer :: u, ios, first, k
    msg = ''
    open(newunit=u, file=path, status='replace', action='write', iostat=ios, iomsg=msg)
    if (ios /= 0) then
      call fail_now(failure, 'cannot write ' // path // ': ' // trim(msg))
      return
    end if
    first = 1
    do
      k = index(text(first:), NL)
      if (k == 0) then
        write(u, '(a)', iostat=ios, iomsg=msg) text(first:)
        exit
      end if
      write(u, '(a)', iostat=ios, iomsg=msg) text(first:first+k-2)
      if (ios /= 0) exit
      first = first + k
    end do
    close(u)
    call check(failure, ios == 0, 'cannot write ' // path // ': ' // trim(msg))
  end subroutine write_lines

  !> Write a bad deck, read it, and check the error: code EXIT_INPUT, the
  !> message starts with '<deck>:<line>:' (just '<deck>:' when line is 0,
  !> for a group missing from the whole deck) and contains every fragment.
  subroutine expect_error(failure, name, text, line, fragments)
    type(failure_t), allocatable, intent(inout) :: failure
    character(len=*), intent(in) :: name
    character(len=*), intent(in) :: text
    integer, intent(in) :: line
    character(len=*), intent(in) :: fragments(:)
    type(scene_t) :: scene
    type(error_t) :: err
    character(len=:), allocatable :: path, here, msg
    integer :: k
    path = 'scene_bad_' // name // '.nml'
    call write_lines(failure, path, text)
    if (allocated(failure)) return
    call read_scene(path, scene, err)
    if (.not. err%failed()) then
      call fail_now(failure, path // ' was accepted; expected an error')
      return
    end if
    call check(failure, err%code == EXIT_INPUT, 'error code ' // str(err%code) // ', expected EXIT_INPUT')
    call check(failure, allocated(err%message), 'the error has no message')
    if (allocated(failure)) return
    msg = err%message
    if (line > 0) then
      here = path // ':' // str(line) // ': '
    else
      here = path // ': '
    end if
    call check(failure, index(msg, here) == 1, 'message does not start with ''' // here // ''': ' // msg)
    do k = 1, size(fragments)
      call check(failure, index(msg, trim(fragments(k))) > 0, &
        'message lacks ''' // trim(fragments(k)) // ''': ' // msg)
    end do
  end subroutine expect_error

  !> Field-by-field equality of two scenes (reals exactly: the echo is exact).
  subroutine compare_scenes(failure, a, b)
    type(failure_t), allocatable, intent(inout) :: failure
    type(scene_t), intent(in) :: a, b
    integer :: k
    call check_text(failure, b%run%title, a%run%title, 'run%title')
    call check_text(failure, b%run%output_dir, a%run%output_dir, 'run%output_dir')
    call check(failure, b%run%wall_clock == a%run%wall_clock, 'run%wall_clock differs')
    call check(failure, b%run%checkpoint_every == a%run%checkpoint_every, 'run%checkpoint_every differs')
    call check_text(failure, b%mesh%file, a%mesh%file, 'mesh%file')
    call check_text(failure, b%mesh%format, a%mesh%format, 'mesh%format')
    call check(failure, b%mesh%scale == a%mesh%scale, 'mesh%scale differs')
    call check(failure, size(b%bodies) == size(a%bodies), 'number of bodies differs')
    call check(failure, size(b%bcs) == size(a%bcs), 'number of boundaries differs')
    call check(failure, size(b%amplitudes) == size(a%amplitudes), 'number of amplitudes differs')
    call check(failure, size(b%contacts) == size(a%contacts), 'number of contact pairs differs')
    if (allocated(failure)) return
    do k = 1, size(a%bodies)
      associate (p => a%bodies(k), q => b%bodies(k))
        call check_text(failure, q%name, p%name, 'body name')
        call check_text(failure, q%elset, p%elset, 'body elset')
        call check(failure, q%young == p%young .and. q%poisson == p%poisson .and. q%density == p%density &
          .and. q%thickness == p%thickness .and. (q%plane_stress .eqv. p%plane_stress) &
          .and. all(q%velocity == p%velocity) .and. all(q%body_force == p%body_force), &
          'body ' // p%name // ' differs')
      end associate
    end do
    do k = 1, size(a%bcs)
      associate (p => a%bcs(k), q => b%bcs(k))
        call check_text(failure, q%set, p%set, 'boundary set')
        call check_text(failure, q%amplitude, p%amplitude, 'boundary amplitude')
        call check(failure, q%kind == p%kind .and. all(q%comp .eqv. p%comp) .and. all(q%value == p%value) &
          .and. q%pressure == p%pressure, 'boundary ' // p%set // ' differs')
      end associate
    end do
    do k = 1, size(a%amplitudes)
      associate (p => a%amplitudes(k), q => b%amplitudes(k))
        call check_text(failure, q%name, p%name, 'amplitude name')
        call check(failure, q%npoint == p%npoint, 'amplitude ' // p%name // ': npoint differs')
        if (allocated(failure)) return
        call check(failure, all(q%t == p%t) .and. all(q%a == p%a), 'amplitude ' // p%name // ' differs')
      end associate
    end do
    call check(failure, b%time%t_end == a%time%t_end .and. b%time%dt == a%time%dt .and. &
      b%time%safety == a%time%safety .and. b%time%damping == a%time%damping, '&time differs')
    call check(failure, b%time%mass_scaling_dt == a%time%mass_scaling_dt .and. &
      b%time%mass_scaling_factor == a%time%mass_scaling_factor .and. &
      b%time%added_mass_warn == a%time%added_mass_warn .and. b%time%kinetic_ratio_warn == a%time%kinetic_ratio_warn &
      .and. b%time%kinetic_check_from == a%time%kinetic_check_from, '&time mass scaling differs')
    call check(failure, b%output%frames == a%output%frames .and. b%output%history_every == a%output%history_every &
      .and. b%output%progress_seconds == a%output%progress_seconds .and. (b%output%stress .eqv. a%output%stress), &
      '&output differs')
    do k = 1, size(a%contacts)
      associate (p => a%contacts(k), q => b%contacts(k))
        call check_text(failure, q%slave, p%slave, 'contact slave')
        call check_text(failure, q%master, p%master, 'contact master')
        call check(failure, q%method == p%method .and. q%multiplier == p%multiplier .and. &
          (q%weighted .eqv. p%weighted) .and. &
          q%friction == p%friction .and. q%search_distance == p%search_distance .and. &
          q%tolerance == p%tolerance .and. q%max_iterations == p%max_iterations, &
          'contact pair ' // p%slave // ' differs')
      end associate
    end do
  end subroutine compare_scenes

  !> Read deck, echo it to a scratch file in the working directory (another
  !> folder than the deck's, so relative paths would show), read the echo.
  subroutine round_trip(failure, deck, echo)
    type(failure_t), allocatable, intent(inout) :: failure
    character(len=*), intent(in) :: deck, echo
    type(scene_t) :: first, second
    type(error_t) :: err
    character(len=256) :: msg
    integer :: u, ios
    call read_good(failure, deck, first)
    if (allocated(failure)) return
    open(newunit=u, file=echo, status='replace', action='write', iostat=ios, iomsg=msg)
    if (ios /= 0) then
      call fail_now(failure, 'cannot write ' // echo // ': ' // trim(msg))
      return
    end if
    call write_scene(first, u, err)
    close(u)
    call check(failure, .not. err%failed(), 'write_scene failed')
    call read_good(failure, echo, second)
    if (allocated(failure)) return
    call compare_scenes(failure, first, second)
  end subroutine round_trip

  ! ------------------------------------------------------------ good decks

  subroutine test_full_deck(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(scene_t) :: s
    character(len=:), allocatable :: data
    data = data_dir()
    call check(failure, len(data) > 0, 'RACCORD_TEST_DATA is not set')
    if (allocated(failure)) return
    call read_good(failure, data // '/decks/full.nml', s)
    if (allocated(failure)) return

    call check_text(failure, s%path, data // '/decks/full.nml', 'path')
    call check_text(failure, s%dir, data // '/decks', 'dir')
    call check_text(failure, s%run%title, 'disc / block ! sliding', 'run%title')
    call check_text(failure, s%run%output_dir, 'out/full', 'run%output_dir')
    call check_close(failure, s%run%wall_clock, 7200.5_wp, 'run%wall_clock')
    call check(failure, s%run%checkpoint_every == 250, 'run%checkpoint_every')
    call check_text(failure, s%mesh%file, data // '/decks/meshes/disc_block.msh', 'mesh%file')
    call check_text(failure, s%mesh%format, 'gmsh', 'mesh%format')
    call check_close(failure, s%mesh%scale, 2.5_wp, 'mesh%scale')

    call check(failure, size(s%bodies) == 2, 'expected 2 bodies, got ' // str(size(s%bodies)))
    if (allocated(failure)) return
    call check_text(failure, s%bodies(1)%name, 'disc', 'body 1 name')
    call check_text(failure, s%bodies(1)%elset, 'disc_surface', 'body 1 elset')
    call check_close(failure, s%bodies(1)%young, 70000.0_wp, 'body 1 young')
    call check_close(failure, s%bodies(1)%poisson, 0.3_wp, 'body 1 poisson')
    call check_close(failure, s%bodies(1)%density, 2.7e-9_wp, 'body 1 density')
    call check(failure, s%bodies(1)%plane_stress, 'body 1 should be plane stress')
    call check_close(failure, s%bodies(1)%thickness, 2.0_wp, 'body 1 thickness')
    call check_close(failure, s%bodies(1)%velocity(1), 1.5_wp, 'body 1 velocity x')
    call check_close(failure, s%bodies(1)%velocity(2), -2.5_wp, 'body 1 velocity y')
    call check_close(failure, s%bodies(1)%body_force(1), 0.0_wp, 'body 1 body_force x', abs_tol=0.0_wp)
    call check_close(failure, s%bodies(1)%body_force(2), -9.81e-6_wp, 'body 1 body_force y')
    call check_text(failure, s%bodies(2)%name, 'block', 'body 2 name')
    call check_text(failure, s%bodies(2)%elset, 'block', 'body 2 elset (default: name)')
    call check_close(failure, s%bodies(2)%young, 210000.0_wp, 'body 2 young')
    call check_close(failure, s%bodies(2)%poisson, 0.29_wp, 'body 2 poisson')
    call check_close(failure, s%bodies(2)%density, 7.85e-9_wp, 'body 2 density')
    call check(failure, .not. s%bodies(2)%plane_stress, 'body 2 should be plane strain')

    call check(failure, size(s%amplitudes) == 2, 'expected 2 amplitudes, got ' // str(size(s%amplitudes)))
    if (allocated(failure)) return
    call check_text(failure, s%amplitudes(1)%name, 'cycle', 'amplitude 1 name')
    call check(failure, s%amplitudes(1)%npoint == 3, 'amplitude 1: npoint ' // str(s%amplitudes(1)%npoint))
    call check(failure, size(s%amplitudes(1)%t) == 3 .and. size(s%amplitudes(1)%a) == 3, 'amplitude 1 sizes')
    if (allocated(failure)) return
    call check(failure, all(s%amplitudes(1)%t == [0.0_wp, 1.0_wp, 2.0_wp]), 'amplitude 1 times')
    call check(failure, all(s%amplitudes(1)%a == [0.0_wp, 1.0_wp, 0.0_wp]), 'amplitude 1 values')
    call check_text(failure, s%amplitudes(2)%name, 'ramp', 'amplitude 2 name')
    call check(failure, s%amplitudes(2)%npoint == 1, 'amplitude 2: npoint ' // str(s%amplitudes(2)%npoint))

    call check(failure, size(s%bcs) == 6, 'expected 6 boundaries, got ' // str(size(s%bcs)))
    if (allocated(failure)) return
    call check_text(failure, s%bcs(1)%set, 'bottom', 'bc 1 set')
    call check(failure, s%bcs(1)%kind == BC_FIXED .and. all(s%bcs(1)%comp), 'bc 1: fixed xy by default')
    call check_text(failure, s%bcs(1)%amplitude, '', 'bc 1 amplitude')
    call check(failure, s%bcs(2)%kind == BC_FIXED .and. s%bcs(2)%comp(1) .and. .not. s%bcs(2)%comp(2), &
      'bc 2: fixed x (upper case in the deck)')
    call check_text(failure, s%bcs(3)%set, 'top', 'bc 3 set')
    call check(failure, s%bcs(3)%kind == BC_DISPLACEMENT .and. all(s%bcs(3)%comp), 'bc 3: displacement xy')
    call check_close(failure, s%bcs(3)%value(1), 0.0_wp, 'bc 3 value x', abs_tol=0.0_wp)
    call check_close(failure, s%bcs(3)%value(2), -0.1581_wp, 'bc 3 value y')
    call check_text(failure, s%bcs(3)%amplitude, 'cycle', 'bc 3 amplitude')
    call check(failure, s%bcs(4)%kind == BC_DISPLACEMENT .and. .not. s%bcs(4)%comp(1) .and. s%bcs(4)%comp(2), &
      'bc 4: displacement y')
    call check_close(failure, s%bcs(4)%value(1), 0.0_wp, 'bc 4 value x (unused, zero)', abs_tol=0.0_wp)
    call check_close(failure, s%bcs(4)%value(2), 0.25_wp, 'bc 4 value y')
    call check(failure, s%bcs(5)%kind == BC_TRACTION, 'bc 5: traction')
    call check_close(failure, s%bcs(5)%value(1), 1.0_wp, 'bc 5 value x')
    call check_close(failure, s%bcs(5)%value(2), -2.0_wp, 'bc 5 value y')
    call check_text(failure, s%bcs(5)%amplitude, 'ramp', 'bc 5 amplitude')
    call check(failure, s%bcs(6)%kind == BC_PRESSURE, 'bc 6: pressure')
    call check_close(failure, s%bcs(6)%pressure, 3.5_wp, 'bc 6 pressure')

    call check_close(failure, s%time%t_end, 2.0_wp, 't_end')
    call check_close(failure, s%time%dt, 1.0e-7_wp, 'dt')
    call check_close(failure, s%time%safety, 0.8_wp, 'safety')
    call check_close(failure, s%time%damping, 12.5_wp, 'damping')

    call check(failure, s%output%frames == 40, 'frames ' // str(s%output%frames))
    call check(failure, s%output%history_every == 100, 'history_every ' // str(s%output%history_every))
    call check_close(failure, s%output%progress_seconds, 5.0_wp, 'progress_seconds')
    call check(failure, .not. s%output%stress, 'stress should be .false.')

    call check(failure, size(s%contacts) == 2, 'expected 2 contact pairs, got ' // str(size(s%contacts)))
    if (allocated(failure)) return
    call check_text(failure, s%contacts(1)%slave, 'block_top', 'contact 1 slave')
    call check_text(failure, s%contacts(1)%master, 'disc_bottom', 'contact 1 master')
    call check(failure, s%contacts(1)%method == METHOD_MORTAR, 'contact 1 method')
    call check(failure, s%contacts(1)%multiplier == MULT_DUAL, 'contact 1 multiplier')
    call check_close(failure, s%contacts(1)%friction, 0.2_wp, 'contact 1 friction')
    call check_close(failure, s%contacts(1)%search_distance, 0.5_wp, 'contact 1 search_distance')
    call check_close(failure, s%contacts(1)%tolerance, 1.0e-8_wp, 'contact 1 tolerance')
    call check(failure, s%contacts(1)%max_iterations == 50, 'contact 1 max_iterations')
    call check(failure, s%contacts(1)%weighted, 'contact 1 conditions')
    call check(failure, .not. s%contacts(2)%weighted, 'contact 2 conditions default')
    call check_text(failure, s%contacts(2)%slave, 'disc_side', 'contact 2 slave')
    call check(failure, s%contacts(2)%method == METHOD_NTS .and. s%contacts(2)%multiplier == MULT_P1, &
      'contact 2 method and multiplier defaults')
    call check_close(failure, s%contacts(2)%friction, 0.0_wp, 'contact 2 friction', abs_tol=0.0_wp)
    call check_close(failure, s%contacts(2)%tolerance, 1.0e-12_wp, 'contact 2 tolerance default')
    call check(failure, s%contacts(2)%max_iterations == 200, 'contact 2 max_iterations')
  end subroutine test_full_deck

  subroutine test_minimal_defaults(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(scene_t) :: s
    character(len=:), allocatable :: data
    data = data_dir()
    call check(failure, len(data) > 0, 'RACCORD_TEST_DATA is not set')
    if (allocated(failure)) return
    call read_good(failure, data // '/decks/minimal.nml', s)
    if (allocated(failure)) return
    call check_text(failure, s%run%title, 'minimal', 'default title (deck stem)')
    call check_text(failure, s%run%output_dir, 'results/minimal', 'default output_dir')
    call check_text(failure, s%mesh%file, data // '/decks/part.msh', 'mesh%file')
    call check_text(failure, s%mesh%format, 'auto', 'default format')
    call check_close(failure, s%mesh%scale, 1.0_wp, 'default scale')
    call check(failure, size(s%bodies) == 1, 'one body')
    if (allocated(failure)) return
    call check_text(failure, s%bodies(1)%elset, 'part', 'default elset (the name)')
    call check(failure, .not. s%bodies(1)%plane_stress, 'default hypothesis plane strain')
    call check_close(failure, s%bodies(1)%thickness, 1.0_wp, 'default thickness')
    call check(failure, all(s%bodies(1)%velocity == 0.0_wp), 'default velocity')
    call check(failure, all(s%bodies(1)%body_force == 0.0_wp), 'default body_force')
    call check(failure, allocated(s%bcs) .and. allocated(s%amplitudes) .and. allocated(s%contacts), &
      'optional lists should be allocated (empty)')
    if (allocated(failure)) return
    call check(failure, size(s%bcs) == 0 .and. size(s%amplitudes) == 0 .and. size(s%contacts) == 0, &
      'no boundaries, amplitudes or contact pairs')
    call check_close(failure, s%time%t_end, 1.0_wp, 't_end')
    call check_close(failure, s%time%dt, 0.0_wp, 'default dt', abs_tol=0.0_wp)
    call check_close(failure, s%time%safety, 0.9_wp, 'default safety')
    call check_close(failure, s%time%damping, 0.0_wp, 'default damping', abs_tol=0.0_wp)
    call check(failure, s%output%frames == 20, 'default frames')
    call check(failure, s%output%history_every == 0, 'default history_every')
    call check_close(failure, s%output%progress_seconds, 10.0_wp, 'default progress_seconds')
    call check(failure, s%output%stress, 'default stress')
  end subroutine test_minimal_defaults

  subroutine test_relative_mesh_path(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(scene_t) :: s
    character(len=:), allocatable :: data
    data = data_dir()
    call check(failure, len(data) > 0, 'RACCORD_TEST_DATA is not set')
    if (allocated(failure)) return
    call read_good(failure, data // '/decks/sub/relative.nml', s)
    if (allocated(failure)) return
    call check_text(failure, s%dir, data // '/decks/sub', 'dir')
    ! './' is dropped; '..' is kept (the file system resolves it).
    call check_text(failure, s%mesh%file, data // '/decks/sub/../meshes/block.inp', 'mesh%file')
    call check_text(failure, s%mesh%format, 'abaqus', 'mesh%format')
    call check_text(failure, s%run%output_dir, 'results/relative', 'default output_dir')
  end subroutine test_relative_mesh_path

  subroutine test_cwd_relative_deck(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(scene_t) :: s
    character(len=:), allocatable :: cwd
    cwd = current_dir()
    call check(failure, len(cwd) > 0, 'current directory unknown')
    call write_lines(failure, 'scene_cwd_deck.nml', &
      "&run output_dir = 'out/cwd' /" // NL // &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /")
    if (allocated(failure)) return
    call read_good(failure, 'scene_cwd_deck.nml', s)
    if (allocated(failure)) return
    call check_text(failure, s%dir, cwd, 'dir of a deck given without folder')
    call check_text(failure, s%mesh%file, cwd // '/m.msh', 'mesh%file made absolute')
    call check_text(failure, s%run%output_dir, 'out/cwd', 'output_dir kept relative to the current directory')
    call check_text(failure, s%run%title, 'scene_cwd_deck', 'default title')

    call write_lines(failure, 'scene_abs_mesh.nml', &
      "&mesh file = '/some/where/m.inp' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /")
    if (allocated(failure)) return
    call read_good(failure, 'scene_abs_mesh.nml', s)
    if (allocated(failure)) return
    call check_text(failure, s%mesh%file, '/some/where/m.inp', 'absolute mesh path kept')
  end subroutine test_cwd_relative_deck

  subroutine test_roundtrip_full(failure)
    type(failure_t), allocatable, intent(out) :: failure
    character(len=:), allocatable :: data
    data = data_dir()
    call check(failure, len(data) > 0, 'RACCORD_TEST_DATA is not set')
    if (allocated(failure)) return
    call round_trip(failure, data // '/decks/full.nml', 'scene_echo_full.nml')
  end subroutine test_roundtrip_full

  subroutine test_roundtrip_minimal(failure)
    type(failure_t), allocatable, intent(out) :: failure
    character(len=:), allocatable :: data
    data = data_dir()
    call check(failure, len(data) > 0, 'RACCORD_TEST_DATA is not set')
    if (allocated(failure)) return
    call round_trip(failure, data // '/decks/minimal.nml', 'scene_echo_minimal.nml')
  end subroutine test_roundtrip_minimal

  !> The echo lists defaults too (the user sees what the run used).
  subroutine test_echo_lists_defaults(failure)
    type(failure_t), allocatable, intent(out) :: failure
    character(len=*), parameter :: expected(*) = [character(len=40) :: "  title = 'minimal'", &
      "  output_dir = 'results/minimal'", "  format = 'auto'", "  scale = 1.0", "  elset = 'part'", &
      "  hypothesis = 'plane_strain'", "  thickness = 1.0", "  velocity = 0.0, 0.0", &
      "  body_force = 0.0, 0.0", "  dt = 0.0", "  safety = 0.9", "  damping = 0.0", "  frames = 20", &
      "  history_every = 0", "  progress_seconds = 10.0", "  stress = .true.", "  young = 1000.0", &
      "  density = 1.0E-09"]
    logical :: found(size(expected))
    character(len=1024) :: line
    character(len=256) :: msg
    integer :: u, ios, k
    call round_trip(failure, data_dir() // '/decks/minimal.nml', 'scene_echo_minimal.nml')
    if (allocated(failure)) return
    open(newunit=u, file='scene_echo_minimal.nml', status='old', action='read', iostat=ios, iomsg=msg)
    if (ios /= 0) then
      call fail_now(failure, 'cannot read the echo: ' // trim(msg))
      return
    end if
    found = .false.
    do
      read(u, '(a)', iostat=ios, iomsg=msg) line
      if (ios /= 0) exit
      do k = 1, size(expected)
        if (trim(line) == trim(expected(k))) found(k) = .true.
      end do
    end do
    close(u)
    do k = 1, size(expected)
      call check(failure, found(k), 'the echo lacks the line "' // trim(expected(k)) // '"')
    end do
  end subroutine test_echo_lists_defaults

  !> The lines every bad deck starts from read without error, so each bad
  !> case fails for its own reason.
  subroutine test_base_deck_reads(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(scene_t) :: s
    call write_lines(failure, 'scene_base.nml', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&amplitude name = 'c', time = 0.0, 1.0, value = 0.0, 1.0 /" // NL // &
      "&boundary set = 'top', type = 'displacement', components = 'y', value = 0.0, 1.0, amplitude = 'c' /" // NL // &
      "&contact_pair slave = 's', master = 'm' /" // NL // &
      "&output frames = 3 /")
    if (allocated(failure)) return
    call read_good(failure, 'scene_base.nml', s)
  end subroutine test_base_deck_reads

  ! ------------------------------------------------------------ bad decks

  subroutine test_missing_deck_file(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(scene_t) :: s
    type(error_t) :: err
    call read_scene('scene_no_such_deck.nml', s, err)
    call check(failure, err%code == EXIT_INPUT, 'error code ' // str(err%code) // ', expected EXIT_INPUT')
    if (allocated(failure)) return
    call check(failure, index(err%message, 'scene_no_such_deck.nml') > 0, 'message lacks the path: ' // err%message)
  end subroutine test_missing_deck_file

  subroutine bad_wall_clock_negative(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'wall_clock_negative', &
      "&run wall_clock = -60.0 /" // NL // &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /", &
      1, [character(len=FRAG_LEN) :: "&run", "'wall_clock'", "must be >= 0", "0 for no limit"])
  end subroutine bad_wall_clock_negative

  subroutine bad_checkpoint_every_negative(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'checkpoint_every_negative', &
      "&mesh file = 'm.msh' /" // NL // &
      "&run checkpoint_every = -1 /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /", &
      2, [character(len=FRAG_LEN) :: "&run", "'checkpoint_every'", "must be >= 0", "0 for none"])
  end subroutine bad_checkpoint_every_negative

  subroutine bad_unknown_group(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'unknown_group', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&bdy name = 'b' /", &
      4, [character(len=FRAG_LEN) :: "&bdy", "unknown group", "known groups: run, mesh"])
  end subroutine bad_unknown_group

  subroutine bad_unknown_key(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'unknown_key', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'disc', yong = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /", &
      2, [character(len=FRAG_LEN) :: "&body 'disc'", "unknown key 'yong'", "known keys: name, elset, young"])
  end subroutine bad_unknown_key

  subroutine bad_key_line_in_multiline_group(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'key_line_in_multiline_group', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a'," // NL // &
      "  poisson = 0.3, density = 1.0," // NL // &
      "  young = -5.0" // NL // &
      "/" // NL // &
      "&time t_end = 1.0 /", &
      4, [character(len=FRAG_LEN) :: "&body 'a'", "'young'", "-5.0", "> 0"])
  end subroutine bad_key_line_in_multiline_group

  subroutine bad_malformed_real_quoted(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'malformed_real_quoted', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 'abc', poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /", &
      2, [character(len=FRAG_LEN) :: "&body 'a'", "'young'", "'abc'", "cannot read"])
  end subroutine bad_malformed_real_quoted

  subroutine bad_malformed_real_word(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'malformed_real_word', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = abc, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /", &
      2, [character(len=FRAG_LEN) :: "&body 'a'", "'young'", "abc", "a real number"])
  end subroutine bad_malformed_real_word

  subroutine bad_malformed_integer(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'malformed_integer', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&output frames = 2.5 /", &
      4, [character(len=FRAG_LEN) :: "&output", "'frames'", "2.5", "whole number"])
  end subroutine bad_malformed_integer

  subroutine bad_malformed_logical(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'malformed_logical', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&output stress = maybe /", &
      4, [character(len=FRAG_LEN) :: "&output", "'stress'", "maybe", ".true."])
  end subroutine bad_malformed_logical

  subroutine bad_text_not_quoted(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'text_not_quoted', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&boundary set = 'top', type = fixed /", &
      4, [character(len=FRAG_LEN) :: "&boundary 'top'", "'type'", "quotes"])
  end subroutine bad_text_not_quoted

  subroutine bad_too_many_values(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'too_many_values', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0, velocity = 1.0, 2.0, 3.0 /" // NL // &
      "&time t_end = 1.0 /", &
      2, [character(len=FRAG_LEN) :: "&body 'a'", "'velocity'", "3.0"])
  end subroutine bad_too_many_values

  subroutine bad_subscript_out_of_range(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'subscript_out_of_range', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0, velocity(3) = 1.0 /" // NL // &
      "&time t_end = 1.0 /", &
      2, [character(len=FRAG_LEN) :: "&body 'a'", "'velocity'", "cannot read"])
  end subroutine bad_subscript_out_of_range

  subroutine bad_key_without_value(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'key_without_value', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = , poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /", &
      2, [character(len=FRAG_LEN) :: "&body", "'young'", "no value"])
  end subroutine bad_key_without_value

  subroutine bad_not_finite(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'not_finite', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = NaN, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /", &
      2, [character(len=FRAG_LEN) :: "&body 'a'", "'young'", "finite"])
  end subroutine bad_not_finite

  subroutine bad_duplicate_key(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'duplicate_key', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3," // NL // &
      "  density = 1.0, young = 2.0 /" // NL // &
      "&time t_end = 1.0 /", &
      3, [character(len=FRAG_LEN) :: "&body 'a'", "'young'", "second time", "line 2"])
  end subroutine bad_duplicate_key

  subroutine bad_missing_slash(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'missing_slash', &
      "&mesh file = 'm.msh'" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /", &
      1, [character(len=FRAG_LEN) :: "&mesh", "not closed by '/'", "line 2"])
  end subroutine bad_missing_slash

  subroutine bad_missing_slash_at_end(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'missing_slash_at_end', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0", &
      3, [character(len=FRAG_LEN) :: "&time", "not closed by '/'", "end of the file"])
  end subroutine bad_missing_slash_at_end

  subroutine bad_unclosed_string(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'unclosed_string', &
      "&run title = 'disc" // NL // &
      "/" // NL // &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /", &
      1, [character(len=FRAG_LEN) :: "&run", "not closed", "quote"])
  end subroutine bad_unclosed_string

  subroutine bad_text_outside_group(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'text_outside_group', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "young = 3.0" // NL // &
      "&time t_end = 1.0 /", &
      3, [character(len=FRAG_LEN) :: "text outside a group", "young = 3.0"])
  end subroutine bad_text_outside_group

  subroutine bad_duplicate_mesh(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'duplicate_mesh', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&mesh file = 'n.msh' /", &
      4, [character(len=FRAG_LEN) :: "&mesh", "second time", "first at line 1"])
  end subroutine bad_duplicate_mesh

  subroutine bad_duplicate_time(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'duplicate_time', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&time t_end = 2.0 /", &
      4, [character(len=FRAG_LEN) :: "&time", "second time", "first at line 3"])
  end subroutine bad_duplicate_time

  subroutine bad_duplicate_run(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'duplicate_run', &
      "&run title = 'x' /" // NL // &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&run title = 'y' /", &
      5, [character(len=FRAG_LEN) :: "&run", "second time", "first at line 1"])
  end subroutine bad_duplicate_run

  subroutine bad_duplicate_output(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'duplicate_output', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&output /" // NL // &
      "&output frames = 3 /", &
      5, [character(len=FRAG_LEN) :: "&output", "second time", "first at line 4"])
  end subroutine bad_duplicate_output

  subroutine bad_missing_mesh(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'missing_mesh', &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /", &
      0, [character(len=FRAG_LEN) :: "&mesh", "no &mesh group"])
  end subroutine bad_missing_mesh

  subroutine bad_missing_time(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'missing_time', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /", &
      0, [character(len=FRAG_LEN) :: "&time", "no &time group"])
  end subroutine bad_missing_time

  subroutine bad_missing_body(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'missing_body', &
      "&mesh file = 'm.msh' /" // NL // &
      "&time t_end = 1.0 /", &
      0, [character(len=FRAG_LEN) :: "&body", "no &body group"])
  end subroutine bad_missing_body

  subroutine bad_mesh_file_missing(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'mesh_file_missing', &
      "&mesh format = 'gmsh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /", &
      1, [character(len=FRAG_LEN) :: "&mesh", "required key 'file'"])
  end subroutine bad_mesh_file_missing

  subroutine bad_mesh_format_unknown(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'mesh_format_unknown', &
      "&mesh file = 'm.msh', format = 'vtk' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /", &
      1, [character(len=FRAG_LEN) :: "&mesh", "'format'", "'vtk'", "'abaqus'"])
  end subroutine bad_mesh_format_unknown

  subroutine bad_mesh_scale_nonpositive(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'mesh_scale_nonpositive', &
      "&mesh file = 'm.msh', scale = 0.0 /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /", &
      1, [character(len=FRAG_LEN) :: "&mesh", "'scale'", "> 0"])
  end subroutine bad_mesh_scale_nonpositive

  subroutine bad_body_name_missing(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'body_name_missing', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /", &
      2, [character(len=FRAG_LEN) :: "&body", "required key 'name'"])
  end subroutine bad_body_name_missing

  subroutine bad_young_missing(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'young_missing', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /", &
      2, [character(len=FRAG_LEN) :: "&body 'a'", "required key 'young'"])
  end subroutine bad_young_missing

  subroutine bad_young_nonpositive(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'young_nonpositive', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 0.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /", &
      2, [character(len=FRAG_LEN) :: "&body 'a'", "'young'", "> 0"])
  end subroutine bad_young_nonpositive

  subroutine bad_poisson_too_high(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'poisson_too_high', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.5, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /", &
      2, [character(len=FRAG_LEN) :: "&body 'a'", "'poisson'", "0.5", "(-1, 0.5)"])
  end subroutine bad_poisson_too_high

  subroutine bad_poisson_too_low(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'poisson_too_low', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = -1.0, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /", &
      2, [character(len=FRAG_LEN) :: "&body 'a'", "'poisson'", "-1.0"])
  end subroutine bad_poisson_too_low

  subroutine bad_density_nonpositive(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'density_nonpositive', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = -2.7e-9 /" // NL // &
      "&time t_end = 1.0 /", &
      2, [character(len=FRAG_LEN) :: "&body 'a'", "'density'", "-2.7e-9", "> 0"])
  end subroutine bad_density_nonpositive

  subroutine bad_thickness_nonpositive(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'thickness_nonpositive', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0, thickness = 0.0 /" // NL // &
      "&time t_end = 1.0 /", &
      2, [character(len=FRAG_LEN) :: "&body 'a'", "'thickness'", "> 0"])
  end subroutine bad_thickness_nonpositive

  subroutine bad_body_damping_negative(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'body_damping_negative', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0, damping = -1.0 /" // NL // &
      "&time t_end = 1.0 /", &
      2, [character(len=FRAG_LEN) :: "&body 'a'", "'damping'", ">= 0"])
  end subroutine bad_body_damping_negative

  !> A body's own damping is kept; a body without one takes &time damping.
  subroutine test_body_damping(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(scene_t) :: scene
    type(error_t) :: err
    call write_lines(failure, 'scene_body_damping.nml', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0, damping = 5.0 /" // NL // &
      "&body name = 'b', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0, damping = 2.0 /")
    if (allocated(failure)) return
    call read_scene('scene_body_damping.nml', scene, err)
    call check(failure, .not. err%failed(), 'deck refused')
    if (allocated(failure)) return
    call check(failure, scene%bodies(1)%damping == 5.0_wp, 'body a lost its own damping')
    call check(failure, scene%bodies(2)%damping == 2.0_wp, 'body b did not take the &time damping')
  end subroutine test_body_damping

  subroutine bad_hypothesis_unknown(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'hypothesis_unknown', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0, hypothesis = 'plane_strian' /" // NL // &
      "&time t_end = 1.0 /", &
      2, [character(len=FRAG_LEN) :: "&body 'a'", "'hypothesis'", "'plane_strian'", "'plane_stress'"])
  end subroutine bad_hypothesis_unknown

  subroutine bad_duplicate_body_name(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'duplicate_body_name', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&body name = 'a', young = 2.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /", &
      3, [character(len=FRAG_LEN) :: "&body 'a'", "'name'", "line 2"])
  end subroutine bad_duplicate_body_name

  subroutine bad_t_end_missing(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 't_end_missing', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time dt = 0.1 /", &
      3, [character(len=FRAG_LEN) :: "&time", "required key 't_end'"])
  end subroutine bad_t_end_missing

  subroutine bad_t_end_nonpositive(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 't_end_nonpositive', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 0.0 /", &
      3, [character(len=FRAG_LEN) :: "&time", "'t_end'", "> 0"])
  end subroutine bad_t_end_nonpositive

  subroutine bad_dt_negative(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'dt_negative', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0, dt = -1e-6 /", &
      3, [character(len=FRAG_LEN) :: "&time", "'dt'", "-1e-6", ">= 0"])
  end subroutine bad_dt_negative

  subroutine bad_safety_above_one(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'safety_above_one', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0, safety = 1.5 /", &
      3, [character(len=FRAG_LEN) :: "&time", "'safety'", "1.5", "(0, 1]"])
  end subroutine bad_safety_above_one

  subroutine bad_mass_scaling_factor(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'mass_scaling_factor', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0, mass_scaling_factor = 0.5 /", &
      3, [character(len=FRAG_LEN) :: "&time", "'mass_scaling_factor'", "0.5", ">= 1"])
  end subroutine bad_mass_scaling_factor

  subroutine bad_mass_scaling_both(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'mass_scaling_both', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0, mass_scaling_factor = 4, mass_scaling_dt = 1e-3 /", &
      3, [character(len=FRAG_LEN) :: "&time", "both given", "give one of them"])
  end subroutine bad_mass_scaling_both

  subroutine bad_mass_scaling_fixed_dt(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'mass_scaling_fixed_dt', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0, dt = 1e-4, mass_scaling_dt = 1e-3 /", &
      3, [character(len=FRAG_LEN) :: "&time", "'dt'", "mass scaling", "leave dt out"])
  end subroutine bad_mass_scaling_fixed_dt

  subroutine bad_safety_zero(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'safety_zero', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0, safety = 0.0 /", &
      3, [character(len=FRAG_LEN) :: "&time", "'safety'", "(0, 1]"])
  end subroutine bad_safety_zero

  subroutine bad_damping_negative(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'damping_negative', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0, damping = -0.1 /", &
      3, [character(len=FRAG_LEN) :: "&time", "'damping'", ">= 0"])
  end subroutine bad_damping_negative

  subroutine bad_frames_negative(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'frames_negative', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&output frames = -1 /", &
      4, [character(len=FRAG_LEN) :: "&output", "'frames'", ">= 0"])
  end subroutine bad_frames_negative

  subroutine bad_bc_set_missing(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'bc_set_missing', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&boundary type = 'fixed' /", &
      4, [character(len=FRAG_LEN) :: "&boundary", "required key 'set'"])
  end subroutine bad_bc_set_missing

  subroutine bad_bc_type_missing(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'bc_type_missing', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&boundary set = 'top' /", &
      4, [character(len=FRAG_LEN) :: "&boundary 'top'", "required key 'type'"])
  end subroutine bad_bc_type_missing

  subroutine bad_bc_type_unknown(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'bc_type_unknown', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&boundary set = 'top', type = 'clamped' /", &
      4, [character(len=FRAG_LEN) :: "&boundary 'top'", "'type'", "'clamped'", "'displacement'"])
  end subroutine bad_bc_type_unknown

  subroutine bad_bc_components_unknown(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'bc_components_unknown', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&boundary set = 'top', type = 'fixed', components = 'z' /", &
      4, [character(len=FRAG_LEN) :: "&boundary 'top'", "'components'", "'z'", "'xy'"])
  end subroutine bad_bc_components_unknown

  subroutine bad_bc_components_missing(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'bc_components_missing', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&boundary set = 'top', type = 'displacement', value = 0.0, 1.0 /", &
      4, [character(len=FRAG_LEN) :: "&boundary 'top'", "required key 'components'"])
  end subroutine bad_bc_components_missing

  subroutine bad_bc_value_missing(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'bc_value_missing', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&boundary set = 'top', type = 'displacement', components = 'y' /", &
      4, [character(len=FRAG_LEN) :: "&boundary 'top'", "required key 'value'"])
  end subroutine bad_bc_value_missing

  subroutine bad_bc_pressure_missing(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'bc_pressure_missing', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&boundary set = 'top', type = 'pressure' /", &
      4, [character(len=FRAG_LEN) :: "&boundary 'top'", "required key 'pressure'"])
  end subroutine bad_bc_pressure_missing

  subroutine bad_bc_key_not_for_type(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'bc_key_not_for_type', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&boundary set = 'top', type = 'fixed'," // NL // &
      "  value = 0.0, 1.0 /", &
      5, [character(len=FRAG_LEN) :: "&boundary 'top'", "'value'", "does not apply", "'fixed'"])
  end subroutine bad_bc_key_not_for_type

  subroutine bad_bc_amplitude_undefined(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'bc_amplitude_undefined', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&amplitude name = 'cycle', time = 0.0, value = 1.0 /" // NL // &
      "&boundary set = 'top', type = 'traction', value = 0.0, 1.0," // NL // &
      "  amplitude = 'cyc' /", &
      6, [character(len=FRAG_LEN) :: "&boundary 'top'", "'amplitude'", "'cyc'", "cycle"])
  end subroutine bad_bc_amplitude_undefined

  subroutine bad_bc_amplitude_case(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'bc_amplitude_case', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&amplitude name = 'Ramp', time = 0.0, value = 1.0 /" // NL // &
      "&boundary set = 'top', type = 'traction', value = 0.0, 1.0," // NL // &
      "  amplitude = 'ramp' /", &
      6, [character(len=FRAG_LEN) :: "&boundary 'top'", "'amplitude'", "line 4 is named 'Ramp'", &
      "case-sensitive", "write amplitude = 'Ramp'"])
  end subroutine bad_bc_amplitude_case

  subroutine bad_amplitude_not_increasing(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'amplitude_not_increasing', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&amplitude name = 'c', time = 0.0, 1.0, 1.0, value = 0.0, 1.0, 0.0 /", &
      4, [character(len=FRAG_LEN) :: "&amplitude 'c'", "'time'", "strictly increasing"])
  end subroutine bad_amplitude_not_increasing

  subroutine bad_amplitude_count_mismatch(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'amplitude_count_mismatch', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&amplitude name = 'c', time = 0.0, 1.0, 2.0," // NL // &
      "  value = 0.0, 1.0 /", &
      5, [character(len=FRAG_LEN) :: "&amplitude 'c'", "'value'", "3 points", "has 2"])
  end subroutine bad_amplitude_count_mismatch

  subroutine bad_amplitude_no_points(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'amplitude_no_points', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&amplitude name = 'c' /", &
      4, [character(len=FRAG_LEN) :: "&amplitude 'c'", "required key 'time'"])
  end subroutine bad_amplitude_no_points

  subroutine bad_amplitude_gap(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'amplitude_gap', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&amplitude name = 'c', time(2) = 1.0, value = 0.0, 1.0 /", &
      4, [character(len=FRAG_LEN) :: "&amplitude 'c'", "'time'", "entry 1"])
  end subroutine bad_amplitude_gap

  subroutine bad_duplicate_amplitude_name(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'duplicate_amplitude_name', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&amplitude name = 'c', time = 0.0, value = 1.0 /" // NL // &
      "&amplitude name = 'c', time = 0.0, value = 2.0 /", &
      5, [character(len=FRAG_LEN) :: "&amplitude 'c'", "'name'", "line 4"])
  end subroutine bad_duplicate_amplitude_name

  subroutine bad_contact_master_missing(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'contact_master_missing', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&contact_pair slave = 's' /", &
      4, [character(len=FRAG_LEN) :: "&contact_pair 's/'", "required key 'master'"])
  end subroutine bad_contact_master_missing

  subroutine bad_slave_equals_master(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'slave_equals_master', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&contact_pair slave = 's', master = 's' /", &
      4, [character(len=FRAG_LEN) :: "&contact_pair 's/s'", "'master'", "same surface"])
  end subroutine bad_slave_equals_master

  subroutine bad_method_unknown(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'method_unknown', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&contact_pair slave = 's', master = 'm', method = 'penalty' /", &
      4, [character(len=FRAG_LEN) :: "&contact_pair 's/m'", "'method'", "'penalty'", "'mortar'"])
  end subroutine bad_method_unknown

  subroutine bad_multiplier_unknown(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'multiplier_unknown', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&contact_pair slave = 's', master = 'm', multiplier = 'P2' /", &
      4, [character(len=FRAG_LEN) :: "&contact_pair 's/m'", "'multiplier'", "'P2'", "'dual'"])
  end subroutine bad_multiplier_unknown

  subroutine bad_conditions_unknown(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'conditions_unknown', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&contact_pair slave = 's', master = 'm', method = 'mortar', conditions = 'dual' /", &
      4, [character(len=FRAG_LEN) :: "&contact_pair 's/m'", "'conditions'", "'dual'", "'weighted'"])
  end subroutine bad_conditions_unknown

  subroutine bad_conditions_nts(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'conditions_nts', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&contact_pair slave = 's', master = 'm', method = 'node_to_segment', conditions = 'weighted' /", &
      4, [character(len=FRAG_LEN) :: "&contact_pair 's/m'", "'conditions'", "method = 'mortar'"])
  end subroutine bad_conditions_nts

  subroutine bad_friction_negative(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'friction_negative', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&contact_pair slave = 's', master = 'm'," // NL // &
      "  friction = -0.1 /", &
      5, [character(len=FRAG_LEN) :: "&contact_pair 's/m'", "'friction'", "-0.1", ">= 0"])
  end subroutine bad_friction_negative

  subroutine bad_tolerance_nonpositive(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'tolerance_nonpositive', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&contact_pair slave = 's', master = 'm', tolerance = 0.0 /", &
      4, [character(len=FRAG_LEN) :: "&contact_pair 's/m'", "'tolerance'", "> 0"])
  end subroutine bad_tolerance_nonpositive

  subroutine bad_max_iterations_zero(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'max_iterations_zero', &
      "&mesh file = 'm.msh' /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /" // NL // &
      "&contact_pair slave = 's', master = 'm', max_iterations = 0 /", &
      4, [character(len=FRAG_LEN) :: "&contact_pair 's/m'", "'max_iterations'", ">= 1"])
  end subroutine bad_max_iterations_zero
  !> 1e400 overflows in the number parser; even with overflow trapping on
  !> (debug builds) the reader must report it rather than die.
  subroutine bad_overflowing_value(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call expect_error(failure, 'overflowing_value', &
      "&mesh file = 'm.msh', scale = 1e400 /" // NL // &
      "&body name = 'a', young = 1.0, poisson = 0.3, density = 1.0 /" // NL // &
      "&time t_end = 1.0 /", &
      1, [character(len=FRAG_LEN) :: "&mesh", "'scale'", "1e400", "finite"])
  end subroutine bad_overflowing_value

end program test_scene_deck
