!> Incremental contact search with a skin distance, as molecular dynamics
!> keeps Verlet neighbour lists (doc/theory-contact.md, "Incremental
!> search"). The search of raccord_contact_search pairs a slave item (a
!> segment for mortar, a node for node-to-segment) with the master segments
!> whose box, inflated by min(reach, segment length), meets the item's box.
!> Here that search is run with each master box inflated by
!> min(reach, length + skin) + skin on the positions x_ref of one step and
!> its result kept as a candidate list per slave item. While no surface
!> node has moved by more than skin/2 from x_ref, every pair the search
!> would find now is in the lists (each of the two boxes moves by at most
!> skin/2, and the inflation min(reach, length) by at most skin, the
!> length growing by at most twice skin/2), so a step only filters
!> the lists with the current boxes, with the same test: the pairs, and so
!> the constraints, are those of a full search, and only the slave items
!> with candidates (the "near" items) and the master segments in some list
!> are looked at. When a node has moved further the lists are rebuilt.
!> The check of the displacements is one pass over the surface nodes'
!> coordinates; everything else follows the near items.
module raccord_contact_verlet
  use raccord_kinds, only: wp, i8
  use raccord_contact_surface, only: contact_surface_t
  use raccord_contact_search, only: bins_t, build_bins, query_bins
  implicit none
  private

  !> Skin distance as a fraction of the search reach. 0.5 until the seventh
  !> pass of issue #16: the lists then held every slave segment within 1.5
  !> reach, and about 30 % of the near segments had no candidate in a step
  !> on the paper's decks; with 0.25 and the inflation above, Fig. 2(a)
  !> has 99 near segments per step instead of 119 (82 with candidates)
  !> and lists of 6.4 entries instead of 10.5, for 60 rebuilds in 40941
  !> steps instead of 30 (doc/performance.md, seventh pass).
  real(wp), parameter, public :: SKIN_OF_REACH = 0.25_wp
  !> Rebuild a little before the bound (the padded boxes carry round-off).
  real(wp), parameter :: SKIN_SAFETY = 0.9_wp
  !> Segments either side of the near ones whose nodes a step reads: the
  !> mortar multiplier weights read the slave segments next to a near one,
  !> node-to-segment the master nodal normals read the segments at the
  !> nodes of the listed ones dilated by two (see rebuild).
  integer, parameter :: LOAD_DILATION = 3

  type, public :: verlet_t
    logical :: by_segment = .true.            !< slave items are segments (mortar) or nodes (node-to-segment)
    real(wp) :: skin = 0.0_wp
    logical :: valid = .false.
    logical :: rebuilt = .false.              !< the lists were rebuilt at this step
    integer(i8) :: rebuilds = 0
    real(wp), allocatable :: xs_ref(:,:), xm_ref(:,:)   !< (2, nnode) slave, master surface nodes at the last build
    integer, allocatable :: ptr(:)            !< (nitem + 1) start of each item's candidates
    integer, allocatable :: item(:)           !< candidate master segments, ascending per item
    integer :: nnear = 0
    integer, allocatable :: near(:)           !< slave items with candidates, ascending
    integer :: nmnear = 0
    integer, allocatable :: mnear(:)          !< master segments in some list, ascending
    logical, allocatable :: mflag(:)          !< (master nseg) scratch
    real(wp), allocatable :: box(:,:)         !< (4, master nseg) inflated boxes this step (at mnear)
    ! Node items (node-to-segment): the segments whose geometry their
    ! constraints read.
    integer :: nmdil = 0
    integer, allocatable :: mdil(:)           !< master segments within two of a listed one, ascending
    integer :: nsnear = 0
    integer, allocatable :: snear(:)          !< slave segments with a near node, ascending
    ! The surface nodes whose positions a step reads while the lists hold
    ! (nodes of the near slave items and of the listed master segments,
    ! each side dilated by LOAD_DILATION segments), and whether this step's
    ! displacement check was made already (verlet_check).
    integer :: nload = 0
    integer, allocatable :: load(:)           !< global node numbers
    logical :: checked = .false.
    ! Node items: each node's closest master segment at the last step and
    ! its foot parameters there (raccord_node_to_segment, smooth_foot).
    integer, allocatable :: warm_seg(:)
    real(wp), allocatable :: warm_t(:,:)      !< (3, slave nnode), -1: none
    integer, allocatable :: sdist(:), mdist(:)   !< (nseg) scratch of load_list
    logical, allocatable :: snode(:), mnode(:)   !< (nnode) scratch of load_list
    type(bins_t) :: bins
  end type verlet_t

  public :: verlet_init, verlet_check, verlet_refresh, verlet_item_box, verlet_overlaps, verlet_candidates

