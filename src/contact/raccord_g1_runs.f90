!> Solves with the blocks of G1 over runs of eliminated constraints (a run:
!> constraints less than g1_band + 1 apart, so that G1 restricted to the
!> eliminated ones is block diagonal over the runs), shared by the reduced
!> forms of the multiplier solve (doc/theory-contact.md, section 3).
module raccord_g1_runs
  use raccord_kinds, only: wp
  use raccord_constraint_set, only: constraint_set_t
  use raccord_band_solver, only: band_solve, band_factor, band_subst, zero_band
  use raccord_solver_work, only: solver_work_t, ZMAX, ensure2
  implicit none
  private

  public :: open_from_active, run_transposed, run_solve

contains

  !> Solve G1_CC' x = v in place over each run C of list (constraints less
  !> than g1_band + 1 apart): v holds the right-hand sides at the list's
  !> constraints and returns the solution there.
  subroutine run_transposed(cs, list, nl, v, w, info)
    type(constraint_set_t), intent(in) :: cs
    integer, intent(in) :: list(:), nl
    real(wp), intent(inout) :: v(:)
    type(solver_work_t), intent(inout) :: w
    integer, intent(out) :: info
    integer :: p1, p2, p, nc
    info = 0
    p1 = 1
    do while (p1 <= nl)
      p2 = p1
      do while (p2 < nl)
        if (list(p2 + 1) - list(p2) > cs%g1_band) exit
        p2 = p2 + 1
      end do
      nc = p2 - p1 + 1
      if (nc == 1) then
        if (cs%g1(0, list(p1)) == 0.0_wp) then
          info = -1
          return
        end if
        v(list(p1)) = v(list(p1))/cs%g1(0, list(p1))
      else
        do p = p1, p2
          w%xr(p - p1 + 1) = v(list(p))
        end do
        call run_solve(cs, list, p1, nc, .true., w, info)
        if (info /= 0) return
        do p = p1, p2
          v(list(p)) = w%xr(p - p1 + 1)
        end do
      end if
      p1 = p2 + 1
    end do
  end subroutine run_transposed

  !> Z = -G1_OO^-1 G1_OA run by run: an open run is a maximal sequence of
  !> open constraints less than g1_band + 1 apart (G1_OO is block diagonal
  !> over the runs); its columns are the active constraints within
  !> g1_band of it. Row p of Z (open constraint olist(p)) is kept as up to
  !> ZMAX (column, value) pairs.
  subroutine open_from_active(cs, olist, no, ia, zcnt, zcol, zval, w, info)
    type(constraint_set_t), intent(in) :: cs
    integer, intent(in) :: olist(:)              !< (no) the eliminated constraints, in order
    integer, intent(in) :: no
    integer, intent(in) :: ia(:)                 !< (m) > 0: a kept constraint (a column of Z)
    integer, intent(inout) :: zcnt(:), zcol(:,:)
    real(wp), intent(inout) :: zval(:,:)
    type(solver_work_t), intent(inout) :: w
    integer, intent(out) :: info
    integer :: p1, p2, p, nc, b, g1b, ldab
    real(wp) :: g
    logical :: nz, factored
    info = 0
    ldab = 3*cs%g1_band + 1
    g1b = cs%g1_band
    p1 = 1
    runs: do while (p1 <= no)
      p2 = p1
      do while (p2 < no)
        if (olist(p2 + 1) - olist(p2) > g1b) exit
        p2 = p2 + 1
      end do
      nc = p2 - p1 + 1
      zcnt(p1:p2) = 0
      factored = .false.
      do b = max(1, olist(p1) - g1b), min(cs%m, olist(p2) + g1b)
        if (ia(b) <= 0) cycle
        nz = .false.
        do p = p1, p2
          ! -G1(olist(p), b), read from the band here (an inlined g1_at)
          g = 0.0_wp
          if (abs(olist(p) - b) <= g1b) g = cs%g1(olist(p) - b, b)
          w%xr(p - p1 + 1) = -g
          nz = nz .or. w%xr(p - p1 + 1) /= 0.0_wp
        end do
        if (.not. nz) cycle
        ! G1_CC factored once per run, at its first column (fifth pass:
        ! band_solve per column repeated the factorisation; band_factor
        ! and band_subst are its two halves, the same arithmetic)
        if (.not. factored) then
          call run_matrix(cs, olist, p1, nc, .false., w)
          call band_factor(nc, g1b, g1b, w%ab(1:ldab, 1:nc), w%ipiv, w%fcol, w%lcol, w%ext, info)
          if (info /= 0) return
          factored = .true.
        end if
        call band_subst(nc, g1b, g1b, w%ab(1:ldab, 1:nc), w%ipiv, w%ext, w%xr)
        do p = p1, p2
          if (w%xr(p - p1 + 1) == 0.0_wp) cycle
          if (zcnt(p) == ZMAX) then
            info = -1
            return
          end if
          zcnt(p) = zcnt(p) + 1
          zcol(zcnt(p), p) = b
          zval(zcnt(p), p) = w%xr(p - p1 + 1)
        end do
      end do
      p1 = p2 + 1
    end do runs
  end subroutine open_from_active

  !> Solve G1_CC x = xr (or G1_CC' x = xr) in place for the open run
  !> olist(p1 : p1 + nc - 1), with the band LU.
  subroutine run_solve(cs, olist, p1, nc, transposed, w, info)
    type(constraint_set_t), intent(in) :: cs
    integer, intent(in) :: olist(:)       !< the constraints of the runs
    integer, intent(in) :: p1, nc
    logical, intent(in) :: transposed
    type(solver_work_t), intent(inout) :: w
    integer, intent(out) :: info
    integer :: g1b, ldab
    g1b = cs%g1_band
    ldab = 3*g1b + 1
    call run_matrix(cs, olist, p1, nc, transposed, w)
    call band_solve(nc, g1b, g1b, w%ab(1:ldab, 1:nc), w%ipiv, w%xr, w%fcol, w%lcol, w%ext, info)
  end subroutine run_solve

  !> G1_CC (or G1_CC') of the open run olist(p1 : p1 + nc - 1) in w%ab
  !> (band storage of dgbsv, kl = ku = g1_band) with each row's profile.
  subroutine run_matrix(cs, olist, p1, nc, transposed, w)
    type(constraint_set_t), intent(in) :: cs
    integer, intent(in) :: olist(:)       !< the constraints of the runs
    integer, intent(in) :: p1, nc
    logical, intent(in) :: transposed
    type(solver_work_t), intent(inout) :: w
    integer :: g1b, ldab, p, q, jp, jq
    g1b = cs%g1_band
    ldab = 3*g1b + 1
    call ensure2(w%ab, ldab, nc)
    ! whole columns of w%ab in one pass (zero_band: the section (1:ldab, 1:nc)
    ! was one memset call per column; rows below ldab are not read)
    call zero_band(size(w%ab, 1)*nc, w%ab)
    do p = 1, nc
      jp = olist(p1 - 1 + p)
      w%fcol(p) = max(1, p - g1b)
      w%lcol(p) = min(nc, p + g1b)
      do q = w%fcol(p), w%lcol(p)
        jq = olist(p1 - 1 + q)
        ! band storage of dgbsv: A(p, q) in ab(kl + ku + 1 + p - q, q);
        ! G1(j, k) = g1(j - k, k) within the band, 0 outside (ab is zeroed)
        if (abs(jp - jq) > g1b) cycle
        if (transposed) then
          w%ab(2*g1b + 1 + p - q, q) = cs%g1(jq - jp, jp)
        else
          w%ab(2*g1b + 1 + p - q, q) = cs%g1(jp - jq, jq)
        end if
      end do
    end do
  end subroutine run_matrix
end module raccord_g1_runs
