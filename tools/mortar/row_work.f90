!> Per-row contact work of a deck's first contact pair (diagnostic; doc/
!> theory-contact-mortar.md section 9, "The axis"; doc/theory-contact.md
!> section 7): on every step between t_min and t_max whose contact work
!> dW_c is below -threshold, each row j with a multiplier (or a small
!> gap): its node, lambda_j, the weighted gap at the prediction, the row's
!> gap g_j at x(n-1) and x(n+1) and its work
!>   W_j = -lambda_j (g_j(x(n+1)) - g_j(x(n-1)))/2,
!> and for rows of tiny weight (below 1e-3 of the largest) their entries
!> and the local G1 of their slave segments.
!>   tools/mortar/build_row_work.sh BUILD_DIR   (a configured, built tree)
!>   RACCORD_SOURCE_DIR=. ./row_work ./deck.nml [t_min t_max [threshold]]
!> (the deck path must start with ./ or /).
program row_work
  use raccord_kinds, only: wp
  use raccord_error, only: error_t
  use raccord_central_difference, only: advance_state
  use raccord_scene_runner, only: scene_run_t, prepare_deck, step_predict, step_finish
  use raccord_contact_energy, only: contact_energy_watch_t, watch_contact_energy, contact_energy_given
  implicit none
  type(scene_run_t), allocatable :: run
  type(error_t) :: err
  type(contact_energy_watch_t) :: watch
  character(len=512) :: path, arg
  real(wp) :: wc_prev, dwc, gm, gp, wj, tmin, tmax, thr, x(2)
  integer :: j, e, p, i, k
  call get_command_argument(1, path)
  tmin = 0.0_wp; tmax = 1.0e30_wp; thr = 1.0e-9_wp
  if (command_argument_count() >= 3) then
    call get_command_argument(2, arg); read(arg, *) tmin
    call get_command_argument(3, arg); read(arg, *) tmax
  end if
  if (command_argument_count() >= 4) then
    call get_command_argument(4, arg); read(arg, *) thr
  end if
  allocate(run)
  call prepare_deck(trim(path), run, err)
  if (err%failed()) stop 'setup'
  wc_prev = 0.0_wp
  do
    call step_predict(run, err)
    if (.not. err%failed()) call step_finish(run, err)
    if (err%failed()) stop 'run'
    call watch_contact_energy(run%pairs, run%state, watch)
    dwc = run%state%energy%contact - wc_prev
    wc_prev = run%state%energy%contact
    if (run%state%time >= tmin .and. run%state%time <= tmax .and. (dwc < -thr .or. thr < 0)) then
      write(*, '(a,i7,a,es14.6,a,es12.4,a,es12.4,a,es12.4,a,i4)') 'step ', run%state%step, ' t ', run%state%time, &
        ' dWc ', dwc, ' given ', contact_energy_given(run%state, watch), ' scale ', run%state%energy%scale, &
        ' m ', run%pairs(1)%cs%m
      associate (cs => run%pairs(1)%cs, pr => run%pairs(1))
        do j = 1, cs%m
          if (pr%work%lam(j) == 0.0_wp .and. abs(cs%gap_w(j)) > 1e-3) cycle
          gm = 0.0_wp; gp = 0.0_wp
          do e = cs%row_ptr(j), cs%row_ptr(j + 1) - 1
            p = cs%ent_node(e)
            gm = gm + cs%ent_w(e)*dot_product(run%model%x(:, p) + run%state%u_prev(:, p), cs%normal(:, j))
            gp = gp + cs%ent_w(e)*dot_product(run%model%x(:, p) + run%state%u_next(:, p), cs%normal(:, j))
          end do
          wj = -pr%work%lam(j)*(gp - gm)/2.0_wp
          i = cs%snode(j)
          x = 0.0_wp
          if (i <= pr%slave%nnode) x = run%model%x(:, pr%slave%node(i)) + run%state%u(:, pr%slave%node(i))
          write(*, '(a,i3,a,i3,a,2f9.5,a,es11.3,a,es11.3,a,es11.3,a,es11.3,a,es11.3,a,es11.3,a,2f8.4,a,i2)') &
            '  j', j, ' node', i, ' x', x, ' lam', pr%work%lam(j), ' gw', cs%gap_w(j), ' g(n-1)', gm, &
            ' g(n+1)', gp, ' W', wj, ' len', cs%length(j), ' n', cs%normal(:, j), ' st', pr%st_c(j)
        end do
        do j = 1, cs%m
          if (cs%length(j) > 1.0e-3_wp*maxval(cs%length(1:cs%m))) cycle
          if (pr%work%lam(j) == 0.0_wp) cycle
          write(*, '(a,i3,a,es11.3,a,es11.3)') '   small row', j, ' len', cs%length(j), ' D(g1 diag)', cs%g1(0, j)
          do e = cs%row_ptr(j), cs%row_ptr(j + 1) - 1
            p = cs%ent_node(e)
            write(*, '(a,i6,a,es12.4,a,2f10.6,a,es12.4)') '     node', p, ' w', cs%ent_w(e), ' x(n)', &
              run%model%x(:, p) + run%state%u(:, p), ' du(n+1)-(n-1) . n', &
              dot_product(run%state%u_next(:, p) - run%state%u_prev(:, p), cs%normal(:, j))
          end do
          do k = 1, pr%slave%nseg
            if (.not. any(pr%slave%seg(:, k) == pr%slave%node(cs%snode(j)))) cycle
            write(*, '(a,i4,a,3i6)') '     seg', k, ' nodes', pr%slave%seg(1:pr%slave%nen_seg, k)
            do i = 1, pr%slave%nen_seg
              write(*, '(a,3es13.5)') '       g1loc(i,:)', pr%mortar%g1loc(i, 1:pr%slave%nen_seg, k)
            end do
          end do
        end do
      end associate
    end if
    if (run%state%step == run%state%nsteps) exit
    call advance_state(run%state)
  end do
  write(*, '(a,es12.4,a,es12.4,a,es12.4)') 'worst given/scale ', watch%worst, ' at t ', watch%worst_time, &
    ' given ', watch%worst_given
end program row_work
