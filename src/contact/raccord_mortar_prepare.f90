!> The mortar step's work before the overlaps (raccord_mortar,
!> build_mortar): the candidates of every near slave segment from its
!> Verlet list, the segments that have any ("active"), the slave nodal
!> normals at the nodes a later pass reads, the corner caches cleared and
!> the inward unit normals of the listed straight master segments
!> (doc/theory-contact-mortar.md section 3, "Seventh pass").
module raccord_mortar_prepare
  use raccord_kinds, only: wp
  use raccord_contact_surface, only: contact_surface_t
  use raccord_contact_verlet, only: verlet_t, verlet_candidates
  use raccord_mortar_segments, only: NODE_XI, outward_normal
  use raccord_mortar_work, only: mortar_work_t, load_segment
  implicit none
  private

  public :: prepare_step

contains

  !> The step's work before the overlaps (build_mortar): the candidates of
  !> every near slave segment, the active segments, their nodal normals,
  !> the corner caches cleared and the listed master segments' normals.
  subroutine prepare_step(slave, master, x, v, w)
    type(contact_surface_t), intent(in) :: slave, master
    real(wp), intent(in) :: x(:,:)
    type(verlet_t), intent(in) :: v
    type(mortar_work_t), intent(inout) :: w
    integer :: k, a, nen, ncand, l, t, tn, nc
    real(wp) :: lo(2), hi(2), tm(2), p1(2), p2(2)
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
      ! The box of the segment's nodes (load_segment's values); a 2-node
      ! segment's without the loop (the same min and max of its two nodes).
      if (nen == 2) then
        p1 = x(:, slave%seg(1, k))
        p2 = x(:, slave%seg(2, k))
        lo = min(p1, p2)
        hi = max(p1, p2)
      else
        lo = x(:, slave%seg(1, k))
        hi = lo
        do a = 2, nen
          lo = min(lo, x(:, slave%seg(a, k)))
          hi = max(hi, x(:, slave%seg(a, k)))
        end do
      end if
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
    integer :: c, tn, t, kk
    logical :: same
    real(wp) :: xs(2, 3), tt(2)
    ! Which segments' normals and which nodes' nodal normals are taken
    ! depends on segs and the fixed adjacency alone: the lists are kept
    ! from the last step while segs are the same (most steps; issue #16,
    ! ninth pass), and built in the same order otherwise.
    same = w%nkept == size(segs)
    if (same) then
      do tn = 1, size(segs)
        if (segs(tn) /= w%kept(tn)) then
          same = .false.
          exit
        end if
      end do
    end if
    if (.not. same) call normal_lists(slave, segs, w)
    if (slave%nen_seg == 2) then
      ! A straight segment has one normal, the same at both ends: taken
      ! once per step for the segments at the nodes of the near ones, in
      ! a loop of its own (their square roots and divisions overlap).
      ! The tangent's length |x_s'| = h/2 is kept for the overlaps'
      ! dGamma (integrate_overlap_line).
      do t = 1, w%nsl
        kk = w%slist(t)
        tt = x(:, slave%seg(1, kk))*(-0.5_wp) + x(:, slave%seg(2, kk))*0.5_wp
        w%slen(kk) = sqrt(tt(1)**2 + tt(2)**2)
        w%snrm(:, kk) = [tt(2), -tt(1)]/max(w%slen(kk), tiny(1.0_wp))
      end do
    end if
    do t = 1, w%nl
      c = w%nlist(t)
      w%covered(c) = .false.
      w%nrm(1, c) = 0.0_wp
      w%nrm(2, c) = 0.0_wp
      do tn = 1, w%nadj(c)
        kk = w%adj_seg(tn, c)
        if (slave%nen_seg == 2) then
          w%nrm(:, c) = w%nrm(:, c) + w%snrm(:, kk)
        else
          call load_segment(slave, x, kk, xs)
          w%nrm(:, c) = w%nrm(:, c) + outward_normal(slave%nen_seg, xs, NODE_XI(w%adj_loc(tn, c)))
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
    end do
    ! Normalised in a loop of its own: the square roots and divisions of
    ! different nodes overlap there instead of waiting on each other.
    do t = 1, w%nl
      c = w%nlist(t)
      w%nrm(:, c) = w%nrm(:, c)/max(sqrt(w%nrm(1, c)**2 + w%nrm(2, c)**2), tiny(1.0_wp))
    end do
  end subroutine slave_normals

  !> The lists slave_normals works through for the segments segs, in the
  !> order it took them before they were kept: the straight segments at
  !> the nodes of segs (slist, each once, in the order of segs, their nodes
  !> and the nodes' segments) and the nodes of segs (nlist, each once, in
  !> the order of segs and their nodes); segs recorded for the next step.
  subroutine normal_lists(slave, segs, w)
    type(contact_surface_t), intent(in) :: slave
    integer, intent(in) :: segs(:)
    type(mortar_work_t), intent(inout) :: w
    integer :: k, a, c, tn, t, kk
    w%nstep = w%nstep + 1
    w%nsl = 0
    if (slave%nen_seg == 2) then
      do tn = 1, size(segs)
        k = segs(tn)
        do a = 1, 2
          c = w%pos(a, k)
          do t = 1, w%nadj(c)
            kk = w%adj_seg(t, c)
            if (w%sstamp(kk) == w%nstep) cycle
            w%sstamp(kk) = w%nstep
            w%nsl = w%nsl + 1
            w%slist(w%nsl) = kk
          end do
        end do
      end do
    end if
    w%nl = 0
    do tn = 1, size(segs)
      k = segs(tn)
      do a = 1, slave%nen_seg
        c = w%pos(a, k)
        if (w%stamp(c) == w%nstep) cycle
        w%stamp(c) = w%nstep
        w%nl = w%nl + 1
        w%nlist(w%nl) = c
      end do
    end do
    w%nkept = size(segs)
    w%kept(1:size(segs)) = segs
  end subroutine normal_lists

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
end module raccord_mortar_prepare
