!> The Delassus product K = B M^-1 B' (raccord_delassus; doc/theory-contact.md,
!> section 3) and Z = -G1_OO^-1 G1_OA (raccord_g1_runs, open_from_active)
!> on synthetic mortar-like rows: slave nodes on a line (a P1 mass-matrix
!> G1 of half band 1), master nodes shared by two neighbouring rows, and a
!> far node shared by three rows in a row, so that a node carries 1 to 4
!> rows; random inverse masses, damping, normals and weights.
!> Asserted: every band entry of the four blocks against K summed entry by
!> entry from its definition, both orders of each pair (K(j, k) and
!> K(k, j) are summed apart); the band width is that of the rows; Knn of
!> a solve without friction is that of one with friction, bit for bit;
!> the tangential blocks are each other's mirrors, bit for bit;
!> a second set after the first (the per-node marks are reset) is right
!> too; the node lists are kept while the rows name the same nodes in the
!> same order (new weights and normals give the blocks of a fresh
!> workspace, bit for bit) and rebuilt when one entry names another node;
!> and G1_OO Z + G1_OA = 0 on every open run, Z nonzero only next to
!> a run.
program test_delassus
  use raccord_kinds, only: wp
  use raccord_check, only: failure_t, new_test, run_tests, check, check_close
  use raccord_constraint_set, only: constraint_set_t, cs_start, cs_add_row, cs_add_entry, cs_finish_row
  use raccord_solver_work, only: solver_work_t, ZMAX, ensure1, ensure_i, ensure_i2, ensure2
  use raccord_delassus, only: delassus
  use raccord_g1_runs, only: open_from_active
  implicit none

  integer :: urand_state = 4711
  !> Rows at most; the solver's per-node lists are sized by its first call,
  !> as by the mesh in a run, so every set has the same node count.
  integer, parameter :: MMAX = 64

  call run_tests('delassus', [ &
    new_test('K = B M^-1 B'' entry by entry, both orders, with and without friction', test_k), &
    new_test('node lists kept while the rows name the same nodes, rebuilt when not', test_kept_lists), &
    new_test('Z = -G1_OO^-1 G1_OA on random open runs', test_z)])

