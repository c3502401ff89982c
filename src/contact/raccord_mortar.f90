!> Mortar matching ("raccord integral", paper sections 2-3, equations
!> (8)-(19); method brief section 5; doc/theory-contact-mortar.md).
!>
!> One constraint per slave chain node j whose multiplier psi_j meets the
!> master (with mortar_work_t%corners the mid nodes of 3-node edges carry
!> none; raccord_mortar_segments):
!> its row holds -G1(i, j) on slave nodes i and +G21(a, j) on master
!> nodes a, with (paper, after (15) and (16))
!>   G1(i, j)  = integral of phi_i psi_j dGamma,   G21(a, j) = integral of phi_a psi_j dGamma,
!> integrated over the part of the slave surface that faces the master
!> with a gap between -reach and +open_reach (open_reach <= reach: see
!> build_mortar). The multiplier solver then imposes (19) on G1 lambda and
!> on the nodal gap G1^-1 g_w (raccord_multiplier_solver).
!>
!> Geometry (nodal normals, segmentation, integrals) is taken on x, the
!> configuration at t(n); gaps on the predicted positions xpred, slip on the
!> increments du: the constraint on u(n+1) stays linear, and the predicted
!> surface, which lacks this step's contact force, never tilts the normals
!> (see raccord_node_to_segment).
!>
!> Segmentation: on each slave segment the ends of every candidate master
!> segment are projected along the interpolated slave normal field; the
!> overlap of [-1, 1] with the projected interval, split at the
!> discontinuities of psi, gives the mortar segments; each is integrated by
!> 3-point Gauss, with the master parameter at each point where the slave
!> normal ray meets the master segment. Candidates come from the lists of
!> raccord_contact_verlet (the bins of raccord_contact_search, rebuilt
!> only when the surfaces have moved by more than a skin distance), and
!> only the slave segments with candidates are visited: the cost follows
!> the part of the slave near the master, not the surfaces' length.
module raccord_mortar
  use raccord_kinds, only: wp, pi
  use raccord_error, only: error_t, raise_error, EXIT_INPUT
  use raccord_scene, only: MULT_P1, MULT_P0, MULT_DUAL
  use raccord_shape, only: shape_line
  use raccord_contact_surface, only: contact_surface_t
  use raccord_contact_verlet, only: verlet_t, verlet_refresh, verlet_candidates
  use raccord_constraint_set, only: constraint_set_t, cs_start, cs_add_row, cs_add_entry, cs_finish_row, cs_put_row, &
    G1_MAX_BAND
  use raccord_segment, only: segment_point
  use raccord_mortar_segments, only: NODE_XI, outward_normal, normal_field, end_offset, root_along_field, &
    intersect_ray, multiplier_basis, multiplier_breaks
  use raccord_mortar_dual, only: dual_coefficients, dual_basis
  implicit none
  private

  ! 3-point Gauss-Legendre on [-1, 1]: exact to degree 5 (the integrands are
  ! of degree <= 3 on straight segments; see the theory note).
  real(wp), parameter :: GS(3) = [-0.774596669241483377_wp, 0.0_wp, 0.774596669241483377_wp]
  real(wp), parameter :: GW(3) = [5.0_wp/9.0_wp, 8.0_wp/9.0_wp, 5.0_wp/9.0_wp]
  ! Overlaps narrower than this in the slave parameter are round-off slivers
  ! of coincident ends (matching meshes), not contact.
  real(wp), parameter :: XI_SLIVER = 1.0e-12_wp
  ! A multiplier whose overlap integral is below this fraction of the
  ! shortest slave segment does not become a constraint.
  real(wp), parameter :: LEN_TOL = 1.0e-9_wp
  ! A slave node that does not itself face the master, and whose
  ! multiplier meets the overlap over less than this fraction of its full
  ! weight (the integral of psi_j over its segments), does not become a
  ! constraint. Its nodal gap (G1^-1 g_w)_j would be the gap of a sliver
  ! at the far end of its support extrapolated to the node (by a factor
  ! of about 1/(2 sqrt(fraction)) for P1): such a node, far from contact,
  ! was found closed with multipliers of 1e10-1e13 (G1_jj ~ 1e-10) and
  ! gave the bodies energy in single steps (doc/theory-contact-mortar.md,
  ! section 7). Its sliver stays constrained through the neighbour whose
  ! multiplier covers it; its own slave entries stay in the other rows.
  real(wp), parameter :: RHO_MIN = 1.0e-3_wp
  ! A slave node counts as facing the master when its parameter lies in an
  ! overlap to within this, and a master end corner projecting this close to
  ! a slave node is left to that node's row (find_corner_rows): the two
  ! tests share it, so a master that ends at a slave node (matching ends, a
  ! symmetry line) is one state, the node's own row. With the round-off
  ! bound 1e-8 a master end on a symmetry line, 1e-4 of a segment from the
  ! slave's end node as the bodies rang (facets not normal to the line),
  ! alternated between a corner row with the node merged and the node's
  ! row: contact gave 0.72 of the energy scale in a hold (the `curved`
  ! test; doc/theory-contact-mortar.md section 3). 1e-3 of the parameter
  ! (0.05 % of the segment) is the size of the slivers RHO_MIN drops.
  real(wp), parameter :: XI_COVER = 1.0e-3_wp

  !> Per-pair scratch, sized once by init_mortar; the master-entry buffers
  !> grow only (no allocation per step once the contact zone is known).
  type, public :: mortar_work_t
    integer :: multiplier = MULT_P1
    !> conditions = 'weighted': rows along the master's normal (row_normal)
    !> and each multiplier against its own weighted gap (cs%weighted);
    !> otherwise the paper's rows along the slave's nodal normal and (19)
    logical :: weighted = .false.
    !> 3-node slave edges: multipliers on the corners only (raccord_mortar_segments;
    !> &contact_pair edge_multipliers = 'corners', opt-in: doc/theory-contact-mortar.md
    !> section 1); otherwise one on every trace node
    logical :: corners = .false.
    !> With `corners` (3-node slave edges): each row entry carries its own
    !> direction, W_ij = int N_i psi_j nu dGamma (g1vec, ment_v), the exact
    !> first variation of the weighted gap on a curved surface instead of
    !> one direction per row (raccord_constraint_set; doc/theory-contact-mortar.md
    !> section 2). Off only to measure what it does (tests).
    logical :: entry_dirs = .true.
    logical :: dirs = .false.                 !< this step: corners and entry_dirs on 3-node edges
    !> multiplier = 'dual': A of the current slave segment (raccord_mortar_dual)
    real(wp) :: adual(3, 3) = 0.0_wp
    integer, allocatable :: pos(:,:)          !< (3, nseg) chain position of local node a (start, end, mid)
    integer, allocatable :: nadj(:)           !< (nnode) segments a chain node belongs to (1 or 2)
    integer, allocatable :: adj_seg(:,:)      !< (2, nnode) those segments
    integer, allocatable :: adj_loc(:,:)      !< (2, nnode) the node's local index there
    real(wp), allocatable :: nrm(:,:)         !< (2, nnode) slave nodal normals (outward)
    real(wp), allocatable :: g1loc(:,:,:)     !< (3, 3, nseg) G1 contributions: (phi local i, psi local j)
    real(wp), allocatable :: nmloc(:,:,:)     !< (2, 3, nseg) integral of psi_j times the master's inward normal
    real(wp), allocatable :: g1vec(:,:,:,:)   !< (2, 3, 3, nseg) int N_i psi_j nu dGamma (dirs only)
    real(wp), allocatable :: len(:)           !< (nnode) integral of psi_j over the overlap
    real(wp), allocatable :: trib(:)          !< (nnode) integral of phi_j over the overlap (sum_k G1(j, k))
    logical, allocatable :: covered(:)        !< (nnode) the node itself faces the master this step
    ! Corner rows: an end corner of an open master inside a slave segment
    ! (at most one per end), kept out of the slave face by a point row.
    integer :: ncrow = 0
    integer :: crow_end(2) = 0                !< which master end (1: first corner, 2: last)
    integer :: crow_seg(2) = 0                !< slave segment it faces
    integer :: crow_node(2) = 0               !< master corner node (global)
    real(wp) :: crow_xi(2) = 0.0_wp           !< slave parameter of its projection
    real(wp) :: crow_n(2, 2) = 0.0_wp         !< slave normal there (unit)
    integer, allocatable :: cidx(:)           !< (nnode) constraint index, 0 if none
    integer, allocatable :: mbeg(:), mend(:)  !< (nseg) each slave segment's master entries (empty: mbeg > mend)
    integer, allocatable :: stamp(:)          !< (nnode) last step a node's normal was taken at
    integer, allocatable :: nlist(:)          !< (nnode) scratch: the nodes whose normals are taken
    integer :: nstep = 0
    integer, allocatable :: sstamp(:)         !< (nseg) last step snrm was taken at (2-node segments)
    real(wp), allocatable :: snrm(:,:)        !< (2, nseg) outward unit normal of each straight segment
    real(wp), allocatable :: slen(:)          !< (nseg) |dx_s/dxi| of each straight segment (half its length)
    real(wp), allocatable :: mnu(:,:)         !< (2, master nseg) inward unit normal of each listed straight
                                              !< master segment, taken once per step (build_mortar)
    integer, allocatable :: slist(:)          !< (nseg) scratch: the segments whose snrm is taken
    integer :: nment = 0
    integer, allocatable :: ment_node(:), ment_loc(:)   !< master node, psi local index
    real(wp), allocatable :: ment_w(:)                  !< G21 contribution
    real(wp), allocatable :: ment_v(:,:)                !< (2, :) int N_a psi_j nu dGamma (dirs only)
    ! The step's near slave segments with candidates (build_mortar), their
    ! candidates in cbuf(cbeg(t):cend(t)), and the segments whose nodal
    ! normals are taken.
    integer :: nact = 0, nnrm = 0
    integer, allocatable :: act(:), cbeg(:), cend(:), nrmseg(:)   !< (nseg)
    integer, allocatable :: cbuf(:)           !< (size of the Verlet lists)
    ! Projections of the master corner nodes on the current slave segment,
    ! shared by the two master segments that meet at a corner, and F at the
    ! slave nodes, shared by the two slave segments that meet at a node.
    integer, allocatable :: mcorner(:,:)      !< (2, master nseg) corner index of the start and end
    integer, allocatable :: xi_seg(:)         !< (master ncorner) slave segment xi_val belongs to, 0 none
    real(wp), allocatable :: xi_val(:)        !< projected slave parameter of the corner
    integer, allocatable :: f_seg(:)          !< (master ncorner) slave segment whose end f_end was taken at
    real(wp), allocatable :: f_end(:)         !< F of project_along_field at that segment's end node
    ! The row being assembled (assemble_rows): its distinct nodes in the
    ! order of first contribution, their summed weights, and each global
    ! node's place in it (0: not in the row).
    integer, allocatable :: slot(:)           !< (largest global node number of the pair)
    integer, allocatable :: rnode(:)
    real(wp), allocatable :: rw(:)
    real(wp), allocatable :: rv(:,:)          !< (2, :) the row's vector weights (dirs only)
  end type mortar_work_t

  public :: init_mortar, build_mortar

