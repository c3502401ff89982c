!> The mortar pair's scratch (raccord_mortar): the slave chain's layout
!> (each segment's chain positions, each node's segments), the
!> per-segment integrals a step builds (G1, G21, the master-normal
!> weights), the step's candidates, the corner-row data and the row
!> buffer; sized once by init_mortar and grown only, so that no step
!> allocates once the contact zone is known. Split from raccord_mortar by
!> concept (issue #16, eighth pass): the step's preparation
!> (raccord_mortar_prepare), the overlap integration (raccord_mortar),
!> where the master ends (raccord_mortar_ends) and the rows
!> (raccord_mortar_rows) share this type.
module raccord_mortar_work
  use raccord_kinds, only: wp
  use raccord_error, only: error_t, raise_error, EXIT_INPUT
  use raccord_scene, only: MULT_P1, MULT_P0, MULT_DUAL
  use raccord_contact_surface, only: contact_surface_t
  implicit none
  private

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
  public :: XI_COVER

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
    !> 3-node slave edges, multipliers on every trace node: the tangential
    !> multipliers and conditions on the corners only (raccord_mortar_rows
    !> writes the map into the constraint set; issue #16 item 3)
    logical :: tcorners = .false.
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
    integer, allocatable :: nlist(:)          !< (nnode) the nodes whose normals are taken
    integer :: nstep = 0
    integer, allocatable :: sstamp(:)         !< (nseg) last step snrm was taken at (2-node segments)
    real(wp), allocatable :: snrm(:,:)        !< (2, nseg) outward unit normal of each straight segment
    real(wp), allocatable :: slen(:)          !< (nseg) |dx_s/dxi| of each straight segment (half its length)
    real(wp), allocatable :: mnu(:,:)         !< (2, master nseg) inward unit normal of each listed straight
                                              !< master segment, taken once per step (build_mortar)
    integer, allocatable :: slist(:)          !< (nseg) the segments whose snrm is taken
    ! slist(1:nsl) and nlist(1:nl) are functions of the segments
    ! slave_normals was given (kept(1:nkept)) and the fixed adjacency:
    ! kept while the step gives the same segments (raccord_mortar_prepare).
    integer :: nsl = 0, nl = 0, nkept = -1
    integer, allocatable :: kept(:)           !< (nseg) the segments the lists were built for
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
    ! The row being assembled (assemble_rows, which writes its distinct
    ! nodes and summed weights straight into the constraint set): each
    ! global node's place in it (0: not in the row).
    integer, allocatable :: slot(:)           !< (largest global node number of the pair)
  end type mortar_work_t

  public :: init_mortar, load_segment, grow_entries

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
    allocate(w%slist(ns), w%kept(ns))
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
end module raccord_mortar_work
