!> The chunk colouring (raccord_colouring) that makes the threaded scatter
!> race-free: every chunk is coloured once, no two chunks of one colour
!> share a node, each colour lists its chunks in ascending order, and the
!> colour count stays within the greedy bound 1 + (largest number of other
!> chunks a chunk shares a node with). On structured Q4 and Q8 meshes, on a
!> mesh with its elements shuffled, on a fan whose chunks all share one
!> node (more than one 64-colour window), and on bad input.
program test_colouring
  use raccord_kinds, only: wp, i8
  use raccord_strings, only: str
  use raccord_check, only: failure_t, new_test, run_tests, check
  use raccord_error, only: error_t
  use raccord_mesh, only: mesh_t, ELEM_Q4, ELEM_Q8
  use raccord_colouring, only: colour_chunks
  use raccord_test_meshes, only: rect_mesh
  implicit none

  integer, parameter :: chunk_len = 32

  call run_tests('colouring', [ &
    new_test('structured Q4 mesh (40 x 30), chunks of 32', test_q4), &
    new_test('structured Q8 mesh (20 x 12), chunks of 32', test_q8), &
    new_test('Q4 mesh with its elements shuffled, chunks of 32 and 8', test_shuffled), &
    new_test('fan of 150 elements around one node, chunks of 1: 150 colours', test_fan), &
    new_test('no elements; a node out of range; a chunk length of 0', test_edge_cases)])

