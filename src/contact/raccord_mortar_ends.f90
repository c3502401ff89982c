!> Where an open master ends inside the slave's reach (raccord_mortar):
!> the corner rows, a point row for each end corner of the master that
!> lies inside a slave segment, and the boundary modification of the
!> multiplier space for the slave nodes past the master's end
!> (doc/theory-contact-mortar.md sections 3 and 7; doc/verification.md
!> section 13). Both act on the step's per-segment integrals before the
!> rows are written (raccord_mortar_rows).
module raccord_mortar_ends
  use raccord_kinds, only: wp
  use raccord_scene, only: MULT_DUAL
  use raccord_contact_surface, only: contact_surface_t
  use raccord_contact_verlet, only: verlet_t
  use raccord_segment, only: segment_point
  use raccord_mortar_segments, only: NODE_XI, normal_field, end_offset, root_along_field
  use raccord_mortar_work, only: mortar_work_t, load_segment, XI_COVER
  implicit none
  private

  public :: find_corner_rows, merge_uncovered

contains

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
end module raccord_mortar_ends
