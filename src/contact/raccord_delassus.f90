!> The Delassus matrix K = B M^-1 B' of a constraint set, in band form
!> (blocks Knn, Knt, Ktn, Ktt in the solver's workspace), that every form
!> of the multiplier solve is built from (doc/theory-contact.md, section 3).
module raccord_delassus
  use raccord_kinds, only: wp
  use raccord_constraint_set, only: constraint_set_t
  use raccord_solver_work, only: solver_work_t, ensure_work, ensure_band
  implicit none
  private

  public :: delassus

contains

  !> K = B M^-1 B' in band form, accumulated node by node:
  !> K(j, k) += w_jp w_kp n_j . (M_p^-1 n_k) for every node p the rows share.
  !> A force f at t(n) moves u(n+1) by dt^2 (h/dt) M^-1 f / (1 + alpha h/2):
  !> (CD-1) with its semi-implicit damping, and the half first step.
  subroutine delassus(cs, minv, alpha, h_ratio, h, friction, w)
    type(constraint_set_t), intent(in) :: cs
    real(wp), intent(in) :: minv(:,:), alpha(:), h_ratio, h
    logical, intent(in) :: friction
    type(solver_work_t), intent(inout) :: w
    integer :: m, j, e, p, nn, a, b, ja, jb, ea, eb, ntouched, t, pos
    real(wp) :: wa, wb, mi(2)
    m = cs%m
    nn = size(minv, 2)
    call ensure_work(w, m, nn, cs%nent)
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
        w%node_row(w%node_last(p)) = j
        w%node_ent(w%node_last(p)) = e
        w%node_last(p) = w%node_last(p) + 1
      end do
    end do
    ! A node's rows are listed in increasing order (filled row by row).
    w%kb = 0
    do t = 1, ntouched
      p = w%touched(t)
      w%kb = max(w%kb, w%node_row(w%node_last(p) - 1) - w%node_row(w%node_ptr(p)))
    end do
    w%kb = min(w%kb, m)
    call ensure_band(w%knn, w%kb, m)
    call ensure_band(w%knt, w%kb, m)
    call ensure_band(w%ktn, w%kb, m)
    call ensure_band(w%ktt, w%kb, m)
    w%knn(-w%kb:w%kb, 1:m) = 0.0_wp
    if (friction) then
      w%knt(-w%kb:w%kb, 1:m) = 0.0_wp
      w%ktn(-w%kb:w%kb, 1:m) = 0.0_wp
      w%ktt(-w%kb:w%kb, 1:m) = 0.0_wp
    end if
    do t = 1, ntouched
      p = w%touched(t)
      mi = h_ratio/(1.0_wp + 0.5_wp*alpha(p)*h)*minv(:, p)
      do a = w%node_ptr(p), w%node_last(p) - 1
        ja = w%node_row(a)
        ea = w%node_ent(a)
        wa = cs%ent_w(ea)
        do b = w%node_ptr(p), w%node_last(p) - 1
          jb = w%node_row(b)
          eb = w%node_ent(b)
          wb = cs%ent_w(eb)
          ! Stored as k(jb - ja, ja) = K(ja, jb). (Both orders of a pair are
          ! summed as written: copying the mirror entry, symmetric to
          ! round-off, moved the active set of test_curved's mortar P0 case.)
          w%knn(jb - ja, ja) = w%knn(jb - ja, ja) + wa*wb*sum(cs%normal(:, ja)*mi*cs%normal(:, jb))
          if (friction) then
            w%knt(jb - ja, ja) = w%knt(jb - ja, ja) + wa*wb*sum(cs%normal(:, ja)*mi*cs%tangent(:, jb))
            w%ktn(jb - ja, ja) = w%ktn(jb - ja, ja) + wa*wb*sum(cs%tangent(:, ja)*mi*cs%normal(:, jb))
            w%ktt(jb - ja, ja) = w%ktt(jb - ja, ja) + wa*wb*sum(cs%tangent(:, ja)*mi*cs%tangent(:, jb))
          end if
        end do
      end do
    end do
    ! Reset the per-node marks for the next call (touched nodes only).
    do t = 1, ntouched
      w%node_first(w%touched(t)) = 0
    end do
  end subroutine delassus
end module raccord_delassus
