!> Reading one finished raccord run of the accuracy-cost study
!> (doc/accuracy-cost.md) and the measures its contact profile is judged by:
!> the last frame of `<stem>.contact1.txt` (doc/output-format.md), values of
!> `<stem>.history.txt` by column name, and the L2 distance of two profiles.
!>
!> A nodal profile is read as the piecewise-linear function through its
!> nodes (x sorted), zero outside them. L2 norms are integrals over a fine
!> uniform grid (trapezoid rule, NGRID intervals): with NGRID = 20000 over
!> [-1.5 a, 1.5 a] the grid spacing is 1.5e-4 a, and the rule's error at the
!> square-root edges of the Hertz profile is below 1e-5 relative, far under
!> every error the study measures.
module study_profile
  use, intrinsic :: iso_fortran_env, only: real64, error_unit
  implicit none
  private

  integer, parameter, public :: wp = real64
  integer, parameter, public :: NGRID = 20000
  real(wp), parameter, public :: pi = 3.14159265358979323846_wp

  !> The last frame of a contact profile, sorted by current x.
  type, public :: profile_t
    real(wp), allocatable :: x(:)        !< current x of the slave nodes
    real(wp), allocatable :: p(:)        !< `pressure` (compression positive)
    real(wp), allocatable :: q(:)        !< `shear`
    real(wp), allocatable :: lam(:)      !< lambda_n
    integer, allocatable :: status(:)    !< 0 open, 1 stick, 2 slip
    real(wp) :: time = 0.0_wp            !< time of the frame
  end type profile_t

  !> A history file: column names and every row.
  type, public :: history_t
    character(len=64), allocatable :: names(:)
    real(wp), allocatable :: rows(:, :)  !< (ncol, nrow)
  end type history_t

  public :: read_profile, read_xy_profile, read_history, history_value, history_row_at
  public :: interp, zero_crossing_half_width, l2_distance, l2_norm_grid, fail