contains

  !> Checks every property of a colouring of conn with chunks of clen; ncol
  !> returns the colour count.
  subroutine check_colouring(failure, conn, nnode, clen, ncol)
    type(failure_t), allocatable, intent(inout) :: failure
    integer, intent(in) :: conn(:,:), nnode, clen
    integer, intent(out) :: ncol
    type(error_t) :: err
    integer, allocatable :: ptr(:), chunk(:), seen(:), owner(:), nbr(:)
    logical, allocatable :: touch(:,:)
    integer :: nel, nchunk, c, k, ic, e, a, node, bad, i, j, maxdeg

    nel = size(conn, 2)
    nchunk = (nel + clen - 1)/clen
    call colour_chunks(conn, nnode, clen, ptr, chunk, err)
    call check(failure, .not. err%failed(), 'colour_chunks failed: ' // err%message)
    if (allocated(failure)) return
    ncol = size(ptr) - 1
    call check(failure, size(chunk) == nchunk .and. ptr(1) == 1 .and. ptr(ncol + 1) == nchunk + 1, &
      'the colour lists do not hold every chunk')
    if (allocated(failure)) return
    ! every chunk exactly once, no empty colour, ascending inside a colour
    allocate(seen(nchunk), source=0)
    bad = 0
    do c = 1, ncol
      if (ptr(c + 1) <= ptr(c)) bad = bad + 1
      do k = ptr(c), ptr(c + 1) - 1
        seen(chunk(k)) = seen(chunk(k)) + 1
        if (k > ptr(c)) then
          if (chunk(k) <= chunk(k - 1)) bad = bad + 1
        end if
      end do
    end do
    call check(failure, all(seen == 1), 'a chunk is coloured more or less than once')
    call check(failure, bad == 0, 'an empty colour or a colour not in ascending chunk order')
    ! no node is touched by two chunks of one colour
    allocate(owner(nnode))
    bad = 0
    do c = 1, ncol
      owner = 0
      do k = ptr(c), ptr(c + 1) - 1
        ic = chunk(k)
        do e = (ic - 1)*clen + 1, min(ic*clen, nel)
          do a = 1, size(conn, 1)
            node = conn(a, e)
            if (owner(node) /= 0 .and. owner(node) /= ic) bad = bad + 1
            owner(node) = ic
          end do
        end do
      end do
    end do
    call check(failure, bad == 0, 'two chunks of one colour share a node (' // str(bad) // ' times)')
    ! greedy bound: 1 + the largest number of neighbouring chunks
    allocate(touch(nnode, nchunk), source=.false.)
    do ic = 1, nchunk
      do e = (ic - 1)*clen + 1, min(ic*clen, nel)
        touch(conn(:, e), ic) = .true.
      end do
    end do
    allocate(nbr(nchunk), source=0)
    do i = 1, nchunk
      do j = i + 1, nchunk
        if (any(touch(:, i) .and. touch(:, j))) then
          nbr(i) = nbr(i) + 1
          nbr(j) = nbr(j) + 1
        end if
      end do
    end do
    maxdeg = 0
    if (nchunk > 0) maxdeg = maxval(nbr)
    call check(failure, ncol <= maxdeg + 1, str(ncol) // ' colours, more than the greedy bound ' // &
      str(maxdeg + 1))
  end subroutine check_colouring

  subroutine test_q4(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(mesh_t) :: mesh
    integer :: ncol
    call rect_mesh(mesh, ELEM_Q4, 40, 30, 4.0_wp, 3.0_wp)
    call check_colouring(failure, mesh%conn(1:4, :), mesh%nnode, chunk_len, ncol)
    ! a chunk of a row-numbered mesh meets the chunks beside it and those of
    ! the rows above and below: a handful of colours, not dozens
    call check(failure, ncol >= 2 .and. ncol <= 6, 'structured Q4 mesh: ' // str(ncol) // ' colours')
  end subroutine test_q4

  subroutine test_q8(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(mesh_t) :: mesh
    integer :: ncol
    call rect_mesh(mesh, ELEM_Q8, 20, 12, 2.0_wp, 1.2_wp)
    call check_colouring(failure, mesh%conn(1:8, :), mesh%nnode, chunk_len, ncol)
    call check(failure, ncol >= 2 .and. ncol <= 6, 'structured Q8 mesh: ' // str(ncol) // ' colours')
  end subroutine test_q8

  !> A fixed pseudo-random permutation of the elements (an unordered mesh):
  !> chunks are scattered, so they meet many others; the bound must hold.
  subroutine test_shuffled(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(mesh_t) :: mesh
    integer, allocatable :: perm(:), conn(:,:)
    integer :: i, j, t, ncol, nel
    integer(i8) :: seed
    call rect_mesh(mesh, ELEM_Q4, 30, 20, 3.0_wp, 2.0_wp)
    nel = mesh%nelem
    perm = [(i, i = 1, nel)]
    seed = 12345
    do i = nel, 2, -1
      seed = mod(seed*48271_i8, 2147483647_i8)
      j = int(mod(seed, int(i, i8))) + 1
      t = perm(i)
      perm(i) = perm(j)
      perm(j) = t
    end do
    conn = mesh%conn(1:4, perm)
    call check_colouring(failure, conn, mesh%nnode, chunk_len, ncol)
    call check_colouring(failure, conn, mesh%nnode, 8, ncol)
  end subroutine test_shuffled

  !> 150 elements sharing node 1, one element per chunk: every chunk meets
  !> every other, so exactly 150 colours (three 64-colour windows).
  subroutine test_fan(failure)
    type(failure_t), allocatable, intent(out) :: failure
    integer :: conn(4, 150), e, ncol
    do e = 1, 150
      conn(:, e) = [1, 3*e - 1, 3*e, 3*e + 1]
    end do
    call check_colouring(failure, conn, 3*150 + 1, 1, ncol)
    call check(failure, ncol == 150, 'fan: ' // str(ncol) // ' colours, expected 150')
  end subroutine test_fan

  subroutine test_edge_cases(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(error_t) :: err
    integer, allocatable :: ptr(:), chunk(:)
    integer :: empty(4, 0), conn(4, 2)
    call colour_chunks(empty, 5, chunk_len, ptr, chunk, err)
    call check(failure, .not. err%failed(), 'no elements: failed')
    if (allocated(failure)) return
    call check(failure, size(ptr) == 1 .and. size(chunk) == 0, 'no elements: expected no colour')
    conn(:, 1) = [1, 2, 3, 4]
    conn(:, 2) = [2, 5, 6, 3]
    call colour_chunks(conn, 5, chunk_len, ptr, chunk, err)
    call check(failure, err%failed(), 'node 6 of 5 accepted')
    if (err%failed()) call check(failure, index(err%message, '1..5') > 0, 'message does not name the range: ' // &
      err%message)
    call err%clear()
    call colour_chunks(conn, 6, 0, ptr, chunk, err)
    call check(failure, err%failed(), 'chunk length 0 accepted')
  end subroutine test_edge_cases

end program test_colouring
