!> Hill's thick-walled cylinder under internal pressure (method brief 7.4,
!> input/verification/hill): plane strain, elastic - perfectly plastic
!> von Mises, a = 1, b = 2, loaded quasi-statically to the pressures whose
!> plastic radius is c = 1.6 and 1.8 (1.8: close to collapse, the flow
!> nearly fully plastic). Checked against a 1D radial finite-element
!> solution (brief 7.4, nu = 0.3: c and u(b)) and the closed form (u(b),
!> which assumes sigma_z the mean of the in-plane stresses, so 0.5-2 % off
!> at nu = 0.3), on three meshes to show the rate; and mean dilatation
!> (B-bar) against full integration, which locks in the plastic flow.
program test_plastic_hill
  use raccord_kinds, only: wp
  use raccord_error, only: error_t
  use raccord_plasticity, only: h_ebar
  use raccord_scene_runner, only: scene_run_t, run_deck
  use raccord_check, only: failure_t, new_test, run_tests, check
  use raccord_strings, only: str
  implicit none

  call run_tests('plastic_hill', [ &
    new_test('c = 1.6: u(b) and c against the 1D solution, error falling with the mesh', test_c16), &
    new_test('c = 1.8: mean dilatation follows the plastic flow, full integration locks', test_c18)])

contains

  !> A copy of input/verification/hill/hill_20.nml with the mesh, the
  !> pressure and the volumetric treatment.
  function write_deck(name, mesh, p, vol, nu) result(path)
    character(len=*), intent(in) :: name, mesh, vol
    real(wp), intent(in) :: p, nu
    character(len=:), allocatable :: path
    character(len=512) :: root
    character(len=32) :: val, pois
    integer :: u, length, stat
    call get_environment_variable('RACCORD_SOURCE_DIR', root, length, stat)
    path = './' // name // '.nml'
    write(val, '(f12.6)') p
    write(pois, '(f6.3)') nu
    open(newunit=u, file=path, status='replace', action='write')
    write(u, '(a)') '&mesh file = ''' // trim(root) // '/input/verification/hill/' // mesh // ''' /'
    write(u, '(a)') '&body name = ''ring'', young = 210000.0, poisson = ' // trim(adjustl(pois)) // &
      ', density = 7.8e-9,'
    write(u, '(a)') '  material = ''j2'', yield_stress = 240.0, hardening = 0.0, volumetric = ''' // vol // ''' /'
    write(u, '(a)') '&amplitude name = ''ramp'', time = 0.0, 1.0e-4, value = 0.0, 1.0 /'
    write(u, '(a)') '&boundary set = ''xsym'', type = ''fixed'', components = ''x'' /'
    write(u, '(a)') '&boundary set = ''ysym'', type = ''fixed'', components = ''y'' /'
    write(u, '(a)') '&boundary set = ''inner'', type = ''pressure'', pressure = ' // trim(adjustl(val)) // &
      ', amplitude = ''ramp'' /'
    write(u, '(a)') '&time t_end = 1.5e-4, damping = 2.0e6 /'
    close(u)
  end function write_deck

  !> Run; ub = radial displacement of the outer radius (mean over the outer
  !> nodes), c = the largest centroid radius of the elements that yielded,
  !> h = the radial element size.
  subroutine run_ring(failure, name, mesh, p, vol, nu, ub, c, h, balance, wpl)
    type(failure_t), allocatable, intent(inout) :: failure
    character(len=*), intent(in) :: name, mesh, vol
    real(wp), intent(in) :: p, nu
    real(wp), intent(out) :: ub, c, h, balance, wpl
    type(scene_run_t), allocatable :: run
    type(error_t) :: err
    real(wp) :: r, x(2), rsum
    integer :: n, e, ic, il, nout
    allocate(run)
    call run_deck(write_deck(name, mesh, p, vol, nu), run, err)
    ub = 0.0_wp
    wpl = 0.0_wp
    c = 0.0_wp
    h = 1.0_wp
    balance = 1.0_wp
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
    ub = rsum/real(nout, wp)
    associate (blk => run%model%bodies(1)%blocks(1), pl => run%state%plastic(1, 1))
      do e = 1, blk%nel
        ic = (e - 1)/32 + 1
        il = e - (ic - 1)*32
        if (maxval(pl%h(il, h_ebar, :, ic)) > 0.0_wp) then
          x = 0.25_wp*sum(run%mesh%x(:, blk%conn(1:4, e)), dim=2)
          c = max(c, norm2(x))
        end if
      end do
    end associate
    ! radial element size: the wall over the elements through it
    h = 1.0_wp/real(nint(sqrt(real(run%model%nelem, wp)*5.0_wp/3.0_wp)), wp)
    balance = run%worst_balance
    wpl = run%state%energy%plastic
    print '(a)', '  ' // name // ': u(b) = ' // str(ub, 6) // ', plastic to c = ' // str(c, 4) // ' (+- ' // &
      str(h, 3) // '), plastic work ' // str(wpl, 4) // ', worst energy balance ' // str(balance, 3) // ', ' // &
      str(run%state%step) // ' steps'
  end subroutine run_ring

  subroutine test_c16(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp), parameter :: p = 180.134_wp, ub_1d = 1.54465e-3_wp, c_1d = 1.6126_wp, ub_closed = 1.53714e-3_wp
    real(wp) :: ub(2), c(2), h(2), bal(2), wpl(2)
    call run_ring(failure, 'hill_c16_10', 'hill_10.msh', p, 'mean_dilatation', 0.3_wp, ub(1), c(1), h(1), bal(1), &
      wpl(1))
    call run_ring(failure, 'hill_c16_20', 'hill_20.msh', p, 'mean_dilatation', 0.3_wp, ub(2), c(2), h(2), bal(2), &
      wpl(2))
    if (allocated(failure)) return
    print '(a)', '  u(b) error against the 1D solution: ' // str(ub(1)/ub_1d - 1.0_wp, 3) // ' (10 elements), ' // &
      str(ub(2)/ub_1d - 1.0_wp, 3) // ' (20); against the closed form ' // str(ub(2)/ub_closed - 1.0_wp, 3)
    call check(failure, abs(ub(2)/ub_1d - 1.0_wp) < 5.0e-3_wp, 'u(b) within 0.5 % of the 1D solution: ' // &
      str(ub(2)) // ' vs ' // str(ub_1d))
    call check(failure, abs(ub(2) - ub_1d) < abs(ub(1) - ub_1d), 'the error falls with the mesh')
    call check(failure, abs(ub(2)/ub_closed - 1.0_wp) < 2.0e-2_wp, 'u(b) within 2 % of the closed form')
    call check(failure, abs(c(2) - c_1d) <= h(2), 'plastic radius ' // str(c(2)) // ' within an element of ' // &
      str(c_1d))
    call check(failure, maxval(bal) < 1.0e-6_wp, 'energy balance closed with the plastic work: ' // str(maxval(bal)))
  end subroutine test_c16

  !> Near collapse and nearly incompressible (nu = 0.49: the flow and the
  !> elastic response both nearly isochoric), 20 elements through the wall: mean dilatation
  !> against the 1D solution (brief 7.4: u(b) = 1.62400e-3, c = 1.7993),
  !> full integration locked (stiffer, much less plastic work).
  subroutine test_c18(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp), parameter :: p = 189.219_wp, ub_1d = 1.62400e-3_wp, c_1d = 1.7993_wp
    real(wp) :: ub(2), c(2), h(2), bal(2), wpl(2), err(2)
    call run_ring(failure, 'hill_c18_md', 'hill_20.msh', p, 'mean_dilatation', 0.49_wp, ub(1), c(1), h(1), bal(1), &
      wpl(1))
    call run_ring(failure, 'hill_c18_full', 'hill_20.msh', p, 'full', 0.49_wp, ub(2), c(2), h(2), bal(2), wpl(2))
    if (allocated(failure)) return
    err = ub/ub_1d - 1.0_wp
    print '(a)', '  nu = 0.49, u(b) against the 1D solution: mean dilatation ' // str(err(1), 3) // &
      ', full integration ' // str(err(2), 3) // '; plastic work ' // str(wpl(1), 4) // ' and ' // str(wpl(2), 4)
    call check(failure, abs(err(1)) < 2.0e-2_wp, 'mean dilatation: u(b) within 2 % of the 1D solution near ' // &
      'collapse: ' // str(ub(1)) // ' vs ' // str(ub_1d))
    call check(failure, abs(c(1) - c_1d) <= h(1), 'mean dilatation: plastic radius ' // str(c(1)) // &
      ' within an element of ' // str(c_1d))
    call check(failure, abs(err(2)) > 3.0_wp*abs(err(1)) .and. wpl(2) < 0.9_wp*wpl(1), 'full integration ' // &
      'locks: u(b) error ' // str(err(2)) // ', plastic work ' // str(wpl(2)) // ' against ' // str(wpl(1)))
  end subroutine test_c18
end program test_plastic_hill
