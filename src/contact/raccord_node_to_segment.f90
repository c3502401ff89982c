!> Node-to-segment matching ("raccord ponctuel", paper 4.1; method brief
!> section 4): each slave node is projected on the closest master segment;
!> one constraint per slave node, its force on the slave node and spread to
!> the master segment's nodes with the segment's shape functions at the
!> projection point (G1 = I, G21 = N_a).
!>
!> The master's normal is continuous: averaged nodal normals interpolated
!> along each segment with its shape functions, and the foot of a slave node
!> is where that normal field passes through it. With the segments' own,
!> piecewise-constant normals a node sliding across a convex master vertex
!> finds its previous position a first-order distance inside the next
!> segment's line, and the forward increment pushes it out: the contact
!> force then does work, and on coarse meshes (the paper's scene, disc as
!> slave) that pumped half the internal energy through the run. On a flat
!> master both definitions coincide.
!>
!> Geometry (closest segment, projection point, normal) is taken on the
!> configuration at t(n); the gap is that of the predicted positions at
!> t(n+1) along it, so the constraint on u(n+1) is linear. The predicted
!> surface is not used for the normal: it lacks this step's contact force,
!> and with unequal nodal masses (HRZ lumping of Q8: corner and mid-side
!> nodes) it is wavy by dt^2 f/m, which tilts the end tangents of quadratic
!> segments and would inject spurious tangential forces.
module raccord_node_to_segment
  use raccord_kinds, only: wp, pi
  use raccord_shape, only: shape_line
  use raccord_contact_surface, only: contact_surface_t
  use raccord_contact_verlet, only: verlet_t, verlet_refresh, verlet_candidates
  use raccord_constraint_set, only: constraint_set_t, cs_start, cs_add_row, cs_add_entry, cs_finish_row, cs_reserve, &
    cs_close_row
  use raccord_segment, only: project_on_segment, rotate_ccw, segment_point
  use raccord_mortar_segments, only: outward_normal, normal_field, project_along_field, cross2, NODE_XI
  implicit none
  private

  public :: build_node_to_segment, tributary_lengths, smooth_foot, span_far

  !> Turning angle (radians, as a sine) below which the end segment of an
  !> open master chain is read as straight (smooth_foot): there the cubic
  !> weights do not add up to the segment's consistent loads, and a flat
  !> master's end must keep the plain row for the patch test.
  real(wp), parameter :: END_TURN = 1.0e-3_wp

