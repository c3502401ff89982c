!> J2 plasticity at one point (src/element/raccord_plasticity.f90): the
!> small-strain radial return against the closed forms of confined
!> compression (load, unload, reverse yield) and uniaxial stress, the yield
!> condition after each return, the energy account, and the finite-strain
!> (Hencky, exponential map) return against the small-strain closed form on
!> a coaxial path, its objectivity and its small-strain limit
!> (method brief method-finite-plastic-axi.md 7.1, 7.3, 8).
program test_plasticity
  use raccord_kinds, only: wp, i8
  use raccord_material, only: moduli_t, make_moduli
  use raccord_plasticity, only: j2_t, nhist, h_ebar, j2_initial_history, j2_return_small, j2_return_hencky
  use raccord_check, only: failure_t, new_test, run_tests, check, check_close
  use raccord_finite_kernel, only: fin_chunk_len
  use raccord_plastic_kernel, only: kernel_j2_small_q4
  implicit none

  real(wp), parameter :: young = 210000.0_wp, nu = 0.3_wp, sy0 = 240.0_wp, hmod = 2000.0_wp
  real(wp), parameter :: r23 = sqrt(2.0_wp/3.0_wp)

  call run_tests('plasticity', [ &
    new_test('confined compression: load, unload, reverse yield (closed form)', test_confined), &
    new_test('confined compression, perfectly plastic and no reverse yield', test_confined_residual), &
    new_test('uniaxial stress: load, unload, reload (closed form)', test_uniaxial), &
    new_test('energy: elastic + plastic work equals the work of the stresses', test_energy), &
    new_test('Hencky return on a coaxial path equals the small-strain closed form in ln l', test_hencky_coaxial), &
    new_test('Hencky return is objective', test_hencky_rotation), &
    new_test('Hencky return tends to the small-strain return', test_hencky_small_limit), &
    new_test('the elastic trial of a virgin chunk equals the return bit for bit', test_virgin_chunk)])

