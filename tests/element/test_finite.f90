!> Finite-strain elements (src/element/raccord_material.f90,
!> raccord_finite_kernel.f90): closed forms of the laws, forces as the
!> gradient of the stored energy, objectivity, the large-deformation patch
!> test, the small-strain limit, inversion and the stable-step estimate.
program test_finite
  use raccord_kinds, only: wp
  use raccord_error, only: error_t
  use raccord_mesh, only: ELEM_Q4, ELEM_Q8, nodes_per_element
  use raccord_material, only: moduli_t, make_moduli, MAT_NEO_HOOKE, MAT_SVK, VOL_FULL, VOL_MEAN, &
    neo_hooke_tau, svk_tau, cauchy_from_tau, log_strain
  use raccord_elastic_block, only: elastic_block_t, init_elastic_block, make_finite, add_internal_force, &
    block_watch_t, init_watch, watch_energy, watch_w2, watch_inverted, add_nodal_stress, max_eigenvalue_bound
  use raccord_check, only: failure_t, new_test, run_tests, check, check_close
  use raccord_strings, only: str
  use element_test_mesh, only: make_mesh
  implicit none

  real(wp), parameter :: young = 7000.0_wp, nu = 0.3_wp, rho = 1.0e-9_wp
  real(wp), parameter :: pi = acos(-1.0_wp)

  call run_tests('finite', [ &
    new_test('neo-Hooke and SVK closed forms (plane strain)', test_closed_forms), &
    new_test('SVK softens in compression past l = 1/sqrt(3)', test_svk_softening), &
    new_test('forces are the gradient of the stored energy', test_energy_gradient), &
    new_test('rigid rotation: no stress, no energy', test_rigid_rotation), &
    new_test('large-deformation patch test', test_patch_large), &
    new_test('small-strain limit equals Hooke', test_small_limit), &
    new_test('inverted element reported', test_inversion), &
    new_test('stable-step estimate is on the safe side', test_stable_estimate), &
    new_test('logarithmic strain of a rotated stretch', test_log_strain)])

