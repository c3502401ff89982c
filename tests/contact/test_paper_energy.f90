!> The paper's scene (coarse regression meshes, input/paper/reg_*): every
!> method and slave choice runs the whole down-and-back cycle with an exact
!> energy balance, without contact giving energy to the bodies, without an
!> unconverged multiplier step, and quasi-statically at maximum indentation.
program test_paper_energy
  use raccord_kinds, only: wp
  use raccord_check, only: failure_t, new_test, run_tests, check
  use raccord_error, only: error_t
  use raccord_scene_runner, only: scene_run_t, run_deck
  implicit none

  call run_tests('paper_energy', [ &
    new_test('node-to-segment, slave = block', test_nts_block), &
    new_test('node-to-segment, slave = disc (mid mesh)', test_nts_disc), &
    new_test('node-to-segment, slave = disc, coarse and mid: no energy given back', test_nts_disc_refine), &
    new_test('mortar P1, slave = block', test_mortar_p1_block), &
    new_test('mortar P1, slave = disc', test_mortar_p1_disc), &
    new_test('mortar P0, slave = block', test_mortar_p0_block), &
    new_test('mortar P1, mu = 0.2', test_mortar_friction)])

contains

  subroutine cycle_case(failure, deck, given_back)
    type(failure_t), allocatable, intent(out) :: failure
    character(len=*), intent(in) :: deck
    real(wp), intent(out), optional :: given_back   !< -min contact work / max internal energy
    type(scene_run_t) :: run, half
    type(error_t) :: err
    real(wp) :: ratio
    ! Maximum indentation is at t = T = 2e-5 s (input/paper/make_decks.sh).
    call run_deck('input/paper/' // deck, half, err, t_stop=2.0e-5_wp)
    call check(failure, .not. err%failed(), 'run to maximum indentation failed')
    if (allocated(failure)) return
    ratio = half%state%energy%kinetic/half%state%energy%internal
    call run_deck('input/paper/' // deck, run, err)
    call check(failure, .not. err%failed(), 'run of the whole cycle failed')
    if (allocated(failure)) return
    write(*, '(a,es10.3,a,es10.3,a,es10.3,a,i0,a,es10.3)') '        ' // deck // ': KE/IE at T ', ratio, &
      ', contact work min/max IE ', run%min_contact_work/run%max_internal, ', end ', &
      run%state%energy%contact/run%max_internal, ', unconverged ', run%pairs(1)%failed_total, &
      ', balance ', run%worst_balance
    if (present(given_back)) given_back = -run%min_contact_work/run%max_internal
    call check(failure, run%worst_balance < 1.0e-10_wp, 'energy balance not exact')
    call check(failure, run%min_contact_work > -1.0e-3_wp*run%max_internal, &
      'contact gave the bodies more than 1e-3 of the peak internal energy')
    call check(failure, run%pairs(1)%failed_total == 0, 'unconverged multiplier steps')
    call check(failure, ratio < 1.0e-3_wp, 'not quasi-static at maximum indentation (KE/IE >= 1e-3)')
  end subroutine cycle_case

  subroutine test_nts_block(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call cycle_case(failure, 'reg_nts_slave_block.nml')
  end subroutine test_nts_block

  subroutine test_nts_disc(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call cycle_case(failure, 'reg_nts_slave_disc_mid.nml')
  end subroutine test_nts_disc

  !> Node-to-segment with the disc as slave: its nodes slide over the
  !> block's faceted top. Against the polygon (before the smoothed master,
  !> doc/theory-contact.md, section 7) a node crossing a vertex, or sliding
  !> along a segment under a tilted normal, was pushed out and contact gave
  !> back energy: 1.6e-3 of the peak internal energy on the coarse mesh,
  !> falling under refinement. Against the smoothed master the condition is
  !> the same as for the other cases and holds on both meshes with a margin
  !> (measured 2e-16 coarse, 2e-6 mid): 1e-5 of the peak on each.
  subroutine test_nts_disc_refine(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp) :: coarse, mid
    call cycle_case(failure, 'reg_nts_slave_disc.nml', coarse)
    if (allocated(failure)) return
    call cycle_case(failure, 'reg_nts_slave_disc_mid.nml', mid)
    if (allocated(failure)) return
    write(*, '(a,es10.3,a,es10.3)') '        energy given back / peak internal: coarse ', coarse, ', mid ', mid
    call check(failure, coarse < 1.0e-5_wp .and. mid < 1.0e-5_wp, &
      'contact gives back more than 1e-5 of the peak internal energy')
  end subroutine test_nts_disc_refine

  subroutine test_mortar_p1_block(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call cycle_case(failure, 'reg_mortar_p1_slave_block.nml')
  end subroutine test_mortar_p1_block

  subroutine test_mortar_p1_disc(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call cycle_case(failure, 'reg_mortar_p1_slave_disc.nml')
  end subroutine test_mortar_p1_disc

  subroutine test_mortar_p0_block(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call cycle_case(failure, 'reg_mortar_p0_slave_block.nml')
  end subroutine test_mortar_p0_block

  subroutine test_mortar_friction(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call cycle_case(failure, 'reg_mortar_p1_mu020.nml')
  end subroutine test_mortar_friction
end program test_paper_energy
