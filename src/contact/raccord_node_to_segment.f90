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
  use raccord_contact_verlet, only: verlet_t, verlet_refresh, verlet_overlaps
  use raccord_constraint_set, only: constraint_set_t, cs_start, cs_add_row, cs_add_entry, cs_finish_row
  use raccord_segment, only: project_on_segment, rotate_ccw, segment_point
  use raccord_mortar_segments, only: outward_normal, normal_field, project_along_field, cross2, NODE_XI
  implicit none
  private

  public :: build_node_to_segment, tributary_lengths

contains

  !> Constraints of the slave nodes that project on the master within
  !> `reach` of it (gap between -reach and +reach): geometry on positions x
  !> (t(n)), gaps on xpred (predicted t(n+1)), slip on the increments du.
  !> Candidates come from the lists of raccord_contact_verlet; only the
  !> slave nodes with candidates, and the master segments near them, are
  !> visited (the pairs are those of the full search, in the same order).
  subroutine build_node_to_segment(slave, master, x, xpred, du, reach, v, trib, nodal_normal, cs)
    type(contact_surface_t), intent(in) :: slave, master
    real(wp), intent(in) :: x(:,:), xpred(:,:), du(:,:)
    real(wp), intent(in) :: reach
    type(verlet_t), intent(inout) :: v
    real(wp), intent(inout) :: trib(:)           !< (slave%nnode) scratch: tributary lengths
    real(wp), intent(inout) :: nodal_normal(:,:) !< (2, nnode) scratch: master nodal normals
    type(constraint_set_t), intent(inout) :: cs
    integer :: i, p, q, k, best, nen, a, tn
    real(wp) :: xp(2), xs(2, 3), s, foot(2), tang(2), dist, best_dist, best_s, best_t(2), n_m(2), g, sh(3), dsh(3)
    real(wp) :: nn(2, 3), dnf(2)
    integer :: k2
    ! A foot up to 1 % of a segment beyond the end of the master chain still
    ! counts: a slave node that sits at the master's end (a common corner)
    ! projects a hair beyond it as soon as the end segment tilts.
    real(wp), parameter :: eps = 1.0e-9_wp, end_tol = 0.02_wp
    logical :: beyond

    nen = master%nen_seg
    call verlet_refresh(v, x, slave, master, reach)
    call master_normals(master, x, v, nodal_normal)
    call tributary_lengths(slave, x, trib, v%snear(1:v%nsnear))
    call cs_start(cs, slave%nnode)
    near_nodes: do tn = 1, v%nnear
      i = v%near(tn)
      p = slave%node(i)
      xp = x(:, p)
      best = 0
      best_dist = huge(1.0_wp)
      do q = v%ptr(i), v%ptr(i + 1) - 1
        k = v%item(q)
        if (.not. verlet_overlaps(v, k, xp, xp)) cycle
        call load_segment(master, x, k, xs)
        call project_on_segment(nen, xs, xp, s, foot, tang)
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
          tang = tang/sqrt(tang(1)**2 + tang(2)**2)
        end if
        dist = sqrt((xp(1) - foot(1))**2 + (xp(2) - foot(2))**2)
        if (dist < best_dist) then
          best_dist = dist
          best = k
          best_s = s
          best_t = tang
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
    real(wp) :: xs(2, 3)
    integer :: k, a, t
    do t = 1, v%nmdil
      k = v%mdil(t)
      do a = 1, master%nen_seg
        nodal_normal(:, master%seg(a, k)) = 0.0_wp
      end do
    end do
    do t = 1, v%nmdil
      k = v%mdil(t)
      call load_segment(master, x, k, xs)
      do a = 1, master%nen_seg
        nodal_normal(:, master%seg(a, k)) = nodal_normal(:, master%seg(a, k)) + &
          outward_normal(master%nen_seg, xs, NODE_XI(a))
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
    real(wp) :: xs(2, 3), xx(2), dx(2), sh(3), dsh(3)
    integer :: k, g, a, stride, t, nk
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
