!> The nodal gaps of the paper's conditions (19) row by row (diagnostic;
!> doc/reproduction.md, "The Q8 stick zigzag: why the corner space gives
!> energy under (19)"). Runs a deck's first contact pair; on every step
!> between t_min and t_max whose contact work dW_c is below -threshold
!> (every step when threshold < 0) it prints, for each row j of the
!> constraint set:
!>   lam      the multiplier lambda_j
!>   F~       the weighted multiplier (G1 lambda)_j, G1 the conditions'
!>            matrix cs%g1 (G1~ of the corner space on 3-node edges)
!>   len      the row's length (ring weight in axisymmetry)
!>   gw*      the row's own weighted gap at the prediction (cs%gap_w)
!>   gn*      its nodal gap (G1^-T g_w*)_j, the quantity (19) holds >= 0
!>   gw-/gw+  the weighted gap at x(n-1) and x(n+1) with this step's rows
!>            (per-entry vector weights where the set has them)
!>   gn-/gn+  the nodal gaps of those; W_c(n) = F . gn(x(n-1))/2
!>   W        the row's work -lambda_j (gw+ - gw-)/2 (negative: given)
!>   st       0 open, 1 stick, 2 slip
!>   G1       the row's band of the conditions' matrix, G1(j-1, j),
!>            G1(j, j), G1(j+1, j) (constraint numbering)
!>   tgt      active rows (frictionless): the weighted gap (19) holds the
!>            row at, sum_o X(o, j) gw+_o with X = G1_OO^-1 G1_OA over the
!>            open rows O and the active A (the solve's N' g_w = 0,
!>            N = [I; -X]: raccord_frictionless_form); gw+ - tgt is 0 to
!>            round-off when the rows are those of the step. Open rows: 0
!> (rows of an open master's end corners have node numbers above the
!> slave's node count) and then each slave node within r < 0.75 with
!> its pointwise gap at x(n+1) to the nearest master node in x, a measure
!> for a flat master along x only, and its lam_n output.
!>   tools/mortar/build_nodal_gap.sh BUILD_DIR   (a configured, built tree)
!>   RACCORD_SOURCE_DIR=. ./nodal_gap ./deck.nml t_min t_max [threshold]
!> (the deck path must start with ./ or /).
program nodal_gap
  use raccord_kinds, only: wp
  use raccord_error, only: error_t
  use raccord_constraint_set, only: G1_MAX_BAND
  use raccord_central_difference, only: advance_state
  use raccord_scene_runner, only: scene_run_t, prepare_deck, step_predict, step_finish
  use raccord_contact_energy, only: contact_energy_watch_t, watch_contact_energy, contact_energy_given
  implicit none
  type(scene_run_t), allocatable :: run
  type(error_t) :: err
  type(contact_energy_watch_t) :: watch
  character(len=512) :: path, arg
  real(wp) :: wc_prev, dwc, tmin, tmax, thr, x(2), xm(2), gpt, dmin
  real(wp), allocatable :: a(:,:), gm(:), gp(:), f(:), b(:,:), g0(:), xz(:,:), aoo(:,:), tgt(:)
  integer, allocatable :: ipiv(:), io(:), iac(:)
  integer :: j, e, p, i, d, m, info, k, kk, q, no, na
  if (command_argument_count() < 3) stop 'usage: nodal_gap ./deck.nml t_min t_max [threshold]'
  call get_command_argument(1, path)
  call get_command_argument(2, arg)
  read(arg, *) tmin
  call get_command_argument(3, arg)
  read(arg, *) tmax
  thr = -1.0_wp
  if (command_argument_count() >= 4) then
    call get_command_argument(4, arg)
    read(arg, *) thr
  end if
  allocate(run)
  call prepare_deck(trim(path), run, err)
  if (err%failed()) stop 'set-up failed'
  wc_prev = 0.0_wp
  do
    call step_predict(run, err)
    if (.not. err%failed()) call step_finish(run, err)
    if (err%failed()) stop 'run failed'
    call watch_contact_energy(run%pairs, run%state, watch)
    dwc = run%state%energy%contact - wc_prev
    wc_prev = run%state%energy%contact
    if (run%state%time >= tmin .and. run%state%time <= tmax .and. (thr < 0.0_wp .or. dwc < -thr)) then
      associate (cs => run%pairs(1)%cs, pr => run%pairs(1))
        m = cs%m
        write(*, '(a,i7,a,es14.6,a,es12.4,a,es12.4,a,es12.4,a,i4)') 'step ', run%state%step, ' t ', &
          run%state%time, ' dWc ', dwc, ' given ', contact_energy_given(run%state, watch), ' scale ', &
          run%state%energy%scale, ' m ', m
        if (allocated(a)) deallocate(a, gm, gp, f, b, ipiv, g0, tgt, io, iac)
        allocate(a(m, m), gm(m), gp(m), f(m), b(m, 3), ipiv(m), g0(m), tgt(m), io(m), iac(m))
        ! The conditions' matrix, dense: a(i, j) = G1(i, j) = g1(i - j, j).
        a = 0.0_wp
        do j = 1, m
          do d = -G1_MAX_BAND, G1_MAX_BAND
            i = j + d
            if (i >= 1 .and. i <= m) a(i, j) = cs%g1(d, j)
          end do
        end do
        do j = 1, m
          gm(j) = 0.0_wp
          gp(j) = 0.0_wp
          do e = cs%row_ptr(j), cs%row_ptr(j + 1) - 1
            p = cs%ent_node(e)
            if (cs%entry_dirs) then
              gm(j) = gm(j) + dot_product(cs%ent_v(:, e), run%model%x(:, p) + run%state%u_prev(:, p))
              gp(j) = gp(j) + dot_product(cs%ent_v(:, e), run%model%x(:, p) + run%state%u_next(:, p))
            else
              gm(j) = gm(j) + cs%ent_w(e)*dot_product(run%model%x(:, p) + run%state%u_prev(:, p), cs%normal(:, j))
              gp(j) = gp(j) + cs%ent_w(e)*dot_product(run%model%x(:, p) + run%state%u_next(:, p), cs%normal(:, j))
            end if
          end do
        end do
        g0 = cs%gap_w(1:m)
        f = matmul(a, pr%work%lam(1:m))
        ! What the active rows are held at: X = G1_OO^-1 G1_OA, tgt_A = X' gw+_O.
        no = 0
        na = 0
        do j = 1, m
          if (pr%st_c(j) == 0) then
            no = no + 1
            io(no) = j
          else
            na = na + 1
            iac(na) = j
          end if
        end do
        tgt = 0.0_wp
        if (no > 0 .and. na > 0) then
          allocate(aoo(no, no), xz(no, na))
          aoo = a(io(1:no), io(1:no))
          xz = a(io(1:no), iac(1:na))
          call dgesv(no, na, aoo, no, ipiv, xz, no, info)
          if (info /= 0) write(*, '(a,i0)') '  (G1_OO singular, dgesv info ', info, ')'
          do k = 1, na
            tgt(iac(k)) = dot_product(xz(:, k), gp(io(1:no)))
          end do
          deallocate(aoo, xz)
        end if
        ! Nodal gaps: G1^T gn = g_w for the three weighted gaps at once.
        b(:, 1) = g0
        b(:, 2) = gm
        b(:, 3) = gp
        a = transpose(a)
        call dgesv(m, 3, a, m, ipiv, b, m, info)
        if (info /= 0) write(*, '(a,i0)') '  (G1 singular, dgesv info ', info, ')'
        do j = 1, m
          i = cs%snode(j)
          x = 0.0_wp
          if (i <= pr%slave%nnode) x = run%model%x(:, pr%slave%node(i)) + run%state%u(:, pr%slave%node(i))
          write(*, '(a,i3,a,i3,a,f8.5,10(a,es10.2),a,i2,a,3es10.2,a,es10.2)') '  j', j, ' nd', i, ' r', x(1), &
            ' lam', pr%work%lam(j), ' F~', f(j), ' len', cs%length(j), ' gw*', g0(j), ' gn*', b(j, 1), &
            ' gw-', gm(j), ' gw+', gp(j), ' gn-', b(j, 2), ' gn+', b(j, 3), &
            ' W', -pr%work%lam(j)*(gp(j) - gm(j))/2.0_wp, ' st', pr%st_c(j), ' G1', cs%g1(-1:1, j), &
            ' tgt', tgt(j)
        end do
        do i = 1, pr%slave%nnode
          k = pr%slave%node(i)
          x = run%model%x(:, k) + run%state%u_next(:, k)
          if (x(1) > 0.75_wp) cycle
          dmin = huge(1.0_wp)
          gpt = 0.0_wp
          do q = 1, pr%master%nnode
            kk = pr%master%node(q)
            xm = run%model%x(:, kk) + run%state%u_next(:, kk)
            if (abs(xm(1) - x(1)) < dmin) then
              dmin = abs(xm(1) - x(1))
              gpt = xm(2) - x(2)
            end if
          end do
          write(*, '(a,i3,a,f8.5,a,es11.3,a,es11.3)') '    node', i, ' r', x(1), ' g(n+1)', gpt, ' lam_n', pr%lam_n(i)
        end do
      end associate
    end if
    if (run%state%step == run%state%nsteps .or. run%state%time > tmax) exit
    call advance_state(run%state)
  end do
  write(*, '(a,es12.4,a,es12.4,a,es12.4)') 'worst given/scale ', watch%worst, ' at t ', watch%worst_time, &
    ' given ', watch%worst_given
end program nodal_gap
