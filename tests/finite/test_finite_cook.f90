!> Near incompressibility (issue: Q4 must not lock): Cook's membrane in
!> finite strain, neo-Hooke with nu = 0.4999 (tests/finite/data/cook.nml),
!> run to its static limit with Q4 mean dilatation (the default) and with
!> full integration. Reference u_y(48, 60) = 6.92 (method brief 11.2:
!> converged value of F-bar and mean dilatation; a static Newton code gives
!> 6.814 with mean dilatation on this 16 x 16 mesh, 2.381 with plain Q4).
program test_finite_cook
  use raccord_kinds, only: wp
  use raccord_error, only: error_t
  use raccord_scene_runner, only: scene_run_t, run_deck
  use raccord_check, only: failure_t, new_test, run_tests, check
  use raccord_strings, only: str
  implicit none

  real(wp), parameter :: reference = 6.92_wp

  call run_tests('finite_cook', [new_test('Q4 mean dilatation does not lock, full integration does', test_cook)])

contains

  !> u_y of the node at (48, 60) after a run of the deck with the given
  !> volumetric treatment.
  real(wp) function corner_uy(volumetric, failure) result(uy)
    character(len=*), intent(in) :: volumetric
    type(failure_t), allocatable, intent(inout) :: failure
    type(scene_run_t), allocatable :: run
    type(error_t) :: err
    character(len=512) :: root
    character(len=:), allocatable :: path
    character(len=256) :: line
    integer :: u, v, length, stat, n, ios
    call get_environment_variable('RACCORD_SOURCE_DIR', root, length, stat)
    ! a copy of the deck with the volumetric key and the mesh path
    path = './cook_' // volumetric // '.nml'
    open(newunit=u, file=trim(root) // '/tests/finite/data/cook.nml', status='old', action='read')
    open(newunit=v, file=path, status='replace', action='write')
    do
      read(u, '(a)', iostat=ios) line
      if (ios /= 0) exit
      if (index(line, '&mesh') == 1) then
        write(v, '(a)') '&mesh file = ''' // trim(root) // '/tests/finite/data/cook.msh'' /'
      else if (index(line, 'kinematics') > 0) then
        write(v, '(a)') '  kinematics = ''finite'', material = ''neo_hooke'', volumetric = ''' // volumetric // ''' /'
      else
        write(v, '(a)') trim(line)
      end if
    end do
    close(u)
    close(v)
    allocate(run)
    call run_deck(path, run, err)
    uy = 0.0_wp
    call check(failure, .not. err%failed(), volumetric // ': ' // err%message)
    if (allocated(failure)) return
    n = minloc((run%model%x(1, :) - 48.0_wp)**2 + (run%model%x(2, :) - 60.0_wp)**2, 1)
    uy = run%state%u(2, n)
    print '(a)', '  ' // volumetric // ': u_y(48, 60) = ' // str(uy, 6) // ' (' // &
      str(100.0_wp*(uy/reference - 1.0_wp), 3) // ' % from the converged ' // str(reference, 3) // '), ' // &
      str(run%state%step) // ' steps, kinetic / stored energy at the end ' // &
      str(run%state%energy%kinetic/max(run%state%energy%internal, tiny(1.0_wp)), 3) // &
      ', worst balance ' // str(run%worst_balance, 3)
    call check(failure, run%state%energy%kinetic < 1.0e-6_wp*run%state%energy%internal, volumetric // &
      ': not settled, kinetic energy ' // str(run%state%energy%kinetic))
  end function corner_uy

  subroutine test_cook(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp) :: umd, ufull
    umd = corner_uy('mean_dilatation', failure)
    if (allocated(failure)) return
    ufull = corner_uy('full', failure)
    if (allocated(failure)) return
    call check(failure, abs(umd/reference - 1.0_wp) < 0.02_wp, 'mean dilatation u_y = ' // str(umd) // &
      ', not within 2 % of ' // str(reference))
    call check(failure, ufull < 0.4_wp*reference, 'full integration u_y = ' // str(ufull) // &
      ' does not show the locking it should')
  end subroutine test_cook
end program test_finite_cook
