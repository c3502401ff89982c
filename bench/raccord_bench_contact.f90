!> Contact cost benchmark: two long strips pressed together (non-matching
!> 3:4 at the interface, every interface node in contact), run for a fixed
!> number of steps; prints the search-and-matching and multiplier-solve time
!> per contact node per step, and the whole step per element, for each
!> method and friction setting. Not a test: figures for doc/performance.md.
!> Contact stays serial; the column contact% is its share of the step (the
!> serial fraction s of Amdahl's law, bounding the speed-up on T threads by
!> 1/(s + (1 - s)/T)). Threads: OMP_NUM_THREADS, as for a run (column thr).
!>
!>   raccord_bench_contact [steps] [n1 n2 ...]     (n = slave nodes wanted)
program raccord_bench_contact
  use raccord_kinds, only: wp, i8
  use raccord_error, only: error_t
  use raccord_mesh, only: mesh_t, ELEM_Q4
  use raccord_scene, only: scene_t, bc_spec_t, body_spec_t, contact_spec_t, BC_FIXED, BC_PRESSURE, &
    METHOD_NTS, METHOD_MORTAR, MULT_P1
  use raccord_model, only: model_t
  use raccord_model_build, only: build_model
  use raccord_time_step, only: time_plan_t, choose_time_step
  use raccord_state, only: state_t, init_state
  use raccord_central_difference, only: compute_forces, predict_motion, update_energy, advance_state
  use raccord_contact_pair, only: contact_pair_t, init_contact_pairs, enforce_contact
  use raccord_test_meshes, only: rect_mesh, join_meshes
  implicit none

  integer :: nsteps, k, nsizes, ios
  integer :: sizes(32)
  character(len=64) :: arg

  nsteps = 200
  nsizes = 3
  sizes(1:3) = [100, 1000, 10000]
  do k = 1, command_argument_count()
    call get_command_argument(k, arg)
    if (arg == '-h' .or. arg == '--help') then
      call print_usage()
      stop
    end if
  end do
  if (command_argument_count() >= 1) then
    call get_command_argument(1, arg)
    read(arg, *, iostat=ios) nsteps
    if (ios /= 0 .or. nsteps < 1) call bad_argument('steps', arg)
  end if
  if (command_argument_count() >= 2) then
    nsizes = min(32, command_argument_count() - 1)
    do k = 1, nsizes
      call get_command_argument(k + 1, arg)
      read(arg, *, iostat=ios) sizes(k)
      if (ios /= 0 .or. sizes(k) < 2) call bad_argument('slave nodes', arg)
    end do
  end if
  write(*, '(a)') '# method          mu   slave_nodes  elements  steps  search_ns/node/step  solve_ns/node/step' // &
    '  iterations/step  step_ns/element  contact%  thr'
  do k = 1, nsizes
    call run_case(METHOD_NTS, 0.0_wp, sizes(k))
    call run_case(METHOD_NTS, 0.3_wp, sizes(k))
    call run_case(METHOD_MORTAR, 0.0_wp, sizes(k))
    call run_case(METHOD_MORTAR, 0.3_wp, sizes(k))
  end do

