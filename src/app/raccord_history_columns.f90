!> The time-history table's columns and rows: energies, then reaction and
!> mean displacement per support, total applied force per surface load,
!> the resultants and counts of each contact pair, and the plastic work
!> of a model with a j2 body (doc/output-format.md, "History").
module raccord_history_columns
  use raccord_kinds, only: wp
  use raccord_strings, only: str
  use raccord_model, only: model_t, amplitude_at
  use raccord_state, only: state_t
  use raccord_contact_pair, only: contact_pair_t
  implicit none
  private

  !> Length of a column name.
  integer, parameter, public :: HISTORY_COL_LEN = 40

  public :: history_columns, history_width, fill_history_row

contains

  !> Column names of the history: energies, then reaction and mean
  !> displacement per support, then total applied force per surface load.
  subroutine history_columns(model, pairs, cols)
    type(model_t), intent(in) :: model
    type(contact_pair_t), intent(in) :: pairs(:)
    character(len=HISTORY_COL_LEN), allocatable, intent(out) :: cols(:)
    integer :: k, n
    ! sized once and filled: cols = [cols, extra] per support copied the
    ! whole list each time, and a deck of 2*10^4 &boundary groups spent
    ! half a minute here before the first step
    n = 10 + 4*size(model%supports) + 2*size(model%loads) + 7*size(pairs)
    if (model%has_plastic) n = n + 1
    allocate(cols(n))
    cols(1:10) = [character(len=HISTORY_COL_LEN) :: 'time', 'step', 'kinetic', 'internal', 'external_work', &
      'damping_work', 'contact_work', 'friction_work', 'energy_balance', 'energy_balance_rel']
    n = 10
    do k = 1, size(model%supports)
      associate (s => model%supports(k)%set)
        cols(n+1:n+4) = [character(len=HISTORY_COL_LEN) :: s // '_Rx', s // '_Ry', s // '_ux', s // '_uy']
      end associate
      n = n + 4
    end do
    do k = 1, size(model%loads)
      associate (s => model%loads(k)%set)
        cols(n+1:n+2) = [character(len=HISTORY_COL_LEN) :: s // '_Fx', s // '_Fy']
      end associate
      n = n + 2
    end do
    ! Per contact pair: force on the slave body, sums of nodal normal and
    ! tangential forces, active and slipping nodes, solver iterations.
    do k = 1, size(pairs)
      associate (s => 'contact' // str(k))
        cols(n+1:n+7) = [character(len=HISTORY_COL_LEN) :: s // '_Fx', s // '_Fy', s // '_N', s // '_T', &
          s // '_active', s // '_slip', s // '_iterations']
      end associate
      n = n + 7
    end do
    ! With a j2 body: its plastic work, a term of the energy balance
    ! (last, so that the other columns keep their places).
    if (model%has_plastic) cols(n+1) = 'plastic_work'
  end subroutine history_columns

  !> Number of history columns of this model and these pairs.
  integer function history_width(model, pairs)
    type(model_t), intent(in) :: model
    type(contact_pair_t), intent(in) :: pairs(:)
    character(len=HISTORY_COL_LEN), allocatable :: cols(:)
    call history_columns(model, pairs, cols)
    history_width = size(cols)
  end function history_width

  !> The history row of the state at t(n), in the order of history_columns.
  subroutine fill_history_row(model, state, pairs, row)
    type(model_t), intent(in) :: model
    type(state_t), intent(in) :: state
    type(contact_pair_t), intent(in) :: pairs(:)
    real(wp), intent(out) :: row(:)   !< history_width(model, pairs) values
    integer :: k, j, col
    real(wp) :: r(2), a
    associate (e => state%energy)
      row(1:10) = [state%time, real(state%step, wp), e%kinetic, e%internal, e%external, e%damping, &
        e%contact, e%friction, e%balance, e%balance/max(e%scale, tiny(1.0_wp))]
      col = 10
      do k = 1, size(model%supports)
        r = 0.0_wp
        do j = 1, model%ncdof
          if (model%cdof_support(j) == k) r(model%cdof_comp(j)) = r(model%cdof_comp(j)) + state%reaction(j)
        end do
        associate (nodes => model%supports(k)%nodes)
          row(col+1:col+4) = [r(1), r(2), sum(state%u(1, nodes))/size(nodes), sum(state%u(2, nodes))/size(nodes)]
        end associate
        col = col + 4
      end do
      do k = 1, size(model%loads)
        a = amplitude_at(model, model%loads(k)%amplitude, state%time)
        row(col+1:col+2) = a*sum(state%load_force(k)%f, dim=2)
        col = col + 2
      end do
      do k = 1, size(pairs)
        row(col+1:col+7) = [pairs(k)%force(1), pairs(k)%force(2), pairs(k)%normal_sum, pairs(k)%tangent_sum, &
          real(pairs(k)%nactive, wp), real(pairs(k)%nslip, wp), real(pairs(k)%iterations, wp)]
        col = col + 7
      end do
      if (model%has_plastic) row(col+1) = e%plastic
    end associate
  end subroutine fill_history_row

end module raccord_history_columns
