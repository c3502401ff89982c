!> A contact pair and the contact step of the explicit scheme: after the
!> predictor, build the constraints on the predicted geometry (matching
!> method), solve for the multipliers that make the contact and friction
!> conditions hold at t(n+1) (forward increment), and correct u(n+1) and
!> v(n+1/2) (method brief section 3):
!>   u(n+1) = u*(n+1) + dt^2 M^-1 f_c,   v(n+1/2) = v*(n+1/2) + dt M^-1 f_c.
!> The energy account is updated at the nodes moved, so the balance stays
!> exact: the contact work is what contact takes out of the system
!> (closure is perfectly inelastic at node level, friction dissipates).
module raccord_contact_pair
  use raccord_kinds, only: wp, i8
  use raccord_error, only: error_t, raise_error, EXIT_INPUT, EXIT_NUMERIC
  use raccord_log, only: log_warn
  use raccord_strings, only: str
  use raccord_mesh, only: mesh_t
  use raccord_scene, only: scene_t, METHOD_NTS, METHOD_MORTAR, MULT_P1, multiplier_name
  use raccord_model, only: model_t
  use raccord_state, only: state_t
  use raccord_contact_surface, only: contact_surface_t, build_contact_surface
  use raccord_contact_verlet, only: verlet_t, verlet_init, verlet_check
  use raccord_constraint_set, only: constraint_set_t
  use raccord_multiplier_solver, only: solver_work_t, solve_multipliers, ST_OPEN, ST_STICK, ST_SLIP
  use raccord_node_to_segment, only: build_node_to_segment
  use raccord_mortar, only: mortar_work_t, init_mortar, build_mortar
  implicit none
  private

  integer, parameter :: MAX_FAILED_STEPS = 20   !< consecutive unconverged steps before the run stops

  type, public :: contact_pair_t
    character(len=:), allocatable :: name          !< slave/master, for logs and outputs
    integer :: method = METHOD_NTS
    integer :: multiplier = 1
    logical :: weighted = .false.                  !< mortar: conditions on each weighted gap
    real(wp) :: mu = 0.0_wp
    real(wp) :: reach = 0.0_wp                     !< search distance
    real(wp) :: open_reach = 0.0_wp                !< mortar: largest open gap that enters the rows
    integer :: max_iter = 50
    type(contact_surface_t) :: slave, master
    type(constraint_set_t) :: cs
    type(verlet_t) :: verlet                       !< candidate lists of the incremental search
    type(solver_work_t) :: work
    type(mortar_work_t) :: mortar                  !< mortar scratch (method mortar only)
    ! Per slave surface node, kept between steps (status is the warm start).
    integer, allocatable :: status(:)
    real(wp), allocatable :: sigma(:), gap(:), lam_n(:), lam_t(:), pressure(:), shear(:), slip(:), trib(:)
    !> Out-of-plane thickness of the slave body (1 when axisymmetric). The
    !> solver's multipliers and forces are those of the whole thickness
    !> (the masses carry it); the per-node results above are per unit of
    !> it, so that pressure and shear are stresses whatever the thickness.
    real(wp) :: thickness = 1.0_wp
    ! The same for mortar's corner rows (constraint index nnode + 1, + 2:
    ! the master's first and last corner against the slave face).
    integer :: corner_status(2) = ST_OPEN
    real(wp) :: corner_sigma(2) = 1.0_wp, corner_force(2) = 0.0_wp
    ! Per constraint scratch, and per global node scratch (touched at surface nodes only).
    integer, allocatable :: st_c(:)
    real(wp), allocatable :: sg_c(:)
    real(wp), allocatable :: xcur(:,:), xpred(:,:), dcur(:,:), fc(:,:), ft(:,:), nodal_normal(:,:)
    integer, allocatable :: touched(:)
    integer, allocatable :: cand(:)                !< (master nseg) node-to-segment scratch: a node's candidates
    integer :: ntouched = 0                        !< nodes touched by this step's contact forces
    integer :: force_lo = 1, force_hi = 0          !< span of the touched slave nodes in chain order
    ! The slave nodes whose per-node results were set at the last step (the
    ! others hold the open values): reset these only (nset < 0: all).
    integer :: nset = -1
    integer, allocatable :: set_node(:)
    integer, allocatable :: chain_of(:)            !< (nnode) chain position of a slave surface node, 0 elsewhere
    logical, allocatable :: mark(:)
    ! Step report.
    real(wp) :: force(2) = 0.0_wp                  !< resultant contact force on the slave body
    real(wp) :: normal_sum = 0.0_wp, tangent_sum = 0.0_wp
    integer :: nactive = 0, nslip = 0, iterations = 0, failed_streak = 0
    integer(i8) :: failed_total = 0, iterations_total = 0, steps = 0
    real(wp) :: residual = 0.0_wp, residual_max = 0.0_wp
    integer(i8) :: clock_build = 0, clock_solve = 0
    ! Search counters of this process, summed over its steps (search_summary):
    ! slave items with candidates (nodes for node-to-segment, segments for
    ! mortar), master segments in some candidate list, constraints built.
    integer(i8) :: near_total = 0, listed_total = 0, rows_total = 0
    ! Initial overlap found at t = 0 (see measure_overlap).
    integer :: overlap_nodes = 0                   !< constraints whose gap at t = 0 is negative
    real(wp) :: overlap_max = 0.0_wp               !< largest overlap at t = 0 (length)
    integer :: overlap_node_id = 0                 !< mesh (file) id of the slave node with that overlap
    integer, allocatable :: slave_id(:)            !< mesh (file) id of each slave surface node, for messages
    real(wp) :: overlap_energy = 0.0_wp            !< energy the first step's push-out gave the bodies
  end type contact_pair_t

  public :: init_contact_pairs, enforce_contact, search_summary

