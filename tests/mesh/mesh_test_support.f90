!> Helpers for the mesh reader tests: data paths, the expected-error check,
!> and comparisons of meshes whose node numbering may differ (by coordinates).
module mesh_test_support
  use raccord_kinds, only: wp
  use raccord_error, only: error_t, EXIT_INPUT
  use raccord_mesh, only: mesh_t, find_node_set, find_elem_set, find_surface, side_nodes, nodes_per_element
  use raccord_mesh_io, only: read_mesh
  use raccord_check, only: failure_t, check, fail_now
  use raccord_strings, only: str
  implicit none
  private

  public :: data_path, expect_error, same_mesh_exactly, same_points, node_set_points, surface_points
  public :: elem_set_centroids, check_surface_parents

  !> Coordinates from Gmsh transfinite meshes carry ~1e-12 noise.
  real(wp), parameter, public :: xtol = 1.0e-9_wp

contains

  !> tests/data/mesh/<name>, from RACCORD_TEST_DATA.
  function data_path(name) result(path)
    character(len=*), intent(in) :: name
    character(len=:), allocatable :: path
    character(len=1024) :: root
    integer :: n, stat
    call get_environment_variable('RACCORD_TEST_DATA', root, n, stat)
    if (stat /= 0) root = 'tests/data'
    path = trim(root) // '/mesh/' // name
  end function data_path

  !> Reading bad/<name> must fail with EXIT_INPUT and a message holding
  !> every one of the given fragments.
  subroutine expect_error(failure, name, fragment1, fragment2, fragment3)
    type(failure_t), allocatable, intent(inout) :: failure
    character(len=*), intent(in) :: name, fragment1
    character(len=*), intent(in), optional :: fragment2, fragment3
    type(mesh_t) :: mesh
    type(error_t) :: err
    call read_mesh(data_path('bad/' // name), mesh, err)
    if (err%code /= EXIT_INPUT) then
      call fail_now(failure, name // ': expected EXIT_INPUT, got code ' // str(err%code))
      return
    end if
    call has(fragment1)
    if (present(fragment2)) call has(fragment2)
    if (present(fragment3)) call has(fragment3)
  contains
    subroutine has(fragment)
      character(len=*), intent(in) :: fragment
      call check(failure, index(err%message, fragment) > 0, name // ': message lacks "' // fragment // &
        '": ' // err%message)
    end subroutine has
  end subroutine expect_error

  !> Same numbering, coordinates, connectivity and sets (two Gmsh versions
  !> of one mesh number everything alike).
  subroutine same_mesh_exactly(failure, a, b, label)
    type(failure_t), allocatable, intent(inout) :: failure
    type(mesh_t), intent(in) :: a, b
    character(len=*), intent(in) :: label
    integer :: k, j
    call check(failure, a%nnode == b%nnode .and. a%nelem == b%nelem, label // ': node/element counts differ')
    if (allocated(failure)) return
    call check(failure, all(a%node_id == b%node_id), label // ': node ids differ')
    call check(failure, all(abs(a%x - b%x) <= xtol), label // ': coordinates differ')
    call check(failure, all(a%etype == b%etype), label // ': element types differ')
    call check(failure, all(a%conn == b%conn), label // ': connectivity differs')
    call check(failure, all(a%elem_id == b%elem_id), label // ': element ids differ')
    call check(failure, size(a%esets) == size(b%esets) .and. size(a%nsets) == size(b%nsets) .and. &
      size(a%surfaces) == size(b%surfaces), label // ': numbers of sets differ')
    if (allocated(failure)) return
    do k = 1, size(a%esets)
      j = find_elem_set(b, a%esets(k)%name)
      call check(failure, j > 0, label // ': element set ' // a%esets(k)%name // ' missing')
      if (allocated(failure)) return
      call check(failure, same_ints(a%esets(k)%elems, b%esets(j)%elems), label // ': eset ' // a%esets(k)%name)
    end do
    do k = 1, size(a%nsets)
      j = find_node_set(b, a%nsets(k)%name)
      call check(failure, j > 0, label // ': node set ' // a%nsets(k)%name // ' missing')
      if (allocated(failure)) return
      call check(failure, same_ints(a%nsets(k)%nodes, b%nsets(j)%nodes), label // ': nset ' // a%nsets(k)%name)
    end do
    do k = 1, size(a%surfaces)
      j = find_surface(b, a%surfaces(k)%name)
      call check(failure, j > 0, label // ': surface ' // a%surfaces(k)%name // ' missing')
      if (allocated(failure)) return
      call check(failure, a%surfaces(k)%nedge == b%surfaces(j)%nedge .and. &
        a%surfaces(k)%nen_edge == b%surfaces(j)%nen_edge, label // ': surface sizes ' // a%surfaces(k)%name)
      if (allocated(failure)) return
      call check(failure, all(a%surfaces(k)%edge == b%surfaces(j)%edge) .and. &
        all(a%surfaces(k)%elem == b%surfaces(j)%elem) .and. all(a%surfaces(k)%side == b%surfaces(j)%side), &
        label // ': surface ' // a%surfaces(k)%name)
    end do
  end subroutine same_mesh_exactly

  pure logical function same_ints(a, b)
    integer, intent(in) :: a(:), b(:)
    same_ints = size(a) == size(b)
    if (same_ints) same_ints = all(a == b)
  end function same_ints

  !> The same multiset of points up to xtol, whatever their order.
  logical function same_points(p, q)
    real(wp), intent(in) :: p(:,:), q(:,:)
    logical, allocatable :: used(:)
    integer :: i, j
    same_points = size(p, 2) == size(q, 2)
    if (.not. same_points) return
    allocate(used(size(q, 2)))
    used = .false.
    do i = 1, size(p, 2)
      same_points = .false.
      do j = 1, size(q, 2)
        if (used(j)) cycle
        if (all(abs(p(:, i) - q(:, j)) <= xtol)) then
          used(j) = .true.
          same_points = .true.
          exit
        end if
      end do
      if (.not. same_points) return
    end do
  end function same_points

  !> Coordinates of the nodes of a node set (empty when the set is absent).
  function node_set_points(mesh, name) result(p)
    type(mesh_t), intent(in) :: mesh
    character(len=*), intent(in) :: name
    real(wp), allocatable :: p(:,:)
    integer :: k
    k = find_node_set(mesh, name)
    if (k == 0) then
      allocate(p(2, 0))
    else
      p = mesh%x(:, mesh%nsets(k)%nodes)
    end if
  end function node_set_points

  !> Edges of a surface as points (start x, start y, end x, end y) in 4-space,
  !> so orientation counts in the comparison.
  function surface_points(mesh, name) result(p)
    type(mesh_t), intent(in) :: mesh
    character(len=*), intent(in) :: name
    real(wp), allocatable :: p(:,:)
    integer :: k, m
    k = find_surface(mesh, name)
    if (k == 0) then
      allocate(p(4, 0))
      return
    end if
    allocate(p(4, mesh%surfaces(k)%nedge))
    do m = 1, mesh%surfaces(k)%nedge
      p(1:2, m) = mesh%x(:, mesh%surfaces(k)%edge(1, m))
      p(3:4, m) = mesh%x(:, mesh%surfaces(k)%edge(2, m))
    end do
  end function surface_points

  !> Centroids of the corners of the elements of an element set.
  function elem_set_centroids(mesh, name) result(p)
    type(mesh_t), intent(in) :: mesh
    character(len=*), intent(in) :: name
    real(wp), allocatable :: p(:,:)
    integer :: k, m, e
    k = find_elem_set(mesh, name)
    if (k == 0) then
      allocate(p(2, 0))
      return
    end if
    allocate(p(2, size(mesh%esets(k)%elems)))
    do m = 1, size(mesh%esets(k)%elems)
      e = mesh%esets(k)%elems(m)
      p(:, m) = sum(mesh%x(:, mesh%conn(1:4, e)), dim=2)/4.0_wp
    end do
  end function elem_set_centroids

  !> Each edge with a parent is that parent's side, node for node.
  subroutine check_surface_parents(failure, mesh)
    type(failure_t), allocatable, intent(inout) :: failure
    type(mesh_t), intent(in) :: mesh
    integer :: k, m, e, loc(3), expect(3)
    do k = 1, size(mesh%surfaces)
      associate (s => mesh%surfaces(k))
        do m = 1, s%nedge
          e = s%elem(m)
          if (e == -1) cycle
          call check(failure, e >= 1 .and. e <= mesh%nelem .and. s%side(m) >= 1 .and. s%side(m) <= 4, &
            'surface ' // s%name // ': bad parent of edge ' // str(m))
          if (allocated(failure)) return
          loc = side_nodes(mesh%etype(e), s%side(m))
          expect(1:2) = mesh%conn(loc(1:2), e)
          expect(3) = 0
          if (loc(3) > 0 .and. loc(3) <= nodes_per_element(mesh%etype(e))) expect(3) = mesh%conn(loc(3), e)
          call check(failure, all(s%edge(:, m) == expect), 'surface ' // s%name // ': edge ' // str(m) // &
            ' is not side ' // str(s%side(m)) // ' of its parent in counter-clockwise order')
        end do
      end associate
    end do
  end subroutine check_surface_parents
end module mesh_test_support
