!> The Delassus matrix K = B M^-1 B' of a constraint set, in band form
!> (blocks Knn, Knt, Ktn, Ktt in the solver's workspace), that every form
!> of the multiplier solve is built from (doc/theory-contact.md, section 3).
module raccord_delassus
  use raccord_kinds, only: wp
  use raccord_constraint_set, only: constraint_set_t
  use raccord_solver_work, only: solver_work_t, ensure_work, ensure_band, ensure_i
  use raccord_band_solver, only: zero_band
  implicit none
  private

  public :: delassus

contains

  !> K = B M^-1 B' in band form, accumulated node by node:
  !> K(j, k) += w_jp w_kp n_j . (M_p^-1 n_k) for every node p the rows share.
  !> A force f at t(n) moves u(n+1) by dt^2 (h/dt) M^-1 f / (1 + alpha h/2):
  !> (CD-1) with its semi-implicit damping, and the half first step.
  !> The rows touching each node are listed with their weights (node_row,
  !> node_w), and the sums run in pair_sums_normal / _friction on
  !> explicit-shape arrays (issue #16, fifth pass: the same products in the
  !> same order, without the workspace's descriptors in the inner loop).
  subroutine delassus(cs, minv, alpha, h_ratio, h, friction, w)
    type(constraint_set_t), intent(in) :: cs
    real(wp), intent(in) :: minv(:,:), alpha(:), h_ratio, h
    logical, intent(in) :: friction
    type(solver_work_t), intent(inout) :: w
    integer :: m, nn, ntouched, kbs, ncap
    m = cs%m
    nn = size(minv, 2)
    call ensure_work(w, m, nn, cs%nent, cs%entry_dirs)
    if (same_structure(cs, w)) then
      ! The rows name the same nodes in the same order as at the last
      ! build: the lists, their order and kb stand, only the weights are
      ! this step's (issue #16, seventh pass: the lists were about 30 % of
      ! the Delassus product, rebuilt every step).
      call gather_weights(cs, w)
      w%lists_kept = w%lists_kept + 1
    else
      call build_node_lists(cs, w)
      w%lists_built = w%lists_built + 1
    end if
    ntouched = w%list_ntouched
    w%kb = w%list_kb
    call ensure_band(w%knn, w%kb, m)
    call ensure_band(w%knt, w%kb, m)
    call ensure_band(w%ktn, w%kb, m)
    call ensure_band(w%ktt, w%kb, m)
    kbs = ubound(w%knn, 1)
    ncap = size(w%knn, 2)
    if (cs%entry_dirs) then
      call pair_sums_vectors(m, kbs, ncap, nn, cs%nent, ntouched, w%touched(1:ntouched), &
        w%node_ptr, w%node_last, w%node_row(1:cs%nent), w%node_v(:, 1:cs%nent), minv, alpha, h_ratio, h, &
        friction, w%knn, w%knt, w%ktn, w%ktt)
    else if (friction) then
      call pair_sums_friction(m, kbs, ncap, nn, cs%nent, ntouched, w%touched(1:ntouched), &
        w%node_ptr, w%node_last, w%node_row(1:cs%nent), w%node_w(1:cs%nent), &
        cs%normal(:, 1:m), cs%tangent(:, 1:m), minv, alpha, h_ratio, h, w%knn, w%knt, w%ktn, w%ktt)
    else
      call pair_sums_normal(m, kbs, ncap, nn, cs%nent, ntouched, w%touched(1:ntouched), &
        w%node_ptr, w%node_last, w%node_row(1:cs%nent), w%node_w(1:cs%nent), &
        cs%normal(:, 1:m), minv, alpha, h_ratio, h, w%knn)
    end if
  end subroutine delassus

  !> The rows of cs name the nodes the node lists were last built from, in
  !> the same order (row_ptr and ent_node as then, the same kind of
  !> weights): build_node_lists would give the same lists.
  logical function same_structure(cs, w) result(same)
    type(constraint_set_t), intent(in) :: cs
    type(solver_work_t), intent(in) :: w
    integer :: j, e
    same = .false.
    if (cs%m /= w%list_m .or. cs%nent /= w%list_nent) return
    if (cs%entry_dirs .neqv. w%list_dirs) return
    do j = 1, cs%m + 1
      if (cs%row_ptr(j) /= w%list_row_ptr(j)) return
    end do
    do e = 1, cs%nent
      if (cs%ent_node(e) /= w%list_node(e)) return
    end do
    same = .true.
  end function same_structure

  !> This step's weights into the kept lists: position pos holds entry
  !> list_ent(pos), where build_node_lists placed it.
  subroutine gather_weights(cs, w)
    type(constraint_set_t), intent(in) :: cs
    type(solver_work_t), intent(inout) :: w
    integer :: pos, e
    do pos = 1, cs%nent
      w%node_w(pos) = cs%ent_w(w%list_ent(pos))
    end do
    if (cs%entry_dirs) then
      do pos = 1, cs%nent
        e = w%list_ent(pos)
        w%node_v(1, pos) = cs%ent_v(1, e)
        w%node_v(2, pos) = cs%ent_v(2, e)
      end do
    end if
  end subroutine gather_weights

  !> The rows touching each node, as CSR over the touched nodes (node p's
  !> rows at node_ptr(p) .. node_last(p) - 1 of node_row, with their
  !> weights node_w / node_v, in increasing row order), the half band kb
  !> they imply, and the structure they were built from (same_structure;
  !> list_ent for gather_weights).
  subroutine build_node_lists(cs, w)
    type(constraint_set_t), intent(in) :: cs
    type(solver_work_t), intent(inout) :: w
    integer :: m, j, e, p, ntouched, t, pos
    m = cs%m
    call ensure_i(w%list_ent, cs%nent)
    call ensure_i(w%list_node, cs%nent)
    call ensure_i(w%list_row_ptr, m + 1)
    ! Rows touching each node, and the band width they imply.
    ntouched = 0
    do e = 1, cs%nent
      p = cs%ent_node(e)
      if (w%node_first(p) == 0) then
        ntouched = ntouched + 1
        w%touched(ntouched) = p
        w%node_ptr(p) = 0
      end if
      w%node_ptr(p) = w%node_ptr(p) + 1
      w%node_first(p) = 1
    end do
    ! CSR offsets over touched nodes (node_last holds the fill position).
    pos = 1
    do t = 1, ntouched
      p = w%touched(t)
      w%node_last(p) = pos
      pos = pos + w%node_ptr(p)
      w%node_ptr(p) = w%node_last(p)
    end do
    do j = 1, m
      do e = cs%row_ptr(j), cs%row_ptr(j + 1) - 1
        p = cs%ent_node(e)
        pos = w%node_last(p)
        w%node_row(pos) = j
        w%list_ent(pos) = e
        w%node_last(p) = pos + 1
      end do
    end do
    ! the weights (and, with cs%entry_dirs, the vector weights) in the
    ! positions just placed, as on the steps that keep the lists
    call gather_weights(cs, w)
    ! A node's rows are listed in increasing order (filled row by row).
    w%kb = 0
    do t = 1, ntouched
      p = w%touched(t)
      w%kb = max(w%kb, w%node_row(w%node_last(p) - 1) - w%node_row(w%node_ptr(p)))
    end do
    w%kb = min(w%kb, m)
    ! Reset the per-node marks for the next build (touched nodes only).
    do t = 1, ntouched
      w%node_first(w%touched(t)) = 0
    end do
    w%list_row_ptr(1:m + 1) = cs%row_ptr(1:m + 1)
    w%list_node(1:cs%nent) = cs%ent_node(1:cs%nent)
    w%list_m = m
    w%list_nent = cs%nent
    w%list_dirs = cs%entry_dirs
    w%list_ntouched = ntouched
    w%list_kb = w%kb
  end subroutine build_node_lists

  !> Knn of delassus, the band zeroed over its whole height (one contiguous
  !> block; only the rows -kb:kb are read). Stored as k(jb - ja, ja) =
  !> K(ja, jb). Both orders of a pair are summed as written, each with its
  !> own products (w_a w_b (n_a M^-1) . n_b and w_b w_a (n_b M^-1) . n_a,
  !> as the loop over ordered pairs computed them), in one pass over the
  !> unordered pairs: copying the mirror entry instead, symmetric only to
  !> round-off, moved the active set of test_curved's mortar P0 case
  !> (doc/theory-contact.md, section 3). The rows of a node are listed in
  !> increasing order, so d = jb - ja > 0 for b after a.
  subroutine pair_sums_normal(m, kbs, ncap, nn, nent, ntouched, touched, node_ptr, node_last, &
      node_row, node_w, normal, minv, alpha, h_ratio, h, knn)
    integer, intent(in) :: m, kbs, ncap, nn, nent, ntouched
    integer, intent(in) :: touched(ntouched), node_ptr(:), node_last(:), node_row(nent)
    real(wp), intent(in) :: node_w(nent), normal(2, m), minv(2, nn), alpha(nn), h_ratio, h
    real(wp), intent(inout) :: knn(-kbs:kbs, ncap)
    integer :: t, p, a, b, ja, jb, d
    real(wp) :: mi(2), wa, wab, na1, na2, xa1, xa2, nb1, nb2, xb1, xb2, s
    call zero_band((2*kbs + 1)*m, knn)
    do t = 1, ntouched
      p = touched(t)
      mi = h_ratio/(1.0_wp + 0.5_wp*alpha(p)*h)*minv(:, p)
      do a = node_ptr(p), node_last(p) - 1
        ja = node_row(a)
        wa = node_w(a)
        na1 = normal(1, ja)
        na2 = normal(2, ja)
        xa1 = na1*mi(1)
        xa2 = na2*mi(2)
        s = xa1*na1
        s = s + xa2*na2
        knn(0, ja) = knn(0, ja) + (wa*wa)*s
        do b = a + 1, node_last(p) - 1
          jb = node_row(b)
          d = jb - ja
          wab = wa*node_w(b)
          nb1 = normal(1, jb)
          nb2 = normal(2, jb)
          xb1 = nb1*mi(1)
          xb2 = nb2*mi(2)
          s = xa1*nb1
          s = s + xa2*nb2
          knn(d, ja) = knn(d, ja) + wab*s
          s = xb1*na1
          s = s + xb2*na2
          knn(-d, jb) = knn(-d, jb) + wab*s
        end do
      end do
    end do
  end subroutine pair_sums_normal

  !> The four blocks of delassus (n and t of each row). Knn as
  !> pair_sums_normal (both orders of a pair with their own products, bit
  !> for bit the frictionless Knn); Knt, Ktn and Ktt summed for one order of
  !> each pair (d = jb - ja > 0) and mirrored after the loop: K is
  !> symmetric, Ktt(jb, ja) = Ktt(ja, jb) and Knt(jb, ja) = t_a M^-1 n_b =
  !> Ktn(ja, jb) (issue #16, sixth pass: three of the eight products and
  !> read-modify-writes of a pair saved; the tangential blocks are now
  !> exactly symmetric instead of to round-off).
  subroutine pair_sums_friction(m, kbs, ncap, nn, nent, ntouched, touched, node_ptr, node_last, &
      node_row, node_w, normal, tangent, minv, alpha, h_ratio, h, knn, knt, ktn, ktt)
    integer, intent(in) :: m, kbs, ncap, nn, nent, ntouched
    integer, intent(in) :: touched(ntouched), node_ptr(:), node_last(:), node_row(nent)
    real(wp), intent(in) :: node_w(nent), normal(2, m), tangent(2, m), minv(2, nn), alpha(nn), h_ratio, h
    real(wp), intent(inout) :: knn(-kbs:kbs, ncap), knt(-kbs:kbs, ncap)
    real(wp), intent(inout) :: ktn(-kbs:kbs, ncap), ktt(-kbs:kbs, ncap)
    integer :: t, p, a, b, ja, jb, d
    real(wp) :: mi(2), wa, wab, s
    real(wp) :: na1, na2, ta1, ta2, xa1, xa2, ya1, ya2, nb1, nb2, tb1, tb2, xb1, xb2
    ! Each block zeroed whole, in one pass (zero_band; issue #16, eighth
    ! pass): the summed upper halves must start at zero; the lower halves
    ! of the tangential blocks (d < 0) are written whole by the mirror
    ! below over every entry a form reads, so zeroing them too changes no
    ! value, and it spares the one memset call per column that the
    ! upper-half sections cost.
    call zero_band((2*kbs + 1)*m, knn)
    call zero_band((2*kbs + 1)*m, knt)
    call zero_band((2*kbs + 1)*m, ktn)
    call zero_band((2*kbs + 1)*m, ktt)
    do t = 1, ntouched
      p = touched(t)
      mi = h_ratio/(1.0_wp + 0.5_wp*alpha(p)*h)*minv(:, p)
      do a = node_ptr(p), node_last(p) - 1
        ja = node_row(a)
        wa = node_w(a)
        na1 = normal(1, ja)
        na2 = normal(2, ja)
        ta1 = tangent(1, ja)
        ta2 = tangent(2, ja)
        xa1 = na1*mi(1)        ! (n_a M^-1), (t_a M^-1)
        xa2 = na2*mi(2)
        ya1 = ta1*mi(1)
        ya2 = ta2*mi(2)
        wab = wa*wa
        s = xa1*na1
        s = s + xa2*na2
        knn(0, ja) = knn(0, ja) + wab*s
        s = xa1*ta1
        s = s + xa2*ta2
        knt(0, ja) = knt(0, ja) + wab*s
        s = ya1*na1
        s = s + ya2*na2
        ktn(0, ja) = ktn(0, ja) + wab*s
        s = ya1*ta1
        s = s + ya2*ta2
        ktt(0, ja) = ktt(0, ja) + wab*s
        do b = a + 1, node_last(p) - 1
          jb = node_row(b)
          d = jb - ja
          wab = wa*node_w(b)
          nb1 = normal(1, jb)
          nb2 = normal(2, jb)
          tb1 = tangent(1, jb)
          tb2 = tangent(2, jb)
          xb1 = nb1*mi(1)
          xb2 = nb2*mi(2)
          ! K(ja, jb)
          s = xa1*nb1
          s = s + xa2*nb2
          knn(d, ja) = knn(d, ja) + wab*s
          s = xa1*tb1
          s = s + xa2*tb2
          knt(d, ja) = knt(d, ja) + wab*s
          s = ya1*nb1
          s = s + ya2*nb2
          ktn(d, ja) = ktn(d, ja) + wab*s
          s = ya1*tb1
          s = s + ya2*tb2
          ktt(d, ja) = ktt(d, ja) + wab*s
          ! Knn(jb, ja), its own products
          s = xb1*na1
          s = s + xb2*na2
          knn(-d, jb) = knn(-d, jb) + wab*s
        end do
      end do
    end do
    ! The mirror of the tangential blocks: K(ja + d, ja) from K(ja, ja + d).
    do ja = 1, m - 1
      do d = 1, min(kbs, m - ja)
        knt(-d, ja + d) = ktn(d, ja)
        ktn(-d, ja + d) = knt(d, ja)
        ktt(-d, ja + d) = ktt(d, ja)
      end do
    end do
  end subroutine pair_sums_friction

  !> delassus for entries with their own vector weights W (cs%entry_dirs):
  !> K_nn(j, k) += W_jp . (M_p^-1 W_kp), K_nt(j, k) += W_jp . (M_p^-1 W^perp_kp),
  !> and so on, W^perp = W turned clockwise (raccord_constraint_set); the
  !> tangential blocks with friction only. Both orders of a pair with
  !> their own products, as pair_sums_normal.
  subroutine pair_sums_vectors(m, kbs, ncap, nn, nent, ntouched, touched, node_ptr, node_last, &
      node_row, node_v, minv, alpha, h_ratio, h, friction, knn, knt, ktn, ktt)
    integer, intent(in) :: m, kbs, ncap, nn, nent, ntouched
    integer, intent(in) :: touched(ntouched), node_ptr(:), node_last(:), node_row(nent)
    real(wp), intent(in) :: node_v(2, nent), minv(2, nn), alpha(nn), h_ratio, h
    logical, intent(in) :: friction
    real(wp), intent(inout) :: knn(-kbs:kbs, ncap), knt(-kbs:kbs, ncap)
    real(wp), intent(inout) :: ktn(-kbs:kbs, ncap), ktt(-kbs:kbs, ncap)
    integer :: t, p, a, b, ja, jb, d
    real(wp) :: mi(2), na(2), ta(2), nb(2), tb(2), xa(2), ya(2), xb(2), yb(2)
    call zero_band((2*kbs + 1)*m, knn)
    if (friction) then
      call zero_band((2*kbs + 1)*m, knt)
      call zero_band((2*kbs + 1)*m, ktn)
      call zero_band((2*kbs + 1)*m, ktt)
    end if
    do t = 1, ntouched
      p = touched(t)
      mi = h_ratio/(1.0_wp + 0.5_wp*alpha(p)*h)*minv(:, p)
      do a = node_ptr(p), node_last(p) - 1
        ja = node_row(a)
        na = node_v(:, a)
        ta = [na(2), -na(1)]
        xa = na*mi                 ! W_a M^-1, W^perp_a M^-1
        ya = ta*mi
        knn(0, ja) = knn(0, ja) + (xa(1)*na(1) + xa(2)*na(2))
        if (friction) then
          knt(0, ja) = knt(0, ja) + (xa(1)*ta(1) + xa(2)*ta(2))
          ktn(0, ja) = ktn(0, ja) + (ya(1)*na(1) + ya(2)*na(2))
          ktt(0, ja) = ktt(0, ja) + (ya(1)*ta(1) + ya(2)*ta(2))
        end if
        do b = a + 1, node_last(p) - 1
          jb = node_row(b)
          d = jb - ja
          nb = node_v(:, b)
          tb = [nb(2), -nb(1)]
          xb = nb*mi
          yb = tb*mi
          knn(d, ja) = knn(d, ja) + (xa(1)*nb(1) + xa(2)*nb(2))
          knn(-d, jb) = knn(-d, jb) + (xb(1)*na(1) + xb(2)*na(2))
          if (friction) then
            knt(d, ja) = knt(d, ja) + (xa(1)*tb(1) + xa(2)*tb(2))
            ktn(d, ja) = ktn(d, ja) + (ya(1)*nb(1) + ya(2)*nb(2))
            ktt(d, ja) = ktt(d, ja) + (ya(1)*tb(1) + ya(2)*tb(2))
            knt(-d, jb) = knt(-d, jb) + (xb(1)*ta(1) + xb(2)*ta(2))
            ktn(-d, jb) = ktn(-d, jb) + (yb(1)*na(1) + yb(2)*na(2))
            ktt(-d, jb) = ktt(-d, jb) + (yb(1)*ta(1) + yb(2)*ta(2))
          end if
        end do
      end do
    end do
  end subroutine pair_sums_vectors
end module raccord_delassus