contains

  subroutine print_usage()
    write(*, '(a)') 'usage: raccord_bench_contact [STEPS [N1 N2 ...]]', &
      '', &
      'Two steel strips pressed together (non-matching 3:4 at the interface, every', &
      'interface node in contact), STEPS steps (default 200) for each number of slave', &
      'nodes N (default 100 1000 10000), with node-to-segment and mortar P1, mu = 0 and 0.3.', &
      'Prints per case: search and matching, and multiplier solve, in ns per contact node', &
      'and step; active-set iterations per step; the whole step in ns per element; the', &
      'contact share of the step (%); threads (OMP_NUM_THREADS; contact stays serial).', &
      'Figures for doc/performance.md, not a test. Exit 0, or 1 on a bad argument.'
  end subroutine print_usage

  subroutine bad_argument(what, text)
    character(len=*), intent(in) :: what, text
    write(*, '(a)') 'raccord_bench_contact: ' // what // ' must be a whole number >= ' // &
      merge('1', '2', what == 'steps') // ', not ''' // trim(text) // '''; see --help'
    stop 1   ! (the message is printed above; ERROR STOP would add a backtrace)
  end subroutine bad_argument

  subroutine run_case(method, mu, nslave)
    integer, intent(in) :: method, nslave
    real(wp), intent(in) :: mu
    type(mesh_t) :: ma, mb, mesh
    type(scene_t) :: scene
    type(model_t) :: model
    type(contact_pair_t), allocatable :: pairs(:)
    type(time_plan_t) :: plan
    type(state_t) :: state
    type(error_t) :: err
    integer(i8) :: t0, t1, rate
    integer :: step, ns, nm
    real(wp) :: wall, tb, ts, lx

    ns = nslave - 1
    nm = max(1, (4*ns)/3)
    lx = real(ns, wp)
    ! Lower strip (master top) and upper strip (slave bottom), touching.
    call rect_mesh(ma, ELEM_Q4, nm, 2, lx, 2.0_wp)
    call rect_mesh(mb, ELEM_Q4, ns, 2, lx, 2.0_wp, y0=2.0_wp)
    call join_meshes(ma, 'a', mb, 'b', mesh)
    call make_scene(scene, method, mu)
    call build_model(scene, mesh, model, err)
    if (.not. err%failed()) call init_contact_pairs(scene, mesh, model, pairs, err)
    if (.not. err%failed()) call choose_time_step(scene, model, plan, err)
    if (err%failed()) then
      write(*, '(a)') 'setup failed: ' // err%message
      return
    end if
    call init_state(model, plan%dt, int(nsteps, i8), state)
    call system_clock(t0, rate)
    do step = 0, nsteps
      call compute_forces(model, state)
      call predict_motion(model, state)
      call enforce_contact(pairs, model, state, err)
      call update_energy(model, state)
      if (step < nsteps) call advance_state(state)
    end do
    call system_clock(t1)
    wall = real(t1 - t0, wp)/real(rate, wp)
    tb = real(pairs(1)%clock_build, wp)/real(rate, wp)
    ts = real(pairs(1)%clock_solve, wp)/real(rate, wp)
    write(*, '(a16,f5.2,i13,i10,i7,f21.1,f20.1,f17.2,f17.1,f10.1,i5)') trim(merge('node_to_segment', 'mortar P1      ', &
      method == METHOD_NTS)), mu, nslave, model%nelem, nsteps + 1, &
      1.0e9_wp*tb/real((nsteps + 1)*nslave, wp), 1.0e9_wp*ts/real((nsteps + 1)*nslave, wp), &
      real(pairs(1)%iterations_total, wp)/real(nsteps + 1, wp), 1.0e9_wp*wall/real((nsteps + 1)*model%nelem, wp), &
      100.0_wp*(tb + ts)/wall, model%nthreads
  end subroutine run_case

  !> Steel-like strips, lower clamped at its bottom, upper pressed on its top.
  subroutine make_scene(scene, method, mu)
    type(scene_t), intent(out) :: scene
    integer, intent(in) :: method
    real(wp), intent(in) :: mu
    type(body_spec_t) :: b
    type(bc_spec_t) :: bc
    type(contact_spec_t) :: c
    scene%path = 'bench'
    scene%dir = '.'
    allocate(scene%bodies(0), scene%bcs(0), scene%amplitudes(0), scene%contacts(0))
    b%young = 200000.0_wp
    b%poisson = 0.3_wp
    b%density = 7.8e-9_wp
    b%damping = 0.0_wp
    b%name = 'a'
    b%elset = 'a_body'
    scene%bodies = [scene%bodies, b]
    b%name = 'b'
    b%elset = 'b_body'
    scene%bodies = [scene%bodies, b]
    bc%amplitude = ''
    bc%set = 'a_bottom'
    bc%kind = BC_FIXED
    bc%comp = [.true., .true.]
    scene%bcs = [scene%bcs, bc]
    bc%set = 'b_top'
    bc%kind = BC_PRESSURE
    bc%comp = [.false., .false.]
    bc%pressure = 100.0_wp
    scene%bcs = [scene%bcs, bc]
    c%slave = 'b_bottom'
    c%master = 'a_top'
    c%method = method
    c%multiplier = MULT_P1
    c%friction = mu
    scene%contacts = [scene%contacts, c]
    scene%time%t_end = 1.0_wp
  end subroutine make_scene
end program raccord_bench_contact
