!> J2 bodies in axisymmetry (the axisymmetric J2 kernels,
!> raccord_plastic_axi_body.inc), elastic - perfectly plastic, loaded
!> quasi-statically by an internal pressure:
!>  - a thick cylinder a = 1, b = 2 held in z on both faces (plane strain
!>    in z: the same problem as the plane-strain ring of plastic_hill),
!>    against the 1D radial solution of the method brief (7.4);
!>  - a hollow sphere a = 1, b = 2 (quarter section, nodes on the axis):
!>    under spherical symmetry von Mises is Tresca and the elastic-plastic
!>    solution is exact (Hill 1950): plastic to c under
!>    p = 2 sigma_y ln(c/a) + (2 sigma_y/3)(1 - c^3/b^3), and the elastic
!>    shell outside gives u(b) = sigma_y c^3 (1 - nu) / (E b^2).
!> Q4 and Q8, with the energy balance closed by the plastic work.
program test_plastic_axi
  use raccord_kinds, only: wp
  use raccord_error, only: error_t
  use raccord_scene_runner, only: scene_run_t, run_deck
  use raccord_check, only: failure_t, new_test, run_tests, check
  use raccord_strings, only: str
  use axi_support, only: write_mesh_inp
  implicit none

  real(wp), parameter :: young = 210000.0_wp, nu = 0.3_wp, sy = 240.0_wp

  call run_tests('plastic_axi', [ &
    new_test('axisymmetric j2 cylinder held in z: u(b) against the 1D plane-strain solution', test_cylinder), &
    new_test('axisymmetric j2 hollow sphere: u(b) against the exact elastic-plastic solution', test_sphere)])

