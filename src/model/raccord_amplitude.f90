!> Amplitude tables: piecewise-linear functions of time, constant beyond
!> their first and last points (the paper's down-and-back displacement
!> cycle is the table 0 -> 1 -> 0).
module raccord_amplitude
  use raccord_kinds, only: wp
  implicit none
  private

  public :: interpolate_table

contains

  !> Value of the table (t(:), a(:)) at time `time`; t strictly increasing.
  pure real(wp) function interpolate_table(t, a, time) result(val)
    real(wp), intent(in) :: t(:), a(:)
    real(wp), intent(in) :: time
    integer :: lo, hi, mid
    integer :: n
    n = size(t)
    if (time <= t(1)) then
      val = a(1)
      return
    end if
    if (time >= t(n)) then
      val = a(n)
      return
    end if
    ! Bisection: t(lo) <= time < t(hi).
    lo = 1
    hi = n
    do while (hi - lo > 1)
      mid = (lo + hi)/2
      if (t(mid) <= time) then
        lo = mid
      else
        hi = mid
      end if
    end do
    val = a(lo) + (a(hi) - a(lo))*(time - t(lo))/(t(hi) - t(lo))
  end function interpolate_table
end module raccord_amplitude
