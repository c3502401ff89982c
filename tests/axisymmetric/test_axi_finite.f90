!> Axisymmetric bodies in finite strain (raccord_finite_axi_kernel;
!> doc/theory-axisymmetric.md, "Finite strain and plasticity"), at element
!> and block level, Q4 and Q8, meshes touching the axis:
!>  - the forces are the gradient of the stored energy (central finite
!>    differences), neo-Hooke (full and mean dilatation) and SVK;
!>  - a homogeneous radial + axial stretch F = diag(a, b, a) (F_tt = r/R = a)
!>    plus a translation along the axis gives the closed-form Cauchy stress
!>    (rr, zz, rz, tt) at every node, no force inside, and a translation
!>    alone no stress and no force;
!>  - at small displacement the forces equal the small-strain axisymmetric
!>    kernel's (Hooke) and the finite j2 kernel's equal the small j2 one's;
!>  - j2 (Hencky, exponential map): homogeneous uniaxial stress of a
!>    cylinder, stretch 1.2, against the closed form.
program test_axi_finite
  use raccord_kinds, only: wp
  use raccord_error, only: error_t
  use raccord_check, only: failure_t, new_test, run_tests, check
  use raccord_strings, only: str
  use raccord_scene_runner, only: scene_run_t, prepare_deck
  use raccord_elastic_block, only: add_internal_force, add_nodal_stress, block_watch_t, init_watch, watch_energy, &
    block_plastic_t, init_plastic, watch_inverted, element_eigenvalue_bounds, finite_w2_elements
  use axi_support, only: write_mesh_inp
  implicit none

  real(wp), parameter :: young = 7000.0_wp, nu = 0.3_wp
  integer :: nseed, iseed
  integer, allocatable :: seed(:)

  ! the same random displacements in every run
  call random_seed(size=nseed)
  seed = [(104729*iseed + 17, iseed = 1, nseed)]
  call random_seed(put=seed)
  call run_tests('axi_finite', [ &
    new_test('forces = dW/du (finite differences): neo-Hooke full and mean, SVK; Q4 and Q8', test_gradient), &
    new_test('homogeneous stretch + axial translation: closed-form Cauchy stress; translation: none', &
      test_homogeneous), &
    new_test('small displacement: finite = small-strain axisymmetric forces (Hooke and j2)', test_small_limit), &
    new_test('j2 Hencky: homogeneous uniaxial stress of a cylinder at stretch 1.2, closed form', test_j2_uniaxial), &
    new_test('stable step: the kernel''s estimate at rest >= the exact element bound (hoop terms, axis)', test_step)])

