!> Colouring of element groups for a race-free threaded scatter
!> (doc/performance.md, "Threading").
!>
!> The elastic blocks process their elements in chunks of consecutive
!> elements (raccord_elastic_block); a chunk's forces are scattered to its
!> nodes by the thread that computed them. (The blocks colour groups of
!> consecutive kernel chunks; to this module a "chunk" is any run of
!> chunk_len consecutive elements.) Two chunks may run at the same
!> time only if they share no node, so the chunks are coloured: chunks of
!> one colour are pairwise node-disjoint, the colours run one after the
!> other, and the chunks of a colour are shared among the threads.
!>
!> Greedy colouring in chunk order (first fit): each chunk takes the lowest
!> colour not yet used by a chunk that shares a node with it. The number of
!> colours is at most 1 + the largest number of other chunks a chunk shares
!> a node with (every neighbour blocks at most one colour). Colours are
!> looked up in windows of 64 held as bit masks per node, so the work is
!> O(nen nel) per window and the memory one integer(int64) per node.
!>
!> The colouring depends on the mesh and the chunk length only, never on
!> the thread count; so does the order in which forces add up at a node,
!> which is what makes the forces bitwise the same for any thread count.
module raccord_colouring
  use, intrinsic :: iso_fortran_env, only: int64
  use raccord_error, only: error_t, raise_error, EXIT_INPUT
  use raccord_strings, only: str
  implicit none
  private

  public :: colour_chunks, chunk_elements

  !> Colours examined per pass (bits of one integer(int64) mask).
  integer, parameter :: window = 64

contains

  !> Colour the chunks of chunk_len consecutive elements of conn(nen, nel)
  !> (nodes 1..nnode). On return colour c holds the chunks
  !> chunk(ptr(c) : ptr(c + 1) - 1), in ascending order, and
  !> ncolour = size(ptr) - 1. Errors (EXIT_INPUT): a node outside 1..nnode,
  !> a chunk length < 1, or no memory for the node masks.
  subroutine colour_chunks(conn, nnode, chunk_len, ptr, chunk, err)
    integer, intent(in) :: conn(:,:)
    integer, intent(in) :: nnode, chunk_len
    integer, allocatable, intent(out) :: ptr(:), chunk(:)
    type(error_t), intent(inout) :: err
    character(len=*), parameter :: where = 'colour_chunks: '
    integer(int64), allocatable :: used(:)
    integer, allocatable :: colour(:), count(:)
    integer(int64) :: busy
    integer :: nel, nchunk, ic, e, a, base, left, free, ncolour, c, stat
    character(len=256) :: msg

    nel = size(conn, 2)
    if (chunk_len < 1) then
      call raise_error(err, EXIT_INPUT, where // 'chunk length must be >= 1, got ' // str(chunk_len))
      return
    end if
    if (nel > 0) then
      if (any(conn < 1) .or. any(conn > nnode)) then
        call raise_error(err, EXIT_INPUT, where // 'connectivity refers to a node outside 1..' // str(nnode))
        return
      end if
    end if
    nchunk = (nel + chunk_len - 1)/chunk_len
    allocate(used(nnode), colour(nchunk), stat=stat, errmsg=msg)
    if (stat /= 0) then
      call raise_error(err, EXIT_INPUT, where // 'cannot allocate the node masks of ' // str(nnode) // &
        ' nodes: ' // trim(msg) // '; use a smaller mesh or more memory')
      return
    end if

    colour = 0
    left = nchunk
    base = 0
    ! One pass per window of 64 colours: the chunks still uncoloured try
    ! colours base+1 .. base+64, first fit; those whose neighbours already
    ! hold all 64 wait for the next window.
    windows: do while (left > 0)
      used = 0_int64
      chunks: do ic = 1, nchunk
        if (colour(ic) /= 0) cycle chunks
        busy = 0_int64
        do e = (ic - 1)*chunk_len + 1, min(ic*chunk_len, nel)
          do a = 1, size(conn, 1)
            busy = ior(busy, used(conn(a, e)))
          end do
        end do
        if (busy == not(0_int64)) cycle chunks
        free = trailz(not(busy))
        colour(ic) = base + free + 1
        left = left - 1
        do e = (ic - 1)*chunk_len + 1, min(ic*chunk_len, nel)
          do a = 1, size(conn, 1)
            used(conn(a, e)) = ibset(used(conn(a, e)), free)
          end do
        end do
      end do chunks
      base = base + window
    end do windows

    ! Counting sort by colour, ascending chunk index inside a colour.
    ncolour = 0
    if (nchunk > 0) ncolour = maxval(colour)
    allocate(count(ncolour + 1), ptr(ncolour + 1), chunk(nchunk), stat=stat, errmsg=msg)
    if (stat /= 0) then
      call raise_error(err, EXIT_INPUT, where // 'cannot allocate the colour lists: ' // trim(msg))
      return
    end if
    count = 0
    do ic = 1, nchunk
      count(colour(ic)) = count(colour(ic)) + 1
    end do
    ptr(1) = 1
    do c = 1, ncolour
      ptr(c + 1) = ptr(c) + count(c)
    end do
    count(1:ncolour) = ptr(1:ncolour)
    do ic = 1, nchunk
      c = colour(ic)
      chunk(count(c)) = ic
      count(c) = count(c) + 1
    end do
  end subroutine colour_chunks
  !> The elements e0..e1 of chunk ic of chunk_len consecutive elements
  !> among nel (the chunks colour_chunks colours).
  pure subroutine chunk_elements(ic, chunk_len, nel, e0, e1)
    integer, intent(in) :: ic, chunk_len, nel
    integer, intent(out) :: e0, e1
    e0 = (ic - 1)*chunk_len + 1
    e1 = min(ic*chunk_len, nel)
  end subroutine chunk_elements

end module raccord_colouring