contains

  !> A finite block on the make_mesh mesh.
  subroutine finite_block(etype, material, vol, nx, ny, amp, blk, x, conn, boundary, err)
    integer, intent(in) :: etype, material, vol, nx, ny
    real(wp), intent(in) :: amp
    type(elastic_block_t), intent(out) :: blk
    real(wp), allocatable, intent(out) :: x(:,:)
    integer, allocatable, intent(out) :: conn(:,:)
    logical, allocatable, intent(out) :: boundary(:)
    type(error_t), intent(inout) :: err
    call make_mesh(etype, nx, ny, 2.0_wp, 1.5_wp, amp, x, conn, boundary)
    call init_elastic_block(blk, etype, conn, x, young, nu, .false., 1.0_wp, err)
    if (err%failed()) return
    call make_finite(blk, x, material, vol, rho, err)
  end subroutine finite_block

  !> Forces and stored energy of a block at displacement u.
  subroutine forces(blk, u, f, w, watch)
    type(elastic_block_t), intent(in) :: blk
    real(wp), intent(in) :: u(:,:)
    real(wp), allocatable, intent(out) :: f(:,:)
    real(wp), intent(out) :: w
    type(block_watch_t), intent(out) :: watch
    allocate(f(2, size(u, 2)), source=0.0_wp)
    call init_watch(blk, watch)
    call add_internal_force(blk, u, f, watch=watch, monitor=.true.)
    w = watch_energy(watch)
  end subroutine forces

  !> Cauchy stress (sxx, syy, sxy, szz) of a homogeneous state F, f = (F11, F21, F12, F22).
  function homogeneous_cauchy(material, f) result(s)
    integer, intent(in) :: material
    real(wp), intent(in) :: f(4)
    real(wp) :: s(4), tau(4), tau33, j
    type(moduli_t) :: m
    m = make_moduli(young, nu)
    j = f(1)*f(4) - f(2)*f(3)
    if (material == MAT_SVK) then
      call svk_tau(m, f, tau, tau33)
    else
      call neo_hooke_tau(m, f, j, tau, tau33)
    end if
    s = cauchy_from_tau(j, tau, tau33)
  end function homogeneous_cauchy

  !> Method brief 3.3: confined F = diag(1, l), E 7000, nu 0.3.
  subroutine test_closed_forms(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(moduli_t) :: m
    real(wp) :: l, s(4), expect_yy, expect_xx, a, e_yy, s_yy
    integer :: k
    real(wp), parameter :: ls(4) = [0.5_wp, 0.8_wp, 1.2_wp, 2.0_wp]
    m = make_moduli(young, nu)
    do k = 1, size(ls)
      l = ls(k)
      ! neo-Hooke: sigma_yy = (2G/3) l^(-5/3) (l^2 - 1) + K (l - 1), sigma_xx = sigma_zz = (G/3) l^(-5/3) (1 - l^2) + K (l - 1)
      s = homogeneous_cauchy(MAT_NEO_HOOKE, [1.0_wp, 0.0_wp, 0.0_wp, l])
      expect_yy = 2.0_wp*m%g/3.0_wp*l**(-5.0_wp/3.0_wp)*(l*l - 1.0_wp) + m%k*(l - 1.0_wp)
      expect_xx = m%g/3.0_wp*l**(-5.0_wp/3.0_wp)*(1.0_wp - l*l) + m%k*(l - 1.0_wp)
      call check_close(failure, s(2), expect_yy, 'neo-Hooke confined sigma_yy at l = ' // str(l), rel_tol=1.0e-12_wp)
      call check_close(failure, s(1), expect_xx, 'neo-Hooke confined sigma_xx at l = ' // str(l), rel_tol=1.0e-12_wp)
      call check_close(failure, s(4), expect_xx, 'neo-Hooke confined sigma_zz at l = ' // str(l), rel_tol=1.0e-12_wp)
      call check_close(failure, s(3), 0.0_wp, 'neo-Hooke confined sigma_xy', abs_tol=1.0e-12_wp)
      ! SVK: sigma_yy = (lam + 2 mu) l (l^2 - 1)/2, sigma_xx = sigma_zz = lam (l^2 - 1)/(2 l)
      s = homogeneous_cauchy(MAT_SVK, [1.0_wp, 0.0_wp, 0.0_wp, l])
      call check_close(failure, s(2), (m%lam + 2.0_wp*m%g)*l*(l*l - 1.0_wp)/2.0_wp, &
        'SVK confined sigma_yy at l = ' // str(l), rel_tol=1.0e-12_wp)
      call check_close(failure, s(1), m%lam*(l*l - 1.0_wp)/(2.0_wp*l), 'SVK confined sigma_xx', rel_tol=1.0e-12_wp)
      call check_close(failure, s(4), m%lam*(l*l - 1.0_wp)/(2.0_wp*l), 'SVK confined sigma_zz', rel_tol=1.0e-12_wp)
    end do
    ! the brief's numbers (script output, 6 digits)
    s = homogeneous_cauchy(MAT_NEO_HOOKE, [1.0_wp, 0.0_wp, 0.0_wp, 0.5_wp])
    call check_close(failure, s(2), -7190.44_wp, 'neo-Hooke confined l = 0.5 (brief)', rel_tol=1.0e-6_wp)
    s = homogeneous_cauchy(MAT_NEO_HOOKE, [1.0_wp, 0.0_wp, 0.0_wp, 2.0_wp])
    call check_close(failure, s(2), 7529.38_wp, 'neo-Hooke confined l = 2 (brief)', rel_tol=1.0e-6_wp)
    ! plane-strain uniaxial stress: the brief's lateral stretch gives sigma_xx = 0
    s = homogeneous_cauchy(MAT_NEO_HOOKE, [0.684921_wp, 0.0_wp, 0.0_wp, 2.0_wp])
    call check_close(failure, s(2), 5626.31_wp, 'neo-Hooke uniaxial l = 2 sigma_yy (brief)', rel_tol=1.0e-5_wp)
    call check(failure, abs(s(1)) < 1.0e-5_wp*abs(s(2)), 'neo-Hooke uniaxial l = 2: sigma_xx = ' // str(s(1)))
    ! SVK uniaxial, closed form: E_xx = -(nu/(1-nu)) E_yy, S_yy = E/(1-nu^2) E_yy, sigma_yy = l S_yy / a
    l = 1.5_wp
    e_yy = 0.5_wp*(l*l - 1.0_wp)
    a = sqrt(1.0_wp - 2.0_wp*nu/(1.0_wp - nu)*e_yy)
    s_yy = young/(1.0_wp - nu*nu)*e_yy
    s = homogeneous_cauchy(MAT_SVK, [a, 0.0_wp, 0.0_wp, l])
    call check_close(failure, s(2), l*s_yy/a, 'SVK uniaxial sigma_yy at l = 1.5', rel_tol=1.0e-12_wp)
    call check_close(failure, s(1), 0.0_wp, 'SVK uniaxial sigma_xx at l = 1.5', abs_tol=1.0e-9_wp*s_yy)
  end subroutine test_closed_forms

  !> Method brief 3.4: the SVK nominal stress C l (l^2 - 1)/2 has its
  !> minimum -C/(3 sqrt 3) at l = 1/sqrt 3; neo-Hooke is monotone.
  subroutine test_svk_softening(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(moduli_t) :: m
    real(wp) :: l, p, pmin, lmin, pn, pn_prev, s(4)
    integer :: k
    m = make_moduli(young, nu)
    pmin = huge(1.0_wp)
    lmin = 0.0_wp
    pn_prev = -huge(1.0_wp)
    do k = 1, 700
      l = 0.3_wp + 0.001_wp*real(k, wp)
      s = homogeneous_cauchy(MAT_SVK, [1.0_wp, 0.0_wp, 0.0_wp, l])
      p = s(2)          ! nominal P_yy = J sigma_yy / F_yy = sigma_yy here
      if (p < pmin) then
        pmin = p
        lmin = l
      end if
      s = homogeneous_cauchy(MAT_NEO_HOOKE, [1.0_wp, 0.0_wp, 0.0_wp, l])
      pn = s(2)
      call check(failure, pn > pn_prev, 'neo-Hooke confined stress not monotone at l = ' // str(l))
      pn_prev = pn
    end do
    call check_close(failure, lmin, 1.0_wp/sqrt(3.0_wp), 'SVK softening point', abs_tol=1.0e-3_wp)
    call check_close(failure, pmin, -(m%lam + 2.0_wp*m%g)/(3.0_wp*sqrt(3.0_wp)), 'SVK least nominal stress', &
      rel_tol=1.0e-5_wp)
  end subroutine test_svk_softening

  !> A fixed, large, non-homogeneous displacement on a distorted mesh.
  function big_field(x) result(u)
    real(wp), intent(in) :: x(:,:)
    real(wp) :: u(2, size(x, 2))
    integer :: n
    do n = 1, size(x, 2)
      u(1, n) = 0.25_wp*x(1, n) - 0.15_wp*x(2, n) + 0.08_wp*sin(2.0_wp*x(1, n) + x(2, n))
      u(2, n) = 0.1_wp*x(1, n) - 0.3_wp*x(2, n) + 0.06_wp*cos(1.3_wp*x(2, n) - x(1, n))
    end do
  end function big_field

  !> (F-2): f = dPi/du, checked by central differences of the stored
  !> energy for every kernel (Q4, Q8; full and mean dilatation; both laws).
  subroutine test_energy_gradient(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(elastic_block_t) :: blk
    type(block_watch_t) :: watch
    type(error_t) :: err
    real(wp), allocatable :: x(:,:), u(:,:), f(:,:), fp(:,:), fm(:,:)
    integer, allocatable :: conn(:,:)
    logical, allocatable :: boundary(:)
    integer :: c, n, i, et, mat, vol
    real(wp) :: w, wp_, wm, h, fd, scale, worst
    integer, parameter :: cases(3, 5) = reshape([ELEM_Q4, MAT_NEO_HOOKE, VOL_FULL, ELEM_Q4, MAT_NEO_HOOKE, VOL_MEAN, &
      ELEM_Q8, MAT_NEO_HOOKE, VOL_FULL, ELEM_Q8, MAT_NEO_HOOKE, VOL_MEAN, ELEM_Q4, MAT_SVK, VOL_FULL], [3, 5])
    do c = 1, size(cases, 2)
      et = cases(1, c)
      mat = cases(2, c)
      vol = cases(3, c)
      call finite_block(et, mat, vol, 2, 2, 0.15_wp, blk, x, conn, boundary, err)
      call check(failure, .not. err%failed(), 'set-up: ' // err%message)
      if (allocated(failure)) return
      u = big_field(x)
      call forces(blk, u, f, w, watch)
      scale = maxval(abs(f))
      worst = 0.0_wp
      h = 1.0e-6_wp
      do n = 1, size(x, 2)
        do i = 1, 2
          u(i, n) = u(i, n) + h
          call forces(blk, u, fp, wp_, watch)
          u(i, n) = u(i, n) - 2.0_wp*h
          call forces(blk, u, fm, wm, watch)
          u(i, n) = u(i, n) + h
          fd = (wp_ - wm)/(2.0_wp*h)
          worst = max(worst, abs(fd - f(i, n)))
        end do
      end do
      call check(failure, worst < 1.0e-6_wp*scale, 'case ' // str(c) // ': |f - dW/du| = ' // str(worst) // &
        ' against force scale ' // str(scale))
    end do
  end subroutine test_energy_gradient

  !> Objectivity: u = (R - I) X for rotations up to 90 degrees gives no
  !> force and no energy; a deformed state rotated rigidly keeps its energy
  !> and its forces rotate with it.
  subroutine test_rigid_rotation(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(elastic_block_t) :: blk
    type(block_watch_t) :: watch
    type(error_t) :: err
    real(wp), allocatable :: x(:,:), u(:,:), f(:,:), u0(:,:), f0(:,:), ur(:,:)
    integer, allocatable :: conn(:,:)
    logical, allocatable :: boundary(:)
    real(wp) :: th, r(2, 2), w, w0, fscale
    integer :: k, c, et, mat, vol
    integer, parameter :: cases(3, 4) = reshape([ELEM_Q4, MAT_NEO_HOOKE, VOL_MEAN, ELEM_Q8, MAT_NEO_HOOKE, VOL_FULL, &
      ELEM_Q4, MAT_SVK, VOL_FULL, ELEM_Q8, MAT_SVK, VOL_FULL], [3, 4])
    do c = 1, size(cases, 2)
      et = cases(1, c)
      mat = cases(2, c)
      vol = cases(3, c)
      call finite_block(et, mat, vol, 3, 2, 0.2_wp, blk, x, conn, boundary, err)
      call check(failure, .not. err%failed(), 'set-up')
      if (allocated(failure)) return
      fscale = young*2.0_wp       ! stress x length
      do k = 1, 6
        th = 0.5_wp*pi*real(k, wp)/6.0_wp
        r = reshape([cos(th), sin(th), -sin(th), cos(th)], [2, 2])
        u = matmul(r, x) - x
        call forces(blk, u, f, w, watch)
        call check(failure, maxval(abs(f)) < 1.0e-12_wp*fscale, 'case ' // str(c) // ': rotation ' // &
          str(th*180.0_wp/pi) // ' deg gives force ' // str(maxval(abs(f))))
        call check(failure, abs(w) < 1.0e-12_wp*young*3.0_wp, 'case ' // str(c) // ': rotation gives energy ' // str(w))
      end do
      ! a deformed state, then rotated by 90 degrees
      u0 = 0.3_wp*big_field(x)
      call forces(blk, u0, f0, w0, watch)
      r = reshape([0.0_wp, 1.0_wp, -1.0_wp, 0.0_wp], [2, 2])
      ur = matmul(r, x + u0) - x
      call forces(blk, ur, f, w, watch)
      call check_close(failure, w, w0, 'case ' // str(c) // ': energy of the rotated state', rel_tol=1.0e-12_wp)
      call check(failure, maxval(abs(f - matmul(r, f0))) < 1.0e-10_wp*maxval(abs(f0)), &
        'case ' // str(c) // ': forces do not rotate with the body')
    end do
  end subroutine test_rigid_rotation

  !> u = (F - I) X with a large F on a distorted mesh: the interior nodes
  !> carry no force and every nodal stress is the homogeneous Cauchy stress.
  subroutine test_patch_large(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(elastic_block_t) :: blk
    type(block_watch_t) :: watch
    type(error_t) :: err
    real(wp), allocatable :: x(:,:), u(:,:), f(:,:), s(:,:), wsum(:)
    integer, allocatable :: conn(:,:)
    logical, allocatable :: boundary(:)
    real(wp) :: fm(2, 2), w, expect(4), fl(4), worst
    integer :: c, n, et, mat, vol
    integer, parameter :: cases(3, 5) = reshape([ELEM_Q4, MAT_NEO_HOOKE, VOL_FULL, ELEM_Q4, MAT_NEO_HOOKE, VOL_MEAN, &
      ELEM_Q8, MAT_NEO_HOOKE, VOL_FULL, ELEM_Q4, MAT_SVK, VOL_FULL, ELEM_Q8, MAT_SVK, VOL_FULL], [3, 5])
    fm = reshape([1.6_wp, -0.3_wp, 0.4_wp, 0.7_wp], [2, 2])
    fl = [fm(1, 1), fm(2, 1), fm(1, 2), fm(2, 2)]
    do c = 1, size(cases, 2)
      et = cases(1, c)
      mat = cases(2, c)
      vol = cases(3, c)
      call finite_block(et, mat, vol, 4, 3, 0.2_wp, blk, x, conn, boundary, err)
      call check(failure, .not. err%failed(), 'set-up')
      if (allocated(failure)) return
      u = matmul(fm, x) - x
      call forces(blk, u, f, w, watch)
      worst = 0.0_wp
      do n = 1, size(x, 2)
        if (.not. boundary(n)) worst = max(worst, maxval(abs(f(:, n))))
      end do
      call check(failure, worst < 1.0e-10_wp*maxval(abs(f)), 'case ' // str(c) // ': interior force ' // str(worst))
      allocate(s(4, size(x, 2)), wsum(size(x, 2)), source=0.0_wp)
      call add_nodal_stress(blk, u, s, wsum)
      expect = homogeneous_cauchy(mat, fl)
      do n = 1, size(x, 2)
        s(:, n) = s(:, n)/wsum(n)
      end do
      call check(failure, maxval(abs(s - spread(expect, 2, size(x, 2)))) < 1.0e-10_wp*maxval(abs(expect)), &
        'case ' // str(c) // ': nodal Cauchy stress differs from the homogeneous one by ' // &
        str(maxval(abs(s - spread(expect, 2, size(x, 2))))))
      deallocate(s, wsum)
    end do
  end subroutine test_patch_large

  !> At small displacement the finite kernel gives Hooke's force to the
  !> order of the strain: the difference scales with the load.
  subroutine test_small_limit(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(elastic_block_t) :: blk, lin
    type(block_watch_t) :: watch
    type(error_t) :: err
    real(wp), allocatable :: x(:,:), u(:,:), f(:,:), fl(:,:)
    integer, allocatable :: conn(:,:)
    logical, allocatable :: boundary(:)
    real(wp) :: w, eps, d(3)
    integer :: k, et, c
    do c = 1, 2
      et = merge(ELEM_Q4, ELEM_Q8, c == 1)
      call finite_block(et, MAT_NEO_HOOKE, VOL_FULL, 3, 2, 0.2_wp, blk, x, conn, boundary, err)
      call init_elastic_block(lin, et, conn, x, young, nu, .false., 1.0_wp, err)
      call check(failure, .not. err%failed(), 'set-up')
      if (allocated(failure)) return
      do k = 1, 3
        eps = 10.0_wp**(-2 - k)
        u = eps*big_field(x)
        call forces(blk, u, f, w, watch)
        allocate(fl(2, size(x, 2)), source=0.0_wp)
        call add_internal_force(lin, u, fl)
        d(k) = maxval(abs(f - fl))/maxval(abs(fl))
        deallocate(fl)
      end do
      call check(failure, d(1) < 0.05_wp, str(et) // ': relative difference at strain 1e-3 is ' // str(d(1)))
      call check(failure, d(2) < 0.2_wp*d(1) .and. d(3) < 0.2_wp*d(2), 'difference does not fall with the load: ' // &
        str(d(1)) // ', ' // str(d(2)) // ', ' // str(d(3)))
    end do
  end subroutine test_small_limit

  !> An element turned inside out is reported with its index.
  subroutine test_inversion(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(elastic_block_t) :: blk
    type(block_watch_t) :: watch
    type(error_t) :: err
    real(wp), allocatable :: x(:,:), u(:,:), f(:,:)
    integer, allocatable :: conn(:,:)
    logical, allocatable :: boundary(:)
    real(wp) :: w, jmin
    integer :: e
    call finite_block(ELEM_Q4, MAT_NEO_HOOKE, VOL_MEAN, 3, 3, 0.0_wp, blk, x, conn, boundary, err)
    allocate(u(2, size(x, 2)), source=0.0_wp)
    call forces(blk, u, f, w, watch)
    call watch_inverted(watch, e, jmin)
    call check(failure, e == 0 .and. jmin > 0.99_wp, 'undeformed mesh reported inverted')
    ! push the third node of element 5 (the centre element) through its opposite corner
    u(:, conn(3, 5)) = 1.5_wp*(x(:, conn(1, 5)) - x(:, conn(3, 5)))
    call forces(blk, u, f, w, watch)
    call watch_inverted(watch, e, jmin)
    call check(failure, e == 5, 'inverted element reported as ' // str(e) // ', expected 5')
    call check(failure, jmin <= 0.0_wp, 'jmin ' // str(jmin))
  end subroutine test_inversion

  !> At rest, the current-length estimate 4 c^2 / L^2 bounds the exact
  !> element eigenvalue from above (dt on the safe side), within a factor 2.
  subroutine test_stable_estimate(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(elastic_block_t) :: blk
    type(block_watch_t) :: watch
    type(error_t) :: err
    real(wp), allocatable :: x(:,:), u(:,:), f(:,:)
    integer, allocatable :: conn(:,:)
    logical, allocatable :: boundary(:)
    real(wp) :: w, w2e, w2x, ratio
    integer :: c, et
    real(wp) :: amp
    do c = 1, 4
      et = merge(ELEM_Q4, ELEM_Q8, c <= 2)
      amp = merge(0.0_wp, 0.2_wp, mod(c, 2) == 1)
      call finite_block(et, MAT_NEO_HOOKE, VOL_FULL, 3, 3, amp, blk, x, conn, boundary, err)
      allocate(u(2, size(x, 2)), source=0.0_wp)
      call forces(blk, u, f, w, watch)
      w2e = watch_w2(watch)
      w2x = max_eigenvalue_bound(blk, rho)
      ratio = w2e/w2x
      call check(failure, ratio >= 1.0_wp .and. ratio < 2.2_wp, 'case ' // str(c) // &
        ': estimate / exact element omega^2 = ' // str(ratio))
      deallocate(u)
    end do
  end subroutine test_stable_estimate

  !> ln V of F = R diag(a, b): principal values ln a, ln b along R's axes.
  subroutine test_log_strain(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp) :: th, r(2, 2), fm(2, 2), e(4), expect(2, 2), d(2, 2)
    th = 0.4_wp
    r = reshape([cos(th), sin(th), -sin(th), cos(th)], [2, 2])
    d = reshape([1.7_wp, 0.0_wp, 0.0_wp, 0.6_wp], [2, 2])
    ! F = V R0 with V = R d R^T (any rotation R0 on the right)
    fm = matmul(matmul(matmul(r, d), transpose(r)), reshape([cos(1.1_wp), sin(1.1_wp), -sin(1.1_wp), &
      cos(1.1_wp)], [2, 2]))
    e = log_strain([fm(1, 1), fm(2, 1), fm(1, 2), fm(2, 2)])
    expect = matmul(matmul(r, reshape([log(1.7_wp), 0.0_wp, 0.0_wp, log(0.6_wp)], [2, 2])), transpose(r))
    call check_close(failure, e(1), expect(1, 1), 'ln V xx', abs_tol=1.0e-13_wp)
    call check_close(failure, e(2), expect(2, 2), 'ln V yy', abs_tol=1.0e-13_wp)
    call check_close(failure, e(3), expect(1, 2), 'ln V xy', abs_tol=1.0e-13_wp)
  end subroutine test_log_strain
end program test_finite
