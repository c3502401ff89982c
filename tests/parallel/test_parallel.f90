!> Threaded runs against the serial run (doc/performance.md, "Threading").
!> The design makes them bitwise equal: the element loops add up at each
!> node in colour order and the per-node sums over fixed node segments
!> (raccord_elastic_block, raccord_central_difference), neither of which
!> depends on the thread count, and contact is serial. So the check is
!> equality of every bit, not a tolerance: displacements, velocities,
!> internal forces, contact multipliers, every energy at every step, and
!> the recovered nodal stresses, after 100 steps on 1, 2 and 3 threads
!> (3: an odd count, so that uneven shares of chunks and segments are met).
!> Two scenes with contact, friction, damping, a body force and a support:
!> Q4 with node-to-segment, Q8 with mortar, each with more than 2048 nodes
!> and a body of at least 1024 elements, so that both the element and the
!> per-node loops run threaded (the thresholds below which they run serial);
!> the smaller body stays below the element threshold (serial next to
!> threaded).
program test_parallel
  use raccord_kinds, only: wp
  use raccord_check, only: failure_t, new_test, run_tests, check
  use raccord_error, only: error_t
  use raccord_strings, only: str
  use raccord_mesh, only: mesh_t, ELEM_Q4, ELEM_Q8
  use raccord_scene, only: scene_t, BC_FIXED, BC_PRESSURE, METHOD_NTS, METHOD_MORTAR
  use raccord_model, only: model_t, set_model_threads
  use raccord_time_step, only: time_plan_t
  use raccord_state, only: state_t
  use raccord_central_difference, only: advance_state
  use raccord_contact_pair, only: contact_pair_t
  use raccord_elastic_block, only: elastic_block_t, init_elastic_block, add_internal_force, add_nodal_stress, &
    element_stiffness, claim_first_touch
  use raccord_test_meshes, only: rect_mesh
  use dynamics_support, only: add_bc, add_pair, contact_step, two_body_scene, prepare_contact
  implicit none

  integer, parameter :: nsteps = 100, nhist = 8
  real(wp), parameter :: e = 1000.0_wp, nu = 0.3_wp, rho = 1.0e-6_wp

  !> What a run leaves to compare.
  type :: run_record_t
    real(wp), allocatable :: u(:,:), v(:,:), f_int(:,:), stress(:,:), lam_n(:), lam_t(:)
    real(wp) :: hist(nhist, nsteps) = 0.0_wp        !< energies at every step
    integer :: nactive = 0, nslip = 0, nthreads_env = 0
  end type run_record_t

  call run_tests('parallel', [ &
    new_test('OMP_NUM_THREADS reaches the model (the suite asks for 3)', test_environment), &
    new_test('Q4, node-to-segment, mu = 0.3: 2 and 3 threads bitwise equal to 1', test_q4_nts), &
    new_test('Q8, mortar, mu = 0.3: 2 and 3 threads bitwise equal to 1', test_q8_mortar), &
    new_test('large Q4 and Q8 blocks (grouped chunks): f = K u, every element once, any thread count', &
      test_large_blocks), &
    new_test('fresh forces: two blocks claimed together give f = K u over any old f, any thread count', &
      test_fresh_forces)])

