!> Bad contact pairs are refused with a message that names the pair, the
!> surface and what is wrong: unknown surface, a surface inside a body, a
!> surface that is not one chain of edges, slave and master on one body.
program test_contact_input
  use raccord_kinds, only: wp
  use raccord_check, only: failure_t, new_test, run_tests, check
  use raccord_error, only: error_t, EXIT_INPUT
  use raccord_mesh, only: mesh_t, surface_t, ELEM_Q4
  use raccord_scene, only: scene_t, METHOD_NTS, METHOD_MORTAR
  use raccord_model, only: model_t
  use raccord_model_build, only: build_model
  use raccord_contact_pair, only: contact_pair_t, init_contact_pairs
  use raccord_test_meshes, only: rect_mesh
  use dynamics_support, only: add_pair, two_body_scene
  implicit none

  call run_tests('contact_input', [ &
    new_test('unknown surface', test_unknown), &
    new_test('surface inside a body', test_interior), &
    new_test('surface of two separate pieces', test_pieces), &
    new_test('slave and master on the same body', test_same_body), &
    new_test('a good pair is accepted (both methods)', test_good)])

contains

  !> Blocks a (4 x 2 elements) and b above it; extra surfaces added by the caller.
  subroutine setup(mesh, scene)
    type(mesh_t), intent(out) :: mesh
    type(scene_t), intent(out) :: scene
    type(mesh_t) :: ma, mb
    call rect_mesh(ma, ELEM_Q4, 4, 2, 1.0_wp, 0.5_wp)
    call rect_mesh(mb, ELEM_Q4, 3, 2, 1.0_wp, 0.5_wp, y0=0.5_wp)
    call two_body_scene(ma, mb, mesh, scene, 1000.0_wp, 0.3_wp, 1.0e-6_wp, .false., 1.0_wp)
  end subroutine setup

  !> init_contact_pairs must fail with EXIT_INPUT and a message holding every fragment.
  subroutine expect_refusal(failure, mesh, scene, fragments)
    type(failure_t), allocatable, intent(inout) :: failure
    type(mesh_t), intent(in) :: mesh
    type(scene_t), intent(inout) :: scene
    character(len=*), intent(in) :: fragments(:)
    type(model_t) :: model
    type(contact_pair_t), allocatable :: pairs(:)
    type(error_t) :: err
    integer :: k
    call build_model(scene, mesh, model, err)
    call check(failure, .not. err%failed(), 'model refused')
    if (allocated(failure)) return
    call init_contact_pairs(scene, mesh, model, pairs, err)
    call check(failure, err%code == EXIT_INPUT, 'bad pair accepted')
    if (allocated(failure)) return
    write(*, '(a)') '        ' // err%message
    do k = 1, size(fragments)
      call check(failure, index(err%message, trim(fragments(k))) > 0, &
        'message lacks ''' // trim(fragments(k)) // ''': ' // err%message)
    end do
  end subroutine expect_refusal

  subroutine test_unknown(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(mesh_t) :: mesh
    type(scene_t) :: scene
    call setup(mesh, scene)
    call add_pair(scene, 'b_nosuch', 'a_top', METHOD_NTS, 0.0_wp)
    call expect_refusal(failure, mesh, scene, [character(len=48) :: '&contact_pair #1', 'b_nosuch', 'not found', &
      'surfaces there: a_bottom, a_right, a_top'])
  end subroutine test_unknown

  !> The horizontal line y = 0.25 through block a: every edge is shared by
  !> two elements (the readers mark such edges with element -1).
  subroutine test_interior(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(mesh_t) :: mesh
    type(scene_t) :: scene
    type(surface_t) :: inner
    integer :: k
    call setup(mesh, scene)
    inner%name = 'a_inner'
    inner%nedge = 4
    inner%nen_edge = 2
    allocate(inner%edge(3, 4), source=0)
    allocate(inner%elem(4), source=-1)
    allocate(inner%side(4), source=1)
    do k = 1, 4
      ! Bottom side of the upper row of elements (elements 5..8).
      inner%edge(1:2, k) = mesh%conn(1:2, 4 + k)
    end do
    mesh%surfaces = [mesh%surfaces, inner]
    call add_pair(scene, 'b_bottom', 'a_inner', METHOD_NTS, 0.0_wp)
    call expect_refusal(failure, mesh, scene, [character(len=32) :: 'a_inner', 'inside a body'])
  end subroutine test_interior

  !> a_bottom without its second edge: two pieces.
  subroutine test_pieces(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(mesh_t) :: mesh
    type(scene_t) :: scene
    type(surface_t) :: broken
    integer :: k
    call setup(mesh, scene)
    do k = 1, size(mesh%surfaces)
      if (mesh%surfaces(k)%name == 'a_top') broken = mesh%surfaces(k)
    end do
    broken%name = 'a_top_broken'
    broken%nedge = 3
    broken%edge = broken%edge(:, [1, 3, 4])
    broken%elem = broken%elem([1, 3, 4])
    broken%side = broken%side([1, 3, 4])
    mesh%surfaces = [mesh%surfaces, broken]
    call add_pair(scene, 'b_bottom', 'a_top_broken', METHOD_MORTAR, 0.0_wp)
    call expect_refusal(failure, mesh, scene, [character(len=32) :: 'a_top_broken', 'not one connected chain'])
  end subroutine test_pieces

  subroutine test_same_body(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(mesh_t) :: mesh
    type(scene_t) :: scene
    call setup(mesh, scene)
    call add_pair(scene, 'a_top', 'a_bottom', METHOD_NTS, 0.0_wp)
    call expect_refusal(failure, mesh, scene, [character(len=32) :: 'same body', 'self-contact'])
  end subroutine test_same_body

  subroutine test_good(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(mesh_t) :: mesh
    type(scene_t) :: scene
    type(model_t) :: model
    type(contact_pair_t), allocatable :: pairs(:)
    type(error_t) :: err
    call setup(mesh, scene)
    call add_pair(scene, 'b_bottom', 'a_top', METHOD_NTS, 0.3_wp)
    call add_pair(scene, 'a_top', 'b_bottom', METHOD_MORTAR, 0.0_wp)
    call build_model(scene, mesh, model, err)
    if (.not. err%failed()) call init_contact_pairs(scene, mesh, model, pairs, err)
    call check(failure, .not. err%failed(), 'good pairs refused')
    if (allocated(failure)) return
    call check(failure, size(pairs) == 2 .and. pairs(1)%slave%nnode == 4 .and. pairs(2)%slave%nnode == 5, &
      'pairs not built from the right surfaces')
  end subroutine test_good
end program test_contact_input
