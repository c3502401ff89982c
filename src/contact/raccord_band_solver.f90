!> Banded LU with partial pivoting and the solve with it, for the small
!> banded systems of the multiplier solve (raccord_multiplier_solver): the
!> algorithm of LAPACK's unblocked dgbtf2 and dgbtrs (row interchanges
!> within the band, fill-in kept in the kl extra rows of the storage) in
!> plain loops. The contact systems have a few hundred unknowns and a half
!> bandwidth of 3 to 20; there the reference BLAS spends most of its time in
!> the call overhead of one idamax, dswap, dscal and dger per column (issue
!> #16: the solve was half of the contact time with friction). The
!> arithmetic is that of dgbsv, so results agree with it to round-off.
!>
!> Storage is LAPACK's general band form: A(i, j) in ab(kl + ku + 1 + i - j, j),
!> rows 1:kl of ab are workspace for the fill-in.
module raccord_band_solver
  use raccord_kinds, only: wp
  implicit none
  private

  public :: band_solve, band_factor, band_subst, band_cholesky_solve, zero_band

  !> A Cholesky pivot below this fraction of its diagonal entry means a row
  !> (nearly) dependent on the ones before it: reported as singular.
  real(wp), parameter :: CHOL_TOL = 1.0e-10_wp

contains

  !> Solve A x = b in place (b becomes x); info = j > 0 when U(j, j) = 0
  !> (A singular; b is then left partly transformed). ab holds A in band
  !> form and zeros elsewhere (the kl fill rows too). Row i of A has its
  !> nonzeros in columns fcol(i) .. lcol(i), within the band, with fcol
  !> nondecreasing up to round-off of the profile (any row order is right,
  !> a monotone one is fast). The elimination of column j then touches only
  !> the rows that reach it and the columns the pivot row reaches, so the
  !> work follows the local band: a contact zone in stick has half the
  !> unknowns per node of an open one, and pays for its own band only.
  pure subroutine band_solve(n, kl, ku, ab, ipiv, b, fcol, lcol, ext, info)
    integer, intent(in) :: n, kl, ku
    real(wp), intent(inout) :: ab(:,:)        !< (2*kl + ku + 1, >= n)
    integer, intent(inout) :: ipiv(:)         !< (>= n) pivot rows
    real(wp), intent(inout) :: b(:)           !< (>= n) right-hand side in, solution out
    integer, intent(in) :: fcol(:), lcol(:)   !< (n) first and last nonzero column of each row
    integer, intent(inout) :: ext(:)          !< (>= 3 n) scratch: row extents, then last row reaching each column
    integer, intent(out) :: info
    call band_factor(n, kl, ku, ab, ipiv, fcol, lcol, ext, info)
    if (info /= 0) return
    call band_subst(n, kl, ku, ab, ipiv, ext, b)
  end subroutine band_solve

  !> The factorisation of band_solve alone (A = P L U in place, same
  !> arguments): band_subst then solves with it for any number of
  !> right-hand sides (ext(n + 1 : 2 n) keeps the extent of each column of
  !> L, ext(2 n + 1 : 3 n) that of each column of U).
  pure subroutine band_factor(n, kl, ku, ab, ipiv, fcol, lcol, ext, info)
    integer, intent(in) :: n, kl, ku
    real(wp), intent(inout) :: ab(:,:)        !< (2*kl + ku + 1, >= n)
    integer, intent(inout) :: ipiv(:)         !< (>= n) pivot rows
    integer, intent(in) :: fcol(:), lcol(:)   !< (n) first and last nonzero column of each row
    integer, intent(inout) :: ext(:)          !< (>= 3 n) scratch: row extents, then last row reaching each column
    integer, intent(out) :: info
    integer :: kv, j, i, jp, km, jj, l, off, last, jl, r
    real(wp) :: amax, piv_inv, t, y

    info = 0
    kv = ku + kl
    ! ext(n + c): the last row whose first column is <= c (rows below it
    ! are zero in column c until it is eliminated).
    ext(n + 1:2*n) = 0
    do i = 1, n
      ext(n + fcol(i)) = max(ext(n + fcol(i)), i)
    end do
    last = 0
    do j = 1, n
      last = max(last, ext(n + j))
      ext(n + j) = last
    end do
    ! ext(i): the last column with a nonzero in the row now at position i
    ! (grows with fill, moves with the row interchanges).
    ext(1:n) = lcol(1:n)
    columns: do j = 1, n
      km = min(kl, n - j, ext(n + j) - j)
      ! Pivot: the first entry of largest magnitude in column j below the diagonal.
      jp = 1
      amax = abs(ab(kv + 1, j))
      do i = 2, km + 1
        if (abs(ab(kv + i, j)) > amax) then
          amax = abs(ab(kv + i, j))
          jp = i
        end if
      end do
      ipiv(j) = jp + j - 1
      if (ab(kv + jp, j) == 0.0_wp) then
        if (info == 0) info = j
        cycle columns
      end if
      if (jp /= 1) then
        ! Swap rows j and j + jp - 1 over the columns either reaches (a row
        ! runs along a diagonal of the band storage).
        r = j + jp - 1
        jl = max(ext(j), ext(r))
        do jj = 0, jl - j
          t = ab(kv + jp - jj, j + jj)
          ab(kv + jp - jj, j + jj) = ab(kv + 1 - jj, j + jj)
          ab(kv + 1 - jj, j + jj) = t
        end do
        l = ext(j)
        ext(j) = ext(r)
        ext(r) = l
      end if
      if (km > 0) then
        piv_inv = 1.0_wp/ab(kv + 1, j)
        ab(kv + 2:kv + km + 1, j) = piv_inv*ab(kv + 2:kv + km + 1, j)
        ! Rank-one update of the rows below over the pivot row's columns.
        jl = min(ext(j), n)
        do jj = 1, jl - j
          y = ab(kv + 1 - jj, j + jj)
          if (y == 0.0_wp) cycle
          off = kv + 1 - jj
          do i = 1, km
            ab(off + i, j + jj) = ab(off + i, j + jj) - ab(kv + 1 + i, j)*y
          end do
        end do
        do i = j + 1, j + km
          ext(i) = max(ext(i), jl)
        end do
      end if
      ! Keep km for the forward substitution (column j of L).
      ext(n + j) = j + km
    end do columns
    if (info /= 0) return
    ! ext(2 n + j): the first row of U reaching column j (from the rows'
    ! last columns, ext(1:n)), so that the back substitution skips the
    ! zeros above it (the same operations on the nonzeros, in the same order).
    ext(2*n + 1:3*n) = n + 1
    do i = 1, n
      l = min(ext(i), n)
      ext(2*n + l) = min(ext(2*n + l), i)
    end do
    last = n + 1
    do j = n, 1, -1
      last = min(last, ext(2*n + j), j)
      ext(2*n + j) = last
    end do
  end subroutine band_factor

  !> Solve A x = b in place with the factors of band_factor.
  pure subroutine band_subst(n, kl, ku, ab, ipiv, ext, b)
    integer, intent(in) :: n, kl, ku
    real(wp), intent(in) :: ab(:,:)           !< factors from band_factor
    integer, intent(in) :: ipiv(:), ext(:)    !< pivots and column extents from band_factor
    real(wp), intent(inout) :: b(:)           !< (>= n) right-hand side in, solution out
    integer :: kv, j, i, km, l
    real(wp) :: t
    kv = ku + kl

    ! Forward: L with the row interchanges.
    do j = 1, n - 1
      km = ext(n + j) - j
      l = ipiv(j)
      if (l /= j) then
        t = b(l)
        b(l) = b(j)
        b(j) = t
      end if
      t = b(j)
      if (t == 0.0_wp) cycle
      do i = 1, km
        b(j + i) = b(j + i) - ab(kv + 1 + i, j)*t
      end do
    end do
    ! Backward: U, upper band of width kl + ku.
    do j = n, 1, -1
      if (b(j) == 0.0_wp) cycle
      b(j) = b(j)/ab(kv + 1, j)
      t = b(j)
      l = kv + 1 - j
      do i = j - 1, max(1, j - kv, ext(2*n + j)), -1
        b(i) = b(i) - t*ab(l + i, j)
      end do
    end do
  end subroutine band_subst

  !> Zero the first n entries of a band store in one pass: the caller
  !> passes the store (whole columns, contiguous) and n = leading extent x
  !> columns. Zeroing a section of whole columns, a(:, 1:m), gfortran
  !> writes as one memset call per column, for columns of 5-40 entries
  !> (about 120 calls per step on Fig. 2(a); issue #16, eighth pass,
  !> doc/performance.md).
  pure subroutine zero_band(n, a)
    integer, intent(in) :: n
    real(wp), intent(inout) :: a(n)
    a = 0.0_wp
  end subroutine zero_band

  !> Solve R x = b in place for R symmetric positive definite with half
  !> band kr, by band Cholesky R = L L' (left-looking, plain loops: the
  !> Delassus systems of the multiplier solve have half bands of 2 to 10,
  !> where a library call costs more than its arithmetic). rb holds the
  !> lower band, rb(d + 1, k) = R(k + d, k), and returns L in its place.
  !> info = j > 0 when the j-th pivot is not above CHOL_TOL of R(j, j)
  !> (R singular or not positive definite to working precision; b is then
  !> left partly transformed).
  pure subroutine band_cholesky_solve(n, kr, rb, b, info)
    integer, intent(in) :: n, kr
    real(wp), intent(inout) :: rb(:,:)        !< (>= kr + 1, >= n)
    real(wp), intent(inout) :: b(:)           !< (>= n) right-hand side in, solution out
    integer, intent(out) :: info
    integer :: i, j, k
    real(wp) :: s, t
    info = 0
    do j = 1, n
      s = rb(1, j)
      do k = max(1, j - kr), j - 1
        s = s - rb(j - k + 1, k)**2
      end do
      if (.not. (s > CHOL_TOL*rb(1, j))) then
        info = j
        return
      end if
      s = sqrt(s)
      rb(1, j) = s
      ! L y = b, row j, as soon as row j of L is complete (L(j, k), k <= j:
      ! the columns before and this pivot): the same operations in the same
      ! order as a forward pass after the factorisation, but its chain of
      ! dependent divisions now overlaps the factorisation's chain of
      ! square roots and divisions (issue #16, ninth pass).
      t = b(j)
      do k = max(1, j - kr), j - 1
        t = t - rb(j - k + 1, k)*b(k)
      end do
      b(j) = t/s
      do i = j + 1, min(n, j + kr)
        t = rb(i - j + 1, j)
        do k = max(1, i - kr), j - 1
          t = t - rb(i - k + 1, k)*rb(j - k + 1, k)
        end do
        rb(i - j + 1, j) = t/s
      end do
    end do
    ! L' x = y.
    do j = n, 1, -1
      t = b(j)
      do i = j + 1, min(n, j + kr)
        t = t - rb(i - j + 1, j)*b(i)
      end do
      b(j) = t/rb(1, j)
    end do
  end subroutine band_cholesky_solve
end module raccord_band_solver
