!> The paper's scene (section 4; doc/scenes.md section 1), fine Q4 mesh
!> (interface h = 0.01 mm block, 0.0138 mm disc), at maximum indentation
!> t = T = 2e-5 s: the contact pressure with the block as slave against the
!> disc as slave, for mortar P1 (Fig. 2(a)) and node-to-segment (Fig. 1(b)).
!> The paper's point: node-to-segment depends on the slave choice, mortar
!> hardly. Pressure: lam_n for mortar (its multiplier is the pressure),
!> `pressure` (multiplier over tributary length) for node-to-segment.
program test_paper_swap
  use raccord_kinds, only: wp
  use raccord_check, only: failure_t, new_test, run_tests, check
  use raccord_error, only: error_t
  use raccord_scene_runner, only: scene_run_t, run_deck
  use mortar_profile_support, only: profile_t, profile_of_run, zero_crossing_half_width, interior_difference
  implicit none

  real(wp), parameter :: T_MAX = 2.0e-5_wp     !< maximum indentation (input/paper/make_decks.sh)
  !> Asserted: mortar's asymmetry over |x| <= 0.8 a_h at most this fraction
  !> of node-to-segment's. Measured (Release): mortar 8.7e-4, node-to-segment
  !> 1.20e-1 of p_max, a ratio of 139; 1/20 leaves a factor 7 for other
  !> compilers and meshes while still failing if mortar's slave choice
  !> mattered at the percent level. (Linear interpolation of a Hertz-like
  !> profile errs by about h^2/8 |p''| = 4.6e-4 p_max at 0.8 a_h for
  !> h = 0.0138 mm, a_h = 0.49 mm: half of mortar's figure is that floor.)
  real(wp), parameter :: SWAP_FACTOR = 0.05_wp
  real(wp) :: mortar_interior = -1.0_wp, mortar_all = -1.0_wp, nts_interior = -1.0_wp, nts_all = -1.0_wp

  call run_tests('paper_swap', [ &
    new_test('mortar P1: slave = block against slave = disc', test_mortar), &
    new_test('node-to-segment: slave = block against slave = disc', test_nts), &
    new_test('mortar swap asymmetry far below node-to-segment''s', test_compare)])

contains

  !> Asymmetry of one method: the largest |p_block - p_disc| / p_max over
  !> the nodes of both profiles (the other interpolated), over the whole
  !> surface and over |x| <= 0.8 a_h (a_h: zero crossing of the block-slave
  !> profile), where the two profiles' edge intervals play no part.
  subroutine swap_case(failure, deck_block, deck_disc, use_lam, d_interior, d_all)
    type(failure_t), allocatable, intent(inout) :: failure
    character(len=*), intent(in) :: deck_block, deck_disc
    logical, intent(in) :: use_lam
    real(wp), intent(out) :: d_interior, d_all
    type(scene_run_t) :: run
    type(error_t) :: err
    type(profile_t) :: pb, pd
    real(wp), allocatable :: qb(:), qd(:)
    real(wp) :: pmax, ah
    d_interior = -1.0_wp
    d_all = -1.0_wp
    call run_deck('input/paper/' // deck_block, run, err, t_stop=T_MAX)
    call check(failure, .not. err%failed(), deck_block // ' failed')
    if (allocated(failure)) return
    call check(failure, run%pairs(1)%failed_total == 0, deck_block // ': unconverged multiplier steps')
    call profile_of_run(run, pb)
    call run_deck('input/paper/' // deck_disc, run, err, t_stop=T_MAX)
    call check(failure, .not. err%failed(), deck_disc // ' failed')
    if (allocated(failure)) return
    call check(failure, run%pairs(1)%failed_total == 0, deck_disc // ': unconverged multiplier steps')
    call profile_of_run(run, pd)
    if (use_lam) then
      qb = pb%lam
      qd = pd%lam
    else
      qb = pb%pres
      qd = pd%pres
    end if
    pmax = max(maxval(qb), maxval(qd))
    ah = zero_crossing_half_width(pb%x, qb)
    d_all = interior_difference(pb%x, qb, pd%x, qd, -huge(1.0_wp), huge(1.0_wp))/pmax
    d_interior = interior_difference(pb%x, qb, pd%x, qd, -0.8_wp*ah, 0.8_wp*ah)/pmax
    write(*, '(a,f8.1,a,f7.4,a,es10.3,a,es10.3)') '        p_max ', pmax, ' MPa, a_h ', ah, &
      ' mm; max |p_block - p_disc| / p_max: |x| <= 0.8 a_h ', d_interior, ', whole surface ', d_all
  end subroutine swap_case

  subroutine test_mortar(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call swap_case(failure, 'fig2a_mortar_p1_slave_block.nml', 'fig2a_mortar_p1_slave_disc.nml', .true., &
      mortar_interior, mortar_all)
  end subroutine test_mortar

  subroutine test_nts(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call swap_case(failure, 'fig1b_nts_slave_block.nml', 'fig1b_nts_slave_disc.nml', .false., &
      nts_interior, nts_all)
  end subroutine test_nts

  subroutine test_compare(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call check(failure, mortar_interior >= 0.0_wp .and. nts_interior >= 0.0_wp, 'the two runs above must run first')
    if (allocated(failure)) return
    write(*, '(a,f7.2,a,f7.2)') '        node-to-segment / mortar: |x| <= 0.8 a_h ', nts_interior/mortar_interior, &
      ', whole surface ', nts_all/mortar_all
    call check(failure, mortar_interior < SWAP_FACTOR*nts_interior, &
      'mortar''s swap asymmetry is not below the asserted fraction of node-to-segment''s')
    ! Over the whole surface the contact edges dominate both (a nodal
    ! profile resolves a square-root edge to O(p_max sqrt(h/a))); measured
    ! ratio 2.7: mortar must still be the smaller.
    call check(failure, mortar_all < nts_all, 'mortar''s whole-surface swap difference exceeds node-to-segment''s')
  end subroutine test_compare
end program test_paper_swap