contains

  !> Deck: the mesh, one axisymmetric j2 body, the &boundary lines, the
  !> pressure p on 'left' ramped over 1e-4 s and held, damped.
  function write_deck(name, mesh, bcs, p) result(path)
    character(len=*), intent(in) :: name, mesh, bcs(:)
    real(wp), intent(in) :: p
    character(len=:), allocatable :: path
    character(len=32) :: val
    integer :: u, k
    path = './' // name // '.nml'
    write(val, '(f12.6)') p
    open(newunit=u, file=path, status='replace', action='write')
    write(u, '(a)') '&mesh file = ''' // mesh // ''' /'
    write(u, '(a)') '&body name = ''body'', young = 210000.0, poisson = 0.3, density = 7.8e-9,'
    write(u, '(a)') '  material = ''j2'', yield_stress = 240.0, hypothesis = ''axisymmetric'' /'
    write(u, '(a)') '&amplitude name = ''ramp'', time = 0.0, 1.0e-4, value = 0.0, 1.0 /'
    do k = 1, size(bcs)
      write(u, '(a)') trim(bcs(k))
    end do
    write(u, '(a)') '&boundary set = ''left'', type = ''pressure'', pressure = ' // trim(adjustl(val)) // &
      ', amplitude = ''ramp'' /'
    write(u, '(a)') '&time t_end = 1.5e-4, damping = 2.0e6 /'
    close(u)
  end function write_deck

  !> Run; ub = mean radial displacement of the nodes at distance 2 from the
  !> origin (the outer surface), the worst energy balance and the plastic work.
  subroutine run_case(failure, name, path, ub, balance, wpl)
    type(failure_t), allocatable, intent(inout) :: failure
    character(len=*), intent(in) :: name, path
    real(wp), intent(out) :: ub, balance, wpl
    type(scene_run_t), allocatable :: run
    type(error_t) :: err
    real(wp) :: x(2), r, rsum
    integer :: n, nout
    allocate(run)
    ub = 0.0_wp
    balance = 1.0_wp
    wpl = 0.0_wp
    call run_deck(path, run, err)
    call check(failure, .not. err%failed(), name // ': ' // err%message)
    if (allocated(failure)) return
    rsum = 0.0_wp
    nout = 0
    do n = 1, run%model%nnode
      x = run%mesh%x(:, n)
      r = norm2(x)
      if (abs(r - 2.0_wp) < 1.0e-9_wp) then
        rsum = rsum + dot_product(run%state%u(:, n), x/r)
        nout = nout + 1
      end if
    end do
    ub = rsum/real(max(nout, 1), wp)
    balance = run%worst_balance
    wpl = run%state%energy%plastic
    print '(a)', '  ' // name // ': u(b) = ' // str(ub, 6) // ', plastic work ' // str(wpl, 4) // &
      ', worst energy balance ' // str(balance, 3) // ', ' // str(run%state%step) // ' steps'
  end subroutine run_case

  !> The cylinder: 20 (Q4) or 10 (Q8) elements through the wall, 2 along z,
  !> both faces held in z; p = 180.134 makes the plane-strain plastic zone
  !> reach c = 1.6126 by the 1D solution, u(b) = 1.54465e-3 (brief 7.4).
  subroutine test_cylinder(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp), parameter :: p = 180.134_wp, ub_1d = 1.54465e-3_wp
    real(wp) :: ub, bal, wpl
    integer :: k
    character(len=4), parameter :: types(2) = ['CAX4', 'CAX8']
    integer, parameter :: nens(2) = [4, 8], nrs(2) = [20, 10]
    do k = 1, 2
      call write_mesh_inp('cyl_' // types(k) // '.inp', 'rect', nens(k), nrs(k), 2, [1.0_wp, 2.0_wp, 0.0_wp, 0.2_wp], &
        types(k))
      call run_case(failure, 'cylinder ' // types(k), write_deck('cyl_' // types(k), 'cyl_' // types(k) // '.inp', &
        [character(len=80) :: '&boundary set = ''bottom'', type = ''fixed'', components = ''y'' /', &
        '&boundary set = ''top'', type = ''fixed'', components = ''y'' /'], p), ub, bal, wpl)
      if (allocated(failure)) return
      call check(failure, abs(ub/ub_1d - 1.0_wp) < 5.0e-3_wp, types(k) // ': u(b) ' // str(ub) // &
        ' not within 0.5 % of the 1D solution ' // str(ub_1d))
      call check(failure, wpl > 0.0_wp, types(k) // ': the cylinder yields')
      call check(failure, bal < 1.0e-6_wp, types(k) // ': energy balance ' // str(bal))
    end do
  end subroutine test_cylinder

  !> The sphere: plastic to c = 1.5, p = 2 sy ln 1.5 + (2 sy/3)(1 - 1.5^3/8),
  !> u(b) = sy c^3 (1 - nu)/(E b^2).
  subroutine test_sphere(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp), parameter :: a = 1.0_wp, b = 2.0_wp, c = 1.5_wp
    real(wp) :: p, ub_exact, ub, bal, wpl
    integer :: k
    character(len=4), parameter :: types(2) = ['CAX4', 'CAX8']
    integer, parameter :: nens(2) = [4, 8], nrs(2) = [16, 8]
    p = 2.0_wp*sy*log(c/a) + (2.0_wp*sy/3.0_wp)*(1.0_wp - c**3/b**3)
    ub_exact = sy*c**3*(1.0_wp - nu)/(young*b*b)
    do k = 1, 2
      call write_mesh_inp('sph_' // types(k) // '.inp', 'shell', nens(k), nrs(k), nrs(k), [a, b, 0.0_wp, 0.0_wp], &
        types(k))
      call run_case(failure, 'sphere ' // types(k), write_deck('sph_' // types(k), 'sph_' // types(k) // '.inp', &
        [character(len=80) :: '&boundary set = ''bottom'', type = ''fixed'', components = ''y'' /'], p), ub, bal, wpl)
      if (allocated(failure)) return
      print '(a)', '    exact u(b) = ' // str(ub_exact, 6) // ' at p = ' // str(p, 6) // ': error ' // &
        str(ub/ub_exact - 1.0_wp, 3)
      call check(failure, abs(ub/ub_exact - 1.0_wp) < 1.0e-2_wp, types(k) // ': u(b) ' // str(ub) // &
        ' not within 1 % of the exact ' // str(ub_exact))
      call check(failure, bal < 1.0e-6_wp, types(k) // ': energy balance ' // str(bal))
    end do
  end subroutine test_sphere
end program test_plastic_axi
