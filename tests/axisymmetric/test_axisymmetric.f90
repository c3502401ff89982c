!> Axisymmetric bodies (doc/theory-axisymmetric.md; method brief
!> method-finite-plastic-axi.md section 9): Lame's thick cylinder and the
!> hollow sphere against their closed forms (static solutions with the
!> blocks' element stiffness), the chunk kernels against the Gauss-sum
!> stiffness, ring-total masses and loads, uniform radial expansion (exact)
!> and rigid motion along the axis through the explicit loop, and the
!> refused inputs.
program test_axisymmetric
  use raccord_kinds, only: wp, pi
  use raccord_error, only: error_t, EXIT_INPUT
  use raccord_check, only: failure_t, new_test, run_tests, check, check_close
  use raccord_strings, only: str
  use raccord_scene_runner, only: scene_run_t, run_deck, prepare_deck
  use raccord_elastic_block, only: add_internal_force, element_stiffness
  use axi_support, only: write_mesh_inp, static_solution, nodal_stress, gauss_stresses
  implicit none

  real(wp), parameter :: young = 210000.0_wp, nu = 0.3_wp, p_in = 100.0_wp

  call run_tests('axisymmetric', [ &
    new_test('Lame cylinder (plane-strain ends), Q8 8 and Q4 16 through the wall', test_lame), &
    new_test('hollow sphere (quarter section, axis nodes), Q8 8 and Q4 16 through the wall', test_sphere), &
    new_test('kernel = Gauss-sum stiffness; ring-total mass and pressure load', test_kernel), &
    new_test('uniform radial expansion is exact, axis included', test_expansion), &
    new_test('explicit run: rigid translation along the axis keeps zero stress', test_translation), &
    new_test('explicit run: radial expansion settles on the closed-form hoop stress', test_expansion_run), &
    new_test('refused: node at r < 0, mixed hypotheses, driven u_r on the axis', test_refused), &
    new_test('thickness ignored when axisymmetric; CAX elements in a plane deck run plane', test_ignored)])

contains

  !> The error's message, '' when there is none.
  function emsg(err) result(m)
    type(error_t), intent(in) :: err
    character(len=:), allocatable :: m
    m = ''
    if (allocated(err%message)) m = err%message
  end function emsg

  !> A deck for mesh `mesh` (in the working folder) with one axisymmetric
  !> body 'body' and the given &boundary lines and &time group.
  function write_deck(name, mesh, bcs, time_group, body_extra) result(path)
    character(len=*), intent(in) :: name, mesh, bcs(:), time_group
    character(len=*), intent(in), optional :: body_extra
    character(len=:), allocatable :: path
    integer :: u, k
    path = './' // name // '.nml'
    open(newunit=u, file=path, status='replace', action='write')
    write(u, '(a)') '&mesh file = ''' // mesh // ''' /'
    write(u, '(a)') '&body name = ''body'', young = 210000.0, poisson = 0.3, density = 1.0,'
    if (present(body_extra)) write(u, '(a)') '  ' // body_extra // ','
    write(u, '(a)') '  hypothesis = ''axisymmetric'' /'
    do k = 1, size(bcs)
      write(u, '(a)') trim(bcs(k))
    end do
    write(u, '(a)') time_group
    close(u)
  end function write_deck

  !> Lame (Timoshenko & Goodier; method brief 9.5), a = 1, b = 2, p_i = 100,
  !> u_z = 0 on both faces (plane strain): sigma_r = A - B/r^2,
  !> sigma_t = A + B/r^2, sigma_z = 2 nu A, u = ((1+nu)/E)((1-2nu) A r + B/r).
  !> Nodal u within 0.5 %; stresses within 2 % of sigma_t(a) at the 3x3
  !> points of Q8 and the centres of Q4 (at the 2x2 points of Q4 the radial
  !> strain is the element's secant slope, off by u'' 0.29 h: 4.7 % for the
  !> cylinder and 15 % for the sphere next to the loaded face, as estimated).
  subroutine test_lame(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call lame_case(failure, 8, 8, 'CAX8')
    call lame_case(failure, 4, 16, 'CAX4')
  end subroutine test_lame

  subroutine lame_case(failure, nen, nr, eltype)
    type(failure_t), allocatable, intent(inout) :: failure
    integer, intent(in) :: nen, nr
    character(len=*), intent(in) :: eltype
    real(wp), parameter :: a = 1.0_wp, b = 2.0_wp
    type(scene_run_t) :: run
    type(error_t) :: err
    real(wp), allocatable :: u(:,:), s(:,:), xg(:,:)
    real(wp) :: ca, cb, r, ue, se(4), eu, es, smax
    integer :: n
    character(len=:), allocatable :: mesh
    mesh = 'lame_' // eltype // '.inp'
    call write_mesh_inp(mesh, 'rect', nen, nr, 2, [a, b, 0.0_wp, 0.25_wp], eltype)
    call prepare_deck(write_deck('lame_' // eltype, mesh, [character(len=120) :: &
      '&boundary set = ''bottom'', type = ''fixed'', components = ''y'' /', &
      '&boundary set = ''top'', type = ''fixed'', components = ''y'' /', &
      '&boundary set = ''left'', type = ''pressure'', pressure = 100.0 /'], '&time t_end = 1.0e-3 /'), run, err)
    call check(failure, .not. err%failed(), eltype // ': ' // emsg(err))
    if (err%failed()) return
    call static_solution(run, u)
    call gauss_stresses(run, u, young, nu, xg, s, .true.)
    ca = p_in*a**2/(b**2 - a**2)
    cb = p_in*a**2*b**2/(b**2 - a**2)
    eu = 0.0_wp
    es = 0.0_wp
    smax = ca + cb/a**2
    do n = 1, run%model%nnode
      r = run%model%x(1, n)
      ue = (1.0_wp + nu)/young*((1.0_wp - 2.0_wp*nu)*ca*r + cb/r)
      eu = max(eu, abs(u(1, n) - ue)/ue, abs(u(2, n))/ue)
    end do
    do n = 1, size(xg, 2)
      r = xg(1, n)
      se = [ca - cb/r**2, 2.0_wp*nu*ca, 0.0_wp, ca + cb/r**2]
      es = max(es, maxval(abs(s(:, n) - se))/smax)
    end do
    print '(a)', '        Lame ' // eltype // ' ' // str(nr) // ' through the wall: largest error of u_r ' // &
      str(eu, 3) // ' of u_r, of the Gauss-point (Q4: centre) stresses ' // str(es, 3) // ' of sigma_t(a); u_r(a) closed form ' // &
      str((1.0_wp + nu)/young*((1.0_wp - 2.0_wp*nu)*ca*a + cb/a), 5)
    call check(failure, eu < 5.0e-3_wp, eltype // ': displacement off by ' // str(eu))
    call check(failure, es < 2.0e-2_wp, eltype // ': Gauss-point stress off by ' // str(es))
  end subroutine lame_case

  !> Hollow sphere a = 1, b = 2, p_i = 100 (method brief 9.5):
  !> sigma_r = A - 2B/r^3, sigma_t = A + B/r^3, u = ((1-2nu) A r + (1+nu) B/r^2)/E,
  !> modelled as a quarter section with u_z = 0 on the equator and the axis
  !> nodes held radially by the code itself.
  subroutine test_sphere(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call sphere_case(failure, 8, 8, 12, 'CAX8')
    call sphere_case(failure, 4, 16, 24, 'CPE4')
  end subroutine test_sphere

  subroutine sphere_case(failure, nen, nr, nt, eltype)
    type(failure_t), allocatable, intent(inout) :: failure
    integer, intent(in) :: nen, nr, nt
    character(len=*), intent(in) :: eltype
    real(wp), parameter :: a = 1.0_wp, b = 2.0_wp
    type(scene_run_t) :: run
    type(error_t) :: err
    real(wp), allocatable :: u(:,:), s(:,:), xg(:,:)
    real(wp) :: ca, cb, rho, ue, urad, st, sr, eu, es, smax, sig(2)
    integer :: n
    character(len=:), allocatable :: mesh
    mesh = 'sphere_' // eltype // '.inp'
    call write_mesh_inp(mesh, 'shell', nen, nr, nt, [a, b, 0.0_wp, 0.0_wp], eltype)
    call prepare_deck(write_deck('sphere_' // eltype, mesh, [character(len=120) :: &
      '&boundary set = ''bottom'', type = ''fixed'', components = ''y'' /', &
      '&boundary set = ''left'', type = ''pressure'', pressure = 100.0 /'], '&time t_end = 1.0e-3 /'), run, err)
    call check(failure, .not. err%failed(), eltype // ': ' // emsg(err))
    if (err%failed()) return
    call check(failure, run%model%supports(size(run%model%supports))%set == 'axis', &
      eltype // ': the axis nodes are not held')
    call static_solution(run, u)
    call gauss_stresses(run, u, young, nu, xg, s, .true.)
    ca = p_in*a**3/(b**3 - a**3)
    cb = p_in*a**3*b**3/(2.0_wp*(b**3 - a**3))
    smax = ca + cb/a**3
    eu = 0.0_wp
    es = 0.0_wp
    do n = 1, run%model%nnode
      rho = norm2(run%model%x(:, n))
      ue = ((1.0_wp - 2.0_wp*nu)*ca*rho + (1.0_wp + nu)*cb/rho**2)/young
      ! radial displacement along the position vector, and no tangential one
      urad = dot_product(u(:, n), run%model%x(:, n))/rho
      eu = max(eu, abs(urad - ue)/ue, abs(u(1, n)*run%model%x(2, n) - u(2, n)*run%model%x(1, n))/(rho*ue))
    end do
    do n = 1, size(xg, 2)
      associate (x => xg(:, n))
        rho = norm2(x)
        sr = ca - 2.0_wp*cb/rho**3
        st = ca + cb/rho**3
        ! (sr, st) of the spherical frame rotated into (r, z); the hoop
        ! component is st everywhere
        sig = [sr*(x(1)/rho)**2 + st*(x(2)/rho)**2, sr*(x(2)/rho)**2 + st*(x(1)/rho)**2]
        es = max(es, abs(s(1, n) - sig(1))/smax, abs(s(2, n) - sig(2))/smax, abs(s(4, n) - st)/smax, &
          abs(s(3, n) - (sr - st)*x(1)*x(2)/rho**2)/smax)
      end associate
    end do
    print '(a)', '        sphere ' // eltype // ' ' // str(nr) // ' x ' // str(nt) // ': largest error of u ' // &
      str(eu, 3) // ' of u, of the Gauss-point (Q4: centre) stresses ' // str(es, 3) // ' of sigma_t(a) = ' // str(smax, 5)
    call check(failure, eu < 5.0e-3_wp, eltype // ': displacement off by ' // str(eu))
    call check(failure, es < 2.0e-2_wp, eltype // ': Gauss-point stress off by ' // str(es))
  end subroutine sphere_case

  !> The chunk kernel against K from the Gauss sum for a random u, on a
  !> mesh that touches the axis; the lumped mass sums to rho pi (r1^2 - r0^2) h
  !> and a pressure on the top face to p pi (r1^2 - r0^2).
  subroutine test_kernel(failure)
    type(failure_t), allocatable, intent(out) :: failure
    integer :: nen
    do nen = 4, 8, 4
      call kernel_case(failure, nen, 'rect')
      call kernel_case(failure, nen, 'shell')
    end do
  end subroutine test_kernel

  subroutine kernel_case(failure, nen, shape)
    type(failure_t), allocatable, intent(inout) :: failure
    integer, intent(in) :: nen
    !> rect: the r-z rectangle below (parallelograms); shell: a quarter of
    !> a thick sphere, r in [0.5, 1.5] (curved, distorted elements: the
    !> xi eta terms of the Q4 kernel's map), the kernel check only
    character(len=*), intent(in) :: shape
    type(scene_run_t) :: run
    type(error_t) :: err
    real(wp), allocatable :: u(:,:), f(:,:), g(:,:)
    real(wp) :: ke(16, 16), ue(16), fz
    integer :: e, a, i, nd
    character(len=:), allocatable :: mesh, tag
    tag = 'Q' // str(nen) // '_' // shape
    mesh = 'kernel_' // tag // '.inp'
    if (shape == 'shell') then
      call write_mesh_inp(mesh, 'shell', nen, 3, 5, [0.5_wp, 1.5_wp, 0.0_wp, 0.0_wp], 'CAX' // str(nen))
    else
      call write_mesh_inp(mesh, 'rect', nen, 5, 3, [0.0_wp, 1.5_wp, 0.2_wp, 1.0_wp], 'CAX' // str(nen))
    end if
    call prepare_deck(write_deck('kernel_' // tag, mesh, [character(len=120) :: &
      '&boundary set = ''top'', type = ''pressure'', pressure = 7.0 /'], '&time t_end = 1.0e-3 /'), run, err)
    call check(failure, .not. err%failed(), tag // ': ' // emsg(err))
    if (err%failed()) return
    associate (blk => run%model%bodies(1)%blocks(1))
      allocate(u(2, run%model%nnode), f(2, run%model%nnode), g(2, run%model%nnode))
      call random_number(u)
      u = u - 0.5_wp
      f = 0.0_wp
      call add_internal_force(blk, u, f)
      g = 0.0_wp
      nd = 2*nen
      do e = 1, blk%nel
        call element_stiffness(blk, e, ke(1:nd, 1:nd))
        do a = 1, nen
          ue(2*a - 1:2*a) = u(:, blk%conn(a, e))
        end do
        ue(1:nd) = matmul(ke(1:nd, 1:nd), ue(1:nd))
        do a = 1, nen
          g(:, blk%conn(a, e)) = g(:, blk%conn(a, e)) + ue(2*a - 1:2*a)
        end do
      end do
      call check(failure, maxval(abs(f - g)) <= 1.0e-12_wp*maxval(abs(g)), tag // ': kernel differs from ' // &
        'the Gauss-sum stiffness by ' // str(maxval(abs(f - g))/maxval(abs(g))))
    end associate
    if (shape == 'shell') return
    call check_close(failure, sum(run%model%mass), pi*1.5_wp**2*0.8_wp, tag // ': total mass', rel_tol=1.0e-13_wp)
    fz = 0.0_wp
    do i = 1, size(run%model%loads(1)%nodes)
      fz = fz + run%model%loads(1)%force(2, i)
    end do
    call check_close(failure, fz, -7.0_wp*pi*1.5_wp**2, tag // ': ring-total pressure load', rel_tol=1.0e-13_wp)
    call check(failure, maxval(abs(run%model%loads(1)%force(1, :))) < 1.0e-12_wp, tag // ': radial load component')
  end subroutine kernel_case

  !> u_r = eps r, u_z = 0 is the static solution with u_r = eps b on r = b
  !> and u_z = 0 on both faces; linear, so exact in both elements:
  !> sigma_rr = sigma_tt = 2 (lam + mu) eps, sigma_zz = 2 lam eps.
  subroutine test_expansion(failure)
    type(failure_t), allocatable, intent(out) :: failure
    integer :: nen
    do nen = 4, 8, 4
      call expansion_case(failure, nen)
    end do
  end subroutine test_expansion

  subroutine expansion_case(failure, nen)
    type(failure_t), allocatable, intent(inout) :: failure
    integer, intent(in) :: nen
    real(wp), parameter :: eps = 1.0e-3_wp
    type(scene_run_t) :: run
    type(error_t) :: err
    real(wp), allocatable :: u(:,:), s(:,:)
    real(wp) :: lam, mu, expect(4)
    integer :: n
    character(len=:), allocatable :: tag
    tag = 'Q' // str(nen)
    call write_mesh_inp('expand_' // tag // '.inp', 'rect', nen, 4, 2, [0.0_wp, 2.0_wp, 0.0_wp, 1.0_wp], &
      'CAX' // str(nen))
    call prepare_deck(write_deck('expand_' // tag, 'expand_' // tag // '.inp', [character(len=120) :: &
      '&boundary set = ''bottom'', type = ''fixed'', components = ''y'' /', &
      '&boundary set = ''top'', type = ''fixed'', components = ''y'' /', &
      '&boundary set = ''left'', type = ''fixed'', components = ''x'' /', &
      '&boundary set = ''right'', type = ''displacement'', components = ''x'', value = 2.0e-3, 0.0 /'], &
      '&time t_end = 1.0e-3 /'), run, err)
    call check(failure, .not. err%failed(), tag // ': ' // emsg(err))
    if (err%failed()) return
    call static_solution(run, u)
    call nodal_stress(run, u, s)
    mu = young/(2.0_wp*(1.0_wp + nu))
    lam = young*nu/((1.0_wp + nu)*(1.0_wp - 2.0_wp*nu))
    expect = [2.0_wp*(lam + mu)*eps, 2.0_wp*lam*eps, 0.0_wp, 2.0_wp*(lam + mu)*eps]
    do n = 1, run%model%nnode
      call check(failure, abs(u(1, n) - eps*run%model%x(1, n)) < 1.0e-12_wp, tag // ': u_r /= eps r at node ' // str(n))
      call check(failure, maxval(abs(s(:, n) - expect)) < 1.0e-9_wp*expect(1), tag // ': stress at node ' // &
        str(n) // ' off by ' // str(maxval(abs(s(:, n) - expect))))
      if (allocated(failure)) return
    end do
  end subroutine expansion_case

  !> A free body touching the axis, moving along it at v = 1: no stress,
  !> no internal energy, every node at the same velocity.
  subroutine test_translation(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(scene_run_t) :: run
    type(error_t) :: err
    real(wp), allocatable :: s(:,:)
    real(wp) :: scale
    call write_mesh_inp('translate.inp', 'rect', 8, 3, 2, [0.0_wp, 1.0_wp, 0.0_wp, 1.0_wp], 'CAX8')
    call run_deck(write_deck('translate', 'translate.inp', [character(len=1) :: ], &
      '&time t_end = 2.0e-3 /', 'velocity = 0.0, 1.0'), run, err)
    call check(failure, .not. err%failed(), emsg(err))
    if (err%failed()) return
    call nodal_stress(run, run%state%u, s)
    scale = young*maxval(abs(run%state%u))
    print '(a)', '        ' // str(run%state%step) // ' steps, moved ' // str(maxval(run%state%u(2, :)), 4) // &
      ', largest stress / (E |u|) ' // str(maxval(abs(s))/scale, 3)
    call check(failure, maxval(abs(s)) < 1.0e-12_wp*scale, 'stress of a rigid motion ' // str(maxval(abs(s))))
    call check(failure, maxval(abs(run%state%u(1, :))) < 1.0e-15_wp, 'radial motion appeared')
    call check(failure, maxval(abs(run%state%v(2, :) - 1.0_wp)) < 1.0e-12_wp, 'velocity changed')
  end subroutine test_translation

  !> The expansion of test_expansion through the explicit loop: ramp, then
  !> a damped hold; the hoop stress settles on 2 (lam + mu) eps.
  subroutine test_expansion_run(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp), parameter :: eps = 1.0e-3_wp
    type(scene_run_t) :: run
    type(error_t) :: err
    real(wp), allocatable :: s(:,:)
    real(wp) :: lam, mu, expect, worst
    call write_mesh_inp('expand_run.inp', 'rect', 4, 6, 3, [0.0_wp, 2.0_wp, 0.0_wp, 1.0_wp], 'CAX4')
    call run_deck(write_deck('expand_run', 'expand_run.inp', [character(len=120) :: &
      '&amplitude name = ''ramp'', time = 0.0, 2.0e-3, value = 0.0, 1.0 /', &
      '&boundary set = ''bottom'', type = ''fixed'', components = ''y'' /', &
      '&boundary set = ''top'', type = ''fixed'', components = ''y'' /', &
      '&boundary set = ''right'', type = ''displacement'', components = ''x'', value = 2.0e-3, 0.0, ' // &
      'amplitude = ''ramp'' /'], '&time t_end = 0.2, damping = 800.0 /'), run, err)
    call check(failure, .not. err%failed(), emsg(err))
    if (err%failed()) return
    call nodal_stress(run, run%state%u, s)
    mu = young/(2.0_wp*(1.0_wp + nu))
    lam = young*nu/((1.0_wp + nu)*(1.0_wp - 2.0_wp*nu))
    expect = 2.0_wp*(lam + mu)*eps
    worst = maxval(abs(s(4, :) - expect))/expect
    print '(a)', '        ' // str(run%state%step) // ' steps, hoop stress within ' // str(worst, 3) // &
      ' of 2 (lam + mu) eps = ' // str(expect, 6) // '; energy balance ' // str(run%worst_balance, 3)
    call check(failure, worst < 1.0e-8_wp, 'hoop stress off by ' // str(worst))
    call check(failure, run%worst_balance < 1.0e-3_wp, 'energy balance ' // str(run%worst_balance))
  end subroutine test_expansion_run

  !> Bad axisymmetric input: messages that name the node, the bodies, the set.
  subroutine test_refused(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(scene_run_t) :: run
    type(error_t) :: err
    integer :: u
    ! a section crossing the axis
    call write_mesh_inp('cross.inp', 'rect', 4, 4, 1, [-0.5_wp, 1.5_wp, 0.0_wp, 1.0_wp], 'CAX4')
    call prepare_deck(write_deck('cross', 'cross.inp', [character(len=1) :: ], &
      '&time t_end = 1.0e-3 /'), run, err)
    call check(failure, err%failed() .and. err%code == EXIT_INPUT, 'a mesh crossing the axis was accepted')
    if (allocated(failure)) return
    print '(a)', '        ' // emsg(err)
    call check(failure, index(emsg(err), 'node 1 ') > 0 .and. index(emsg(err), 'r = x') > 0, &
      'the message does not name the node')
    ! mixed hypotheses
    call err%clear()
    call write_mesh_inp('two.inp', 'rect', 4, 2, 1, [0.0_wp, 1.0_wp, 0.0_wp, 1.0_wp], 'CAX4', elset='one', &
      prefix='one_')
    call write_mesh_inp('two.inp', 'rect', 4, 2, 1, [0.0_wp, 1.0_wp, 2.0_wp, 3.0_wp], 'CAX4', elset='two', &
      prefix='two_', append=.true., id0=100)
    open(newunit=u, file='mixed.nml', status='replace', action='write')
    write(u, '(a)') '&mesh file = ''two.inp'' /'
    write(u, '(a)') '&body name = ''one'', young = 1.0, poisson = 0.3, density = 1.0, hypothesis = ''axisymmetric'' /'
    write(u, '(a)') '&body name = ''two'', young = 1.0, poisson = 0.3, density = 1.0 /'
    write(u, '(a)') '&time t_end = 1.0 /'
    close(u)
    call prepare_deck('./mixed.nml', run, err)
    call check(failure, err%failed() .and. err%code == EXIT_INPUT, 'mixed hypotheses were accepted')
    if (allocated(failure)) return
    print '(a)', '        ' // emsg(err)
    call check(failure, index(emsg(err), 'hypothesis') > 0 .and. index(emsg(err), '''one''') > 0, &
      'the message does not name the key and the other body')
    ! u_r driven on the axis; fixed there is accepted
    call err%clear()
    call write_mesh_inp('axis.inp', 'rect', 4, 2, 1, [0.0_wp, 1.0_wp, 0.0_wp, 1.0_wp], 'CAX4')
    call prepare_deck(write_deck('axis_fixed', 'axis.inp', [character(len=120) :: &
      '&boundary set = ''left'', type = ''fixed'', components = ''x'' /'], '&time t_end = 1.0e-3 /'), run, err)
    call check(failure, .not. err%failed(), 'u_r = 0 fixed on the axis by the deck was refused: ' // emsg(err))
    if (allocated(failure)) return
    call check(failure, run%model%supports(size(run%model%supports))%set == 'left', &
      'a second support was added on the axis')
    call prepare_deck(write_deck('axis_driven', 'axis.inp', [character(len=120) :: &
      '&boundary set = ''left'', type = ''displacement'', components = ''x'', value = 0.1, 0.0 /'], &
      '&time t_end = 1.0e-3 /'), run, err)
    call check(failure, err%failed() .and. err%code == EXIT_INPUT, 'u_r driven on the axis was accepted')
    if (allocated(failure)) return
    print '(a)', '        ' // emsg(err)
    call check(failure, index(emsg(err), '''left''') > 0 .and. index(emsg(err), 'axis') > 0, &
      'the message does not name the set')
  end subroutine test_refused

  !> thickness = 2 on an axisymmetric body is ignored (the masses are those
  !> of thickness 1 = the ring's); a CAX4 mesh under a plane deck is read
  !> as Q4 and runs plane (raccord_model_build warns).
  subroutine test_ignored(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(scene_run_t) :: run
    type(error_t) :: err
    integer :: u
    call write_mesh_inp('thick.inp', 'rect', 4, 2, 1, [0.0_wp, 1.0_wp, 0.0_wp, 1.0_wp], 'CAX4')
    call prepare_deck(write_deck('thick', 'thick.inp', [character(len=1) :: ], '&time t_end = 1.0e-3 /', &
      'thickness = 2.0'), run, err)
    call check(failure, .not. err%failed(), 'thickness with an axisymmetric body refused: ' // emsg(err))
    if (allocated(failure)) return
    call check(failure, run%scene%bodies(1)%thickness == 1.0_wp, 'thickness not ignored')
    call check_close(failure, sum(run%model%mass), pi, 'ring mass rho pi r^2 h', rel_tol=1.0e-13_wp)
    open(newunit=u, file='plane_cax.nml', status='replace', action='write')
    write(u, '(a)') '&mesh file = ''thick.inp'' /'
    write(u, '(a)') '&body name = ''body'', young = 210000.0, poisson = 0.3, density = 1.0 /'
    write(u, '(a)') '&time t_end = 1.0e-3 /'
    close(u)
    call prepare_deck('./plane_cax.nml', run, err)
    call check(failure, .not. err%failed(), 'plane deck on a CAX mesh refused: ' // emsg(err))
    if (allocated(failure)) return
    call check(failure, run%mesh%axi_types == 'CAX4', 'the CAX types were not recorded: ''' // run%mesh%axi_types // '''')
    call check(failure, .not. run%model%axisymmetric, 'a plane deck ran axisymmetric')
    call check_close(failure, sum(run%model%mass), 1.0_wp, 'plane mass rho A t', rel_tol=1.0e-13_wp)
  end subroutine test_ignored
end program test_axisymmetric
