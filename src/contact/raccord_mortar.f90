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
!> only the slave segments with candidates are visited: the cost follows!>
!> This module holds the step's driver and the overlap integration (the
!> Gauss loop must stay in the module of its one caller, build_mortar, for
!> gfortran to inline it); the scratch, the step's preparation, the
!> master's ends and the rows are modules of their own
!> (raccord_mortar_work, raccord_mortar_prepare, raccord_mortar_ends,
!> raccord_mortar_rows).
module raccord_mortar
  use raccord_kinds, only: wp, pi
  use raccord_scene, only: MULT_P0, MULT_DUAL
  use raccord_shape, only: shape_line
  use raccord_contact_surface, only: contact_surface_t
  use raccord_contact_verlet, only: verlet_t, verlet_refresh
  use raccord_constraint_set, only: constraint_set_t
  use raccord_segment, only: segment_point
  use raccord_mortar_segments, only: NODE_XI, normal_field, root_along_field, intersect_ray, multiplier_basis, &
    multiplier_breaks
  use raccord_mortar_dual, only: dual_coefficients, dual_basis
  use raccord_mortar_work, only: mortar_work_t, init_mortar, load_segment, grow_entries, XI_COVER
  use raccord_mortar_prepare, only: prepare_step
  use raccord_mortar_ends, only: find_corner_rows, merge_uncovered
  use raccord_mortar_rows, only: assemble_rows
  implicit none
  private

  ! 3-point Gauss-Legendre on [-1, 1]: exact to degree 5 (the integrands are
  ! of degree <= 3 on straight segments; see the theory note).
  real(wp), parameter :: GS(3) = [-0.774596669241483377_wp, 0.0_wp, 0.774596669241483377_wp]
  real(wp), parameter :: GW(3) = [5.0_wp/9.0_wp, 8.0_wp/9.0_wp, 5.0_wp/9.0_wp]
  ! Overlaps narrower than this in the slave parameter are round-off slivers
  ! of coincident ends (matching meshes), not contact.
  real(wp), parameter :: XI_SLIVER = 1.0e-12_wp

  public :: mortar_work_t, init_mortar, build_mortar

contains

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
    integer :: k, a, c, nen, l, t, tn, cprev, side, side0
    real(wp) :: xs(2, 3), nn(2, 3), xi1, xi2, tsgn, xi, flo, fhi, pc(2)

    w%multiplier = multiplier
    nen = slave%nen_seg
    ! Per-entry directions: chosen by the pair's keys (corners on 3-node
    ! slave edges), the buffers sized once at the first step.
    w%dirs = w%corners .and. w%entry_dirs .and. nen == 3
    if (w%dirs .and. .not. allocated(w%g1vec)) then
      allocate(w%g1vec(2, 3, 3, slave%nseg), source=0.0_wp)
      allocate(w%ment_v(2, size(w%ment_node)))
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
      ! ends lies on (root_along_field's test, once per segment: the corner
      ! projection below decides those corners without the call).
      tsgn = sign(1.0_wp, (xs(1, 2) - xs(1, 1))*(nn(2, 1) + nn(2, 2)) - (xs(2, 2) - xs(2, 1))*(nn(1, 1) + nn(1, 2)))
      cprev = 0
      do t = w%cbeg(tn), w%cend(tn)
        l = w%cbuf(t)
        ! Segmentation (method brief section 5): the master ends seen from
        ! the slave along its normal field, each corner projected once per
        ! slave segment. The list is ascending: a candidate that follows
        ! its chain neighbour starts at the corner that one ended at (the
        ! value the corner cache below holds, without recomputing it).
        ! (cprev: the last candidate's end corner, 0 before the first.)
        side0 = 1
        if (w%mcorner(1, l) == cprev) then
          xi1 = xi2
          side0 = 2
        end if
        ! The slave parameter xi of master corner c on slave segment k (xs,
        ! nn): the root of project_along_field, computed once per (k, c).
        ! Its end values F(-1), F(+1) are those of the slave nodes; F at
        ! the start node of k is the end value the corner had on segment
        ! k - 1 when it was seen there. (Written once, here: as an internal
        ! function, called twice, gfortran did not inline it, and the call
        ! and its host-frame loads were about 100 instructions per corner,
        ! 209 corners per step on Fig. 2(a); doc/performance.md, eighth pass.)
        do side = side0, 2
          c = w%mcorner(side, l)
          if (w%xi_seg(c) == k) then
            xi = w%xi_val(c)
          else
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
            ! (flo, fhi finite: x passed the state guard, nn are unit.)
            if ((flo > 0.0_wp .and. fhi > 0.0_wp) .or. (flo < 0.0_wp .and. fhi < 0.0_wp)) then
              ! No root inside: past the end root_along_field picks (the same
              ! test, written out; most corners of the candidates are such).
              ! Both nonzero and of one sign, as sign(1, flo) == sign(1, fhi)
              ! with both /= 0 tested; tsgn is +1 or -1 (ninth pass: the
              ! sign() form took two more compares and the bit masks).
              xi = merge(1.0_wp, -1.0_wp, (flo > 0.0_wp) .eqv. (tsgn > 0.0_wp))
            else
              xi = root_along_field(nen, xs, nn, pc, flo, fhi)
            end if
            w%xi_seg(c) = k
            w%xi_val(c) = xi
          end if
          if (side == 1) then
            xi1 = xi
          else
            xi2 = xi
          end if
        end do
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
  end subroutine build_mortar

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
    ! Room for the overlap's (at most four) entries, checked once.
    do while (w%nment + 4 > size(w%ment_node))
      call grow_entries(w)
    end do
    do b = 1, 2
      do a = 1, 2
        if (mloc(a, b) == 0.0_wp) cycle
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
end module raccord_mortar
