!> Axisymmetric finite-strain bodies through the explicit loop
!> (raccord_finite_axi_kernel, variable step; doc/verification.md,
!> "Axisymmetric finite strain"):
!>  - a hollow neo-Hooke ball (radii 0.3 and 1, upper quarter, equator on
!>    rollers, nodes on the axis) squashed by 25 % of its radius under a
!>    stiffer neo-Hooke plate (the slave surface), mortar P1 with friction
!>    0.2 and node-to-segment without (with friction its multipliers do not
!>    converge on this coarse curved master, in small strain too):
!>    the runs complete (no inverted element), the contact gives no energy
!>    (mortar: none; node-to-segment Q8: 7e-4 of the stored energy, under
!>    the 1e-3 asserted; Q8 mortar with corner multipliers, mu = 0.2 and
!>    0, whose rows carry per-entry directions: 7e-4 and 8e-4) and the balance (internal + kinetic + damping + friction + contact
!>    losses = work of the driven plate) stays closed;
!>  - a neo-Hooke tube (nu = 0.499) whose bore is driven to 1.5 times its
!>    radius: bore pressure within 0.3 % of the incompressible closed form
!>    (measured -8e-4 with Q4 and Q8 alike: the O(G/K) compressibility);
!>  - the j2 hollow sphere of plastic_axi (a = 1, b = 2, plastic to
!>    c = 1.5, strains of 1e-3) in finite strain: u(b) within 1 % of the
!>    exact small-strain elastic-plastic solution (Hill 1950).
program test_axi_finite_runs
  use raccord_kinds, only: wp
  use raccord_error, only: error_t
  use raccord_check, only: failure_t, new_test, run_tests, check
  use raccord_strings, only: str
  use raccord_kinds, only: pi
  use raccord_scene_runner, only: scene_run_t, run_deck
  use raccord_elastic_block, only: add_internal_force
  use axi_support, only: write_mesh_inp
  implicit none

  call run_tests('axi_finite_runs', [ &
    new_test('neo-Hooke hollow ball squashed by a plate, mortar and node-to-segment: energy balance', test_ball), &
    new_test('j2 hollow sphere in finite strain: u(b) against the small-strain exact solution', test_j2_sphere), &
    new_test('neo-Hooke tube (nu 0.499) inflated to 1.5 x its bore: pressure against the incompressible closed form', &
      test_tube)])

