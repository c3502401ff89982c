!> Workspace and results of the multiplier solve (raccord_multiplier_solver),
!> the codes of the constraint sets, and the grow-only buffers shared by
!> the solve's forms (saddle, Delassus, node-to-segment and banded
!> friction: each in its own module, all sized here).
module raccord_solver_work
  use raccord_kinds, only: wp
  use raccord_constraint_set, only: G1_MAX_BAND
  implicit none
  private

  integer, parameter, public :: ST_OPEN = 0, ST_STICK = 1, ST_SLIP = 2
  !> Reduced forms: most kept neighbours of one eliminated row of Z.
  integer, parameter, public :: ZMAX = 4*G1_MAX_BAND + 2

  !> Workspace and results, indexed by constraint; buffers grow only.
  type, public :: solver_work_t
    real(wp), allocatable :: lam(:), tau(:), gn(:), gt(:), fn(:), ft(:), c(:)
    integer, allocatable :: status(:), status_old(:)
    !> Tangential corner multipliers (cs%tcorners): the stick / slip set of
    !> each owner row apart from the normal set, and its c of the
    !> tangential test (raccord_saddle_form, solve_saddle_tc)
    integer, allocatable :: tstat(:), tstat_old(:)
    real(wp), allocatable :: ct(:)
    real(wp), allocatable :: sigma(:)
    real(wp), allocatable :: knn(:,:), knt(:,:), ktn(:,:), ktt(:,:)   !< (-kb:kb, m)
    integer :: kb = 0
    real(wp), allocatable :: ab(:,:), rhs(:)
    integer, allocatable :: var(:,:)     !< (4, m) unknown index of lambda_j, gn_j, tau_j, gt_j (0: eliminated)
    integer, allocatable :: vfirst(:)    !< (m + 1) first unknown of constraint j
    integer, allocatable :: fcol(:), lcol(:), ext(:)   !< per row: first, last column; band_solve scratch
    integer, allocatable :: ipiv(:)
    integer, allocatable :: node_first(:), node_last(:)   !< per global node: rows touching it
    integer, allocatable :: node_ptr(:), node_row(:)   !< node -> row lists
    integer, allocatable :: touched(:)
    real(wp), allocatable :: node_w(:)   !< (nent) the weight of each node_row entry
    real(wp), allocatable :: node_v(:,:) !< (2, nent) its vector weight (constraint sets with entry_dirs)
    ! The structure the node lists were last built from (raccord_delassus):
    ! while the rows' entries name the same nodes in the same order, the
    ! lists are kept and only the weights are gathered again (list_ent).
    integer, allocatable :: list_ent(:)     !< (nent) the entry e behind each node_row position
    integer, allocatable :: list_row_ptr(:) !< (m + 1) cs%row_ptr of that build
    integer, allocatable :: list_node(:)    !< (nent) cs%ent_node of that build
    integer :: list_m = -1, list_nent = -1, list_ntouched = 0, list_kb = 0
    logical :: list_dirs = .false.
    integer :: lists_built = 0, lists_kept = 0   !< Delassus calls that built / kept the node lists
    ! Reduced (Delassus) solve: compressed active index, open list, the
    ! open multipliers in terms of the active ones (Z), the band of R.
    integer, allocatable :: ia(:), olist(:), zcnt(:), zcol(:,:)
    real(wp), allocatable :: zval(:,:), rb(:,:), xr(:)
    integer :: reduced_calls = 0                  !< solves done in the reduced form (all iterations)
    ! Reduced form with friction and a banded G1 (solve_banded_friction):
    ! tangential index and list (stick kept, open and slip eliminated), the
    ! sign s of tau = q + mu s lambda, the slip-free rows of q in terms of
    ! q_K (Zt), the unknown of lambda_j and q_j (< 0: a border unknown),
    ! the rows of N_n and N_t in the unknowns, the border blocks.
    integer, allocatable :: it(:), ulist(:), ztcnt(:), ztcol(:,:), ulam(:), uq(:), bmark(:)
    real(wp), allocatable :: ztval(:,:), sgn(:), qv(:)
    integer, allocatable :: ncnt(:), ncol(:,:), tcnt(:), tcol(:,:)
    real(wp), allocatable :: nval(:,:), tval(:,:)
    real(wp), allocatable :: bc(:,:), bd(:,:), bx(:,:), be(:,:), bg(:)
    real(wp), allocatable :: rowsc(:)    !< (2 m) row scales of the reduced friction matrix
    !> Use the saddle form only (tests compare the reduced forms with it).
    logical :: saddle_only = .false.
    !> &contact_pair tolerance: the relative residual of (19) within which
    !> an iterate whose active sets have not settled after LEAST_INDEX_AFTER
    !> iterations ends the iteration (raccord_solver_conditions,
    !> holds_to_roundoff). The default is the round-off bound the check
    !> was written with (1e-12, the fraction of the active test's band).
    real(wp) :: tolerance = 1.0e-12_wp
    integer :: border_unknowns = 0                !< border unknowns of the last solve_banded_friction
    ! Report of the last solve.
    integer :: iterations = 0
    logical :: converged = .true.
    real(wp) :: residual = 0.0_wp
    integer :: dropped = 0                        !< constraints with no movable node
    logical :: singular = .false.                 !< the last solve met a singular system
  end type solver_work_t

  public :: ensure_work, ensure_band, ensure2, ensure_i2, ensure1, ensure_i

contains

  !> Size the workspace for m constraints, nn nodes and nent entries;
  !> `vectors`: also the entries' vector weights (node_v).
  subroutine ensure_work(w, m, nn, nent, vectors)
    type(solver_work_t), intent(inout) :: w
    integer, intent(in) :: m, nn, nent
    logical, intent(in), optional :: vectors
    integer :: cap
    if (.not. allocated(w%node_first)) then
      allocate(w%node_first(nn), w%node_last(nn), w%node_ptr(nn), source=0)
      allocate(w%touched(nn))
    end if
    call ensure_i(w%node_row, nent)
    call ensure1(w%node_w, nent)
    if (present(vectors)) then
      if (vectors) call ensure2(w%node_v, 2, nent)
    end if
    if (allocated(w%lam)) then
      if (size(w%lam) >= m) return
    end if
    cap = max(m, 16)
    call ensure_i(w%status, cap)
    call ensure_i(w%status_old, cap)
    call ensure1(w%sigma, cap)
    if (allocated(w%lam)) deallocate(w%lam, w%tau, w%gn, w%gt, w%fn, w%ft, w%c)
    allocate(w%lam(cap), w%tau(cap), w%gn(cap), w%gt(cap), w%fn(cap), w%ft(cap), w%c(cap), source=0.0_wp)
  end subroutine ensure_work

  subroutine ensure_band(a, kb, m)
    real(wp), allocatable, intent(inout) :: a(:,:)
    integer, intent(in) :: kb, m
    if (allocated(a)) then
      if (lbound(a, 1) <= -kb .and. size(a, 2) >= m) return
      deallocate(a)
    end if
    allocate(a(-max(kb, 2):max(kb, 2), max(m, 16)))
  end subroutine ensure_band

  !> Grow-only: the band's height changes with the sets.
  subroutine ensure2(a, n1, n2)
    real(wp), allocatable, intent(inout) :: a(:,:)
    integer, intent(in) :: n1, n2
    integer :: c1, c2
    c1 = n1
    c2 = max(n2, 1)
    if (allocated(a)) then
      if (size(a, 1) >= n1 .and. size(a, 2) >= n2) return
      c1 = max(c1, size(a, 1))
      c2 = max(c2, size(a, 2))
      deallocate(a)
    end if
    allocate(a(c1, c2))
  end subroutine ensure2

  subroutine ensure_i2(a, n1, n2)
    integer, allocatable, intent(inout) :: a(:,:)
    integer, intent(in) :: n1, n2
    if (allocated(a)) then
      if (size(a, 1) >= n1 .and. size(a, 2) >= n2) return
      deallocate(a)
    end if
    allocate(a(n1, max(n2, 16)))
  end subroutine ensure_i2

  subroutine ensure1(a, n)
    real(wp), allocatable, intent(inout) :: a(:)
    integer, intent(in) :: n
    if (allocated(a)) then
      if (size(a) >= n) return
      deallocate(a)
    end if
    allocate(a(max(n, 1)))
  end subroutine ensure1

  subroutine ensure_i(a, n)
    integer, allocatable, intent(inout) :: a(:)
    integer, intent(in) :: n
    if (allocated(a)) then
      if (size(a) >= n) return
      deallocate(a)
    end if
    allocate(a(max(n, 1)))
  end subroutine ensure_i
end module raccord_solver_work