contains

  !> Mesh (nen = 4 or 8, nx x ny on [0, 1.5] x [0, 1], touching the axis) and
  !> a deck with one axisymmetric body; prepared (not run).
  subroutine prepare(failure, name, nen, body_keys, run)
    type(failure_t), allocatable, intent(inout) :: failure
    character(len=*), intent(in) :: name, body_keys
    integer, intent(in) :: nen
    type(scene_run_t), intent(out) :: run
    type(error_t) :: err
    integer :: u
    call write_mesh_inp(name // '.inp', 'rect', nen, 3, 2, [0.0_wp, 1.5_wp, 0.0_wp, 1.0_wp], 'CAX' // str(nen))
    open(newunit=u, file=name // '.nml', status='replace', action='write')
    write(u, '(a)') '&mesh file = ''' // name // '.inp'' /'
    write(u, '(a)') '&body name = ''body'', young = 7000.0, poisson = 0.3, density = 1.0e-3,'
    write(u, '(a)') '  hypothesis = ''axisymmetric'', ' // body_keys // ' /'
    write(u, '(a)') '&time t_end = 1.0e-3 /'
    close(u)
    call prepare_deck('./' // name // '.nml', run, err)
    if (err%failed()) call check(failure, .false., name // ': ' // err%message)
  end subroutine prepare

  !> Internal force and stored energy of block 1 at u (j2: from a virgin state).
  subroutine forces(run, u, f, w, jmin)
    type(scene_run_t), intent(in) :: run
    real(wp), intent(in) :: u(:,:)
    real(wp), intent(out) :: f(:,:), w
    real(wp), intent(out), optional :: jmin
    type(block_watch_t) :: watch
    type(block_plastic_t) :: plastic
    integer :: e
    real(wp) :: jm
    associate (blk => run%model%bodies(1)%blocks(1))
      call init_watch(blk, watch)
      f = 0.0_wp
      if (blk%material == 4) then
        call init_plastic(blk, plastic)
        call add_internal_force(blk, u, f, watch=watch, plastic=plastic)
      else
        call add_internal_force(blk, u, f, watch=watch)
      end if
      w = watch_energy(watch)
      call watch_inverted(watch, e, jm)
      if (present(jmin)) jmin = jm
    end associate
  end subroutine forces

  !> Nodal stress (rr, zz, rz, tt) of block 1 at u (j2: from a virgin state).
  subroutine stress(run, u, s)
    type(scene_run_t), intent(in) :: run
    real(wp), intent(in) :: u(:,:)
    real(wp), allocatable, intent(out) :: s(:,:)
    real(wp), allocatable :: wsum(:)
    type(block_plastic_t) :: plastic
    allocate(s(4, run%model%nnode), wsum(run%model%nnode), source=0.0_wp)
    associate (blk => run%model%bodies(1)%blocks(1))
      if (blk%material == 4) then
        call init_plastic(blk, plastic)
        call add_nodal_stress(blk, u, s, wsum, plastic=plastic)
      else
        call add_nodal_stress(blk, u, s, wsum)
      end if
    end associate
    where (wsum > 0.0_wp) s(1, :) = s(1, :)/wsum
    where (wsum > 0.0_wp) s(2, :) = s(2, :)/wsum
    where (wsum > 0.0_wp) s(3, :) = s(3, :)/wsum
    where (wsum > 0.0_wp) s(4, :) = s(4, :)/wsum
  end subroutine stress

  !> A random displacement of amplitude amp, u_r = 0 on the axis.
  subroutine random_u(run, amp, u)
    type(scene_run_t), intent(in) :: run
    real(wp), intent(in) :: amp
    real(wp), allocatable, intent(out) :: u(:,:)
    allocate(u(2, run%model%nnode))
    call random_number(u)
    u = amp*(u - 0.5_wp)
    where (run%model%x(1, :) == 0.0_wp) u(1, :) = 0.0_wp
  end subroutine random_u

  subroutine test_gradient(failure)
    type(failure_t), allocatable, intent(out) :: failure
    character(len=*), parameter :: laws(3) = [character(len=80) :: &
      'kinematics = ''finite'', material = ''neo_hooke'', volumetric = ''full''', &
      'kinematics = ''finite'', material = ''neo_hooke'', volumetric = ''mean_dilatation''', &
      'kinematics = ''finite'', material = ''svk''']
    character(len=*), parameter :: tags(3) = [character(len=8) :: 'nh full', 'nh mean', 'svk']
    type(scene_run_t), allocatable :: run
    real(wp), allocatable :: u(:,:), f(:,:), g(:,:)
    real(wp) :: wp1, wm1, w, h, worst, fmax, jmin
    integer :: nen, k, n, i
    do nen = 4, 8, 4
      do k = 1, 3
        allocate(run)
        call prepare(failure, 'grad_' // str(nen) // '_' // str(k), nen, trim(laws(k)), run)
        if (allocated(failure)) return
        call random_u(run, 0.1_wp, u)
        allocate(f(2, run%model%nnode), g(2, run%model%nnode))
        call forces(run, u, f, w, jmin)
        h = 1.0e-6_wp
        worst = 0.0_wp
        do n = 1, run%model%nnode
          do i = 1, 2
            u(i, n) = u(i, n) + h
            call forces(run, u, g, wp1)
            u(i, n) = u(i, n) - 2.0_wp*h
            call forces(run, u, g, wm1)
            u(i, n) = u(i, n) + h
            worst = max(worst, abs(f(i, n) - (wp1 - wm1)/(2.0_wp*h)))
          end do
        end do
        fmax = maxval(abs(f))
        print '(a)', '        Q' // str(nen) // ' ' // trim(tags(k)) // ': |f - dW/du| / max|f| = ' // &
          str(worst/fmax, 3) // ' (W = ' // str(w, 6) // ', smallest J ' // str(jmin, 3) // ')'
        ! (a random field that inverts a point is not a test of the gradient)
        call check(failure, jmin > 0.2_wp, 'Q' // str(nen) // ' ' // trim(tags(k)) // ': the random ' // &
          'displacement has J = ' // str(jmin) // ' at a Gauss point; take a smaller amplitude')
        call check(failure, worst <= 1.0e-7_wp*fmax, 'Q' // str(nen) // ' ' // trim(tags(k)) // &
          ': forces differ from dW/du by ' // str(worst/fmax))
        deallocate(run, f, g)
        if (allocated(failure)) return
      end do
    end do
  end subroutine test_gradient

  !> F = diag(a, b, a): J = a^2 b. neo-Hooke sigma = (G/J) dev(Bbar)' ... in
  !> principal form; SVK sigma = F S F^T / J with E = (F^2 - 1)/2.
  subroutine test_homogeneous(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp), parameter :: a = 1.3_wp, b = 0.8_wp, shift = 0.7_wp
    character(len=*), parameter :: laws(3) = [character(len=80) :: &
      'kinematics = ''finite'', material = ''neo_hooke'', volumetric = ''full''', &
      'kinematics = ''finite'', material = ''neo_hooke'', volumetric = ''mean_dilatation''', &
      'kinematics = ''finite'', material = ''svk''']
    type(scene_run_t), allocatable :: run
    real(wp), allocatable :: u(:,:), f(:,:), s(:,:)
    real(wp) :: g, kb, lam, j, jm23, tr, expect(4), err_s, err_f, er, ez, w
    integer :: nen, k, n
    logical :: inner
    g = young/(2.0_wp*(1.0_wp + nu))
    kb = young/(3.0_wp*(1.0_wp - 2.0_wp*nu))
    lam = young*nu/((1.0_wp + nu)*(1.0_wp - 2.0_wp*nu))
    j = a*a*b
    do nen = 4, 8, 4
      do k = 1, 3
        if (k < 3) then
          jm23 = j**(-2.0_wp/3.0_wp)
          tr = (2.0_wp*a*a + b*b)/3.0_wp
          expect(1) = (g*jm23*(a*a - tr) + kb*j*(j - 1.0_wp))/j
          expect(2) = (g*jm23*(b*b - tr) + kb*j*(j - 1.0_wp))/j
        else
          er = 0.5_wp*(a*a - 1.0_wp)
          ez = 0.5_wp*(b*b - 1.0_wp)
          expect(1) = a*a*(lam*(2.0_wp*er + ez) + 2.0_wp*g*er)/j
          expect(2) = b*b*(lam*(2.0_wp*er + ez) + 2.0_wp*g*ez)/j
        end if
        expect(3) = 0.0_wp
        expect(4) = expect(1)
        allocate(run)
        call prepare(failure, 'homog_' // str(nen) // '_' // str(k), nen, trim(laws(k)), run)
        if (allocated(failure)) return
        allocate(u(2, run%model%nnode), f(2, run%model%nnode))
        u(1, :) = (a - 1.0_wp)*run%model%x(1, :)
        u(2, :) = (b - 1.0_wp)*run%model%x(2, :) + shift
        call stress(run, u, s)
        call forces(run, u, f, w)
        err_s = 0.0_wp
        err_f = 0.0_wp
        do n = 1, run%model%nnode
          err_s = max(err_s, maxval(abs(s(:, n) - expect)))
          inner = run%model%x(1, n) > 0.0_wp .and. run%model%x(1, n) < 1.5_wp .and. &
            run%model%x(2, n) > 0.0_wp .and. run%model%x(2, n) < 1.0_wp
          if (inner) err_f = max(err_f, maxval(abs(f(:, n))))
        end do
        print '(a)', '        Q' // str(nen) // ' law ' // str(k) // ': sigma_rr = ' // str(expect(1), 8) // &
          ', sigma_zz = ' // str(expect(2), 8) // '; worst |sigma - closed form| / |sigma_zz| ' // &
          str(err_s/abs(expect(2)), 3) // ', inner force / max|f| ' // str(err_f/maxval(abs(f)), 3)
        call check(failure, err_s <= 1.0e-10_wp*abs(expect(2)), 'Q' // str(nen) // ' law ' // str(k) // &
          ': stress off the closed form by ' // str(err_s))
        call check(failure, err_f <= 1.0e-10_wp*maxval(abs(f)), 'Q' // str(nen) // ' law ' // str(k) // &
          ': force at an inner node ' // str(err_f))
        ! translation along the axis alone
        u(1, :) = 0.0_wp
        u(2, :) = shift
        call stress(run, u, s)
        call forces(run, u, f, w)
        call check(failure, maxval(abs(s)) <= 1.0e-12_wp*young .and. maxval(abs(f)) <= 1.0e-12_wp*young .and. &
          abs(w) <= 1.0e-14_wp*young, 'Q' // str(nen) // ' law ' // str(k) // ': a translation along the axis ' // &
          'gives stress ' // str(maxval(abs(s))) // ', force ' // str(maxval(abs(f))) // ', energy ' // str(w))
        deallocate(run, u, f)
        if (allocated(failure)) return
      end do
    end do
  end subroutine test_homogeneous

  !> Forces at u = 1e-7 (Hooke) and at strains of 1e-5 past the yield
  !> strain (j2, yield 0.02, i.e. 3e-6 E): finite against small, both with
  !> full integration for Hooke and the same volumetric treatment for j2
  !> (auto: mean for Q4, full for Q8).
  subroutine test_small_limit(failure)
    type(failure_t), allocatable, intent(out) :: failure
    character(len=*), parameter :: small(3) = [character(len=80) :: &
      'kinematics = ''small''', 'kinematics = ''small''', &
      'kinematics = ''small'', material = ''j2'', yield_stress = 0.02']
    character(len=*), parameter :: finite(3) = [character(len=100) :: &
      'kinematics = ''finite'', material = ''neo_hooke'', volumetric = ''full''', &
      'kinematics = ''finite'', material = ''svk''', &
      'kinematics = ''finite'', material = ''j2'', yield_stress = 0.02']
    real(wp), parameter :: amp(3) = [1.0e-7_wp, 1.0e-7_wp, 2.0e-5_wp]
    character(len=*), parameter :: tags(3) = [character(len=10) :: 'neo-Hooke', 'svk', 'j2']
    type(scene_run_t), allocatable :: rs, rf
    real(wp), allocatable :: u(:,:), fs(:,:), ff(:,:)
    real(wp) :: w, d
    integer :: nen, k
    do nen = 4, 8, 4
      do k = 1, 3
        allocate(rs, rf)
        call prepare(failure, 'small_s_' // str(nen) // '_' // str(k), nen, trim(small(k)), rs)
        call prepare(failure, 'small_f_' // str(nen) // '_' // str(k), nen, trim(finite(k)), rf)
        if (allocated(failure)) return
        call random_u(rs, amp(k), u)
        allocate(fs(2, rs%model%nnode), ff(2, rs%model%nnode))
        call forces(rs, u, fs, w)
        call forces(rf, u, ff, w)
        d = maxval(abs(ff - fs))/maxval(abs(fs))
        print '(a)', '        Q' // str(nen) // ' ' // trim(tags(k)) // ': |f_finite - f_small| / max|f| = ' // &
          str(d, 3)
        call check(failure, d <= 20.0_wp*amp(k), 'Q' // str(nen) // ' case ' // str(k) // &
          ': finite and small-strain forces differ by ' // str(d))
        deallocate(rs, rf, fs, ff)
        if (allocated(failure)) return
      end do
    end do
  end subroutine test_small_limit

  !> Uniaxial Kirchhoff stress tau along z, Hencky elasticity, linear
  !> hardening: the logarithmic strains are eps_z = ln l, eps_r = eps_t =
  !> -nu tau/E - ebar/2 with ebar = (eps_z - sy/E)/(1 + H/E), tau = sy + H
  !> ebar (one return from the virgin state is exact on this proportional
  !> path); sigma_zz = tau/J, J = exp(eps_z + 2 eps_r), sigma_rr = sigma_tt = 0.
  subroutine test_j2_uniaxial(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp), parameter :: sy = 20.0_wp, hh = 700.0_wp, l = 1.2_wp
    type(scene_run_t), allocatable :: run
    real(wp), allocatable :: u(:,:), s(:,:)
    real(wp) :: ez, eb, tau, er, a, j, worst, sz
    integer :: nen, n
    ez = log(l)
    eb = (ez - sy/young)/(1.0_wp + hh/young)
    tau = sy + hh*eb
    er = -nu*tau/young - 0.5_wp*eb
    a = exp(er)
    j = exp(ez + 2.0_wp*er)
    sz = tau/j
    do nen = 4, 8, 4
      allocate(run)
      call prepare(failure, 'j2uni_' // str(nen), nen, 'kinematics = ''finite'', material = ''j2'', ' // &
        'yield_stress = 20.0, hardening = 700.0', run)
      if (allocated(failure)) return
      allocate(u(2, run%model%nnode))
      u(1, :) = (a - 1.0_wp)*run%model%x(1, :)
      u(2, :) = (l - 1.0_wp)*run%model%x(2, :)
      call stress(run, u, s)
      worst = 0.0_wp
      do n = 1, run%model%nnode
        worst = max(worst, maxval(abs(s(:, n) - [0.0_wp, sz, 0.0_wp, 0.0_wp])))
      end do
      print '(a)', '        Q' // str(nen) // ': lateral stretch ' // str(a, 10) // ', sigma_zz = ' // str(sz, 10) // &
        ', worst |sigma - closed form| / sigma_zz ' // str(worst/sz, 3)
      call check(failure, worst <= 1.0e-10_wp*sz, 'Q' // str(nen) // ': j2 uniaxial stress off by ' // str(worst))
      deallocate(run, u)
      if (allocated(failure)) return
    end do
  end subroutine test_j2_uniaxial

  !> Every element's omega^2 estimate of the kernel at rest (the plane
  !> current-length estimate times the hoop factor) is at least its exact
  !> bound lambda_max(K_e, M_e) with the hoop stiffness and the axis dofs
  !> dropped; the estimates of elements touching the axis and away from it
  !> are printed against that bound.
  subroutine test_step(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(scene_run_t), allocatable :: run
    real(wp), allocatable :: w2e(:), w2f(:)
    integer :: nen
    do nen = 4, 8, 4
      allocate(run)
      call prepare(failure, 'step_' // str(nen), nen, 'kinematics = ''finite'', material = ''neo_hooke''', run)
      if (allocated(failure)) return
      associate (blk => run%model%bodies(1)%blocks(1))
        allocate(w2e(blk%nel), w2f(blk%nel))
        call element_eigenvalue_bounds(blk, 1.0e-3_wp, w2e)
        call finite_w2_elements(blk, w2f)
        print '(a)', '        Q' // str(nen) // ': estimate / exact bound from ' // str(minval(w2f/w2e), 4) // &
          ' to ' // str(maxval(w2f/w2e), 4) // ' (element 1, on the axis: ' // str(w2f(1)/w2e(1), 4) // ')'
        call check(failure, all(w2f >= w2e*(1.0_wp - 1.0e-12_wp)), 'Q' // str(nen) // ': an estimate below the ' // &
          'exact bound: ' // str(minval(w2f/w2e)))
      end associate
      deallocate(run, w2e, w2f)
    end do
  end subroutine test_step
end program test_axi_finite
