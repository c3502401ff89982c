!> The paper's test with a plastic layer (issue #14; doc/reproduction.md,
!> "The paper's test with a plastic layer"), on the coarse mesh: the disc
!> pressed 0.1581 mm into the 0.3 mm layer and lifted back, the block J2
!> elastoplastic in small strain (yield stress 700 MPa, linear hardening
!> H = 70 MPa), mortar P1 with the block as slave
!> (input/paper/plastic_coarse_mortar_p1_slave_block.nml). The layer
!> yields at a quarter of the indentation; at full depth it carries less
!> than half the elastic force, and unloaded it keeps a dent. Compared with
!> CalculiX *PLASTIC on the same mesh, and with raccord's own energy account.
program test_plastic_paper
  use raccord_kinds, only: wp
  use raccord_check, only: failure_t, new_test, run_tests, check
  use raccord_error, only: error_t
  use raccord_mesh, only: find_node_set
  use raccord_scene_runner, only: scene_run_t, prepare_deck, step_predict, step_finish
  use raccord_central_difference, only: advance_state
  use raccord_strings, only: str
  implicit none

  real(wp), parameter :: T_MAX = 2.0e-5_wp     !< maximum indentation (input/paper/make_decks.sh)
  character(len=*), parameter :: DECK = 'input/paper/plastic_coarse_mortar_p1_slave_block.nml'
  !> CalculiX 2.20 on the same mesh (paper_q4_coarse.msh): `sh
  !> tools/calculix/plastic-ccx.sh OUT input/paper/paper_q4_coarse.msh`,
  !> static, two steps (load, unload), CPE4 fully integrated, *PLASTIC with
  !> the same yield stress and linear hardening, node-to-surface penalty
  !> contact, slave = block (ccx_numbers.txt): disc-top reaction at full
  !> depth 1098.21 N/mm, peak contact pressure 1108.07 MPa (at the contact
  !> edge, x = -0.4636 mm), block-top u_y at x = 0 after unloading
  !> -0.094227 mm, work of the disc-top force over the cycle 78.851 N mm/mm.
  !> An independent code's values, not raccord's own.
  real(wp), parameter :: CCX_FORCE = 1098.21_wp, CCX_PEAK = 1108.07_wp, CCX_DENT = 0.094227_wp, &
    CCX_WORK = 78.851_wp
  !> Tolerances, from what separates the two models on this mesh, measured
  !> with raccord (doc/reproduction.md): the contact discretisation (mortar
  !> against node-to-segment: force 1.2 %, dent 0.5 %, peak 2.7 %), the
  !> volumetric treatment (raccord's mean dilatation against the full
  !> integration of ccx's bricks: force 3.7 %, dent 2.8 %, peak 1.8 %,
  !> half of each taken), and the dynamics of the explicit run (a 4x
  !> slower load: force 0.4 %, dent 1.0 %, peak 1.8 %); their sums, 3.5 %,
  !> 2.9 % and 5.4 %, rounded to 3.5 %, 3 % and 6 %.
  !> They still catch a wrong law: a yield stress 10 % high moves the force
  !> by 10 %, the residual depth by 6 % and the peak by 9 %; perfect
  !> plasticity (H = 0) moves the force by 5 % and the peak by 10 %.
  real(wp), parameter :: FORCE_TOL = 0.035_wp, DENT_TOL = 0.03_wp, PEAK_TOL = 0.06_wp, WORK_TOL = 0.02_wp

  ! save: the test procedures passed to run_tests use these, and static
  ! storage spares them a trampoline (and the program an executable stack).
  type(scene_run_t), allocatable, save :: run
  type(error_t), save :: err
  real(wp), save :: force_t = 0.0_wp, reaction_t = 0.0_wp, peak_t = 0.0_wp, plastic_t = 0.0_wp, dent = 0.0_wp
  logical, save :: reached_t = .false.

  allocate(run)
  call run_cycle(run, err)
  call run_tests('plastic_paper', [ &
    new_test('at full depth: the layer has yielded; force and peak pressure against CalculiX *PLASTIC', &
      test_full_depth), &
    new_test('after unloading: contact open, a dent at the centre against CalculiX', test_residual), &
    new_test('over the cycle: energy balance with the plastic work, work left in the layer against CalculiX', &
      test_energy)])

