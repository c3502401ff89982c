!> Closed contact surfaces (issue 16, item 4): loops as slave and as
!> master, node-to-segment and mortar (P1, P0), in memory.
!>
!> 1. Rings (patch-type): a compound cylinder of two full rings, plane
!>    strain, E 1000 inside (a <= r <= b), 2000 outside (b <= r <= c), in
!>    frictionless contact at r = b with zero interference, a pressure p on
!>    r = a; rigid motions held by symmetric supports (u_y = 0 on y = 0,
!>    u_x = 0 on x = 0). Either loop is the slave. On matching meshes the
!>    discrete problem has the mesh's cyclic symmetry, so the contact
!>    pressure must be uniform to round-off round the whole loop (mortar
!>    multipliers across the seam of the loop included); its value and
!>    u_r(a) are compared with the Lame closed form (the faceting error of
!>    the interface polygon, d^2/8 for a facet angle d, and the ring's
!>    discretisation error bound them). On non-matching meshes (1:2, the
!>    fine ring's interface nodes on the coarse ring's chords, zero gap)
!>    the pressure is compared with Lame.
!> 2. Pin in a hole with clearance: a thick pin (ring 0.5 <= r <= 0.97)
!>    in a plate (ring 1 <= r <= 3, outer edge clamped), pushed in +x by a
!>    traction on its bore (ramped, then held, damped to rest), touching
!>    at theta = 0 at t = 0. Frictionless and mu = 0.3, each matching, the
!>    pin's loop as slave; against the same runs on a mesh refined twice
!>    (the fine-mesh reference): the pin's displacement, the contact
!>    resultant (= the applied load at rest) and the contact arc.
program test_closed
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use raccord_kinds, only: wp, pi
  use raccord_check, only: failure_t, new_test, run_tests, check
  use raccord_error, only: error_t
  use raccord_strings, only: str
  use raccord_mesh, only: mesh_t, ELEM_Q4, ELEM_Q8, find_node_set, find_elem_set
  use raccord_scene, only: scene_t, BC_FIXED, BC_PRESSURE, BC_TRACTION, BC_DISPLACEMENT, METHOD_NTS, METHOD_MORTAR, MULT_P1, &
    MULT_P0
  use raccord_model, only: model_t
  use raccord_time_step, only: time_plan_t
  use raccord_state, only: state_t
  use raccord_central_difference, only: advance_state
  use raccord_contact_pair, only: contact_pair_t
  use raccord_multiplier_solver, only: ST_OPEN
  use dynamics_support, only: add_bc, add_pair, add_amplitude, contact_step, two_body_scene, prepare_contact
  use closed_ring_mesh, only: ring_full
  implicit none

  real(wp), parameter :: RA = 1.0_wp, RB = 1.5_wp, RC = 2.0_wp
  character(len=10), parameter :: MN(3) = [character(len=10) :: 'NTS', 'mortar P1', 'mortar P0']
  integer, parameter :: ME(3) = [METHOD_NTS, METHOD_MORTAR, METHOD_MORTAR], MU(3) = [MULT_P1, MULT_P1, MULT_P0]
  real(wp), parameter :: E_IN = 1000.0_wp, E_OUT = 2000.0_wp, NU = 0.3_wp, RHO = 1.0_wp, P = 1.0_wp
  ! Pin in a hole: bore, pin, hole and plate radii, Young's modulus, bore traction.
  real(wp), parameter :: R_BORE = 0.5_wp, R_PIN = 0.97_wp, R_HOLE = 1.0_wp, R_PLATE = 3.0_wp, &
    E = 1000.0_wp, Q = 5.0_wp

  type :: run_t
    logical :: failed = .false., finite = .false.
    integer :: nopen = -1, m = 0
    real(wp) :: spread = huge(1.0_wp), ep = huge(1.0_wp), emean = huge(1.0_wp), eu = huge(1.0_wp), bal = 0.0_wp, overlap = 0.0_wp
  end type run_t

  type :: pin_t
    logical :: failed = .false., finite = .false.
    real(wp) :: disp = 0.0_wp, force = 0.0_wp, arc = 0.0_wp, load = 0.0_wp, bal = 0.0_wp, h_angle = 0.0_wp
  end type pin_t

  character(len=256) :: arg, dir

  ! Argument 'CalculiX DIR': the pin against CalculiX on the same mesh, in DIR.
  arg = ''
  if (command_argument_count() >= 1) call get_command_argument(1, arg)
  if (trim(arg) == 'CalculiX') then
    dir = '.'
    if (command_argument_count() >= 2) call get_command_argument(2, dir)
    call run_tests('closed_ccx', [new_test('pin in a hole, frictionless: NTS and mortar P1 against CalculiX, same mesh', &
      test_pin_ccx)])
    stop
  end if
  ! Argument 'refine_q8': the matching Q8 rings refined (16, 32, 64 edges
  ! round, 2, 4, 8 through), mortar P1 and P0, a multiplier on every trace
  ! node and on the corners only (doc/reproduction.md, "The Q8 stick zigzag:
  ! corner multipliers on curved surfaces").
  if (trim(arg) == 'refine_q8') then
    call refine_q8()
    stop
  end if
  call run_tests('closed', [ &
    new_test('rings, matching Q4 loops, either loop slave: pressure uniform to round-off, Lame', test_matching_q4), &
    new_test('rings, matching Q8 loops, NTS, mortar P1/P0: pressure uniform across the seam, Lame', test_matching_q8), &
    new_test('rings, matching Q8 loops, mortar corner multipliers: within the trace''s bound (per-entry directions)', &
      test_matching_q8_corners), &
    new_test('rings, non-matching Q4 loops (1:2), either loop slave: pressure against Lame', test_nonmatching), &
    new_test('pin in a hole with clearance, NTS and mortar, mu = 0 and 0.3, against a fine mesh', test_pin)])

contains

  !> Radial displacement at r of a Lame ring ri..ro under inner pressure pin
  !> and outer pressure pout, plane strain: u = (1+nu)/E ((1-2nu) A r + B/r),
  !> A = (pin ri^2 - pout ro^2)/(ro^2 - ri^2), B = (pin - pout) ri^2 ro^2/(ro^2 - ri^2).
  pure real(wp) function u_ring(r, ri, ro, pin, pout, e) result(u)
    real(wp), intent(in) :: r, ri, ro, pin, pout, e
    real(wp) :: a, b
    a = (pin*ri**2 - pout*ro**2)/(ro**2 - ri**2)
    b = (pin - pout)*ri**2*ro**2/(ro**2 - ri**2)
    u = (1.0_wp + NU)/e*((1.0_wp - 2.0_wp*NU)*a*r + b/r)
  end function u_ring

  !> Interface pressure of the compound cylinder with zero interference:
  !> u_in(b; p, p_c) = u_out(b; p_c, 0), linear in p_c.
  pure real(wp) function lame_pc() result(pc)
    pc = u_ring(RB, RA, RB, P, 0.0_wp, E_IN)/(u_ring(RB, RB, RC, 1.0_wp, 0.0_wp, E_OUT) &
      - u_ring(RB, RA, RB, 0.0_wp, 1.0_wp, E_IN))
  end function lame_pc

  !> One compound-cylinder run: inner ring (ti, ni x nri), outer ring (to,
  !> no x nro); the ring with fewer elements round has its interface nodes
  !> on the circle, the other's on its chords (zero gap). inner_slave: the
  !> inner ring's outer loop is the slave, else the outer ring's inner loop.
  subroutine rings(ti, ni, nri, to, no, nro, inner_slave, method, mult, r, corners)
    integer, intent(in) :: ti, ni, nri, to, no, nro, method, mult
    logical, intent(in) :: inner_slave
    type(run_t), intent(out) :: r
    !> &contact_pair edge_multipliers = 'corners' (3-node slave edges)
    logical, intent(in), optional :: corners
    type(mesh_t) :: mi, mo, mesh
    type(scene_t) :: scene
    type(model_t) :: model
    type(contact_pair_t), allocatable :: pairs(:)
    type(time_plan_t) :: plan
    type(state_t) :: state
    type(error_t) :: err
    real(wp) :: omega1, pc, ua, ur
    real(wp), allocatable :: val(:)
    integer :: k, n, is

    if (ni <= no) then
      call ring_full(mi, ti, ni, nri, RA, 0, RB, 0)
      call ring_full(mo, to, no, nro, RB, merge(0, ni, ni == no), RC, 0)
    else
      call ring_full(mi, ti, ni, nri, RA, 0, RB, no)
      call ring_full(mo, to, no, nro, RB, 0, RC, 0)
    end if
    ! Critical mass damping on the lowest (ovalling) mode, as test_curved.
    omega1 = 0.3_wp*sqrt(E_IN/RHO)
    call two_body_scene(mi, mo, mesh, scene, E_IN, NU, RHO, .false., 30.0_wp/omega1)
    scene%bodies(2)%young = E_OUT
    scene%time%damping = 2.0_wp*omega1
    call add_bc(scene, 'a_xaxis', BC_FIXED, comp=[.false., .true.])
    call add_bc(scene, 'a_yaxis', BC_FIXED, comp=[.true., .false.])
    call add_bc(scene, 'b_xaxis', BC_FIXED, comp=[.false., .true.])
    call add_bc(scene, 'b_yaxis', BC_FIXED, comp=[.true., .false.])
    call add_bc(scene, 'a_bottom', BC_PRESSURE, pressure=P)
    if (inner_slave) then
      call add_pair(scene, 'a_top', 'b_bottom', method, 0.0_wp)
    else
      call add_pair(scene, 'b_bottom', 'a_top', method, 0.0_wp)
    end if
    scene%contacts(1)%multiplier = mult
    if (present(corners)) scene%contacts(1)%corners = corners
    call prepare_contact(scene, mesh, model, pairs, plan, state, err)
    r%failed = err%failed()
    if (r%failed) then
      write(*, '(8x,a)') err%message
      return
    end if
    do
      call contact_step(model, pairs, state, err)
      if (err%failed()) exit
      if (state%step == 0) r%overlap = pairs(1)%overlap_max
      if (state%energy%scale > 0.0_wp) r%bal = max(r%bal, abs(state%energy%balance)/state%energy%scale)
      if (state%step == state%nsteps) exit
      call advance_state(state)
    end do
    r%failed = err%failed()
    r%finite = all(ieee_is_finite(state%u)) .and. all(ieee_is_finite(pairs(1)%lam_n)) &
      .and. all(ieee_is_finite(pairs(1)%pressure))
    if (r%failed .or. .not. r%finite) return
    if (method == METHOD_MORTAR) then
      val = pairs(1)%lam_n
    else
      val = pairs(1)%pressure
    end if
    pc = lame_pc()
    r%m = size(pairs(1)%status)
    r%nopen = count(pairs(1)%status == ST_OPEN)
    ! Spread round the loop; on 3-node edges corner and mid nodes apart
    ! (the cyclic symmetry maps corners to corners, mids to mids).
    if (merge(ti, to, inner_slave) == ELEM_Q8) then
      r%spread = max(spread_of(val(1::2)), spread_of(val(2::2)))
    else
      r%spread = spread_of(val)
    end if
    r%ep = maxval(abs(val - pc)/pc)
    r%emean = abs(sum(val)/size(val) - pc)/pc
    ua = u_ring(RA, RA, RB, P, pc, E_IN)
    is = find_node_set(mesh, 'a_bottom')
    r%eu = 0.0_wp
    do k = 1, size(mesh%nsets(is)%nodes)
      n = mesh%nsets(is)%nodes(k)
      ur = dot_product(state%u(:, n), mesh%x(:, n))/norm2(mesh%x(:, n))
      r%eu = max(r%eu, abs(ur - ua)/ua)
    end do
  end subroutine rings

  !> Matching Q8 rings refined round and through together: the error of
  !> the interface multiplier and of u_r(a) against Lame, and its observed
  !> order log2(e(h)/e(h/2)), for both multiplier spaces of 3-node edges.
  subroutine refine_q8()
    integer, parameter :: NLEV = 3
    type(run_t) :: r
    real(wp) :: ep(NLEV), eu(NLEV)
    integer :: m, s, c, lev, ni
    character(len=:), allocatable :: label
    do c = 1, 2
      do m = 2, 3
        do s = 1, 2
          do lev = 1, NLEV
            ni = 16*2**(lev - 1)
            call rings(ELEM_Q8, ni, 2**lev, ELEM_Q8, ni, 2**lev, s == 1, ME(m), MU(m), r, corners=c == 2)
            label = merge('corners  ', 'all nodes', c == 2) // ', ' // merge('inner', 'outer', s == 1) // &
              ' slave, ' // trim(MN(m)) // ', ' // str(ni) // ' edges'
            call show(label, r)
            ep(lev) = r%ep
            eu(lev) = r%eu
          end do
          write(*, '(8x,a,2(1x,f6.2),a,2(1x,f6.2))') 'order max|p - p_c|:', log(ep(1:NLEV-1)/ep(2:NLEV))/log(2.0_wp), &
            '   u_r(a):', log(eu(1:NLEV-1)/eu(2:NLEV))/log(2.0_wp)
        end do
      end do
    end do
  end subroutine refine_q8

  pure real(wp) function spread_of(v) result(s)
    real(wp), intent(in) :: v(:)
    s = (maxval(v) - minval(v))/abs(sum(v)/size(v))
  end function spread_of

  subroutine show(label, r)
    character(len=*), intent(in) :: label
    type(run_t), intent(in) :: r
    write(*, '(8x,a,": open ",i0,"/",i0,", spread ",es9.2,", max |p - p_c|/p_c ",es9.2, &
      & ", mean ",es9.2,", max |u_r(a) - Lame|/Lame ",es9.2,", balance ",es9.2)') label, r%nopen, r%m, r%spread, r%ep, &
      r%emean, r%eu, r%bal
  end subroutine show

  !> Every ring run: it ran, finite, no overlap at t = 0, the energy
  !> balance exact, every slave node of the loop closed.
  subroutine common_checks(failure, label, r)
    type(failure_t), allocatable, intent(inout) :: failure
    character(len=*), intent(in) :: label
    type(run_t), intent(in) :: r
    call check(failure, .not. r%failed, label // ': the run failed')
    if (allocated(failure)) return
    call check(failure, r%finite, label // ': non-finite displacement or pressure')
    call check(failure, r%overlap <= 1.0e-12_wp, label // ': surfaces overlap at t = 0')
    call check(failure, r%bal < 1.0e-10_wp, label // ': energy balance not exact')
    call check(failure, r%nopen == 0, label // ': a slave node of the loop is open')
  end subroutine common_checks

  !> Matching loops of ni facets: the pressure uniform to round-off; its
  !> error against p_c and u_r(a)'s within bp and bu.
  subroutine matching(failure, et, ni, nr, bp, bu)
    type(failure_t), allocatable, intent(inout) :: failure
    integer, intent(in) :: et, ni, nr
    real(wp), intent(in) :: bp, bu
    type(run_t) :: r
    integer :: m, s
    character(len=:), allocatable :: label
    do m = 1, 3
      do s = 1, 2
        call rings(et, ni, nr, et, ni, nr, s == 1, ME(m), MU(m), r)
        label = merge('inner loop slave', 'outer loop slave', s == 1) // ', ' // trim(MN(m))
        call show(label, r)
        call common_checks(failure, label, r)
        if (allocated(failure)) return
        call check(failure, r%spread <= 1.0e-9_wp, label // ': contact pressure not uniform round the loop')
        call check(failure, r%ep <= bp, label // ': interface pressure error above the faceting bound')
        call check(failure, r%eu <= bu, label // ': u_r(a) error above its bound')
        if (allocated(failure)) return
      end do
    end do
  end subroutine matching

  !> Q4, 32 facets, 3 elements through each ring. Facet angle d = pi/16:
  !> the interface polygon's radius varies by d^2/8 = 4.8e-3 over a facet;
  !> the pressure error is held to twice that, u_r(a) (Q4 with 3 elements
  !> through the thickness) to 2 %.
  subroutine test_matching_q4(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call matching(failure, ELEM_Q4, 32, 3, 2.0_wp*(pi/16.0_wp)**2/8.0_wp, 0.02_wp)
  end subroutine test_matching_q4

  !> Q8, 16 facets of 3-node edges (the seam couples 4 entries of G1 for
  !> mortar; node-to-segment's quadratic master with its normal field
  !> wraps round the loop).
  subroutine test_matching_q8(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call matching(failure, ELEM_Q8, 16, 2, 2.0_wp*(pi/16.0_wp)**2/8.0_wp, 0.02_wp)
  end subroutine test_matching_q8

  !> Q8 rings with multipliers on the corners only (edge_multipliers =
  !> 'corners', opt-in), 16 and 32 edges round (2 and 4 elements through).
  !> A corner's row gives each node of its two edges its force along
  !> that entry's own direction, int N_i psi_j nu dGamma (per-entry
  !> directions, raccord_constraint_set). With one direction per row, the
  !> corner's, the mid nodes' forces were tilted from their normals by half
  !> the edge angle d and the multiplier exceeded p_c by about
  !> (2/3)(1 - cos(d/2)) ~ d^2/12 (1.22 % at d = pi/8, converging at
  !> second order; doc/reproduction.md, "The Q8 stick zigzag: per-entry
  !> directions"). Asserted: the pressure uniform round the loop; within
  !> the trace-node space's bound (twice the faceting error of the trace,
  !> as test_matching_q8) at 16 and at 32 edges; at 16 edges below a tenth
  !> of the one-direction term d^2/12 (measured 7.3e-4 for P1, at the
  !> floor of a few 1e-4 both spaces reach); u_r(a) as for the trace-node
  !> space (within 1e-3: the displacements do not see the multiplier
  !> space).
  subroutine test_matching_q8_corners(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(run_t) :: r16, r32
    integer :: m
    character(len=:), allocatable :: label
    do m = 2, 3
      call rings(ELEM_Q8, 16, 2, ELEM_Q8, 16, 2, .true., ME(m), MU(m), r16, corners=.true.)
      call rings(ELEM_Q8, 32, 4, ELEM_Q8, 32, 4, .true., ME(m), MU(m), r32, corners=.true.)
      label = 'corners, inner loop slave, ' // trim(MN(m))
      call show(label // ', 16 edges', r16)
      call show(label // ', 32 edges', r32)
      call common_checks(failure, label // ', 16 edges', r16)
      call common_checks(failure, label // ', 32 edges', r32)
      if (allocated(failure)) return
      call check(failure, max(r16%spread, r32%spread) <= 1.0e-9_wp, label // ': contact pressure not uniform')
      call check(failure, r16%ep <= 2.0_wp*(pi/16.0_wp)**2/8.0_wp, label // ': pressure error ' // str(r16%ep) // &
        ' at 16 edges above the trace''s faceting bound')
      call check(failure, r32%ep <= 2.0_wp*(pi/32.0_wp)**2/8.0_wp, label // ': pressure error ' // str(r32%ep) // &
        ' at 32 edges above the trace''s faceting bound')
      call check(failure, r16%ep <= 0.1_wp*(pi/8.0_wp)**2/12.0_wp, label // ': pressure error ' // str(r16%ep) // &
        ' at 16 edges: the one-direction rows'' d^2/12 is back')
      call check(failure, max(r16%eu, r32%eu) <= 1.0e-3_wp, label // ': u_r(a) error above 1e-3')
      if (allocated(failure)) return
    end do
  end subroutine test_matching_q8_corners

  !> Non-matching loops, 32 against 16 facets (the fine ring's interface on
  !> the coarse chords, zero gap), each ring inside and outside. With the
  !> coarse loop as slave (its nodes see the fine master symmetrically) the
  !> pressure at every node against p_c: within twice the coarse faceting
  !> error d^2/8 (d = pi/8: 1.9e-2) for mortar, five times for
  !> node-to-segment (not a consistent method); u_r(a) within 3 % (10 %
  !> NTS: the coarse ring's own error is 2.4 %). With the fine loop as
  !> mortar slave the mean pressure round the loop within 2 d^2/8.
  subroutine test_nonmatching(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp), parameter :: d2 = (pi/8.0_wp)**2/8.0_wp
    type(run_t) :: r
    integer :: m, s
    logical :: fine_slave
    character(len=:), allocatable :: label
    do m = 1, 3
      do s = 1, 4
        fine_slave = s == 1 .or. s == 4
        ! Node-to-segment reads the coarse master as the smooth curve
        ! through its nodes, not its chords: the fine slave's nodes, on the
        ! chords, would start off it by the chord's sag (open where the
        ! master is concave, overlapping where convex). Not run.
        if (fine_slave .and. m == 1) cycle
        ! s = 1, 2: inner ring fine (32), outer coarse (16); 3, 4: the reverse.
        if (s <= 2) then
          call rings(ELEM_Q4, 32, 3, ELEM_Q4, 16, 3, mod(s, 2) == 1, ME(m), MU(m), r)
        else
          call rings(ELEM_Q4, 16, 3, ELEM_Q4, 32, 3, mod(s, 2) == 1, ME(m), MU(m), r)
        end if
        label = merge('inner fine  ', 'inner coarse', s <= 2) // ', ' // &
          merge('inner loop slave', 'outer loop slave', mod(s, 2) == 1) // ', ' // trim(MN(m))
        call show(label, r)
        call common_checks(failure, label, r)
        if (allocated(failure)) return
        if (fine_slave) then
          ! The coarse master's vertices bear on the fine slave (peaks, as
          ! in test_curved): the mean pressure round the loop is held.
          call check(failure, r%emean <= 2.0_wp*d2, label // ': mean interface pressure error above its bound')
        else
          call check(failure, r%ep <= merge(5.0_wp, 2.0_wp, m == 1)*d2, label // &
            ': interface pressure error above its bound')
        end if
        call check(failure, r%eu <= merge(0.1_wp, 0.03_wp, m == 1), label // ': u_r(a) error above its bound')
        if (allocated(failure)) return
      end do
    end do
  end subroutine test_nonmatching

  ! ------------------------------------------------------------ pin in hole

  !> Pin (ring 0.5 .. 0.97, nth x nr Q4) in a plate (ring 1 .. 3, nth x
  !> 2 nr Q4, outer edge clamped), E 1000 both, plane strain; the pin moved
  !> by the clearance 0.03 in +x so that it touches the hole at theta = 0;
  !> a traction q in +x on the pin's bore, ramped over [0, T/2] and held,
  !> the pin's nodes on y = 0 held in y (symmetry). The pin's outer loop is
  !> the slave. Returns the pin's mean x displacement (bore), the resultant
  !> of the contact force on the pin, the applied load, the contact arc
  !> (half angle, largest |theta| of a closed slave node) and the balance.
  subroutine pin_run(nth, nr, method, mult, mu, r, mesh_out, drive)
    integer, intent(in) :: nth, nr, method, mult
    real(wp), intent(in) :: mu
    type(pin_t), intent(out) :: r
    type(mesh_t), intent(out), optional :: mesh_out   !< the joined mesh (for the CalculiX deck)
    real(wp), intent(in), optional :: drive           !< instead of the traction, the bore moved rigidly by this in x
    type(mesh_t) :: mp, mh, mesh
    type(scene_t) :: scene
    type(model_t) :: model
    type(contact_pair_t), allocatable :: pairs(:)
    type(time_plan_t) :: plan
    type(state_t) :: state
    type(error_t) :: err
    real(wp) :: omega1, t_end, th
    integer :: k, n, is, i

    call ring_full(mp, ELEM_Q4, nth, nr, R_BORE, 0, R_PIN, 0)
    call ring_full(mh, ELEM_Q4, nth, 2*nr, R_HOLE, 0, R_PLATE, 0)
    mp%x(1, :) = mp%x(1, :) + (R_HOLE - R_PIN)
    ! The pin on its plate spring: lowest frequency about c/R_HOLE; critical
    ! damping on it, the load ramped over many periods, then held.
    omega1 = 0.5_wp*sqrt(E/RHO)
    t_end = 40.0_wp/omega1
    call two_body_scene(mp, mh, mesh, scene, E, NU, RHO, .false., t_end)
    if (present(mesh_out)) mesh_out = mesh
    scene%time%damping = 2.0_wp*omega1
    call add_amplitude(scene, 'ramp', [0.0_wp, 0.5_wp*t_end], [0.0_wp, 1.0_wp])
    call add_bc(scene, 'b_top', BC_FIXED, comp=[.true., .true.])
    ! The pin's rigid motions: held by the driven bore, or in y on y = 0.
    if (.not. present(drive)) call add_bc(scene, 'a_xaxis', BC_FIXED, comp=[.false., .true.])
    if (present(drive)) then
      call add_bc(scene, 'a_bottom', BC_DISPLACEMENT, comp=[.true., .true.], value=[drive, 0.0_wp], amplitude='ramp')
    else
      call add_bc(scene, 'a_bottom', BC_TRACTION, value=[Q, 0.0_wp], amplitude='ramp')
    end if
    call add_pair(scene, 'a_top', 'b_bottom', method, mu)
    scene%contacts(1)%multiplier = mult
    call prepare_contact(scene, mesh, model, pairs, plan, state, err)
    r%failed = err%failed()
    if (r%failed) then
      write(*, '(8x,a)') err%message
      return
    end if
    do
      call contact_step(model, pairs, state, err)
      if (err%failed()) exit
      if (state%energy%scale > 0.0_wp) r%bal = max(r%bal, abs(state%energy%balance)/state%energy%scale)
      if (state%step == state%nsteps) exit
      call advance_state(state)
    end do
    r%failed = err%failed()
    r%finite = all(ieee_is_finite(state%u)) .and. all(ieee_is_finite(pairs(1)%lam_n))
    if (r%failed .or. .not. r%finite) return
    is = find_node_set(mesh, 'a_bottom')
    r%disp = 0.0_wp
    do k = 1, size(mesh%nsets(is)%nodes)
      r%disp = r%disp + state%u(1, mesh%nsets(is)%nodes(k))
    end do
    r%disp = r%disp/size(mesh%nsets(is)%nodes)
    ! The bore's traction integrates to Q times its length (the polygon of
    ! nth chords), all in x.
    r%load = Q*real(nth, wp)*2.0_wp*R_BORE*sin(pi/real(nth, wp))
    r%force = abs(pairs(1)%force(1))
    r%arc = 0.0_wp
    do i = 1, size(pairs(1)%status)
      if (pairs(1)%status(i) == ST_OPEN) cycle
      n = pairs(1)%slave%node(i)
      th = abs(atan2(mesh%x(2, n) + state%u(2, n), mesh%x(1, n) + state%u(1, n) - (R_HOLE - R_PIN)))
      r%arc = max(r%arc, th)
    end do
    r%h_angle = 2.0_wp*pi/nth
  end subroutine pin_run

  !> Each matching and friction coefficient on 48 x 2 (pin) elements
  !> against the same on 96 x 4: the pin's displacement within 3 % (the
  !> coarse pin is 2 % stiffer), the contact resultant equal to the load
  !> within 1e-6 (at rest: measured 2e-10), the contact arc (the last closed node's angle)
  !> within one coarse facet angle (the arc ends between nodes), the
  !> energy balance exact.
  subroutine test_pin(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp), parameter :: MUS(2) = [0.0_wp, 0.3_wp]
    type(pin_t) :: rc, rf
    integer :: m, f
    character(len=:), allocatable :: label
    do f = 1, 2
      do m = 1, 3
        label = trim(MN(m)) // ', mu = ' // merge('0  ', '0.3', f == 1)
        call pin_run(48, 2, ME(m), MU(m), MUS(f), rc)
        call pin_run(96, 4, ME(m), MU(m), MUS(f), rf)
        write(*, '(8x,a,": coarse / fine: u_pin ",es11.4," / ",es11.4,", F_c/load - 1 ",es9.2," / ",es9.2, &
          & ", arc ",f6.2," / ",f6.2," deg, balance ",es9.2," / ",es9.2)') label, rc%disp, rf%disp, &
          rc%force/rc%load - 1.0_wp, rf%force/rf%load - 1.0_wp, rc%arc*180.0_wp/pi, rf%arc*180.0_wp/pi, rc%bal, rf%bal
        call check(failure, .not. (rc%failed .or. rf%failed) .and. rc%finite .and. rf%finite, &
          label // ': a run failed or is not finite')
        if (allocated(failure)) return
        call check(failure, max(rc%bal, rf%bal) < 1.0e-10_wp, label // ': energy balance not exact')
        call check(failure, abs(rc%disp - rf%disp) <= 0.03_wp*abs(rf%disp), label // ': pin displacement off the fine mesh')
        call check(failure, abs(rc%force/rc%load - 1.0_wp) <= 1.0e-6_wp .and. abs(rf%force/rf%load - 1.0_wp) <= 1.0e-6_wp, &
          label // ': contact resultant differs from the load at rest')
        call check(failure, abs(rc%arc - rf%arc) <= rc%h_angle, label // ': contact arc off the fine mesh')
        if (allocated(failure)) return
      end do
    end do
  end subroutine test_pin

  !> The pin, frictionless, NTS and mortar P1, its bore driven rigidly by
  !> DRIVE in x (ccx diverged with the traction load of test_pin: the pin's
  !> rigid motion was left to the contact springs), against CalculiX on the
  !> same mesh (tools/calculix/pin-hole-ccx.sh: static, surface-to-surface,
  !> linear penalty K = 1e6, ccx's reactions balance to 1e-6), on 48 x 2
  !> and on 96 x 4 pin elements. Measured: ccx's contact resultant is 5 %
  !> above raccord's on the coarse mesh (ccx 29.79, and 30.04 with its
  !> node-to-surface contact: ccx itself moves 5 % between the meshes,
  !> raccord 2 %), 1.3 % on the fine one. Asserted: on the fine mesh within
  !> 2 %, the gap closing with refinement, the contact arc within one facet
  !> angle on both, the energy balance exact. Passes with a message when
  !> ccx is not installed.
  subroutine test_pin_ccx(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp), parameter :: DRIVE = 0.03_wp
    integer, parameter :: NTH(2) = [48, 96], NR(2) = [2, 4]
    type(pin_t) :: r(2)
    type(mesh_t) :: mesh
    character(len=512) :: root, line
    real(wp) :: arc_ccx, rf_bore, rf_plate, dev(2, 2)
    integer :: m, length, stat, u, ios, g
    call get_environment_variable('RACCORD_SOURCE_DIR', root, length, stat)
    if (stat /= 0) root = '.'
    do g = 1, 2
      call pin_run(NTH(g), NR(g), METHOD_NTS, MULT_P1, 0.0_wp, r(1), mesh, DRIVE)
      call pin_run(NTH(g), NR(g), METHOD_MORTAR, MULT_P1, 0.0_wp, r(2), drive=DRIVE)
      call write_pin_inp(mesh, trim(dir), DRIVE)
      call execute_command_line('sh ' // trim(root) // '/tools/calculix/pin-hole-ccx.sh ' // trim(dir), exitstat=stat)
      call check(failure, stat == 0, 'tools/calculix/pin-hole-ccx.sh failed')
      if (allocated(failure)) return
      open(newunit=u, file=trim(dir) // '/ccx_result.txt', status='old', action='read', iostat=ios)
      if (ios /= 0) then
        write(*, '(8x,a)') 'no ccx_result.txt (ccx not installed): comparison skipped'
        return
      end if
      read(u, '(a)') line
      read(u, *, iostat=ios) arc_ccx, rf_bore, rf_plate
      close(u)
      call check(failure, ios == 0, 'ccx_result.txt unreadable')
      if (allocated(failure)) return
      write(*, '(8x,i0," x ",i0," pin elements, CalculiX: bore reaction ",es12.5,", plate reaction ",es12.5, &
        & ", arc ",f6.2," deg")') NTH(g), NR(g), rf_bore, rf_plate, arc_ccx
      call check(failure, abs(rf_bore + rf_plate) <= 1.0e-6_wp*abs(rf_bore), 'CalculiX reactions do not balance')
      do m = 1, 2
        dev(m, g) = r(m)%force/abs(rf_bore) - 1.0_wp
        write(*, '(8x,a,": contact resultant ",es12.5," (",sp,f7.3," % of ccx), arc ",ss,f6.2," deg, balance ",es9.2)') &
          trim(MN(m)), r(m)%force, 100.0_wp*dev(m, g), r(m)%arc*180.0_wp/pi, r(m)%bal
        call check(failure, .not. r(m)%failed .and. r(m)%finite, trim(MN(m)) // ': the run failed')
        if (allocated(failure)) return
        call check(failure, abs(r(m)%arc - arc_ccx*pi/180.0_wp) <= r(m)%h_angle, trim(MN(m)) // &
          ': contact arc off CalculiX')
        call check(failure, r(m)%bal < 1.0e-10_wp, trim(MN(m)) // ': energy balance not exact')
      end do
    end do
    do m = 1, 2
      call check(failure, abs(dev(m, 2)) <= 0.02_wp, trim(MN(m)) // ': contact force off CalculiX on the fine mesh')
      call check(failure, abs(dev(m, 2)) < abs(dev(m, 1)), trim(MN(m)) // &
        ': the difference to CalculiX does not fall with refinement')
    end do
  end subroutine test_pin_ccx

  !> The pin mesh as CalculiX input (pin_mesh.inp: nodes, CPE4 elements in
  !> ELSETs pin and plate, node sets, element-face surfaces) and the bore's
  !> drive (pin_load.inp).
  subroutine write_pin_inp(mesh, dir, drive)
    type(mesh_t), intent(in) :: mesh
    character(len=*), intent(in) :: dir
    real(wp), intent(in) :: drive
    integer :: u, n, e, k, is
    character(len=*), parameter :: SETS(5) = [character(len=11) :: 'a_bottom', 'a_top', 'a_xaxis', 'b_bottom', 'b_top']
    character(len=*), parameter :: NAMES(5) = [character(len=11) :: 'pin_bore', 'pin_surf', 'pin_xaxis', 'hole', &
      'plate_outer']
    open(newunit=u, file=dir // '/pin_mesh.inp', status='replace', action='write')
    write(u, '(a)') '*NODE'
    do n = 1, mesh%nnode
      ! ccx reads at most 20 characters a field: 12 significant digits.
      write(u, '(i0,2(",",es19.11))') n, mesh%x(:, n)
    end do
    do k = 1, 2
      write(u, '(a)') '*ELEMENT, TYPE=CPE4, ELSET=' // merge('pin  ', 'plate', k == 1)
      is = find_elem_set(mesh, merge('a_body', 'b_body', k == 1))
      do e = 1, size(mesh%esets(is)%elems)
        associate (el => mesh%esets(is)%elems(e))
          write(u, '(i0,4(", ",i0))') el, mesh%conn(1:4, el)
        end associate
      end do
    end do
    do k = 1, 5
      is = find_node_set(mesh, trim(SETS(k)))
      write(u, '(a)') '*NSET, NSET=' // trim(NAMES(k))
      do n = 1, size(mesh%nsets(is)%nodes)
        write(u, '(i0,",")') mesh%nsets(is)%nodes(n)
      end do
    end do
    do k = 1, size(mesh%surfaces)
      if (mesh%surfaces(k)%name /= 'a_top' .and. mesh%surfaces(k)%name /= 'b_bottom') cycle
      write(u, '(a)') '*SURFACE, NAME=' // merge('S_pin ', 'S_hole', mesh%surfaces(k)%name == 'a_top') // ', TYPE=ELEMENT'
      do e = 1, mesh%surfaces(k)%nedge
        write(u, '(i0,", S",i0)') mesh%surfaces(k)%elem(e), mesh%surfaces(k)%side(e)
      end do
    end do
    close(u)
    open(newunit=u, file=dir // '/pin_load.inp', status='replace', action='write')
    write(u, '(a)') '*BOUNDARY'
    write(u, '(a,es19.11)') 'pin_bore, 1, 1,', drive
    write(u, '(a)') 'pin_bore, 2, 2'
    close(u)
  end subroutine write_pin_inp
end program test_closed