contains

  subroutine test_k(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(constraint_set_t) :: cs
    type(solver_work_t) :: w, w0
    real(wp), allocatable :: minv(:,:), alpha(:), knn0(:,:)
    integer :: icase, m, nn
    real(wp) :: h, h_ratio
    do icase = 1, 4
      m = 17 + 11*icase
      call build_set(cs, m, minv, alpha, nn)
      h = 1.0e-3_wp*(0.5_wp + urand())
      h_ratio = merge(0.5_wp, 1.0_wp, icase == 1)   ! the half first step once
      call delassus(cs, minv, alpha, h_ratio, h, .true., w)
      call check_blocks(failure, cs, minv, alpha, h_ratio, h, w, icase)
      if (allocated(failure)) return
      ! the tangential blocks summed for one order of each pair and
      ! mirrored (issue #16, sixth pass): exactly symmetric
      call check(failure, tangential_mirrored(w, m), &
        'Ktt(k, j) = Ktt(j, k) and Knt(k, j) = Ktn(j, k), bit for bit')
      if (allocated(failure)) return
      ! without friction: Knn alone, the same sums
      call delassus(cs, minv, alpha, h_ratio, h, .false., w0)
      call check(failure, w0%kb == w%kb, 'the same band width without friction')
      if (allocated(failure)) return
      knn0 = w0%knn(-w%kb:w%kb, 1:m)
      call check(failure, all(knn0 == w%knn(-w%kb:w%kb, 1:m)), &
        'Knn without friction is Knn with friction, bit for bit')
      if (allocated(failure)) return
    end do
  end subroutine test_k

  !> Whether the four blocks of w and w2 agree bit for bit on the entries
  !> of the m x m matrix within w's band (k(d, j) = K(j, j + d)).
  logical function same_blocks(w, w2, m) result(ok)
    type(solver_work_t), intent(in) :: w, w2
    integer, intent(in) :: m
    integer :: j, d
    ok = .true.
    do j = 1, m
      do d = max(-w%kb, 1 - j), min(w%kb, m - j)
        if (w%knn(d, j) /= w2%knn(d, j) .or. w%knt(d, j) /= w2%knt(d, j) .or. &
          w%ktn(d, j) /= w2%ktn(d, j) .or. w%ktt(d, j) /= w2%ktt(d, j)) ok = .false.
      end do
    end do
  end function same_blocks

  !> Whether the tangential blocks of w are the mirrors of each other:
  !> ktt(-d, j + d) = ktt(d, j), knt(-d, j + d) = ktn(d, j) and
  !> ktn(-d, j + d) = knt(d, j) over the band (k(d, j) = K(j, j + d)).
  logical function tangential_mirrored(w, m) result(ok)
    type(solver_work_t), intent(in) :: w
    integer, intent(in) :: m
    integer :: j, d
    ok = .true.
    do j = 1, m - 1
      do d = 1, min(w%kb, m - j)
        if (w%ktt(-d, j + d) /= w%ktt(d, j)) ok = .false.
        if (w%knt(-d, j + d) /= w%ktn(d, j)) ok = .false.
        if (w%ktn(-d, j + d) /= w%knt(d, j)) ok = .false.
      end do
    end do
  end function tangential_mirrored

  !> The four blocks against their definition, entry by entry:
  !> K(j, k) = sum over the nodes p of both rows of w_jp w_kp a_j . (M_p^-1 b_k)
  !> with a, b the normal or the tangent, M_p^-1 scaled by h_ratio / (1 + alpha h / 2).
  subroutine check_blocks(failure, cs, minv, alpha, h_ratio, h, w, icase)
    type(failure_t), allocatable, intent(inout) :: failure
    type(constraint_set_t), intent(in) :: cs
    real(wp), intent(in) :: minv(:,:), alpha(:), h_ratio, h
    type(solver_work_t), intent(in) :: w
    integer, intent(in) :: icase
    integer :: j, k, e1, e2, p, kbmax, blk
    real(wp) :: ref(4), got(4), scale, mi(2), a(2), b(2)
    character(len=160) :: msg
    kbmax = 0
    scale = 0.0_wp
    do j = 1, cs%m
      scale = max(scale, abs(w%knn(0, j)))
    end do
    do j = 1, cs%m
      do k = 1, cs%m
        ref = 0.0_wp
        do e1 = cs%row_ptr(j), cs%row_ptr(j + 1) - 1
          do e2 = cs%row_ptr(k), cs%row_ptr(k + 1) - 1
            p = cs%ent_node(e1)
            if (cs%ent_node(e2) /= p) cycle
            mi = h_ratio/(1.0_wp + 0.5_wp*alpha(p)*h)*minv(:, p)
            do blk = 1, 4
              a = merge(cs%normal(:, j), cs%tangent(:, j), blk <= 2)
              b = merge(cs%normal(:, k), cs%tangent(:, k), blk == 1 .or. blk == 3)
              ref(blk) = ref(blk) + cs%ent_w(e1)*cs%ent_w(e2)*dot_product(a*mi, b)
            end do
          end do
        end do
        if (any(ref /= 0.0_wp)) kbmax = max(kbmax, abs(k - j))
        if (abs(k - j) > w%kb) then
          write(msg, '(a, i0, a, i0, a, i0, a)') 'case ', icase, ': K(', j, ', ', k, ') outside the band is zero'
          call check(failure, all(ref == 0.0_wp), trim(msg))
          if (allocated(failure)) return
          cycle
        end if
        got = [w%knn(k - j, j), w%knt(k - j, j), w%ktn(k - j, j), w%ktt(k - j, j)]
        do blk = 1, 4
          write(msg, '(a, i0, a, i0, a, i0, a, i0, a)') 'case ', icase, ': block ', blk, ' (nn, nt, tn, tt) at (', &
            j, ', ', k, ')'
          call check_close(failure, got(blk), ref(blk), trim(msg), abs_tol=1.0e-14_wp*scale)
          if (allocated(failure)) return
        end do
      end do
    end do
    write(msg, '(a, i0, a, i0, a, i0)') 'case ', icase, ': band width ', w%kb, ' is that of the rows, ', kbmax
    call check(failure, w%kb == kbmax, trim(msg))
  end subroutine check_blocks

  !> The node lists of a workspace are kept across calls while the rows'
  !> entries name the same nodes in the same order (issue #16, seventh
  !> pass): with this step's weights and normals the four blocks are those
  !> of a fresh workspace bit for bit, and right against the definition;
  !> an entry moved to another node, or a set of another size, rebuilds.
  subroutine test_kept_lists(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(constraint_set_t) :: cs
    type(solver_work_t) :: w, wf
    real(wp), allocatable :: minv(:,:), alpha(:)
    integer :: m, nn, e, j, nb, nk, step
    real(wp) :: h, th
    m = 31
    call build_set(cs, m, minv, alpha, nn)
    h = 1.0e-3_wp
    call delassus(cs, minv, alpha, 1.0_wp, h, .true., w)
    call check(failure, w%lists_built == 1 .and. w%lists_kept == 0, 'the first call builds the lists')
    if (allocated(failure)) return
    do step = 1, 3
      nb = w%lists_built
      nk = w%lists_kept
      ! the next step: new weights and directions on the same nodes
      do e = 1, cs%nent
        cs%ent_w(e) = cs%ent_w(e)*(1.0_wp + 0.2_wp*(urand() - 0.5_wp))
      end do
      do j = 1, m
        th = 0.3_wp*(urand() - 0.5_wp)
        cs%normal(:, j) = [sin(th), cos(th)]
        cs%tangent(:, j) = [cos(th), -sin(th)]
      end do
      if (step == 3) then
        ! one entry of row 5 moved to another node of the same count:
        ! another structure
        cs%ent_node(cs%row_ptr(6) - 1) = cs%ent_node(cs%row_ptr(6) - 1) + 1
      end if
      call delassus(cs, minv, alpha, 1.0_wp, h, .true., w)
      if (step < 3) then
        call check(failure, w%lists_kept == nk + 1 .and. w%lists_built == nb, 'the same nodes keep the lists')
      else
        call check(failure, w%lists_built == nb + 1 .and. w%lists_kept == nk, 'an entry on another node rebuilds')
      end if
      if (allocated(failure)) return
      wf = solver_work_t()
      call delassus(cs, minv, alpha, 1.0_wp, h, .true., wf)
      call check(failure, wf%kb == w%kb, 'the band width of a fresh workspace')
      if (allocated(failure)) return
      call check(failure, same_blocks(w, wf, m), 'kept lists give the blocks of a fresh workspace, bit for bit')
      if (allocated(failure)) return
      call check_blocks(failure, cs, minv, alpha, 1.0_wp, h, w, 10 + step)
      if (allocated(failure)) return
    end do
    ! a set of another size: rebuilt, right against the definition
    nb = w%lists_built
    call build_set(cs, m + 7, minv, alpha, nn)
    call delassus(cs, minv, alpha, 1.0_wp, h, .true., w)
    call check(failure, w%lists_built == nb + 1, 'a set of another size rebuilds')
    if (allocated(failure)) return
    call check_blocks(failure, cs, minv, alpha, 1.0_wp, h, w, 20)
  end subroutine test_kept_lists

  subroutine test_z(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(constraint_set_t) :: cs
    type(solver_work_t) :: w
    real(wp), allocatable :: minv(:,:), alpha(:), r(:)
    integer, allocatable :: olist(:), ia(:)
    integer :: icase, m, nn, j, no, na, p, q, e, b, info, nruns
    real(wp) :: v, g
    character(len=160) :: msg
    nruns = 0
    do icase = 1, 20
      m = 20 + mod(13*icase, 31)
      call build_set(cs, m, minv, alpha, nn)
      if (allocated(olist)) deallocate(olist, ia, r)
      allocate(olist(m), ia(m), r(m))
      call ensure1(w%xr, m)
      call ensure_i(w%ipiv, m)
      call ensure_i(w%fcol, m)
      call ensure_i(w%lcol, m)
      call ensure_i(w%ext, 3*m)
      call ensure_i(w%zcnt, m)
      call ensure_i2(w%zcol, ZMAX, m)
      call ensure2(w%zval, ZMAX, m)
      ! random open runs of 1 to 6 constraints
      no = 0
      na = 0
      j = 1
      do while (j <= m)
        if (urand() < 0.4_wp) then
          do p = j, min(m, j + int(6*urand()))
            no = no + 1
            olist(no) = p
            ia(p) = -no
          end do
          j = p       ! (p is the run's last + 1 after the loop)
          if (j <= m) then
            na = na + 1
            ia(j) = na
          end if
        else
          na = na + 1
          ia(j) = na
        end if
        j = j + 1
      end do
      call open_from_active(cs, olist, no, ia, w%zcnt, w%zcol, w%zval, w, info)
      write(msg, '(a, i0, a)') 'case ', icase, ': open_from_active takes the runs'
      call check(failure, info == 0, trim(msg))
      if (allocated(failure)) return
      ! (G1_OO Z + G1_OA)(o, b) = 0 for every open o and active b: row o of
      ! G1 applied to the column of Z for b (Z(o', b) over the open o', 1 at b)
      do p = 1, no
        if (p > 1) then
          if (olist(p) - olist(p - 1) > 1) nruns = nruns + 1
        end if
        do b = 1, m
          if (ia(b) <= 0) cycle
          v = 0.0_wp
          do q = max(1, olist(p) - 1), min(m, olist(p) + 1)
            g = cs%g1(olist(p) - q, q)   ! G1(olist(p), q)
            if (q == b) then
              v = v + g
            else if (ia(q) < 0) then
              do e = 1, w%zcnt(-ia(q))
                if (w%zcol(e, -ia(q)) == b) v = v + g*w%zval(e, -ia(q))
              end do
            end if
          end do
          write(msg, '(a, i0, a, i0, a, i0)') 'case ', icase, ': (G1_OO Z + G1_OA) at open ', olist(p), &
            ', active ', b
          call check_close(failure, v, 0.0_wp, trim(msg), abs_tol=1.0e-13_wp)
          if (allocated(failure)) return
        end do
        ! Z's columns are active constraints within g1_band of the run
        do e = 1, w%zcnt(p)
          b = w%zcol(e, p)
          call check(failure, ia(b) > 0, 'Z has active columns only')
        end do
      end do
    end do
    call check(failure, nruns > 20, 'several open runs were exercised')
  end subroutine test_z

  !> m rows on slave nodes 1..m (G1 of half band 1, the negated slave
  !> weights), master nodes m + j and m + j + 1 for row j, and a far node
  !> 2 m + 2 + (j - 1)/3 shared by three rows in a row.
  subroutine build_set(cs, m, minv, alpha, nn)
    type(constraint_set_t), intent(inout) :: cs
    integer, intent(in) :: m
    real(wp), allocatable, intent(inout) :: minv(:,:), alpha(:)
    integer, intent(out) :: nn
    real(wp), allocatable :: x(:,:), du(:,:)
    real(wp) :: g1(-1:1), th, nrm(2)
    integer :: j, i
    nn = 3*MMAX + 3
    if (allocated(minv)) deallocate(minv, alpha)
    allocate(minv(2, nn), alpha(nn), x(2, nn), du(2, nn))
    do j = 1, nn
      minv(:, j) = [0.5_wp + urand(), 0.5_wp + urand()]
      alpha(j) = 10.0_wp*urand()
    end do
    minv(:, m + 3) = 0.0_wp         ! a prescribed master node
    x = 0.0_wp
    du = 0.0_wp
    g1 = [1.0_wp/6.0_wp, 2.0_wp/3.0_wp, 1.0_wp/6.0_wp]
    call cs_start(cs, m)
    do j = 1, m
      th = 0.3_wp*(urand() - 0.5_wp)
      nrm = [sin(th), cos(th)]
      call cs_add_row(cs, j, j, nrm, 1.0_wp, real(j, wp))
      do i = max(1, j - 1), min(m, j + 1)
        call cs_add_entry(cs, i, -g1(i - j)*(1.0_wp + 0.1_wp*urand()))
      end do
      call cs_add_entry(cs, m + j, 0.5_wp + 0.1_wp*urand())
      call cs_add_entry(cs, m + j + 1, 0.5_wp + 0.1_wp*urand())
      call cs_add_entry(cs, 2*m + 2 + (j - 1)/3, 0.1_wp*urand())
      call cs_finish_row(cs, x, du)
    end do
    cs%g1_band = 1
    do j = 1, m
      do i = max(1, j - 1), min(m, j + 1)
        cs%g1(i - j, j) = -cs%ent_w(cs%row_ptr(j) + i - max(1, j - 1))
      end do
    end do
  end subroutine build_set

  real(wp) function urand()
    urand_state = int(mod(1103515245_8*int(urand_state, 8) + 12345_8, 2147483648_8))
    urand = real(urand_state, wp)/2147483648.0_wp
  end function urand
end program test_delassus
