!> The contact constraints of one pair at one step, as built by a matching
!> method (node-to-segment, mortar) and consumed by the multiplier solver.
!>
!> One constraint j per multiplier node of the slave surface (paper
!> section 3: m slave nodes). Its row is a list of (node p, weight w_jp)
!> with w = -G1(i, j) on slave nodes i and w = +G21(a, j) on master nodes a,
!> so that, with n_j the normal at j pointing from the slave into the master
!> and t_j the tangent (n_j turned clockwise):
!>   weighted gap    g_w(j) = sum_p w_jp x_p . n_j      (>= 0: open)
!>   weighted slip   s_w(j) = sum_p w_jp du_p . t_j     (master relative to slave)
!>   contact force   f_p    = sum_j w_jp (lambda_j n_j + tau_j t_j)
!> and the paper's conditions (19) bear on the nodal gap G1^-1 g_w and the
!> weighted multipliers G1 lambda. Node-to-segment is the case G1 = I.
!>
!> Per-entry directions (`entry_dirs`, chosen once per pair: mortar with
!> corner multipliers on 3-node slave edges, raccord_mortar): each entry
!> carries its own vector weight W_jp = w_jp nu_jp, the exact first
!> variation of the row's weighted gap int psi_j (x_m - x_s) . nu dGamma
!> (nu the master's normal, doc/theory-contact.md section 7), instead of
!> w_jp n_j with one direction per row; with W^perp = W turned clockwise
!>   g_w(j) = sum_p W_jp . x_p,  s_w(j) = sum_p W^perp_jp . du_p,
!>   f_p    = sum_j (lambda_j W_jp + tau_j W^perp_jp).
!> The scalar w_jp stays G1's entry (the conditions); rows without
!> per-entry directions keep their arithmetic exactly.
module raccord_constraint_set
  use raccord_kinds, only: wp
  implicit none
  private

  !> half bandwidth of G1 kept: P0/P1 on Q4 or Q8 edges, with a mortar
  !> corner row between (3); a closed slave loop with multipliers all
  !> round, numbered folded (raccord_mortar, assemble_rows), on Q8 edges
  !> (4), with the two corner rows of an open master between (6)
  integer, parameter, public :: G1_MAX_BAND = 6

  type, public :: constraint_set_t
    integer :: m = 0                          !< constraints this step
    integer, allocatable :: snode(:)          !< index in the slave surface's node list
    integer, allocatable :: gnode(:)          !< global node index
    real(wp), allocatable :: normal(:,:)      !< (2, m) slave -> master
    real(wp), allocatable :: tangent(:,:)     !< (2, m) normal turned clockwise
    integer :: g1_band = 0                    !< half bandwidth of G1 this step
    !> The contact conditions bear on each multiplier and its own weighted
    !> gap (lambda_j >= 0, g_w(j) >= 0; mortar) instead of on G1 lambda and
    !> the nodal gap (paper (19)); G1 stays the map to the nodal forces.
    logical :: weighted = .false.
    real(wp), allocatable :: g1(:,:)          !< (-G1_MAX_BAND:G1_MAX_BAND, m): g1(d, j) = G1(j+d, j)
    integer, allocatable :: row_ptr(:)        !< (m+1) start of each row's entries
    integer :: nent = 0
    integer, allocatable :: ent_node(:)
    real(wp), allocatable :: ent_w(:)
    !> Entries carry their own vector weights ent_v (above); set by cs_start.
    logical :: entry_dirs = .false.
    real(wp), allocatable :: ent_v(:,:)       !< (2, nent) W_jp, with entry_dirs only
    real(wp), allocatable :: gap_w(:)         !< weighted gap at the predicted positions
    real(wp), allocatable :: slip_w(:)        !< weighted slip of the predicted increment
    real(wp), allocatable :: length(:)        !< length the multiplier acts on (for stresses)
    real(wp), allocatable :: coord(:)         !< reference arc length of the node (for profiles)
    !> Tangential corner multipliers (mortar on 3-node slave edges, chosen
    !> once per pair; set by raccord_mortar_rows): tau = T tau_c, a mid
    !> row's tau the mean of its corners' (tcor(:, j), 0: no row), the
    !> tangential conditions tested with T' (an owner row j and the mid
    !> rows tmid(:, j) that take half of its value). tcor(1, j) < 0: row j
    !> owns its tangential unknown.
    logical :: tcorners = .false.
    integer, allocatable :: tcor(:,:)         !< (2, m) mid row: the rows of its corners
    integer, allocatable :: tmid(:,:)         !< (2, m) owner row: the mid rows that take half its value
  end type constraint_set_t

  public :: cs_start, cs_add_row, cs_add_entry, cs_finish_row, cs_reserve, cs_close_row