contains

  !> Size the lists for a pair; by_segment for mortar.
  subroutine verlet_init(v, slave, master, by_segment, reach)
    type(verlet_t), intent(out) :: v
    type(contact_surface_t), intent(in) :: slave, master
    logical, intent(in) :: by_segment
    real(wp), intent(in) :: reach
    integer :: nitem
    v%by_segment = by_segment
    v%skin = SKIN_OF_REACH*reach
    nitem = merge(slave%nseg, slave%nnode, by_segment)
    allocate(v%xs_ref(2, slave%nnode), v%xm_ref(2, master%nnode), source=0.0_wp)
    allocate(v%ptr(nitem + 1), source=1)
    allocate(v%item(4*nitem + 16), v%near(nitem), v%mnear(master%nseg))
    allocate(v%mflag(master%nseg), source=.false.)
    allocate(v%box(4, master%nseg), source=0.0_wp)
    allocate(v%mdil(master%nseg), v%snear(slave%nseg))
    allocate(v%load(slave%nnode + master%nnode))
    allocate(v%sdist(slave%nseg), v%mdist(master%nseg))
    allocate(v%snode(slave%nnode), v%mnode(master%nnode))
    allocate(v%warm_seg(slave%nnode), source=0)
    allocate(v%warm_t(3, slave%nnode), source=-1.0_wp)
  end subroutine verlet_init

  !> The displacement check of verlet_refresh on x0 + u (reference
  !> positions and displacements, the same sums the caller's positions are
  !> made of), before the caller has formed them: afterwards, while
  !> v%valid, the step reads only the nodes v%load(1:nload), and the
  !> surface nodes far from the other surface cost this one pass. The
  !> refresh that follows in the same step does not check again.
  subroutine verlet_check(v, x0, u, slave, master)
    type(verlet_t), intent(inout) :: v
    real(wp), intent(in) :: x0(:,:), u(:,:)
    type(contact_surface_t), intent(in) :: slave, master
    integer :: q, n
    real(wp) :: d2
    v%checked = .true.
    if (.not. v%valid) return
    d2 = 0.0_wp
    do q = 1, slave%nnode
      n = slave%node(q)
      d2 = max(d2, (x0(1, n) + u(1, n) - v%xs_ref(1, q))**2 + (x0(2, n) + u(2, n) - v%xs_ref(2, q))**2)
    end do
    do q = 1, master%nnode
      n = master%node(q)
      d2 = max(d2, (x0(1, n) + u(1, n) - v%xm_ref(1, q))**2 + (x0(2, n) + u(2, n) - v%xm_ref(2, q))**2)
    end do
    if (2.0_wp*sqrt(d2) > SKIN_SAFETY*v%skin) v%valid = .false.
  end subroutine verlet_check

  !> Rebuild the lists if a surface node has moved by more than skin/2
  !> since the last build (or at the first call), then the current inflated
  !> boxes of the listed master segments, exactly as build_bins makes them.
  subroutine verlet_refresh(v, x, slave, master, reach)
    type(verlet_t), intent(inout) :: v
    real(wp), intent(in) :: x(:,:)
    type(contact_surface_t), intent(in) :: slave, master
    real(wp), intent(in) :: reach
    integer :: q, t, l, j
    real(wp) :: d2, lo(2), hi(2), r
    v%rebuilt = .false.
    d2 = 0.0_wp
    if (v%valid .and. .not. v%checked) then
      do q = 1, slave%nnode
        d2 = max(d2, (x(1, slave%node(q)) - v%xs_ref(1, q))**2 + (x(2, slave%node(q)) - v%xs_ref(2, q))**2)
      end do
      do q = 1, master%nnode
        d2 = max(d2, (x(1, master%node(q)) - v%xm_ref(1, q))**2 + (x(2, master%node(q)) - v%xm_ref(2, q))**2)
      end do
    end if
    v%checked = .false.
    if (.not. v%valid .or. 2.0_wp*sqrt(d2) > SKIN_SAFETY*v%skin) call rebuild(v, x, slave, master, reach)
    do t = 1, v%nmnear
      l = v%mnear(t)
      lo = x(:, master%seg(1, l))
      hi = lo
      do j = 2, master%nen_seg
        lo = min(lo, x(:, master%seg(j, l)))
        hi = max(hi, x(:, master%seg(j, l)))
      end do
      r = min(reach, norm2(x(:, master%seg(2, l)) - x(:, master%seg(1, l))))
      v%box(:, l) = [lo - r, hi + r]
    end do
  end subroutine verlet_refresh

  !> Box of slave item k (segment or node) on x.
  pure subroutine verlet_item_box(v, slave, x, k, lo, hi)
    type(verlet_t), intent(in) :: v
    type(contact_surface_t), intent(in) :: slave
    real(wp), intent(in) :: x(:,:)
    integer, intent(in) :: k
    real(wp), intent(out) :: lo(2), hi(2)
    integer :: a
    if (v%by_segment) then
      lo = x(:, slave%seg(1, k))
      hi = lo
      do a = 2, slave%nen_seg
        lo = min(lo, x(:, slave%seg(a, k)))
        hi = max(hi, x(:, slave%seg(a, k)))
      end do
    else
      lo = x(:, slave%node(k))
      hi = lo
    end if
  end subroutine verlet_item_box

  !> Does master segment l's current inflated box meet [lo, hi]? (The
  !> test of the full search.)
  pure logical function verlet_overlaps(v, l, lo, hi) result(yes)
    type(verlet_t), intent(in) :: v
    integer, intent(in) :: l
    real(wp), intent(in) :: lo(2), hi(2)
    yes = .not. (v%box(1, l) > hi(1) .or. v%box(3, l) < lo(1) .or. v%box(2, l) > hi(2) .or. v%box(4, l) < lo(2))
  end function verlet_overlaps

  !> The listed master segments of slave item k whose current inflated box
  !> meets [lo, hi] (verlet_overlaps on each, in list order, in one call:
  !> the filter runs once per list entry and step).
  pure subroutine verlet_candidates(v, k, lo, hi, cand, ncand)
    type(verlet_t), intent(in) :: v
    integer, intent(in) :: k
    real(wp), intent(in) :: lo(2), hi(2)
    integer, intent(inout) :: cand(:)
    integer, intent(out) :: ncand
    integer :: q, l
    ncand = 0
    do q = v%ptr(k), v%ptr(k + 1) - 1
      l = v%item(q)
      if (v%box(1, l) > hi(1) .or. v%box(3, l) < lo(1) .or. v%box(2, l) > hi(2) .or. v%box(4, l) < lo(2)) cycle
      ncand = ncand + 1
      cand(ncand) = l
    end do
  end subroutine verlet_candidates

  !> The full search on x with boxes inflated by reach + skin.
  subroutine rebuild(v, x, slave, master, reach)
    type(verlet_t), intent(inout) :: v
    real(wp), intent(in) :: x(:,:)
    type(contact_surface_t), intent(in) :: slave, master
    real(wp), intent(in) :: reach
    integer :: q, k, nitem, n, nx, ny, ix, iy, first, last, i, l, a, b, tmp
    real(wp) :: lo(2), hi(2), p(2)
    integer, allocatable :: grown(:)
    v%valid = .true.
    v%rebuilt = .true.
    v%rebuilds = v%rebuilds + 1
    do q = 1, slave%nnode
      v%xs_ref(:, q) = x(:, slave%node(q))
    end do
    do q = 1, master%nnode
      v%xm_ref(:, q) = x(:, master%node(q))
    end do
    call build_bins(v%bins, x, master%seg, master%nen_seg, reach, skin=v%skin)
    nitem = merge(slave%nseg, slave%nnode, v%by_segment)
    n = 0
    v%nnear = 0
    v%ptr(1) = 1
    items: do k = 1, nitem
      call verlet_item_box(v, slave, x, k, lo, hi)
      ! Sample points one cell apart reach every cell the item's box covers.
      nx = ceiling((hi(1) - lo(1))/v%bins%cell)
      ny = ceiling((hi(2) - lo(2))/v%bins%cell)
      do iy = 0, ny
        do ix = 0, nx
          p = [min(lo(1) + real(ix, wp)*v%bins%cell, hi(1)), min(lo(2) + real(iy, wp)*v%bins%cell, hi(2))]
          call query_bins(v%bins, p, first, last)
          do q = first, last
            l = v%bins%item(q)
            if (v%mflag(l)) cycle
            if (v%bins%box(1, l) > hi(1) .or. v%bins%box(3, l) < lo(1) .or. &
                v%bins%box(2, l) > hi(2) .or. v%bins%box(4, l) < lo(2)) cycle
            v%mflag(l) = .true.
            if (n == size(v%item)) then
              allocate(grown(2*size(v%item)))
              grown(1:n) = v%item(1:n)
              call move_alloc(grown, v%item)
            end if
            n = n + 1
            v%item(n) = l
          end do
        end do
      end do
      ! Ascending master order (insertion sort: a few candidates).
      do a = v%ptr(k) + 1, n
        tmp = v%item(a)
        b = a - 1
        do while (b >= v%ptr(k))
          if (v%item(b) <= tmp) exit
          v%item(b + 1) = v%item(b)
          b = b - 1
        end do
        v%item(b + 1) = tmp
      end do
      do i = v%ptr(k), n
        v%mflag(v%item(i)) = .false.
      end do
      v%ptr(k + 1) = n + 1
      if (n >= v%ptr(k)) then
        v%nnear = v%nnear + 1
        v%near(v%nnear) = k
      end if
    end do items
    ! Master segments in some list.
    do i = 1, n
      v%mflag(v%item(i)) = .true.
    end do
    v%nmnear = 0
    do l = 1, master%nseg
      if (.not. v%mflag(l)) cycle
      v%nmnear = v%nmnear + 1
      v%mnear(v%nmnear) = l
    end do
    call load_list(v, slave, master)
    if (v%by_segment) then
      v%mflag = .false.
      return
    end if
    ! Node-to-segment reads the master's nodal normals on a listed segment
    ! and its neighbours, each the mean over the segments at the node: the
    ! listed segments dilated by two.
    do a = 1, 2
      do l = 1, master%nseg
        if (.not. v%mflag(l)) cycle
        do b = -1, 1, 2
          i = l + b
          if (master%closed) i = modulo(i - 1, master%nseg) + 1
          if (i >= 1 .and. i <= master%nseg) then
            if (.not. v%mflag(i)) v%mdil(i) = -a
          end if
        end do
      end do
      do l = 1, master%nseg
        if (v%mdil(l) == -a) v%mflag(l) = .true.
      end do
    end do
    v%nmdil = 0
    do l = 1, master%nseg
      if (.not. v%mflag(l)) cycle
      v%mflag(l) = .false.
      v%nmdil = v%nmdil + 1
      v%mdil(v%nmdil) = l
    end do
    ! And the tributary lengths of the near nodes: their slave segments.
    v%nsnear = 0
    do k = 1, slave%nseg
      do a = 1, slave%nen_seg
        i = chain_position(slave, k, a)
        if (v%ptr(i + 1) > v%ptr(i)) then
          v%nsnear = v%nsnear + 1
          v%snear(v%nsnear) = k
          exit
        end if
      end do
    end do
  end subroutine rebuild

  !> v%load: the nodes of the slave segments holding a near item and of
  !> the listed master segments (v%mflag), each dilated by LOAD_DILATION
  !> segments along its chain. v%mflag is left as it was.
  subroutine load_list(v, slave, master)
    type(verlet_t), intent(inout) :: v
    type(contact_surface_t), intent(in) :: slave, master
    integer :: t, k, c, stride
    v%sdist(1:slave%nseg) = huge(1)
    v%mdist(1:master%nseg) = huge(1)
    stride = slave%nen_seg - 1
    do t = 1, v%nnear
      k = v%near(t)
      if (v%by_segment) then
        v%sdist(k) = 0
      else
        ! The segments at chain node c = k: the one it starts or lies in,
        ! and the one a corner ends.
        c = k
        k = (c - 1)/stride + 1
        if (k <= slave%nseg) v%sdist(k) = 0
        if (mod(c - 1, stride) == 0) then
          k = k - 1
          if (k == 0 .and. slave%closed) k = slave%nseg
          if (k >= 1) v%sdist(k) = 0
        end if
      end if
    end do
    do k = 1, master%nseg
      if (v%mflag(k)) v%mdist(k) = 0
    end do
    v%nload = 0
    call add_nodes(slave, v%sdist(1:slave%nseg), v%snode)
    call add_nodes(master, v%mdist(1:master%nseg), v%mnode)
  contains
    !> Distances along the chain to the nearest flagged segment (twice
    !> round a closed loop), then the nodes of those within LOAD_DILATION.
    subroutine add_nodes(surf, dist, seen)
      type(contact_surface_t), intent(in) :: surf
      integer, intent(inout) :: dist(:)
      logical, intent(inout) :: seen(:)
      integer :: n, q, kk, a, i, prev, rounds
      n = surf%nseg
      rounds = merge(2, 1, surf%closed)
      prev = huge(1)
      do q = 1, rounds*n
        kk = modulo(q - 1, n) + 1
        if (prev < huge(1)) dist(kk) = min(dist(kk), prev + 1)
        prev = dist(kk)
      end do
      prev = huge(1)
      do q = rounds*n, 1, -1
        kk = modulo(q - 1, n) + 1
        if (prev < huge(1)) dist(kk) = min(dist(kk), prev + 1)
        prev = dist(kk)
      end do
      seen(1:surf%nnode) = .false.
      do kk = 1, n
        if (dist(kk) > LOAD_DILATION) cycle
        do a = 1, surf%nen_seg
          i = chain_position(surf, kk, a)
          if (seen(i)) cycle
          seen(i) = .true.
          v%nload = v%nload + 1
          v%load(v%nload) = surf%node(i)
        end do
      end do
    end subroutine add_nodes
  end subroutine load_list

  !> Chain position (index in slave%node) of local node a of segment k.
  pure integer function chain_position(surf, k, a) result(pos)
    type(contact_surface_t), intent(in) :: surf
    integer, intent(in) :: k, a
    integer :: stride
    stride = surf%nen_seg - 1
    select case (a)
    case (1)
      pos = stride*(k - 1) + 1
    case (2)
      pos = stride*k + 1
      if (surf%closed .and. k == surf%nseg) pos = 1
    case default
      pos = stride*(k - 1) + 2
    end select
  end function chain_position
end module raccord_contact_verlet
