!> Elastic block (src/element/raccord_elastic_block.f90): stiffness, masses,
!> body force, patch test, stress recovery, the stable-step bound, errors.
program test_element_block
  use raccord_kinds, only: wp
  use raccord_error, only: error_t, EXIT_INPUT
  use raccord_mesh, only: ELEM_Q4, ELEM_Q8, nodes_per_element
  use raccord_elastic_block, only: elastic_block_t, init_elastic_block, add_internal_force, &
    element_stiffness, add_lumped_mass, add_body_force, max_eigenvalue_bound, add_nodal_stress
  use raccord_check, only: failure_t, new_test, run_tests, check, check_close
  use raccord_strings, only: str
  use element_test_mesh, only: make_mesh
  implicit none

  external :: dsyev
  real(wp), parameter :: young = 2.1e5_wp, nu = 0.3_wp, thick = 0.8_wp, rho = 7.8e-9_wp

  call run_tests('element_block', [ &
    new_test('stiffness symmetric with three rigid modes', test_stiffness_modes), &
    new_test('internal force equals assembled K u', test_force_matches_k), &
    new_test('lumped masses positive, total exact', test_lumped_mass), &
    new_test('HRZ and row-sum values on a rectangle', test_lumped_rectangle), &
    new_test('body force total', test_body_force), &
    new_test('patch test and constant stress', test_patch), &
    new_test('element eigenvalue bound', test_eigen_bound), &
    new_test('inverted element is an input error', test_inverted)])

