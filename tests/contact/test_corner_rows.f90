!> Corner multipliers on curved Q8 edges (edge_multipliers = 'corners';
!> issue #16 item 3; doc/theory-contact-mortar.md section 2, "Per-entry
!> directions"): a corner row's nodal forces must be the gradient of its
!> weighted gap g_j(x) = int psi_j (x_m - x_s) . nu dGamma, so that the
!> frictionless force does no work on the sliding (doc/theory-contact.md
!> section 7). On two non-matching Q8 traces of one arc (mean gap below
!> 1e-6) the gradient is taken by central differences of the weighted gap the mortar build
!> returns with the geometry at the perturbed positions, and compared with
!> each entry's vector weight W_jp (raccord_constraint_set). With one
!> direction per row (mortar_work_t%entry_dirs off) the mid nodes' entries
!> miss by about half the edge angle: the test asserts that too, so that
!> it would fail without per-entry directions. Also the Delassus blocks of
!> such a set against their definition with the vector weights.
program test_corner_rows
  use raccord_kinds, only: wp
  use raccord_check, only: failure_t, new_test, run_tests, check, check_close
  use raccord_error, only: error_t
  use raccord_mesh, only: mesh_t, ELEM_Q8
  use raccord_scene, only: MULT_P1, MULT_P0
  use raccord_contact_surface, only: contact_surface_t, build_contact_surface
  use raccord_contact_verlet, only: verlet_t, verlet_init
  use raccord_constraint_set, only: constraint_set_t
  use raccord_mortar, only: mortar_work_t, init_mortar, build_mortar
  use raccord_solver_work, only: solver_work_t
  use raccord_delassus, only: delassus
  use raccord_test_meshes, only: rect_mesh, join_meshes
  implicit none

  !> Arc radius of the bent interface and its edge angle: 5 Q8 edges of
  !> 0.2 on a radius of 1, d = 0.2 rad.
  real(wp), parameter :: RADIUS = 1.0_wp
  real(wp), parameter :: REACH = 0.25_wp
  !> Central-difference step (positions of order 1).
  real(wp), parameter :: FD_STEP = 1.0e-6_wp

  call run_tests('corner_rows', [ &
    new_test('corner rows on a curved Q8 arc: force = gradient of the weighted gap (P1, P0)', test_gradient), &
    new_test('the same with one direction per row: the mid nodes'' entries miss (the test discriminates)', &
      test_one_direction), &
    new_test('Delassus blocks of per-entry vector weights against their definition', test_delassus_vectors)])

contains

  !> Two Q8 blocks meeting on y = 0.5 (slave: 5 edges on [0, 1]; master:
  !> 9 on [-0.25, 1.25], past both slave ends, no node in common), bent
  !> onto an arc of radius RADIUS about (0.5, 0.5 - RADIUS): (x, y) ->
  !> centre + (RADIUS + y - 0.5) (sin t, cos t), t = (x - 0.5)/RADIUS.
  !> Every node is mapped, so both traces interpolate the same arc.
  subroutine curved_pair(mesh, slave, master, failure)
    type(mesh_t), intent(out) :: mesh
    type(contact_surface_t), intent(out) :: slave, master
    type(failure_t), allocatable, intent(inout) :: failure
    type(mesh_t) :: ma, mb
    type(error_t) :: err
    integer :: n
    real(wp) :: t, r
    call rect_mesh(ma, ELEM_Q8, 9, 2, 1.5_wp, 0.5_wp, x0=-0.25_wp)
    call rect_mesh(mb, ELEM_Q8, 5, 2, 1.0_wp, 0.5_wp, y0=0.5_wp)
    call join_meshes(ma, 'a', mb, 'b', mesh)
    do n = 1, mesh%nnode
      t = (mesh%x(1, n) - 0.5_wp)/RADIUS
      r = RADIUS + mesh%x(2, n) - 0.5_wp
      mesh%x(:, n) = [0.5_wp + r*sin(t), 0.5_wp - RADIUS + r*cos(t)]
    end do
    call build_contact_surface(mesh, 'b_bottom', 'test slave', slave, err)
    if (.not. err%failed()) call build_contact_surface(mesh, 'a_top', 'test master', master, err)
    if (err%failed()) call check(failure, .false., 'setup failed: ' // err%message)
  end subroutine curved_pair

  !> The mortar rows on positions x (geometry and gaps both at x), from a
  !> fresh workspace.
  subroutine rows_at(slave, master, x, mult, dirs, cs)
    type(contact_surface_t), intent(in) :: slave, master
    real(wp), intent(in) :: x(:,:)
    integer, intent(in) :: mult
    logical, intent(in) :: dirs
    type(constraint_set_t), intent(out) :: cs
    type(mortar_work_t) :: w
    type(verlet_t) :: verlet
    type(error_t) :: err
    real(wp), allocatable :: du(:,:)
    call init_mortar(slave, master, mult, 'test', w, err)
    w%corners = .true.
    w%entry_dirs = dirs
    allocate(du(2, size(x, 2)), source=0.0_wp)
    call verlet_init(verlet, slave, master, .true., REACH)
    call build_mortar(slave, master, x, x, du, REACH, REACH, mult, verlet, cs, w)
  end subroutine rows_at

  !> Largest |W_jp - dg_j/dx_p| over the entries of every row of an
  !> interior corner, over the largest |W_jp| of those rows; also over the
  !> slave mid nodes' entries only (mid_err). dg_j/dx_p by central
  !> differences of cs%gap_w(j) with the rows rebuilt at x +- FD_STEP e.
  subroutine gradient_error(mult, dirs, err_all, err_mid, nrows, failure)
    integer, intent(in) :: mult
    logical, intent(in) :: dirs
    real(wp), intent(out) :: err_all, err_mid
    integer, intent(out) :: nrows
    type(failure_t), allocatable, intent(inout) :: failure
    type(mesh_t) :: mesh
    type(contact_surface_t) :: slave, master
    type(constraint_set_t) :: cs, csp, csm
    real(wp), allocatable :: x(:,:)
    real(wp) :: wv(2), fd(2), gp, gm, wmax, gmean
    integer :: j, e, p, c, jp, jm, sn
    logical :: mid, dbg
    dbg = .false.
    err_all = huge(1.0_wp)
    err_mid = huge(1.0_wp)
    nrows = 0
    call curved_pair(mesh, slave, master, failure)
    if (allocated(failure)) return
    call rows_at(slave, master, mesh%x, mult, dirs, cs)
    call check(failure, cs%entry_dirs .eqv. dirs, 'the constraint set carries vector weights exactly when asked')
    call check(failure, cs%m == 6 .and. all(mod(cs%snode(1:cs%m), 2) == 1), &
      'every corner and no mid node carries a multiplier')
    if (allocated(failure)) return
    ! Both traces interpolate the same arc: the gap is the difference of
    ! two quadratic interpolants of a circle, R phi^4 / 8 at most for a
    ! half-edge angle phi = 0.1 (1.25e-5), so the mean gap is below that.
    gmean = maxval(abs(cs%gap_w(1:cs%m)/cs%length(1:cs%m)))
    write(*, '(a, es10.3)') '        largest mean gap |g_w| / int psi = ', gmean
    call check(failure, gmean < 1.25e-5_wp, 'the traces of one arc have (nearly) zero weighted gaps')
    if (allocated(failure)) return
    x = mesh%x
    err_all = 0.0_wp
    err_mid = 0.0_wp
    wmax = 0.0_wp
    do j = 1, cs%m
      sn = cs%snode(j)
      if (sn == 1 .or. sn == slave%nnode) cycle          ! interior corners: a full two-edge support
      nrows = nrows + 1
      do e = cs%row_ptr(j), cs%row_ptr(j + 1) - 1
        p = cs%ent_node(e)
        if (dirs) then
          wv = cs%ent_v(:, e)
        else
          wv = cs%ent_w(e)*cs%normal(:, j)
        end if
        wmax = max(wmax, norm2(wv))
        do c = 1, 2
          x(c, p) = mesh%x(c, p) + FD_STEP
          call rows_at(slave, master, x, mult, dirs, csp)
          x(c, p) = mesh%x(c, p) - FD_STEP
          call rows_at(slave, master, x, mult, dirs, csm)
          x(c, p) = mesh%x(c, p)
          jp = findloc(csp%snode(1:csp%m), sn, 1)
          jm = findloc(csm%snode(1:csm%m), sn, 1)
          call check(failure, jp > 0 .and. jm > 0, 'the row keeps its corner under the perturbation')
          if (allocated(failure)) return
          gp = csp%gap_w(jp)
          gm = csm%gap_w(jm)
          fd(c) = (gp - gm)/(2.0_wp*FD_STEP)
        end do
        if (dbg) print '(a,i4,i4,4es14.5)', 'dbg', j, p, wv, fd
        err_all = max(err_all, norm2(wv - fd))
        mid = findloc(slave%node, p, 1) > 0
        if (mid) mid = mod(findloc(slave%node, p, 1), 2) == 0
        if (mid) err_mid = max(err_mid, norm2(wv - fd))
      end do
    end do
    err_all = err_all/wmax
    err_mid = err_mid/wmax
  end subroutine gradient_error

  subroutine test_gradient(failure)
    type(failure_t), allocatable, intent(out) :: failure
    integer, parameter :: mults(2) = [MULT_P1, MULT_P0]
    real(wp) :: ea, em
    integer :: im, nrows
    do im = 1, 2
      call gradient_error(mults(im), .true., ea, em, nrows, failure)
      if (allocated(failure)) return
      write(*, '(a, a, a, es10.3, a, es10.3, a, i0, a)') '        ', merge('P1', 'P0', im == 1), &
        ': max |W - grad g| / max |W| = ', ea, ' (mid nodes ', em, '; ', nrows, ' rows)'
      call check(failure, nrows == 4, 'four interior corner rows')
      ! W is the gradient at zero gap; what remains is the gap (mean below
      ! 1e-6 here) times the change of the weights and directions with the
      ! positions, 1.4e-5 measured (central differences add 1e-10), against
      ! 6e-2 with one direction per row (test_one_direction).
      call check(failure, ea < 1.0e-4_wp, 'a corner row''s vector weights are the gradient of its weighted gap')
      if (allocated(failure)) return
    end do
  end subroutine test_gradient

  subroutine test_one_direction(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp) :: ea, em
    integer :: nrows
    call gradient_error(MULT_P1, .false., ea, em, nrows, failure)
    if (allocated(failure)) return
    write(*, '(a, es10.3, a, es10.3, a)') '        one direction per row: max |w n - grad g| / max |W| = ', ea, &
      ' (mid nodes ', em, ')'
    ! A mid node's entry along the corner's normal, tilted by half the
    ! edge angle (0.1 rad) from its own: its error is about sin(0.1) of it,
    ! and the mid nodes carry the largest entries (16/48 H against 8/48 H).
    ! (6.0e-2 measured.)
    call check(failure, em > 3.0e-2_wp, 'with one direction per row the mid nodes'' entries are not the gradient')
  end subroutine test_one_direction

  !> K(j, k) = sum_p a_jp . (M_p^-1 b_kp), a and b the entries' vector
  !> weights W or W^perp, M_p^-1 scaled by h_ratio / (1 + alpha h / 2),
  !> against delassus on the P1 corner rows of the arc (vector weights).
  subroutine test_delassus_vectors(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(mesh_t) :: mesh
    type(contact_surface_t) :: slave, master
    type(constraint_set_t) :: cs
    type(solver_work_t) :: w
    real(wp), allocatable :: minv(:,:), alpha(:)
    real(wp) :: ref(4), got(4), mi(2), a(2), b(2), scale, h, h_ratio
    integer :: j, k, e1, e2, p, blk, n
    call curved_pair(mesh, slave, master, failure)
    if (allocated(failure)) return
    call rows_at(slave, master, mesh%x, MULT_P1, .true., cs)
    allocate(minv(2, mesh%nnode), alpha(mesh%nnode))
    do n = 1, mesh%nnode
      minv(:, n) = [1.0_wp + 0.1_wp*mod(n, 7), 1.0_wp + 0.13_wp*mod(n, 5)]
      alpha(n) = 0.5_wp*mod(n, 3)
    end do
    h = 1.0e-3_wp
    h_ratio = 1.0_wp
    call delassus(cs, minv, alpha, h_ratio, h, .true., w)
    scale = maxval(abs(w%knn(0, 1:cs%m)))
    do j = 1, cs%m
      do k = max(1, j - w%kb), min(cs%m, j + w%kb)
        ref = 0.0_wp
        do e1 = cs%row_ptr(j), cs%row_ptr(j + 1) - 1
          do e2 = cs%row_ptr(k), cs%row_ptr(k + 1) - 1
            p = cs%ent_node(e1)
            if (cs%ent_node(e2) /= p) cycle
            mi = h_ratio/(1.0_wp + 0.5_wp*alpha(p)*h)*minv(:, p)
            do blk = 1, 4
              a = cs%ent_v(:, e1)
              if (blk > 2) a = [a(2), -a(1)]
              b = cs%ent_v(:, e2)
              if (blk == 2 .or. blk == 4) b = [b(2), -b(1)]
              ref(blk) = ref(blk) + dot_product(a*mi, b)
            end do
          end do
        end do
        got = [w%knn(k - j, j), w%knt(k - j, j), w%ktn(k - j, j), w%ktt(k - j, j)]
        do blk = 1, 4
          call check_close(failure, got(blk), ref(blk), 'Delassus block (nn, nt, tn, tt) with vector weights', &
            abs_tol=1.0e-14_wp*scale)
          if (allocated(failure)) return
        end do
      end do
    end do
    ! On a curved arc the tangential coupling of neighbouring rows is not
    ! zero (their entries' directions differ): the set is not trivial.
    call check(failure, maxval(abs(w%knt(-1:1, 1:cs%m))) > 1.0e-6_wp*scale, &
      'the arc couples normal and tangential parts')
  end subroutine test_delassus_vectors
end program test_corner_rows
