!> Benchmark helpers: in-memory structured meshes, a wall clock, peak memory.
module raccord_bench_util
  use raccord_kinds, only: wp, i8
  use raccord_mesh, only: ELEM_Q8
  implicit none
  private

  public :: structured_mesh, wall_time, peak_memory_kib, reset_peak_memory

contains

  !> nx x ny elements of type etype on [0, nx] x [0, ny], interior grid
  !> points moved by up to 0.2 h (fixed sine pattern) so no two elements are
  !> alike; nodes numbered row by row (the locality a meshing tool's
  !> renumbering would give).
  subroutine structured_mesh(etype, nx, ny, x, conn, stat)
    integer, intent(in) :: etype, nx, ny
    real(wp), allocatable, intent(out) :: x(:,:)
    integer, allocatable, intent(out) :: conn(:,:)
    integer, intent(out) :: stat
    integer, allocatable :: id(:,:)
    integer :: s, ni, nj, i, j, n, ie, je, e, i0, j0
    real(wp) :: h, px, py
    s = 1
    if (etype == ELEM_Q8) s = 2
    ni = s*nx
    nj = s*ny
    allocate(id(0:ni, 0:nj), stat=stat)
    if (stat /= 0) return
    id = 0
    n = 0
    do j = 0, nj
      do i = 0, ni
        if (s == 2 .and. mod(i, 2) == 1 .and. mod(j, 2) == 1) cycle
        n = n + 1
        id(i, j) = n
      end do
    end do
    allocate(x(2, n), conn(4*s, nx*ny), stat=stat)
    if (stat /= 0) return
    h = 1.0_wp/real(s, wp)
    do j = 0, nj
      do i = 0, ni
        if (id(i, j) == 0) cycle
        px = 0.0_wp
        py = 0.0_wp
        if (i > 0 .and. i < ni) px = 0.2_wp*h*sin(1.7_wp*real(i, wp) + 2.3_wp*real(j, wp))
        if (j > 0 .and. j < nj) py = 0.2_wp*h*cos(2.9_wp*real(i, wp) - 1.3_wp*real(j, wp))
        x(:, id(i, j)) = [real(i, wp)*h + px, real(j, wp)*h + py]
      end do
    end do
    do je = 1, ny
      do ie = 1, nx
        e = ie + nx*(je - 1)
        i0 = s*(ie - 1)
        j0 = s*(je - 1)
        conn(1:4, e) = [id(i0, j0), id(i0 + s, j0), id(i0 + s, j0 + s), id(i0, j0 + s)]
        if (s == 2) conn(5:8, e) = [id(i0 + 1, j0), id(i0 + 2, j0 + 1), id(i0 + 1, j0 + 2), id(i0, j0 + 1)]
      end do
    end do
  end subroutine structured_mesh

  !> Wall-clock seconds from an arbitrary origin.
  real(wp) function wall_time()
    integer(i8) :: count, rate
    call system_clock(count, rate)
    wall_time = real(count, wp)/real(rate, wp)
  end function wall_time

  !> Peak resident memory (VmHWM of /proc/self/status) in KiB, -1 if unknown.
  integer(i8) function peak_memory_kib()
    character(len=256) :: line
    integer :: unit, ios
    peak_memory_kib = -1
    open(newunit=unit, file='/proc/self/status', action='read', status='old', iostat=ios)
    if (ios /= 0) return
    do
      read(unit, '(a)', iostat=ios) line
      if (ios /= 0) exit
      if (line(1:6) == 'VmHWM:') then
        read(line(7:), *, iostat=ios) peak_memory_kib
        if (ios /= 0) peak_memory_kib = -1
        exit
      end if
    end do
    close(unit)
  end function peak_memory_kib

  !> Reset VmHWM to the current resident size (Linux: write 5 to
  !> /proc/self/clear_refs) so each case reports its own peak. Silent when the
  !> kernel refuses: the peak then accumulates over the cases.
  subroutine reset_peak_memory()
    integer :: unit, ios
    open(newunit=unit, file='/proc/self/clear_refs', action='write', status='old', iostat=ios)
    if (ios /= 0) return
    write(unit, '(a)', iostat=ios) '5'
    close(unit, iostat=ios)
  end subroutine reset_peak_memory
end module raccord_bench_util