contains

  !> Constraints of the slave nodes that project on the master within
  !> `reach` of it (gap between -reach and +reach): geometry on positions x
  !> (t(n)), gaps on xpred (predicted t(n+1)), slip on the increments du.
  !> Candidates come from the lists of raccord_contact_verlet; only the
  !> slave nodes with candidates, and the master segments near them, are
  !> visited (the pairs are those of the full search, in the same order).
  subroutine build_node_to_segment(slave, master, x, xpred, du, reach, v, trib, nodal_normal, cand, cs)
    type(contact_surface_t), intent(in) :: slave, master
    real(wp), intent(in) :: x(:,:), xpred(:,:), du(:,:)
    real(wp), intent(in) :: reach
    type(verlet_t), intent(inout) :: v
    real(wp), intent(inout) :: trib(:)           !< (slave%nnode) scratch: tributary lengths
    real(wp), intent(inout) :: nodal_normal(:,:) !< (2, nnode) scratch: master nodal normals
    integer, intent(inout) :: cand(:)            !< (master%nseg) scratch: a node's candidates
    type(constraint_set_t), intent(inout) :: cs
    integer :: i, p, q, k, best, nen, a, tn, ncand
    real(wp) :: xp(2), xs(2, 3), s, foot(2), tang(2), dist, best_dist, best_s, n_m(2), g, sh(3), dsh(3)
    real(wp) :: nn(2, 3), dnf(2), sw(4), xa(2), xb(2), chord(2), bx, by, margin
    integer :: k2, sn(4), t0, gap, tt, q0, qq, e0, ne, f
    logical :: fold
    ! A foot up to 1 % of a segment beyond the end of the master chain still
    ! counts: a slave node that sits at the master's end (a common corner)
    ! projects a hair beyond it as soon as the end segment tilts.
    real(wp), parameter :: eps = 1.0e-9_wp, end_tol = 0.02_wp
    logical :: beyond

    nen = master%nen_seg
    call verlet_refresh(v, x, slave, master, reach)
    ! The nodal normals serve the 3-node segments' normal field only (the
    ! smoothed master of 2-node segments takes its own tangent).
    if (nen /= 2) call master_normals(master, x, v, nodal_normal)
    call tributary_lengths(slave, x, trib, v%snear(1:v%nsnear))
    call cs_start(cs, slave%nnode)
    ! On a closed slave loop, start after the widest gap between near nodes
    ! (cyclically): a contact arc across the loop's first node is then
    ! numbered in one piece and its rows stay banded in the solve. With
    ! every node of the loop near (no gap), number them folded, 1, m, 2,
    ! m - 1, ..., so that the neighbours across the seam are neighbours in
    ! the numbering too (raccord_mortar, assemble_rows).
    t0 = 0
    fold = .false.
    if (slave%closed .and. v%nnear > 1) then
      gap = v%near(1) + slave%nnode - v%near(v%nnear)
      do tt = 2, v%nnear
        if (v%near(tt) - v%near(tt - 1) > gap) then
          gap = v%near(tt) - v%near(tt - 1)
          t0 = tt - 1
        end if
      end do
      fold = gap <= 1
    end if
    near_nodes: do tn = 1, v%nnear
      tt = tn
      if (fold) tt = merge((tn + 1)/2, v%nnear - tn/2 + 1, mod(tn, 2) == 1)
      i = v%near(modulo(tt - 1 + t0, v%nnear) + 1)
      p = slave%node(i)
      xp = x(:, p)
      best = 0
      best_dist = huge(1.0_wp)
      call verlet_candidates(v, i, xp, xp, cand, ncand)
      if (nen == 2) then
        margin = 64.0_wp*epsilon(1.0_wp)*(abs(xp(1)) + abs(xp(2)))
        ! Straight segments: project_on_segment and segment_point written
        ! out (the same sums; no calls per candidate).
        ! The last step's closest segment first (when it is a candidate):
        ! a candidate whose box is farther than the best distance so far
        ! cannot be closer and is passed; ties go to the earlier candidate
        ! (ascending), as in a pass in list order.
        q0 = 0
        do q = 1, ncand
          if (cand(q) == v%warm_seg(i)) q0 = q
        end do
        do qq = 0, ncand
          q = qq
          if (qq == 0) q = q0
          if (q == 0 .or. (qq > 0 .and. qq == q0)) cycle
          k = cand(q)
          xa = x(:, master%seg(1, k))
          xb = x(:, master%seg(2, k))
          if (best > 0) then
            bx = max(min(xa(1), xb(1)) - xp(1), xp(1) - max(xa(1), xb(1)), 0.0_wp)
            by = max(min(xa(2), xb(2)) - xp(2), xp(2) - max(xa(2), xb(2)), 0.0_wp)
            if (bx**2 + by**2 > (best_dist*(1.0_wp + 1.0e-12_wp) + margin)**2) cycle
          end if
          chord = xb - xa
          s = -1.0_wp + 2.0_wp*dot_product(xp - xa, chord)/max(dot_product(chord, chord), tiny(1.0_wp))
          if (abs(s) > 1.0_wp + eps) then
            if (s > 1.0_wp + end_tol .and. k == master%nseg .and. .not. master%closed) cycle
            if (s < -1.0_wp - end_tol .and. k == 1 .and. .not. master%closed) cycle
            s = max(-1.0_wp, min(1.0_wp, s))
          end if
          foot = xa*(0.5_wp*(1.0_wp - s)) + xb*(0.5_wp*(1.0_wp + s))
          dist = sqrt((xp(1) - foot(1))**2 + (xp(2) - foot(2))**2)
          if (dist < best_dist .or. (dist == best_dist .and. k < best)) then
            best_dist = dist
            best = k
          end if
        end do
        if (best == 0) cycle near_nodes
        ! The foot on the smoothed master (see smooth_foot). Warm start:
        ! the node's feet of the last step on the same spans.
        if (v%warm_seg(i) /= best) v%warm_t(:, i) = -1.0_wp
        v%warm_seg(i) = best
        call smooth_foot(master, x, best, xp, sn, sw, n_m, v%warm_t(:, i))
        g = dot_product(xpred(:, p) - (sw(1)*xpred(:, sn(1)) + sw(2)*xpred(:, sn(2)) + sw(3)*xpred(:, sn(3)) + &
          sw(4)*xpred(:, sn(4))), n_m)
        if (g > reach .or. g < -reach) cycle near_nodes
        ! The row written in place (cs_reserve, cs_close_row): the slave
        ! node with weight -1, then each master node of nonzero weight sw
        ! in order, a repeated one merged into its first entry; the entries
        ! and sums the general row (cs_add_entry per node) would give,
        ! without two arrays built per node and their copy (issue #16,
        ! ninth pass).
        call cs_reserve(cs, 5)
        e0 = cs%nent
        ne = 1
        cs%ent_node(e0 + 1) = p
        cs%ent_w(e0 + 1) = -1.0_wp
        entries: do a = 1, 4
          if (sw(a) == 0.0_wp) cycle
          do f = 1, ne
            if (cs%ent_node(e0 + f) == sn(a)) then
              cs%ent_w(e0 + f) = cs%ent_w(e0 + f) + sw(a)
              cycle entries
            end if
          end do
          ne = ne + 1
          cs%ent_node(e0 + ne) = sn(a)
          cs%ent_w(e0 + ne) = sw(a)
        end do entries
        call cs_close_row(cs, i, p, -n_m, trib(i), slave%s0(i), ne, xpred, du)
        cycle near_nodes
      end if
      do q = 1, ncand
        k = cand(q)
        call load_segment(master, x, k, xs)
        ! (The closest segment's tangent is not needed: the normal comes
        ! from smooth_foot or field_foot below.)
        call project_on_segment(nen, xs, xp, s, foot)
        ! A foot beyond the segment's end belongs to the neighbour, or, at
        ! the end of the master chain, to nobody: the node has slid off.
        beyond = abs(s) > 1.0_wp + eps
        if (beyond) then
          if (s > 1.0_wp + end_tol .and. k == master%nseg .and. .not. master%closed) cycle
          if (s < -1.0_wp - end_tol .and. k == 1 .and. .not. master%closed) cycle
          ! Near a vertex between two segments (convex corner): keep the
          ! vertex as the closest point; the neighbour gives the normal too.
          s = max(-1.0_wp, min(1.0_wp, s))
          call segment_point(nen, xs, s, foot, tang)
        end if
        dist = sqrt((xp(1) - foot(1))**2 + (xp(2) - foot(2))**2)
        if (dist < best_dist) then
          best_dist = dist
          best = k
          best_s = s
        end if
      end do
      if (best == 0) cycle near_nodes
      ! Foot and normal from the continuous normal field of the closest
      ! segment; past its end, the neighbour's field takes over.
      k = best
      call field_foot(k, best_s, n_m)
      if (abs(best_s) >= 1.0_wp) then
        k2 = k + merge(1, -1, best_s > 0.0_wp)
        if (master%closed) k2 = modulo(k2 - 1, master%nseg) + 1
        if (k2 >= 1 .and. k2 <= master%nseg) then
          s = best_s
          call field_foot(k2, s, tang)
          if (abs(s) < 1.0_wp) then
            k = k2
            best_s = s
            n_m = tang
          end if
        end if
      end if
      ! At an end of the master chain (the orthogonal test let it in), clip.
      best_s = max(-1.0_wp, min(1.0_wp, best_s))
      best = k
      call load_segment(master, xpred, best, xs)
      call segment_point(nen, xs, best_s, foot, tang)
      g = dot_product(xpred(:, p) - foot, n_m)
      if (g > reach .or. g < -reach) cycle near_nodes
      call cs_add_row(cs, i, p, -n_m, trib(i), slave%s0(i))
      call cs_add_entry(cs, p, -1.0_wp)
      call shape_line(nen, best_s, sh, dsh)
      do a = 1, nen
        call cs_add_entry(cs, master%seg(a, best), sh(a))
      end do
      call cs_finish_row(cs, xpred, du)
    end do near_nodes
  contains
    !> Parameter s on master segment kk whose interpolated normal passes
    !> through the slave node (t(n) geometry), and the unit normal there.
    !> |s| = 1 returned with no root means the node is beyond that end.
    subroutine field_foot(kk, s_out, normal)
      integer, intent(in) :: kk
      real(wp), intent(out) :: s_out, normal(2)
      real(wp) :: xk(2, 3), fx(2), ft(2)
      integer :: aa
      call load_segment(master, x, kk, xk)
      nn = 0.0_wp
      do aa = 1, nen
        nn(:, aa) = nodal_normal(:, master%seg(aa, kk))
      end do
      s_out = project_along_field(nen, xk, nn, xp)
      call normal_field(nen, nn, s_out, normal, dnf)
      normal = normal/max(sqrt(normal(1)**2 + normal(2)**2), tiny(1.0_wp))
      ! A clipped end is a root only if the field there points at the node.
      if (abs(s_out) >= 1.0_wp) then
        call segment_point(nen, xk, s_out, fx, ft)
        if (abs(cross2(xp - fx, normal)) > 1.0e-9_wp*max(norm2(xp - fx), sqrt(ft(1)**2 + ft(2)**2))) &
          s_out = sign(1.0_wp + 1.0e-6_wp, s_out)
      end if
    end subroutine field_foot
  end subroutine build_node_to_segment

  !> Foot of point xp on the smoothed master near its straight segment k
  !> (doc/theory-contact.md, section 4, "Smoothed master"). Each straight
  !> master segment (nodes A, B, t in [0, 1]) is read as the cubic Hermite
  !> curve through A and B whose end tangents are (B - P)/2 and (N - A)/2,
  !> P the node before A and N the node after B (uniform Catmull-Rom):
  !>   C(t) = h00 A + h01 B + h10 (B - P)/2 + h11 (N - A)/2.
  !> The curve runs through every master node, its tangent (so its normal)
  !> is continuous at every node, and it is a fixed affine combination of
  !> four master nodes: the gap row
  !> n . (x_s - sum_a w_a x_a), n the curve's normal at the foot, is the
  !> exact first variation of the distance to the curve (sliding along it
  !> does no work) and follows rigid motions exactly. At an end of an open
  !> chain the missing node is the reflection of the other one about the
  !> end (the end tangent is along the end segment). The closest point is
  !> sought on segment k and its two neighbours. On the end segment of an
  !> open chain, where the chords turn by less than END_TURN/10 from the
  !> segment, the piece is read as the segment itself, with its normal and
  !> its own weights 1 - t and t (blended smoothly into the cubic up to
  !> END_TURN): there the cubic weights do not add up to the segment's
  !> consistent loads, and the plain row passes the patch test on
  !> non-matching meshes with the fine side as slave. Returns the four nodes,
  !> their weights (0 for an unused one) and the outward unit normal, on
  !> the positions x (t(n)).
  !> With `warm` (the span parameters of the last step's call on the same
  !> k, -1 for none) each span's Newton starts there instead of at the
  !> chord projection, and warm returns this call's: the root is the same,
  !> reached in one or two iterations (doc/theory-contact.md, section 4).
  subroutine smooth_foot(master, x, k, xp, nodes, w, normal, warm, full)
    type(contact_surface_t), intent(in) :: master
    real(wp), intent(in) :: x(:,:)
    integer, intent(in) :: k
    real(wp), intent(in) :: xp(2)
    integer, intent(out) :: nodes(4)
    real(wp), intent(out) :: w(4), normal(2)
    real(wp), intent(inout), optional :: warm(3)
    logical, intent(in), optional :: full   !< evaluate all three spans (tests: the skip changes nothing)
    integer :: kk, c, i, nd(4)
    real(wp) :: d, best_d, wt(4), tg(2), tbest(2)
    logical :: skip
    ! Span k first, then k - 1 and k + 1: a neighbour that lies farther
    ! than the distance found so far (span_far) cannot be closer and is
    ! not evaluated (doc/theory-contact.md, section 5, "Smoothed
    ! master"). Ties go to the span earlier along the chain, as when the
    ! three were taken in chain order: k - 1 wins a tie with k, k + 1 none.
    skip = .true.
    if (present(full)) skip = .not. full
    best_d = huge(1.0_wp)
    nodes = master%seg(1, k)
    w = [0.0_wp, 1.0_wp, 0.0_wp, 0.0_wp]
    tbest = 0.0_wp
    do i = 1, 3
      c = merge(0, merge(-1, 1, i == 2), i == 1)
      kk = neighbour_segment(master, k, c)
      if (kk == 0) cycle
      nd = [neighbour_segment(master, kk, -1), master%seg(1, kk), master%seg(2, kk), neighbour_segment(master, kk, 1)]
      if (nd(1) > 0) nd(1) = master%seg(1, nd(1))
      if (nd(4) > 0) nd(4) = master%seg(2, nd(4))
      if (skip .and. c /= 0) then
        if (span_far(x, nd, xp, best_d)) then
          ! Not evaluated: its Newton starts cold when it is next.
          if (present(warm)) warm(c + 2) = -1.0_wp
          cycle
        end if
      end if
      if (present(warm)) then
        call span_closest(x, nd, xp, d, wt, tg, warm(c + 2))
      else
        call span_closest(x, nd, xp, d, wt, tg)
      end if
      if (d < best_d .or. (c == -1 .and. d == best_d)) then
        best_d = d
        nodes = nd
        w = wt
        tbest = tg
      end if
    end do
    normal = [tbest(2), -tbest(1)]/max(norm2(tbest), tiny(1.0_wp))
    where (nodes == 0) nodes = master%seg(1, k)
  end subroutine smooth_foot

  !> The four points P, A, B, N of the Hermite span of nodes nd (P or N 0
  !> when missing: reflected about A or B, P = 2A - B, N = 2B - A).
  pure subroutine span_points(x, nd, xq, xa, xb, xn)
    real(wp), intent(in) :: x(:,:)
    integer, intent(in) :: nd(4)
    real(wp), intent(out) :: xq(2), xa(2), xb(2), xn(2)
    xa = x(:, nd(2))
    xb = x(:, nd(3))
    if (nd(1) > 0) then
      xq = x(:, nd(1))
    else
      xq = 2.0_wp*xa - xb
    end if
    if (nd(4) > 0) then
      xn = x(:, nd(4))
    else
      xn = 2.0_wp*xb - xa
    end if
  end subroutine span_points

  !> Is every point of the Hermite span of nodes nd = (P, A, B, N), as
  !> span_closest reads it (P or N 0: reflected), farther from xp than
  !> dref? In Bezier form the span's control points are A, A + T_A/3,
  !> B - T_B/3, B (T_A = (B - P)/2, T_B = (N - A)/2), and the curve lies
  !> in their convex hull; so do the chord AB and any blend of the two
  !> (span_closest's end segments). The test takes the box that holds the
  !> four points in the frame of the chord (along it, across it), in
  !> coordinates scaled by the chord's length (no root, no division): the
  !> span is far when the box is farther from xp than dref plus a margin
  !> for round-off (squared: 1e-9 of the chord's length squared, and a
  !> few ulps of the coordinates),
  !> and a far span cannot give the closest point.
  pure logical function span_far(x, nd, xp, dref) result(far)
    real(wp), intent(in) :: x(:,:)
    integer, intent(in) :: nd(4)
    real(wp), intent(in) :: xp(2), dref
    real(wp) :: xa(2), xb(2), xq(2), xn(2), b(2, 4), e(2), len2, s, r, smin, smax, rmin, rmax, ds, dr, tol
    integer :: i
    call span_points(x, nd, xq, xa, xb, xn)
    b(:, 1) = xa - xp
    b(:, 2) = xa + (xb - xq)/6.0_wp - xp
    b(:, 3) = xb - (xn - xa)/6.0_wp - xp
    b(:, 4) = xb - xp
    e = xb - xa
    len2 = e(1)**2 + e(2)**2
    smin = huge(1.0_wp)
    smax = -huge(1.0_wp)
    rmin = huge(1.0_wp)
    rmax = -huge(1.0_wp)
    do i = 1, 4
      s = b(1, i)*e(1) + b(2, i)*e(2)
      r = b(2, i)*e(1) - b(1, i)*e(2)
      smin = min(smin, s)
      smax = max(smax, s)
      rmin = min(rmin, r)
      rmax = max(rmax, r)
    end do
    ds = max(smin, -smax, 0.0_wp)
    dr = max(rmin, -rmax, 0.0_wp)
    ! Far: (box distance)^2 > (dref + tol)^2 + 1e-9 len^2, all times len^2
    ! (ds, dr are scaled by len), with a relative 1e-12 more.
    tol = 64.0_wp*epsilon(1.0_wp)*(abs(xp(1)) + abs(xp(2)) + abs(xa(1)) + abs(xa(2)))
    far = len2 > 0.0_wp .and. ds**2 + dr**2 > ((dref + tol)**2 + 1.0e-9_wp*len2)*len2*(1.0_wp + 1.0e-12_wp)
  end function span_far

  !> Segment c = -1 (before), 0 (itself) or +1 (after) segment k along
  !> the master chain; 0 past the end of an open chain.
  pure integer function neighbour_segment(master, k, c) result(kk)
    type(contact_surface_t), intent(in) :: master
    integer, intent(in) :: k, c
    kk = k + c
    if (master%closed) then
      kk = modulo(kk - 1, master%nseg) + 1
    else if (kk < 1 .or. kk > master%nseg) then
      kk = 0
    end if
  end function neighbour_segment

  !> Closest point of xp on the Hermite span of nodes nd = (P, A, B, N)
  !> (P or N 0 when missing: reflected about A or B), by safeguarded Newton
  !> on (C(t) - xp) . C'(t) = 0 over t in [0, 1]: its distance d, the
  !> node weights w and the tangent t there.
  subroutine span_closest(x, nd, xp, d, w, tg, warm)
    real(wp), intent(in) :: x(:,:)
    integer, intent(in) :: nd(4)
    real(wp), intent(in) :: xp(2)
    real(wp), intent(out) :: d, w(4), tg(2)
    real(wp), intent(inout), optional :: warm   !< start parameter (none if outside [0, 1]); returns the foot's
    real(wp) :: xa(2), xb(2), xq(2), xn(2), ba, bb, len, t, tn, f, fp, c(2), c2(2), dbest, tbest, dw(4), phi, turn
    real(wp) :: ta(2), tb(2), p1(2), p2(2), p3(2), q0(2)
    integer :: it
    call span_points(x, nd, xq, xa, xb, xn)
    ba = 0.5_wp
    bb = 0.5_wp
    ! The end segment of an open chain: how much the piece turns (the sines
    ! of the angles of the chords to P and N with the segment). Below
    ! END_TURN/10 it is the segment itself (phi = 0: its weights 1 - t, t
    ! and its normal), above END_TURN the cubic (phi = 1), in between a
    ! smooth blend of the two curves, so that the row does not jump when a
    ! bending master crosses the threshold. Elsewhere always the cubic.
    phi = 1.0_wp
    if (nd(1) == 0 .or. nd(4) == 0) then
      len = norm2(xb - xa)
      turn = max(abs(cross2(xb - xq, xb - xa))/max(norm2(xb - xq)*len, tiny(1.0_wp)), &
        abs(cross2(xn - xa, xb - xa))/max(norm2(xn - xa)*len, tiny(1.0_wp)))
      phi = max(0.0_wp, min(1.0_wp, (turn - 0.1_wp*END_TURN)/(0.9_wp*END_TURN)))
      phi = phi*phi*(3.0_wp - 2.0_wp*phi)
    end if
    ! Start from the projection on the chord.
    t = -1.0_wp
    if (present(warm)) t = warm
    if (.not. (t >= 0.0_wp .and. t <= 1.0_wp)) then
      t = dot_product(xp - xa, xb - xa)/max((xb(1) - xa(1))**2 + (xb(2) - xa(2))**2, tiny(1.0_wp))
      t = max(0.0_wp, min(1.0_wp, t))
    end if
    ! The iteration on the span's power form C(t) = p0 + t (p1 + t (p2 +
    ! t p3)) (the same curve: Hermite basis with the tangents above, blended
    ! with the chord), a quarter of the operations of the nodal weights per
    ! iterate; the weights are taken once, at the root (a round-off
    ! difference in the root from iterating on the weights, as the warm
    ! start's).
    ta = ba*(xb - xq)
    tb = bb*(xn - xa)
    p1 = phi*ta + (1.0_wp - phi)*(xb - xa)
    p2 = phi*(3.0_wp*(xb - xa) - 2.0_wp*ta - tb)
    p3 = phi*(2.0_wp*(xa - xb) + ta + tb)
    q0 = xa - xp
    dbest = huge(1.0_wp)
    tbest = t
    ! Distances compared squared in the iteration (norm2 is a scaled loop
    ! with divisions, a third of the node-to-segment matching).
    do it = 1, 30
      c = q0 + t*(p1 + t*(p2 + t*p3))
      if (c(1)**2 + c(2)**2 < dbest) then
        dbest = c(1)**2 + c(2)**2
        tbest = t
      end if
      tg = p1 + t*(2.0_wp*p2 + 3.0_wp*t*p3)
      c2 = 2.0_wp*p2 + 6.0_wp*t*p3
      f = c(1)*tg(1) + c(2)*tg(2)
      fp = tg(1)**2 + tg(2)**2 + (c(1)*c2(1) + c(2)*c2(2))
      if (fp <= 0.0_wp) fp = tg(1)**2 + tg(2)**2
      tn = max(0.0_wp, min(1.0_wp, t - f/max(fp, tiny(1.0_wp))))
      if (abs(tn - t) <= 1.0e-14_wp) then
        ! Converged: t is the root. The best iterate by distance is kept
        ! only when t is clearly worse (another basin): near the root the
        ! squared distances of the last iterates differ by less than their
        ! round-off, and picking among them left the root up to 1e-8 off,
        ! differently from a warm and a cold start.
        if (c(1)**2 + c(2)**2 <= dbest*(1.0_wp + 1.0e-8_wp)) tbest = t
        exit
      end if
      t = tn
    end do
    ! The node weights, the point and the tangent at the root.
    t = tbest
    call weights(t)
    c = w(1)*xq + w(2)*xa + w(3)*xb + w(4)*xn - xp
    tg = dw(1)*xq + dw(2)*xa + dw(3)*xb + dw(4)*xn
    if (present(warm)) warm = t
    d = norm2(c)
    ! A reflected node moves its weight to its neighbours (2 w to the end, -w to the other).
    if (nd(1) == 0) then
      w(2) = w(2) + 2.0_wp*w(1)
      w(3) = w(3) - w(1)
      w(1) = 0.0_wp
    end if
    if (nd(4) == 0) then
      w(3) = w(3) + 2.0_wp*w(4)
      w(2) = w(2) - w(4)
      w(4) = 0.0_wp
    end if
  contains
    !> Node weights of C(t) and C'(t) (Hermite basis with the tangents above).
    subroutine weights(tt)
      real(wp), intent(in) :: tt
      real(wp) :: h00, h10, h01, h11
      h00 = 2.0_wp*tt**3 - 3.0_wp*tt**2 + 1.0_wp
      h10 = tt**3 - 2.0_wp*tt**2 + tt
      h01 = -2.0_wp*tt**3 + 3.0_wp*tt**2
      h11 = tt**3 - tt**2
      w = [-ba*h10, h00 - bb*h11, h01 + ba*h10, bb*h11]
      h00 = 6.0_wp*tt**2 - 6.0_wp*tt
      h10 = 3.0_wp*tt**2 - 4.0_wp*tt + 1.0_wp
      h01 = -h00
      h11 = 3.0_wp*tt**2 - 2.0_wp*tt
      dw = [-ba*h10, h00 - bb*h11, h01 + ba*h10, bb*h11]
      ! Blend with the segment: C = (1 - phi) chord + phi cubic.
      w = phi*w + (1.0_wp - phi)*[0.0_wp, 1.0_wp - tt, tt, 0.0_wp]
      dw = phi*dw + (1.0_wp - phi)*[0.0_wp, -1.0_wp, 1.0_wp, 0.0_wp]
    end subroutine weights
  end subroutine span_closest

  !> Outward unit normal of the master at its nodes: the mean of the
  !> normals of the segments meeting there (of its segment for a mid node),
  !> summed in chain order. Taken on the listed segments dilated by two
  !> (v%mdil), which is complete at the nodes of the listed segments and
  !> of their neighbours, the ones field_foot reads.
  subroutine master_normals(master, x, v, nodal_normal)
    type(contact_surface_t), intent(in) :: master
    real(wp), intent(in) :: x(:,:)
    type(verlet_t), intent(in) :: v
    real(wp), intent(inout) :: nodal_normal(:,:)
    real(wp) :: xs(2, 3), tn(2)
    integer :: k, a, t
    do t = 1, v%nmdil
      k = v%mdil(t)
      do a = 1, master%nen_seg
        nodal_normal(1, master%seg(a, k)) = 0.0_wp
        nodal_normal(2, master%seg(a, k)) = 0.0_wp
      end do
    end do
    do t = 1, v%nmdil
      k = v%mdil(t)
      call load_segment(master, x, k, xs)
      if (master%nen_seg == 2) then
        ! A straight segment has one normal (outward_normal at either end),
        ! taken once.
        tn = xs(:, 1)*(-0.5_wp) + xs(:, 2)*0.5_wp
        tn = [tn(2), -tn(1)]/max(sqrt(tn(1)**2 + tn(2)**2), tiny(1.0_wp))
        nodal_normal(:, master%seg(1, k)) = nodal_normal(:, master%seg(1, k)) + tn
        nodal_normal(:, master%seg(2, k)) = nodal_normal(:, master%seg(2, k)) + tn
        cycle
      end if
      do a = 1, master%nen_seg
        ! (Through tn: the sum with the function result in one statement
        ! made gfortran allocate a temporary.)
        tn = outward_normal(master%nen_seg, xs, NODE_XI(a))
        nodal_normal(1, master%seg(a, k)) = nodal_normal(1, master%seg(a, k)) + tn(1)
        nodal_normal(2, master%seg(a, k)) = nodal_normal(2, master%seg(a, k)) + tn(2)
      end do
    end do
    ! Normalise each node once: the end and mid nodes of every segment, and
    ! the start node where the chain's previous segment is not in the set
    ! (there it is that segment's end node).
    do t = 1, v%nmdil
      k = v%mdil(t)
      do a = 1, master%nen_seg
        if (a == 1 .and. previous_in_set(t, k)) cycle
        associate (nv => nodal_normal(:, master%seg(a, k)))
          ! along the axis at an axisymmetric surface's axis node (raccord_mortar, slave_normals)
          if (master%axisymmetric) then
            if (x(1, master%seg(a, k)) == 0.0_wp) nv(1) = 0.0_wp
          end if
          nv = nv/max(sqrt(nv(1)**2 + nv(2)**2), tiny(1.0_wp))
        end associate
      end do
    end do
  contains
    logical function previous_in_set(t, k)
      integer, intent(in) :: t, k
      previous_in_set = .false.
      if (t > 1) previous_in_set = v%mdil(t - 1) == k - 1
      if (k == 1 .and. master%closed) previous_in_set = v%mdil(v%nmdil) == master%nseg
    end function previous_in_set
  end subroutine master_normals

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

  !> Length of surface carried by each node: integral of its shape
  !> function along the current surface (half of each neighbouring segment
  !> for 2-node segments; 1/6, 2/3, 1/6 of a straight 3-node one).
  subroutine tributary_lengths(surf, x, trib, segs)
    type(contact_surface_t), intent(in) :: surf
    real(wp), intent(in) :: x(:,:)
    real(wp), intent(inout) :: trib(:)
    integer, intent(in), optional :: segs(:)   !< only these segments (ascending), and their nodes
    real(wp), parameter :: gs(3) = [-0.774596669241483377_wp, 0.0_wp, 0.774596669241483377_wp]
    real(wp), parameter :: gw(3) = [5.0_wp/9.0_wp, 8.0_wp/9.0_wp, 5.0_wp/9.0_wp]
    real(wp) :: xs(2, 3), xx(2), dx(2), sh(3), dsh(3), jac
    integer :: k, g, a, stride, t, nk, p1, p2
    stride = surf%nen_seg - 1
    if (present(segs)) then
      nk = size(segs)
      do t = 1, nk
        do a = 1, surf%nen_seg
          trib(chain_position(surf, segs(t), a, stride)) = 0.0_wp
        end do
      end do
    else
      nk = surf%nseg
      trib(1:surf%nnode) = 0.0_wp
    end if
    do t = 1, nk
      k = t
      if (present(segs)) k = segs(t)
      call load_segment(surf, x, k, xs)
      if (surf%nen_seg == 2 .and. .not. surf%axisymmetric) then
        ! Straight segment, plane: the same sums with the linear shape
        ! functions written out and the constant |dx/ds| (no calls).
        dx = xs(:, 1)*(-0.5_wp) + xs(:, 2)*0.5_wp
        jac = sqrt(dx(1)**2 + dx(2)**2)
        p1 = chain_position(surf, k, 1, stride)
        p2 = chain_position(surf, k, 2, stride)
        do g = 1, 3
          trib(p1) = trib(p1) + 0.5_wp*(1.0_wp - gs(g))*jac*gw(g)
          trib(p2) = trib(p2) + 0.5_wp*(1.0_wp + gs(g))*jac*gw(g)
        end do
        cycle
      end if
      do g = 1, 3
        call segment_point(surf%nen_seg, xs, gs(g), xx, dx)
        call shape_line(surf%nen_seg, gs(g), sh, dsh)
        ! Local node a of segment k sits at chain position stride*(k-1)+1
        ! (start), +stride (end), +1 (mid of a 3-node segment).
        do a = 1, surf%nen_seg
          associate (pos => chain_position(surf, k, a, stride))
            if (surf%axisymmetric) then
              ! the area of the ring the node carries: 2 pi int N_a r ds
              trib(pos) = trib(pos) + sh(a)*sqrt(dx(1)**2 + dx(2)**2)*gw(g)*(2.0_wp*pi*xx(1))
            else
              trib(pos) = trib(pos) + sh(a)*sqrt(dx(1)**2 + dx(2)**2)*gw(g)
            end if
          end associate
        end do
      end do
    end do
  end subroutine tributary_lengths

  pure integer function chain_position(surf, k, a, stride) result(pos)
    type(contact_surface_t), intent(in) :: surf
    integer, intent(in) :: k, a, stride
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
end module raccord_node_to_segment
