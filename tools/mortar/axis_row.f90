!> The axis row of axisymmetric mortar contact (diagnostic; doc/
!> theory-contact-mortar.md section 7, "The axis row in P1 and P0"): runs a
!> deck's first contact pair and follows the row of the slave chain node
!> that lies on the axis (reference r = 0) every step:
!>  - whether it is a constraint (its multiplier's overlap weight
!>    len = integral of psi_axis 2 pi r dGamma passes the constraint test),
!>    and how often it is dropped and comes back while other rows exist;
!>  - how often its condition changes between open and closed;
!>  - the range of len, of its nodal ring weight (the row's length,
!>    D_axis = integral of N_axis 2 pi r dGamma) and of G1_jj;
!>  - its contact work W = -lambda (g(x(n+1)) - g(x(n-1)))/2 per step
!>    (the per-row work of tools/mortar/row_work.f90) summed over the run,
!>    its least single step and its least running sum (the most energy
!>    that row has given at any time), against the same for all rows;
!>  - its weighted mean gap g(x(n+1))/len after the contact correction
!>    (least value: how far the axis row's support sinks into the master);
!> and the energy contact has given the bodies (the run's watch).
!>   tools/mortar/build_axis_row.sh BUILD_DIR   (a configured, built tree)
!>   RACCORD_SOURCE_DIR=. ./axis_row ./deck.nml [P1|P0|dual|deck [nodal|weighted|deck [undamped_body]]]
!> (the deck path must start with ./ or /).
program axis_row
  use raccord_kinds, only: wp
  use raccord_error, only: error_t
  use raccord_scene, only: MULT_P1, MULT_P0, MULT_DUAL
  use raccord_central_difference, only: advance_state
  use raccord_scene_runner, only: scene_run_t, prepare_deck, step_predict, step_finish
  use raccord_contact_energy, only: contact_energy_watch_t, watch_contact_energy
  use raccord_multiplier_solver, only: ST_OPEN
  implicit none
  type(scene_run_t), allocatable :: run
  type(error_t) :: err
  type(contact_energy_watch_t) :: watch
  character(len=512) :: path, arg, body
  integer :: mult, j, e, p, c, cax, jax, nstep, npresent, ndrop, nreturn, nflip, nclosed
  logical :: was_present, was_closed, present_now, closed_now, set_mult, set_cond, weighted
  real(wp) :: gm, gp, wj, w_axis, w_all, w_axis_min, w_all_min, lam_max, lam_ax_max, len_lo, len_hi, d_lo, d_hi, &
    g1_lo, g1_hi, gap_lo, rmax, wall_step, seg_len, gap_ax, w_axis_cmin, w_all_cmin
  call get_command_argument(1, path)
  set_mult = .false.; set_cond = .false.; weighted = .false.; mult = MULT_P1; body = ''
  if (command_argument_count() >= 2) then
    call get_command_argument(2, arg)
    set_mult = trim(arg) /= 'deck'
    if (trim(arg) == 'P0') mult = MULT_P0
    if (trim(arg) == 'dual') mult = MULT_DUAL
  end if
  if (command_argument_count() >= 3) then
    call get_command_argument(3, arg)
    set_cond = trim(arg) /= 'deck'
    weighted = trim(arg) == 'weighted'
  end if
  if (command_argument_count() >= 4) call get_command_argument(4, body)
  allocate(run)
  if (set_mult .and. set_cond) then
    call prepare_deck(trim(path), run, err, undamped_body=trim(body), multiplier=mult, weighted=weighted)
  else if (set_mult) then
    call prepare_deck(trim(path), run, err, undamped_body=trim(body), multiplier=mult)
  else if (set_cond) then
    call prepare_deck(trim(path), run, err, undamped_body=trim(body), weighted=weighted)
  else
    call prepare_deck(trim(path), run, err, undamped_body=trim(body))
  end if
  if (err%failed()) stop 'setup'
  ! The slave chain node on the axis: reference r = 0 (to round-off of the
  ! surface's extent).
  associate (sl => run%pairs(1)%slave)
    rmax = maxval(abs(run%model%x(1, sl%node(1:sl%nnode))))
    cax = 0
    do c = 1, sl%nnode
      if (abs(run%model%x(1, sl%node(c))) <= 1.0e-12_wp*rmax) cax = c
    end do
    seg_len = sl%h_min
  end associate
  if (cax == 0) stop 'no slave node on the axis'
  nstep = 0; npresent = 0; ndrop = 0; nreturn = 0; nflip = 0; nclosed = 0
  was_present = .false.; was_closed = .false.
  w_axis = 0.0_wp; w_all = 0.0_wp; w_axis_min = 0.0_wp; w_all_min = 0.0_wp; w_axis_cmin = 0.0_wp; w_all_cmin = 0.0_wp
  lam_max = 0.0_wp; lam_ax_max = 0.0_wp
  len_lo = huge(1.0_wp); len_hi = -huge(1.0_wp); d_lo = huge(1.0_wp); d_hi = -huge(1.0_wp)
  g1_lo = huge(1.0_wp); g1_hi = -huge(1.0_wp); gap_lo = huge(1.0_wp)
  do
    call step_predict(run, err)
    if (.not. err%failed()) call step_finish(run, err)
    if (err%failed()) stop 'run'
    call watch_contact_energy(run%pairs, run%state, watch)
    nstep = nstep + 1
    associate (cs => run%pairs(1)%cs, pr => run%pairs(1))
      jax = 0
      wall_step = 0.0_wp
      do j = 1, cs%m
        gm = 0.0_wp; gp = 0.0_wp
        do e = cs%row_ptr(j), cs%row_ptr(j + 1) - 1
          p = cs%ent_node(e)
          gm = gm + cs%ent_w(e)*dot_product(run%model%x(:, p) + run%state%u_prev(:, p), cs%normal(:, j))
          gp = gp + cs%ent_w(e)*dot_product(run%model%x(:, p) + run%state%u_next(:, p), cs%normal(:, j))
        end do
        wj = -pr%work%lam(j)*(gp - gm)/2.0_wp
        wall_step = wall_step + wj
        lam_max = max(lam_max, abs(pr%work%lam(j)))
        if (cs%snode(j) == cax) then
          jax = j
          gap_ax = gp
          w_axis = w_axis + wj
          w_axis_min = min(w_axis_min, wj)
          lam_ax_max = max(lam_ax_max, abs(pr%work%lam(j)))
        end if
      end do
      w_all = w_all + wall_step
      w_all_min = min(w_all_min, wall_step)
      w_axis_cmin = min(w_axis_cmin, w_axis)
      w_all_cmin = min(w_all_cmin, w_all)
      present_now = jax > 0
      closed_now = .false.
      if (present_now) then
        npresent = npresent + 1
        closed_now = pr%st_c(jax) /= ST_OPEN
        if (closed_now) nclosed = nclosed + 1
        len_lo = min(len_lo, pr%mortar%len(cax)); len_hi = max(len_hi, pr%mortar%len(cax))
        d_lo = min(d_lo, cs%length(jax)); d_hi = max(d_hi, cs%length(jax))
        g1_lo = min(g1_lo, cs%g1(0, jax)); g1_hi = max(g1_hi, cs%g1(0, jax))
        if (pr%mortar%len(cax) > 0.0_wp) gap_lo = min(gap_lo, gap_ax/pr%mortar%len(cax))
      end if
      if (cs%m > 0) then
        if (was_present .and. .not. present_now) ndrop = ndrop + 1
        if (.not. was_present .and. present_now .and. npresent > 1) nreturn = nreturn + 1
      end if
      if (present_now .and. was_present .and. (closed_now .neqv. was_closed)) nflip = nflip + 1
      was_present = present_now
      was_closed = closed_now
    end associate
    if (run%state%step == run%state%nsteps) exit
    call advance_state(run%state)
  end do
  write(*, '(a,i0,a,i0,a,i0,a,i0,a,i0,a,i0)') 'steps ', nstep, ' axis row present ', npresent, ' closed ', nclosed, &
    ' drops ', ndrop, ' returns ', nreturn, ' open/closed changes ', nflip
  write(*, '(a,2es11.3,a,2es11.3,a,2es11.3,a,es10.3)') 'len (int psi 2 pi r) ', len_lo, len_hi, &
    '  D_axis (int N 2 pi r) ', d_lo, d_hi, '  G1_jj ', g1_lo, g1_hi, '  h_min ', seg_len
  write(*, '(a,es11.3,a,es11.3,a,es11.3,a,es11.3)') 'axis row work: sum ', w_axis, ' least step ', w_axis_min, &
    '   all rows: sum ', w_all, ' least step ', w_all_min
  write(*, '(a,es11.3,a,es11.3,a,es11.3)') 'least running sum of the work: axis row ', w_axis_cmin, &
    '  all rows ', w_all_cmin, '  over the scale at the end ', w_axis_cmin/run%state%energy%scale
  write(*, '(a,es11.3,a,es11.3,a,es11.3)') 'max |lam| axis ', lam_ax_max, ' all ', lam_max, &
    '  least mean gap g(n+1)/len of the axis row ', gap_lo
  write(*, '(a,es12.4,a,es12.4,a,es12.4,a,es12.4)') 'worst given/scale ', watch%worst, ' at t ', watch%worst_time, &
    ' given ', watch%worst_given, ' scale at end ', run%state%energy%scale
end program axis_row
