!> The candidate lists of raccord_contact_verlet hold every pair of the
!> full search while the lists are kept (doc/theory-contact.md, section 4,
!> "Incremental search"): built on x_ref with each master box inflated by
!> min(reach, length + skin) + skin, then, after every surface node has
!> moved by up to the rebuild bound (SKIN_SAFETY skin/2, here 0.999 of
!> it), the listed master segments whose current box (inflated by
!> min(reach, current length)) meets a slave item's current box are
!> exactly the master segments the full search pairs with it, for slave
!> segments (mortar) and slave nodes (node-to-segment). The motions are
!> the worst case of the bound: master nodes moved one way, slave nodes
!> the other, along an axis or a diagonal, and master segments stretched.
!> Also checks that the lists do not rebuild under those motions (else the
!> test would only check a fresh build) and are shorter than with the
!> inflation reach + skin of the sixth pass (what the change bought).
program test_verlet_lists
  use raccord_kinds, only: wp, pi
  use raccord_check, only: failure_t, new_test, run_tests, check
  use raccord_contact_surface, only: contact_surface_t
  use raccord_contact_verlet, only: verlet_t, verlet_init, verlet_refresh, verlet_item_box, verlet_candidates
  implicit none
  integer :: nseed
  integer, allocatable :: seed(:)

  call random_seed(size=nseed)
  allocate(seed(nseed))
  seed = 20261201
  call random_seed(put=seed)
  call run_tests('verlet_lists', [ &
    new_test('segment items: lists hold every pair of the full search after motions up to the bound', test_segments), &
    new_test('node items: lists hold every pair of the full search after motions up to the bound', test_nodes)])

