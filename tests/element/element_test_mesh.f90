!> Structured, deterministically distorted Q4/Q8 meshes for the element tests.
module element_test_mesh
  use raccord_kinds, only: wp
  use raccord_mesh, only: ELEM_Q4, ELEM_Q8
  implicit none
  private

  public :: make_mesh

contains

  !> nx x ny elements on [0, lx] x [0, ly]. Interior grid points move by up to
  !> amp*h (a fixed sine pattern); for Q8 the mid-side points move too, so
  !> edges are curved. boundary(n) marks nodes on the outer rectangle.
  subroutine make_mesh(etype, nx, ny, lx, ly, amp, x, conn, boundary)
    integer, intent(in) :: etype, nx, ny
    real(wp), intent(in) :: lx, ly, amp
    real(wp), allocatable, intent(out) :: x(:,:)
    integer, allocatable, intent(out) :: conn(:,:)
    logical, allocatable, intent(out) :: boundary(:)
    integer, allocatable :: id(:,:)
    integer :: s, ni, nj, i, j, n, ie, je, e, i0, j0
    real(wp) :: hx, hy, px, py
    s = 1
    if (etype == ELEM_Q8) s = 2
    ni = s*nx
    nj = s*ny
    allocate(id(0:ni, 0:nj))
    id = 0
    n = 0
    do j = 0, nj
      do i = 0, ni
        if (s == 2 .and. mod(i, 2) == 1 .and. mod(j, 2) == 1) cycle
        n = n + 1
        id(i, j) = n
      end do
    end do
    allocate(x(2, n), boundary(n))
    hx = lx/real(ni, wp)
    hy = ly/real(nj, wp)
    do j = 0, nj
      do i = 0, ni
        if (id(i, j) == 0) cycle
        px = 0.0_wp
        py = 0.0_wp
        if (i > 0 .and. i < ni) px = amp*hx*sin(1.7_wp*real(i, wp) + 2.3_wp*real(j, wp))
        if (j > 0 .and. j < nj) py = amp*hy*cos(2.9_wp*real(i, wp) - 1.3_wp*real(j, wp))
        x(:, id(i, j)) = [real(i, wp)*hx + px, real(j, wp)*hy + py]
        boundary(id(i, j)) = i == 0 .or. i == ni .or. j == 0 .or. j == nj
      end do
    end do
    allocate(conn(4*s, nx*ny))
    do je = 1, ny
      do ie = 1, nx
        e = ie + nx*(je - 1)
        i0 = s*(ie - 1)
        j0 = s*(je - 1)
        conn(1:4, e) = [id(i0, j0), id(i0 + s, j0), id(i0 + s, j0 + s), id(i0, j0 + s)]
        if (s == 2) conn(5:8, e) = [id(i0 + 1, j0), id(i0 + 2, j0 + 1), id(i0 + 1, j0 + 2), id(i0, j0 + 1)]
      end do
    end do
  end subroutine make_mesh
end module element_test_mesh
