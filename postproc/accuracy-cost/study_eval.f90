!> Errors of one case of the accuracy-cost study (tools/accuracy-cost.sh,
!> doc/accuracy-cost.md) against its closed form or reference run. Prints
!> `key value` lines on stdout (the script keeps them as CASEDIR/eval.txt).
!>
!>   raccord_study_eval hertz    CASEDIR T_LOAD [REFDIR]
!>   raccord_study_eval cattaneo CASEDIR
!>   raccord_study_eval patch    CASEDIR
!>   raccord_study_eval paper    CASEDIR REFDIR
!>   raccord_study_eval ccx      PRESSUREFILE REFDIR
!>
!> CASEDIR holds a finished run with stem `case` (case.contact1.txt,
!> case.history.txt, case.scene.nml). The normal contact stress compared is
!> lambda_n for mortar (the multiplier is the pressure of the mixed
!> formulation) and the `pressure` output for node-to-segment (nodal force
!> over tributary length); the tangential one is the `shear` output for both
!> (lambda_t of mortar alternates node to node in the stick zone,
!> doc/verification.md section 12). Each is read as the piecewise-linear
!> field through the slave nodes.
!> Closed forms (method brief section 7), plane strain, identical bodies
!> (E = 200000 MPa, nu = 0.3, R = 10 mm, as the study's decks):
!>   1/E* = 2 (1 - nu^2)/E, a = sqrt(4 P R/(pi E*)), p0 = 2 P/(pi a),
!>   p(x) = p0 sqrt(1 - x^2/a^2);
!>   Cattaneo-Mindlin, mu = 0.3: c = a sqrt(1 - Q/(mu P)),
!>   q(x) = mu p(x) - [|x| < c] mu p0 (c/a) sqrt(1 - x^2/c^2).
program study_eval
  use study_profile, only: wp, pi, NGRID, profile_t, history_t, read_profile, read_xy_profile, read_history, &
    history_value, history_row_at, interp, zero_crossing_half_width, l2_distance, l2_norm_grid, fail
  implicit none

  real(wp), parameter :: YOUNG = 200000.0_wp, POISSON = 0.3_wp, RADIUS = 10.0_wp, MU = 0.3_wp
  real(wp), parameter :: Q_APPLIED = 1200.0_wp   !< Cattaneo: 60 MPa on the 20 mm top
  real(wp), parameter :: P_PATCH = 10.0_wp       !< patch test: uniform pressure, MPa
  character(len=1024) :: mode, arg2, arg3, arg4
  integer :: nargs

  nargs = command_argument_count()
  if (nargs < 2) call fail('usage: raccord_study_eval hertz|cattaneo|patch|paper|ccx CASEDIR|FILE [T_LOAD|REFDIR] [REFDIR]')
  call get_command_argument(1, mode)
  call get_command_argument(2, arg2)
  arg3 = ''
  arg4 = ''
  if (nargs >= 3) call get_command_argument(3, arg3)
  if (nargs >= 4) call get_command_argument(4, arg4)
  select case (trim(mode))
  case ('hertz')
    if (nargs < 3) call fail('hertz needs CASEDIR T_LOAD [REFDIR]')
    call eval_hertz(trim(arg2), trim(arg3), trim(arg4))
  case ('cattaneo')
    call eval_cattaneo(trim(arg2))
  case ('patch')
    call eval_patch(trim(arg2))
  case ('paper', 'ccx')
    if (nargs < 3) call fail(trim(mode) // ' needs a reference folder REFDIR')
    call eval_paper(trim(mode), trim(arg2), trim(arg3))
  case default
    call fail('unknown problem "' // trim(mode) // '" (hertz, cattaneo, patch, paper, ccx)')
  end select

contains

  subroutine put(key, v)
    character(len=*), intent(in) :: key
    real(wp), intent(in) :: v
    write(*, '(a,1x,es14.6)') key, v
  end subroutine put

  pure subroutine hertz_closed_form(p_load, a, p0)
    real(wp), intent(in) :: p_load
    real(wp), intent(out) :: a, p0
    real(wp) :: e_star
    e_star = YOUNG/(2.0_wp*(1.0_wp - POISSON**2))
    a = sqrt(4.0_wp*p_load*RADIUS/(pi*e_star))
    p0 = 2.0_wp*p_load/(pi*a)
  end subroutine hertz_closed_form

  !> p0 sqrt(1 - x^2/a^2) on the grid over [-xmax, xmax].
  pure subroutine hertz_on_grid(a, p0, xmax, g)
    real(wp), intent(in) :: a, p0, xmax
    real(wp), intent(out) :: g(0:NGRID)
    integer :: k
    real(wp) :: x
    do k = 0, NGRID
      x = -xmax + 2.0_wp*xmax*real(k, wp)/real(NGRID, wp)
      g(k) = p0*sqrt(max(0.0_wp, 1.0_wp - (x/a)**2))
    end do
  end subroutine hertz_on_grid

  !> Relative L2 error, peak and half-width errors of a normal profile
  !> against the Hertz closed form of load p_load.
  subroutine hertz_errors(prof, p_load, a, p0)
    type(profile_t), intent(in) :: prof
    real(wp), intent(in) :: p_load
    real(wp), intent(out) :: a, p0
    real(wp) :: xmax
    real(wp), allocatable :: g(:)
    allocate(g(0:NGRID))
    call hertz_closed_form(p_load, a, p0)
    xmax = 1.5_wp*a
    call hertz_on_grid(a, p0, xmax, g)
    call put('a_exact', a)
    call put('p0_exact', p0)
    call put('err_l2', l2_distance(prof%x, prof%p, g, xmax)/l2_norm_grid(g, xmax))
    call put('err_peak', (maxval(prof%p) - p0)/p0)
    call put('err_halfwidth', (zero_crossing_half_width(prof%x, prof%p) - a)/a)
  end subroutine hertz_errors

  !> Frictionless Hertz under a pressure load ramped over t_load: the
  !> closed form for the applied P; the dynamic error as KE/IE at the end of
  !> the ramp and at the end; the profile change against a reference run.
  subroutine eval_hertz(dir, t_load_text, refdir)
    character(len=*), intent(in) :: dir, t_load_text, refdir
    type(profile_t) :: prof, ref
    type(history_t) :: hist
    real(wp) :: p_load, a, p0, t_load, xmax, ke, ie
    integer :: ios, r
    real(wp), allocatable :: g(:)
    allocate(g(0:NGRID))
    read(t_load_text, *, iostat=ios) t_load
    if (ios /= 0) call fail('hertz: T_LOAD "' // t_load_text // '" is not a number')
    call read_profile(dir // '/case.contact1.txt', prof)
    call read_history(dir // '/case.history.txt', hist)
    p_load = abs(history_value(hist, 'cylinder_top_Fy'))
    call put('load_P', p_load)
    call hertz_errors(prof, p_load, a, p0)
    call put('err_force', (history_value(hist, 'contact1_N') - p_load)/p_load)
    r = history_row_at(hist, t_load)
    ke = history_value(hist, 'kinetic', r)
    ie = history_value(hist, 'internal', r)
    call put('ke_ie_load', ke/max(ie, tiny(1.0_wp)))
    call put('ke_ie_end', history_value(hist, 'kinetic')/max(history_value(hist, 'internal'), tiny(1.0_wp)))
    if (len(refdir) > 0) then
      call read_profile(refdir // '/case.contact1.txt', ref)
      xmax = 1.5_wp*a
      do r = 0, NGRID
        g(r) = interp(ref%x, ref%p, -xmax + 2.0_wp*xmax*real(r, wp)/real(NGRID, wp))
      end do
      call put('change_ref', l2_distance(prof%x, prof%p, g, xmax)/l2_norm_grid(g, xmax))
    end if
  end subroutine eval_hertz

  !> Cattaneo-Mindlin against the closed form of the measured P and Q.
  subroutine eval_cattaneo(dir)
    character(len=*), intent(in) :: dir
    type(profile_t) :: prof
    type(history_t) :: hist
    real(wp) :: p_load, q_load, a, p0, c, xmax, x, s, ch
    integer :: k, n, first, last
    real(wp), allocatable :: g(:)
    allocate(g(0:NGRID))
    call read_profile(dir // '/case.contact1.txt', prof)
    call read_history(dir // '/case.history.txt', hist)
    p_load = abs(history_value(hist, 'contact1_Fy'))
    q_load = abs(history_value(hist, 'contact1_Fx'))
    call put('load_P', p_load)
    call put('load_Q', q_load)
    call hertz_errors(prof, p_load, a, p0)
    call put('err_force', (q_load - Q_APPLIED)/Q_APPLIED)
    c = a*sqrt(max(0.0_wp, 1.0_wp - q_load/(MU*p_load)))
    call put('c_a_exact', c/a)
    ! Tangential traction with the sign of Q, relative L2 error.
    s = sign(1.0_wp, sum(prof%q))
    xmax = 1.5_wp*a
    do k = 0, NGRID
      x = -xmax + 2.0_wp*xmax*real(k, wp)/real(NGRID, wp)
      g(k) = MU*p0*sqrt(max(0.0_wp, 1.0_wp - (x/a)**2))
      if (abs(x) < c) g(k) = g(k) - MU*p0*(c/a)*sqrt(1.0_wp - (x/c)**2)
    end do
    call put('err_l2_shear', l2_distance(prof%x, s*prof%q, g, xmax)/l2_norm_grid(g, xmax))
    ! Stick zone: each edge midway between the outermost stick node and its
    ! (slipping) neighbour: resolution h/2.
    n = size(prof%x)
    first = 0
    last = 0
    do k = 1, n
      if (prof%status(k) /= 1) cycle
      if (first == 0) first = k
      last = k
    end do
    if (first == 0) then
      ch = 0.0_wp
    else
      ch = 0.5_wp*(0.5_wp*(prof%x(last) + prof%x(min(n, last + 1))) - 0.5_wp*(prof%x(first) + prof%x(max(1, first - 1))))
    end if
    call put('c_a', ch/a)
    call put('err_stick', (ch - c)/a)
  end subroutine eval_cattaneo

  !> Patch test: the largest deviation of the nodal pressure from its mean
  !> over the slave nodes, relative to the applied pressure (every node must
  !> be closed). Uniformity, not the value: the `pressure` output is force
  !> per current length, and the upper block's lateral (Poisson) expansion
  !> of 1.95e-5 lowers it uniformly by that much (err_mean).
  subroutine eval_patch(dir)
    character(len=*), intent(in) :: dir
    type(profile_t) :: prof
    type(history_t) :: hist
    real(wp) :: pm
    call read_profile(dir // '/case.contact1.txt', prof)
    call read_history(dir // '/case.history.txt', hist)
    call put('open_nodes', real(count(prof%status == 0), wp))
    pm = sum(prof%p)/real(size(prof%p), wp)
    call put('err_max', maxval(abs(prof%p - pm))/P_PATCH)
    call put('err_l2', sqrt(sum((prof%p - pm)**2)/real(size(prof%p), wp))/P_PATCH)
    call put('err_mean', (pm - P_PATCH)/P_PATCH)
    call put('err_force', (history_value(hist, 'contact1_N') - P_PATCH)/P_PATCH)
  end subroutine eval_patch

  !> The paper's scene (or CalculiX's profile) against the reference run.
  subroutine eval_paper(mode, path, refdir)
    character(len=*), intent(in) :: mode, path, refdir
    type(profile_t) :: prof, ref
    type(history_t) :: hist, href
    real(wp) :: a, pmax, xmax, n_ref, n_h
    integer :: k
    real(wp), allocatable :: g(:)
    allocate(g(0:NGRID))
    call read_profile(refdir // '/case.contact1.txt', ref)
    call read_history(refdir // '/case.history.txt', href)
    n_ref = history_value(href, 'contact1_N')
    if (mode == 'ccx') then
      call read_xy_profile(path, prof)
      n_h = 0.0_wp
      do k = 1, size(prof%x) - 1
        n_h = n_h + 0.5_wp*(prof%p(k) + prof%p(k + 1))*(prof%x(k + 1) - prof%x(k))
      end do
    else
      call read_profile(path // '/case.contact1.txt', prof)
      call read_history(path // '/case.history.txt', hist)
      n_h = history_value(hist, 'contact1_N')
    end if
    a = zero_crossing_half_width(ref%x, ref%p)
    pmax = maxval(ref%p)
    xmax = 1.5_wp*a
    do k = 0, NGRID
      g(k) = interp(ref%x, ref%p, -xmax + 2.0_wp*xmax*real(k, wp)/real(NGRID, wp))
    end do
    call put('a_ref', a)
    call put('pmax_ref', pmax)
    call put('err_l2', l2_distance(prof%x, prof%p, g, xmax)/l2_norm_grid(g, xmax))
    call put('err_peak', (maxval(prof%p) - pmax)/pmax)
    call put('err_halfwidth', (zero_crossing_half_width(prof%x, prof%p) - a)/a)
    call put('err_force', (n_h - n_ref)/n_ref)
  end subroutine eval_paper
end program study_eval