contains

  !> Stop with a message naming the file (the program's only error exit).
  subroutine fail(msg)
    character(len=*), intent(in) :: msg
    write(error_unit, '(a)') 'raccord_study_eval: ' // msg
    error stop 2
  end subroutine fail

  !> The last frame of a raccord contact profile file.
  subroutine read_profile(path, prof)
    character(len=*), intent(in) :: path
    type(profile_t), intent(out) :: prof
    logical :: mortar
    integer :: u, ios, n, nlast, k
    character(len=1024) :: line
    real(wp) :: v(10), t
    real(wp), allocatable :: buf(:, :)
    open(newunit=u, file=path, status='old', action='read', iostat=ios)
    if (ios /= 0) call fail('cannot open the contact profile ' // path)
    ! First pass: the size of the last block.
    n = 0
    nlast = -1
    do
      read(u, '(a)', iostat=ios) line
      if (ios /= 0) exit
      if (index(line, '# frame') == 1) then
        n = 0
        nlast = 0
      else if (line(1:1) /= '#' .and. len_trim(line) > 0) then
        n = n + 1
        nlast = n
      end if
    end do
    if (nlast <= 0) call fail('no frame with nodes in ' // path)
    allocate(buf(10, nlast))
    rewind(u)
    k = 0
    do
      read(u, '(a)', iostat=ios) line
      if (ios /= 0) exit
      if (index(line, '# frame') == 1) then
        k = 0
        read(line(index(line, 'time') + 4:), *, iostat=ios) t
        if (ios /= 0) call fail('bad frame line in ' // path // ': ' // trim(line))
        prof%time = t
      else if (line(1:1) /= '#' .and. len_trim(line) > 0) then
        k = k + 1
        read(line, *, iostat=ios) v
        if (ios /= 0) call fail('bad profile line in ' // path // ': ' // trim(line))
        if (k <= nlast) buf(:, k) = v
      end if
    end do
    close(u)
    if (k /= nlast) call fail('the last frame of ' // path // ' is truncated')
    call sort_columns(buf)
    prof%x = buf(2, :)
    prof%p = buf(5, :)
    prof%q = buf(6, :)
    prof%lam = buf(9, :)
    prof%status = nint(buf(7, :))
    ! Mortar: the normal multiplier is the contact pressure of the mixed
    ! formulation (paper (8)-(9)); the `pressure` output is a weighted mean of
    ! three multipliers that reaches one node beyond the active set.
    mortar = is_mortar(path(1:index(path, ".contact1.txt") - 1) // ".scene.nml")
    if (mortar) prof%p = prof%lam
  end subroutine read_profile

  !> True when the resolved scene STEM.scene.nml uses mortar matching.
  logical function is_mortar(path) result(yes)
    character(len=*), intent(in) :: path
    character(len=512) :: line
    integer :: u, ios
    yes = .false.
    open(newunit=u, file=path, status="old", action="read", iostat=ios)
    if (ios /= 0) call fail("cannot open the resolved scene " // path)
    do
      read(u, "(a)", iostat=ios) line
      if (ios /= 0) exit
      if (index(line, "method") > 0 .and. index(line, "'mortar'") > 0) yes = .true.
    end do
    close(u)
  end function is_mortar

  !> A two-column (x, p) profile, e.g. CalculiX's contact pressure
  !> (tools/calculix/fig1b-ccx.sh); status is 1 where p > 0.
  subroutine read_xy_profile(path, prof)
    character(len=*), intent(in) :: path
    type(profile_t), intent(out) :: prof
    integer :: u, ios, n, k
    character(len=512) :: line
    real(wp), allocatable :: buf(:, :)
    open(newunit=u, file=path, status='old', action='read', iostat=ios)
    if (ios /= 0) call fail('cannot open the profile ' // path)
    n = 0
    do
      read(u, '(a)', iostat=ios) line
      if (ios /= 0) exit
      if (line(1:1) /= '#' .and. len_trim(line) > 0) n = n + 1
    end do
    if (n == 0) call fail('no rows in ' // path)
    allocate(buf(10, n))
    buf = 0.0_wp
    rewind(u)
    k = 0
    do
      read(u, '(a)', iostat=ios) line
      if (ios /= 0) exit
      if (line(1:1) == '#' .or. len_trim(line) == 0) cycle
      k = k + 1
      read(line, *, iostat=ios) buf(2, k), buf(5, k)
      if (ios /= 0) call fail('bad line in ' // path // ': ' // trim(line))
    end do
    close(u)
    buf(9, :) = buf(5, :)
    buf(7, :) = merge(1.0_wp, 0.0_wp, buf(5, :) > 0.0_wp)
    call sort_columns(buf)
    prof%x = buf(2, :)
    prof%p = buf(5, :)
    prof%q = buf(6, :)
    prof%lam = buf(9, :)
    prof%status = nint(buf(7, :))
  end subroutine read_xy_profile

  !> Insertion sort of the columns of buf by row 2 (x): a few hundred nodes.
  pure subroutine sort_columns(buf)
    real(wp), intent(inout) :: buf(:, :)
    real(wp) :: tmp(size(buf, 1))
    integer :: i, j
    do i = 2, size(buf, 2)
      tmp = buf(:, i)
      j = i - 1
      do while (j >= 1)
        if (buf(2, j) <= tmp(2)) exit
        buf(:, j + 1) = buf(:, j)
        j = j - 1
      end do
      buf(:, j + 1) = tmp
    end do
  end subroutine sort_columns

  !> Every row and the `# N name` column names of a raccord history file.
  subroutine read_history(path, hist)
    character(len=*), intent(in) :: path
    type(history_t), intent(out) :: hist
    integer :: u, ios, ncol, nrow, k, icol
    character(len=4096) :: line
    character(len=64) :: name
    open(newunit=u, file=path, status='old', action='read', iostat=ios)
    if (ios /= 0) call fail('cannot open the history ' // path)
    ncol = 0
    nrow = 0
    do
      read(u, '(a)', iostat=ios) line
      if (ios /= 0) exit
      if (line(1:1) == "#") then
        read(line(3:), *, iostat=ios) icol
        if (ios == 0) ncol = max(ncol, icol)
      else if (line(1:1) /= '#' .and. len_trim(line) > 0) then
        nrow = nrow + 1
      end if
    end do
    if (ncol == 0 .or. nrow == 0) call fail('no columns or no rows in ' // path)
    allocate(hist%names(ncol), hist%rows(ncol, nrow))
    hist%names = ''
    rewind(u)
    k = 0
    do
      read(u, '(a)', iostat=ios) line
      if (ios /= 0) exit
      if (line(1:1) == '#') then
        read(line(3:), *, iostat=ios) icol, name
        if (ios == 0 .and. icol >= 1 .and. icol <= ncol) hist%names(icol) = name
      else if (len_trim(line) > 0) then
        k = k + 1
        read(line, *, iostat=ios) hist%rows(:, k)
        if (ios /= 0) call fail('bad history row in ' // path)
      end if
    end do
    close(u)
  end subroutine read_history

  !> Value of column `name` in row `irow` (default: the last row).
  real(wp) function history_value(hist, name, irow) result(v)
    type(history_t), intent(in) :: hist
    character(len=*), intent(in) :: name
    integer, intent(in), optional :: irow
    integer :: k, r
    r = size(hist%rows, 2)
    if (present(irow)) r = irow
    do k = 1, size(hist%names)
      if (hist%names(k) == name) then
        v = hist%rows(k, r)
        return
      end if
    end do
    call fail('the history has no column ' // name)
  end function history_value

  !> The row whose time is nearest to t.
  integer function history_row_at(hist, t) result(r)
    type(history_t), intent(in) :: hist
    real(wp), intent(in) :: t
    r = minloc(abs(hist%rows(1, :) - t), 1)
  end function history_row_at

  !> The piecewise-linear field through (xs, ps) at x; zero outside.
  pure real(wp) function interp(xs, ps, x) result(v)
    real(wp), intent(in) :: xs(:), ps(:), x
    integer :: lo, hi, mid
    v = 0.0_wp
    if (size(xs) < 2) return
    if (x < xs(1) .or. x > xs(size(xs))) return
    lo = 1
    hi = size(xs)
    do while (hi - lo > 1)
      mid = (lo + hi)/2
      if (xs(mid) <= x) then
        lo = mid
      else
        hi = mid
      end if
    end do
    v = ps(lo) + (ps(hi) - ps(lo))*(x - xs(lo))/max(xs(hi) - xs(lo), tiny(1.0_wp))
  end function interp

  !> Half-width of the zone where the piecewise-linear field is positive
  !> around its peak: on each side the zero crossing in the first interval
  !> where it changes sign (sub-node).
  pure real(wp) function zero_crossing_half_width(x, p) result(hw)
    real(wp), intent(in) :: x(:), p(:)
    integer :: ipk, i, n
    real(wp) :: left, right
    n = size(x)
    ipk = maxloc(p, 1)
    i = ipk
    do while (i < n)
      if (p(i + 1) <= 0.0_wp) exit
      i = i + 1
    end do
    right = x(i)
    if (i < n) right = x(i) + (x(i + 1) - x(i))*p(i)/(p(i) - p(i + 1))
    i = ipk
    do while (i > 1)
      if (p(i - 1) <= 0.0_wp) exit
      i = i - 1
    end do
    left = x(i)
    if (i > 1) left = x(i) + (x(i - 1) - x(i))*p(i)/(p(i) - p(i - 1))
    hw = 0.5_wp*(right - left)
  end function zero_crossing_half_width

  !> L2 norm over [-xmax, xmax] of samples f on the uniform grid of NGRID
  !> intervals (trapezoid rule).
  pure real(wp) function l2_norm_grid(f, xmax) result(s)
    real(wp), intent(in) :: f(0:NGRID), xmax
    real(wp) :: dx
    dx = 2.0_wp*xmax/real(NGRID, wp)
    s = sqrt(dx*(sum(f**2) - 0.5_wp*(f(0)**2 + f(NGRID)**2)))
  end function l2_norm_grid

  !> L2 distance over [-xmax, xmax] between the nodal profile (xs, ps) and
  !> the grid samples g.
  real(wp) function l2_distance(xs, ps, g, xmax) result(s)
    real(wp), intent(in) :: xs(:), ps(:), g(0:NGRID), xmax
    real(wp), allocatable :: f(:)
    real(wp) :: x
    integer :: k
    allocate(f(0:NGRID))
    do k = 0, NGRID
      x = -xmax + 2.0_wp*xmax*real(k, wp)/real(NGRID, wp)
      f(k) = interp(xs, ps, x) - g(k)
    end do
    s = l2_norm_grid(f, xmax)
  end function l2_distance
end module study_profile