contains

  !> Check that mortar applies to this pair and size the scratch. `where`
  !> names the scene entry in messages.
  subroutine init_mortar(slave, master, multiplier, where, w, err)
    type(contact_surface_t), intent(in) :: slave, master
    integer, intent(in) :: multiplier
    character(len=*), intent(in) :: where
    type(mortar_work_t), intent(out) :: w
    type(error_t), intent(inout) :: err
    integer :: k, a, c, stride, ns, nn, nc

    if (multiplier /= MULT_P1 .and. multiplier /= MULT_P0 .and. multiplier /= MULT_DUAL) then
      call raise_error(err, EXIT_INPUT, where // ': unknown mortar multiplier space; use ''P1'', ''P0'' or ''dual''.')
      return
    end if
    w%multiplier = multiplier
    ns = slave%nseg
    nn = slave%nnode
    stride = slave%nen_seg - 1
    allocate(w%pos(3, ns), source=0)
    allocate(w%nadj(nn), w%adj_seg(2, nn), w%adj_loc(2, nn), w%cidx(nn), source=0)
    allocate(w%nrm(2, nn), w%len(nn), w%trib(nn), source=0.0_wp)
    allocate(w%g1loc(3, 3, ns), source=0.0_wp)
    allocate(w%nmloc(2, 3, ns), source=0.0_wp)
    allocate(w%covered(nn), source=.false.)
    allocate(w%mbeg(ns), source=1)
    allocate(w%mend(ns), w%stamp(nn), w%sstamp(ns), source=0)
    allocate(w%nlist(nn))
    allocate(w%snrm(2, ns), w%slen(ns), source=0.0_wp)
    allocate(w%mnu(2, master%nseg), source=0.0_wp)
    allocate(w%slist(ns))
    allocate(w%ment_node(16*ns), w%ment_loc(16*ns), w%ment_w(16*ns))
    allocate(w%act(ns), w%cbeg(ns), w%cend(ns), w%nrmseg(ns))
    allocate(w%cbuf(max(16, 4*ns)))
    ! Corner c of the master chain is master%corner(c); segment l runs from
    ! corner l to corner l+1 (corner 1 again at the end of a closed loop).
    nc = size(master%corner)
    allocate(w%mcorner(2, master%nseg))
    do k = 1, master%nseg
      w%mcorner(1, k) = k
      w%mcorner(2, k) = k + 1
      if (master%closed .and. k == master%nseg) w%mcorner(2, k) = 1
    end do
    allocate(w%xi_seg(nc), w%f_seg(nc), source=0)
    allocate(w%slot(max(maxval(slave%node), maxval(master%node))), source=0)
    allocate(w%rnode(64), w%rw(64))
    allocate(w%xi_val(nc), w%f_end(nc), source=0.0_wp)
    ! Local node a of slave segment k sits at chain position stride*(k-1)+1
    ! (start), stride*k+1 (end), stride*(k-1)+2 (mid): the order of
    ! contact_surface_t%node.
    do k = 1, ns
      w%pos(1, k) = stride*(k - 1) + 1
      w%pos(2, k) = stride*k + 1
      ! A closed loop's last segment ends at its first node (no end nodes:
      ! every node has two segments and its full multiplier support).
      if (slave%closed .and. k == ns) w%pos(2, k) = 1
      if (slave%nen_seg == 3) w%pos(3, k) = stride*(k - 1) + 2
      do a = 1, slave%nen_seg
        c = w%pos(a, k)
        w%nadj(c) = w%nadj(c) + 1
        w%adj_seg(w%nadj(c), c) = k
        w%adj_loc(w%nadj(c), c) = a
      end do
    end do
  end subroutine init_mortar

  !> Constraints of the slave multipliers that meet the master with a gap
  !> between -reach and +open_reach: geometry on x (t(n)), weighted gaps on
  !> xpred (predicted t(n+1)), weighted slip on the increments du.
  !> `reach` (the search distance) bounds the candidate search and how deep
  !> an overlap is caught; `open_reach` (<= reach) bounds how far open a part
  !> of the slave may be and still enter G1 and G21. The paper's nodal gap
  !> G1^-1 g_w (19) is an L2 projection over every row, so a far part whose
  !> gap climbs steeply (a die's flank) makes it undershoot below zero at an
  !> open node next to the contact zone, which is then held closed
  !> (doc/theory-contact-mortar.md section 3, "Which parts enter the rows").
  !> `multiplier` is MULT_P1, MULT_P0 or MULT_DUAL (as given to init_mortar).
  subroutine build_mortar(slave, master, x, xpred, du, reach, open_reach, multiplier, v, cs, w)
    type(contact_surface_t), intent(in) :: slave, master
    real(wp), intent(in) :: x(:,:), xpred(:,:), du(:,:)
    real(wp), intent(in) :: reach, open_reach
    integer, intent(in) :: multiplier
    type(verlet_t), intent(inout) :: v
    type(constraint_set_t), intent(inout) :: cs
    type(mortar_work_t), intent(inout) :: w
    integer :: k, a, c, nen, l, t, tn, cprev
    real(wp) :: xs(2, 3), nn(2, 3), xi1, xi2, tsgn

    w%multiplier = multiplier
    nen = slave%nen_seg
    ! Per-entry directions: chosen by the pair's keys (corners on 3-node
    ! slave edges), the buffers sized once at the first step.
    w%dirs = w%corners .and. w%entry_dirs .and. nen == 3
    if (w%dirs .and. .not. allocated(w%g1vec)) then
      allocate(w%g1vec(2, 3, 3, slave%nseg), source=0.0_wp)
      allocate(w%ment_v(2, size(w%ment_node)), w%rv(2, size(w%rnode)))
    end if
    call verlet_refresh(v, x, slave, master, reach)
    if (v%rebuilt) then
      ! The near segments change: clear what the others keep between steps.
      w%g1loc = 0.0_wp
      if (w%dirs) w%g1vec = 0.0_wp
      w%nmloc = 0.0_wp
      w%covered = .false.
      w%len = 0.0_wp
      w%trib = 0.0_wp
      w%cidx = 0
      w%mbeg = 1
      w%mend = 0
    end if
    call prepare_step(slave, master, x, v, w)
    ! Pass 2: the overlaps of the active segments with their candidates.
    w%nment = 0
    slave_segments: do tn = 1, w%nact
      k = w%act(tn)
      call load_segment(slave, x, k, xs)
      nn = 0.0_wp
      do a = 1, nen
        nn(:, a) = w%nrm(:, w%pos(a, k))
      end do
      ! Dual basis: biorthogonal over this whole edge (raccord_mortar_dual).
      if (multiplier == MULT_DUAL) call dual_coefficients(nen, xs, slave%axisymmetric, w%adual)
      w%mbeg(k) = w%nment + 1
      ! The side of the segment's normal lines a corner past both its
      ! ends lies on (root_along_field's test, once per segment: corner_xi
      ! decides those corners without the call).
      tsgn = sign(1.0_wp, (xs(1, 2) - xs(1, 1))*(nn(2, 1) + nn(2, 2)) - (xs(2, 2) - xs(2, 1))*(nn(1, 1) + nn(1, 2)))
      cprev = 0
      do t = w%cbeg(tn), w%cend(tn)
        l = w%cbuf(t)
        ! Segmentation (method brief section 5): the master ends seen from
        ! the slave along its normal field, each corner projected once per
        ! slave segment. The list is ascending: a candidate that follows
        ! its chain neighbour starts at the corner that one ended at (the
        ! value corner_xi would return from its cache, without the call).
        ! (cprev: the last candidate's end corner, 0 before the first.)
        if (w%mcorner(1, l) == cprev) then
          xi1 = xi2
        else
          xi1 = corner_xi(w%mcorner(1, l))
        end if
        xi2 = corner_xi(w%mcorner(2, l))
        cprev = w%mcorner(2, l)
        ! Most candidates lie past one end of the slave segment (both
        ! corners clipped to it): an empty overlap, tested here without
        ! the call (integrate_overlap's first test, the same expression).
        if (max(xi1, xi2) - min(xi1, xi2) <= XI_SLIVER) cycle
        if (nen == 2 .and. master%nen_seg == 2) then
          call integrate_overlap_line(slave%axisymmetric, master, x, k, l, xs, nn, min(xi1, xi2), max(xi1, xi2), &
            reach, open_reach, w)
        else
          call integrate_overlap(slave, master, x, k, l, xs, nn, xi1, xi2, reach, open_reach, w)
        end if
      end do
      w%mend(k) = w%nment
    end do slave_segments
    call find_corner_rows(slave, master, x, reach, open_reach, v, w)
    call merge_uncovered(slave, v, w)

    ! Overlap integral of each multiplier: sum_i G1(i, j) (sum_i phi_i = 1).
    ! And of each slave shape function: sum_k G1(j, k) (sum_k psi_k = 1), the
    ! length the weighted multiplier (G1 lambda)_j acts on, so that stresses
    ! (G1 lambda)_j / trib_j compare with node-to-segment's (and equal lambda
    ! for a uniform pressure even where G1 is not symmetric, Q8 edges).
    do tn = 1, v%nnear
      k = v%near(tn)
      do a = 1, nen
        w%len(w%pos(a, k)) = 0.0_wp
        w%trib(w%pos(a, k)) = 0.0_wp
      end do
    end do
    if (nen == 2) then
      ! The same sums with the length known (two terms, in order).
      do tn = 1, v%nnear
        k = v%near(tn)
        do a = 1, 2
          c = w%pos(a, k)
          w%len(c) = w%len(c) + (w%g1loc(1, a, k) + w%g1loc(2, a, k))
          w%trib(c) = w%trib(c) + (w%g1loc(a, 1, k) + w%g1loc(a, 2, k))
        end do
      end do
    else
      do tn = 1, v%nnear
        k = v%near(tn)
        do a = 1, nen
          c = w%pos(a, k)
          w%len(c) = w%len(c) + sum(w%g1loc(1:nen, a, k))
          w%trib(c) = w%trib(c) + sum(w%g1loc(a, 1:nen, k))
        end do
      end do
    end if
    call assemble_rows(slave, xpred, du, v, w, cs)
  contains
    !> Slave parameter of master corner c on slave segment k (xs, nn): the
    !> root of project_along_field, computed once per (k, c). Its end values
    !> F(-1), F(+1) are those of the slave nodes; F at the start node of k is
    !> the end value the corner had on segment k - 1 when it was seen there.
    real(wp) function corner_xi(c) result(xi)
      integer, intent(in) :: c
      real(wp) :: flo, fhi, pc(2)
      if (w%xi_seg(c) == k) then
        xi = w%xi_val(c)
        return
      end if
      pc = x(:, master%corner(c))
      if (k > 1 .and. w%f_seg(c) == k - 1) then
        flo = w%f_end(c)
      else
        ! end_offset written out (a call for one cross product)
        flo = (pc(1) - xs(1, 1))*nn(2, 1) - (pc(2) - xs(2, 1))*nn(1, 1)
      end if
      fhi = (pc(1) - xs(1, 2))*nn(2, 2) - (pc(2) - xs(2, 2))*nn(1, 2)
      w%f_seg(c) = k
      w%f_end(c) = fhi
      if (flo /= 0.0_wp .and. fhi /= 0.0_wp .and. sign(1.0_wp, flo) == sign(1.0_wp, fhi)) then
        ! No root inside: past the end root_along_field picks (the same
        ! test, written out; most corners of the candidates are such).
        xi = merge(1.0_wp, -1.0_wp, sign(1.0_wp, flo) == tsgn)
      else
        xi = root_along_field(nen, xs, nn, pc, flo, fhi)
      end if
      w%xi_seg(c) = k
      w%xi_val(c) = xi
    end function corner_xi
  end subroutine build_mortar

  !> The step's work before the overlaps (build_mortar): the candidates of
  !> every near slave segment, the active segments, their nodal normals,
  !> the corner caches cleared and the listed master segments' normals.
  subroutine prepare_step(slave, master, x, v, w)
    type(contact_surface_t), intent(in) :: slave, master
    real(wp), intent(in) :: x(:,:)
    type(verlet_t), intent(in) :: v
    type(mortar_work_t), intent(inout) :: w
    integer :: k, a, nen, ncand, l, t, tn, nc
    real(wp) :: lo(2), hi(2), tm(2)
    nen = slave%nen_seg
    ! Pass 1: the candidates of every near segment (the current boxes),
    ! kept in w%cbuf; the segments with candidates ("active") are the only
    ! ones whose overlaps are integrated. About a third of the near
    ! segments have none in a step (the lists hold the segments within
    ! the skin too): for them only the filter and the cleared integrals.
    ! Their nodal normals are taken only where a later pass reads them:
    ! the active segments' nodes, and those of the segments find_corner_rows
    ! looks at (a list that starts with the master's first segment or ends
    ! with its last, open masters).
    if (size(w%cbuf) < size(v%item)) then
      deallocate(w%cbuf)
      allocate(w%cbuf(size(v%item)))
    end if
    w%nact = 0
    w%nnrm = 0
    nc = 0
    do tn = 1, v%nnear
      k = v%near(tn)
      call clear_segment(w, k)
      w%mbeg(k) = 1
      w%mend(k) = 0
      ! The box of the segment's nodes (load_segment's values).
      lo = x(:, slave%seg(1, k))
      hi = lo
      do a = 2, nen
        lo = min(lo, x(:, slave%seg(a, k)))
        hi = max(hi, x(:, slave%seg(a, k)))
      end do
      ! Candidates: the listed master segments whose inflated box meets
      ! the slave segment's box now (the test of the full search).
      call verlet_candidates(v, k, lo, hi, w%cbuf(nc + 1:), ncand)
      if (ncand > 0) then
        w%nact = w%nact + 1
        w%act(w%nact) = k
        w%cbeg(w%nact) = nc + 1
        w%cend(w%nact) = nc + ncand
        nc = nc + ncand
        w%nnrm = w%nnrm + 1
        w%nrmseg(w%nnrm) = k
      else if (.not. master%closed) then
        if (v%item(v%ptr(k)) == 1 .or. v%item(v%ptr(k + 1) - 1) == master%nseg) then
          w%nnrm = w%nnrm + 1
          w%nrmseg(w%nnrm) = k
        end if
      end if
    end do
    call slave_normals(slave, x, w%nrmseg(1:w%nnrm), w)
    do t = 1, v%nmnear
      l = v%mnear(t)
      ! (Element by element: a vector subscript on the left made gfortran
      ! allocate a temporary here, twice per listed segment and step.)
      w%xi_seg(w%mcorner(1, l)) = 0
      w%xi_seg(w%mcorner(2, l)) = 0
      w%f_seg(w%mcorner(1, l)) = 0
      w%f_seg(w%mcorner(2, l)) = 0
    end do
    ! The inward unit normal of each listed straight master segment (its
    ! tangent x_m' = -x_1/2 + x_2/2 turned anticlockwise), once per step
    ! instead of once per overlap (integrate_overlap_line).
    if (master%nen_seg == 2) then
      do t = 1, v%nmnear
        l = v%mnear(t)
        tm = x(:, master%seg(1, l))*(-0.5_wp) + x(:, master%seg(2, l))*0.5_wp
        w%mnu(:, l) = [-tm(2), tm(1)]/max(sqrt(tm(1)**2 + tm(2)**2), tiny(1.0_wp))
      end do
    end if
  end subroutine prepare_step

  !> Constraint rows in chain order from the per-segment integrals. A
  !> chain node is a constraint when its multiplier meets the overlap
  !> (integral above LEN_TOL h_min) and either the node itself faces the
  !> master or that integral is at least RHO_MIN of its full weight. On a
  !> closed slave loop the order starts after the longest run of nodes
  !> without a multiplier, so that a contact arc is numbered in one piece;
  !> a loop with multipliers all round (no run of two such nodes) is
  !> numbered folded, 1, m, 2, m - 1, ... along the chain, so that its
  !> neighbours across the seam are neighbours in the numbering too and G1
  !> and the Delassus operator stay banded (half width doubled) instead of
  !> coupling the first and last rows (doc/theory-contact.md, section 3,
  !> "Closed surfaces").
  subroutine assemble_rows(slave, xpred, du, vl, w, cs)
    type(contact_surface_t), intent(in) :: slave
    real(wp), intent(in) :: xpred(:,:), du(:,:)
    type(verlet_t), intent(in) :: vl
    type(mortar_work_t), intent(inout) :: w
    type(constraint_set_t), intent(inout) :: cs
    integer :: c, m, j, t, k, b, ai, i, d, e, band, nen, cfirst, npos, q, run, best, c0, nr, pn, sl
    logical :: fold, take
    real(wp) :: v, tol, g1col(-G1_MAX_BAND:G1_MAX_BAND)

    nen = slave%nen_seg
    tol = LEN_TOL*slave%h_min
    call cs_start(cs, slave%nnode + 2, w%dirs)
    cs%weighted = w%weighted
    if (vl%nnear == 0) return
    fold = .false.
    if (slave%closed) then
      ! Every position, cyclically from c0: after the longest run of
      ! positions without a multiplier (twice round finds runs across
      ! node 1); node 1 when there is none.
      npos = slave%nnode
      c0 = 1
      run = 0
      best = 0
      do q = 1, 2*npos
        c = modulo(q - 1, npos) + 1
        if (w%len(c) > tol) then
          run = 0
        else
          run = run + 1
          if (run > best .and. run < npos) then
            best = run
            c0 = modulo(c, npos) + 1
          end if
        end if
      end do
      cfirst = c0
      ! A run of one node leaves its neighbours sharing a segment (a Q8 mid
      ! node): fold as for none.
      fold = best <= 1
    else
      ! Chain nodes of the near segments (the others have no overlap).
      cfirst = w%pos(1, vl%near(1))
      npos = w%pos(2, vl%near(vl%nnear)) - cfirst + 1
    end if
    m = 0
    do q = 1, npos
      c = at(q)
      if (w%len(c) > tol .and. (w%covered(c) .or. w%len(c) >= RHO_MIN*full_weight(c))) then
        m = m + 1
        w%cidx(c) = m
      else
        w%cidx(c) = 0
      end if
      ! A corner row takes the place after the start node of its segment
      ! (chain order keeps the banded solve narrow).
      do t = 1, w%ncrow
        if (w%pos(1, w%crow_seg(t)) == c) m = m + 1
      end do
    end do
    band = 0
    do q = 1, npos
      c = at(q)
      j = w%cidx(c)
      if (j > 0) then
        ! The row's entries merged through w%slot in the order of their
        ! first contribution, the weights summed in contribution order (as
        ! cs_add_entry did with a search per entry), and written at once.
        nr = 0
        g1col = 0.0_wp
        do t = 1, w%nadj(c)
          k = w%adj_seg(t, c)
          b = w%adj_loc(t, c)
          ! Slave entries -G1(i, j), and the band of G1 between constraints
          ! (constraint numbering: g1(d, j) = G1(j + d, j)).
          do ai = 1, nen
            v = w%g1loc(ai, b, k)
            ! (dirs: an entry whose G1 vanishes, by symmetry on a straight
            ! edge, keeps its vector weight, which need not on a curved one;
            ! tested only where v = 0, without a call per entry)
            take = v /= 0.0_wp
            if (.not. take .and. w%dirs) take = w%g1vec(1, ai, b, k) /= 0.0_wp .or. w%g1vec(2, ai, b, k) /= 0.0_wp
            if (take) then
              ! put(slave%seg(ai, k), -v), written out here and below (the
              ! internal procedure was not inlined: a call per entry)
              pn = slave%seg(ai, k)
              sl = w%slot(pn)
              if (sl > 0) then
                w%rw(sl) = w%rw(sl) - v
              else
                if (nr == size(w%rnode)) call grow_row(w)
                nr = nr + 1
                w%rnode(nr) = pn
                w%rw(nr) = -v
                w%slot(pn) = nr
                sl = nr
                if (w%dirs) w%rv(:, sl) = 0.0_wp
              end if
              ! W_ij = -int N_i psi_j nu dGamma on slave nodes
              if (w%dirs) w%rv(:, sl) = w%rv(:, sl) - w%g1vec(:, ai, b, k)
            end if
            i = w%cidx(w%pos(ai, k))
            ! 3-node edges: the conditions' G1 is that of the corners' linear
            ! hats N_corner + N_mid/2 (each mid node's share split between
            ! its two corners; see below).
            if (nen == 3 .and. w%corners .and. ai <= 2) v = v + 0.5_wp*w%g1loc(3, b, k)
            if (i > 0 .and. v /= 0.0_wp) then
              d = i - j
              g1col(d) = g1col(d) + v
              band = max(band, abs(d))
            end if
          end do
          ! Master entries +G21(a, j).
          do e = w%mbeg(k), w%mend(k)
            if (w%ment_loc(e) /= b) cycle
            pn = w%ment_node(e)
            sl = w%slot(pn)
            if (sl > 0) then
              w%rw(sl) = w%rw(sl) + w%ment_w(e)
            else
              if (nr == size(w%rnode)) call grow_row(w)
              nr = nr + 1
              w%rnode(nr) = pn
              w%rw(nr) = w%ment_w(e)
              w%slot(pn) = nr
              sl = nr
              if (w%dirs) w%rv(:, sl) = 0.0_wp
            end if
            ! W_aj = +int N_a psi_j nu dGamma on master nodes
            if (w%dirs) w%rv(:, sl) = w%rv(:, sl) + w%ment_v(:, e)
          end do
        end do
        if (w%dirs) then
          ! Each entry along its own vector weight (the row's normal kept
          ! for the row's outputs only).
          call cs_put_row(cs, c, slave%node(c), w%nrm(:, c), w%trib(c), slave%s0(c), w%rnode(1:nr), w%rw(1:nr), &
            xpred, du, merged=.true., wv=w%rv(:, 1:nr))
        else if (w%weighted) then
          call cs_put_row(cs, c, slave%node(c), row_normal(c), w%trib(c), slave%s0(c), w%rnode(1:nr), w%rw(1:nr), &
            xpred, du, merged=.true.)
        else
          call cs_put_row(cs, c, slave%node(c), w%nrm(:, c), w%trib(c), slave%s0(c), w%rnode(1:nr), w%rw(1:nr), &
            xpred, du, merged=.true.)
        end if
        cs%g1(:, j) = g1col
        do e = 1, nr
          w%slot(w%rnode(e)) = 0
        end do
        if (nen == 3 .and. w%corners) then
          ! 3-node edges: the multipliers live on the corners only, so G1
          ! (slave nodes x multipliers) is not square. The conditions (19)
          ! bear on the corners with G1~(i, j) = integral of phi~_i psi_j,
          ! phi~ the corners' linear hats (N_corner + N_mid/2, exactly):
          ! F~ = G1~ lambda is the nodal force with each mid node's force
          ! split equally between its corners, and G1~^-T g_w the corner
          ! values of the gap's linear interpolant that has the same
          ! weighted gaps; on full overlaps G1~ = tridiag(H/6, 2H/3, H/6)
          ! (P1), as for a 2-node edge. The rows keep the full G1 (forces
          ! on every slave node, the gap of the quadratic trace).
          ! (doc/theory-contact-mortar.md, section 1, "The Q8 choice")
          v = 0.0_wp
          do t = 1, w%nadj(c)
            k = w%adj_seg(t, c)
            b = w%adj_loc(t, c)
            v = v + sum(w%g1loc(b, 1:2, k)) + 0.5_wp*sum(w%g1loc(3, 1:2, k))
          end do
          cs%length(j) = v
        end if
      end if
      call corner_rows_after(c)
    end do
    cs%g1_band = band
  contains
    !> Chain position of the q-th node in constraint order: along the
    !> chain from cfirst, or folded (the chain's q-th node from the start
    !> for odd q, from the end for even q).
    integer function at(qq)
      integer, intent(in) :: qq
      integer :: kk
      kk = qq
      if (fold) kk = merge((qq + 1)/2, npos - qq/2 + 1, mod(qq, 2) == 1)
      at = cfirst + kk - 1
      if (slave%closed) at = modulo(at - 1, slave%nnode) + 1
    end function at

    !> The row's normal: the psi_c-weighted mean of the master's inward
    !> normal over the overlap, int psi_c nu dGamma normalised. At zero gap
    !> this is the direction of the gradient of the weighted gap
    !> int psi_c (x_m - x_s) . nu dGamma with respect to the nodal
    !> positions (moving the projection point along the master, or turning
    !> nu, changes it only at second order), so the row is the first
    !> variation of the weighted gap and the frictionless contact force has
    !> no part along the master that could work on the sliding. The slave's
    !> nodal normal n_c, used before, is not the master's normal on a
    !> curved slave: its rows let the slave nodes zigzag about a flat
    !> master at zero weighted gap and gave energy (doc/theory-contact.md,
    !> section 7). Exact on a straight master; on a curved one the mean
    !> over the support (the direction varies by the master's turn over
    !> one slave segment). Falls back to n_c where the overlap has no
    !> weight (round-off).
    function row_normal(cc) result(nr)
      integer, intent(in) :: cc
      real(wp) :: nr(2), s
      integer :: tt
      nr = 0.0_wp
      do tt = 1, w%nadj(cc)
        nr = nr + w%nmloc(:, w%adj_loc(tt, cc), w%adj_seg(tt, cc))
      end do
      s = sqrt(nr(1)**2 + nr(2)**2)
      if (s > 0.0_wp) then
        nr = nr/s
      else
        nr = w%nrm(:, cc)
      end if
    end function row_normal

    !> Integral of psi_c over the whole of its slave segments, the weight
    !> its multiplier has where its support faces the master: 1/2 of each
    !> segment (2-node edges, and 3-node ones with corner multipliers; with
    !> one on every trace node 1/4 (corner) or 1/2 (mid node) of a 3-node
    !> edge), P1 and P0 alike; chord lengths of the predicted positions (a threshold
    !> only); axisymmetric: times 2 pi r at the segment's middle.
    real(wp) function full_weight(cc) result(wf)
      integer, intent(in) :: cc
      integer :: tt, kk
      real(wp) :: xa(2), xb(2), frac
      wf = 0.0_wp
      do tt = 1, w%nadj(cc)
        kk = w%adj_seg(tt, cc)
        xa = xpred(:, slave%seg(1, kk))
        xb = xpred(:, slave%seg(2, kk))
        frac = 0.5_wp
        ! A multiplier on every trace node of a 3-node edge (not
        ! w%corners): a corner's weight is 1/4 of the edge.
        if (nen == 3 .and. .not. w%corners .and. w%adj_loc(tt, cc) /= 3) frac = 0.25_wp
        ! Dual basis: integral of psi_j = integral of N_j, 1/6 (corner) or
        ! 2/3 (mid node) of a 3-node edge.
        if (nen == 3 .and. w%multiplier == MULT_DUAL) frac = merge(2.0_wp/3.0_wp, 1.0_wp/6.0_wp, w%adj_loc(tt, cc) == 3)
        if (slave%axisymmetric) frac = frac*pi*abs(xa(1) + xb(1))
        wf = wf + frac*norm2(xb - xa)
      end do
    end function full_weight

    !> Emit the corner rows that follow chain node cprev (where the
    !> numbering above reserved their place).
    subroutine corner_rows_after(cprev)
      integer, intent(in) :: cprev
      integer :: tt, a, kk
      real(wp) :: sh(3), dsh(3)
      do tt = 1, w%ncrow
        kk = w%crow_seg(tt)
        if (w%pos(1, kk) /= cprev) cycle
        call shape_line(nen, w%crow_xi(tt), sh, dsh)
        ! Constraint index slave%nnode + end, so the pair keeps its state
        ! apart from the slave nodes'.
        call cs_add_row(cs, slave%nnode + w%crow_end(tt), w%crow_node(tt), w%crow_n(:, tt), &
          slave%s0(w%pos(2, kk)) - slave%s0(w%pos(1, kk)), &
          0.5_wp*((1.0_wp - w%crow_xi(tt))*slave%s0(w%pos(1, kk)) + (1.0_wp + w%crow_xi(tt))*slave%s0(w%pos(2, kk))))
        ! Gap of the master corner to the slave face along the slave normal:
        ! +1 on the corner node, -N_a(xi_c) on the slave segment's nodes.
        call cs_add_entry(cs, w%crow_node(tt), 1.0_wp)
        do a = 1, nen
          call cs_add_entry(cs, slave%seg(a, kk), -sh(a))
        end do
        call cs_finish_row(cs, xpred, du)
      end do
    end subroutine corner_rows_after
  end subroutine assemble_rows

  !> Mortar segments of slave segment k against master segment l, and their
  !> contributions to G1 (g1loc) and G21 (master entries).
  subroutine integrate_overlap(slave, master, x, k, l, xs, nn, xi1, xi2, reach, open_reach, w)
    type(contact_surface_t), intent(in) :: slave, master
    real(wp), intent(in) :: x(:,:)
    integer, intent(in) :: k, l
    real(wp), intent(in) :: xs(2, 3), nn(2, 3)
    real(wp), intent(in) :: xi1, xi2      !< slave parameters of the master ends (project_along_field)
    real(wp), intent(in) :: reach, open_reach   !< admitted gaps: -reach to +open_reach (build_mortar)
    type(mortar_work_t), intent(inout) :: w
    integer :: nen, nenm, nb, ib, g, a, b, cm
    real(wp) :: xm(2, 3), s0, s1, bounds(4), brk(2), xi, wgt, ps(2), ts(2), n(2), dn(2), eta, &
      pm(2), tm(2), dg, gap, ns(3), dns(3), nm(3), dnm(3), psi(3), mloc(3, 3), nu(2), mvec(2, 3, 3)

    nen = slave%nen_seg
    nenm = master%nen_seg
    ! The overlap in the slave parameter.
    s0 = min(xi1, xi2)
    s1 = max(xi1, xi2)
    if (s1 - s0 <= XI_SLIVER) return
    ! (2-node slave and master: integrate_overlap_line, called by build_mortar.)
    call load_segment(master, x, l, xm)
    ! Only a master that faces the slave, with a gap from -reach to
    ! +open_reach, counts (tested at the middle of the overlap: no coupling
    ! to far or back-facing parts).
    xi = 0.5_wp*(s0 + s1)
    call segment_point(nen, xs, xi, ps, ts)
    call normal_field(nen, nn, xi, n, dn)
    n = n/max(sqrt(n(1)**2 + n(2)**2), tiny(1.0_wp))
    eta = intersect_ray(nenm, xm, ps, n)
    call segment_point(nenm, xm, eta, pm, tm)
    if (dot_product([tm(2), -tm(1)], n) >= 0.0_wp) return
    gap = dot_product(pm - ps, n)
    if (gap > open_reach .or. gap < -reach) return
    ! Slave nodes whose own point faces this master segment.
    do a = 1, nen
      if (NODE_XI(a) >= s0 - XI_COVER .and. NODE_XI(a) <= s1 + XI_COVER) w%covered(w%pos(a, k)) = .true.
    end do

    ! Split at the discontinuities of psi (P0: dual-cell bounds z_i; P1 on
    ! 3-node edges: the mid node) so that each piece is smooth.
    call multiplier_breaks(nen, w%multiplier, w%corners, nb, brk)
    ! The dual basis is one polynomial over the edge: one piece, the rule
    ! its coefficients were integrated with (raccord_mortar_dual).
    if (w%multiplier == MULT_DUAL) nb = 0
    bounds(1) = s0
    a = 1
    do ib = 1, nb
      if (brk(ib) > s0 .and. brk(ib) < s1) then
        a = a + 1
        bounds(a) = brk(ib)
      end if
    end do
    a = a + 1
    bounds(a) = s1
    mloc = 0.0_wp
    if (w%dirs) mvec = 0.0_wp
    pieces: do ib = 1, a - 1
      if (bounds(ib + 1) - bounds(ib) <= XI_SLIVER) cycle
      do g = 1, 3
        xi = 0.5_wp*(bounds(ib) + bounds(ib + 1)) + 0.5_wp*(bounds(ib + 1) - bounds(ib))*GS(g)
        wgt = 0.5_wp*(bounds(ib + 1) - bounds(ib))*GW(g)
        ! Slave point, tangent and normal field from one evaluation of the
        ! slave shape functions (segment_point and normal_field in one).
        call shape_line(nen, xi, ns, dns)
        ps = xs(:, 1)*ns(1) + xs(:, 2)*ns(2)
        ts = xs(:, 1)*dns(1) + xs(:, 2)*dns(2)
        n = nn(:, 1)*ns(1) + nn(:, 2)*ns(2)
        if (nen == 3) then
          ps = ps + xs(:, 3)*ns(3)
          ts = ts + xs(:, 3)*dns(3)
          n = n + nn(:, 3)*ns(3)
        end if
        dg = sqrt(ts(1)**2 + ts(2)**2)*wgt       ! dGamma = |dx_s/dxi| dxi
        ! axisymmetric: dGamma = 2 pi r |dx_s/dxi| dxi (method brief 9.4)
        if (slave%axisymmetric) dg = dg*(2.0_wp*pi*ps(1))
        eta = intersect_ray(nenm, xm, ps, n)
        call shape_line(nenm, eta, nm, dnm)
        ! The master's inward unit normal at eta (its tangent turned
        ! anticlockwise): the direction of the gap's gradient there.
        tm = xm(:, 1)*dnm(1) + xm(:, 2)*dnm(2)
        if (nenm == 3) tm = tm + xm(:, 3)*dnm(3)
        nu = [-tm(2), tm(1)]/max(sqrt(tm(1)**2 + tm(2)**2), tiny(1.0_wp))
        if (w%multiplier == MULT_DUAL) then
          call dual_basis(nen, w%adual, ns, psi)
        else
          call multiplier_basis(nen, w%multiplier, w%corners, xi, psi)
        end if
        do b = 1, nen
          if (psi(b) == 0.0_wp) cycle
          ! G1(i, j) += N_i^s(xi) psi_j(xi) dGamma; G21(a, j) += N_a^m(eta) psi_j(xi) dGamma.
          w%g1loc(1:nen, b, k) = w%g1loc(1:nen, b, k) + ns(1:nen)*psi(b)*dg
          mloc(1:nenm, b) = mloc(1:nenm, b) + nm(1:nenm)*psi(b)*dg
          w%nmloc(:, b, k) = w%nmloc(:, b, k) + nu*psi(b)*dg
        end do
        if (w%dirs) then
          ! Vector weights: int N_i psi_j nu dGamma, int N_a psi_j nu dGamma
          ! (nu the master's inward normal; raccord_constraint_set).
          do b = 1, nen
            do a = 1, nen
              w%g1vec(:, a, b, k) = w%g1vec(:, a, b, k) + nu*(ns(a)*psi(b)*dg)
            end do
            do cm = 1, nenm
              mvec(:, cm, b) = mvec(:, cm, b) + nu*(nm(cm)*psi(b)*dg)
            end do
          end do
        end if
      end do
    end do pieces
    do b = 1, nen
      do cm = 1, nenm
        ! (dirs: an entry whose G21 vanishes, by symmetry on a straight
        ! edge, keeps its vector weight, which need not on a curved one)
        if (mloc(cm, b) == 0.0_wp) then
          if (.not. w%dirs) cycle
          if (mvec(1, cm, b) == 0.0_wp .and. mvec(2, cm, b) == 0.0_wp) cycle
        end if
        if (w%nment == size(w%ment_node)) call grow_entries(w)
        w%nment = w%nment + 1
        w%ment_node(w%nment) = master%seg(cm, l)
        w%ment_loc(w%nment) = b
        w%ment_w(w%nment) = mloc(cm, b)
        if (w%dirs) w%ment_v(:, w%nment) = mvec(:, cm, b)
      end do
    end do
  end subroutine integrate_overlap

  !> integrate_overlap for straight 2-node slave and master segments (Q4
  !> edges, the common case) on the overlap [s0, s1]: the same integrals
  !> with the linear shape functions, the ray intersection and the
  !> multiplier basis written out, so that no procedure of another module is
  !> called per Gauss point (gfortran does not inline across modules; the
  !> calls were most of the matching's time, doc/performance.md).
  subroutine integrate_overlap_line(axisymmetric, master, x, k, l, xs, nn, s0, s1, reach, open_reach, w)
    logical, intent(in) :: axisymmetric
    type(contact_surface_t), intent(in) :: master
    real(wp), intent(in) :: x(:,:)
    integer, intent(in) :: k, l
    real(wp), intent(in) :: xs(2, 3), nn(2, 3)
    real(wp), intent(in) :: s0, s1, reach, open_reach
    type(mortar_work_t), intent(inout) :: w
    integer :: a, b, g, ib, np
    real(wp) :: xm1(2), xm2(2), tm(2), xi, wgt, ps(2), n(2), eta, pm(2), dg, ns(2), nm(2), psi(2), &
      mloc(2, 2), bounds(3), lo, hi, dgw, nu(2), gap, g1(2, 2), nml(2, 2), glo, ghi
    logical :: p0, dual

    xm1 = x(:, master%seg(1, l))
    xm2 = x(:, master%seg(2, l))
    ! Tangent of the straight master segment: x_m'(eta) = -x_1/2 + x_2/2 (shape_line).
    tm = xm1*(-0.5_wp) + xm2*0.5_wp
    ! Only a master that faces the slave, with a gap from -reach to
    ! +open_reach, counts (tested at the middle of the overlap, as
    ! integrate_overlap). The normal field n there is not normalised: the
    ! facing test is a sign, and the reach test |(p_m - p_s) . n| > r |n|
    ! (r = open_reach on the open side, reach on the closed one) is taken
    ! squared (no square root or division; the same test up to round-off at
    ! its bound).
    xi = 0.5_wp*(s0 + s1)
    ns = [0.5_wp*(1.0_wp - xi), 0.5_wp*(1.0_wp + xi)]
    n = nn(:, 1)*ns(1) + nn(:, 2)*ns(2)
    if (tm(2)*n(1) - tm(1)*n(2) >= 0.0_wp) return
    ps = xs(:, 1)*ns(1) + xs(:, 2)*ns(2)
    eta = ray_line(xm1, xm2, ps, n)
    pm = xm1*(0.5_wp*(1.0_wp - eta)) + xm2*(0.5_wp*(1.0_wp + eta))
    gap = (pm(1) - ps(1))*n(1) + (pm(2) - ps(2))*n(2)
    if (gap > 0.0_wp) then
      if (gap**2 > open_reach**2*(n(1)**2 + n(2)**2)) return
    else
      if (gap**2 > reach**2*(n(1)**2 + n(2)**2)) return
    end if
    ! Slave nodes whose own point faces this master segment.
    do a = 1, 2
      if (NODE_XI(a) >= s0 - XI_COVER .and. NODE_XI(a) <= s1 + XI_COVER) w%covered(w%pos(a, k)) = .true.
    end do
    ! P0 on a 2-node edge: psi jumps at xi = 0 (multiplier_breaks).
    p0 = w%multiplier == MULT_P0
    dual = w%multiplier == MULT_DUAL
    bounds(1) = s0
    np = 1
    if (p0 .and. 0.0_wp > s0 .and. 0.0_wp < s1) then
      np = 2
      bounds(2) = 0.0_wp
    end if
    bounds(np + 1) = s1
    ! dGamma = |dx_s/dxi| dxi, |dx_s/dxi| constant on a straight segment
    ! (taken with the segment's normal, slave_normals); the master's
    ! inward unit normal, taken once per step (build_mortar).
    dg = w%slen(k)
    nu = w%mnu(:, l)
    ! The segment's sums in registers over the Gauss points (loaded and
    ! stored back: the same additions in the same order).
    g1 = w%g1loc(1:2, 1:2, k)
    nml = w%nmloc(:, 1:2, k)
    mloc = 0.0_wp
    pieces: do ib = 1, np
      lo = bounds(ib)
      hi = bounds(ib + 1)
      if (hi - lo <= XI_SLIVER) cycle
      do g = 1, 3
        xi = 0.5_wp*(lo + hi) + 0.5_wp*(hi - lo)*GS(g)
        wgt = 0.5_wp*(hi - lo)*GW(g)
        ns = [0.5_wp*(1.0_wp - xi), 0.5_wp*(1.0_wp + xi)]
        ps = xs(:, 1)*ns(1) + xs(:, 2)*ns(2)
        n = nn(:, 1)*ns(1) + nn(:, 2)*ns(2)
        dgw = dg*wgt
        ! axisymmetric: dGamma = 2 pi r |dx_s/dxi| dxi (method brief 9.4)
        if (axisymmetric) dgw = dgw*(2.0_wp*pi*ps(1))
        ! ray_line written out (the call was not inlined)
        glo = (xm1(1) - ps(1))*n(2) - (xm1(2) - ps(2))*n(1)
        ghi = (xm2(1) - ps(1))*n(2) - (xm2(2) - ps(2))*n(1)
        if (glo == 0.0_wp) then
          eta = -1.0_wp
        else if (ghi == 0.0_wp) then
          eta = 1.0_wp
        else if (sign(1.0_wp, glo) == sign(1.0_wp, ghi)) then
          eta = merge(-1.0_wp, 1.0_wp, abs(glo) < abs(ghi))
        else
          eta = -1.0_wp - 2.0_wp*glo/(ghi - glo)
        end if
        nm = [0.5_wp*(1.0_wp - eta), 0.5_wp*(1.0_wp + eta)]
        ! psi of multiplier_basis: P1 hats (= the shape functions), P0
        ! the dual cells [-1, 0), [0, 1].
        if (p0) then
          psi = merge([1.0_wp, 0.0_wp], [0.0_wp, 1.0_wp], xi < 0.0_wp)
        else if (dual) then
          ! psi_i = sum_j A(i, j) N_j (raccord_mortar_dual)
          psi(1) = w%adual(1, 1)*ns(1) + w%adual(1, 2)*ns(2)
          psi(2) = w%adual(2, 1)*ns(1) + w%adual(2, 2)*ns(2)
        else
          psi = ns
        end if
        ! G1(i, j) += N_i^s(xi) psi_j(xi) dGamma; G21(a, j) += N_a^m(eta) psi_j(xi) dGamma.
        ! (A psi_j of 0 adds zeros: no test.)
        do b = 1, 2
          g1(:, b) = g1(:, b) + ns*psi(b)*dgw
          mloc(:, b) = mloc(:, b) + nm*psi(b)*dgw
          nml(:, b) = nml(:, b) + nu*psi(b)*dgw
        end do
      end do
    end do pieces
    w%g1loc(1:2, 1:2, k) = g1
    w%nmloc(:, 1:2, k) = nml
    do b = 1, 2
      do a = 1, 2
        if (mloc(a, b) == 0.0_wp) cycle
        if (w%nment == size(w%ment_node)) call grow_entries(w)
        w%nment = w%nment + 1
        w%ment_node(w%nment) = master%seg(a, l)
        w%ment_loc(w%nment) = b
        w%ment_w(w%nment) = mloc(a, b)
      end do
    end do
  end subroutine integrate_overlap_line

  !> Master parameter where the line q + alpha n meets the straight master
  !> segment x1-x2: intersect_ray for nen = 2 (closed form of the linear
  !> G(eta) = (x_m(eta) - q) x n, clipped to the end where |G| is smaller).
  pure real(wp) function ray_line(x1, x2, q, n) result(eta)
    real(wp), intent(in) :: x1(2), x2(2), q(2), n(2)
    real(wp) :: glo, ghi
    glo = (x1(1) - q(1))*n(2) - (x1(2) - q(2))*n(1)
    ghi = (x2(1) - q(1))*n(2) - (x2(2) - q(2))*n(1)
    if (glo == 0.0_wp) then
      eta = -1.0_wp
    else if (ghi == 0.0_wp) then
      eta = 1.0_wp
    else if (sign(1.0_wp, glo) == sign(1.0_wp, ghi)) then
      eta = merge(-1.0_wp, 1.0_wp, abs(glo) < abs(ghi))
    else
      eta = -1.0_wp - 2.0_wp*glo/(ghi - glo)
    end if
  end function ray_line

  !> Boundary modification of the multiplier space (Wohlmuth, SIAM J.
  !> Numer. Anal. 38 (2000) 989-1012; Popp et al., IJNME 2010, section 3.3):
  !> a slave node that does not itself face the master, but whose multiplier
  !> support meets it (the slave runs past the master's end), gets no
  !> multiplier of its own; on each slave segment its basis function is
  !> added to that of the nearest node of the segment that does face the
  !> master (psi_b' <- psi_b' + psi_b, so sum_j psi_j = 1 still holds and a
  !> constant pressure is still represented). Without this the nodal gap
  !> G1^-1 g_w of such a node is the gap to the master's last segment
  !> extended past its end: the node is held on a line that is not there,
  !> and as that segment turns (a block tipping over the master's corner)
  !> the constraint does work on the bodies, giving energy back
  !> (doc/verification.md section 13).
  subroutine merge_uncovered(slave, vl, w)
    type(contact_surface_t), intent(in) :: slave
    type(verlet_t), intent(in) :: vl
    type(mortar_work_t), intent(inout) :: w
    integer :: k, b, bb, target, nen, e, t, nt
    real(wp) :: dist, best
    nen = slave%nen_seg
    ! Only where the master ends: the slave segments an end corner of the
    ! master lies over (find_corner_rows). Elsewhere a node whose overlap
    ! stops short of it stops there because the master beyond is out of
    ! reach or faces away, and the standard basis is kept (the paper's
    ! scenes, whose master arcs end far from the contact, are unchanged).
    ! Dual basis: on every slave segment the overlap covers in part
    ! (raccord_mortar_dual; doc/theory-contact-mortar.md section 9): a dual
    ! psi_j is not small at the far end of its support (Q4: -1, Q8
    ! corner: +1/2 at the other corner), so the row of a node beyond the
    ! overlap's end would weigh the same sliver as its covered neighbour's
    ! row, nearly parallel to it. Without this the paper's Q8 deck
    ! (Fig. 4(a)) blew up at t = 4.5e-6 s with dual multipliers.
    nt = w%ncrow
    if (w%multiplier == MULT_DUAL) nt = w%ncrow + vl%nnear
    do t = 1, nt
      if (t <= w%ncrow) then
        k = w%crow_seg(t)
      else
        k = vl%near(t - w%ncrow)
      end if
      do b = 1, nen
        if (w%covered(w%pos(b, k))) cycle
        if (all(w%g1loc(1:nen, b, k) == 0.0_wp)) cycle
        ! Nearest node of this segment that faces the master.
        target = 0
        best = huge(1.0_wp)
        ! With w%corners a mid node carries no multiplier.
        do bb = 1, merge(2, nen, w%corners)
          if (bb == b .or. .not. w%covered(w%pos(bb, k))) cycle
          dist = abs(NODE_XI(bb) - NODE_XI(b))
          if (dist < best) then
            best = dist
            target = bb
          end if
        end do
        ! No node of the segment faces the master (a master shorter than
        ! one slave segment): keep the standard basis there.
        if (target == 0) cycle
        w%g1loc(1:nen, target, k) = w%g1loc(1:nen, target, k) + w%g1loc(1:nen, b, k)
        w%g1loc(1:nen, b, k) = 0.0_wp
        if (w%dirs) then
          w%g1vec(:, 1:nen, target, k) = w%g1vec(:, 1:nen, target, k) + w%g1vec(:, 1:nen, b, k)
          w%g1vec(:, 1:nen, b, k) = 0.0_wp
        end if
        w%nmloc(:, target, k) = w%nmloc(:, target, k) + w%nmloc(:, b, k)
        w%nmloc(:, b, k) = 0.0_wp
        do e = w%mbeg(k), w%mend(k)
          if (w%ment_loc(e) == b) w%ment_loc(e) = target
        end do
      end do
    end do
  end subroutine merge_uncovered

  !> Corner rows. Both methods constrain slave points only; a convex master
  !> corner that lies inside a slave face (a slave tipping over the end of
  !> its master) is held by nothing, and mortar's overlap then ends at the
  !> corner's projection xi_c with a negative gap there: as the overlap
  !> shrinks, the moving constraint does work lambda psi(xi_c) g(xi_c)
  !> dxi_c/dt on the bodies (energy given back; doc/verification.md section
  !> 13). A point row for each end corner of an open master that projects
  !> strictly inside a slave segment (along the slave normal field, with a
  !> gap from -reach to +open_reach as the overlaps in integrate_overlap, the
  !> master's end segment facing the slave) keeps g(xi_c) >= 0. A corner
  !> farther open gets no row: its row would mark the slave segment below it
  !> as one where the master ends (merge_uncovered), where the overlap in
  !> fact ends because the master is out of reach.
  subroutine find_corner_rows(slave, master, x, reach, open_reach, vl, w)
    type(contact_surface_t), intent(in) :: slave, master
    real(wp), intent(in) :: x(:,:)
    real(wp), intent(in) :: reach, open_reach
    type(verlet_t), intent(in) :: vl
    type(mortar_work_t), intent(inout) :: w
    integer :: t, k, a, l, cn, nen, kbest, tn
    real(wp) :: pc(2), xs(2, 3), nn(2, 3), xm(2, 3), flo, fhi, xi, ps(2), ts(2), n(2), dn(2), g, best, &
      pm(2), tm(2), xibest, nbest(2)
    w%ncrow = 0
    if (master%closed) return
    nen = slave%nen_seg
    do t = 1, 2
      cn = master%corner(merge(1, size(master%corner), t == 1))
      l = merge(1, master%nseg, t == 1)
      pc = x(:, cn)
      call load_segment(master, x, l, xm)
      call segment_point(master%nen_seg, xm, 0.0_wp, pm, tm)
      best = reach
      kbest = 0
      xibest = 0.0_wp
      nbest = 0.0_wp
      ! A corner within reach of a slave segment makes that segment near
      ! (the master's end segment is in the slave segment's list): the
      ! segments whose ascending list does not start (end) with segment
      ! l = 1 (nseg) cannot hold the corner within reach, and are passed.
      do tn = 1, vl%nnear
        k = vl%near(tn)
        if (t == 1) then
          if (vl%item(vl%ptr(k)) /= l) cycle
        else
          if (vl%item(vl%ptr(k + 1) - 1) /= l) cycle
        end if
        call load_segment(slave, x, k, xs)
        nn = 0.0_wp
        do a = 1, nen
          nn(:, a) = w%nrm(:, w%pos(a, k))
        end do
        flo = end_offset(xs(:, 1), nn(:, 1), pc)
        fhi = end_offset(xs(:, 2), nn(:, 2), pc)
        if (sign(1.0_wp, flo) == sign(1.0_wp, fhi) .or. flo == 0.0_wp .or. fhi == 0.0_wp) cycle
        xi = root_along_field(nen, xs, nn, pc, flo, fhi)
        ! At a slave node the node's own row sees the corner.
        if (abs(xi) >= 1.0_wp - XI_COVER) cycle
        call segment_point(nen, xs, xi, ps, ts)
        call normal_field(nen, nn, xi, n, dn)
        n = n/max(sqrt(n(1)**2 + n(2)**2), tiny(1.0_wp))
        g = dot_product(pc - ps, n)
        if (g >= open_reach) cycle
        if (abs(g) >= best) cycle
        if (dot_product([tm(2), -tm(1)], n) >= 0.0_wp) cycle
        best = abs(g)
        kbest = k
        xibest = xi
        nbest = n
      end do
      if (kbest == 0) cycle
      w%ncrow = w%ncrow + 1
      w%crow_end(w%ncrow) = t
      w%crow_seg(w%ncrow) = kbest
      w%crow_node(w%ncrow) = cn
      w%crow_xi(w%ncrow) = xibest
      w%crow_n(:, w%ncrow) = nbest
    end do
  end subroutine find_corner_rows

  !> Slave nodal normals at the nodes of the segments segs (build_mortar:
  !> the near segments a step reads): the normalised
  !> mean of the outward unit normals of the segments meeting at the node,
  !> each taken at the node (for 3-node segments the quadratic's own
  !> tangent there), summed in chain order; along the axis at an
  !> axisymmetric surface's axis node. Also clears their `covered`.
  subroutine slave_normals(slave, x, segs, w)
    type(contact_surface_t), intent(in) :: slave
    real(wp), intent(in) :: x(:,:)
    integer, intent(in) :: segs(:)
    type(mortar_work_t), intent(inout) :: w
    integer :: k, a, c, tn, t, kk, nl, nsl
    real(wp) :: xs(2, 3), tt(2)
    w%nstep = w%nstep + 1
    nl = 0
    if (slave%nen_seg == 2) then
      ! A straight segment has one normal, the same at both ends: taken
      ! once per step for the segments at the nodes of the near ones, in
      ! a loop of its own (their square roots and divisions overlap).
      nsl = 0
      do tn = 1, size(segs)
        k = segs(tn)
        do a = 1, 2
          c = w%pos(a, k)
          do t = 1, w%nadj(c)
            kk = w%adj_seg(t, c)
            if (w%sstamp(kk) == w%nstep) cycle
            w%sstamp(kk) = w%nstep
            nsl = nsl + 1
            w%slist(nsl) = kk
          end do
        end do
      end do
      ! The tangent's length |x_s'| = h/2 is kept for the overlaps'
      ! dGamma (integrate_overlap_line).
      do t = 1, nsl
        kk = w%slist(t)
        tt = x(:, slave%seg(1, kk))*(-0.5_wp) + x(:, slave%seg(2, kk))*0.5_wp
        w%slen(kk) = sqrt(tt(1)**2 + tt(2)**2)
        w%snrm(:, kk) = [tt(2), -tt(1)]/max(w%slen(kk), tiny(1.0_wp))
      end do
    end if
    do tn = 1, size(segs)
      k = segs(tn)
      do a = 1, slave%nen_seg
        c = w%pos(a, k)
        if (w%stamp(c) == w%nstep) cycle
        w%stamp(c) = w%nstep
        w%covered(c) = .false.
        w%nrm(1, c) = 0.0_wp
        w%nrm(2, c) = 0.0_wp
        do t = 1, w%nadj(c)
          kk = w%adj_seg(t, c)
          if (slave%nen_seg == 2) then
            w%nrm(:, c) = w%nrm(:, c) + w%snrm(:, kk)
          else
            call load_segment(slave, x, kk, xs)
            w%nrm(:, c) = w%nrm(:, c) + outward_normal(slave%nen_seg, xs, NODE_XI(w%adj_loc(t, c)))
          end if
        end do
        ! A surface of revolution meets the axis at a right angle: at a node
        ! on the axis (r = 0) the normal is along the axis (its one segment
        ! tilts as the surface deforms; a tilted normal there would project
        ! a master corner on the axis off the slave end and leave the axis
        ! node without its multiplier).
        if (slave%axisymmetric) then
          if (x(1, slave%node(c)) == 0.0_wp) w%nrm(1, c) = 0.0_wp
        end if
        nl = nl + 1
        w%nlist(nl) = c
      end do
    end do
    ! Normalised in a loop of its own: the square roots and divisions of
    ! different nodes overlap there instead of waiting on each other.
    do t = 1, nl
      c = w%nlist(t)
      w%nrm(:, c) = w%nrm(:, c)/max(sqrt(w%nrm(1, c)**2 + w%nrm(2, c)**2), tiny(1.0_wp))
    end do
  end subroutine slave_normals

  !> Zero slave segment k's integrals (g1loc, nmloc) with stores written
  !> out: the array sections were a call to memset each, per near segment
  !> and step.
  subroutine clear_segment(w, k)
    type(mortar_work_t), intent(inout) :: w
    integer, intent(in) :: k
    integer :: a
    do a = 1, 3
      w%g1loc(1, a, k) = 0.0_wp
      w%g1loc(2, a, k) = 0.0_wp
      w%g1loc(3, a, k) = 0.0_wp
      w%nmloc(1, a, k) = 0.0_wp
      w%nmloc(2, a, k) = 0.0_wp
    end do
    if (w%dirs) w%g1vec(:, :, :, k) = 0.0_wp
  end subroutine clear_segment

  subroutine load_segment(surf, x, k, xs)
    type(contact_surface_t), intent(in) :: surf
    real(wp), intent(in) :: x(:,:)
    integer, intent(in) :: k
    real(wp), intent(out) :: xs(2, 3)
    integer :: a
    xs = 0.0_wp
    do a = 1, surf%nen_seg
      xs(:, a) = x(:, surf%seg(a, k))
    end do
  end subroutine load_segment

  !> Double the row buffer of assemble_rows, keeping its entries.
  subroutine grow_row(w)
    type(mortar_work_t), intent(inout) :: w
    integer :: cap
    real(wp), allocatable :: tr(:), tv(:,:)
    cap = 2*size(w%rnode)
    call grow_int(w%rnode, cap, size(w%rnode))
    allocate(tr(cap))
    tr(1:size(w%rw)) = w%rw
    call move_alloc(tr, w%rw)
    if (allocated(w%rv)) then
      allocate(tv(2, cap))
      tv(:, 1:size(w%rv, 2)) = w%rv
      call move_alloc(tv, w%rv)
    end if
  end subroutine grow_row

  !> Double the master-entry buffers, keeping the entries written so far.
  subroutine grow_entries(w)
    type(mortar_work_t), intent(inout) :: w
    integer :: cap
    real(wp), allocatable :: tr(:), tv(:,:)
    cap = 2*size(w%ment_node)
    call grow_int(w%ment_node, cap, w%nment)
    call grow_int(w%ment_loc, cap, w%nment)
    allocate(tr(cap))
    tr(1:w%nment) = w%ment_w(1:w%nment)
    call move_alloc(tr, w%ment_w)
    if (allocated(w%ment_v)) then
      allocate(tv(2, cap))
      tv(:, 1:w%nment) = w%ment_v(:, 1:w%nment)
      call move_alloc(tv, w%ment_v)
    end if
  end subroutine grow_entries

  subroutine grow_int(a, cap, keep)
    integer, allocatable, intent(inout) :: a(:)
    integer, intent(in) :: cap, keep
    integer, allocatable :: t(:)
    allocate(t(cap))
    t(1:keep) = a(1:keep)
    call move_alloc(t, a)
  end subroutine grow_int
end module raccord_mortar
