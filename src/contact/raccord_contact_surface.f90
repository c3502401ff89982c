!> A contact surface: a mesh surface checked to be one chain of element
!> edges and ordered along it, so that neighbouring segments and nodes are
!> neighbours in the arrays (the paper's x_0 < x_1 < ... < x_N, section 2).
module raccord_contact_surface
  use raccord_kinds, only: wp
  use raccord_error, only: error_t, raise_error, EXIT_INPUT
  use raccord_strings, only: str
  use raccord_mesh, only: mesh_t, find_surface
  use raccord_mesh_names, only: not_found_text
  implicit none
  private

  type, public :: contact_surface_t
    character(len=:), allocatable :: name
    integer :: nseg = 0
    integer :: nen_seg = 2                  !< 2 (Q4 edges) or 3 (Q8 edges)
    integer, allocatable :: seg(:,:)        !< (3, nseg) start, end, mid; consecutive along the chain
    integer :: nnode = 0
    integer, allocatable :: node(:)         !< chain nodes in order: corners and mid-side nodes
    integer, allocatable :: corner(:)       !< (nseg+1) corner nodes in chain order (nseg for a loop)
    logical :: closed = .false.
    real(wp), allocatable :: s0(:)          !< reference arc length of each node of `node`
    real(wp) :: h_max = 0.0_wp              !< longest segment (reference)
    real(wp) :: h_min = 0.0_wp              !< shortest segment (reference)
    !> axisymmetric bodies (x = r): surface integrals carry 2 pi r, so
    !> weights and tributary measures are areas of surfaces of revolution
    logical :: axisymmetric = .false.
  end type contact_surface_t

  public :: build_contact_surface

contains

  !> Build the ordered chain of the mesh surface `name`; errors name the
  !> scene key `where` and say how to fix the mesh.
  subroutine build_contact_surface(mesh, name, where, surf, err)
    type(mesh_t), intent(in) :: mesh
    character(len=*), intent(in) :: name, where
    type(contact_surface_t), intent(out) :: surf
    type(error_t), intent(inout) :: err
    integer :: is, k, e, a, b, nedge, cnt, start, cur, nxt, i, j
    integer, allocatable :: deg(:), first(:), second(:), order(:)
    logical, allocatable :: used(:)

    is = find_surface(mesh, name)
    if (is == 0) then
      call raise_error(err, EXIT_INPUT, where // ': ''' // trim(name) // ''' ' // not_found_text(mesh, name, &
        'surface') // '. A contact surface is a Gmsh physical curve or an Abaqus *SURFACE, TYPE=ELEMENT.')
      return
    end if
    associate (ms => mesh%surfaces(is))
      nedge = ms%nedge
      if (nedge == 0) then
        call raise_error(err, EXIT_INPUT, where // ': surface ''' // trim(name) // ''' has no edges.')
        return
      end if
      do k = 1, nedge
        if (ms%elem(k) <= 0) then
          call raise_error(err, EXIT_INPUT, where // ': surface ''' // trim(name) // ''' edge with nodes ' // &
            str(mesh%node_id(ms%edge(1, k))) // '-' // str(mesh%node_id(ms%edge(2, k))) // &
            ' lies inside a body (shared by two elements); a contact surface must be on a body''s boundary.')
          return
        end if
      end do
      ! Degree of each corner node: 1 at the two ends of an open chain, 2
      ! inside; anything else is a branch or several pieces.
      allocate(deg(mesh%nnode), first(mesh%nnode), second(mesh%nnode), source=0)
      do k = 1, nedge
        do j = 1, 2
          a = ms%edge(j, k)
          deg(a) = deg(a) + 1
          if (deg(a) == 1) then
            first(a) = k
          else if (deg(a) == 2) then
            second(a) = k
          else
            call raise_error(err, EXIT_INPUT, where // ': surface ''' // trim(name) // ''' is not a chain: node ' // &
              str(mesh%node_id(a)) // ' is shared by more than two of its edges. Split it into separate surfaces.')
            return
          end if
        end do
      end do
      ! Start at an end of the chain: the start node of an edge that no
      ! other edge ends at (orientation is consistent: edges are
      ! counter-clockwise around their elements).
      start = 0
      do k = 1, nedge
        if (deg(ms%edge(1, k)) == 1) then
          start = k
          exit
        end if
      end do
      surf%closed = start == 0
      if (surf%closed) start = 1
      allocate(used(nedge), source=.false.)
      allocate(order(nedge))
      cnt = 0
      cur = start
      do
        cnt = cnt + 1
        order(cnt) = cur
        used(cur) = .true.
        b = ms%edge(2, cur)
        nxt = first(b)
        if (nxt == cur) nxt = second(b)
        if (nxt == 0) exit
        if (used(nxt)) exit
        ! The chain must run one way: the next edge starts where this one ends.
        if (ms%edge(1, nxt) /= b) then
          call raise_error(err, EXIT_INPUT, where // ': surface ''' // trim(name) // ''' joins two bodies or ' // &
            'folds back at node ' // str(mesh%node_id(b)) // '; a contact surface must lie on one body.')
          return
        end if
        cur = nxt
      end do
      if (cnt /= nedge) then
        call raise_error(err, EXIT_INPUT, where // ': surface ''' // trim(name) // ''' is not one connected chain ' // &
          '(it has ' // str(nedge) // ' edges but only ' // str(cnt) // ' follow each other from node ' // &
          str(mesh%node_id(ms%edge(1, start))) // '). Use one physical curve / *SURFACE per connected piece.')
        return
      end if
      surf%name = trim(name)
      surf%nseg = nedge
      surf%nen_seg = ms%nen_edge
      allocate(surf%seg(3, nedge))
      do k = 1, nedge
        surf%seg(:, k) = ms%edge(:, order(k))
      end do
      if (surf%nen_seg == 3 .and. any(surf%seg(3, :) == 0)) then
        call raise_error(err, EXIT_INPUT, where // ': surface ''' // trim(name) // ''' mixes Q4 and Q8 edges; ' // &
          'a contact surface must lie on elements of one type.')
        return
      end if
    end associate

    ! Nodes in chain order, and reference arc lengths.
    allocate(surf%corner(surf%nseg + 1))
    do k = 1, surf%nseg
      surf%corner(k) = surf%seg(1, k)
    end do
    surf%corner(surf%nseg + 1) = surf%seg(2, surf%nseg)
    if (surf%closed) surf%corner = surf%corner(1:surf%nseg)
    cnt = 0
    allocate(surf%node((surf%nen_seg - 1)*surf%nseg + 1))
    allocate(surf%s0(size(surf%node)))
    surf%h_max = 0.0_wp
    surf%h_min = huge(1.0_wp)
    do k = 1, surf%nseg
      cnt = cnt + 1
      surf%node(cnt) = surf%seg(1, k)
      if (cnt == 1) surf%s0(cnt) = 0.0_wp
      e = surf%seg(1, k)
      i = surf%seg(2, k)
      if (surf%nen_seg == 3) then
        cnt = cnt + 1
        surf%node(cnt) = surf%seg(3, k)
        surf%s0(cnt) = surf%s0(cnt - 1) + norm2(mesh%x(:, surf%seg(3, k)) - mesh%x(:, e))
        surf%s0(cnt + 1) = surf%s0(cnt) + norm2(mesh%x(:, i) - mesh%x(:, surf%seg(3, k)))
      else
        surf%s0(cnt + 1) = surf%s0(cnt) + norm2(mesh%x(:, i) - mesh%x(:, e))
      end if
      surf%h_max = max(surf%h_max, norm2(mesh%x(:, i) - mesh%x(:, e)))
      surf%h_min = min(surf%h_min, norm2(mesh%x(:, i) - mesh%x(:, e)))
    end do
    if (.not. surf%closed) then
      cnt = cnt + 1
      surf%node(cnt) = surf%seg(2, surf%nseg)
    end if
    surf%nnode = cnt
    surf%node = surf%node(1:cnt)
    surf%s0 = surf%s0(1:cnt)
  end subroutine build_contact_surface
end module raccord_contact_surface
