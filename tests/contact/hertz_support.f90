!> Hertz line contact (method brief section 7): the closed form and the
!> measures a contact profile is judged by.
module hertz_support
  use raccord_kinds, only: wp, pi
  use raccord_scene_runner, only: scene_run_t
  use raccord_multiplier_solver, only: ST_OPEN
  use raccord_check, only: failure_t, check_close
  implicit none
  private

  public :: hertz_closed_form, profile_of, profile_measures, profile_difference, normal_sum_excess, &
    check_resultants

  !> Equilibrium at rest: the vector resultant of the contact forces is the
  !> load, to the dynamic remainder and round-off (measured 7e-11 to 1e-10
  !> in both Hertz tests; the bound leaves a factor 100).
  real(wp), parameter :: RESULTANT_TOL = 1.0e-8_wp
  !> The normal-force sum against its second-order closed form
  !> (normal_sum_excess); the discrete interface only approximates the tilt:
  !> measured within 1.2 % on the moderate mesh and 2.6 % on the coarse one
  !> (doc/verification.md).
  real(wp), parameter :: EXCESS_TOL = 0.05_wp

contains

  !> Half-width a and peak p0 for a load P per unit thickness, radius R and
  !> two identical plane-strain bodies (E, nu): 1/E* = 2 (1 - nu^2)/E.
  pure subroutine hertz_closed_form(p_load, radius, young, nu, a, p0)
    real(wp), intent(in) :: p_load, radius, young, nu
    real(wp), intent(out) :: a, p0
    real(wp) :: e_star
    e_star = young/(2.0_wp*(1.0_wp - nu**2))
    a = sqrt(4.0_wp*p_load*radius/(pi*e_star))
    p0 = 2.0_wp*p_load/(pi*a)
  end subroutine hertz_closed_form

  !> Relative excess of the sum of the nodal normal forces (history column
  !> contact<k>_N, pair%normal_sum) over the load P on a Hertz interface.
  !> Each nodal force acts along the normal of the deformed interface; for
  !> two bodies of one material each gives half the approach, so the
  !> interface is y = x^2/(4R), tilted by theta = x/(2R). Equilibrium holds
  !> for the vertical components, sum f cos(theta) = P, so to second order
  !>   (N - P)/P = <theta^2/2>_p = (a/R)^2/8 <xi^2>_p = a^2/(32 R^2),
  !> with <xi^2>_p = 1/4 the mean of (x/a)^2 over the elliptic pressure.
  pure real(wp) function normal_sum_excess(a, radius) result(excess)
    real(wp), intent(in) :: a, radius
    excess = a**2/(32.0_wp*radius**2)
  end function normal_sum_excess

  !> Pair 1 of a Hertz run at rest under the load p_load (half-width a,
  !> radius R): the vector resultant |Fy| is the load, and the sum of the
  !> nodal normal forces exceeds it by normal_sum_excess. Prints both.
  subroutine check_resultants(failure, run, p_load, a, radius)
    type(failure_t), allocatable, intent(inout) :: failure
    type(scene_run_t), intent(in) :: run
    real(wp), intent(in) :: p_load, a, radius
    real(wp) :: force, excess
    force = abs(run%pairs(1)%force(2))
    excess = run%pairs(1)%normal_sum/p_load - 1.0_wp
    write(*, '(a,es10.2,a,es10.3,a,es10.3)') '        resultant |Fy|/P - 1 ', force/p_load - 1.0_wp, &
      '; normal-force sum (N - P)/P ', excess, ', closed form ', normal_sum_excess(a, radius)
    call check_close(failure, force, p_load, 'contact force = P at rest', rel_tol=RESULTANT_TOL)
    call check_close(failure, excess, normal_sum_excess(a, radius), &
      'sum of nodal normal forces above P by the tilt of the deformed interface, a^2/(32 R^2)', rel_tol=EXCESS_TOL)
  end subroutine check_resultants

  !> Contact stress of pair 1 against the current x of its slave nodes,
  !> sorted by x; status 0 where open.
  subroutine profile_of(run, x, p, status)
    type(scene_run_t), intent(in) :: run
    real(wp), allocatable, intent(out) :: x(:), p(:)
    integer, allocatable, intent(out) :: status(:)
    integer :: n, i, j, key(1), ti
    real(wp) :: tx, tp
    associate (pair => run%pairs(1))
      n = pair%slave%nnode
      allocate(x(n), p(n), status(n))
      do i = 1, n
        x(i) = run%model%x(1, pair%slave%node(i)) + run%state%u(1, pair%slave%node(i))
        p(i) = pair%pressure(i)
        status(i) = pair%status(i)
      end do
    end associate
    ! Insertion sort: surfaces have a few hundred nodes.
    do i = 2, n
      tx = x(i)
      tp = p(i)
      ti = status(i)
      j = i - 1
      do while (j >= 1)
        if (x(j) <= tx) exit
        x(j + 1) = x(j)
        p(j + 1) = p(j)
        status(j + 1) = status(j)
        j = j - 1
      end do
      x(j + 1) = tx
      p(j + 1) = tp
      status(j + 1) = ti
    end do
    key = 0
  end subroutine profile_of

  !> Peak stress and contact half-width: each edge of the active zone is
  !> placed midway between its last active node and the first open one.
  subroutine profile_measures(x, p, status, peak, half_width)
    real(wp), intent(in) :: x(:), p(:)
    integer, intent(in) :: status(:)
    real(wp), intent(out) :: peak, half_width
    integer :: i, first, last
    peak = maxval(p)
    first = 0
    last = 0
    do i = 1, size(x)
      if (status(i) == ST_OPEN) cycle
      if (first == 0) first = i
      last = i
    end do
    if (first == 0) then
      half_width = 0.0_wp
      return
    end if
    half_width = 0.5_wp*(edge(first, -1) - edge(last, +1))
    half_width = abs(half_width)
  contains
    real(wp) function edge(i, dir)
      integer, intent(in) :: i, dir
      if (i + dir >= 1 .and. i + dir <= size(x)) then
        edge = 0.5_wp*(x(i) + x(i + dir))
      else
        edge = x(i)
      end if
    end function edge
  end subroutine profile_measures

  !> Largest |p_a - p_b| over the nodes of profile a, with p_b linearly
  !> interpolated at x_a (zero outside b's nodes).
  real(wp) function profile_difference(xa, pa, xb, pb) result(d)
    real(wp), intent(in) :: xa(:), pa(:), xb(:), pb(:)
    integer :: i, j
    real(wp) :: q
    d = 0.0_wp
    do i = 1, size(xa)
      q = 0.0_wp
      do j = 1, size(xb) - 1
        if (xa(i) >= xb(j) .and. xa(i) <= xb(j + 1)) then
          q = pb(j) + (pb(j + 1) - pb(j))*(xa(i) - xb(j))/max(xb(j + 1) - xb(j), tiny(1.0_wp))
          exit
        end if
      end do
      d = max(d, abs(pa(i) - q))
    end do
  end function profile_difference
end module hertz_support