contains

  subroutine test_ball(failure)
    type(failure_t), allocatable, intent(out) :: failure
    character(len=16), parameter :: methods(2) = [character(len=16) :: 'mortar', 'node_to_segment']
    character(len=4), parameter :: frictions(4) = ['0.2', '0.0', '0.2', '0.0']
    type(scene_run_t), allocatable :: run
    type(error_t) :: err
    real(wp) :: fy, e_in
    integer :: u, im, n, nen, nrun
    character(len=:), allocatable :: key, label
    do nen = 4, 8, 4
      call write_mesh_inp('ball.inp', 'shell', nen, 6, 8, [0.3_wp, 1.0_wp, 0.0_wp, 0.0_wp], 'CAX' // str(nen), &
        elset='ball', prefix='b_')
      call write_mesh_inp('ball.inp', 'rect', nen, 4, 1, [0.0_wp, 0.8_wp, 1.01_wp, 1.21_wp], 'CAX' // str(nen), &
        elset='plate', prefix='p_', append=.true., id0=10000)
      ! Q8: also mortar with corner multipliers (edge_multipliers =
      ! 'corners'), with friction and without: their rows' per-entry
      ! directions keep the energy contact gives below the same 1e-3 of
      ! the stored energy (one direction per row gave 6.6e-3 (mu = 0.2)
      ! and 4.9e-2 (mu = 0); doc/reproduction.md, "The Q8 stick zigzag:
      ! corner multipliers on curved surfaces").
      nrun = merge(4, 2, nen == 8)
      do im = 1, nrun
        key = ''
        if (im > 2) key = ', edge_multipliers = ''corners'''
        label = trim(methods(min(im, 2)))
        if (im == 3) label = 'mortar'
        if (im == 4) label = 'mortar'
        if (im > 2) label = label // ' corners mu ' // trim(frictions(im))
        open(newunit=u, file='ball.nml', status='replace', action='write')
        write(u, '(a)') '&mesh file = ''ball.inp'' /'
        write(u, '(a)') '&body name = ''ball'', elset = ''ball'', young = 10.0, poisson = 0.45, density = 1.0e-3, ' // &
          'hypothesis = ''axisymmetric'', kinematics = ''finite'', material = ''neo_hooke'' /'
        write(u, '(a)') '&body name = ''plate'', elset = ''plate'', young = 200.0, poisson = 0.3, density = 1.0e-3, ' // &
          'hypothesis = ''axisymmetric'', kinematics = ''finite'', material = ''neo_hooke'' /'
        write(u, '(a)') '&amplitude name = ''ramp'', time = 0.0, 0.3, value = 0.0, 1.0 /'
        write(u, '(a)') '&boundary set = ''b_bottom'', type = ''fixed'', components = ''y'' /'
        write(u, '(a)') '&boundary set = ''p_top'', type = ''displacement'', components = ''xy'', value = 0.0, -0.26, ' // &
          'amplitude = ''ramp'' /'
        write(u, '(a)') '&time t_end = 0.4, damping = 20.0 /'
        write(u, '(a)') '&contact_pair slave = ''p_bottom'', master = ''b_right'', friction = ' // &
          trim(frictions(im)) // ', method = ''' // trim(methods(merge(1, im, im > 2))) // '''' // key // ' /'
        close(u)
        allocate(run)
        call run_deck('./ball.nml', run, err)
        if (err%failed()) call check(failure, .false., 'Q' // str(nen) // ' ' // label // ': ' // err%message)
        if (allocated(failure)) return
        ! the ball's pole (r = 0, z = 1) follows the plate down
        fy = 0.0_wp
        do n = 1, run%model%nnode
          if (run%model%node_body(n) == 1 .and. run%model%x(1, n) == 0.0_wp .and. &
            abs(run%model%x(2, n) - 1.0_wp) < 1.0e-12_wp) fy = run%state%u(2, n)
        end do
        e_in = run%state%energy%internal
        print '(a)', '        Q' // str(nen) // ' ' // label // ': ' // str(run%state%step) // &
          ' steps, pole moved ' // str(fy, 5) // ', stored energy ' // str(e_in, 5) // &
          ', worst balance ' // str(run%worst_balance, 3) // ', least contact work ' // str(run%min_contact_work, 3)
        call check(failure, fy < -0.24_wp, label // ': the pole moved by ' // str(fy) // &
          ', not with the plate (-0.25)')
        call check(failure, run%min_contact_work > -1.0e-3_wp*e_in, label // ': contact gave energy ' // &
          str(run%min_contact_work))
        call check(failure, run%worst_balance < 1.0e-3_wp, label // ': energy balance ' // &
          str(run%worst_balance))
        deallocate(run)
        if (allocated(failure)) return
      end do
    end do
  end subroutine test_ball

  subroutine test_j2_sphere(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp), parameter :: young = 210000.0_wp, nu = 0.3_wp, sy = 240.0_wp, a = 1.0_wp, b = 2.0_wp, c = 1.5_wp
    type(scene_run_t), allocatable :: run
    type(error_t) :: err
    character(len=32) :: val
    real(wp) :: p, ub_exact, x(2), r, rsum
    integer :: u, k, n, nout
    character(len=4), parameter :: types(2) = ['CAX4', 'CAX8']
    integer, parameter :: nens(2) = [4, 8], nrs(2) = [16, 8]
    p = 2.0_wp*sy*log(c/a) + (2.0_wp*sy/3.0_wp)*(1.0_wp - c**3/b**3)
    ub_exact = sy*c**3*(1.0_wp - nu)/(young*b*b)
    write(val, '(f12.6)') p
    do k = 1, 2
      call write_mesh_inp('sph.inp', 'shell', nens(k), nrs(k), nrs(k), [a, b, 0.0_wp, 0.0_wp], types(k))
      open(newunit=u, file='sph.nml', status='replace', action='write')
      write(u, '(a)') '&mesh file = ''sph.inp'' /'
      write(u, '(a)') '&body name = ''body'', young = 210000.0, poisson = 0.3, density = 7.8e-9, kinematics = ''finite'','
      write(u, '(a)') '  material = ''j2'', yield_stress = 240.0, hypothesis = ''axisymmetric'' /'
      write(u, '(a)') '&amplitude name = ''ramp'', time = 0.0, 1.0e-4, value = 0.0, 1.0 /'
      write(u, '(a)') '&boundary set = ''bottom'', type = ''fixed'', components = ''y'' /'
      write(u, '(a)') '&boundary set = ''left'', type = ''pressure'', pressure = ' // trim(adjustl(val)) // &
        ', amplitude = ''ramp'' /'
      write(u, '(a)') '&time t_end = 1.5e-4, damping = 2.0e6 /'
      close(u)
      allocate(run)
      call run_deck('./sph.nml', run, err)
      if (err%failed()) call check(failure, .false., types(k) // ': ' // err%message)
      if (allocated(failure)) return
      rsum = 0.0_wp
      nout = 0
      do n = 1, run%model%nnode
        x = run%mesh%x(:, n)
        r = norm2(x)
        if (abs(r - b) < 1.0e-9_wp) then
          rsum = rsum + dot_product(run%state%u(:, n), x/r)
          nout = nout + 1
        end if
      end do
      rsum = rsum/real(max(nout, 1), wp)
      print '(a)', '        ' // types(k) // ': u(b) = ' // str(rsum, 6) // ', exact (small strain) ' // &
        str(ub_exact, 6) // ', error ' // str(rsum/ub_exact - 1.0_wp, 3) // ', plastic work ' // &
        str(run%state%energy%plastic, 4) // ', worst balance ' // str(run%worst_balance, 3) // ', ' // &
        str(run%state%step) // ' steps'
      call check(failure, abs(rsum/ub_exact - 1.0_wp) < 1.0e-2_wp, types(k) // ': u(b) ' // str(rsum) // &
        ' not within 1 % of ' // str(ub_exact))
      call check(failure, run%state%energy%plastic > 0.0_wp, types(k) // ': the sphere yields')
      call check(failure, run%worst_balance < 1.0e-4_wp, types(k) // ': energy balance ' // str(run%worst_balance))
      deallocate(run)
      if (allocated(failure)) return
    end do
  end subroutine test_j2_sphere

  !> A long tube A = 1, B = 2 (a slice of height H = 0.2 held in z on both
  !> faces: plane strain along the axis), neo-Hooke E = 1, nu = 0.499, its
  !> bore driven to a = 1.5 A (ramp, damped hold). Incompressible closed
  !> form (equilibrium d sigma_r/dr = (sigma_t - sigma_r)/r with the
  !> stretches l = r/R, b^2 - B^2 = a^2 - A^2):
  !>   p = G [ln l - 1/(2 l^2)] from l_b = b/B to l_a = a/A.
  !> The ring-total radial force on the bore, F = p 2 pi a H, is the sum of
  !> the internal forces of its nodes at the end. The compressible model
  !> differs by O(G/K) = 0.2 %.
  subroutine test_tube(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp), parameter :: young = 1.0_wp, nu = 0.499_wp, ra = 1.0_wp, rb = 2.0_wp, hz = 0.2_wp, la = 1.5_wp
    character(len=4), parameter :: types(2) = ['CAX4', 'CAX8']
    integer, parameter :: nens(2) = [4, 8], nrs(2) = [16, 8]
    type(scene_run_t), allocatable :: run
    type(error_t) :: err
    real(wp), allocatable :: f(:,:)
    real(wp) :: g, a, b, lb, p, fr, pfe, ub
    integer :: u, k, n
    g = young/(2.0_wp*(1.0_wp + nu))
    a = la*ra
    b = sqrt(rb*rb + a*a - ra*ra)
    lb = b/rb
    p = g*((log(la) - 0.5_wp/la**2) - (log(lb) - 0.5_wp/lb**2))
    do k = 1, 2
      call write_mesh_inp('tube.inp', 'rect', nens(k), nrs(k), 1, [ra, rb, 0.0_wp, hz], types(k))
      open(newunit=u, file='tube.nml', status='replace', action='write')
      write(u, '(a)') '&mesh file = ''tube.inp'' /'
      write(u, '(a)') '&body name = ''body'', young = 1.0, poisson = 0.499, density = 1.0, ' // &
        'hypothesis = ''axisymmetric'', kinematics = ''finite'', material = ''neo_hooke'' /'
      write(u, '(a)') '&amplitude name = ''ramp'', time = 0.0, 40.0, value = 0.0, 1.0 /'
      write(u, '(a)') '&boundary set = ''bottom'', type = ''fixed'', components = ''y'' /'
      write(u, '(a)') '&boundary set = ''top'', type = ''fixed'', components = ''y'' /'
      write(u, '(a)') '&boundary set = ''left'', type = ''displacement'', components = ''x'', value = 0.5, 0.0, ' // &
        'amplitude = ''ramp'' /'
      write(u, '(a)') '&time t_end = 80.0, damping = 1.5 /'
      close(u)
      allocate(run)
      call run_deck('./tube.nml', run, err)
      if (err%failed()) call check(failure, .false., types(k) // ': ' // err%message)
      if (allocated(failure)) return
      allocate(f(2, run%model%nnode), source=0.0_wp)
      call add_internal_force(run%model%bodies(1)%blocks(1), run%state%u, f)
      fr = 0.0_wp
      ub = 0.0_wp
      do n = 1, run%model%nnode
        if (abs(run%model%x(1, n) - ra) < 1.0e-12_wp) fr = fr + f(1, n)
        if (abs(run%model%x(1, n) - rb) < 1.0e-12_wp) ub = run%state%u(1, n)
      end do
      pfe = fr/(2.0_wp*pi*a*hz)
      print '(a)', '        ' // types(k) // ': bore pressure ' // str(pfe, 6) // ', incompressible closed form ' // &
        str(p, 6) // ' (' // str(p/g, 4) // ' G), error ' // str(pfe/p - 1.0_wp, 3) // ', outer radius ' // &
        str(rb + ub, 6) // ' (closed form ' // str(b, 6) // '), worst balance ' // &
        str(run%worst_balance, 3) // ', ' // str(run%state%step) // ' steps'
      call check(failure, abs(pfe/p - 1.0_wp) < 3.0e-3_wp, types(k) // ': bore pressure ' // str(pfe) // &
        ' not within 0.3 % of ' // str(p))
      call check(failure, abs(ub + rb - b) < 1.0e-2_wp*(b - rb), types(k) // ': outer radius ' // str(rb + ub) // &
        ' off the closed form ' // str(b))
      call check(failure, run%worst_balance < 1.0e-3_wp, types(k) // ': energy balance ' // str(run%worst_balance))
      deallocate(run, f)
      if (allocated(failure)) return
    end do
  end subroutine test_tube
end program test_axi_finite_runs
