!> The order in which a results file stores the nodes: grouped by element
!> block, so that each block's nodes are one contiguous range of rows of
!> /mesh/x and of every nodal field (doc/output-format.md, "Node order").
!> An XDMF grid then takes a body's own nodes as a hyperslab of the global
!> arrays, without copying them.
!>
!> Rule: nodes are ordered by the first block (in block order) whose
!> connectivity uses them, and within that block by their model index;
!> nodes used by no block come last. A block's range is [first, first+count)
!> over the rows its connectivity uses: for blocks that share no node (the
!> bodies of a contact model) it holds exactly that block's nodes.
module raccord_node_order
  implicit none
  private

  public :: node_order

contains

  !> For nnode model nodes and the blocks' connectivities conn_k(nen, nel)
  !> (1-based model indices, passed as one list `nodes_of_block` per block
  !> through block_start/block_nodes: the nodes of block b are
  !> block_nodes(block_start(b):block_start(b+1)-1)), compute
  !>   order(i): the model node stored at row i (1-based),
  !>   row(p):   the row (1-based) of model node p,
  !>   first(b), count(b): block b's rows are first(b) .. first(b)+count(b)-1.
  pure subroutine node_order(nnode, block_start, block_nodes, order, row, first, count)
    integer, intent(in) :: nnode
    integer, intent(in) :: block_start(:)     !< (nblock + 1)
    integer, intent(in) :: block_nodes(:)
    integer, intent(out) :: order(nnode), row(nnode)
    integer, intent(out) :: first(:), count(:)
    integer :: b, k, p, n, lo, hi
    row = 0
    n = 0
    do b = 1, size(block_start) - 1
      do k = block_start(b), block_start(b + 1) - 1
        p = block_nodes(k)
        if (row(p) == 0) row(p) = -b          ! claimed by block b, numbered below
      end do
      ! Within a block, model order: scan the claimed nodes in index order.
      do p = 1, nnode
        if (row(p) == -b) then
          n = n + 1
          row(p) = n
          order(n) = p
        end if
      end do
    end do
    do p = 1, nnode
      if (row(p) == 0) then
        n = n + 1
        row(p) = n
        order(n) = p
      end if
    end do
    do b = 1, size(block_start) - 1
      lo = huge(1)
      hi = 0
      do k = block_start(b), block_start(b + 1) - 1
        lo = min(lo, row(block_nodes(k)))
        hi = max(hi, row(block_nodes(k)))
      end do
      if (hi == 0) then
        first(b) = 1
        count(b) = 0
      else
        first(b) = lo
        count(b) = hi - lo + 1
      end if
    end do
  end subroutine node_order
end module raccord_node_order
