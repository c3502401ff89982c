!> Working precision and the few numeric constants shared by every module.
module raccord_kinds
  use, intrinsic :: iso_fortran_env, only: real64, int64
  implicit none
  private

  !> Working real kind: every real in raccord is real(wp) and every literal carries _wp.
  integer, parameter, public :: wp = real64
  !> Integer kind for counters that may exceed 2**31 (step counts times elements, bytes).
  integer, parameter, public :: i8 = int64

  real(wp), parameter, public :: pi = 3.14159265358979323846264338327950288_wp
  real(wp), parameter, public :: zero = 0.0_wp, one = 1.0_wp, half = 0.5_wp

  !> Length of fixed-size names (sets, bodies, keys) in namelist-facing types.
  integer, parameter, public :: name_len = 64
  !> Length of file paths and free text in namelist-facing types.
  integer, parameter, public :: path_len = 512
end module raccord_kinds
