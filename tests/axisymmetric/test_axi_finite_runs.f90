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
!>  - the j2 hollow sphere of plastic_axi (a = 1, b = 2), plastic to
!>    c = 1.2 (strains of 5e-4), in finite strain: u(b) within 1 % of the
!>    exact small-strain elastic-plastic solution (Hill 1950). Not at
!>    plastic_axi's c = 1.5: there the bore pressure, which follows the
!>    growing bore, makes u(b) 1.0 % larger in finite than in small strain
!>    (CalculiX CAX4 NLGEOM against its small-strain run on this mesh:
!>    +1.00 %; raccord +0.95 %), so the small-strain solution is no
!>    reference to 1 %; at c = 1.2 CalculiX's finite-strain effect is
!>    +0.32 % (doc/verification.md, section 17.5).
!>  - a neo-Hooke cylinder (axisymmetric) and block (plane strain),
!>    stretched 1.4 along y and pressed by p = 30 (E = 1000) on its side
!>    x = 2: homogeneous, the side's displacement equals the closed form
!>    with sigma_xx = -p on the deformed side (the pressure follows the
!>    surface, as in Abaqus and CalculiX with NLGEOM) to 1e-6; a pressure
!>    held on the undeformed side gives a 2 % smaller contraction.
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
      test_tube), &
    new_test('pressure on a stretched neo-Hooke block follows the surface (axisymmetric, plane strain)', &
      test_follower_pressure)])

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
    real(wp), parameter :: young = 210000.0_wp, nu = 0.3_wp, sy = 240.0_wp, a = 1.0_wp, b = 2.0_wp, c = 1.2_wp
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
  !> A neo-Hooke block [0, 2] x [0, 2], E = 1000, nu = 0.3, its bottom on
  !> rollers, its top driven to y = 2.8 (stretch 1.4) and a pressure p = 30
  !> on its side x = 2; axisymmetric (x = r: a solid cylinder, the axis
  !> held by raccord) and plane strain (x = 0 on rollers). The state is
  !> homogeneous, F = diag(l, 1.4, l_t) with l_t = l (axisymmetric) or 1,
  !> and sigma_xx = -p on the deformed side fixes l (bisection on the
  !> Cauchy stress of neo-Hooke, W = C10 (Ibar1 - 3) + (J - 1)^2/D1). A
  !> pressure held on the undeformed side (the nominal stress P_xx = -p)
  !> gives sigma_xx = -p l / J instead, 2 % less contraction here: the
  !> test tells the two apart 1e4 times over.
  subroutine test_follower_pressure(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp), parameter :: w = 2.0_wp
    character(len=*), parameter :: hyp(2) = [character(len=12) :: 'axisymmetric', 'plane_strain']
    character(len=4), parameter :: types(2, 2) = reshape(['CAX4', 'CAX8', 'CPE4', 'CPE8'], [2, 2])
    integer, parameter :: nens(2) = [4, 8]
    type(scene_run_t), allocatable :: run
    type(error_t) :: err
    real(wp) :: l_exact, l_dead, err_max, x(2)
    integer :: ih, k, u, n, nside
    do ih = 1, 2
      l_exact = lateral_stretch(ih == 1, .true.)
      l_dead = lateral_stretch(ih == 1, .false.)
      do k = 1, 2
        call write_mesh_inp('fol.inp', 'rect', nens(k), 3, 3, [0.0_wp, w, 0.0_wp, w], types(k, ih))
        open(newunit=u, file='fol.nml', status='replace', action='write')
        write(u, '(a)') '&mesh file = ''fol.inp'' /'
        write(u, '(a)') '&body name = ''body'', young = 1000.0, poisson = 0.3, density = 1.0e-9, kinematics = ''finite'','
        write(u, '(a)') '  material = ''neo_hooke'', hypothesis = ''' // trim(hyp(ih)) // ''' /'
        write(u, '(a)') '&amplitude name = ''ramp'', time = 0.0, 6.0e-5, value = 0.0, 1.0 /'
        write(u, '(a)') '&boundary set = ''bottom'', type = ''fixed'', components = ''y'' /'
        if (ih == 2) write(u, '(a)') '&boundary set = ''left'', type = ''fixed'', components = ''x'' /'
        write(u, '(a)') '&boundary set = ''top'', type = ''displacement'', components = ''y'', value = 0.0, 0.8, ' // &
          'amplitude = ''ramp'' /'
        write(u, '(a)') '&boundary set = ''right'', type = ''pressure'', pressure = 30.0, amplitude = ''ramp'' /'
        write(u, '(a)') '&time t_end = 2.4e-4, damping = 1.0e6 /'
        close(u)
        allocate(run)
        call run_deck('./fol.nml', run, err)
        if (err%failed()) call check(failure, .false., types(k, ih) // ': ' // err%message)
        if (allocated(failure)) return
        err_max = 0.0_wp
        nside = 0
        do n = 1, run%model%nnode
          x = run%mesh%x(:, n)
          if (abs(x(1) - w) > 1.0e-9_wp) cycle
          nside = nside + 1
          err_max = max(err_max, abs(run%state%u(1, n) - w*(l_exact - 1.0_wp)))
        end do
        err_max = err_max/(w*abs(l_exact - 1.0_wp))
        print '(a)', '        ' // types(k, ih) // ': side u_x error ' // str(err_max, 3) // ' of w (l - 1) = ' // &
          str(w*(l_exact - 1.0_wp), 8) // ' (a pressure on the undeformed side: ' // str(w*(l_dead - 1.0_wp), 8) // &
          '), ' // str(nside) // ' side nodes, balance at the end ' // &
          str(run%state%energy%balance/run%state%energy%scale, 3) // ' of the energy scale'
        call check(failure, nside > 0 .and. err_max < 1.0e-6_wp, types(k, ih) // ': side displacement off by ' // &
          str(err_max) // ' of the closed form')
        ! the work of the following pressure is in the account (the worst
        ! balance, 5e-4 in the first steps, is the start of the driven top,
        ! the same with a traction)
        call check(failure, abs(run%state%energy%balance) < 1.0e-4_wp*run%state%energy%scale, types(k, ih) // &
          ': energy balance at the end ' // str(run%state%energy%balance/run%state%energy%scale))
        deallocate(run)
        if (allocated(failure)) return
      end do
    end do
  end subroutine test_follower_pressure

  !> The lateral stretch l of the block of test_follower_pressure with
  !> sigma_xx = -p (follows) or P_xx = -p (not), by bisection.
  real(wp) function lateral_stretch(axi, follows) result(l)
    logical, intent(in) :: axi, follows
    real(wp) :: lo, hi
    integer :: it
    lo = 0.5_wp
    hi = 1.0_wp
    do it = 1, 200
      l = 0.5_wp*(lo + hi)
      if (side_residual(l, axi, follows) > 0.0_wp) then
        hi = l
      else
        lo = l
      end if
    end do
  end function lateral_stretch

  !> sigma_xx + p (or + p l / J) of neo-Hooke (E = 1000, nu = 0.3) at
  !> F = diag(l, 1.4, l_t).
  real(wp) function side_residual(l, axi, follows) result(r)
    real(wp), intent(in) :: l
    logical, intent(in) :: axi, follows
    real(wp), parameter :: young = 1000.0_wp, nu = 0.3_wp, p = 30.0_wp, lz = 1.4_wp
    real(wp) :: c10, d1, lt, j, bb(3)
    c10 = young/(4.0_wp*(1.0_wp + nu))
    d1 = 6.0_wp*(1.0_wp - 2.0_wp*nu)/young
    lt = 1.0_wp
    if (axi) lt = l
    j = l*lz*lt
    bb = [l*l, lz*lz, lt*lt]*j**(-2.0_wp/3.0_wp)
    r = 2.0_wp*c10/j*(bb(1) - sum(bb)/3.0_wp) + 2.0_wp/d1*(j - 1.0_wp)
    if (follows) then
      r = r + p
    else
      r = r + p*l/j
    end if
  end function side_residual

end program test_axi_finite_runs