contains

  !> One distorted element of each type, with a curved Q8 edge.
  subroutine one_element(etype, x, conn)
    integer, intent(in) :: etype
    real(wp), allocatable, intent(out) :: x(:,:)
    integer, allocatable, intent(out) :: conn(:,:)
    integer :: nen, a
    nen = nodes_per_element(etype)
    allocate(x(2, nen), conn(nen, 1))
    x(:, 1:4) = reshape([0.1_wp, -0.2_wp, 2.3_wp, 0.1_wp, 1.9_wp, 1.6_wp, -0.3_wp, 1.1_wp], [2, 4])
    if (nen == 8) then
      x(:, 5) = 0.5_wp*(x(:, 1) + x(:, 2)) + [0.05_wp, -0.12_wp]
      x(:, 6) = 0.5_wp*(x(:, 2) + x(:, 3)) + [0.1_wp, 0.03_wp]
      x(:, 7) = 0.5_wp*(x(:, 3) + x(:, 4)) + [-0.04_wp, 0.08_wp]
      x(:, 8) = 0.5_wp*(x(:, 4) + x(:, 1)) + [0.02_wp, 0.0_wp]
    end if
    conn(:, 1) = [(a, a = 1, nen)]
  end subroutine one_element

  !> Area enclosed by an element's boundary, 1/2 loop integral (x dy - y dx)
  !> along its (possibly quadratic) edges, by Simpson's rule, exact for the
  !> cubic integrand.
  function boundary_area(etype, x, conn) result(area)
    integer, intent(in) :: etype
    real(wp), intent(in) :: x(:,:)
    integer, intent(in) :: conn(:)
    real(wp) :: area, p0(2), p1(2), pm(2), s, xs(2), dxs(2)
    integer :: side, k
    area = 0.0_wp
    do side = 1, 4
      p0 = x(:, conn(side))
      p1 = x(:, conn(mod(side, 4) + 1))
      pm = 0.5_wp*(p0 + p1)
      if (etype == ELEM_Q8) pm = x(:, conn(4 + side))
      do k = -1, 1
        s = real(k, wp)
        xs = 0.5_wp*s*(s - 1.0_wp)*p0 + 0.5_wp*s*(s + 1.0_wp)*p1 + (1.0_wp - s*s)*pm
        dxs = (s - 0.5_wp)*p0 + (s + 0.5_wp)*p1 - 2.0_wp*s*pm
        area = area + merge(4.0_wp, 1.0_wp, k == 0)/3.0_wp*0.5_wp*(xs(1)*dxs(2) - xs(2)*dxs(1))
      end do
    end do
  end function boundary_area

  subroutine test_stiffness_modes(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(elastic_block_t) :: blk
    type(error_t) :: err
    real(wp), allocatable :: x(:,:)
    integer, allocatable :: conn(:,:)
    real(wp) :: ke(16, 16), ev(16), work(200), kmax
    integer :: et, ps, n, info, nzero
    logical :: pstress
    character(len=:), allocatable :: label
    do et = ELEM_Q4, ELEM_Q8
      do ps = 0, 1
        pstress = ps == 1
        label = 'etype ' // str(et) // merge(' plane stress', ' plane strain', pstress)
        call one_element(et, x, conn)
        call init_elastic_block(blk, et, conn, x, young, nu, pstress, thick, err)
        call check(failure, .not. err%failed(), label // ': init failed')
        if (allocated(failure)) return
        n = 2*blk%nen
        call element_stiffness(blk, 1, ke(1:n, 1:n))
        kmax = maxval(abs(ke(1:n, 1:n)))
        call check(failure, maxval(abs(ke(1:n, 1:n) - transpose(ke(1:n, 1:n)))) <= 1.0e-13_wp*kmax, &
          label // ': not symmetric')
        call dsyev('N', 'U', n, ke, 16, ev, work, size(work), info)
        call check(failure, info == 0, label // ': dsyev failed')
        ! rigid modes: |lambda| <= 1e-10 lambda_max; the fourth eigenvalue of a
        ! fully integrated element is a deformation mode, >= 1e-3 lambda_max
        nzero = count(abs(ev(1:n)) <= 1.0e-10_wp*ev(n))
        call check(failure, nzero == 3, label // ': ' // str(nzero) // ' zero eigenvalues, expected 3')
        call check(failure, ev(4) >= 1.0e-3_wp*ev(n), label // ': spurious soft mode ' // str(ev(4)/ev(n)))
        call check(failure, ev(1) >= -1.0e-10_wp*ev(n), label // ': negative eigenvalue')
      end do
    end do
  end subroutine test_stiffness_modes

  subroutine test_force_matches_k(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(elastic_block_t) :: blk
    type(error_t) :: err
    real(wp), allocatable :: x(:,:), u(:,:), f(:,:), fk(:,:)
    integer, allocatable :: conn(:,:)
    logical, allocatable :: bnd(:)
    real(wp) :: ke(16, 16), ue(16)
    integer :: et, e, a, n, nen
    do et = ELEM_Q4, ELEM_Q8
      ! 7 x 6 = 42 elements: one full chunk and a partial one
      call make_mesh(et, 7, 6, 3.0_wp, 2.0_wp, 0.2_wp, x, conn, bnd)
      call init_elastic_block(blk, et, conn, x, young, nu, .false., thick, err)
      call check(failure, .not. err%failed(), 'init failed')
      if (allocated(failure)) return
      nen = blk%nen
      n = 2*nen
      allocate(u(2, size(x, 2)), f(2, size(x, 2)), fk(2, size(x, 2)))
      u(1, :) = 1.0e-3_wp*sin(3.1_wp*x(1, :) + x(2, :))
      u(2, :) = 1.0e-3_wp*cos(x(1, :) - 2.2_wp*x(2, :)**2)
      f = 0.0_wp
      call add_internal_force(blk, u, f)
      fk = 0.0_wp
      do e = 1, blk%nel
        call element_stiffness(blk, e, ke(1:n, 1:n))
        ue(1:n) = reshape(u(:, conn(:, e)), [n])
        ue(1:n) = matmul(ke(1:n, 1:n), ue(1:n))
        do a = 1, nen
          fk(:, conn(a, e)) = fk(:, conn(a, e)) + ue(2*a - 1:2*a)
        end do
      end do
      call check(failure, maxval(abs(f - fk)) <= 1.0e-12_wp*maxval(abs(fk)), 'etype ' // str(et) // &
        ': kernel and K u differ by ' // str(maxval(abs(f - fk))/maxval(abs(fk))))
      deallocate(u, f, fk)
    end do
  end subroutine test_force_matches_k

  subroutine test_lumped_mass(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(elastic_block_t) :: blk
    type(error_t) :: err
    real(wp), allocatable :: x(:,:), m(:)
    integer, allocatable :: conn(:,:)
    logical, allocatable :: bnd(:)
    real(wp) :: area
    integer :: et, e
    do et = ELEM_Q4, ELEM_Q8
      ! single distorted element (curved edges for Q8)
      call one_element(et, x, conn)
      call init_elastic_block(blk, et, conn, x, young, nu, .false., thick, err)
      allocate(m(size(x, 2)))
      m = 0.0_wp
      call add_lumped_mass(blk, rho, m)
      area = boundary_area(et, x, conn(:, 1))
      call check(failure, all(m > 0.0_wp), 'etype ' // str(et) // ': non-positive nodal mass')
      call check_close(failure, sum(m), rho*area*thick, 'etype ' // str(et) // ': element mass', rel_tol=1.0e-13_wp)
      deallocate(m)
      ! distorted mesh
      call make_mesh(et, 5, 4, 3.0_wp, 2.0_wp, 0.2_wp, x, conn, bnd)
      call init_elastic_block(blk, et, conn, x, young, nu, .false., thick, err)
      allocate(m(size(x, 2)))
      m = 0.0_wp
      call add_lumped_mass(blk, rho, m)
      area = 0.0_wp
      do e = 1, size(conn, 2)
        area = area + boundary_area(et, x, conn(:, e))
      end do
      call check(failure, all(m > 0.0_wp), 'etype ' // str(et) // ': non-positive nodal mass on the mesh')
      ! the outer boundary is the 3 x 2 rectangle: area 6
      call check_close(failure, area, 6.0_wp, 'mesh area', rel_tol=1.0e-13_wp)
      call check_close(failure, sum(m), rho*6.0_wp*thick, 'etype ' // str(et) // ': mesh mass', rel_tol=1.0e-13_wp)
      deallocate(m)
    end do
  end subroutine test_lumped_mass

  subroutine test_lumped_rectangle(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(elastic_block_t) :: blk
    type(error_t) :: err
    real(wp) :: x(2, 8), m(8), total
    integer :: conn(8, 1), a
    ! 2 x 1 rectangle; HRZ on a Q8 rectangle gives corners 3/76 and
    ! mid-sides 16/76 of the mass (Hinton, Rock & Zienkiewicz 1976), where
    ! the row sum would give corners -1/12
    x = reshape([0.0_wp, 0.0_wp, 2.0_wp, 0.0_wp, 2.0_wp, 1.0_wp, 0.0_wp, 1.0_wp, &
      1.0_wp, 0.0_wp, 2.0_wp, 0.5_wp, 1.0_wp, 1.0_wp, 0.0_wp, 0.5_wp], [2, 8])
    conn(:, 1) = [(a, a = 1, 8)]
    total = rho*2.0_wp*thick
    call init_elastic_block(blk, ELEM_Q8, conn, x, young, nu, .false., thick, err)
    m = 0.0_wp
    call add_lumped_mass(blk, rho, m)
    do a = 1, 4
      call check_close(failure, m(a), 3.0_wp/76.0_wp*total, 'Q8 corner ' // str(a), rel_tol=1.0e-13_wp)
      call check_close(failure, m(4 + a), 16.0_wp/76.0_wp*total, 'Q8 mid-side ' // str(4 + a), rel_tol=1.0e-13_wp)
    end do
    call init_elastic_block(blk, ELEM_Q4, conn(1:4, :), x(:, 1:4), young, nu, .false., thick, err)
    m = 0.0_wp
    call add_lumped_mass(blk, rho, m(1:4))
    do a = 1, 4
      call check_close(failure, m(a), 0.25_wp*total, 'Q4 corner ' // str(a), rel_tol=1.0e-13_wp)
    end do
  end subroutine test_lumped_rectangle

  subroutine test_body_force(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(elastic_block_t) :: blk
    type(error_t) :: err
    real(wp), allocatable :: x(:,:), f(:,:)
    integer, allocatable :: conn(:,:)
    logical, allocatable :: bnd(:)
    real(wp), parameter :: b(2) = [1.5_wp, -9.81_wp]
    integer :: et
    do et = ELEM_Q4, ELEM_Q8
      call make_mesh(et, 4, 3, 3.0_wp, 2.0_wp, 0.2_wp, x, conn, bnd)
      call init_elastic_block(blk, et, conn, x, young, nu, .true., thick, err)
      allocate(f(2, size(x, 2)))
      f = 0.0_wp
      call add_body_force(blk, b, f)
      call check_close(failure, sum(f(1, :)), b(1)*6.0_wp*thick, 'etype ' // str(et) // ': Fx', rel_tol=1.0e-13_wp)
      call check_close(failure, sum(f(2, :)), b(2)*6.0_wp*thick, 'etype ' // str(et) // ': Fy', rel_tol=1.0e-13_wp)
      deallocate(f)
    end do
  end subroutine test_body_force

  subroutine test_patch(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(elastic_block_t) :: blk
    type(error_t) :: err
    real(wp), allocatable :: x(:,:), u(:,:), f(:,:), s(:,:), w(:)
    integer, allocatable :: conn(:,:)
    logical, allocatable :: bnd(:)
    ! u = u0 + G x with a general (non-symmetric) displacement gradient G
    real(wp), parameter :: g(2, 2) = reshape([1.2e-3_wp, -0.4e-3_wp, 0.7e-3_wp, -0.9e-3_wp], [2, 2])
    real(wp), parameter :: u0(2) = [0.01_wp, -0.02_wp]
    real(wp) :: lam, mu, sig(4), fscale, sscale
    integer :: et, ps, k, i
    logical :: pstress
    character(len=:), allocatable :: label
    do et = ELEM_Q4, ELEM_Q8
      do ps = 0, 1
        pstress = ps == 1
        label = 'etype ' // str(et) // merge(' plane stress', ' plane strain', pstress)
        call make_mesh(et, 5, 4, 3.0_wp, 2.0_wp, 0.25_wp, x, conn, bnd)
        call init_elastic_block(blk, et, conn, x, young, nu, pstress, thick, err)
        call check(failure, .not. err%failed(), label // ': init failed')
        if (allocated(failure)) return
        allocate(u(2, size(x, 2)), f(2, size(x, 2)), s(4, size(x, 2)), w(size(x, 2)))
        do k = 1, size(x, 2)
          u(:, k) = u0 + matmul(g, x(:, k))
        end do
        f = 0.0_wp
        call add_internal_force(blk, u, f)
        ! exact stress of the linear field (Hooke, plane strain or stress)
        mu = young/(2.0_wp*(1.0_wp + nu))
        lam = young*nu/((1.0_wp + nu)*(1.0_wp - 2.0_wp*nu))
        if (pstress) lam = young*nu/(1.0_wp - nu**2)
        sig(1) = lam*(g(1, 1) + g(2, 2)) + 2.0_wp*mu*g(1, 1)
        sig(2) = lam*(g(1, 1) + g(2, 2)) + 2.0_wp*mu*g(2, 2)
        sig(3) = mu*(g(1, 2) + g(2, 1))
        sig(4) = merge(0.0_wp, nu*(sig(1) + sig(2)), pstress)
        ! force scale: boundary nodal forces ~ |sigma| * h * thickness
        fscale = maxval(abs(f(:, pack([(i, i = 1, size(x, 2))], bnd))))
        call check(failure, fscale > 0.0_wp, label // ': no boundary force')
        call check(failure, maxval(abs(f(:, pack([(i, i = 1, size(x, 2))], .not. bnd)))) <= 1.0e-12_wp*fscale, &
          label // ': interior residual ' // str(maxval(abs(f(:, pack([(i, i = 1, size(x, 2))], .not. bnd))))/fscale))
        s = 0.0_wp
        w = 0.0_wp
        call add_nodal_stress(blk, u, s, w)
        call check(failure, all(w > 0.0_wp), label // ': node without stress contribution')
        sscale = maxval(abs(sig))
        do k = 1, size(x, 2)
          do i = 1, 4
            call check_close(failure, s(i, k)/w(k), sig(i), label // ': stress component ' // str(i) // &
              ' at node ' // str(k), abs_tol=1.0e-11_wp*sscale)
          end do
        end do
        deallocate(u, f, s, w)
      end do
    end do
  end subroutine test_patch

  subroutine test_eigen_bound(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(elastic_block_t) :: blk
    type(error_t) :: err
    real(wp), allocatable :: x(:,:), k(:,:), m(:), ev(:), work(:)
    integer, allocatable :: conn(:,:), dof(:)
    logical, allocatable :: bnd(:)
    real(wp) :: ke(16, 16), bound, lmax
    integer :: et, e, n, nd, a, i, j, info
    do et = ELEM_Q4, ELEM_Q8
      call make_mesh(et, 3, 2, 3.0_wp, 2.0_wp, 0.2_wp, x, conn, bnd)
      call init_elastic_block(blk, et, conn, x, young, nu, .false., thick, err)
      nd = 2*size(x, 2)
      n = 2*blk%nen
      allocate(k(nd, nd), m(size(x, 2)), ev(nd), work(4*nd), dof(n))
      k = 0.0_wp
      do e = 1, blk%nel
        call element_stiffness(blk, e, ke(1:n, 1:n))
        do a = 1, blk%nen
          dof(2*a - 1:2*a) = [2*conn(a, e) - 1, 2*conn(a, e)]
        end do
        k(dof, dof) = k(dof, dof) + ke(1:n, 1:n)
      end do
      m = 0.0_wp
      call add_lumped_mass(blk, rho, m)
      ! symmetric scaling M^-1/2 K M^-1/2 of the free (unsupported) mesh
      do j = 1, nd
        do i = 1, nd
          k(i, j) = k(i, j)/sqrt(m((i + 1)/2)*m((j + 1)/2))
        end do
      end do
      call dsyev('N', 'U', nd, k, nd, ev, work, size(work), info)
      call check(failure, info == 0, 'dsyev failed')
      lmax = ev(nd)
      bound = max_eigenvalue_bound(blk, rho)
      call check(failure, bound >= lmax*(1.0_wp - 1.0e-12_wp), 'etype ' // str(et) // ': bound ' // &
        str(bound) // ' below the true omega_max^2 ' // str(lmax))
      call check(failure, bound <= 2.0_wp*lmax, 'etype ' // str(et) // ': bound ' // str(bound) // &
        ' more than twice omega_max^2 ' // str(lmax))
      deallocate(k, m, ev, work, dof)
    end do
  end subroutine test_eigen_bound

  subroutine test_inverted(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(elastic_block_t) :: blk
    type(error_t) :: err
    real(wp), allocatable :: x(:,:)
    integer, allocatable :: conn(:,:)
    logical, allocatable :: bnd(:)
    call make_mesh(ELEM_Q4, 3, 2, 3.0_wp, 2.0_wp, 0.0_wp, x, conn, bnd)
    ! element 5: clockwise node order
    conn(:, 5) = conn([1, 4, 3, 2], 5)
    call init_elastic_block(blk, ELEM_Q4, conn, x, young, nu, .false., thick, err)
    call check(failure, err%code == EXIT_INPUT, 'expected EXIT_INPUT, got ' // str(err%code))
    if (allocated(failure)) return
    call check(failure, index(err%message, 'element 5 ') > 0, 'message does not name element 5: ' // err%message)
    call err%clear()
    call init_elastic_block(blk, ELEM_Q4, conn(:, 1:4), x, young, 0.5_wp, .false., thick, err)
    call check(failure, err%code == EXIT_INPUT, 'nu = 0.5 accepted')
  end subroutine test_inverted
end program test_element_block
