!> Helpers of the axisymmetric tests: structured (r, z) meshes written as
!> Abaqus .inp files (a rectangle or a spherical shell section), the static
!> solution K u = f of a prepared deck by a dense solve (the closed forms
!> are static), and nodal stresses.
module axi_support
  use raccord_kinds, only: wp, pi
  use raccord_scene_runner, only: scene_run_t
  use raccord_elastic_block, only: element_stiffness, add_nodal_stress
  use raccord_shape, only: shape_quad
  use raccord_quadrature, only: gauss_legendre
  use raccord_mesh, only: ELEM_Q4
  implicit none
  private

  public :: write_mesh_inp, static_solution, nodal_stress, gauss_stresses

  interface
    subroutine dgesv(n, nrhs, a, lda, ipiv, b, ldb, info)
      import :: wp
      integer, intent(in) :: n, nrhs, lda, ldb
      real(wp), intent(inout) :: a(lda, *), b(ldb, *)
      integer, intent(out) :: ipiv(*), info
    end subroutine dgesv
  end interface

contains

  !> Write an nx x ny mesh of Q4 or Q8 (nen 4 or 8) elements of type
  !> `eltype` (e.g. 'CAX4', 'CPE8') to path. shape 'rect': r in [p(1), p(2)],
  !> z in [p(3), p(4)]; 'shell': radius in [p(1), p(2)] from the equator
  !> (z = 0) to the axis (r = 0), r = rho sin(phi), z = rho cos(phi).
  !> Surfaces (and their nodes as sets): 'left' (first r, or inner radius),
  !> 'right', 'bottom' (z = 0, or the equator), 'top' (last z, or the axis);
  !> element set 'body'. Elements and node ids offset by id0 (several
  !> meshes in one file through *INCLUDE are not needed: one body per file).
  subroutine write_mesh_inp(path, shape, nen, nx, ny, p, eltype, elset, prefix, append, id0)
    character(len=*), intent(in) :: path, shape, eltype
    integer, intent(in) :: nen, nx, ny
    real(wp), intent(in) :: p(4)
    character(len=*), intent(in), optional :: elset, prefix
    logical, intent(in), optional :: append
    integer, intent(in), optional :: id0
    integer :: u, i, j, step, mx, my, e, c(8), off
    integer, allocatable :: id(:,:)
    real(wp) :: s, t, r, z, rho, phi
    character(len=:), allocatable :: es, pre
    logical :: app
    es = 'body'
    if (present(elset)) es = elset
    pre = ''
    if (present(prefix)) pre = prefix
    app = .false.
    if (present(append)) app = append
    off = 0
    if (present(id0)) off = id0
    step = merge(1, 2, nen == 4)
    mx = step*nx
    my = step*ny
    allocate(id(0:mx, 0:my), source=0)
    if (app) then
      open(newunit=u, file=path, status='old', position='append', action='write')
    else
      open(newunit=u, file=path, status='replace', action='write')
    end if
    write(u, '(a)') '*NODE'
    do j = 0, my
      do i = 0, mx
        if (nen == 8 .and. mod(i, 2) == 1 .and. mod(j, 2) == 1) cycle
        id(i, j) = off + 1 + i + (mx + 1)*j
        s = real(i, wp)/real(mx, wp)
        t = real(j, wp)/real(my, wp)
        if (shape == 'shell') then
          rho = p(1) + (p(2) - p(1))*s
          phi = 0.5_wp*pi*(1.0_wp - t)
          r = rho*sin(phi)
          z = rho*cos(phi)
          if (j == my) r = 0.0_wp
          if (j == 0) z = 0.0_wp
        else
          r = p(1) + (p(2) - p(1))*s
          z = p(3) + (p(4) - p(3))*t
        end if
        write(u, '(i0,2(",",es24.16))') id(i, j), r, z
      end do
    end do
    write(u, '(a)') '*ELEMENT, TYPE=' // eltype // ', ELSET=' // es
    do j = 0, my - step, step
      do i = 0, mx - step, step
        e = off + 1 + i/step + nx*(j/step)
        c(1:4) = [id(i, j), id(i + step, j), id(i + step, j + step), id(i, j + step)]
        if (nen == 8) then
          c(5:8) = [id(i + 1, j), id(i + 2, j + 1), id(i + 1, j + 2), id(i, j + 1)]
          write(u, '(i0,8(",",i0))') e, c
        else
          write(u, '(i0,4(",",i0))') e, c(1:4)
        end if
      end do
    end do
    call side('bottom', 'S1', .true., 0)
    call side('right', 'S2', .false., nx - 1)
    call side('top', 'S3', .true., ny - 1)
    call side('left', 'S4', .false., 0)
    close(u)
  contains
    subroutine side(name, face, along_x, k)
      character(len=*), intent(in) :: name, face
      logical, intent(in) :: along_x
      integer, intent(in) :: k
      integer :: q
      write(u, '(a)') '*ELSET, ELSET=' // pre // name // '_e'
      if (along_x) then
        do q = 0, nx - 1
          write(u, '(i0)') off + 1 + q + nx*k
        end do
      else
        do q = 0, ny - 1
          write(u, '(i0)') off + 1 + k + nx*q
        end do
      end if
      write(u, '(a)') '*SURFACE, NAME=' // pre // name // ', TYPE=ELEMENT'
      write(u, '(a)') pre // name // '_e, ' // face
    end subroutine side
  end subroutine write_mesh_inp

  !> Static solution of a prepared deck: K u = f (surface loads and body
  !> forces at amplitude 1), supports at their value (amplitude 1), by a
  !> dense LU solve. K from element_stiffness (axisymmetric: hoop terms too).
  subroutine static_solution(run, u)
    type(scene_run_t), intent(in) :: run
    real(wp), allocatable, intent(out) :: u(:,:)
    real(wp), allocatable :: k(:,:), f(:)
    real(wp) :: ke(16, 16), val
    integer, allocatable :: ipiv(:), dof(:)
    integer :: n, ib, kb, e, a, b, i, j, nd, info, node, comp
    associate (model => run%model)
      n = 2*model%nnode
      allocate(k(n, n), f(n), source=0.0_wp)
      allocate(ipiv(n))
      do ib = 1, size(model%bodies)
        do kb = 1, size(model%bodies(ib)%blocks)
          associate (blk => model%bodies(ib)%blocks(kb))
            nd = 2*blk%nen
            allocate(dof(nd))
            do e = 1, blk%nel
              call element_stiffness(blk, e, ke(1:nd, 1:nd))
              do a = 1, blk%nen
                dof(2*a - 1) = 2*blk%conn(a, e) - 1
                dof(2*a) = 2*blk%conn(a, e)
              end do
              do b = 1, nd
                do a = 1, nd
                  k(dof(a), dof(b)) = k(dof(a), dof(b)) + ke(a, b)
                end do
              end do
            end do
            deallocate(dof)
          end associate
        end do
      end do
      f = reshape(model%f_body, [n])
      do i = 1, size(model%loads)
        do j = 1, size(model%loads(i)%nodes)
          node = model%loads(i)%nodes(j)
          f(2*node - 1:2*node) = f(2*node - 1:2*node) + model%loads(i)%force(:, j)
        end do
      end do
      ! prescribed dofs by elimination
      do i = 1, model%ncdof
        node = model%cdof_node(i)
        comp = model%cdof_comp(i)
        j = 2*(node - 1) + comp
        val = model%supports(model%cdof_support(i))%value(comp)
        f = f - k(:, j)*val
        k(j, :) = 0.0_wp
        k(:, j) = 0.0_wp
        k(j, j) = 1.0_wp
        f(j) = val
      end do
      ! nodes in no body (none in these meshes) would be singular
      do j = 1, n
        if (k(j, j) == 0.0_wp) k(j, j) = 1.0_wp
      end do
      call dgesv(n, 1, k, n, ipiv, f, n, info)
      if (info /= 0) error stop 'static_solution: singular stiffness'
      u = reshape(f, [2, model%nnode])
    end associate
  end subroutine static_solution

  !> Nodal averages of the stress (rr, zz, rz, tt) of every block.
  subroutine nodal_stress(run, u, s)
    type(scene_run_t), intent(in) :: run
    real(wp), intent(in) :: u(:,:)
    real(wp), allocatable, intent(out) :: s(:,:)
    real(wp), allocatable :: wsum(:)
    integer :: ib, kb, n
    allocate(s(4, run%model%nnode), wsum(run%model%nnode), source=0.0_wp)
    do ib = 1, size(run%model%bodies)
      do kb = 1, size(run%model%bodies(ib)%blocks)
        call add_nodal_stress(run%model%bodies(ib)%blocks(kb), u, s, wsum)
      end do
    end do
    do n = 1, run%model%nnode
      if (wsum(n) > 0.0_wp) s(:, n) = s(:, n)/wsum(n)
    end do
  end subroutine nodal_stress

  !> Stress (rr, zz, rz, tt) and position at every Gauss point of every
  !> element, computed here from u with the shape functions (independent of
  !> the blocks' stress recovery): axisymmetric Hooke with eps_tt = u_r/r.
  !> With centre, Q4 elements are sampled at their centre only, where the
  !> gradient of the bilinear interpolant is second-order accurate (at the
  !> 2x2 points it is first order: the radial strain is constant across
  !> the element).
  subroutine gauss_stresses(run, u, young, nu, xg, sg, centre)
    type(scene_run_t), intent(in) :: run
    real(wp), intent(in) :: u(:,:), young, nu
    logical, intent(in) :: centre
    real(wp), allocatable, intent(out) :: xg(:,:), sg(:,:)
    real(wp) :: gx(3), gw(3), n(8), dn(2, 8), jac(2, 2), jinv(2, 2), dx(2, 8), gu(2, 2), ett, r, lam, mu, tr
    real(wp), allocatable :: xe(:,:), ue(:,:)
    integer :: ib, kb, e, i, j, ng, m, nen
    lam = young*nu/((1.0_wp + nu)*(1.0_wp - 2.0_wp*nu))
    mu = young/(2.0_wp*(1.0_wp + nu))
    allocate(xg(2, 9*run%model%nelem), sg(4, 9*run%model%nelem))
    m = 0
    do ib = 1, size(run%model%bodies)
      do kb = 1, size(run%model%bodies(ib)%blocks)
        associate (blk => run%model%bodies(ib)%blocks(kb))
          nen = blk%nen
          ng = merge(2, 3, blk%etype == ELEM_Q4)
          call gauss_legendre(ng, gx(1:ng), gw(1:ng))
          if (centre .and. blk%etype == ELEM_Q4) then
            ng = 1
            gx(1) = 0.0_wp
          end if
          do e = 1, blk%nel
            xe = run%model%x(:, blk%conn(:, e))
            ue = u(:, blk%conn(:, e))
            do j = 1, ng
              do i = 1, ng
                call shape_quad(blk%etype, gx(i), gx(j), n(1:nen), dn(:, 1:nen))
                jac = matmul(xe, transpose(dn(:, 1:nen)))
                jinv = reshape([jac(2, 2), -jac(2, 1), -jac(1, 2), jac(1, 1)], [2, 2]) / &
                  (jac(1, 1)*jac(2, 2) - jac(1, 2)*jac(2, 1))
                dx(:, 1:nen) = matmul(transpose(jinv), dn(:, 1:nen))
                gu = matmul(ue, transpose(dx(:, 1:nen)))
                r = dot_product(n(1:nen), xe(1, :))
                ett = dot_product(n(1:nen), ue(1, :))/r
                tr = lam*(gu(1, 1) + gu(2, 2) + ett)
                m = m + 1
                xg(:, m) = matmul(xe, n(1:nen))
                sg(:, m) = [tr + 2.0_wp*mu*gu(1, 1), tr + 2.0_wp*mu*gu(2, 2), mu*(gu(1, 2) + gu(2, 1)), &
                  tr + 2.0_wp*mu*ett]
              end do
            end do
          end do
        end associate
      end do
    end do
    xg = xg(:, 1:m)
    sg = sg(:, 1:m)
  end subroutine gauss_stresses
end module axi_support
