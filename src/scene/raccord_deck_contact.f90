!> Scene deck reader, the &contact_pair group: surfaces, matching method,
!> multiplier space, friction and the solve's keys, each checked against
!> its range and the others (doc/scene-reference.md, &contact_pair). Split
!> from raccord_deck, whose read_deck calls read_contact; messages follow
!> its form
!>   <deck>:<line>: &<group> '<name>': <what is wrong>; <how to fix it>
module raccord_deck_contact
  use raccord_kinds, only: wp, name_len
  use raccord_error, only: error_t
  use raccord_strings, only: str, lower
  use raccord_log, only: log_warn
  use raccord_deck_scan, only: deck_block_t
  use raccord_deck_checks, only: head, check_keys, unreadable, bad_value, missing_key, check_length, check_finite
  use raccord_deck_write, only: real_text
  use raccord_scene, only: contact_spec_t, METHOD_NTS, METHOD_MORTAR, MULT_P1, MULT_P0, MULT_DUAL
  implicit none
  private

  public :: read_contact

  !> Largest &contact_pair max_iterations (read_contact).
  integer, parameter :: MAX_CONTACT_ITERATIONS = 10000
  !> &contact_pair friction: largest Coulomb coefficient accepted, and the
  !> one above which a warning says the value is not a measured friction
  !> coefficient (doc/scene-reference.md, &contact_pair). Measured dry
  !> coefficients lie below about 1.5 (rubber up to about 3); a larger mu
  !> is a device for contact that seldom slips, and beyond 1e3 the value
  !> changes nothing in a run: a node slips only where the tangential
  !> traction passes mu times the pressure, so mu = 1e3 already sticks
  !> wherever the pressure is 1e-3 of the tangential traction.
  real(wp), parameter :: MAX_FRICTION = 1.0e3_wp
  real(wp), parameter :: WARN_FRICTION = 10.0_wp
  !> Keys of the group, in the order the documentation and the echo use.
  character(len=*), parameter :: CONTACT_KEYS(*) = [character(len=16) :: 'slave', 'master', 'method', &
    'multiplier', 'friction', 'search_distance', 'tolerance', 'max_iterations', 'conditions', &
    'edge_multipliers']