contains

  subroutine test_segments(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call run_case(.true., failure)
  end subroutine test_segments

  subroutine test_nodes(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call run_case(.false., failure)
  end subroutine test_nodes

  !> 40 trials: a master arc of 30 segments of uneven length (some shorter
  !> than the reach, some longer), a slave chain of 40 nodes beside it at
  !> up to 2 reach, lists built, then the worst-case motion and the
  !> comparison with the brute-force search on the moved positions.
  subroutine run_case(by_segment, failure)
    logical, intent(in) :: by_segment
    type(failure_t), allocatable, intent(out) :: failure
    type(contact_surface_t) :: master, slave
    type(verlet_t) :: v
    real(wp), allocatable :: x(:,:), x0(:,:)
    integer, allocatable :: cand(:)
    logical, allocatable :: full(:), listed(:)
    real(wp) :: reach, d, u(3), th, r, lo(2), hi(2), mlo(2), mhi(2), rr, dir(2), mean_len
    integer :: trial, nm, ns, k, i, l, ncand, nitem, nmiss, nextra, nrebuilt, npairs, nlist, nlist_old, q
    nmiss = 0
    nextra = 0
    nrebuilt = 0
    npairs = 0
    nlist = 0
    nlist_old = 0
    do trial = 1, 40
      nm = 31
      ns = 40
      allocate(x(2, nm + ns))
      do k = 1, nm
        call random_number(u)
        th = 0.6_wp*pi*(real(k - 1, wp) + 0.4_wp*(u(1) - 0.5_wp))/real(nm - 1, wp)
        r = 1.0_wp + 0.02_wp*(u(2) - 0.5_wp)
        x(:, k) = r*[cos(th), sin(th)]
      end do
      mean_len = 0.0_wp
      do k = 1, nm - 1
        mean_len = mean_len + norm2(x(:, k + 1) - x(:, k))/real(nm - 1, wp)
      end do
      ! Reach between the shortest and the longest segments (both branches
      ! of min(reach, length)).
      reach = mean_len*merge(0.6_wp, 1.3_wp, mod(trial, 2) == 0)
      do i = 1, ns
        call random_number(u)
        th = 0.7_wp*pi*(real(i - 1, wp)/real(ns - 1, wp)) - 0.05_wp*pi
        r = 1.0_wp + 2.0_wp*reach*u(1)
        x(:, nm + i) = r*[cos(th), sin(th)]
      end do
      call make_chain(master, 1, nm)
      call make_chain(slave, nm + 1, ns)
      call verlet_init(v, slave, master, by_segment, reach)
      call verlet_refresh(v, x, slave, master, reach)
      nitem = merge(slave%nseg, slave%nnode, by_segment)
      nlist = nlist + (v%ptr(nitem + 1) - 1)
      nlist_old = nlist_old + old_list_length(x, slave, master, reach, v%skin, by_segment)
      ! Worst case of the bound: every node by d (just under the rebuild
      ! bound), master nodes one way, slave nodes the other; odd master
      ! nodes the opposite way (stretching segments).
      d = 0.999_wp*0.9_wp*0.5_wp*v%skin
      x0 = x
      call random_number(u)
      select case (mod(trial, 4))
      case (0)
        dir = [1.0_wp, 0.0_wp]
      case (1)
        dir = [0.0_wp, 1.0_wp]
      case (2)
        dir = [1.0_wp, 1.0_wp]/sqrt(2.0_wp)
      case default
        dir = [cos(2.0_wp*pi*u(1)), sin(2.0_wp*pi*u(1))]
      end select
      do k = 1, nm
        x(:, k) = x0(:, k) + d*dir*merge(1.0_wp, -1.0_wp, mod(k, 2) == 0 .or. u(2) < 0.5_wp)
      end do
      do i = 1, ns
        x(:, nm + i) = x0(:, nm + i) - d*dir
      end do
      call verlet_refresh(v, x, slave, master, reach)
      if (v%rebuilt) nrebuilt = nrebuilt + 1
      allocate(cand(master%nseg), full(master%nseg), listed(master%nseg))
      do k = 1, nitem
        call verlet_item_box(v, slave, x, k, lo, hi)
        call verlet_candidates(v, k, lo, hi, cand, ncand)
        listed = .false.
        listed(cand(1:ncand)) = .true.
        ! The full search's test (raccord_contact_search) on x.
        do l = 1, master%nseg
          mlo = min(x(:, master%seg(1, l)), x(:, master%seg(2, l)))
          mhi = max(x(:, master%seg(1, l)), x(:, master%seg(2, l)))
          rr = min(reach, norm2(x(:, master%seg(2, l)) - x(:, master%seg(1, l))))
          full(l) = .not. (mlo(1) - rr > hi(1) .or. mhi(1) + rr < lo(1) .or. mlo(2) - rr > hi(2) .or. mhi(2) + rr < lo(2))
        end do
        npairs = npairs + count(full)
        do q = 1, master%nseg
          if (full(q) .and. .not. listed(q)) nmiss = nmiss + 1
          if (listed(q) .and. .not. full(q)) nextra = nextra + 1
        end do
      end do
      deallocate(x, cand, full, listed)
    end do
    call check(failure, npairs > 1000, 'too few pairs to test')
    if (allocated(failure)) return
    call check(failure, nrebuilt == 0, 'the lists rebuilt under motions below the bound')
    if (allocated(failure)) return
    call check(failure, nmiss == 0 .and. nextra == 0, 'filtered lists differ from the full search')
    if (allocated(failure)) return
    ! The inflation min(reach, length + skin) + skin against reach + skin:
    ! fewer list entries whenever segments are shorter than the reach.
    call check(failure, nlist < nlist_old, 'lists not shorter than with the inflation reach + skin')
  end subroutine run_case

  !> An open chain of n nodes first, first+1, ... (2-node segments).
  subroutine make_chain(surf, first, n)
    type(contact_surface_t), intent(out) :: surf
    integer, intent(in) :: first, n
    integer :: i
    surf%nseg = n - 1
    surf%nen_seg = 2
    surf%nnode = n
    allocate(surf%seg(3, n - 1), surf%node(n), surf%corner(n), source=0)
    allocate(surf%s0(n))
    do i = 1, n
      surf%node(i) = first + i - 1
      surf%corner(i) = first + i - 1
      surf%s0(i) = real(i, wp)
    end do
    do i = 1, n - 1
      surf%seg(1:2, i) = [first + i - 1, first + i]
    end do
  end subroutine make_chain

  !> Number of (item, master segment) pairs with boxes inflated by
  !> reach + skin (the lists before the seventh pass), brute force.
  integer function old_list_length(x, slave, master, reach, skin, by_segment) result(n)
    real(wp), intent(in) :: x(:,:), reach, skin
    type(contact_surface_t), intent(in) :: slave, master
    logical, intent(in) :: by_segment
    integer :: k, l
    real(wp) :: lo(2), hi(2), mlo(2), mhi(2), rr
    n = 0
    do k = 1, merge(slave%nseg, slave%nnode, by_segment)
      if (by_segment) then
        lo = min(x(:, slave%seg(1, k)), x(:, slave%seg(2, k)))
        hi = max(x(:, slave%seg(1, k)), x(:, slave%seg(2, k)))
      else
        lo = x(:, slave%node(k))
        hi = lo
      end if
      do l = 1, master%nseg
        mlo = min(x(:, master%seg(1, l)), x(:, master%seg(2, l)))
        mhi = max(x(:, master%seg(1, l)), x(:, master%seg(2, l)))
        rr = reach + skin
        if (.not. (mlo(1) - rr > hi(1) .or. mhi(1) + rr < lo(1) .or. mlo(2) - rr > hi(2) .or. mhi(2) + rr < lo(2))) &
          n = n + 1
      end do
    end do
  end function old_list_length
end program test_verlet_lists