contains

  !> Contact pairs from the scene's &contact_pair groups.
  subroutine init_contact_pairs(scene, mesh, model, pairs, err)
    type(scene_t), intent(in) :: scene
    type(mesh_t), intent(in) :: mesh
    type(model_t), intent(in) :: model
    type(contact_pair_t), allocatable, intent(out) :: pairs(:)
    type(error_t), intent(inout) :: err
    integer :: k, np, bs, bm, j
    character(len=:), allocatable :: where

    np = 0
    if (allocated(scene%contacts)) np = size(scene%contacts)
    allocate(pairs(np))
    do k = 1, np
      associate (spec => scene%contacts(k), pair => pairs(k))
        where = 'scene ' // scene%path // ': &contact_pair #' // str(k) // ' (slave ''' // trim(spec%slave) // &
          ''', master ''' // trim(spec%master) // ''')'
        call build_contact_surface(mesh, spec%slave, where // ' slave', pair%slave, err)
        if (err%failed()) return
        call build_contact_surface(mesh, spec%master, where // ' master', pair%master, err)
        if (err%failed()) return
        pair%slave%axisymmetric = model%axisymmetric
        pair%master%axisymmetric = model%axisymmetric
        if (spec%method == METHOD_MORTAR) then
          call init_mortar(pair%slave, pair%master, spec%multiplier, where, pair%mortar, err)
          if (err%failed()) return
        else if (spec%multiplier /= MULT_P1) then
          call log_warn('contact', where // ': multiplier = ''' // multiplier_name(spec%multiplier) // &
            ''' has no effect with node-to-segment matching, whose ' // &
            'multipliers sit at the slave nodes; the P0/P1 choice is a mortar one (method = ''mortar'')')
        end if
        bs = surface_body(model, pair%slave)
        bm = surface_body(model, pair%master)
        if (bs == 0 .or. bm == 0) then
          call raise_error(err, EXIT_INPUT, where // ': a contact surface lies on elements that belong to no ' // &
            '&body; give each body its element set.')
          return
        end if
        if (bs == bm) then
          call raise_error(err, EXIT_INPUT, where // ': slave and master are on the same body ''' // &
            model%bodies(bs)%name // '''; self-contact is not supported. Use surfaces of two bodies.')
          return
        end if
        ! One thickness per pair of plane bodies: the multipliers are forces
        ! over the whole out-of-plane thickness and the pair's pressure and
        ! shear are per unit of the slave's; two thicknesses give no one
        ! contact width in a 2D model (doc/scene-reference.md, &contact_pair).
        ! Both are the deck's numbers, so they are compared exactly.
        if (.not. model%axisymmetric .and. scene%bodies(bs)%thickness /= scene%bodies(bm)%thickness) then
          call raise_error(err, EXIT_INPUT, where // ': the slave body ''' // model%bodies(bs)%name // &
            ''' has thickness = ' // str(scene%bodies(bs)%thickness, 6) // ', the master body ''' // &
            model%bodies(bm)%name // ''' thickness = ' // str(scene%bodies(bm)%thickness, 6) // &
            '; two plane bodies in contact must have the same thickness (a 2D model has no one contact width ' // &
            'for two, and the contact pressure would be per unit of the slave''s only): give both &body groups ' // &
            'the thickness over which they touch')
          return
        end if
        ! Multipliers act through 1/mass of the free dofs: with every dof of
        ! both surfaces prescribed they cannot act at all (the solve then
        ! 'failed to converge' with a residual of 0).
        if (all(model%minv_dof(:, pair%slave%node) == 0.0_wp) .and. &
            all(model%minv_dof(:, pair%master%node) == 0.0_wp)) then
          call raise_error(err, EXIT_INPUT, where // ': every node of both surfaces has both components ' // &
            'prescribed by &boundary groups, so contact can move neither body: free one body (or some ' // &
            'components), or remove the &contact_pair')
          return
        end if
        pair%name = trim(spec%slave) // '/' // trim(spec%master)
        if (.not. model%axisymmetric) pair%thickness = scene%bodies(bs)%thickness
        pair%method = spec%method
        pair%multiplier = spec%multiplier
        pair%weighted = spec%weighted
        pair%mortar%weighted = spec%weighted
        ! Q8 corner multipliers (edge_multipliers = 'corners', opt-in): they
        ! remove the Fig. 4(b) stick zigzag; their rows carry per-entry
        ! directions (raccord_constraint_set), without which they gave
        ! energy where the contact edge moves over a curved master. Not the
        ! default: on a curved slave under the paper's conditions contact
        ! still gives energy (doc/reproduction.md, "The Q8 stick zigzag:
        ! per-entry directions"). Default: every trace node.
        pair%mortar%corners = spec%corners
        ! Tangential corner multipliers (edge_multipliers =
        ! 'tangential_corners'): the corner space for the tangential
        ! conditions only, which removes the zigzag and leaves the normal
        ! conditions those of the default (doc/reproduction.md, "The Q8
        ! stick zigzag: tangential corner multipliers").
        pair%mortar%tcorners = spec%tcorners .and. spec%friction > 0.0_wp
        if (spec%tcorners .and. pair%slave%nen_seg /= 3) call log_warn('contact', where // &
          ': edge_multipliers = ''tangential_corners'' has no effect on a slave of 2-node edges (Q4), whose ' // &
          'multipliers sit at the corners already')
        if (spec%tcorners .and. spec%friction <= 0.0_wp) call log_warn('contact', where // &
          ': edge_multipliers = ''tangential_corners'' has no effect without friction (it places the ' // &
          'tangential multipliers only)')
        if (spec%corners .and. pair%slave%nen_seg /= 3) call log_warn('contact', where // &
          ': edge_multipliers = ''corners'' has no effect on a slave of 2-node edges (Q4), whose multipliers ' // &
          'sit at the corners already')
        pair%mu = spec%friction
        pair%max_iter = spec%max_iterations
        ! the residual of (19) that ends an active-set iteration whose sets
        ! have not settled (raccord_solver_conditions, holds_to_roundoff)
        pair%work%tolerance = spec%tolerance
        pair%reach = spec%search_distance
        if (pair%reach <= 0.0_wp) pair%reach = max(pair%slave%h_max, pair%master%h_max)
        ! Mortar rows take in open parts of the slave up to one surface
        ! element from the master, whatever the search distance: a larger
        ! distance widens the search and the depth of overlap caught, not
        ! the zone of G1's projection, whose nodal gap (19) would otherwise
        ! change with it (build_mortar; doc/theory-contact-mortar.md
        ! section 3). The default distance is that bound, so nothing moves.
        pair%open_reach = min(pair%reach, max(pair%slave%h_max, pair%master%h_max))
        call verlet_init(pair%verlet, pair%slave, pair%master, spec%method == METHOD_MORTAR, pair%reach)
        associate (ns => pair%slave%nnode)
          allocate(pair%status(ns), source=ST_OPEN)
          allocate(pair%sigma(ns), pair%gap(ns), pair%lam_n(ns), pair%lam_t(ns), pair%pressure(ns), &
            pair%shear(ns), pair%slip(ns), pair%trib(ns), source=0.0_wp)
          pair%sigma = 1.0_wp
          pair%slave_id = mesh%node_id(pair%slave%node)
          allocate(pair%st_c(ns + 2), pair%sg_c(ns + 2))
        end associate
        allocate(pair%xcur(2, model%nnode), pair%xpred(2, model%nnode), pair%dcur(2, model%nnode), &
          pair%fc(2, model%nnode), &
          pair%ft(2, model%nnode), pair%nodal_normal(2, model%nnode), source=0.0_wp)
        allocate(pair%mark(model%nnode), source=.false.)
        allocate(pair%touched(pair%slave%nnode + pair%master%nnode))
        allocate(pair%set_node(pair%slave%nnode))
        allocate(pair%cand(pair%master%nseg))
        allocate(pair%chain_of(model%nnode), source=0)
        pair%chain_of(pair%slave%node) = [(j, j = 1, pair%slave%nnode)]
        pair%gap = huge(1.0_wp)
      end associate
    end do
  end subroutine init_contact_pairs

  !> Body of a surface (of its first node).
  integer function surface_body(model, surf)
    type(model_t), intent(in) :: model
    type(contact_surface_t), intent(in) :: surf
    surface_body = model%node_body(surf%node(1))
  end function surface_body

  !> The contact step for every pair, one after the other.
  subroutine enforce_contact(pairs, model, state, err)
    type(contact_pair_t), intent(inout) :: pairs(:)
    type(model_t), intent(in) :: model
    type(state_t), intent(inout) :: state
    type(error_t), intent(inout) :: err
    integer :: k
    do k = 1, size(pairs)
      call enforce_pair(pairs(k), model, state, err)
      if (err%failed()) return
      if (k > 1) call account_shared_nodes(pairs(1:k), model, state)
    end do
  end subroutine enforce_contact

  !> Pairs are solved one after the other, each on the positions the
  !> previous ones corrected. Where pairs share nodes (two-pass contact:
  !> the same surfaces with the roles swapped; a surface in contact with
  !> two others) the last pair's correction dx also moves the increment
  !> (u(n+1) - u(n-1))/2 (dx/4 on the first half step: (dt/4)(v(0) + v(1/2)))
  !> that the earlier pairs' forces work on: their contact and friction
  !> work gain -f . dx/2 (/4), so that (E-2) holds for the summed contact
  !> force exactly (doc/theory-contact.md, section 7; doc/scene-reference.md,
  !> contact). Each pair's fc, ft is zero off the nodes it touched this step.
  subroutine account_shared_nodes(pairs, model, state)
    type(contact_pair_t), intent(in) :: pairs(:)
    type(model_t), intent(in) :: model
    type(state_t), intent(inout) :: state
    integer :: k, j, t, p, c
    real(wp) :: dx, h, w, wc, wf
    k = size(pairs)
    h = velocity_step(state)
    w = merge(0.25_wp, 0.5_wp, state%step == 0)
    wc = 0.0_wp
    wf = 0.0_wp
    do t = 1, pairs(k)%ntouched
      p = pairs(k)%touched(t)
      do c = 1, 2
        if (model%minv_dof(c, p) <= 0.0_wp) cycle
        dx = state%dt*h*model%minv_dof(c, p)*pairs(k)%fc(c, p)/(1.0_wp + 0.5_wp*model%alpha(p)*h)
        do j = 1, k - 1
          wc = wc - w*pairs(j)%fc(c, p)*dx
          wf = wf - w*pairs(j)%ft(c, p)*dx
        end do
      end do
    end do
    state%energy%contact = state%energy%contact + wc
    state%energy%friction = state%energy%friction + wf
  end subroutine account_shared_nodes

  subroutine enforce_pair(pair, model, state, err)
    type(contact_pair_t), intent(inout) :: pair
    type(model_t), intent(in) :: model
    type(state_t), intent(inout) :: state
    type(error_t), intent(inout) :: err
    integer :: i, p, j, m
    integer(i8) :: c0, c1, c2
    real(wp) :: wc0, lmin

    call system_clock(c0)
    ! Positions at t(n), predicted positions and increments, at the surface
    ! nodes only; while the candidate lists hold, at the nodes near the
    ! other surface only (raccord_contact_verlet: the others are checked
    ! for their displacement and not read).
    call verlet_check(pair%verlet, model%x, state%u, pair%slave, pair%master)
    if (pair%verlet%valid) then
      call load_nodes(pair%verlet%load(1:pair%verlet%nload))
    else
      call load_nodes(pair%slave%node)
      call load_nodes(pair%master%node)
    end if
    select case (pair%method)
    case (METHOD_MORTAR)
      call build_mortar(pair%slave, pair%master, pair%xcur, pair%xpred, pair%dcur, pair%reach, pair%open_reach, &
        pair%multiplier, &
        pair%verlet, pair%cs, pair%mortar)
    case default
      call build_node_to_segment(pair%slave, pair%master, pair%xcur, pair%xpred, pair%dcur, pair%reach, &
        pair%verlet, pair%trib, pair%nodal_normal, pair%cand, pair%cs)
    end select
    m = pair%cs%m
    pair%near_total = pair%near_total + pair%verlet%nnear
    pair%listed_total = pair%listed_total + pair%verlet%nmnear
    pair%rows_total = pair%rows_total + m
    ! Warm start: last step's sets; a newly met node enters if it would penetrate.
    do j = 1, m
      i = pair%cs%snode(j)
      if (i > pair%slave%nnode) then
        pair%st_c(j) = pair%corner_status(i - pair%slave%nnode)
        pair%sg_c(j) = pair%corner_sigma(i - pair%slave%nnode)
      else
        pair%st_c(j) = pair%status(i)
        pair%sg_c(j) = pair%sigma(i)
      end if
      if (pair%st_c(j) == ST_OPEN .and. pair%cs%gap_w(j) < 0.0_wp) pair%st_c(j) = ST_STICK
    end do
    call system_clock(c1)
    call solve_multipliers(pair%cs, model%minv_dof, model%alpha, velocity_step(state), state%dt, pair%mu, &
      pair%max_iter, pair%st_c, pair%sg_c, pair%work)
    call system_clock(c2)
    pair%clock_build = pair%clock_build + (c1 - c0)
    pair%clock_solve = pair%clock_solve + (c2 - c1)
    pair%steps = pair%steps + 1
    pair%iterations = pair%work%iterations
    pair%iterations_total = pair%iterations_total + pair%work%iterations
    pair%residual = pair%work%residual
    pair%residual_max = max(pair%residual_max, pair%residual)
    if (.not. pair%work%converged) then
      pair%failed_streak = pair%failed_streak + 1
      pair%failed_total = pair%failed_total + 1
      call log_warn('contact', 'pair ' // pair%name // ': multipliers not converged at step ' // &
        str(state%step) // ' (t = ' // str(state%time) // ') after ' // str(pair%work%iterations) // &
        ' iterations; residual ' // str(pair%residual, 3) // ', ' // str(m) // ' constraints')
      if (pair%failed_streak > MAX_FAILED_STEPS .and. pair%work%singular) then
        ! A singular contact system: constraints whose nodes cannot move
        ! (their motion prescribed on both sides), not a hard solve.
        call raise_error(err, EXIT_NUMERIC, 'contact pair ' // pair%name // ': the contact system is singular ' // &
          'for ' // str(pair%failed_streak) // ' steps in a row (t = ' // str(state%time) // '): the surfaces ' // &
          'meet where the motion of both sides is prescribed (&boundary groups), so contact cannot act there; ' // &
          'free one side there, or remove the &contact_pair.')
        return
      else if (pair%failed_streak > MAX_FAILED_STEPS) then
        call raise_error(err, EXIT_NUMERIC, 'contact pair ' // pair%name // ': the multiplier solve failed ' // &
          'to converge for ' // str(pair%failed_streak) // ' steps in a row (last residual ' // &
          str(pair%residual, 3) // ' at t = ' // str(state%time) // '). Reduce the time step (&time safety), ' // &
          'raise &contact_pair max_iterations, or check the surfaces.')
        return
      end if
    else
      pair%failed_streak = 0
    end if
    if (state%step == 0) call measure_overlap(pair)
    wc0 = state%energy%contact
    call apply_correction(pair, model, state)
    if (state%step == 0 .and. pair%overlap_nodes > 0) then
      pair%overlap_energy = -(state%energy%contact - wc0)
      call log_warn('contact', 'pair ' // pair%name // ': the surfaces overlap at t = 0: ' // &
        str(pair%overlap_nodes) // ' of ' // str(pair%slave%nnode) // ' slave nodes are inside the master, ' // &
        'by up to ' // str(pair%overlap_max, 3) // ' (node ' // str(pair%overlap_node_id) // '). The first ' // &
        'step pushed them out (forward increment: the gap is closed at t(1)), which gave the bodies ' // &
        str(pair%overlap_energy, 3) // ' of energy (negative contact work in the energy account). ' // &
        'To start without it, move the slave surface out of the master in the mesh.')
    end if

    ! Per slave node results (open unless constrained this step): the open
    ! values back at the nodes set last step (all nodes after a restart).
    if (pair%nset < 0) then
      pair%status = ST_OPEN
      pair%gap = huge(1.0_wp)
      pair%lam_n = 0.0_wp
      pair%lam_t = 0.0_wp
      pair%pressure = 0.0_wp
      pair%shear = 0.0_wp
      pair%slip = 0.0_wp
    else
      do j = 1, pair%nset
        i = pair%set_node(j)
        pair%status(i) = ST_OPEN
        pair%gap(i) = huge(1.0_wp)
        pair%lam_n(i) = 0.0_wp
        pair%lam_t(i) = 0.0_wp
        pair%pressure(i) = 0.0_wp
        pair%shear(i) = 0.0_wp
        pair%slip(i) = 0.0_wp
      end do
    end if
    pair%nset = 0
    pair%normal_sum = 0.0_wp
    pair%tangent_sum = 0.0_wp
    pair%nactive = 0
    pair%nslip = 0
    pair%corner_status = ST_OPEN
    pair%corner_force = 0.0_wp
    ! Weights below this are zero up to round-off (only an axisymmetric
    ! quadratic edge's node on the axis has one).
    lmin = 0.0_wp
    if (m > 0) lmin = 1.0e-12_wp*maxval(pair%cs%length(1:m))
    do j = 1, m
      i = pair%cs%snode(j)
      if (i > pair%slave%nnode) then
        ! A mortar corner row: a point force, no per-node output.
        pair%corner_status(i - pair%slave%nnode) = pair%st_c(j)
        pair%corner_sigma(i - pair%slave%nnode) = pair%sg_c(j)
        pair%corner_force(i - pair%slave%nnode) = pair%work%fn(j)
        pair%normal_sum = pair%normal_sum + pair%work%fn(j)
        pair%tangent_sum = pair%tangent_sum + pair%work%ft(j)
        cycle
      end if
      pair%nset = pair%nset + 1
      pair%set_node(pair%nset) = i
      pair%status(i) = pair%st_c(j)
      pair%sigma(i) = pair%sg_c(j)
      pair%gap(i) = pair%work%gn(j)
      ! conditions = 'weighted': gn is the weighted gap; over the length
      ! the row carries, a mean gap
      if (pair%cs%weighted .and. pair%cs%length(j) > lmin) pair%gap(i) = pair%gap(i)/pair%cs%length(j)
      ! Per unit thickness: the multipliers act on the whole thickness t
      ! of a plane body (its masses and loads carry t), so the stress is
      ! the weighted multiplier over the length and over t; with t = 1 the
      ! division is exact.
      pair%lam_n(i) = pair%work%lam(j)/pair%thickness
      pair%lam_t(i) = pair%work%tau(j)/pair%thickness
      pair%slip(i) = pair%work%gt(j)
      ! Contact stress: weighted multiplier over the length (and the
      ! thickness) it acts on.
      if (pair%cs%length(j) > lmin) then
        pair%pressure(i) = pair%work%fn(j)/(pair%cs%length(j)*pair%thickness)
        pair%shear(i) = pair%work%ft(j)/(pair%cs%length(j)*pair%thickness)
      else if (pair%method == METHOD_MORTAR) then
        ! Axisymmetric quadratic edge, end node on the axis: its ring weight
        ! int N r ds is 0 (so is its share of a uniform pressure); the
        ! multiplier is the pressure there (doc/theory-axisymmetric.md).
        pair%pressure(i) = pair%lam_n(i)
        pair%shear(i) = pair%lam_t(i)
      end if
      pair%normal_sum = pair%normal_sum + pair%work%fn(j)
      pair%tangent_sum = pair%tangent_sum + pair%work%ft(j)
      if (pair%st_c(j) /= ST_OPEN) pair%nactive = pair%nactive + 1
      if (pair%st_c(j) == ST_SLIP) pair%nslip = pair%nslip + 1
    end do
    if (pair%method == METHOD_MORTAR .and. pair%slave%nen_seg == 3 .and. pair%mortar%corners) call mid_node_values(pair)
    ! Resultant on the slave: fc is zero off the touched nodes, so the sum
    ! in chain order over the span of the touched slave nodes is the sum
    ! over the whole surface, term for term.
    pair%force = 0.0_wp
    do i = pair%force_lo, pair%force_hi
      p = pair%slave%node(i)
      pair%force = pair%force + pair%fc(:, p)
    end do
  contains
    subroutine load_nodes(nodes)
      integer, intent(in) :: nodes(:)
      integer :: q, n
      do q = 1, size(nodes)
        n = nodes(q)
        ! Component by component: the extent of model%x's first dimension
        ! is not known here, and the sections were a loop of unknown length
        ! per node, unrolled with a jump table.
        pair%xcur(1, n) = model%x(1, n) + state%u(1, n)
        pair%xcur(2, n) = model%x(2, n) + state%u(2, n)
        pair%xpred(1, n) = model%x(1, n) + state%u_next(1, n)
        pair%xpred(2, n) = model%x(2, n) + state%u_next(2, n)
        pair%dcur(1, n) = state%u_next(1, n) - state%u(1, n)
        pair%dcur(2, n) = state%u_next(2, n) - state%u(2, n)
      end do
    end subroutine load_nodes
  end subroutine enforce_pair

  !> The search counters of a pair for the run summary: the rebuilds of the
  !> candidate lists (raccord_contact_verlet) and, per step, the slave items
  !> with candidates, the master segments listed and the constraints built,
  !> over the steps of this process (after a restart, those since it).
  function search_summary(pair) result(text)
    type(contact_pair_t), intent(in) :: pair
    character(len=:), allocatable :: text
    real(wp) :: steps
    steps = real(max(1_i8, pair%steps), wp)
    text = 'candidate lists built ' // str(pair%verlet%rebuilds) // ' times in ' // str(pair%steps) // &
      ' steps; per step ' // str(real(pair%near_total, wp)/steps, 4) // ' slave ' // &
      trim(merge('segments', 'nodes   ', pair%verlet%by_segment)) // ' with list candidates of ' // &
      str(merge(pair%slave%nseg, pair%slave%nnode, pair%verlet%by_segment)) // ', ' // &
      str(real(pair%listed_total, wp)/steps, 4) // ' listed master segments of ' // str(pair%master%nseg) // &
      ', ' // str(real(pair%rows_total, wp)/steps, 4) // ' constraints'
  end function search_summary

  !> Mortar on 3-node slave edges: the multipliers live on the corners
  !> with friction and the paper's conditions (raccord_mortar_segments), so
  !> a mid node has no constraint of its own.
  !> Its per-node results are the multiplier field at its point, the mean
  !> of its two corners' values (P1: linear along the edge; P0: the two
  !> cells meet there), a corner without a constraint counting 0; its
  !> status is its corners' common status, stick and slip giving slip, an
  !> open corner giving the other's (the edge is in contact on that side);
  !> its gap the corners' mean where both are set. Output only: no
  !> condition bears on the mid node, and its status is not read back.
  subroutine mid_node_values(pair)
    type(contact_pair_t), intent(inout) :: pair
    integer :: j, c, t, k, cm, ca, cb, nmid, ns
    logical :: sa, sb
    nmid = pair%nset
    ns = pair%slave%nseg
    ! Over the corners set this step (chain position c = 2k - 1 starts
    ! segment k, c = 2k + 1 ends it): each mid node next to one, once.
    do j = 1, nmid
      c = pair%set_node(j)
      do t = 1, 2
        if (t == 1) then
          k = (c - 1)/2
          if (k < 1 .and. pair%slave%closed) k = ns
        else
          k = (c + 1)/2
        end if
        if (k < 1 .or. k > ns) cycle
        cm = 2*k
        ca = 2*k - 1
        cb = 2*k + 1
        if (pair%slave%closed .and. k == ns) cb = 1
        sa = is_set(ca)
        sb = is_set(cb)
        ! Done from the start corner when it is set.
        if (c /= ca .and. sa) cycle
        pair%nset = pair%nset + 1
        pair%set_node(pair%nset) = cm
        pair%lam_n(cm) = 0.5_wp*(pair%lam_n(ca) + pair%lam_n(cb))
        pair%lam_t(cm) = 0.5_wp*(pair%lam_t(ca) + pair%lam_t(cb))
        pair%pressure(cm) = 0.5_wp*(pair%pressure(ca) + pair%pressure(cb))
        pair%shear(cm) = 0.5_wp*(pair%shear(ca) + pair%shear(cb))
        pair%slip(cm) = 0.5_wp*(pair%slip(ca) + pair%slip(cb))
        if (sa .and. sb) then
          pair%gap(cm) = 0.5_wp*(pair%gap(ca) + pair%gap(cb))
          if (pair%status(ca) == ST_OPEN) then
            pair%status(cm) = pair%status(cb)
            pair%sigma(cm) = pair%sigma(cb)
          else if (pair%status(cb) == ST_OPEN .or. pair%status(ca) == pair%status(cb)) then
            pair%status(cm) = pair%status(ca)
            pair%sigma(cm) = pair%sigma(ca)
          else
            pair%status(cm) = ST_SLIP
            pair%sigma(cm) = merge(pair%sigma(ca), pair%sigma(cb), pair%status(ca) == ST_SLIP)
          end if
        else if (sa) then
          pair%status(cm) = pair%status(ca)
          pair%sigma(cm) = pair%sigma(ca)
        else
          pair%status(cm) = pair%status(cb)
          pair%sigma(cm) = pair%sigma(cb)
        end if
      end do
    end do
  contains
    !> Chain node cc carries a constraint this step: the nodes not set
    !> this step keep the open gap huge(1) of the reset above.
    logical function is_set(cc)
      integer, intent(in) :: cc
      is_set = pair%gap(cc) < huge(1.0_wp)
    end function is_set
  end subroutine mid_node_values

  !> Overlap of the surfaces at t = 0, before any contact force: the gap of
  !> each constraint on the positions at t(0), g_w(x) = g_w(xpred) - sum_p
  !> w_jp du_p . n_j, as a length (over sum_i G1(i, j), the integral of
  !> psi_j: a uniform overlap d reads d for every method and multiplier).
  !> Overlaps below 1e-9 of the shortest slave segment are round-off of
  !> surfaces that touch, not overlaps.
  subroutine measure_overlap(pair)
    type(contact_pair_t), intent(inout) :: pair
    integer :: j, e
    real(wp) :: g0, ov, tol
    tol = 1.0e-9_wp*pair%slave%h_min
    pair%overlap_nodes = 0
    pair%overlap_max = 0.0_wp
    pair%overlap_node_id = 0
    do j = 1, pair%cs%m
      g0 = pair%cs%gap_w(j)
      if (pair%cs%entry_dirs) then
        do e = pair%cs%row_ptr(j), pair%cs%row_ptr(j + 1) - 1
          g0 = g0 - dot_product(pair%dcur(:, pair%cs%ent_node(e)), pair%cs%ent_v(:, e))
        end do
      else
        do e = pair%cs%row_ptr(j), pair%cs%row_ptr(j + 1) - 1
          g0 = g0 - pair%cs%ent_w(e)*dot_product(pair%dcur(:, pair%cs%ent_node(e)), pair%cs%normal(:, j))
        end do
      end if
      ov = -g0/sum(pair%cs%g1(:, j))
      if (pair%cs%snode(j) > pair%slave%nnode) cycle      ! a master corner, not a slave node
      if (ov > tol) then
        pair%overlap_nodes = pair%overlap_nodes + 1
        if (ov > pair%overlap_max) then
          pair%overlap_max = ov
          pair%overlap_node_id = pair%slave_id(pair%cs%snode(j))
        end if
      end if
    end do
  end subroutine measure_overlap

  !> Velocity step h of (CD-1): dt, or dt/2 on the first half step
  !> ((dt(n-1/2) + dt(n+1/2))/2 with a variable step). A force
  !> f_c at t(n) then moves v(n+1/2) by h M^-1 f_c / (1 + alpha h/2) (the
  !> semi-implicit damping) and u(n+1) by dt times that.
  pure real(wp) function velocity_step(state) result(h)
    type(state_t), intent(in) :: state
    h = state%dt
    if (state%adaptive) h = 0.5_wp*(state%dt_prev + state%dt)   ! variable step: dt_n
    if (state%step == 0) h = 0.5_wp*state%dt
  end function velocity_step

  !> Contact forces f_c = sum_j w_j (lambda_j n_j + tau_j t_j), the
  !> correction dt^2 M^-1 f_c of u(n+1) and dt M^-1 f_c of v(n+1/2), and the
  !> energy account at the moved nodes: H(n+1/2) of (E-1) and the contact
  !> work -f_c . (u(n+1) - u(n-1))/2 of (E-2). On dofs with prescribed
  !> motion the force goes to the support's reaction instead.
  subroutine apply_correction(pair, model, state)
    type(contact_pair_t), intent(inout) :: pair
    type(model_t), intent(in) :: model
    type(state_t), intent(inout) :: state
    integer :: j, e, p, c, nt, t, jc
    real(wp) :: dt, dx, vold, dv, vd, dh, wc, wf, dd, dk, inc, fvec(2), tvec(2), h
    logical :: fric

    dt = state%dt
    h = velocity_step(state)
    ! The last step's forces off: fc, ft are zero off this step's nodes
    ! (account_shared_nodes relies on it).
    ! (Component by component: the sections were two calls to memset per node.)
    ! Frictionless (mu = 0 for the whole run), ft is never set and stays
    ! zero: neither cleared nor read.
    fric = pair%mu > 0.0_wp
    do t = 1, pair%ntouched
      p = pair%touched(t)
      pair%fc(1, p) = 0.0_wp
      pair%fc(2, p) = 0.0_wp
      if (fric) then
        pair%ft(1, p) = 0.0_wp
        pair%ft(2, p) = 0.0_wp
      end if
    end do
    nt = 0
    if (pair%cs%entry_dirs) then
      call entry_forces(pair, nt)
    else
      do j = 1, pair%cs%m
        ! An open row (lambda = tau = 0) adds zeros to its nodes' forces:
        ! its nodes are only listed, in the same order (the energy sums
        ! below run in it).
        if (pair%work%lam(j) == 0.0_wp .and. pair%work%tau(j) == 0.0_wp) then
          call list_row_nodes(pair, j, nt)
          cycle
        end if
        fvec = pair%work%lam(j)*pair%cs%normal(:, j) + pair%work%tau(j)*pair%cs%tangent(:, j)
        tvec = pair%work%tau(j)*pair%cs%tangent(:, j)
        do e = pair%cs%row_ptr(j), pair%cs%row_ptr(j + 1) - 1
          p = pair%cs%ent_node(e)
          if (.not. pair%mark(p)) call first_touch(pair, p, nt)
          pair%fc(:, p) = pair%fc(:, p) + pair%cs%ent_w(e)*fvec
          ! Frictionless: tau = 0 and ft stays 0 (its work below adds zeros).
          if (pair%mu > 0.0_wp) pair%ft(:, p) = pair%ft(:, p) + pair%cs%ent_w(e)*tvec
        end do
      end do
    end if
    ! Nodes of the slave surface not touched this step carry no force (fc
    ! was zeroed at the last step's nodes above and is set at this step's).
    pair%force_lo = pair%slave%nnode + 1
    pair%force_hi = 0
    do t = 1, nt
      j = pair%chain_of(pair%touched(t))
      if (j == 0) cycle
      pair%force_lo = min(pair%force_lo, j)
      pair%force_hi = max(pair%force_hi, j)
    end do
    dh = 0.0_wp
    wc = 0.0_wp
    wf = 0.0_wp
    dd = 0.0_wp
    dk = 0.0_wp
    do t = 1, nt
      p = pair%touched(t)
      pair%mark(p) = .false.
      ! A node without force (only open rows touch it) moves by zero and
      ! adds zeros to every sum here: passed, without the gathers of its
      ! state (issue #16, ninth pass); the others' sums run in the same
      ! order.
      if (pair%fc(1, p) == 0.0_wp .and. pair%fc(2, p) == 0.0_wp) then
        if (.not. fric) cycle
        if (pair%ft(1, p) == 0.0_wp .and. pair%ft(2, p) == 0.0_wp) cycle
      end if
      do c = 1, 2
        if (model%minv_dof(c, p) > 0.0_wp) then
          dx = dt*h*model%minv_dof(c, p)*pair%fc(c, p)/(1.0_wp + 0.5_wp*model%alpha(p)*h)
          dv = dx/dt
          vold = state%v(c, p)
          state%v(c, p) = vold + dv
          dh = dh + 0.5_wp*model%mass(p)*(state%v(c, p)**2 - vold**2) + 0.5_wp*dx*state%f_int(c, p)
          state%u_next(c, p) = state%u_next(c, p) + dx
          ! Damping dissipates alpha h m |v(n)|^2 with v(n) the mean of the
          ! half-step velocities, which moves by dv/2 (predict_motion).
          if (state%step == 0) then
            vd = 0.5_wp*(model%v0(c, p) + vold)
          else
            vd = state%v_mid(c, p)
            state%v_mid(c, p) = vd + 0.5_wp*dv
            dk = dk + 0.5_wp*model%mass(p)*((vd + 0.5_wp*dv)**2 - vd**2)
          end if
          dd = dd + model%alpha(p)*h*model%mass(p)*((vd + 0.5_wp*dv)**2 - vd**2)
        else
          jc = model%dof_cdof(c, p)
          if (jc > 0) state%reaction(jc) = state%reaction(jc) - pair%fc(c, p)
        end if
        if (state%step == 0) then
          inc = 0.25_wp*dt*(model%v0(c, p) + state%v(c, p))
        else
          inc = 0.5_wp*(state%u_next(c, p) - state%u_prev(c, p))
        end if
        wc = wc - pair%fc(c, p)*inc
        if (fric) wf = wf - pair%ft(c, p)*inc
      end do
    end do
    pair%ntouched = nt
    state%energy%discrete = state%energy%discrete + dh
    state%energy%damping = state%energy%damping + dd
    state%energy%kinetic = state%energy%kinetic + dk
    state%energy%contact = state%energy%contact + wc
    state%energy%friction = state%energy%friction + wf
  end subroutine apply_correction

  !> The contact forces of apply_correction for entries with their own
  !> vector weights W (cs%entry_dirs, raccord_constraint_set):
  !> f_p = sum_j (lambda_j W_jp + tau_j W^perp_jp), the gradient of the
  !> rows' weighted gaps and slips; the touched nodes listed as there.
  subroutine entry_forces(pair, nt)
    type(contact_pair_t), intent(inout) :: pair
    integer, intent(inout) :: nt
    integer :: j, e, p
    real(wp) :: lam, tau, v(2), tv(2)
    do j = 1, pair%cs%m
      lam = pair%work%lam(j)
      tau = pair%work%tau(j)
      if (lam == 0.0_wp .and. tau == 0.0_wp) then
        ! no force: the nodes listed only (apply_correction)
        call list_row_nodes(pair, j, nt)
        cycle
      end if
      do e = pair%cs%row_ptr(j), pair%cs%row_ptr(j + 1) - 1
        p = pair%cs%ent_node(e)
        if (.not. pair%mark(p)) call first_touch(pair, p, nt)
        v = pair%cs%ent_v(:, e)
        tv = [v(2), -v(1)]
        pair%fc(:, p) = pair%fc(:, p) + (lam*v + tau*tv)
        if (pair%mu > 0.0_wp) pair%ft(:, p) = pair%ft(:, p) + tau*tv
      end do
    end do
  end subroutine entry_forces

  !> The nodes of row j that no row touched before this step, listed in
  !> the row's order (first_touch), for a row that carries no force.
  subroutine list_row_nodes(pair, j, nt)
    type(contact_pair_t), intent(inout) :: pair
    integer, intent(in) :: j
    integer, intent(inout) :: nt
    integer :: e, p
    do e = pair%cs%row_ptr(j), pair%cs%row_ptr(j + 1) - 1
      p = pair%cs%ent_node(e)
      if (.not. pair%mark(p)) call first_touch(pair, p, nt)
    end do
  end subroutine list_row_nodes

  !> A node met for the first time this step by a row of apply_correction or
  !> entry_forces: listed among the touched nodes, its forces started at 0.
  subroutine first_touch(pair, p, nt)
    type(contact_pair_t), intent(inout) :: pair
    integer, intent(in) :: p
    integer, intent(inout) :: nt
    pair%mark(p) = .true.
    nt = nt + 1
    pair%touched(nt) = p
    ! component by component: the sections were two memset calls per node
    pair%fc(1, p) = 0.0_wp
    pair%fc(2, p) = 0.0_wp
    if (pair%mu > 0.0_wp) then   ! frictionless: ft stays zero (apply_correction)
      pair%ft(1, p) = 0.0_wp
      pair%ft(2, p) = 0.0_wp
    end if
  end subroutine first_touch
end module raccord_contact_pair