contains

  !> Block b (element set b_body) pressed (pressure on its top) and thrown
  !> down and sideways onto block a, which is clamped at its bottom and
  !> damped; a gravity-like body force on b; 100 steps on nthreads threads.
  subroutine run_scene(etype, method, na, nb, nthreads, rec, err)
    integer, intent(in) :: etype, method, na(2), nb(2), nthreads
    type(run_record_t), intent(out) :: rec
    type(error_t), intent(inout) :: err
    type(mesh_t) :: ma, mb, mesh
    type(scene_t) :: scene
    type(model_t) :: model
    type(contact_pair_t), allocatable :: pairs(:)
    type(time_plan_t) :: plan
    type(state_t) :: state
    integer :: k, ib, kb

    call rect_mesh(ma, etype, na(1), na(2), 2.0_wp, 0.5_wp)
    call rect_mesh(mb, etype, nb(1), nb(2), 1.0_wp, 0.5_wp, x0=0.5_wp, y0=0.5_wp, distortion=0.1_wp)
    call two_body_scene(ma, mb, mesh, scene, e, nu, rho, .false., 1.0_wp)
    scene%bodies(1)%damping = 2000.0_wp
    scene%bodies(2)%damping = 0.0_wp
    scene%bodies(2)%velocity = [3.0_wp, -6.0_wp]
    call add_bc(scene, 'b_top', BC_PRESSURE, pressure=1.0_wp)
    scene%bodies(2)%body_force = [0.0_wp, -2.0e-3_wp]
    call add_bc(scene, 'a_bottom', BC_FIXED, comp=[.true., .true.])
    call add_pair(scene, 'b_bottom', 'a_top', method, 0.3_wp)
    call prepare_contact(scene, mesh, model, pairs, plan, state, err)
    if (err%failed()) return
    rec%nthreads_env = model%nthreads
    call set_model_threads(model, nthreads)
    steps: do k = 1, nsteps
      call contact_step(model, pairs, state, err)
      if (err%failed()) return
      associate (en => state%energy)
        rec%hist(:, k) = [en%kinetic, en%internal, en%discrete, en%external, en%damping, en%contact, &
          en%friction, en%balance]
      end associate
      if (k < nsteps) call advance_state(state)
    end do steps
    rec%u = state%u
    rec%v = state%v
    rec%f_int = state%f_int
    rec%lam_n = pairs(1)%lam_n
    rec%lam_t = pairs(1)%lam_t
    rec%nactive = pairs(1)%nactive
    rec%nslip = pairs(1)%nslip
    allocate(rec%stress(4, model%nnode), source=0.0_wp)
    block
      real(wp) :: wsum(model%nnode)
      wsum = 0.0_wp
      do ib = 1, size(model%bodies)
        do kb = 1, size(model%bodies(ib)%blocks)
          call add_nodal_stress(model%bodies(ib)%blocks(kb), state%u, rec%stress, wsum)
        end do
      end do
    end block
  end subroutine run_scene

  !> Bitwise comparison of run rec with the serial reference ref.
  subroutine compare(failure, what, rec, ref)
    type(failure_t), allocatable, intent(inout) :: failure
    character(len=*), intent(in) :: what
    type(run_record_t), intent(in) :: rec, ref
    call check(failure, all(rec%u == ref%u), what // ': displacements differ in ' // &
      str(count(rec%u /= ref%u)) // ' components, by up to ' // str(maxval(abs(rec%u - ref%u))))
    call check(failure, all(rec%v == ref%v), what // ': velocities differ in ' // str(count(rec%v /= ref%v)) // &
      ' components')
    call check(failure, all(rec%f_int == ref%f_int), what // ': internal forces differ in ' // &
      str(count(rec%f_int /= ref%f_int)) // ' components')
    call check(failure, all(rec%lam_n == ref%lam_n) .and. all(rec%lam_t == ref%lam_t), &
      what // ': contact multipliers differ')
    call check(failure, all(rec%hist == ref%hist), what // ': energies differ at ' // &
      str(count(rec%hist /= ref%hist)) // ' of ' // str(size(ref%hist)) // ' (step, term) entries')
    call check(failure, all(rec%stress == ref%stress), what // ': nodal stresses differ in ' // &
      str(count(rec%stress /= ref%stress)) // ' components')
  end subroutine compare

  subroutine threads_case(failure, etype, method, na, nb)
    type(failure_t), allocatable, intent(out) :: failure
    integer, intent(in) :: etype, method, na(2), nb(2)
    type(run_record_t) :: ref, rec
    type(error_t) :: err
    real(wp) :: scale
    integer :: nt
    call run_scene(etype, method, na, nb, 1, ref, err)
    call check(failure, .not. err%failed(), 'serial run failed: ' // err%message)
    if (allocated(failure)) return
    ! the scene must exercise what is compared: contact, friction, damping
    call check(failure, ref%nactive > 0, 'no active contact node at the end')
    call check(failure, ref%hist(7, nsteps) > 0.0_wp, 'no friction dissipation')
    call check(failure, ref%hist(5, nsteps) > 0.0_wp, 'no damping dissipation')
    ! a sane serial run (the balance itself is checked by the contact suites)
    scale = maxval(abs(ref%hist(1:7, :)))
    call check(failure, abs(ref%hist(8, nsteps)) <= 1.0e-2_wp*scale, &
      'serial energy balance ' // str(ref%hist(8, nsteps)) // ' of a scale ' // str(scale))
    if (allocated(failure)) return
    print '(a, i0, a, i0, a, es10.3, a, es10.3, a)', '  serial: ', ref%nactive, ' active, ', ref%nslip, &
      ' slipping; friction work ', ref%hist(7, nsteps), ', energy balance ', ref%hist(8, nsteps)/scale, &
      ' of the largest energy'
    do nt = 2, 3
      call run_scene(etype, method, na, nb, nt, rec, err)
      call check(failure, .not. err%failed(), str(nt) // ' threads: run failed: ' // err%message)
      if (allocated(failure)) return
      call compare(failure, str(nt) // ' threads', rec, ref)
    end do
  end subroutine threads_case

  subroutine test_q4_nts(failure)
    type(failure_t), allocatable, intent(out) :: failure
    ! a: 64 x 28 (1792 elements), b: 25 x 12 (300); 2210 nodes in all
    call threads_case(failure, ELEM_Q4, METHOD_NTS, [64, 28], [25, 12])
  end subroutine test_q4_nts

  subroutine test_q8_mortar(failure)
    type(failure_t), allocatable, intent(out) :: failure
    ! a: 64 x 16 (1024 elements), b: 17 x 6 (102); 3586 nodes in all
    call threads_case(failure, ELEM_Q8, METHOD_MORTAR, [64, 16], [17, 6])
  end subroutine test_q8_mortar

  !> Blocks large enough for several chunks per colouring group (5120 Q4,
  !> 4608 Q8 elements on distorted meshes): the threaded internal force
  !> equals the element-by-element product sum_e K_e u_e (element_stiffness,
  !> the Gauss sum of eq. 3.2) to 1e-12 of its largest entry, bitwise the
  !> same on 1, 2 and 3 threads; the stress recovery counts every element
  !> once at each of its nodes (wsum equals the node's element count).
  subroutine test_large_blocks(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call large_block_case(failure, ELEM_Q4, 80, 64)
    call large_block_case(failure, ELEM_Q8, 72, 64)
  end subroutine test_large_blocks

  !> compute_forces does not zero f_int: each node is reset by the group
  !> that touches it first, over the blocks claimed in call order. Two Q4
  !> blocks of 1152 elements each (threaded) share a row of nodes; f starts
  !> as garbage, with one extra node that no block touches. The result must
  !> be bitwise that of zeroing f and adding both blocks, whatever the
  !> thread count, and the extra node must keep its value. A group that
  !> claimed a node too late, or twice, or not at all, would fail it.
  subroutine test_fresh_forces(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(mesh_t) :: mesh
    type(elastic_block_t) :: blk(2)
    type(error_t) :: err
    real(wp), allocatable :: u(:,:), f(:,:), fref(:,:)
    logical, allocatable :: claimed(:)
    integer :: n, half, nt, b
    call rect_mesh(mesh, ELEM_Q4, 48, 48, 4.0_wp, 3.0_wp, distortion=0.2_wp)
    n = mesh%nnode
    half = mesh%nelem/2
    call init_elastic_block(blk(1), ELEM_Q4, mesh%conn(1:4, 1:half), mesh%x, e, nu, .false., 1.0_wp, err)
    if (.not. err%failed()) call init_elastic_block(blk(2), ELEM_Q4, mesh%conn(1:4, half+1:), mesh%x, &
      2.0_wp*e, nu, .false., 1.0_wp, err)
    call check(failure, .not. err%failed(), 'blocks: ' // err%message)
    if (allocated(failure)) return
    allocate(u(2, n + 1), source=0.0_wp)
    u(1, 1:n) = 1.0e-3_wp*sin(mesh%x(1, :) + 0.3_wp*mesh%x(2, :))
    u(2, 1:n) = 1.0e-3_wp*cos(0.7_wp*mesh%x(1, :) - mesh%x(2, :))
    allocate(fref(2, n + 1), source=0.0_wp)
    fref(:, n + 1) = -7.0_wp
    call add_internal_force(blk(1), u, fref)
    call add_internal_force(blk(2), u, fref)
    allocate(claimed(n + 1), source=.false.)
    call claim_first_touch(blk(1), claimed)
    call claim_first_touch(blk(2), claimed)
    call check(failure, count(claimed) == n .and. .not. claimed(n + 1), 'claimed ' // str(count(claimed)) // &
      ' nodes, expected the ' // str(n) // ' of the mesh')
    allocate(f(2, n + 1))
    do nt = 1, 3
      f = -7.0_wp
      do b = 1, 2
        blk(b)%nthreads = nt
        call add_internal_force(blk(b), u, f, fresh=.true.)
      end do
      call check(failure, all(f == fref), str(nt) // ' threads: fresh forces differ from zero-then-add at ' // &
        str(count(f /= fref)/2) // ' nodes (largest difference ' // str(maxval(abs(f - fref))) // ')')
      ! twice in a row (as from one step to the next): the same again
      do b = 1, 2
        call add_internal_force(blk(b), u, f, fresh=.true.)
      end do
      call check(failure, all(f == fref), str(nt) // ' threads: a second fresh pass does not reset f')
    end do
  end subroutine test_fresh_forces

  subroutine large_block_case(failure, etype, nx, ny)
    type(failure_t), allocatable, intent(inout) :: failure
    integer, intent(in) :: etype, nx, ny
    type(mesh_t) :: mesh
    type(elastic_block_t) :: blk
    type(error_t) :: err
    real(wp), allocatable :: u(:,:), f(:,:), fref(:,:), f1(:,:), s(:,:), w(:), s1(:,:), w1(:)
    real(wp) :: ke(16, 16), ue(16), fe(16)
    integer, allocatable :: nelem_at(:)
    integer :: nen, el, a, nt, n
    character(len=2) :: name
    name = 'Q4'
    if (etype == ELEM_Q8) name = 'Q8'
    call rect_mesh(mesh, etype, nx, ny, 4.0_wp, 3.0_wp, distortion=0.2_wp)
    nen = 4
    if (etype == ELEM_Q8) nen = 8
    call init_elastic_block(blk, etype, mesh%conn(1:nen, :), mesh%x, e, nu, .false., 1.0_wp, err)
    call check(failure, .not. err%failed(), name // ' block: ' // err%message)
    if (allocated(failure)) return
    n = mesh%nnode
    allocate(u(2, n), f(2, n), fref(2, n), s(4, n), w(n))
    u(1, :) = 1.0e-3_wp*sin(mesh%x(1, :) + 0.3_wp*mesh%x(2, :))
    u(2, :) = 1.0e-3_wp*cos(0.7_wp*mesh%x(1, :) - mesh%x(2, :))
    fref = 0.0_wp
    allocate(nelem_at(n), source=0)
    do el = 1, mesh%nelem
      call element_stiffness(blk, el, ke(1:2*nen, 1:2*nen))
      do a = 1, nen
        ue(2*a - 1:2*a) = u(:, mesh%conn(a, el))
      end do
      fe(1:2*nen) = matmul(ke(1:2*nen, 1:2*nen), ue(1:2*nen))
      do a = 1, nen
        fref(:, mesh%conn(a, el)) = fref(:, mesh%conn(a, el)) + fe(2*a - 1:2*a)
        nelem_at(mesh%conn(a, el)) = nelem_at(mesh%conn(a, el)) + 1
      end do
    end do
    do nt = 1, 3
      blk%nthreads = nt
      f = 0.0_wp
      call add_internal_force(blk, u, f)
      s = 0.0_wp
      w = 0.0_wp
      call add_nodal_stress(blk, u, s, w)
      if (nt == 1) then
        call check(failure, maxval(abs(f - fref)) <= 1.0e-12_wp*maxval(abs(fref)), name // ': f differs from ' // &
          'sum_e K_e u_e by ' // str(maxval(abs(f - fref))) // ' of a largest ' // str(maxval(abs(fref))))
        call check(failure, all(nint(w) == nelem_at), name // ': stress recovery does not count every element ' // &
          'once at its nodes')
        f1 = f
        s1 = s
        w1 = w
      else
        call check(failure, all(f == f1) .and. all(s == s1) .and. all(w == w1), name // ': ' // str(nt) // &
          ' threads differ from 1 (internal force or nodal stress)')
      end if
    end do
  end subroutine large_block_case

  !> The suite runs with OMP_NUM_THREADS=3 (tests/parallel/CMakeLists.txt):
  !> build_model must take it, capped at the processors this process may use
  !> (raccord_threads; 1 in a build without OpenMP).
  subroutine test_environment(failure)
    !$ use omp_lib, only: omp_get_num_procs
    type(failure_t), allocatable, intent(out) :: failure
    type(run_record_t) :: rec
    type(error_t) :: err
    integer :: expected, length, status
    call get_environment_variable('OMP_NUM_THREADS', length=length, status=status)
    call check(failure, status == 0 .and. length > 0, 'OMP_NUM_THREADS is not set for this suite')
    if (allocated(failure)) return
    expected = 1
    !$ expected = min(3, omp_get_num_procs())
    call run_scene(ELEM_Q4, METHOD_NTS, [4, 2], [2, 2], 1, rec, err)
    call check(failure, .not. err%failed(), 'run failed')
    call check(failure, rec%nthreads_env == expected, 'model threads ' // str(rec%nthreads_env) // &
      ', expected ' // str(expected))
  end subroutine test_environment
end program test_parallel