contains

  !> &contact_pair slave, master, method, multiplier, friction, search_distance, tolerance, max_iterations,
  !> conditions, edge_multipliers.
  subroutine read_contact(deck, blk, spec, err)
    character(len=*), intent(in) :: deck
    type(deck_block_t), intent(in) :: blk
    type(contact_spec_t), intent(out) :: spec
    type(error_t), intent(inout) :: err
    character(len=name_len) :: slave, master, method, multiplier, conditions, edge_multipliers
    real(wp) :: friction, search_distance, tolerance
    integer :: max_iterations
    namelist /contact_pair/ slave, master, method, multiplier, friction, search_distance, tolerance, max_iterations, &
      conditions, edge_multipliers
    character(len=:), allocatable :: record, label
    character(len=256) :: msg
    integer :: k, ios

    slave = ''
    master = ''
    method = 'node_to_segment'
    multiplier = 'P1'
    conditions = 'nodal'
    edge_multipliers = 'all_nodes'
    friction = spec%friction
    search_distance = spec%search_distance
    tolerance = spec%tolerance
    max_iterations = spec%max_iterations

    ! The pair is labelled 'slave/master' in messages.
    do k = 1, size(blk%keys)
      if (blk%keys(k)%name /= 'slave' .and. blk%keys(k)%name /= 'master') cycle
      record = blk%item(k)
      read(record, nml=contact_pair, iostat=ios, iomsg=msg)
    end do
    label = trim(slave) // '/' // trim(master)
    if (len_trim(slave) == 0 .and. len_trim(master) == 0) label = ''   ! not '/'
    call check_keys(deck, blk, CONTACT_KEYS, label, err)
    if (err%failed()) return
    do k = 1, size(blk%keys)
      record = blk%item(k)
      msg = ''
      read(record, nml=contact_pair, iostat=ios, iomsg=msg)
      if (ios /= 0) then
        call unreadable(deck, blk, k, label, msg, err)
        return
      end if
    end do
    call check_length(deck, blk, label, 'slave', slave, err)
    call check_length(deck, blk, label, 'master', master, err)
    call check_finite(deck, blk, label, [character(len=16) :: 'friction', 'search_distance', 'tolerance'], &
      [friction, search_distance, tolerance], err)
    if (err%failed()) return

    if (len_trim(slave) == 0) then
      call missing_key(deck, blk, label, 'slave', 'slave = ''<surface of the mesh>''', err)
    else if (len_trim(master) == 0) then
      call missing_key(deck, blk, label, 'master', 'master = ''<surface of the mesh>''', err)
    else if (slave == master) then
      call bad_value(deck, blk, label, 'master', 'slave and master are the same surface', &
        'a pair needs two different surfaces (self-contact is not supported)', err)
    else if (.not. (friction >= 0.0_wp)) then
      call bad_value(deck, blk, label, 'friction', 'the friction coefficient must be >= 0', &
        'give the Coulomb coefficient, or friction = 0 for frictionless contact', err)
    else if (friction > MAX_FRICTION) then
      call bad_value(deck, blk, label, 'friction', 'the Coulomb coefficient must be at most ' // &
        real_text(MAX_FRICTION) // ' (measured coefficients of dry contact lie below about 1.5; a pair ' // &
        'slips only where the tangential traction passes friction times the pressure, so a larger value ' // &
        'changes nothing but the round-off)', 'give the measured coefficient, or friction = ' // &
        real_text(MAX_FRICTION) // ' for contact that should not slip', err)
    else if (.not. (search_distance >= 0.0_wp)) then
      call bad_value(deck, blk, label, 'search_distance', 'the search distance must be >= 0', &
        'give a length, or search_distance = 0 for automatic', err)
    else if (.not. (tolerance > 0.0_wp .and. tolerance < 1.0_wp)) then
      call bad_value(deck, blk, label, 'tolerance', 'the solver tolerance is a relative residual: it must be ' // &
        '> 0 and < 1', 'use e.g. tolerance = 1e-12 (the default)', err)
    else if (max_iterations < 1) then
      call bad_value(deck, blk, label, 'max_iterations', 'the iteration cap must be >= 1', &
        'use e.g. max_iterations = 200', err)
    else if (max_iterations > MAX_CONTACT_ITERATIONS) then
      ! A step is not interrupted inside the multiplier solve (a stop
      ! signal waits for the step's end), so the cap bounds a step's time
      ! when the active set cycles; the iteration settles in tens.
      call bad_value(deck, blk, label, 'max_iterations', 'the iteration cap must be at most ' // &
        str(MAX_CONTACT_ITERATIONS) // ' (a step is not interrupted inside the multiplier solve, so a ' // &
        'larger cap could hold one step for hours)', 'use e.g. max_iterations = 200; a pair that does ' // &
        'not converge within it is reported at each such step', err)
    end if
    if (err%failed()) return

    select case (lower(method))
    case ('node_to_segment')
      spec%method = METHOD_NTS
    case ('mortar')
      spec%method = METHOD_MORTAR
    case default
      call bad_value(deck, blk, label, 'method', 'unknown contact method', &
        'use ''node_to_segment'' or ''mortar''', err)
      return
    end select
    select case (lower(multiplier))
    case ('p1')
      spec%multiplier = MULT_P1
    case ('p0')
      spec%multiplier = MULT_P0
    case ('dual')
      spec%multiplier = MULT_DUAL
    case default
      call bad_value(deck, blk, label, 'multiplier', 'unknown multiplier space', &
        'use ''P1'', ''P0'' or ''dual''', err)
      return
    end select
    select case (lower(conditions))
    case ('nodal')
      spec%weighted = .false.
    case ('weighted')
      spec%weighted = .true.
    case default
      call bad_value(deck, blk, label, 'conditions', 'unknown contact conditions', &
        'use ''nodal'' (the paper''s (19), the default) or ''weighted'' (each multiplier against its ' // &
        'own weighted gap; doc/scene-reference.md)', err)
      return
    end select
    if (spec%weighted .and. spec%method == METHOD_NTS) then
      call bad_value(deck, blk, label, 'conditions', 'conditions = ''weighted'' is a key of method = ''mortar''', &
        'node-to-segment already holds each multiplier against its own gap along the master''s normal; ' // &
        'remove the key or use method = ''mortar''', err)
      return
    end if
    select case (lower(edge_multipliers))
    case ('all_nodes')
      spec%corners = .false.
    case ('corners')
      spec%corners = .true.
    case ('tangential_corners')
      spec%corners = .false.
      spec%tcorners = .true.
    case default
      call bad_value(deck, blk, label, 'edge_multipliers', 'unknown choice of multiplier nodes on quadratic edges', &
        'use ''all_nodes'' (a multiplier at every node of a Q8 slave edge, the default), ''corners'' ' // &
        '(at its corner nodes only) or ''tangential_corners'' (the tangential ones at the corners only, ' // &
        'the normal ones at every node; doc/scene-reference.md)', err)
      return
    end select
    if (spec%tcorners .and. (spec%method == METHOD_NTS .or. spec%multiplier == MULT_DUAL .or. spec%weighted)) then
      call bad_value(deck, blk, label, 'edge_multipliers', 'edge_multipliers = ''tangential_corners'' works with ' // &
        'method = ''mortar'', multiplier = ''P1'' or ''P0'' and conditions = ''nodal''', &
        'it changes the tangential multipliers of the paper''s conditions (19) on a Q8 slave only; remove the ' // &
        'key or change the others', err)
      return
    end if
    if (spec%corners .and. spec%method == METHOD_NTS) then
      call bad_value(deck, blk, label, 'edge_multipliers', 'edge_multipliers = ''corners'' is a key of ' // &
        'method = ''mortar''', 'node-to-segment has a multiplier at every slave node; remove the key or use ' // &
        'method = ''mortar''', err)
      return
    end if
    if (spec%corners .and. spec%multiplier == MULT_DUAL) then
      call bad_value(deck, blk, label, 'edge_multipliers', 'edge_multipliers = ''corners'' works with ' // &
        'multiplier = ''P1'' or ''P0''', 'the dual basis has a multiplier at every node of the edge, ' // &
        'biorthogonal to its shape functions; remove the key or use ''P1''', err)
      return
    end if
    if (spec%corners .and. spec%weighted) then
      call bad_value(deck, blk, label, 'edge_multipliers', 'edge_multipliers = ''corners'' works with the ' // &
        'paper''s conditions only', 'use conditions = ''nodal'' (the default) with it, or remove the key ' // &
        '(with the weighted conditions the corner space let contact give energy on a Q8 ball)', err)
      return
    end if
    if (friction > WARN_FRICTION) call log_warn('read_deck', head(deck, blk, blk%key_line('friction'), label) // &
      ': friction = ' // real_text(friction) // ' is above the Coulomb coefficients measured for dry contact ' // &
      '(below about 1.5); accepted: the pair slips only where the tangential traction passes ' // &
      real_text(friction) // ' times the contact pressure. If that is not meant, give the measured coefficient')
    ! tolerance: the multiplier solve is direct (banded solves) and ends
    ! when its active sets repeat, (19) then holding to round-off; where
    ! the sets have not settled after 30 iterations, an iterate whose
    ! residual of (19) is within tolerance ends it (holds_to_roundoff in
    ! raccord_solver_conditions; max_iterations caps the rest).
    spec%slave = trim(slave)
    spec%master = trim(master)
    spec%friction = friction
    spec%search_distance = search_distance
    spec%tolerance = tolerance
    spec%max_iterations = max_iterations
  end subroutine read_contact
end module raccord_deck_contact
