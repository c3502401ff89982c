!> The shortcuts of node-to-segment's search (doc/theory-contact.md,
!> section 5, "The search as built"), checked against the search without
!> them on random geometry:
!> 1. span_far, the Bezier-hull test that lets smooth_foot pass a
!>    neighbouring Hermite span, is sound: whenever it says a span is
!>    farther than d, every sampled point of the span (the cubic, the
!>    chord and their blends) is farther than d; and it does say so for
!>    most spans one segment away (else nothing is saved).
!> 2. smooth_foot with the skip gives the same nodes, weights and normal,
!>    bit for bit, as with all three spans evaluated (full = .true.), on
!>    open and closed wavy chains with uneven segments and straight ends.
!> 3. build_node_to_segment's polygon search (last step's segment first,
!>    box bound) picks the closest segment of a brute-force pass over all
!>    master segments, and its rows are those of smooth_foot(full) there.
program test_nts_search
  use raccord_kinds, only: wp, pi
  use raccord_check, only: failure_t, new_test, run_tests, check
  use raccord_contact_surface, only: contact_surface_t
  use raccord_contact_verlet, only: verlet_t, verlet_init
  use raccord_constraint_set, only: constraint_set_t
  use raccord_node_to_segment, only: smooth_foot, span_far, build_node_to_segment
  implicit none
  integer :: nseed
  integer, allocatable :: seed(:)

  ! A fixed seed: the same geometry every run.
  call random_seed(size=nseed)
  allocate(seed(nseed))
  seed = 20261127
  call random_seed(put=seed)
  call run_tests('nts_search', [ &
    new_test('span_far: never passes a span that has a point within d; passes most far spans', test_span_far), &
    new_test('smooth_foot: the same foot with the skip as with all three spans (open, closed chains)', test_skip), &
    new_test('build_node_to_segment: polygon search = brute force, rows = smooth_foot(full)', test_build)])

