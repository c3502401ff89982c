!> The paper's test with finite strain (issue #13; doc/reproduction.md,
!> "The paper's test with finite strain"), on the coarse mesh: the disc
!> pressed 0.1581 mm into the 0.3 mm layer, both bodies neo-Hooke
!> (input/paper/finite_coarse_mortar_p1_slave_block.nml), beside the same
!> scene in small strain (input/paper/reg_mortar_p1_slave_block.nml).
!> At maximum indentation the layer is compressed by about half under the
!> disc: finite strain must carry the contact force to the support, keep
!> the energy account, and raise the force and the peak pressure over
!> small strain by what CalculiX with NLGEOM finds on the same mesh.
program test_finite_paper
  use raccord_kinds, only: wp
  use raccord_check, only: failure_t, new_test, run_tests, check
  use raccord_error, only: error_t
  use raccord_scene_runner, only: scene_run_t, run_deck
  use raccord_strings, only: str
  implicit none

  real(wp), parameter :: T_MAX = 2.0e-5_wp     !< maximum indentation (input/paper/make_decks.sh)
  character(len=*), parameter :: FINITE_DECK = 'input/paper/finite_coarse_mortar_p1_slave_block.nml'
  character(len=*), parameter :: SMALL_DECK = 'input/paper/reg_mortar_p1_slave_block.nml'
  !> CalculiX 2.20, the same coarse mesh, node-to-surface, slave = block
  !> (tools/calculix/fig1b-ccx.sh and finite-ccx.sh with
  !> input/paper/paper_q4_coarse.msh): disc-top reaction 2562.2 N/mm small,
  !> 3230.6 N/mm with NLGEOM and neo-Hooke bodies (ratio 1.261); peak
  !> contact pressure 3437.8 and 4807.9 MPa (ratio 1.399). An independent
  !> code's ratios, not raccord's own numbers: raccord measured 1.257 and
  !> 1.416 (Release). The force ratio is asserted within 0.02 (1.6 %), the
  !> peak ratio, a single nodal value on a coarse mesh with two different
  !> contact discretisations, within 0.05; small strain twice (ratio 1)
  !> or a finite kernel with a wrong modulus would fail both.
  real(wp), parameter :: CCX_FORCE_RATIO = 1.261_wp, CCX_PEAK_RATIO = 1.399_wp
  real(wp), parameter :: FORCE_TOL = 0.02_wp, PEAK_TOL = 0.05_wp

  call run_tests('finite_paper', [ &
    new_test('finite strain at maximum indentation: the support carries the contact force', test_equilibrium), &
    new_test('finite strain raises force and peak pressure as CalculiX NLGEOM does', test_against_small), &
    new_test('finite strain over the whole cycle: energy account, contact gives no energy', test_cycle)])

