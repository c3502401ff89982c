!> Scene deck reader: fills scene_t from a file of namelist groups and checks
!> every value on its own (doc/scene-reference.md lists groups and keys).
!>
!> The deck is first split into groups by raccord_deck_scan, which knows the
!> line of every group and key; each group is then read here key by key with
!> an internal namelist read, so that a value that does not read is reported
!> with its key and line. Every message has the form
!>   <deck>:<line>: &<group> '<name>': <what is wrong>; <how to fix it>
!> and comes back in error_t with code EXIT_INPUT; nothing here stops.
!>
!> Defaults come from the default initialization of the raccord_scene types;
!> a required key starts at a sentinel (UNSET, or '' for text) so that a key
!> left out is reported instead of silently taking a value.
module raccord_deck
  use, intrinsic :: ieee_exceptions, only: ieee_overflow, ieee_get_halting_mode, ieee_set_halting_mode, &
    ieee_set_flag, ieee_support_halting
  use raccord_kinds, only: wp, name_len, path_len
  use raccord_error, only: error_t, raise_error, EXIT_INPUT
  use raccord_strings, only: str, lower, text_flaw
  use raccord_log, only: log_warn
  use raccord_paths, only: path_dir, path_stem, path_join, absolute_path
  use raccord_deck_scan, only: deck_block_t, scan_deck, join_names
  use raccord_int_map, only: int_map_t, map_init, map_insert, map_get, text_key
  use raccord_deck_checks, only: head, check_keys, unreadable, bad_value, missing_key, check_length, check_finite, &
    UNSET
  use raccord_deck_run, only: read_run, read_time, read_output
  use raccord_deck_material, only: read_constitution, read_plastic
  use raccord_deck_write, only: write_scene, real_text
  use raccord_deck_contact, only: read_contact
  use raccord_scene, only: scene_t, mesh_spec_t, body_spec_t, bc_spec_t, amplitude_spec_t, &
    MAX_TABLE, BC_FIXED, BC_DISPLACEMENT, BC_TRACTION, BC_PRESSURE
  implicit none
  private

  public :: read_scene, write_scene

  !> A name to check for repeats (first_twin).
  type :: label_t
    character(len=:), allocatable :: s
  end type label_t

  !> Groups a deck may hold, and which of them may appear only once.
  character(len=*), parameter :: GROUPS(*) = [character(len=12) :: 'run', 'mesh', 'body', 'boundary', &
    'amplitude', 'time', 'output', 'contact_pair']
  logical, parameter :: SINGLE(*) = [.true., .true., .false., .false., .false., .true., .true., .false.]

  !> Keys of each group, in the order the documentation and the echo use.
  character(len=*), parameter :: MESH_KEYS(*) = [character(len=16) :: 'file', 'format', 'scale']
  character(len=*), parameter :: BODY_KEYS(*) = [character(len=16) :: 'name', 'elset', 'young', 'poisson', &
    'density', 'hypothesis', 'thickness', 'velocity', 'body_force', 'damping', 'kinematics', 'material', &
    'volumetric', 'yield_stress', 'hardening']
  character(len=*), parameter :: BC_KEYS(*) = [character(len=16) :: 'set', 'type', 'components', 'value', &
    'pressure', 'amplitude']
  character(len=*), parameter :: AMP_KEYS(*) = [character(len=16) :: 'name', 'time', 'value']


