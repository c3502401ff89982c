!> Impact of two identical bars (nu = 0) approaching at +v and -v, for any
!> matching method: the 1D wave solution says contact lasts 2L/c and the bars
!> leave with their velocities exchanged; momentum is conserved; the forward
!> increment closes the gap exactly, so a little kinetic energy is lost at
!> node level, never gained (method brief section 7).
module two_bar_impact
  use raccord_kinds, only: wp
  use raccord_check, only: failure_t, check, check_close
  use raccord_error, only: error_t
  use raccord_mesh, only: mesh_t, ELEM_Q4, find_node_set
  use raccord_scene, only: scene_t
  use raccord_model, only: model_t
  use raccord_time_step, only: time_plan_t
  use raccord_state, only: state_t
  use raccord_central_difference, only: advance_state
  use raccord_contact_pair, only: contact_pair_t
  use raccord_test_meshes, only: rect_mesh
  use dynamics_support, only: add_pair, contact_step, two_body_scene, prepare_contact
  implicit none
  private

  public :: check_two_bar_impact

contains

  !> Bars 10 x 1 (40 elements along, nya and nyb across: 1:1 gives matching
  !> end faces), gap 0.01, v = 0.01 c; slave = the end of bar a.
  subroutine check_two_bar_impact(failure, method, multiplier, nya, nyb)
    type(failure_t), allocatable, intent(inout) :: failure
    integer, intent(in) :: method, multiplier, nya, nyb
    real(wp), parameter :: e = 1000.0_wp, rho = 1.0e-6_wp, lx = 10.0_wp, gap0 = 0.01_wp
    type(mesh_t) :: ma, mb, mesh
    type(scene_t) :: scene
    type(model_t) :: model
    type(contact_pair_t), allocatable :: pairs(:)
    type(time_plan_t) :: plan
    type(state_t) :: state
    type(error_t) :: err
    real(wp) :: c, v, t_first, t_last, pen_max, p_total, p_a, ke0, bal_max, mass_a, wc_min
    integer :: ka, kb, i
    integer, allocatable :: a_nodes(:)

    c = sqrt(e/rho)
    v = 0.01_wp*c
    call rect_mesh(ma, ELEM_Q4, 40, nya, lx, 1.0_wp)
    call rect_mesh(mb, ELEM_Q4, 40, nyb, lx, 1.0_wp, x0=lx + gap0)
    call two_body_scene(ma, mb, mesh, scene, e, 0.0_wp, rho, .true., 0.0_wp)
    scene%bodies(1)%velocity = [v, 0.0_wp]
    scene%bodies(2)%velocity = [-v, 0.0_wp]
    scene%time%t_end = gap0/(2.0_wp*v) + 3.0_wp*lx/c
    call add_pair(scene, 'a_right', 'b_left', method, 0.0_wp)
    scene%contacts(1)%multiplier = multiplier
    call prepare_contact(scene, mesh, model, pairs, plan, state, err)
    if (err%failed()) call check(failure, .false., 'setup failed: ' // err%message)
    if (allocated(failure)) return
    ka = find_node_set(mesh, 'a_right')
    kb = find_node_set(mesh, 'b_left')
    a_nodes = [(i, i = 1, ma%nnode)]
    mass_a = sum(model%mass(a_nodes))
    t_first = -1.0_wp
    t_last = -1.0_wp
    pen_max = 0.0_wp
    bal_max = 0.0_wp
    wc_min = 0.0_wp
    ke0 = 0.0_wp
    do
      call contact_step(model, pairs, state, err)
      if (err%failed()) exit
      if (state%step == 0) ke0 = state%energy%kinetic
      ! Penetration at t(n+1): a's right face beyond b's left face.
      pen_max = max(pen_max, maxval(mesh%x(1, mesh%nsets(ka)%nodes) + state%u_next(1, mesh%nsets(ka)%nodes)) - &
        minval(mesh%x(1, mesh%nsets(kb)%nodes) + state%u_next(1, mesh%nsets(kb)%nodes)))
      if (pairs(1)%nactive > 0) then
        if (t_first < 0.0_wp) t_first = state%time
        t_last = state%time
      end if
      bal_max = max(bal_max, abs(state%energy%balance)/state%energy%scale)
      wc_min = min(wc_min, state%energy%contact)
      if (state%step == state%nsteps) exit
      call advance_state(state)
    end do
    call check(failure, .not. err%failed(), 'contact step failed')
    if (allocated(failure)) return
    p_total = sum(model%mass*state%v_mid(1, :))
    p_a = sum(model%mass(a_nodes)*state%v_mid(1, a_nodes))
    write(*, '(a,es10.3,a,f8.4,a,es10.3,a,f8.5,a,es10.3,a,es10.3)') '        penetration max/L ', pen_max/lx, &
      ', duration c/(2L) ', (t_last - t_first)*c/(2.0_wp*lx), ', momentum total/(M v) ', p_total/(mass_a*v), &
      ', bar a final velocity/(-v) ', p_a/(-mass_a*v), ', contact loss/KE0 ', state%energy%contact/ke0, &
      ', balance ', bal_max
    call check(failure, pen_max <= 1.0e-10_wp*lx, 'penetration above round-off')
    call check(failure, abs(p_total) <= 1.0e-9_wp*mass_a*v, 'momentum not conserved')
    call check_close(failure, (t_last - t_first)*c/(2.0_wp*lx), 1.0_wp, 'contact duration / (2L/c)', rel_tol=0.05_wp)
    call check_close(failure, p_a/(-mass_a*v), 1.0_wp, 'bar a leaves with -v (mean)', rel_tol=0.05_wp)
    call check(failure, bal_max < 1.0e-10_wp, 'energy balance not exact: energy created or lost unaccounted')
    call check(failure, wc_min >= -1.0e-12_wp*ke0, 'contact did positive work: energy gained')
    call check(failure, state%energy%contact > 0.0_wp .and. state%energy%contact < 0.1_wp*ke0, &
      'node-level inelastic loss should be small and positive')
  end subroutine check_two_bar_impact
end module two_bar_impact
