!> Convergence to a known static solution reached by damped explicit
!> dynamics. Manufactured solution on the unit square, clamped all round:
!>   u1 = A sin(pi x) sin(pi y),  u2 = B sin(pi x) sin(pi y),
!> with the body force b = -div sigma(u) (plane strain, Hooke):
!>   b1 = (lam+mu) pi^2 (A ss - B cc) + 2 mu pi^2 A ss
!>   b2 = (lam+mu) pi^2 (B ss - A cc) + 2 mu pi^2 B ss
!> (ss = sin(pi x) sin(pi y), cc = cos(pi x) cos(pi y)), applied as
!> consistent nodal forces. Mass-proportional damping alpha ~ 2 omega_1
!> drives the dynamics to the discrete static solution; the relative L2
!> displacement error must fall at rate 2 for Q4 and 3 for Q8.
program test_convergence
  use raccord_kinds, only: wp, pi
  use raccord_check, only: failure_t, new_test, run_tests, check
  use raccord_error, only: error_t
  use raccord_mesh, only: mesh_t, ELEM_Q4, ELEM_Q8, nodes_per_element
  use raccord_scene, only: scene_t, BC_FIXED
  use raccord_model, only: model_t
  use raccord_model_build, only: build_model
  use raccord_time_step, only: time_plan_t, choose_time_step
  use raccord_state, only: state_t, init_state
  use raccord_shape, only: shape_quad
  use raccord_quadrature, only: gauss_legendre
  use raccord_test_meshes, only: rect_mesh
  use dynamics_support, only: one_body_scene, add_bc, start_march, march_to
  implicit none

  real(wp), parameter :: young = 1.0_wp, nu = 0.3_wp, amp_a = 0.01_wp, amp_b = -0.005_wp
  real(wp), parameter :: lam = young*nu/((1.0_wp + nu)*(1.0_wp - 2.0_wp*nu))
  real(wp), parameter :: mu = young/(2.0_wp*(1.0_wp + nu))

  call run_tests('convergence', [ &
    new_test('Q4 displacement error rate about 2', test_rate_q4), &
    new_test('Q8 displacement error rate about 3', test_rate_q8)])