contains

  !> Vertical contact force on the slave (block) and the reaction of the
  !> support 'block_bottom' at the end of `run`.
  subroutine forces(run, fy, ry)
    type(scene_run_t), intent(in) :: run
    real(wp), intent(out) :: fy, ry
    integer :: j, k
    fy = abs(run%pairs(1)%force(2))
    ry = 0.0_wp
    do k = 1, size(run%model%supports)
      if (run%model%supports(k)%set /= 'block_bottom') cycle
      do j = 1, run%model%ncdof
        if (run%model%cdof_support(j) == k .and. run%model%cdof_comp(j) == 2) ry = ry + run%state%reaction(j)
      end do
    end do
  end subroutine forces

  !> Quasi-static at T: the layer's support reaction equals the contact
  !> force on its top within 2e-3 (the layer's inertia and damping force
  !> are small: measured 1.4e-4 here, 8e-5 in small strain), and the run neither
  !> inverted an element (the runner stops with exit 3) nor left a
  !> multiplier step unconverged.
  subroutine test_equilibrium(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(scene_run_t), allocatable :: run
    type(error_t) :: err
    real(wp) :: fy, ry, ratio
    allocate(run)
    call run_deck(FINITE_DECK, run, err, t_stop=T_MAX)
    call check(failure, .not. err%failed(), 'finite run to T failed: ' // err%message)
    if (allocated(failure)) return
    call forces(run, fy, ry)
    ratio = run%state%energy%kinetic/run%state%energy%internal
    print '(a)', '  finite, t = ' // str(run%state%time, 5) // ': contact force ' // str(fy, 6) // &
      ' N/mm, block bottom reaction ' // str(ry, 6) // ' N/mm (relative difference ' // &
      str(abs(fy - ry)/fy, 3) // '), KE/IE ' // str(ratio, 3) // ', dt / planned ' // &
      str(run%state%dt/run%plan%dt, 3)
    call check(failure, abs(fy - ry) < 2.0e-3_wp*fy, 'contact force ' // str(fy) // ' against support reaction ' // str(ry))
    call check(failure, ratio < 1.0e-3_wp, 'not quasi-static at T: KE/IE = ' // str(ratio))
    call check(failure, run%pairs(1)%failed_total == 0, 'unconverged multiplier steps')
  end subroutine test_equilibrium

  !> Finite over small at T: contact force and peak pressure (the mortar
  !> multiplier over its tributary length, `pressure`, as CalculiX's CSTR
  !> of node-to-surface contact) against CalculiX's ratios.
  subroutine test_against_small(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(scene_run_t), allocatable :: run
    type(error_t) :: err
    real(wp) :: fy(2), ry, pk(2), rf, rp
    integer :: k
    character(len=*), parameter :: decks(2) = [character(len=64) :: SMALL_DECK, FINITE_DECK]
    do k = 1, 2
      allocate(run)
      call run_deck(trim(decks(k)), run, err, t_stop=T_MAX)
      call check(failure, .not. err%failed(), trim(decks(k)) // ' failed: ' // err%message)
      if (allocated(failure)) return
      call forces(run, fy(k), ry)
      pk(k) = maxval(run%pairs(1)%pressure)
      deallocate(run)
    end do
    rf = fy(2)/fy(1)
    rp = pk(2)/pk(1)
    print '(a)', '  contact force small ' // str(fy(1), 6) // ', finite ' // str(fy(2), 6) // ' N/mm: ratio ' // &
      str(rf, 4) // ' (CalculiX ' // str(CCX_FORCE_RATIO, 4) // '); peak pressure ' // str(pk(1), 6) // ', ' // &
      str(pk(2), 6) // ' MPa: ratio ' // str(rp, 4) // ' (CalculiX ' // str(CCX_PEAK_RATIO, 4) // ')'
    call check(failure, abs(rf - CCX_FORCE_RATIO) < FORCE_TOL, 'force ratio finite/small ' // str(rf) // &
      ', CalculiX ' // str(CCX_FORCE_RATIO))
    call check(failure, abs(rp - CCX_PEAK_RATIO) < PEAK_TOL, 'peak pressure ratio finite/small ' // str(rp) // &
      ', CalculiX ' // str(CCX_PEAK_RATIO))
  end subroutine test_against_small

  !> Down and back: the energy account of the finite bodies (stored energy
  !> W, damping and contact work) balances to 1e-5 of the energy scale
  !> (measured: worst 7.3e-7 over the run; with a nonlinear W the
  !> trapezoidal work of the internal force matches W only to O(dt^2), not
  !> to round-off as in small strain, where the paper tests assert 1e-10;
  !> a wrong stored energy or force is off by far more), contact never
  !> gives the bodies more than 1e-5 of the peak internal energy (measured
  !> -6.8e-7; the same deck on the fine mesh, input/paper/
  !> finite_mortar_p1_slave_block.nml, gave 1.1e-2 of the energy scale
  !> through far nodes closed on slivers of the overlap, now 1.5e-5: doc/
  !> theory-contact-mortar.md section 7), and the layer, unloaded, gives back its stored energy (less
  !> than 1e-2 of the peak left at the end; measured 3e-5).
  subroutine test_cycle(failure)
    type(failure_t), allocatable, intent(out) :: failure
    type(scene_run_t), allocatable :: run
    type(error_t) :: err
    allocate(run)
    call run_deck(FINITE_DECK, run, err)
    call check(failure, .not. err%failed(), 'finite run of the cycle failed: ' // err%message)
    if (allocated(failure)) return
    print '(a)', '  cycle: worst balance ' // str(run%worst_balance, 3) // ' of the energy scale, contact work min ' // &
      str(run%min_contact_work/run%max_internal, 3) // ' and end ' // str(run%state%energy%contact/run%max_internal, 3) // &
      ' of the peak internal energy ' // str(run%max_internal, 5) // ', internal at the end ' // &
      str(run%state%energy%internal/run%max_internal, 3) // ' of it; ' // str(run%state%step) // ' steps'
    call check(failure, run%worst_balance < 1.0e-5_wp, 'energy balance ' // str(run%worst_balance))
    call check(failure, run%min_contact_work > -1.0e-5_wp*run%max_internal, &
      'contact gave the bodies more than 1e-5 of the peak internal energy')
    call check(failure, run%state%energy%internal < 1.0e-2_wp*run%max_internal, &
      'the unloaded layer kept ' // str(run%state%energy%internal/run%max_internal) // ' of its peak energy')
    call check(failure, run%pairs(1)%failed_total == 0, 'unconverged multiplier steps')
  end subroutine test_cycle
end program test_finite_paper
