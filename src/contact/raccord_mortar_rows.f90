!> The mortar constraint rows (raccord_mortar): from the step's
!> per-segment integrals G1 and G21 (and the corner rows), one row per
!> slave chain node whose multiplier meets the master, in chain order (a
!> closed loop from its longest free run, or folded), each written whole
!> into the constraint set with its weighted gap and slip, and the band of
!> G1 between the constraints (paper (15)-(19); doc/theory-contact-mortar.md
!> section 2; raccord_constraint_set).
module raccord_mortar_rows
  use raccord_kinds, only: wp, pi
  use raccord_scene, only: MULT_DUAL
  use raccord_shape, only: shape_line
  use raccord_contact_surface, only: contact_surface_t
  use raccord_contact_verlet, only: verlet_t
  use raccord_constraint_set, only: constraint_set_t, cs_start, cs_add_row, cs_add_entry, cs_finish_row, cs_reserve, &
    cs_close_row, G1_MAX_BAND
  use raccord_mortar_work, only: mortar_work_t
  implicit none
  private

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

  public :: assemble_rows

contains

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
    integer :: c, m, j, t, k, b, ai, i, d, e, band, nen, cfirst, npos, q, run, best, c0, nr, pn, sl, e0, nbound
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
    ! The rows are written in place in the constraint set (cs_close_row):
    ! room for all of them first. A near segment adds to the rows of its
    ! nen nodes at most its nen slave entries and its master entries.
    nbound = 0
    do t = 1, vl%nnear
      k = vl%near(t)
      nbound = nbound + nen*(nen + max(w%mend(k) - w%mbeg(k) + 1, 0))
    end do
    call cs_reserve(cs, nbound)
    band = 0
    do q = 1, npos
      c = at(q)
      j = w%cidx(c)
      if (j > 0) then
        ! The row's entries merged through w%slot in the order of their
        ! first contribution, the weights summed in contribution order (as
        ! cs_add_entry did with a search per entry), written straight into
        ! the constraint set's storage after its last entry (e0): entry sl
        ! of the row is cs entry e0 + sl.
        e0 = cs%nent
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
                cs%ent_w(e0 + sl) = cs%ent_w(e0 + sl) - v
              else
                nr = nr + 1
                cs%ent_node(e0 + nr) = pn
                cs%ent_w(e0 + nr) = -v
                w%slot(pn) = nr
                sl = nr
                if (w%dirs) cs%ent_v(:, e0 + sl) = 0.0_wp
              end if
              ! W_ij = -int N_i psi_j nu dGamma on slave nodes
              if (w%dirs) cs%ent_v(:, e0 + sl) = cs%ent_v(:, e0 + sl) - w%g1vec(:, ai, b, k)
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
              cs%ent_w(e0 + sl) = cs%ent_w(e0 + sl) + w%ment_w(e)
            else
              nr = nr + 1
              cs%ent_node(e0 + nr) = pn
              cs%ent_w(e0 + nr) = w%ment_w(e)
              w%slot(pn) = nr
              sl = nr
              if (w%dirs) cs%ent_v(:, e0 + sl) = 0.0_wp
            end if
            ! W_aj = +int N_a psi_j nu dGamma on master nodes
            if (w%dirs) cs%ent_v(:, e0 + sl) = cs%ent_v(:, e0 + sl) + w%ment_v(:, e)
          end do
        end do
        ! (dirs: each entry along its own vector weight, the row's normal
        ! kept for the row's outputs only.)
        if (w%weighted .and. .not. w%dirs) then
          call cs_close_row(cs, c, slave%node(c), row_normal(c), w%trib(c), slave%s0(c), nr, xpred, du)
        else
          call cs_close_row(cs, c, slave%node(c), w%nrm(:, c), w%trib(c), slave%s0(c), nr, xpred, du)
        end if
        cs%g1(:, j) = g1col
        do e = e0 + 1, e0 + nr
          w%slot(cs%ent_node(e)) = 0
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
    cs%tcorners = w%tcorners .and. nen == 3 .and. .not. w%corners
    if (cs%tcorners) call tangential_map()
  contains
    !> Tangential corner multipliers: for each mid row the rows of its
    !> edge's two corners (cs%tcor; 0 where a corner has no row), for each
    !> corner row the mid rows that take half of its value (cs%tmid); every
    !> other row (corners, master corner rows) owns its tangential unknown
    !> (tcor(1, j) = -1). Grow-only storage.
    subroutine tangential_map()
      integer :: jm, s, a, tt, kk
      if (allocated(cs%tcor)) then
        if (size(cs%tcor, 2) < size(cs%snode)) deallocate(cs%tcor, cs%tmid)
      end if
      if (.not. allocated(cs%tcor)) allocate(cs%tcor(2, size(cs%snode)), cs%tmid(2, size(cs%snode)))
      cs%tcor(1, 1:cs%m) = -1
      cs%tcor(2, 1:cs%m) = 0
      cs%tmid(:, 1:cs%m) = 0
      do tt = 1, vl%nnear
        kk = vl%near(tt)
        jm = w%cidx(w%pos(3, kk))
        if (jm <= 0) cycle
        cs%tcor(1, jm) = w%cidx(w%pos(1, kk))
        cs%tcor(2, jm) = w%cidx(w%pos(2, kk))
        do s = 1, 2
          a = cs%tcor(s, jm)
          if (a <= 0) cycle
          if (cs%tmid(1, a) == 0) then
            cs%tmid(1, a) = jm
          else
            cs%tmid(2, a) = jm
          end if
        end do
      end do
    end subroutine tangential_map

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
end module raccord_mortar_rows
