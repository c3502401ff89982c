!> Contact profiles of a finished in-process run (raccord_scene_runner) and
!> the measures the mortar verification tests judge them by: the multiplier
!> profile, a sub-node contact half-width, the swap asymmetry away from the
!> contact edges, and RMS errors against a closed form
!> (doc/verification.md, "Contact II: mortar").
module mortar_profile_support
  use raccord_kinds, only: wp
  use raccord_scene_runner, only: scene_run_t
  ! The sub-node half-width is the accuracy-cost study's own measure
  ! (postproc/accuracy-cost/study_profile.f90): one definition for both.
  use study_profile, only: zero_crossing_half_width
  implicit none
  private

  !> One pair's profile along its slave surface, sorted by current x.
  type, public :: profile_t
    real(wp), allocatable :: x(:)         !< current x of the slave nodes
    real(wp), allocatable :: lam(:)       !< normal multiplier lam_n (mortar: the contact pressure)
    real(wp), allocatable :: pres(:)      !< `pressure` output: (G1 lam)_j / integral of phi_j
    real(wp), allocatable :: tau(:)       !< tangential multiplier lam_t
    real(wp), allocatable :: shear(:)     !< `shear` output
    integer, allocatable :: status(:)     !< 0 open, 1 stick, 2 slip
  end type profile_t

  public :: profile_of_run, zero_crossing_half_width, active_half_width, interior_difference, interp_at
  public :: hertz_rms_error, stick_zigzag

contains

  !> Profile of pair `ipair` (default 1) at the end of `run`.
  subroutine profile_of_run(run, prof, ipair)
    type(scene_run_t), intent(in) :: run
    type(profile_t), intent(out) :: prof
    integer, intent(in), optional :: ipair
    integer :: k, n, i, j, key(1)
    integer, allocatable :: order(:)
    real(wp), allocatable :: xs(:)
    k = 1
    if (present(ipair)) k = ipair
    associate (pair => run%pairs(k))
      n = pair%slave%nnode
      allocate(xs(n), order(n))
      do i = 1, n
        xs(i) = run%model%x(1, pair%slave%node(i)) + run%state%u(1, pair%slave%node(i))
        order(i) = i
      end do
      ! Insertion sort of the permutation: surfaces have a few hundred nodes.
      do i = 2, n
        key(1) = order(i)
        j = i - 1
        do while (j >= 1)
          if (xs(order(j)) <= xs(key(1))) exit
          order(j + 1) = order(j)
          j = j - 1
        end do
        order(j + 1) = key(1)
      end do
      prof%x = xs(order)
      prof%lam = pair%lam_n(order)
      prof%pres = pair%pressure(order)
      prof%tau = pair%lam_t(order)
      prof%shear = pair%shear(order)
      prof%status = pair%status(order)
    end associate
  end subroutine profile_of_run

  !> Half-width of the active set: each edge midway between the outermost
  !> active node and its open neighbour (resolution h/2).
  pure real(wp) function active_half_width(x, status) result(hw)
    real(wp), intent(in) :: x(:)
    integer, intent(in) :: status(:)
    integer :: i, first, last, n
    real(wp) :: left, right
    n = size(x)
    first = 0
    last = 0
    do i = 1, n
      if (status(i) == 0) cycle
      if (first == 0) first = i
      last = i
    end do
    hw = 0.0_wp
    if (first == 0) return
    left = x(first)
    if (first > 1) left = 0.5_wp*(x(first) + x(first - 1))
    right = x(last)
    if (last < n) right = 0.5_wp*(x(last) + x(last + 1))
    hw = 0.5_wp*(right - left)
  end function active_half_width

  !> p_b linearly interpolated at x (0 outside b's nodes).
  pure real(wp) function interp_at(xb, pb, x) result(q)
    real(wp), intent(in) :: xb(:), pb(:), x
    integer :: j
    q = 0.0_wp
    do j = 1, size(xb) - 1
      if (x >= xb(j) .and. x <= xb(j + 1)) then
        q = pb(j) + (pb(j + 1) - pb(j))*(x - xb(j))/max(xb(j + 1) - xb(j), tiny(1.0_wp))
        return
      end if
    end do
  end function interp_at

  !> Largest |p_a - p_b| at the nodes of either profile with
  !> xlo <= x <= xhi, the other profile interpolated linearly there.
  pure real(wp) function interior_difference(xa, pa, xb, pb, xlo, xhi) result(d)
    real(wp), intent(in) :: xa(:), pa(:), xb(:), pb(:), xlo, xhi
    integer :: i
    d = 0.0_wp
    do i = 1, size(xa)
      if (xa(i) < xlo .or. xa(i) > xhi) cycle
      d = max(d, abs(pa(i) - interp_at(xb, pb, xa(i))))
    end do
    do i = 1, size(xb)
      if (xb(i) < xlo .or. xb(i) > xhi) cycle
      d = max(d, abs(pb(i) - interp_at(xa, pa, xb(i))))
    end do
  end function interior_difference
  !> RMS of (lam - p_Hertz)/p0 at the slave nodes with |x| < a, p_Hertz =
  !> p0 sqrt(1 - (x/a)^2).
  real(wp) function hertz_rms_error(prof, a, p0) result(r)
    type(profile_t), intent(in) :: prof
    real(wp), intent(in) :: a, p0
    integer :: i, n
    real(wp) :: s
    s = 0.0_wp
    n = 0
    do i = 1, size(prof%x)
      if (abs(prof%x(i)) >= a) cycle
      s = s + (prof%lam(i) - p0*sqrt(1.0_wp - (prof%x(i)/a)**2))**2
      n = n + 1
    end do
    r = sqrt(s/real(max(n, 1), wp))/p0
  end function hertz_rms_error

  !> Stick traction zigzag (doc/reproduction.md, Fig. 3): the largest
  !> |fourth difference|/16 of lam_t over windows of five nodes of the
  !> stick core (pressure >= 0.6 of its peak, |shear| <= 0.95 mu pressure),
  !> over max |lam_t|; xz its node, ncore the core's size.
  subroutine stick_zigzag(p, mu, z, xz, ncore)
    type(profile_t), intent(in) :: p
    real(wp), intent(in) :: mu
    real(wp), intent(out) :: z, xz
    integer, intent(out) :: ncore
    logical, allocatable :: core(:)
    real(wp) :: pmax, tmax, d
    integer :: i, n
    n = size(p%x)
    pmax = maxval(p%pres)
    tmax = maxval(abs(p%tau))
    allocate(core(n))
    do i = 1, n
      core(i) = p%pres(i) >= 0.6_wp*pmax .and. abs(p%shear(i)) <= 0.95_wp*mu*p%pres(i)
    end do
    ncore = count(core)
    z = 0.0_wp
    xz = 0.0_wp
    do i = 3, n - 2
      if (.not. all(core(i-2:i+2))) cycle
      d = abs(p%tau(i-2) - 4.0_wp*p%tau(i-1) + 6.0_wp*p%tau(i) - 4.0_wp*p%tau(i+1) + p%tau(i+2))/16.0_wp/tmax
      if (d > z) then
        z = d
        xz = p%x(i)
      end if
    end do
  end subroutine stick_zigzag
end module mortar_profile_support