contains

  !> A master chain of n segments (nodes 1..n+1, or 1..n closed) on a wavy
  !> arc with uneven spacing; `straight_ends`: the first and last three
  !> nodes on a line (the blended end spans of smooth_foot).
  subroutine wavy_chain(n, closed, straight_ends, surf, x)
    integer, intent(in) :: n
    logical, intent(in) :: closed, straight_ends
    type(contact_surface_t), intent(out) :: surf
    real(wp), allocatable, intent(out) :: x(:,:)
    integer :: k, nn
    real(wp) :: th, r, u(3), span
    nn = merge(n, n + 1, closed)
    allocate(x(2, nn))
    span = merge(2.0_wp*pi, 0.8_wp*pi, closed)
    do k = 1, nn
      call random_number(u)
      th = span*(real(k - 1, wp) + 0.35_wp*(u(1) - 0.5_wp))/real(n, wp)
      r = 1.0_wp + 0.04_wp*(u(2) - 0.5_wp) + 0.03_wp*sin(5.0_wp*th)
      x(:, k) = r*[cos(th), sin(th)]
    end do
    if (straight_ends .and. .not. closed) then
      x(:, 3) = x(:, 1) + 2.0_wp*(x(:, 2) - x(:, 1))
      x(:, nn - 2) = x(:, nn) + 2.0_wp*(x(:, nn - 1) - x(:, nn))
    end if
    surf%nseg = n
    surf%nen_seg = 2
    surf%nnode = nn
    surf%closed = closed
    allocate(surf%seg(3, n), surf%node(nn), surf%corner(nn), source=0)
    allocate(surf%s0(nn))
    do k = 1, nn
      surf%node(k) = k
      surf%corner(k) = k
      surf%s0(k) = real(k, wp)
    end do
    do k = 1, n
      surf%seg(1, k) = k
      surf%seg(2, k) = k + 1
      if (closed .and. k == n) surf%seg(2, k) = 1
    end do
  end subroutine wavy_chain

  !> A random point near segment k of the chain: at parameter t along it,
  !> off it by -0.5..2.5 of its length along its normal.
  function point_near(surf, x, k) result(p)
    type(contact_surface_t), intent(in) :: surf
    real(wp), intent(in) :: x(:,:)
    integer, intent(in) :: k
    real(wp) :: p(2), u(2), a(2), b(2)
    call random_number(u)
    a = x(:, surf%seg(1, k))
    b = x(:, surf%seg(2, k))
    p = a + (1.2_wp*u(1) - 0.1_wp)*(b - a) + (3.0_wp*u(2) - 0.5_wp)*[b(2) - a(2), a(1) - b(1)]
  end function point_near

  subroutine test_span_far(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(contact_surface_t) :: surf
    real(wp), allocatable :: x(:,:)
    real(wp) :: xp(2), d, dmin, t, c(2), xq(2), xa(2), xb(2), xn(2), u(1), h00, h01, h10, h11, phi
    integer :: trial, k, kk, nd(4), i, ip, nfar, nneigh, nbad, ib
    logical :: closed
    nfar = 0
    nneigh = 0
    nbad = 0
    do trial = 1, 40
      closed = mod(trial, 2) == 0
      call wavy_chain(10, closed, mod(trial, 4) == 1, surf, x)
      do k = 1, surf%nseg
        do ip = 1, 5
          xp = point_near(surf, x, k)
          do kk = 1, surf%nseg
            nd = [kk - 1, surf%seg(1, kk), surf%seg(2, kk), kk + 1]
            if (closed) nd([1, 4]) = modulo(nd([1, 4]) - 1, surf%nseg) + 1
            if (nd(1) > 0) nd(1) = surf%seg(1, nd(1))
            if (nd(4) > surf%nseg) nd(4) = 0
            if (nd(4) > 0) nd(4) = surf%seg(2, nd(4))
            xa = x(:, nd(2))
            xb = x(:, nd(3))
            xq = 2.0_wp*xa - xb
            if (nd(1) > 0) xq = x(:, nd(1))
            xn = 2.0_wp*xb - xa
            if (nd(4) > 0) xn = x(:, nd(4))
            ! The span's closest sampled point: cubic, chord and a blend.
            dmin = huge(1.0_wp)
            do i = 0, 2000
              t = real(i, wp)/2000.0_wp
              h00 = 2.0_wp*t**3 - 3.0_wp*t**2 + 1.0_wp
              h01 = 3.0_wp*t**2 - 2.0_wp*t**3
              h10 = t**3 - 2.0_wp*t**2 + t
              h11 = t**3 - t**2
              c = h00*xa + h01*xb + h10*0.5_wp*(xb - xq) + h11*0.5_wp*(xn - xa)
              do ib = 0, 2
                phi = 0.5_wp*real(ib, wp)
                dmin = min(dmin, norm2(phi*c + (1.0_wp - phi)*(xa + t*(xb - xa)) - xp))
              end do
            end do
            ! A reference distance at random, up to twice the true one.
            call random_number(u)
            d = 2.0_wp*u(1)*dmin
            if (span_far(x, nd, xp, d)) then
              if (.not. dmin > d) nbad = nbad + 1
              if (abs(kk - k) == 1 .and. d > 0.0_wp) nfar = nfar + 1
            end if
            if (abs(kk - k) == 1 .and. d > 0.0_wp) nneigh = nneigh + 1
            ! Clearly far: d at a third of the sampled distance, a span
            ! three or more segments away.
            if (abs(kk - k) >= 3 .and. .not. closed) then
              if (.not. span_far(x, nd, xp, dmin/3.0_wp)) nbad = nbad + 1
            end if
          end do
        end do
      end do
    end do
    call check(failure, nbad == 0, 'span_far passed a span with a point within d, or kept one clearly far')
    ! About half the neighbours have d below their distance; most of those should be seen far.
    call check(failure, nfar > nneigh/4, 'span_far rarely passes a neighbouring span')
  end subroutine test_span_far

  subroutine test_skip(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(contact_surface_t) :: surf
    real(wp), allocatable :: x(:,:)
    real(wp) :: xp(2), w1(4), w2(4), n1(2), n2(2)
    integer :: trial, k, kk, ip, nd1(4), nd2(4), ndiff, ncase
    logical :: closed
    ndiff = 0
    ncase = 0
    do trial = 1, 40
      closed = mod(trial, 2) == 0
      call wavy_chain(12, closed, mod(trial, 4) == 1, surf, x)
      do k = 1, surf%nseg
        do ip = 1, 8
          xp = point_near(surf, x, k)
          do kk = max(1, k - 1), min(surf%nseg, k + 1)
            call smooth_foot(surf, x, kk, xp, nd1, w1, n1)
            call smooth_foot(surf, x, kk, xp, nd2, w2, n2, full=.true.)
            ncase = ncase + 1
            if (any(nd1 /= nd2) .or. any(w1 /= w2) .or. any(n1 /= n2)) ndiff = ndiff + 1
          end do
        end do
      end do
    end do
    call check(failure, ncase > 1000 .and. ndiff == 0, 'smooth_foot with the skip differs from the full evaluation')
  end subroutine test_skip

  subroutine test_build(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(contact_surface_t) :: master, slave
    type(verlet_t) :: v
    type(constraint_set_t) :: cs
    real(wp), allocatable :: xm(:,:), x(:,:), du(:,:), trib(:), nrm(:,:)
    integer, allocatable :: cand(:)
    real(wp) :: reach, hmin, s, foot(2), dist, best_dist, w(4), nrm1(2), u(2), tol
    integer :: trial, i, k, m, nm, ns, p, best, nd(4), j, e, a, nrow, nbad, pass
    nbad = 0
    nrow = 0
    do trial = 1, 20
      call wavy_chain(16, mod(trial, 2) == 0, mod(trial, 4) == 1, master, xm)
      nm = master%nnode
      hmin = huge(1.0_wp)
      do k = 1, master%nseg
        hmin = min(hmin, norm2(xm(:, master%seg(2, k)) - xm(:, master%seg(1, k))))
      end do
      reach = 0.5_wp*hmin
      ! Slave: 40 nodes near the master (within 0.4 hmin of a random
      ! point of a random segment), an open chain of their own.
      ns = 40
      allocate(x(2, nm + ns), du(2, nm + ns), source=0.0_wp)
      x(:, 1:nm) = xm
      do i = 1, ns
        call random_number(u)
        k = 1 + min(master%nseg - 1, int(u(1)*master%nseg))
        call random_number(u)
        x(:, nm + i) = xm(:, master%seg(1, k)) + u(1)*(xm(:, master%seg(2, k)) - xm(:, master%seg(1, k)))
        call random_number(u)
        x(:, nm + i) = x(:, nm + i) + 0.4_wp*hmin*(2.0_wp*u - 1.0_wp)/sqrt(2.0_wp)
      end do
      slave%nseg = ns - 1
      slave%nen_seg = 2
      slave%nnode = ns
      allocate(slave%seg(3, ns - 1), slave%node(ns), slave%corner(ns), source=0)
      allocate(slave%s0(ns))
      do i = 1, ns
        slave%node(i) = nm + i
        slave%corner(i) = nm + i
        slave%s0(i) = real(i, wp)
      end do
      do k = 1, ns - 1
        slave%seg(1:2, k) = [nm + k, nm + k + 1]
      end do
      allocate(trib(ns), nrm(2, nm + ns), cand(master%nseg))
      call verlet_init(v, slave, master, .false., reach)
      ! Pass 1 cold (bit for bit against smooth_foot(full)); pass 2 after
      ! the slave nodes moved by up to 0.02 hmin: last step's segment
      ! first, warm Newton (the foot to round-off).
      do pass = 1, 2
      if (pass == 2) then
        do i = 1, ns
          call random_number(u)
          x(:, nm + i) = x(:, nm + i) + 0.02_wp*hmin*(2.0_wp*u - 1.0_wp)
        end do
      end if
      call build_node_to_segment(slave, master, x, x, du, reach, v, trib, nrm, cand, cs)
      do j = 1, cs%m
        nrow = nrow + 1
        i = cs%snode(j)
        p = slave%node(i)
        ! Brute force: every master segment, the rules of the search.
        best = 0
        best_dist = huge(1.0_wp)
        do k = 1, master%nseg
          s = -1.0_wp + 2.0_wp*dot_product(x(:, p) - xm(:, master%seg(1, k)), &
            xm(:, master%seg(2, k)) - xm(:, master%seg(1, k)))/norm2(xm(:, master%seg(2, k)) - xm(:, master%seg(1, k)))**2
          if (abs(s) > 1.0_wp + 1.0e-9_wp) then
            if (s > 1.02_wp .and. k == master%nseg .and. .not. master%closed) cycle
            if (s < -1.02_wp .and. k == 1 .and. .not. master%closed) cycle
            s = max(-1.0_wp, min(1.0_wp, s))
          end if
          foot = xm(:, master%seg(1, k))*(0.5_wp*(1.0_wp - s)) + xm(:, master%seg(2, k))*(0.5_wp*(1.0_wp + s))
          dist = norm2(x(:, p) - foot)
          ! (1e-12: a round-off tie between the two segments at a vertex)
          if (dist < best_dist*(1.0_wp - 1.0e-12_wp)) then
            best_dist = dist
            best = k
          end if
        end do
        if (best /= v%warm_seg(i)) then
          ! A tie at a vertex may go either way: the two must be as close.
          if (v%warm_seg(i) == 0) then
            nbad = nbad + 1
            cycle
          end if
        end if
        call smooth_foot(master, x, v%warm_seg(i), x(:, p), nd, w, nrm1, full=.true.)
        tol = merge(0.0_wp, 1.0e-10_wp, pass == 1)
        if (any(abs(cs%normal(:, j) + nrm1) > tol)) nbad = nbad + 1
        ! Entries: the slave node, then the weighted master nodes.
        e = cs%row_ptr(j)
        if (cs%ent_node(e) /= p .or. cs%ent_w(e) /= -1.0_wp) nbad = nbad + 1
        do a = 1, 4
          if (w(a) == 0.0_wp) cycle
          e = e + 1
          if (cs%ent_node(e) /= nd(a) .or. abs(cs%ent_w(e) - w(a)) > tol) nbad = nbad + 1
        end do
        if (e /= cs%row_ptr(j + 1) - 1) nbad = nbad + 1
        ! The chosen segment's polygon distance is the brute force's.
        m = v%warm_seg(i)
        s = -1.0_wp + 2.0_wp*dot_product(x(:, p) - xm(:, master%seg(1, m)), &
          xm(:, master%seg(2, m)) - xm(:, master%seg(1, m)))/norm2(xm(:, master%seg(2, m)) - xm(:, master%seg(1, m)))**2
        s = max(-1.0_wp, min(1.0_wp, s))
        foot = xm(:, master%seg(1, m))*(0.5_wp*(1.0_wp - s)) + xm(:, master%seg(2, m))*(0.5_wp*(1.0_wp + s))
        if (abs(norm2(x(:, p) - foot) - best_dist) > 1.0e-12_wp*hmin) nbad = nbad + 1
      end do
      end do
      deallocate(x, du, trib, nrm, cand, slave%seg, slave%node, slave%corner, slave%s0)
    end do
    call check(failure, nrow > 300, 'too few constraints to test')
    call check(failure, nbad == 0, 'node-to-segment rows differ from the brute-force search')
  end subroutine test_build
end program test_nts_search