contains

  !> Closed form of confined compression (eps_yy = eps < 0, others 0),
  !> linear isotropic hardening, path 0 -> eps_max -> eps (method brief 7.3):
  !> sigma_yy, sigma_xx and ebar.
  subroutine confined_closed(m, eps_max, eps, unloading, syy, sxx, ebar)
    type(moduli_t), intent(in) :: m
    real(wp), intent(in) :: eps_max, eps
    logical, intent(in) :: unloading
    real(wp), intent(out) :: syy, sxx, ebar
    real(wp) :: d, q, qmax, ebmax, eps_r, g
    g = m%g
    if (.not. unloading) then
      ! loading in compression: d = sigma_yy - sigma_xx = 2G eps until -sigma_y0
      if (2.0_wp*g*abs(eps) <= sy0) then
        d = 2.0_wp*g*eps
        ebar = 0.0_wp
      else
        ebar = (2.0_wp*g*abs(eps) - sy0)/(3.0_wp*g + hmod)
        q = sy0 + hmod*ebar
        d = -q
      end if
    else
      ebmax = max(0.0_wp, (2.0_wp*g*abs(eps_max) - sy0)/(3.0_wp*g + hmod))
      qmax = sy0 + hmod*ebmax
      eps_r = eps_max + qmax/g
      if (eps <= eps_r) then
        d = -qmax + 2.0_wp*g*(eps - eps_max)
        ebar = ebmax
      else
        d = qmax + (2.0_wp*g*hmod/(3.0_wp*g + hmod))*(eps - eps_r)
        ebar = ebmax + (2.0_wp*g/(3.0_wp*g + hmod))*(eps - eps_r)
      end if
    end if
    syy = m%k*eps + 2.0_wp*d/3.0_wp
    sxx = m%k*eps - d/3.0_wp
  end subroutine confined_closed

  !> |s| - sqrt(2/3) sigma_y(ebar) of a stress (xx, yy, xy, zz): 0 on the surface.
  pure real(wp) function yield_fn(sig, ebar, h) result(f)
    real(wp), intent(in) :: sig(4), ebar, h
    real(wp) :: p
    p = (sig(1) + sig(2) + sig(4))/3.0_wp
    f = sqrt((sig(1) - p)**2 + (sig(2) - p)**2 + (sig(4) - p)**2 + 2.0_wp*sig(3)**2) - r23*(sy0 + h*ebar)
  end function yield_fn

  subroutine test_confined(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(moduli_t) :: m
    type(j2_t) :: j2
    real(wp) :: h(nhist), hn(nhist), sig(4), we, dwp, eps, syy, sxx, eb
    real(wp), parameter :: eps_max = -0.01_wp
    integer, parameter :: n = 200
    integer :: k
    m = make_moduli(young, nu)
    j2 = j2_t(sy0, hmod)
    h = j2_initial_history(.false.)
    do k = 1, n
      eps = eps_max*real(k, wp)/real(n, wp)
      call j2_return_small(m, j2, [0.0_wp, eps, 0.0_wp, 0.0_wp], h, hn, sig, we, dwp)
      h = hn
      call confined_closed(m, eps_max, eps, .false., syy, sxx, eb)
      call check_close(failure, sig(2), syy, 'loading sigma_yy at eps ' // fmt(eps), rel_tol=1.0e-10_wp)
      call check_close(failure, sig(1), sxx, 'loading sigma_xx at eps ' // fmt(eps), rel_tol=1.0e-10_wp)
      call check_close(failure, sig(4), sxx, 'loading sigma_zz at eps ' // fmt(eps), rel_tol=1.0e-10_wp)
      call check_close(failure, h(h_ebar), eb, 'loading ebar at eps ' // fmt(eps), abs_tol=1.0e-13_wp)
      call check(failure, dwp >= 0.0_wp, 'plastic work of a step is >= 0')
      if (h(h_ebar) > 0.0_wp) call check_close(failure, yield_fn(sig, h(h_ebar), hmod), 0.0_wp, &
        'on the yield surface after a plastic return', abs_tol=1.0e-9_wp)
      if (allocated(failure)) return
    end do
    ! the brief's numbers (independent script), to its 7 digits
    call check_close(failure, sig(2), -1917.506_wp, 'sigma_yy at -0.01 (brief 7.3)', rel_tol=1.0e-6_wp)
    call check_close(failure, h(h_ebar), 5.629723e-3_wp, 'ebar at -0.01 (brief 7.3)', rel_tol=1.0e-6_wp)
    do k = n - 1, 0, -1
      eps = eps_max*real(k, wp)/real(n, wp)
      call j2_return_small(m, j2, [0.0_wp, eps, 0.0_wp, 0.0_wp], h, hn, sig, we, dwp)
      h = hn
      call confined_closed(m, eps_max, eps, .true., syy, sxx, eb)
      call check_close(failure, sig(2), syy, 'unloading sigma_yy at eps ' // fmt(eps), abs_tol=1.0e-10_wp*sy0)
      call check_close(failure, sig(1), sxx, 'unloading sigma_xx at eps ' // fmt(eps), abs_tol=1.0e-10_wp*sy0)
      call check_close(failure, h(h_ebar), eb, 'unloading ebar at eps ' // fmt(eps), abs_tol=1.0e-13_wp)
      if (allocated(failure)) return
    end do
    call check_close(failure, sig(2), 173.5799_wp, 'residual sigma_yy after reverse yield (brief 7.3)', &
      rel_tol=1.0e-6_wp)
    call check_close(failure, h(h_ebar), 1.018490e-2_wp, 'ebar after the cycle (brief 7.3)', rel_tol=1.0e-6_wp)
  end subroutine test_confined

  !> Perfectly plastic (H = 0) load beyond yield, unload without reverse
  !> yield: residual sigma_yy = 2G ebar, sigma_xx = -G ebar; and the
  !> hardening case's no-reverse-yield residual (brief 7.3).
  subroutine test_confined_residual(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(moduli_t) :: m
    type(j2_t) :: j2
    real(wp) :: h(nhist), hn(nhist), sig(4), we, dwp, eps
    integer :: k
    m = make_moduli(young, nu)
    j2 = j2_t(sy0, 0.0_wp)
    h = j2_initial_history(.false.)
    do k = 1, 50
      eps = -0.0025_wp*real(k, wp)/50.0_wp
      call j2_return_small(m, j2, [0.0_wp, eps, 0.0_wp, 0.0_wp], h, hn, sig, we, dwp)
      h = hn
      if (h(h_ebar) > 0.0_wp) call check_close(failure, yield_fn(sig, h(h_ebar), 0.0_wp), 0.0_wp, &
        'perfectly plastic: on the yield surface', abs_tol=1.0e-9_wp)
    end do
    ! H = 0: sigma_yy - sigma_xx = -sigma_y0 while flowing; sigma_yy slope K
    call check_close(failure, sig(2) - sig(1), -sy0, 'perfectly plastic: sigma_yy - sigma_xx', rel_tol=1.0e-12_wp)
    call check_close(failure, h(h_ebar), (2.0_wp*m%g*0.0025_wp - sy0)/(3.0_wp*m%g), 'perfectly plastic ebar', &
      rel_tol=1.0e-12_wp)
    call j2_return_small(m, j2, [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp], h, hn, sig, we, dwp)
    call check_close(failure, sig(2), 2.0_wp*m%g*hn(h_ebar), 'residual sigma_yy = 2G ebar', rel_tol=1.0e-12_wp)
    call check_close(failure, sig(1), -m%g*hn(h_ebar), 'residual sigma_xx = -G ebar', rel_tol=1.0e-12_wp)
    call check_close(failure, dwp, 0.0_wp, 'elastic unloading dissipates nothing', abs_tol=0.0_wp)
    ! with hardening, 0 -> -0.0025 -> 0 stays below reverse yield (brief 7.3)
    j2 = j2_t(sy0, hmod)
    h = j2_initial_history(.false.)
    do k = 1, 50
      call j2_return_small(m, j2, [0.0_wp, -0.0025_wp*real(k, wp)/50.0_wp, 0.0_wp, 0.0_wp], h, hn, sig, we, dwp)
      h = hn
    end do
    call j2_return_small(m, j2, [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp], h, hn, sig, we, dwp)
    call check_close(failure, sig(2), 108.3366_wp, 'residual sigma_yy (brief 7.3)', rel_tol=1.0e-6_wp)
    call check_close(failure, sig(1), -54.1683_wp, 'residual sigma_xx (brief 7.3)', rel_tol=1.0e-6_wp)
  end subroutine test_confined_residual

  !> Uniaxial stress sigma_yy with sigma_xx = sigma_zz = 0 (the lateral
  !> strains solved by Newton on the 4-component return): sigma = sigma_y0 +
  !> H (E eps - sigma_y0)/(E + H) while loading, elastic unloading to zero
  !> stress with the plastic strain left, reload to yield at the old stress.
  subroutine test_uniaxial(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(moduli_t) :: m
    type(j2_t) :: j2
    real(wp) :: h(nhist), hn(nhist), sig(4), lat(2), eps, expect, smax, ep_axial
    integer :: k
    m = make_moduli(young, nu)
    j2 = j2_t(sy0, hmod)
    h = j2_initial_history(.false.)
    lat = 0.0_wp
    do k = 1, 100
      eps = 0.01_wp*real(k, wp)/100.0_wp
      call uniaxial_point(m, j2, eps, h, lat, hn, sig)
      h = hn
      if (young*eps <= sy0) then
        expect = young*eps
      else
        expect = sy0 + hmod*(young*eps - sy0)/(young + hmod)
      end if
      call check_close(failure, sig(2), expect, 'uniaxial sigma at eps ' // fmt(eps), rel_tol=1.0e-10_wp)
      call check_close(failure, sig(1), 0.0_wp, 'uniaxial: sigma_xx = 0', abs_tol=1.0e-10_wp*sy0)
      call check_close(failure, sig(4), 0.0_wp, 'uniaxial: sigma_zz = 0', abs_tol=1.0e-10_wp*sy0)
      if (allocated(failure)) return
    end do
    call check_close(failure, sig(2), 257.547_wp, 'uniaxial sigma at 0.01 (brief 7.2)', rel_tol=2.0e-6_wp)
    smax = sig(2)
    ! plastic axial strain = ebar in uniaxial stress; unload to zero stress
    ep_axial = h(2)
    call check_close(failure, h(h_ebar), ep_axial, 'uniaxial: ebar = axial plastic strain', rel_tol=1.0e-10_wp)
    call uniaxial_point(m, j2, ep_axial, h, lat, hn, sig)
    call check_close(failure, sig(2), 0.0_wp, 'unloaded to the plastic strain: zero stress', abs_tol=1.0e-9_wp*sy0)
    call check_close(failure, hn(h_ebar), h(h_ebar), 'unloading keeps ebar', abs_tol=0.0_wp)
    ! reload just below the old strain: elastic, below the old peak
    call uniaxial_point(m, j2, 0.01_wp - 1.0e-5_wp, h, lat, hn, sig)
    call check_close(failure, sig(2), smax - young*1.0e-5_wp, 'reloading is elastic up to the old peak', &
      rel_tol=1.0e-10_wp)
    call check_close(failure, hn(h_ebar), h(h_ebar), 'reloading below the peak keeps ebar', abs_tol=0.0_wp)
  end subroutine test_uniaxial

  !> One uniaxial-stress return at axial strain eps: Newton (finite-difference
  !> Jacobian) on the lateral strains (xx, zz) until sigma_xx = sigma_zz = 0.
  subroutine uniaxial_point(m, j2, eps, h, lat, hn, sig)
    type(moduli_t), intent(in) :: m
    type(j2_t), intent(in) :: j2
    real(wp), intent(in) :: eps, h(nhist)
    real(wp), intent(inout) :: lat(2)
    real(wp), intent(out) :: hn(nhist), sig(4)
    real(wp) :: r(2), r1(2), jac(2, 2), dl(2), det, we, dwp, s1(4), dh
    integer :: it, c
    dh = 1.0e-7_wp
    do it = 1, 50
      call j2_return_small(m, j2, [lat(1), eps, 0.0_wp, lat(2)], h, hn, sig, we, dwp)
      r = [sig(1), sig(4)]
      if (maxval(abs(r)) < 1.0e-12_wp*sy0) exit
      do c = 1, 2
        dl = lat
        dl(c) = dl(c) + dh
        call j2_return_small(m, j2, [dl(1), eps, 0.0_wp, dl(2)], h, hn, s1, we, dwp)
        r1 = [s1(1), s1(4)]
        jac(:, c) = (r1 - r)/dh
      end do
      det = jac(1, 1)*jac(2, 2) - jac(1, 2)*jac(2, 1)
      dl(1) = (jac(2, 2)*r(1) - jac(1, 2)*r(2))/det
      dl(2) = (jac(1, 1)*r(2) - jac(2, 1)*r(1))/det
      lat = lat - dl
    end do
    call j2_return_small(m, j2, [lat(1), eps, 0.0_wp, lat(2)], h, hn, sig, we, dwp)
  end subroutine uniaxial_point

  !> Confined cycle 0 -> -0.01 -> 0 in fine steps: the trapezoidal work of
  !> the stresses equals W_e + W_p (method brief 6: 2.6879 per unit volume),
  !> and W_p grows monotonically.
  subroutine test_energy(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(moduli_t) :: m
    type(j2_t) :: j2
    real(wp) :: h(nhist), hn(nhist), sig(4), sold, we, dwp, wtrap, wp_sum, eps, eold
    integer, parameter :: n = 2000
    integer :: k
    m = make_moduli(young, nu)
    j2 = j2_t(sy0, hmod)
    h = j2_initial_history(.false.)
    wtrap = 0.0_wp
    wp_sum = 0.0_wp
    sold = 0.0_wp
    eold = 0.0_wp
    do k = 1, 2*n
      if (k <= n) then
        eps = -0.01_wp*real(k, wp)/real(n, wp)
      else
        eps = -0.01_wp*real(2*n - k, wp)/real(n, wp)
      end if
      call j2_return_small(m, j2, [0.0_wp, eps, 0.0_wp, 0.0_wp], h, hn, sig, we, dwp)
      h = hn
      wtrap = wtrap + 0.5_wp*(sold + sig(2))*(eps - eold)
      sold = sig(2)
      eold = eps
      call check(failure, dwp >= 0.0_wp, 'dW_p >= 0')
      wp_sum = wp_sum + dwp
    end do
    call check_close(failure, we + wp_sum, wtrap, 'W_e + W_p = work of the stresses', rel_tol=1.0e-5_wp)
    call check_close(failure, wtrap, 2.6879_wp, 'work of the cycle (brief 6)', rel_tol=1.0e-4_wp)
  end subroutine test_energy

  !> F = diag(1, l), l: 1 -> 0.5 -> 1: the Kirchhoff stress equals the
  !> small-strain closed form at eps = ln l (brief 8), and sigma_yy = tau/l.
  subroutine test_hencky_coaxial(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(moduli_t) :: m
    type(j2_t) :: j2
    real(wp) :: h(nhist), hn(nhist), tau(4), we, dwp, l, syy, sxx, eb, eps
    integer, parameter :: n = 200
    integer :: k
    m = make_moduli(young, nu)
    j2 = j2_t(sy0, hmod)
    h = j2_initial_history(.true.)
    do k = 1, 2*n
      if (k <= n) then
        l = 1.0_wp - 0.5_wp*real(k, wp)/real(n, wp)
      else
        l = 0.5_wp + 0.5_wp*real(k - n, wp)/real(n, wp)
      end if
      eps = log(l)
      call j2_return_hencky(m, j2, [1.0_wp, 0.0_wp, 0.0_wp, l], h, hn, tau, we, dwp)
      h = hn
      call confined_closed(m, log(0.5_wp), eps, k > n, syy, sxx, eb)
      call check_close(failure, tau(2), syy, 'tau_yy at l = ' // fmt(l), abs_tol=1.0e-9_wp*abs(syy) + 1.0e-9_wp*sy0)
      call check_close(failure, tau(1), sxx, 'tau_xx at l = ' // fmt(l), abs_tol=1.0e-9_wp*abs(sxx) + 1.0e-9_wp*sy0)
      call check_close(failure, h(h_ebar), eb, 'ebar at l = ' // fmt(l), abs_tol=1.0e-12_wp)
      call check(failure, dwp >= 0.0_wp, 'finite: dW_p >= 0')
      if (allocated(failure)) return
      if (k == n) call check_close(failure, tau(2), -122070.534_wp, 'tau_yy at l = 0.5 (brief 8)', rel_tol=1.0e-8_wp)
    end do
    call check_close(failure, tau(2), 1368.2606_wp, 'tau_yy back at l = 1 (brief 8)', rel_tol=1.0e-7_wp)
    ! coaxial: Cp^-1 stays diagonal
    call check_close(failure, h(3), 0.0_wp, 'Cp^-1_xy = 0 on a coaxial path', abs_tol=1.0e-14_wp)
  end subroutine test_hencky_coaxial

  !> A non-proportional plastic path F(t), and the same path rotated,
  !> Q F(t): the Kirchhoff stresses satisfy tau(QF) = Q tau(F) Q^T and the
  !> internal variables (reference quantities) are the same.
  subroutine test_hencky_rotation(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(moduli_t) :: m
    type(j2_t) :: j2
    real(wp) :: h(nhist), hn(nhist), hq(nhist), hqn(nhist), tau(4), tq(4), we, dwp, f(2, 2), q(2, 2), fq(2, 2)
    real(wp) :: t(2, 2), rt(2, 2), s, a
    integer :: k
    m = make_moduli(young, nu)
    j2 = j2_t(sy0, hmod)
    h = j2_initial_history(.true.)
    hq = h
    do k = 1, 100
      s = real(k, wp)/100.0_wp
      f = reshape([1.0_wp + 0.05_wp*s, 0.02_wp*s**2, 0.3_wp*s, 1.0_wp - 0.2_wp*s], [2, 2])
      a = 1.3_wp*s
      q = reshape([cos(a), sin(a), -sin(a), cos(a)], [2, 2])
      fq = matmul(q, f)
      call j2_return_hencky(m, j2, reshape(f, [4]), h, hn, tau, we, dwp)
      call j2_return_hencky(m, j2, reshape(fq, [4]), hq, hqn, tq, we, dwp)
      h = hn
      hq = hqn
    end do
    t = reshape([tau(1), tau(3), tau(3), tau(2)], [2, 2])
    rt = matmul(q, matmul(t, transpose(q)))
    call check(failure, h(h_ebar) > 0.01_wp, 'the path is well into plastic flow')
    call check_close(failure, tq(1), rt(1, 1), 'rotated tau_xx', abs_tol=1.0e-9_wp*maxval(abs(tau)))
    call check_close(failure, tq(2), rt(2, 2), 'rotated tau_yy', abs_tol=1.0e-9_wp*maxval(abs(tau)))
    call check_close(failure, tq(3), rt(1, 2), 'rotated tau_xy', abs_tol=1.0e-9_wp*maxval(abs(tau)))
    call check_close(failure, tq(4), tau(4), 'rotated tau_zz', abs_tol=1.0e-9_wp*maxval(abs(tau)))
    call check_close(failure, hq(h_ebar), h(h_ebar), 'ebar independent of the rotation', rel_tol=1.0e-10_wp)
  end subroutine test_hencky_rotation

  !> A small non-symmetric displacement gradient of size d: the Hencky
  !> return differs from the small-strain return by O(d) relative.
  subroutine test_hencky_small_limit(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(moduli_t) :: m
    type(j2_t) :: j2
    real(wp) :: d, gu(4), h(nhist), hs(nhist), hn(nhist), tau(4), sig(4), we, dwp, diff(2)
    integer :: k, j
    m = make_moduli(young, nu)
    do j = 1, 2
      d = 1.0e-2_wp/10.0_wp**(j - 1)
      ! the yield stress scales with the gradient, so both paths flow alike
      j2 = j2_t(sy0*d/1.0e-2_wp, hmod)
      h = j2_initial_history(.true.)
      hs = j2_initial_history(.false.)
      do k = 1, 20
        gu = d*real(k, wp)/20.0_wp*[-1.0_wp, 0.3_wp, 0.5_wp, 0.4_wp]
        call j2_return_hencky(m, j2, [1.0_wp + gu(1), gu(2), gu(3), 1.0_wp + gu(4)], h, hn, tau, we, dwp)
        h = hn
        call j2_return_small(m, j2, [gu(1), gu(4), 0.5_wp*(gu(2) + gu(3)), 0.0_wp], hs, hn, sig, we, dwp)
        hs = hn
      end do
      call check(failure, hs(h_ebar) > 0.0_wp, 'the small path yields')
      diff(j) = maxval(abs(tau - sig))/maxval(abs(sig))
    end do
    ! O(d): ten times smaller gradient, about ten times closer
    call check(failure, diff(1) < 3.0e-2_wp, 'finite vs small at 1e-2: ' // fmt(diff(1)))
    call check(failure, diff(2) < 0.2_wp*diff(1), 'finite vs small at 1e-3 (' // fmt(diff(2)) // &
      ') ten times closer than at 1e-2 (' // fmt(diff(1)) // ')')
  end subroutine test_hencky_small_limit

  function fmt(x) result(s)
    real(wp), intent(in) :: x
    character(len=:), allocatable :: s
    character(len=24) :: buf
    write(buf, '(es12.5)') x
    s = trim(adjustl(buf))
  end function fmt
  !> The small-strain Q4 kernel on a virgin chunk (internal variables 0)
  !> with virgin = .true. (elastic trial alone when no point yields, the
  !> internal variables untouched) and .false. (the return at every point):
  !> forces, stresses, energies, plastic work and internal variables equal
  !> bit for bit, with B-bar and without, on chunks that stay elastic and
  !> chunks that yield; the flag on exit says whether the chunk is still 0.
  subroutine test_virgin_chunk(failure)
    type(failure_t), allocatable, intent(out) :: failure
    integer, parameter :: ld = fin_chunk_len
    type(moduli_t) :: m
    type(j2_t) :: j2
    real(wp) :: dn(2, 4, 4), pg(ld, 4, 4), cw(ld, 4), vol0(ld), diag(ld, 4), rinv(ld)
    real(wp) :: ue(ld, 2, 8), fe(ld, 2, 8, 2), sg(ld, 4, 4, 2), act(ld, 2), hist(ld, nhist, 4, 2)
    real(wp) :: en(2), dis(2), jm, w2, amp, cw4(ld, 4, 1)
    integer :: trial, k, jel, nc, nel_yield, nel_trial
    integer(i8) :: seed
    logical :: virgin(2), mean
    m = make_moduli(young, nu)
    j2 = j2_t(sy0, hmod)
    dn = 0.0_wp
    diag = 1.0_wp
    rinv = 1.0_wp
    seed = 12345_i8
    nel_yield = 0
    nel_trial = 0
    do trial = 1, 40
      nc = ld - mod(trial, 5)
      mean = mod(trial, 2) == 0
      ! strains of about amp: around the yield strain sy0/(2G) ~ 1.5e-3
      amp = 4.0e-4_wp*real(1 + mod(trial, 8), wp)
      call fill(pg, 0.0_wp, 1.0_wp, seed)
      call fill(cw4, 0.5_wp, 1.0_wp, seed)
      cw = cw4(:, :, 1)
      vol0 = sum(cw, 2)
      ue = 0.0_wp
      call fill(ue(:, :, 1:4), -0.5_wp*amp, amp, seed)
      do k = 1, 2
        hist(:, :, :, k) = 0.0_wp
        virgin(k) = k == 1
        call kernel_j2_small_q4(nc, m, j2, mean, dn, pg, cw, vol0, diag, rinv, 1.0_wp, .false., &
          hist(:, :, :, k), virgin(k), ue, fe(:, :, :, k), sg(:, :, :, k), act(:, k), en(k), dis(k), jm, jel, w2)
      end do
      if (virgin(1)) then
        nel_trial = nel_trial + 1
      else
        nel_yield = nel_yield + 1
      end if
      call check(failure, all(fe(1:nc, :, 1:4, 1) == fe(1:nc, :, 1:4, 2)), 'virgin chunk: forces bit for bit')
      call check(failure, all(sg(1:nc, :, :, 1) == sg(1:nc, :, :, 2)), 'virgin chunk: stresses bit for bit')
      call check(failure, all(act(1:nc, 1) == act(1:nc, 2)), 'virgin chunk: yielded flags')
      call check(failure, en(1) == en(2) .and. dis(1) == dis(2), 'virgin chunk: energy and plastic work bit for bit')
      call check(failure, all(hist(1:nc, :, :, 1) == hist(1:nc, :, :, 2)), 'virgin chunk: internal variables')
      call check(failure, virgin(1) .eqv. all(hist(1:nc, :, :, 2) == 0.0_wp), &
        'virgin on exit = internal variables still 0')
    end do
    call check(failure, nel_trial > 0 .and. nel_yield > 0, 'both elastic and yielding chunks were tried')
  end subroutine test_virgin_chunk

  !> a = lo + width x reproducible numbers in [0, 1) (linear congruential)
  subroutine fill(a, lo, width, seed)
    real(wp), intent(out) :: a(:,:,:)
    real(wp), intent(in) :: lo, width
    integer(i8), intent(inout) :: seed
    integer :: i, j, k
    do k = 1, size(a, 3)
      do j = 1, size(a, 2)
        do i = 1, size(a, 1)
          seed = mod(1103515245_i8*seed + 12345_i8, 2147483648_i8)
          a(i, j, k) = lo + width*real(seed, wp)/2147483648.0_wp
        end do
      end do
    end do
  end subroutine fill
end program test_plasticity