contains

  pure function exact_u(x) result(u)
    real(wp), intent(in) :: x(2)
    real(wp) :: u(2)
    u = [amp_a, amp_b]*sin(pi*x(1))*sin(pi*x(2))
  end function exact_u

  pure function body_force(x) result(b)
    real(wp), intent(in) :: x(2)
    real(wp) :: b(2), ss, cc
    ss = sin(pi*x(1))*sin(pi*x(2))
    cc = cos(pi*x(1))*cos(pi*x(2))
    b(1) = (lam + mu)*pi**2*(amp_a*ss - amp_b*cc) + 2.0_wp*mu*pi**2*amp_a*ss
    b(2) = (lam + mu)*pi**2*(amp_b*ss - amp_a*cc) + 2.0_wp*mu*pi**2*amp_b*ss
  end function body_force

  !> Consistent nodal forces of the body force (5x5 Gauss), or the relative
  !> L2 error of u_h when `u` is given.
  subroutine integrate(mesh, etype, f, u, err_l2)
    type(mesh_t), intent(in) :: mesh
    integer, intent(in) :: etype
    real(wp), intent(inout), optional :: f(:,:)
    real(wp), intent(in), optional :: u(:,:)
    real(wp), intent(out), optional :: err_l2
    integer, parameter :: ng = 5
    real(wp) :: xg(ng), wg(ng), n(8), dn(2, 8), xe(2, 8), jac(2, 2), xp(2), uh(2), da, num, den
    integer :: e, i, j, a, nen
    nen = nodes_per_element(etype)
    call gauss_legendre(ng, xg, wg)
    num = 0.0_wp
    den = 0.0_wp
    do e = 1, mesh%nelem
      xe(:, 1:nen) = mesh%x(:, mesh%conn(1:nen, e))
      do j = 1, ng
        do i = 1, ng
          call shape_quad(etype, xg(i), xg(j), n(1:nen), dn(:, 1:nen))
          jac = matmul(dn(:, 1:nen), transpose(xe(:, 1:nen)))
          da = (jac(1, 1)*jac(2, 2) - jac(1, 2)*jac(2, 1))*wg(i)*wg(j)
          xp = matmul(xe(:, 1:nen), n(1:nen))
          if (present(f)) then
            do a = 1, nen
              f(:, mesh%conn(a, e)) = f(:, mesh%conn(a, e)) + n(a)*body_force(xp)*da
            end do
          end if
          if (present(u)) then
            uh = matmul(u(:, mesh%conn(1:nen, e)), n(1:nen))
            num = num + sum((uh - exact_u(xp))**2)*da
            den = den + sum(exact_u(xp)**2)*da
          end if
        end do
      end do
    end do
    if (present(err_l2)) err_l2 = sqrt(num/den)
  end subroutine integrate

  !> Damped march to the static solution on an n x n mesh; relative L2 error.
  real(wp) function static_error(etype, n) result(e_l2)
    integer, intent(in) :: etype, n
    type(mesh_t) :: mesh
    type(scene_t) :: scene
    type(model_t) :: model
    type(time_plan_t) :: plan
    type(state_t) :: state
    type(error_t) :: err
    real(wp) :: omega1, t_end
    ! Lowest frequency of the clamped square, shear-wave estimate
    ! c_s pi sqrt(2); damping alpha = 2 omega1 makes it about critical, and
    ! every mode then decays at least like exp(-omega1 t).
    omega1 = sqrt(mu)*pi*sqrt(2.0_wp)
    t_end = 40.0_wp/omega1
    call rect_mesh(mesh, etype, n, n, 1.0_wp, 1.0_wp, distortion=0.3_wp)
    call one_body_scene(scene, young, nu, 1.0_wp, .false., t_end)
    scene%time%damping = 2.0_wp*omega1
    call add_bc(scene, 'left', BC_FIXED, comp=[.true., .true.])
    call add_bc(scene, 'right', BC_FIXED, comp=[.true., .true.])
    call add_bc(scene, 'bottom', BC_FIXED, comp=[.true., .true.])
    call add_bc(scene, 'top', BC_FIXED, comp=[.true., .true.])
    call build_model(scene, mesh, model, err)
    model%f_body = 0.0_wp
    call integrate(mesh, etype, f=model%f_body)
    model%has_body_force = .true.
    call choose_time_step(scene, model, plan, err)
    call init_state(model, plan%dt, plan%nsteps, state)
    state%f_ext = model%f_body
    call start_march(model, state)
    call march_to(model, state, t_end)
    call integrate(mesh, etype, u=state%u, err_l2=e_l2)
  end function static_error

  subroutine rate_case(failure, etype, levels, lo, hi)
    type(failure_t), allocatable, intent(out) :: failure
    integer, intent(in) :: etype, levels(:)
    real(wp), intent(in) :: lo, hi
    real(wp) :: errs(size(levels)), rate
    character(len=200) :: msg
    integer :: k
    do k = 1, size(levels)
      errs(k) = static_error(etype, levels(k))
    end do
    do k = 2, size(levels)
      rate = log(errs(k - 1)/errs(k))/log(real(levels(k), wp)/real(levels(k - 1), wp))
      write(msg, '(a,i0,a,i0,a,es10.3,a,es10.3,a,f6.3)') 'n = ', levels(k - 1), ' -> ', levels(k), &
        ': error ', errs(k - 1), ' -> ', errs(k), ', rate ', rate
      write(*, '(a)') '        ' // trim(msg)
      ! The last pair is in the asymptotic range: assert its rate.
      if (k == size(levels)) call check(failure, rate > lo .and. rate < hi, 'rate out of range: ' // trim(msg))
    end do
  end subroutine rate_case

  subroutine test_rate_q4(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call rate_case(failure, ELEM_Q4, [4, 8, 16, 32], 1.85_wp, 2.3_wp)
  end subroutine test_rate_q4

  subroutine test_rate_q8(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call rate_case(failure, ELEM_Q8, [2, 4, 8, 16], 2.7_wp, 3.5_wp)
  end subroutine test_rate_q8
end program test_convergence