contains

  !> Read the scene deck at path into scene. On failure err%code is
  !> EXIT_INPUT and err%message names the file, line, group and key.
  subroutine read_scene(path, scene, err)
    character(len=*), intent(in) :: path
    type(scene_t), intent(out) :: scene
    type(error_t), intent(out) :: err
    logical :: halt_overflow
    ! A value such as 1e400 overflows inside the C library's number parser;
    ! with overflow trapping on (debug builds) that would kill the run before
    ! check_finite can name the key. Trapping is off while reading only.
    call ieee_get_halting_mode(ieee_overflow, halt_overflow)
    if (ieee_support_halting(ieee_overflow)) call ieee_set_halting_mode(ieee_overflow, .false.)
    call read_deck(path, scene, err)
    call ieee_set_flag(ieee_overflow, .false.)
    if (ieee_support_halting(ieee_overflow)) call ieee_set_halting_mode(ieee_overflow, halt_overflow)
  end subroutine read_scene

  subroutine read_deck(path, scene, err)
    character(len=*), intent(in) :: path
    type(scene_t), intent(inout) :: scene
    type(error_t), intent(inout) :: err
    type(deck_block_t), allocatable :: blocks(:)
    integer :: first(size(GROUPS)), n_of(size(GROUPS))
    integer, allocatable :: body_blk(:), bc_blk(:), amp_blk(:), pair_blk(:)
    integer :: k, g, nbody, nbc, namp, ncontact
    character(len=:), allocatable :: stem

    scene%path = path
    scene%dir = absolute_path(path_dir(path))
    stem = path_stem(path)
    ! The results are named after the deck, and the .xmf (XML) names its
    ! .h5 file: a name that is not UTF-8 would make the .xmf unreadable.
    if (len(text_flaw(stem, .true.)) > 0) then
      call raise_error(err, EXIT_INPUT, path // ': the deck''s file name names the results (<name>.h5, ' // &
        '<name>.xmf), and in it ' // text_flaw(stem, .true.) // ', which the .xmf (XML) cannot hold; ' // &
        'rename the deck in plain ASCII or UTF-8')
      return
    end if

    call scan_deck(path, GROUPS, blocks, err)
    if (err%failed()) return

    ! Which groups are there, and are the single ones single.
    first = 0
    n_of = 0
    do k = 1, size(blocks)
      g = findloc(GROUPS, blocks(k)%group, dim=1)
      n_of(g) = n_of(g) + 1
      if (first(g) == 0) then
        first(g) = k
      else if (SINGLE(g)) then
        call raise_error(err, EXIT_INPUT, path // ':' // str(blocks(k)%line) // ': &' // trim(GROUPS(g)) // &
          ': the group appears a second time (first at line ' // str(blocks(first(g))%line) // &
          '); keep a single &' // trim(GROUPS(g)) // ' group')
        return
      end if
    end do
    if (n_of(group_index('mesh')) == 0) then
      call raise_error(err, EXIT_INPUT, path // ': &mesh: the deck has no &mesh group; add one, e.g. ' // &
        '&mesh file = ''part.msh'' /')
    else if (n_of(group_index('time')) == 0) then
      call raise_error(err, EXIT_INPUT, path // ': &time: the deck has no &time group; add one, e.g. ' // &
        '&time t_end = 1.0 /')
    else if (n_of(group_index('body')) == 0) then
      call raise_error(err, EXIT_INPUT, path // ': &body: the deck has no &body group; add one per body, ' // &
        'e.g. &body name = ''part'', young = 70000.0, poisson = 0.3, density = 2.7e-9 /')
    end if
    if (err%failed()) return

    ! Groups that may be left out take their defaults.
    scene%run%title = stem
    scene%run%output_dir = 'results/' // stem
    nbody = n_of(group_index('body'))
    nbc = n_of(group_index('boundary'))
    namp = n_of(group_index('amplitude'))
    ncontact = n_of(group_index('contact_pair'))
    allocate(scene%bodies(nbody), scene%bcs(nbc), scene%amplitudes(namp), scene%contacts(ncontact))
    allocate(body_blk(nbody), bc_blk(nbc), amp_blk(namp), pair_blk(ncontact))

    nbody = 0
    nbc = 0
    namp = 0
    ncontact = 0
    do k = 1, size(blocks)
      select case (blocks(k)%group)
      case ('run')
        call read_run(path, blocks(k), stem, scene%run, err)
      case ('mesh')
        call read_mesh(path, blocks(k), scene%dir, scene%mesh, err)
      case ('body')
        nbody = nbody + 1
        body_blk(nbody) = k
        call read_body(path, blocks(k), scene%bodies(nbody), err)
      case ('boundary')
        nbc = nbc + 1
        bc_blk(nbc) = k
        call read_boundary(path, blocks(k), scene%bcs(nbc), err)
      case ('amplitude')
        namp = namp + 1
        amp_blk(namp) = k
        call read_amplitude(path, blocks(k), scene%amplitudes(namp), err)
      case ('time')
        call read_time(path, blocks(k), scene%time, err)
      case ('output')
        call read_output(path, blocks(k), scene%output, err)
      case ('contact_pair')
        ncontact = ncontact + 1
        pair_blk(ncontact) = k
        call read_contact(path, blocks(k), scene%contacts(ncontact), err)
      end select
      if (err%failed()) return
    end do

    call check_references(path, blocks, scene, body_blk, bc_blk, amp_blk, err)
    if (err%failed()) return
    call check_hypotheses(path, blocks, scene, body_blk, err)
    if (err%failed()) return
    call check_pairs(path, blocks, scene, pair_blk, err)
    ! A body without its own damping takes the &time damping.
    do k = 1, size(scene%bodies)
      if (scene%bodies(k)%damping < 0.0_wp) scene%bodies(k)%damping = scene%time%damping
    end do
  end subroutine read_deck

  pure integer function group_index(name)
    character(len=*), intent(in) :: name
    group_index = findloc(GROUPS, name, dim=1)
  end function group_index

  !> Checks across groups: unique body and amplitude names, and every
  !> amplitude a boundary names is defined.
  subroutine check_references(deck, blocks, scene, body_blk, bc_blk, amp_blk, err)
    character(len=*), intent(in) :: deck
    type(deck_block_t), intent(in) :: blocks(:)
    type(scene_t), intent(in) :: scene
    integer, intent(in) :: body_blk(:), bc_blk(:), amp_blk(:)
    type(error_t), intent(inout) :: err
    integer :: i, j, twin(2)
    type(label_t), allocatable :: labels(:)
    type(int_map_t) :: body_index, amp_index
    ! filled one by one: gfortran 12 leaves the text empty in an array
    ! constructor of label_t(...) values
    allocate(labels(size(scene%bodies)))
    do i = 1, size(labels)
      labels(i)%s = scene%bodies(i)%name
    end do
    twin = first_twin(labels, body_index)
    if (twin(1) > 0) then
      i = twin(1)
      call bad_value(deck, blocks(body_blk(i)), scene%bodies(i)%name, 'name', &
        'the name is already used by the &body at line ' // str(blocks(body_blk(twin(2)))%line), &
        'give each body its own name', err)
      return
    end if
    deallocate(labels)
    allocate(labels(size(scene%amplitudes)))
    do i = 1, size(labels)
      labels(i)%s = scene%amplitudes(i)%name
    end do
    twin = first_twin(labels, amp_index)
    if (twin(1) > 0) then
      i = twin(1)
      call bad_value(deck, blocks(amp_blk(i)), scene%amplitudes(i)%name, 'name', &
        'the name is already used by the &amplitude at line ' // str(blocks(amp_blk(twin(2)))%line), &
        'give each amplitude its own name', err)
      return
    end if
    do i = 1, size(scene%bcs)
      if (len(scene%bcs(i)%amplitude) == 0) cycle
      ! amp_index: name -> amplitude (first_twin above), so that each of
      ! 10^4 boundaries finds its amplitude among 10^4 in O(1)
      j = map_get(amp_index, text_key(scene%bcs(i)%amplitude))
      if (j > 0) then
        if (scene%amplitudes(j)%name == scene%bcs(i)%amplitude) cycle
        ! two names of one text_key (rare): look the name up one by one
        if (any([(scene%amplitudes(j)%name == scene%bcs(i)%amplitude, j = 1, size(scene%amplitudes))])) cycle
      end if
      ! A near miss (the same name in another case) is named: deck names
      ! are case-sensitive, as the mesh's Gmsh names are.
      do j = 1, size(scene%amplitudes)
        if (lower(scene%amplitudes(j)%name) /= lower(scene%bcs(i)%amplitude)) cycle
        call bad_value(deck, blocks(bc_blk(i)), scene%bcs(i)%set, 'amplitude', &
          'no &amplitude group has this name; the &amplitude at line ' // str(blocks(amp_blk(j))%line) // &
          ' is named ''' // scene%amplitudes(j)%name // ''' (names are case-sensitive)', &
          'write amplitude = ''' // scene%amplitudes(j)%name // '''', err)
        return
      end do
      call bad_value(deck, blocks(bc_blk(i)), scene%bcs(i)%set, 'amplitude', &
        'no &amplitude group has this name (defined: ' // amplitude_names(scene) // ')', &
        'add &amplitude name = ''' // scene%bcs(i)%amplitude // ''', time = ..., value = ... / ' // &
        'or correct the name (names are case-sensitive)', err)
      return
    end do
  end subroutine check_references

  !> A pair given twice (the same slave and the same master) would enforce
  !> the same conditions twice; two-pass contact swaps the roles.
  subroutine check_pairs(deck, blocks, scene, pair_blk, err)
    character(len=*), intent(in) :: deck
    type(deck_block_t), intent(in) :: blocks(:)
    type(scene_t), intent(in) :: scene
    integer, intent(in) :: pair_blk(:)
    type(error_t), intent(inout) :: err
    integer :: i, twin(2)
    type(int_map_t) :: index
    type(label_t), allocatable :: labels(:)
    ! a NUL between the names: no two different pairs give one label
    allocate(labels(size(scene%contacts)))
    do i = 1, size(labels)
      labels(i)%s = scene%contacts(i)%slave // achar(0) // scene%contacts(i)%master
    end do
    twin = first_twin(labels, index)
    if (twin(1) == 0) return
    i = twin(1)
    call bad_value(deck, blocks(pair_blk(i)), scene%contacts(i)%slave // '/' // scene%contacts(i)%master, &
      'master', 'the same slave and master as the &contact_pair at line ' // str(blocks(pair_blk(twin(2)))%line), &
      'give each pair once (two-pass contact swaps slave and master in the second pair)', err)
  end subroutine check_pairs

  !> The first label equal to an earlier one, as [its index, the earlier
  !> one's], or [0, 0] when all differ; index maps text_key of each label to
  !> its first index. Linear through the map: comparing every pair made a
  !> deck of 2*10^4 groups spend minutes here.
  function first_twin(labels, index) result(twin)
    type(label_t), intent(in) :: labels(:)
    type(int_map_t), intent(out) :: index
    integer :: twin(2)
    integer :: i, j, prev
    twin = 0
    call map_init(index, size(labels))
    do i = 1, size(labels)
      call map_insert(index, text_key(labels(i)%s), i, prev)
      if (prev == 0) cycle
      if (labels(prev)%s == labels(i)%s) then
        twin = [i, prev]
        return
      end if
      ! two labels of one text_key (rare): compare with each earlier one
      do j = 1, i - 1
        if (labels(j)%s /= labels(i)%s) cycle
        twin = [i, j]
        return
      end do
    end do
  end function first_twin

  !> Bodies of one scene share the hypothesis family: all axisymmetric or
  !> all plane (plane strain and plane stress may mix; doc/scene-reference.md).
  subroutine check_hypotheses(deck, blocks, scene, body_blk, err)
    character(len=*), intent(in) :: deck
    type(deck_block_t), intent(in) :: blocks(:)
    type(scene_t), intent(in) :: scene
    integer, intent(in) :: body_blk(:)
    type(error_t), intent(inout) :: err
    integer :: i
    do i = 2, size(scene%bodies)
      if (scene%bodies(i)%axisymmetric .eqv. scene%bodies(1)%axisymmetric) cycle
      call bad_value(deck, blocks(body_blk(i)), scene%bodies(i)%name, 'hypothesis', &
        'the body is ' // trim(merge('axisymmetric', 'plane       ', scene%bodies(i)%axisymmetric)) // &
        ' but &body ''' // scene%bodies(1)%name // ''' (line ' // str(blocks(body_blk(1))%line) // ') is ' // &
        trim(merge('axisymmetric', 'plane       ', scene%bodies(1)%axisymmetric)) // &
        '; the bodies of one scene share the hypothesis', &
        'write hypothesis = ''axisymmetric'' in every &body, or in none', err)
      return
    end do
  end subroutine check_hypotheses

  function amplitude_names(scene) result(s)
    type(scene_t), intent(in) :: scene
    character(len=:), allocatable :: s
    integer :: j
    s = ''
    do j = 1, size(scene%amplitudes)
      if (j > 1) s = s // ', '
      s = s // scene%amplitudes(j)%name
    end do
    if (len(s) == 0) s = 'none'
  end function amplitude_names

  ! ---------------------------------------------------------------- groups


  !> &mesh file, format, scale.
  subroutine read_mesh(deck, blk, dir, spec, err)
    character(len=*), intent(in) :: deck, dir
    type(deck_block_t), intent(in) :: blk
    type(mesh_spec_t), intent(out) :: spec
    type(error_t), intent(inout) :: err
    character(len=path_len) :: file
    character(len=name_len) :: format
    real(wp) :: scale
    namelist /mesh/ file, format, scale
    character(len=:), allocatable :: record
    character(len=256) :: msg
    integer :: k, ios

    file = ''
    format = 'auto'
    scale = spec%scale
    call check_keys(deck, blk, MESH_KEYS, '', err)
    if (err%failed()) return
    do k = 1, size(blk%keys)
      record = blk%item(k)
      msg = ''
      read(record, nml=mesh, iostat=ios, iomsg=msg)
      if (ios /= 0) then
        call unreadable(deck, blk, k, '', msg, err)
        return
      end if
    end do
    call check_length(deck, blk, '', 'file', file, err)
    call check_finite(deck, blk, '', ['scale'], [scale], err)
    if (err%failed()) return

    if (len_trim(file) == 0) then
      call missing_key(deck, blk, '', 'file', 'file = ''part.msh'' (a path relative to the deck''s folder)', err)
      return
    end if
    format = lower(format)
    select case (format)
    case ('auto', 'gmsh', 'abaqus')
    case default
      call bad_value(deck, blk, '', 'format', 'unknown mesh format', &
        'use ''auto'' (from the file extension), ''gmsh'' or ''abaqus''', err)
      return
    end select
    if (.not. (scale > 0.0_wp)) then
      call bad_value(deck, blk, '', 'scale', 'the scale factor must be > 0', &
        'give the factor from mesh units to deck units, e.g. scale = 1.0e3 for a mesh in m and a deck in mm', err)
      return
    end if
    ! The mesh lives with the deck: a relative path is resolved against the
    ! deck's folder, so the deck can be run from anywhere.
    spec%file = path_join(dir, trim(file))
    spec%format = trim(format)
    spec%scale = scale
  end subroutine read_mesh

  !> &body name, elset, young, poisson, density, hypothesis, thickness, velocity, body_force, damping.
  subroutine read_body(deck, blk, spec, err)
    character(len=*), intent(in) :: deck
    type(deck_block_t), intent(in) :: blk
    type(body_spec_t), intent(out) :: spec
    type(error_t), intent(inout) :: err
    character(len=name_len) :: name, elset, hypothesis, kinematics, material, volumetric
    real(wp) :: young, poisson, density, thickness, velocity(2), body_force(2), damping, yield_stress, hardening
    namelist /body/ name, elset, young, poisson, density, hypothesis, thickness, velocity, body_force, damping, &
      kinematics, material, volumetric, yield_stress, hardening
    character(len=:), allocatable :: record, label
    character(len=256) :: msg
    integer :: k, ios

    name = ''
    elset = ''
    young = UNSET
    poisson = UNSET
    density = UNSET
    hypothesis = 'plane_strain'
    kinematics = 'small'
    material = 'linear_elastic'
    volumetric = 'auto'
    yield_stress = UNSET
    hardening = UNSET
    thickness = spec%thickness
    velocity = spec%velocity
    body_force = spec%body_force
    damping = spec%damping

    ! The body's name labels every message, so read it first.
    k = blk%find('name')
    if (k > 0) then
      record = blk%item(k)
      read(record, nml=body, iostat=ios, iomsg=msg)
    end if
    label = trim(name)
    call check_keys(deck, blk, BODY_KEYS, label, err)
    if (err%failed()) return
    do k = 1, size(blk%keys)
      record = blk%item(k)
      msg = ''
      read(record, nml=body, iostat=ios, iomsg=msg)
      if (ios /= 0) then
        call unreadable(deck, blk, k, label, msg, err)
        return
      end if
    end do
    call check_length(deck, blk, label, 'name', name, err)
    call check_length(deck, blk, label, 'elset', elset, err)
    call check_finite(deck, blk, label, [character(len=12) :: 'young', 'poisson', 'density', 'thickness', &
      'velocity', 'velocity', 'body_force', 'body_force', 'damping', 'yield_stress', 'hardening'], &
      [young, poisson, density, thickness, velocity, body_force, damping, yield_stress, hardening], err)
    if (err%failed()) return

    if (len_trim(name) == 0) then
      call missing_key(deck, blk, label, 'name', 'name = ''part'' (used in messages and results)', err)
    else if (.not. link_name(name)) then
      call bad_value(deck, blk, label, 'name', 'the results file keeps the body''s elements under ' // &
        '/mesh/blocks/<name>, and an HDF5 name can neither hold ''/'' nor be ''.''', &
        'rename the body (the elements still come from elset, or the mesh set of the old name: ' // &
        'elset = ''' // trim(name) // ''')', err)
    else if (young == UNSET) then
      call missing_key(deck, blk, label, 'young', 'young = <Young''s modulus>, e.g. 70000.0 (MPa)', err)
    else if (poisson == UNSET) then
      call missing_key(deck, blk, label, 'poisson', 'poisson = <Poisson''s ratio>, e.g. 0.3', err)
    else if (density == UNSET) then
      call missing_key(deck, blk, label, 'density', 'density = <mass density>, e.g. 2.7e-9 (t/mm^3)', err)
    else if (.not. (young > 0.0_wp)) then
      call bad_value(deck, blk, label, 'young', 'Young''s modulus must be > 0', &
        'give it in stress units, e.g. young = 70000.0 (MPa)', err)
    else if (.not. (poisson > -1.0_wp .and. poisson < 0.5_wp)) then
      call bad_value(deck, blk, label, 'poisson', 'Poisson''s ratio must lie in (-1, 0.5)', &
        'use e.g. poisson = 0.3 (0.5 would be incompressible, which this element cannot represent)', err)
    else if (.not. (density > 0.0_wp)) then
      call bad_value(deck, blk, label, 'density', 'the density must be > 0', &
        'give it in mass/length^3, e.g. density = 2.7e-9 (t/mm^3)', err)
    else if (.not. (thickness > 0.0_wp)) then
      call bad_value(deck, blk, label, 'thickness', 'the thickness must be > 0', &
        'give the out-of-plane thickness, e.g. thickness = 1.0', err)
    else if (blk%find('damping') > 0 .and. .not. (damping >= 0.0_wp)) then
      call bad_value(deck, blk, label, 'damping', 'the damping coefficient must be >= 0', &
        'give alpha in 1/time (about twice the lowest circular frequency damps that mode critically), ' // &
        'or leave the key out to use the &time damping', err)
    end if
    if (err%failed()) return
    hypothesis = lower(hypothesis)
    select case (hypothesis)
    case ('plane_strain')
      spec%plane_stress = .false.
    case ('plane_stress')
      spec%plane_stress = .true.
    case ('axisymmetric')
      ! x is the radius, y the axis; every integral carries 2 pi r, so a
      ! thickness has no meaning: ignored, with a warning (scene reference)
      spec%axisymmetric = .true.
      if (blk%find('thickness') > 0) call log_warn('read_deck', deck // ':' // str(blk%line) // ': &body ''' // &
        label // ''': thickness is ignored with hypothesis = ''axisymmetric'' (forces are totals over 2 pi); ' // &
        'remove the key')
      thickness = 1.0_wp
    case default
      call bad_value(deck, blk, label, 'hypothesis', 'unknown hypothesis', &
        'use ''plane_strain'', ''plane_stress'' or ''axisymmetric''', err)
      return
    end select
    call read_constitution(deck, blk, label, lower(kinematics), lower(material), lower(volumetric), spec, err)
    if (err%failed()) return
    call read_plastic(deck, blk, label, yield_stress, hardening, spec, err)
    if (err%failed()) return

    spec%name = trim(name)
    ! The element set defaults to the body's name (one physical group per body).
    if (len_trim(elset) == 0) then
      spec%elset = spec%name
    else
      spec%elset = trim(elset)
    end if
    spec%young = young
    spec%poisson = poisson
    spec%density = density
    spec%thickness = thickness
    spec%velocity = velocity
    spec%body_force = body_force
    spec%damping = damping
  end subroutine read_body

  !> &boundary set, type, components, value, pressure, amplitude.
  subroutine read_boundary(deck, blk, spec, err)
    character(len=*), intent(in) :: deck
    type(deck_block_t), intent(in) :: blk
    type(bc_spec_t), intent(out) :: spec
    type(error_t), intent(inout) :: err
    character(len=name_len) :: set, type, components, amplitude
    real(wp) :: value(2), pressure
    namelist /boundary/ set, type, components, value, pressure, amplitude
    character(len=:), allocatable :: record, label
    character(len=16), allocatable :: applies(:)
    character(len=256) :: msg
    integer :: k, ios

    set = ''
    type = ''
    components = ''
    value = UNSET
    pressure = UNSET
    amplitude = ''

    k = blk%find('set')
    if (k > 0) then
      record = blk%item(k)
      read(record, nml=boundary, iostat=ios, iomsg=msg)
    end if
    label = trim(set)
    call check_keys(deck, blk, BC_KEYS, label, err)
    if (err%failed()) return
    do k = 1, size(blk%keys)
      record = blk%item(k)
      msg = ''
      read(record, nml=boundary, iostat=ios, iomsg=msg)
      if (ios /= 0) then
        call unreadable(deck, blk, k, label, msg, err)
        return
      end if
    end do
    call check_length(deck, blk, label, 'set', set, err)
    call check_length(deck, blk, label, 'amplitude', amplitude, err)
    call check_finite(deck, blk, label, [character(len=8) :: 'value', 'value', 'pressure'], &
      [value, pressure], err)
    if (err%failed()) return

    if (len_trim(set) == 0) then
      call missing_key(deck, blk, label, 'set', 'set = ''<node set or surface of the mesh>''', err)
      return
    end if
    if (len_trim(type) == 0) then
      call missing_key(deck, blk, label, 'type', 'type = ''fixed'', ''displacement'', ''traction'' or ''pressure''', err)
      return
    end if

    ! Each type uses only some keys; a key of another type is refused rather
    ! than ignored, since type = 'fixed' with a value usually means the user
    ! wanted an imposed displacement.
    select case (lower(type))
    case ('fixed')
      spec%kind = BC_FIXED
      applies = [character(len=16) :: 'set', 'type', 'components']
      if (len_trim(components) == 0) components = 'xy'
    case ('displacement')
      spec%kind = BC_DISPLACEMENT
      applies = [character(len=16) :: 'set', 'type', 'components', 'value', 'amplitude']
    case ('traction')
      spec%kind = BC_TRACTION
      applies = [character(len=16) :: 'set', 'type', 'value', 'amplitude']
    case ('pressure')
      spec%kind = BC_PRESSURE
      applies = [character(len=16) :: 'set', 'type', 'pressure', 'amplitude']
    case default
      call bad_value(deck, blk, label, 'type', 'unknown boundary condition type', &
        'use ''fixed'', ''displacement'', ''traction'' or ''pressure''', err)
      return
    end select
    do k = 1, size(blk%keys)
      if (any(applies == blk%keys(k)%name)) cycle
      call bad_value(deck, blk, label, blk%keys(k)%name, 'the key does not apply to type ''' // &
        trim(lower(type)) // '''', 'remove it (keys of this type: ' // join_names(applies) // ')', err)
      return
    end do

    if (spec%kind == BC_FIXED .or. spec%kind == BC_DISPLACEMENT) then
      if (.not. link_name(set)) then
        call bad_value(deck, blk, label, 'set', 'the results file keeps the nodes of a support under ' // &
          '/mesh/node_sets/<set>, and an HDF5 name can neither hold ''/'' nor be ''.''', &
          'rename the set in the mesh (and here)', err)
        return
      end if
      if (len_trim(components) == 0) then
        call missing_key(deck, blk, label, 'components', 'components = ''xy'', ''x'' or ''y''', err)
        return
      end if
      select case (lower(components))
      case ('xy')
        spec%comp = [.true., .true.]
      case ('x')
        spec%comp = [.true., .false.]
      case ('y')
        spec%comp = [.false., .true.]
      case default
        call bad_value(deck, blk, label, 'components', 'unknown components', &
          'use ''xy'', ''x'' or ''y''', err)
        return
      end select
    end if

    select case (spec%kind)
    case (BC_DISPLACEMENT)
      ! value is always the (x, y) pair; only the listed components need one.
      if (any(spec%comp .and. value == UNSET)) then
        call missing_key(deck, blk, label, 'value', 'value = <ux>, <uy> (give a number for each listed component)', err)
        return
      end if
      where (.not. spec%comp .or. value == UNSET) value = 0.0_wp
      spec%value = value
    case (BC_TRACTION)
      if (any(value == UNSET)) then
        call missing_key(deck, blk, label, 'value', 'value = <tx>, <ty> (the traction vector, stress units)', err)
        return
      end if
      spec%value = value
    case (BC_PRESSURE)
      if (pressure == UNSET) then
        call missing_key(deck, blk, label, 'pressure', 'pressure = <p> (stress units, positive pushes inward)', err)
        return
      end if
      spec%pressure = pressure
    end select

    spec%set = trim(set)
    spec%amplitude = trim(amplitude)
  end subroutine read_boundary

  !> &amplitude name, time, value.
  subroutine read_amplitude(deck, blk, spec, err)
    character(len=*), intent(in) :: deck
    type(deck_block_t), intent(in) :: blk
    type(amplitude_spec_t), intent(out) :: spec
    type(error_t), intent(inout) :: err
    character(len=name_len) :: name
    real(wp) :: time(MAX_TABLE), value(MAX_TABLE)
    namelist /amplitude/ name, time, value
    character(len=:), allocatable :: record, label
    character(len=5), allocatable :: table_keys(:)
    character(len=256) :: msg
    integer :: k, ios, nt, nv

    name = ''
    time = UNSET
    value = UNSET

    k = blk%find('name')
    if (k > 0) then
      record = blk%item(k)
      read(record, nml=amplitude, iostat=ios, iomsg=msg)
    end if
    label = trim(name)
    call check_keys(deck, blk, AMP_KEYS, label, err)
    if (err%failed()) return
    do k = 1, size(blk%keys)
      record = blk%item(k)
      msg = ''
      read(record, nml=amplitude, iostat=ios, iomsg=msg)
      if (ios /= 0) then
        call unreadable(deck, blk, k, label, msg, err)
        return
      end if
    end do
    call check_length(deck, blk, label, 'name', name, err)
    if (err%failed()) return
    if (len_trim(name) == 0) then
      call missing_key(deck, blk, label, 'name', 'name = ''<amplitude name>'' (boundaries refer to it)', err)
      return
    end if
    nt = table_length(deck, blk, label, 'time', time, err)
    nv = table_length(deck, blk, label, 'value', value, err)
    if (err%failed()) return
    ! Key names built by hand: gfortran 12 overruns a typed character array
    ! constructor with implied-do loops over literals of different lengths.
    allocate(table_keys(nt + nv))
    table_keys(1:nt) = 'time'
    table_keys(nt+1:) = 'value'
    call check_finite(deck, blk, label, table_keys, [time(1:nt), value(1:nv)], err)
    if (err%failed()) return
    if (nt == 0) then
      call missing_key(deck, blk, label, 'time', 'time = t1, t2, ... (at least one point)', err)
      return
    end if
    if (nv == 0) then
      call missing_key(deck, blk, label, 'value', 'value = a1, a2, ... (one per time)', err)
      return
    end if
    if (nt /= nv) then
      call bad_value(deck, blk, label, 'value', 'time has ' // str(nt) // ' points but value has ' // str(nv), &
        'give one value per time', err)
      return
    end if
    do k = 2, nt
      if (time(k) > time(k-1)) cycle
      call bad_value(deck, blk, label, 'time', 'the times are not strictly increasing (point ' // str(k) // &
        ': ' // real_text(time(k)) // ' after ' // real_text(time(k-1)) // ')', 'list the times in increasing order', err)
      return
    end do
    spec%name = trim(name)
    spec%npoint = nt
    spec%t = time(1:nt)
    spec%a = value(1:nt)
  end subroutine read_amplitude

  !> A name that can be one link of an HDF5 path in the results file.
  pure logical function link_name(name)
    character(len=*), intent(in) :: name
    link_name = index(name, '/') == 0 .and. trim(name) /= '.'
  end function link_name

  !> Number of entries given in a table key; the entries must be contiguous
  !> from the first (a gap would leave a sentinel inside the table).
  integer function table_length(deck, blk, label, key, table, err) result(n)
    character(len=*), intent(in) :: deck, label, key
    type(deck_block_t), intent(in) :: blk
    real(wp), intent(in) :: table(:)
    type(error_t), intent(inout) :: err
    integer :: k
    n = 0
    do k = size(table), 1, -1
      if (table(k) /= UNSET) then
        n = k
        exit
      end if
    end do
    do k = 1, n
      if (table(k) /= UNSET) cycle
      call bad_value(deck, blk, label, key, 'entry ' // str(k) // ' is not given but entry ' // str(n) // ' is', &
        'give every entry from the first, e.g. ' // key // ' = 0.0, 1.0, 2.0', err)
      return
    end do
  end function table_length
end module raccord_deck
