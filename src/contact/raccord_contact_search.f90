!> Contact search by binning: the master segments are sorted into a uniform
!> grid of cells on the current geometry, and each slave node looks only at
!> the segments of its own cell. Building and querying are O(n) in surface
!> nodes. raccord_contact_verlet builds it only when the surfaces have
!> moved by more than a skin distance, with boxes padded by that skin.
!> Memory is kept between steps and grows only when a surface needs more.
module raccord_contact_search
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use raccord_kinds, only: wp
  implicit none
  private

  type, public :: bins_t
    integer :: nx = 0, ny = 0
    real(wp) :: origin(2) = 0.0_wp
    real(wp) :: cell = 1.0_wp
    integer, allocatable :: head(:)        !< (nx*ny + 1) CSR start of each cell
    integer, allocatable :: item(:)        !< segment indices, cell by cell
    integer, allocatable :: count(:)
    real(wp), allocatable :: box(:,:)      !< (4, nseg) inflated bounding boxes
  end type bins_t

  public :: build_bins, query_bins

contains

  !> Bin the segments seg(:, 1:nseg) (nodes of x). Each segment's box is
  !> inflated by its own length, capped by `reach`: a slave node further
  !> than that from a segment along its normal is not its concern this step
  !> (a step moves nodes by a small fraction of an element). Cells have the
  !> mean inflated box size, so a node sees a few segments wherever the
  !> surface is refined; large distant segments span several cells.
  !> With `skin`, every box is inflated by
  !> min(reach, length + skin) + skin: the bound, over every later position
  !> with no node moved by more than skin/2, of the inflation plus the
  !> relative motion of the two boxes (the candidate lists of
  !> raccord_contact_verlet, built for several steps).
  subroutine build_bins(bins, x, seg, nen, reach, skin)
    type(bins_t), intent(inout) :: bins
    real(wp), intent(in) :: x(:,:)
    integer, intent(in) :: seg(:,:), nen
    real(wp), intent(in) :: reach
    real(wp), intent(in), optional :: skin
    integer :: k, j, nseg, i0, i1, j0, j1, ii, jj, c, total
    real(wp) :: lo(2), hi(2), gl(2), gh(2), r, mean_size
    nseg = size(seg, 2)
    if (.not. allocated(bins%box)) allocate(bins%box(4, nseg))
    if (size(bins%box, 2) < nseg) then
      deallocate(bins%box)
      allocate(bins%box(4, nseg))
    end if
    gl = huge(1.0_wp)
    gh = -huge(1.0_wp)
    mean_size = 0.0_wp
    do k = 1, nseg
      lo = x(:, seg(1, k))
      hi = lo
      do j = 2, nen
        lo = min(lo, x(:, seg(j, k)))
        hi = max(hi, x(:, seg(j, k)))
      end do
      r = min(reach, norm2(x(:, seg(2, k)) - x(:, seg(1, k))))
      if (present(skin)) r = min(reach, norm2(x(:, seg(2, k)) - x(:, seg(1, k))) + skin) + skin
      ! A quadratic edge bulges beyond the box of its nodes by less than its
      ! own length for any sane mesh: the inflation covers it.
      bins%box(:, k) = [lo - r, hi + r]
      gl = min(gl, lo - r)
      gh = max(gh, hi + r)
      mean_size = mean_size + maxval(hi - lo) + 2.0_wp*r
    end do
    bins%cell = max(mean_size/real(max(nseg, 1), wp), tiny(1.0_wp))
    ! Extents that overflow (a search distance near huge) or are not finite
    ! (a NaN position) would never bring the cell count below the bound
    ! (an endless loop): one cell holding every segment then (a fuzz input
    ! check; the time loop stops a non-finite motion before the search).
    if (.not. (all(ieee_is_finite(gh - gl)) .and. ieee_is_finite(bins%cell))) then
      bins%cell = huge(1.0_wp)
      bins%nx = 1
      bins%ny = 1
      gl = 0.0_wp
    else
      do while (real(ceiling((gh(1) - gl(1))/bins%cell), wp)*real(ceiling((gh(2) - gl(2))/bins%cell), wp) > &
                4.0_wp*real(nseg, wp) + 16.0_wp)
        bins%cell = 2.0_wp*bins%cell
      end do
      bins%nx = max(1, ceiling((gh(1) - gl(1))/bins%cell))
      bins%ny = max(1, ceiling((gh(2) - gl(2))/bins%cell))
    end if
    bins%origin = gl
    call ensure(bins%count, bins%nx*bins%ny)
    call ensure(bins%head, bins%nx*bins%ny + 1)
    bins%count(1:bins%nx*bins%ny) = 0
    do k = 1, nseg
      call cell_range(bins, bins%box(:, k), i0, i1, j0, j1)
      do jj = j0, j1
        do ii = i0, i1
          c = ii + (jj - 1)*bins%nx
          bins%count(c) = bins%count(c) + 1
        end do
      end do
    end do
    bins%head(1) = 1
    do c = 1, bins%nx*bins%ny
      bins%head(c + 1) = bins%head(c) + bins%count(c)
    end do
    total = bins%head(bins%nx*bins%ny + 1) - 1
    call ensure(bins%item, total)
    bins%count(1:bins%nx*bins%ny) = 0
    do k = 1, nseg
      call cell_range(bins, bins%box(:, k), i0, i1, j0, j1)
      do jj = j0, j1
        do ii = i0, i1
          c = ii + (jj - 1)*bins%nx
          bins%item(bins%head(c) + bins%count(c)) = k
          bins%count(c) = bins%count(c) + 1
        end do
      end do
    end do
  end subroutine build_bins

  !> Segments whose inflated box contains p: item(first:last) of the cell,
  !> filtered by the caller with bins%box. first > last when p is outside.
  pure subroutine query_bins(bins, p, first, last)
    type(bins_t), intent(in) :: bins
    real(wp), intent(in) :: p(2)
    integer, intent(out) :: first, last
    integer :: i, j, c
    first = 1
    last = 0
    if (bins%cell == huge(1.0_wp)) then         ! the one-cell fallback of build_bins
      first = bins%head(1)
      last = bins%head(2) - 1
      return
    end if
    i = floor((p(1) - bins%origin(1))/bins%cell) + 1
    j = floor((p(2) - bins%origin(2))/bins%cell) + 1
    if (i < 1 .or. i > bins%nx .or. j < 1 .or. j > bins%ny) return
    c = i + (j - 1)*bins%nx
    first = bins%head(c)
    last = bins%head(c + 1) - 1
  end subroutine query_bins

  pure subroutine cell_range(bins, box, i0, i1, j0, j1)
    type(bins_t), intent(in) :: bins
    real(wp), intent(in) :: box(4)
    integer, intent(out) :: i0, i1, j0, j1
    if (bins%cell == huge(1.0_wp)) then         ! the one-cell fallback of build_bins
      i0 = 1
      i1 = 1
      j0 = 1
      j1 = 1
      return
    end if
    i0 = max(1, floor((box(1) - bins%origin(1))/bins%cell) + 1)
    j0 = max(1, floor((box(2) - bins%origin(2))/bins%cell) + 1)
    i1 = min(bins%nx, floor((box(3) - bins%origin(1))/bins%cell) + 1)
    j1 = min(bins%ny, floor((box(4) - bins%origin(2))/bins%cell) + 1)
  end subroutine cell_range

  !> Grow-only integer buffer.
  subroutine ensure(a, n)
    integer, allocatable, intent(inout) :: a(:)
    integer, intent(in) :: n
    if (allocated(a)) then
      if (size(a) >= n) return
      deallocate(a)
    end if
    allocate(a(max(n, 1)))
  end subroutine ensure
end module raccord_contact_search
