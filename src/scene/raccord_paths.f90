!> File-path helpers for the scene deck: a path's folder, base name and stem,
!> joining a relative path to a folder, and the current directory.
!>
!> Paths are POSIX ('/' separated). The current directory comes from POSIX
!> getcwd through standard C interoperability (Fortran 2008 has no intrinsic
!> for it): the scene stores absolute paths, so that a run, or a re-read of
!> the echoed scene, finds the same files whatever folder it starts from.
module raccord_paths
  use, intrinsic :: iso_c_binding, only: c_char, c_ptr, c_size_t, c_null_char, c_associated
  implicit none
  private

  public :: is_absolute, path_dir, path_base, path_stem, path_join, current_dir, absolute_path, normal_path

  interface
    !> POSIX getcwd(3): fills buf, returns NULL when the path does not fit.
    function c_getcwd(buf, size) bind(C, name='getcwd') result(p)
      import :: c_char, c_ptr, c_size_t
      character(kind=c_char), intent(out) :: buf(*)
      integer(c_size_t), value :: size
      type(c_ptr) :: p
    end function c_getcwd
  end interface

contains

  !> True for a path starting at the root ('/').
  pure logical function is_absolute(path)
    character(len=*), intent(in) :: path
    is_absolute = .false.
    if (len(path) > 0) is_absolute = path(1:1) == '/'
  end function is_absolute

  !> Folder part of a path: 'a/b/c.nml' -> 'a/b', 'c.nml' -> '.', '/c.nml' -> '/'.
  pure function path_dir(path) result(dir)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: dir
    integer :: k
    k = index(path, '/', back=.true.)
    if (k == 0) then
      dir = '.'
    else if (k == 1) then
      dir = '/'
    else
      dir = path(1:k-1)
    end if
  end function path_dir

  !> Last component of a path: 'a/b/c.nml' -> 'c.nml'.
  pure function path_base(path) result(base)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: base
    base = path(index(path, '/', back=.true.)+1:)
  end function path_base

  !> Base name without its last extension: 'a/disc.block.nml' -> 'disc.block'.
  !> A leading dot is part of the name ('.nml' stays '.nml').
  pure function path_stem(path) result(stem)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: stem
    integer :: k
    stem = path_base(path)
    k = index(stem, '.', back=.true.)
    if (k > 1) stem = stem(1:k-1)
  end function path_stem

  !> rel resolved against dir; an absolute rel is returned unchanged and
  !> leading './' components are dropped so stored paths stay readable.
  pure function path_join(dir, rel) result(path)
    character(len=*), intent(in) :: dir, rel
    character(len=:), allocatable :: path
    character(len=:), allocatable :: r
    if (is_absolute(rel) .or. len(dir) == 0) then
      path = rel
      return
    end if
    r = rel
    do while (len(r) >= 2)
      if (r(1:2) /= './') exit
      r = r(3:)
    end do
    if (r == '.' .or. len(r) == 0) then
      path = dir
    else if (dir == '.') then
      path = r
    else if (dir(len(dir):len(dir)) == '/') then
      path = dir // r
    else
      path = dir // '/' // r
    end if
  end function path_join

  !> The process's current directory, or '' when the system cannot tell.
  function current_dir() result(dir)
    character(len=:), allocatable :: dir
    integer, parameter :: buf_len = 4096
    character(kind=c_char) :: buf(buf_len)
    type(c_ptr) :: p
    integer :: k
    dir = ''
    p = c_getcwd(buf, int(buf_len, c_size_t))
    if (.not. c_associated(p)) return
    do k = 1, buf_len
      if (buf(k) == c_null_char) exit
      dir = dir // buf(k)
    end do
  end function current_dir

  !> path made absolute against the current directory (unchanged when it is
  !> already absolute or the current directory is unknown).
  function absolute_path(path) result(abs_path)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: abs_path
    character(len=:), allocatable :: cwd
    if (is_absolute(path)) then
      abs_path = path
      return
    end if
    cwd = current_dir()
    if (len(cwd) == 0) then
      abs_path = path
    else
      abs_path = path_join(cwd, path)
    end if
  end function absolute_path

  !> absolute_path with its '.' and empty components dropped and each '..'
  !> taken back, so that two spellings of one path compare equal (symbolic
  !> links are not followed).
  function normal_path(path) result(np)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: np
    character(len=:), allocatable :: a, part
    integer :: i, j, cut
    a = absolute_path(path)
    np = ''
    i = 1
    do while (i <= len(a))
      j = index(a(i:), '/')
      if (j == 0) then
        j = len(a) + 1
      else
        j = i + j - 1
      end if
      part = a(i:j - 1)
      i = j + 1
      if (len(part) == 0 .or. part == '.') cycle
      if (part == '..') then
        cut = index(np, '/', back=.true.)
        if (cut > 0) np = np(1:cut - 1)
        cycle
      end if
      np = np // '/' // part
    end do
    if (len(np) == 0) np = '/'
  end function normal_path
end module raccord_paths
