!> Stress and strain recovery of the elastic blocks for output (theory eq.
!> 7.1): each element's Gauss-point values extrapolated to its nodes and
!> summed there, group by group in colour order as the internal force
!> (raccord_elastic_block), so the sums have the same bits for any thread
!> count. The element-level work is in raccord_elastic_block_element and
!> the submodules of the other kernels; here is the choice among them, once
!> per group.
submodule (raccord_elastic_block) raccord_elastic_block_stress
  implicit none

contains

  !> The block's nodal stress or strain (declared in raccord_elastic_block).
  module procedure add_nodal_stress
    integer :: col, k, e, e0, e1, what
    integer, parameter :: small_stress = 1, small_strain = 2, finite_stress = 3, finite_strain = 4, j2_stress = 9
    integer, parameter :: axi_stress = 5, axi_strain = 6, finite_axi_stress = 7, finite_axi_strain = 8
    what = small_stress
    if (present(strain)) then
      if (strain) what = small_strain
    end if
    if (blk%kinematics == KIN_FINITE) what = what + 2
    if (blk%axisymmetric) what = what + 4
    if (blk%material == MAT_J2 .and. what /= small_strain .and. what /= finite_strain .and. what /= axi_strain &
        .and. what /= finite_axi_strain) then
      if (.not. present(plastic)) error stop 'add_nodal_stress: a j2 block needs its plastic state'
      what = j2_stress
    end if
    !$omp parallel if (blk%nthreads > 1 .and. blk%nchunk >= min_parallel_chunks) num_threads(blk%nthreads) &
    !$omp   default(none) shared(blk, u, s, wsum, what, plastic) &
    !$omp   private(col, k, e, e0, e1)
    colours: do col = 1, blk%ncolour
      !$omp do schedule(static)
      groups: do k = blk%colour_ptr(col), blk%colour_ptr(col + 1) - 1
        call chunk_elements(blk%colour_group(k), blk%group_len*chunk_len, blk%nel, e0, e1)
        select case (what)
        case (small_stress)
          do e = e0, e1
            call add_element_stress(blk, e, u, s, wsum)
          end do
        case (small_strain)
          do e = e0, e1
            call add_element_small_strain(blk, e, u, s, wsum)
          end do
        case (finite_stress)
          do e = e0, e1
            call add_element_finite(blk, e, u, .false., s, wsum)
          end do
        case (finite_strain)
          do e = e0, e1
            call add_element_finite(blk, e, u, .true., s, wsum)
          end do
        case (j2_stress)
          call add_group_j2_stress(blk, blk%colour_group(k), u, plastic, s, wsum)
        case (axi_stress, axi_strain)
          do e = e0, e1
            call add_element_axi(blk, e, u, what == axi_strain, s, wsum)
          end do
        case (finite_axi_stress, finite_axi_strain)
          call add_group_finite_axi(blk, blk%colour_group(k), u, what == finite_axi_strain, s, wsum)
        end select
      end do groups
      !$omp end do
    end do colours
    !$omp end parallel
  end procedure add_nodal_stress

end submodule raccord_elastic_block_stress