contains

  !> Start a new set with room for up to `mcap` constraints (grow-only
  !> buffers); `entry_dirs`: the entries carry vector weights (ent_v).
  subroutine cs_start(cs, mcap, entry_dirs)
    type(constraint_set_t), intent(inout) :: cs
    integer, intent(in) :: mcap
    logical, intent(in), optional :: entry_dirs
    cs%entry_dirs = .false.
    if (present(entry_dirs)) cs%entry_dirs = entry_dirs
    if (.not. allocated(cs%snode)) then
      call grow(cs, max(mcap, 1), max(8*mcap, 8))
    else if (size(cs%snode) < mcap) then
      call grow(cs, mcap, max(size(cs%ent_node), 8*mcap))
    else if (cs%entry_dirs .and. .not. allocated(cs%ent_v)) then
      call grow(cs, size(cs%snode), size(cs%ent_node))
    end if
    cs%m = 0
    cs%nent = 0
    cs%g1_band = 0
    cs%weighted = .false.
    cs%row_ptr(1) = 1
  end subroutine cs_start

  !> Open row j = m+1 for slave surface node `snode` (global `gnode`).
  subroutine cs_add_row(cs, snode, gnode, normal, length, coord)
    type(constraint_set_t), intent(inout) :: cs
    integer, intent(in) :: snode, gnode
    real(wp), intent(in) :: normal(2), length, coord
    integer :: j, d
    cs%m = cs%m + 1
    j = cs%m
    cs%snode(j) = snode
    cs%gnode(j) = gnode
    cs%normal(:, j) = normal
    cs%tangent(:, j) = [normal(2), -normal(1)]
    ! (A loop of known length: the section was a call to memset per row.)
    do d = -G1_MAX_BAND, G1_MAX_BAND
      cs%g1(d, j) = 0.0_wp
    end do
    cs%g1(0, j) = 1.0_wp
    cs%length(j) = length
    cs%coord(j) = coord
    cs%gap_w(j) = 0.0_wp
    cs%slip_w(j) = 0.0_wp
  end subroutine cs_add_row

  !> Add weight w of node p to the open row (merging a repeated node).
  subroutine cs_add_entry(cs, p, w)
    type(constraint_set_t), intent(inout) :: cs
    integer, intent(in) :: p
    real(wp), intent(in) :: w
    integer :: e
    do e = cs%row_ptr(cs%m), cs%nent
      if (cs%ent_node(e) == p) then
        cs%ent_w(e) = cs%ent_w(e) + w
        if (cs%entry_dirs) cs%ent_v(:, e) = cs%ent_v(:, e) + w*cs%normal(:, cs%m)
        return
      end if
    end do
    if (cs%nent == size(cs%ent_node)) call grow(cs, size(cs%snode), 2*size(cs%ent_node))
    cs%nent = cs%nent + 1
    cs%ent_node(cs%nent) = p
    cs%ent_w(cs%nent) = w
    ! A row added entry by entry has one direction, the row's normal.
    if (cs%entry_dirs) cs%ent_v(:, cs%nent) = w*cs%normal(:, cs%m)
  end subroutine cs_add_entry

  !> Close the open row: weighted gap and slip from positions x and increments du.
  subroutine cs_finish_row(cs, x, du)
    type(constraint_set_t), intent(inout) :: cs
    real(wp), intent(in) :: x(:,:), du(:,:)
    integer :: j, e, p
    j = cs%m
    cs%row_ptr(j + 1) = cs%nent + 1
    cs%gap_w(j) = 0.0_wp
    cs%slip_w(j) = 0.0_wp
    if (cs%entry_dirs) then
      call vector_sums(cs, j, x, du)
      return
    end if
    do e = cs%row_ptr(j), cs%nent
      p = cs%ent_node(e)
      cs%gap_w(j) = cs%gap_w(j) + cs%ent_w(e)*dot_product(x(:, p), cs%normal(:, j))
      cs%slip_w(j) = cs%slip_w(j) + cs%ent_w(e)*dot_product(du(:, p), cs%tangent(:, j))
    end do
  end subroutine cs_finish_row

  !> The row's weighted gap and slip, g_w = sum_e w_e x_e . n and
  !> s_w = sum_e w_e du_e . t with t = (n_2, -n_1), for rows of scalar
  !> weights (vector_sums for per-entry directions).
  subroutine scalar_sums(cs, j, normal, x, du)
    type(constraint_set_t), intent(inout) :: cs
    integer, intent(in) :: j
    real(wp), intent(in) :: normal(2), x(:,:), du(:,:)
    integer :: e, p
    real(wp) :: tangent(2), gap, slip
    tangent = [normal(2), -normal(1)]
    gap = 0.0_wp
    slip = 0.0_wp
    do e = cs%row_ptr(j), cs%row_ptr(j + 1) - 1
      p = cs%ent_node(e)
      gap = gap + cs%ent_w(e)*dot_product(x(:, p), normal)
      slip = slip + cs%ent_w(e)*dot_product(du(:, p), tangent)
    end do
    cs%gap_w(j) = gap
    cs%slip_w(j) = slip
  end subroutine scalar_sums

  !> Weighted gap and slip of row j from the entries' vector weights:
  !> g_w = sum_p W_jp . x_p, s_w = sum_p W^perp_jp . du_p (module header).
  subroutine vector_sums(cs, j, x, du)
    type(constraint_set_t), intent(inout) :: cs
    integer, intent(in) :: j
    real(wp), intent(in) :: x(:,:), du(:,:)
    integer :: e, p
    real(wp) :: gap, slip, v1, v2
    gap = 0.0_wp
    slip = 0.0_wp
    do e = cs%row_ptr(j), cs%row_ptr(j + 1) - 1
      p = cs%ent_node(e)
      v1 = cs%ent_v(1, e)
      v2 = cs%ent_v(2, e)
      gap = gap + (v1*x(1, p) + v2*x(2, p))
      slip = slip + (v2*du(1, p) - v1*du(2, p))
    end do
    cs%gap_w(j) = gap
    cs%slip_w(j) = slip
  end subroutine vector_sums

  !> Room for n more entries after the last (rows written in place by the
  !> caller, cs_close_row); the entries written so far are kept.
  subroutine cs_reserve(cs, n)
    type(constraint_set_t), intent(inout) :: cs
    integer, intent(in) :: n
    if (cs%nent + n > size(cs%ent_node)) call grow(cs, size(cs%snode), 2*size(cs%ent_node) + n)
  end subroutine cs_reserve

  !> A whole row whose n distinct entries the caller has written in place,
  !> at cs%nent + 1 to cs%nent + n (ent_node, ent_w and, with
  !> cs%entry_dirs, ent_v), within room taken by cs_reserve: opens the row
  !> (cs_add_row), takes the entries as they are, zeros included, and
  !> closes it with the sums of cs_finish_row in the same order, without a
  !> copy of the entries through a caller's buffer (issue #16, eighth pass;
  !> node-to-segment and mortar rows since the ninth).
  subroutine cs_close_row(cs, snode, gnode, normal, length, coord, n, x, du)
    type(constraint_set_t), intent(inout) :: cs
    integer, intent(in) :: snode, gnode
    real(wp), intent(in) :: normal(2), length, coord
    integer, intent(in) :: n
    real(wp), intent(in) :: x(:,:), du(:,:)
    integer :: j
    call cs_add_row(cs, snode, gnode, normal, length, coord)
    j = cs%m
    cs%nent = cs%nent + n
    cs%row_ptr(j + 1) = cs%nent + 1
    if (cs%entry_dirs) then
      call vector_sums(cs, j, x, du)
      return
    end if
    call scalar_sums(cs, j, normal, x, du)
  end subroutine cs_close_row

  subroutine grow(cs, mcap, ecap)
    type(constraint_set_t), intent(inout) :: cs
    integer, intent(in) :: mcap, ecap
    integer, allocatable :: ti(:)
    real(wp), allocatable :: tr(:), tv(:,:)
    logical :: small
    small = .true.
    if (allocated(cs%snode)) small = size(cs%snode) < mcap
    if (small) then
      if (allocated(cs%snode)) deallocate(cs%snode, cs%gnode, cs%normal, cs%tangent, cs%g1, cs%row_ptr, &
        cs%gap_w, cs%slip_w, cs%length, cs%coord)
      allocate(cs%snode(mcap), cs%gnode(mcap), cs%normal(2, mcap), cs%tangent(2, mcap), &
        cs%g1(-G1_MAX_BAND:G1_MAX_BAND, mcap), cs%row_ptr(mcap + 1), cs%gap_w(mcap), cs%slip_w(mcap), &
        cs%length(mcap), cs%coord(mcap))
      cs%g1 = 0.0_wp
    end if
    if (.not. allocated(cs%ent_node)) then
      allocate(cs%ent_node(ecap), cs%ent_w(ecap))
      if (cs%entry_dirs) allocate(cs%ent_v(2, ecap))
    else if (cs%entry_dirs .and. .not. allocated(cs%ent_v)) then
      allocate(cs%ent_v(2, max(ecap, size(cs%ent_node))))
    end if
    if (size(cs%ent_node) < ecap) then
      ! Keep the entries written so far: rows are built in place.
      allocate(ti(ecap))
      ti(1:cs%nent) = cs%ent_node(1:cs%nent)
      call move_alloc(ti, cs%ent_node)
      allocate(tr(ecap))
      tr(1:cs%nent) = cs%ent_w(1:cs%nent)
      call move_alloc(tr, cs%ent_w)
    end if
    if (allocated(cs%ent_v)) then
      if (size(cs%ent_v, 2) < size(cs%ent_node)) then
        allocate(tv(2, size(cs%ent_node)))
        tv(:, 1:cs%nent) = cs%ent_v(:, 1:cs%nent)
        call move_alloc(tv, cs%ent_v)
      end if
    end if
  end subroutine grow
end module raccord_constraint_set