contains

  !> Run the deck through the whole cycle, keeping at t = T the contact
  !> force, the reaction of the support, the peak pressure and the plastic
  !> work, and at the end the depth of the dent at x = 0.
  subroutine run_cycle(run, err)
    type(scene_run_t), intent(inout) :: run
    type(error_t), intent(inout) :: err
    integer :: j, k, iset, n, centre
    call prepare_deck(DECK, run, err)
    if (err%failed()) return
    do
      call step_predict(run, err)
      if (err%failed()) return
      call step_finish(run, err)
      if (err%failed()) return
      if (.not. reached_t .and. run%state%time >= T_MAX - 0.5_wp*run%state%dt) then
        reached_t = .true.
        force_t = abs(run%pairs(1)%force(2))
        peak_t = maxval(run%pairs(1)%pressure)
        plastic_t = run%state%energy%plastic
        do k = 1, size(run%model%supports)
          if (run%model%supports(k)%set /= 'block_bottom') cycle
          do j = 1, run%model%ncdof
            if (run%model%cdof_support(j) == k .and. run%model%cdof_comp(j) == 2) &
              reaction_t = reaction_t + run%state%reaction(j)
          end do
        end do
      end if
      if (run%state%step == run%state%nsteps) exit
      call advance_state(run%state)
    end do
    ! the block-top node at x = 0 (the disc's lowest node sits there too,
    ! in another set)
    iset = find_node_set(run%mesh, 'block_top')
    centre = 0
    do k = 1, size(run%mesh%nsets(iset)%nodes)
      n = run%mesh%nsets(iset)%nodes(k)
      if (abs(run%mesh%x(1, n)) < 1.0e-9_wp .and. abs(run%mesh%x(2, n)) < 1.0e-9_wp) centre = n
    end do
    if (centre > 0) dent = -run%state%u(2, centre)
  end subroutine run_cycle

  subroutine test_full_depth(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call check(failure, .not. err%failed(), 'the plastic run failed: ' // err%message)
    if (allocated(failure)) return
    call check(failure, reached_t, 'the run never reached t = T')
    print '(a)', '  t = T: block bottom reaction ' // str(reaction_t, 6) // ' N/mm (CalculiX ' // str(CCX_FORCE, 6) // &
      ', ' // str(reaction_t/CCX_FORCE - 1.0_wp, 3) // '), contact force ' // str(force_t, 6) // &
      '; peak pressure ' // str(peak_t, 6) // ' MPa (CalculiX ' // str(CCX_PEAK, 6) // ', ' // &
      str(peak_t/CCX_PEAK - 1.0_wp, 3) // '); plastic work ' // str(plastic_t, 5)
    ! Quasi-static: the support carries the contact force. The contact
    ! force rings by +-0.5 % from step to step (the disc, undamped, is
    ! driven rigidly from its top; measured 1081.5-1093.6 N/mm over the 30
    ! steps about T, 6.8e-3 off the reaction at the step taken), the
    ! support reaction drifts smoothly (1090.1 to 1086.6): it is the force
    ! compared with CalculiX's static disc-top reaction.
    call check(failure, abs(force_t - reaction_t) < 1.0e-2_wp*force_t, 'contact force ' // str(force_t) // &
      ' against support reaction ' // str(reaction_t))
    call check(failure, plastic_t > 0.0_wp, 'no plastic work at full depth')
    call check(failure, abs(reaction_t/CCX_FORCE - 1.0_wp) < FORCE_TOL, 'force at full depth ' // str(reaction_t) // &
      ', CalculiX ' // str(CCX_FORCE))
    call check(failure, abs(peak_t/CCX_PEAK - 1.0_wp) < PEAK_TOL, 'peak pressure at full depth ' // str(peak_t) // &
      ', CalculiX ' // str(CCX_PEAK))
  end subroutine test_full_depth

  subroutine test_residual(failure)
    type(failure_t), allocatable, intent(out) :: failure
    call check(failure, .not. err%failed(), 'the plastic run failed: ' // err%message)
    if (allocated(failure)) return
    print '(a)', '  end: dent at x = 0 ' // str(dent, 6) // ' mm (CalculiX ' // str(CCX_DENT, 6) // ', ' // &
      str(dent/CCX_DENT - 1.0_wp, 3) // '); ' // str(run%pairs(1)%nactive) // ' active contact nodes, force ' // &
      str(abs(run%pairs(1)%force(2)), 3) // ' N/mm'
    call check(failure, run%pairs(1)%nactive == 0 .and. abs(run%pairs(1)%force(2)) == 0.0_wp, &
      'contact still closed after the disc went back up')
    call check(failure, dent > 0.0_wp, 'no residual indentation after unloading')
    call check(failure, abs(dent/CCX_DENT - 1.0_wp) < DENT_TOL, 'residual indentation ' // str(dent) // &
      ', CalculiX ' // str(CCX_DENT))
  end subroutine test_residual

  !> The energy account of the explicit run closes with the plastic work
  !> as its own term (worst balance over the run below 1e-4 of the energy
  !> scale: measured 1.2e-7); contact never gives the bodies more than 1e-5
  !> of the peak internal energy (measured 7.3e-7; 2.0e-3 before the
  !> mortar rows of nodes whose multiplier barely meets the overlap were
  !> dropped: a block-top node far from the disc closed with a multiplier
  !> of 4e12 and the contact work fell by 0.22 N mm in one step,
  !> doc/theory-contact-mortar.md section 7); and the work,
  !> the plastic work plus what the layer still stores (residual stresses)
  !> and its kinetic energy, equals CalculiX's work of the disc-top force
  !> over the cycle within 2 % (measured 0.4 %; a 4x slower load moves it
  !> by 0.9 %). This last check is of the account, not of the law: the
  !> work of a displacement-driven cycle hardly depends on it (H = 0 moves
  !> it by 1.5 %, a yield stress 10 % high by 0.3 %); a plastic work that
  !> missed or doubled a term of the dissipation would not pass.
  subroutine test_energy(failure)
    type(failure_t), allocatable, intent(out) :: failure
    real(wp) :: left
    call check(failure, .not. err%failed(), 'the plastic run failed: ' // err%message)
    if (allocated(failure)) return
    associate (e => run%state%energy)
      left = e%plastic + e%internal + e%kinetic
      print '(a)', '  cycle: worst balance ' // str(run%worst_balance, 3) // '; plastic work ' // &
        str(e%plastic, 5) // ' of ' // str(e%external, 5) // ' external, damping ' // str(e%damping, 4) // &
        ', contact ' // str(e%contact, 3) // ' (min ' // str(run%min_contact_work/run%max_internal, 3) // &
        ' of the peak internal energy); left in the layer ' // &
        str(left, 5) // ' (CalculiX work of the cycle ' // str(CCX_WORK, 5) // ', ' // &
        str(left/CCX_WORK - 1.0_wp, 3) // ')'
      call check(failure, run%worst_balance < 1.0e-4_wp, 'energy balance ' // str(run%worst_balance))
      call check(failure, e%plastic > plastic_t .and. plastic_t > 0.0_wp, 'plastic work not positive and growing')
      call check(failure, run%min_contact_work > -1.0e-5_wp*run%max_internal, 'contact gave the bodies ' // &
        str(-run%min_contact_work) // ', more than 1e-5 of the peak internal energy ' // str(run%max_internal))
      call check(failure, abs(left/CCX_WORK - 1.0_wp) < WORK_TOL, 'work left in the layer ' // str(left) // &
        ', CalculiX ' // str(CCX_WORK))
    end associate
    call check(failure, run%pairs(1)%failed_total == 0, 'unconverged multiplier steps')
  end subroutine test_energy
end program test_plastic_paper
