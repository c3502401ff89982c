!> Mass scaling for quasi-static scenes (issue #19, doc/theory.md "Mass
!> scaling"): the elements whose own stable step is below a target get a
!> larger density, so that the run can take the target step.
!>
!> Element e's bound omega_e^2 = lambda_max(Ke, Me) (theory eq. 4.3) scales
!> as 1/rho, so with the target step dt_t and the safety factor s the
!> element needs omega_e^2 <= w2_t = (2 s / dt_t)^2 and its density becomes
!>   rho_e = s_e rho,   s_e = max(1, omega_e^2 / w2_t),                   (MS-1)
!> uniform over the element and lumped as before. Elements already at or
!> above the target keep their mass; the stable step of the scaled model is
!> then dt_t / s and the plan's step dt_t (raccord_time_step).
!>
!> The factors are fixed at the build, from the undeformed mesh. A
!> finite-strain body keeps its variable step: the kernel's current-length
!> estimate uses each element's scaled density, so the step follows the
!> deformation of the scaled system. Its omega_e^2 there is the larger of
!> the exact bound and that estimate at rest (which passes the exact bound
!> on some distorted elements), so the step at rest is the target.
!>
!> Everything that reads model%mass -- the predictor, the contact
!> correction of both matchings with friction (minv_dof, raccord_contact_pair),
!> the kinetic energy -- sees the scaled masses: the energy balance is that
!> of the scaled system. The damping matrix does not change: node i's
!> alpha becomes
!>   alpha_i m_i / m_s,i,   so that C = alpha M (deck masses)               (MS-2)
!> -- with C = alpha M_s a damped body would creep s_e times slower after
!> the load (measured on the paper's unloading, doc/accuracy-cost.md
!> section 14). Body forces are given per unit volume and are not scaled.
module raccord_mass_scaling
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use raccord_kinds, only: wp
  use raccord_error, only: error_t, raise_error, EXIT_INPUT
  use raccord_log, only: log_info, log_warn
  use raccord_strings, only: str
  use raccord_scene, only: scene_t
  use raccord_model, only: model_t
  use raccord_material, only: KIN_FINITE
  use raccord_elastic_block, only: add_lumped_mass, element_eigenvalue_bounds, scale_element_density, &
    finite_w2_at_rest, finite_w2_elements
  implicit none
  private

  public :: apply_mass_scaling, mass_scaling_requested

contains

  !> The scene asks for mass scaling (a target step or a target factor).
  pure logical function mass_scaling_requested(scene)
    type(scene_t), intent(in) :: scene
    mass_scaling_requested = scene%time%mass_scaling_dt > 0.0_wp .or. scene%time%mass_scaling_factor > 0.0_wp
  end function mass_scaling_requested

  !> Scale the densities (MS-1) of the model built unscaled by build_bodies
  !> and rebuild its lumped masses, the bodies' masses and the stable-step
  !> bounds. Before the inverse masses are formed. Does nothing when the
  !> scene does not ask for it. A target step longer than the run, or one
  !> whose density factors overflow, is refused (exit 2) naming the key.
  subroutine apply_mass_scaling(scene, model, err)
    type(scene_t), intent(in) :: scene
    type(model_t), intent(inout) :: model
    type(error_t), intent(inout) :: err
    real(wp), allocatable :: w2e(:), sc(:), mb(:), ones(:), w2f(:), m0(:)
    real(wp) :: w2_target, dt_unscaled
    integer :: ib, k, nb

    if (.not. mass_scaling_requested(scene)) return
    if (.not. (model%w2_bound > 0.0_wp)) return      ! choose_time_step reports it
    dt_unscaled = scene%time%safety*2.0_wp/sqrt(model%w2_bound)
    if (scene%time%mass_scaling_dt > 0.0_wp) then
      model%scaling%dt_target = scene%time%mass_scaling_dt
    else
      model%scaling%dt_target = scene%time%mass_scaling_factor*dt_unscaled
    end if
    if (scene%time%mass_scaling_dt <= 0.0_wp .and. model%scaling%dt_target > scene%time%t_end) then
      call raise_error(err, EXIT_INPUT, 'scene ' // scene%path // ': &time mass_scaling_factor = ' // &
        str(scene%time%mass_scaling_factor) // ' asks for a step of ' // str(model%scaling%dt_target) // &
        ' (that factor times the unscaled step ' // str(dt_unscaled) // '), longer than the run (t_end = ' // &
        str(scene%time%t_end) // '); give a factor of at most ' // str(scene%time%t_end/dt_unscaled, 3) // &
        ' (a quasi-static run takes hundreds of steps or more)')
      return
    end if
    w2_target = (2.0_wp*scene%time%safety/model%scaling%dt_target)**2
    if (.not. (w2_target >= tiny(1.0_wp))) then
      call raise_error(err, EXIT_INPUT, 'scene ' // scene%path // ': &time ' // trim(target_key(scene)) // &
        ': the target step ' // str(model%scaling%dt_target) // ' s is beyond what the density factors ' // &
        '(MS-1) can reach in floating point; give a shorter target step')
      return
    end if
    model%scaling%active = .true.
    model%scaling%w2_target = w2_target
    model%scaling%w2_unscaled = model%w2_bound

    m0 = model%mass
    model%mass = 0.0_wp
    allocate(mb(model%nnode))
    model%w2_bound = 0.0_wp
    model%w2_small = 0.0_wp
    nb = size(model%bodies)
    do ib = 1, nb
      associate (body => model%bodies(ib), spec => scene%bodies(ib))
        body%mass_unscaled = 0.0_wp
        body%mass = 0.0_wp
        body%w2_bound = 0.0_wp
        body%nscaled = 0
        body%scale_max = 1.0_wp
        do k = 1, size(body%blocks)
          associate (blk => body%blocks(k))
            if (allocated(w2e)) deallocate(w2e, sc, ones, w2f)
            allocate(w2e(blk%nel), sc(blk%nel), ones(blk%nel), w2f(blk%nel))
            call element_eigenvalue_bounds(blk, spec%density, w2e)
            ! finite strain: the variable step follows the kernel's own
            ! estimate, which can pass the exact bound on some elements
            if (spec%kinematics == KIN_FINITE) then
              call finite_w2_elements(blk, w2f)
              w2e = max(w2e, w2f)
            end if
            sc = max(1.0_wp, w2e/w2_target)                         ! (MS-1)
            body%nscaled = body%nscaled + count(sc > 1.0_wp)
            if (blk%nel > 0) body%scale_max = max(body%scale_max, maxval(sc))
            ! the block's masses summed alone, unscaled and scaled the same
            ! way, so that an unscaled body shows exactly 0 added mass
            ones = 1.0_wp
            mb = 0.0_wp
            call add_lumped_mass(blk, spec%density, mb, ones)
            body%mass_unscaled = body%mass_unscaled + sum(mb)
            mb = 0.0_wp
            call add_lumped_mass(blk, spec%density, mb, sc)
            body%mass = body%mass + sum(mb)
            model%mass = model%mass + mb
            if (blk%nel > 0) body%w2_bound = max(body%w2_bound, maxval(w2e/sc))
            if (spec%kinematics == KIN_FINITE) then
              call scale_element_density(blk, sc)
              body%w2_bound = max(body%w2_bound, finite_w2_at_rest(blk, model%nnode))
            end if
          end associate
        end do
        if (.not. ieee_is_finite(body%scale_max)) then
          call raise_error(err, EXIT_INPUT, 'scene ' // scene%path // ': &time ' // trim(target_key(scene)) // &
            ': the density factors (MS-1) of body ''' // body%name // ''' overflow for the target step ' // &
            str(model%scaling%dt_target) // ' s; give a shorter target step')
          return
        end if
        model%w2_bound = max(model%w2_bound, body%w2_bound)
        if (spec%kinematics /= KIN_FINITE) model%w2_small = max(model%w2_small, body%w2_bound)
        call log_info('mass_scaling', 'body ''' // body%name // ''': ' // str(body%nscaled) // ' of ' // &
          str(size(body%elems)) // ' elements scaled (density factor up to ' // str(body%scale_max, 4) // &
          '), added mass ' // str(100.0_wp*added_fraction(body%mass, body%mass_unscaled), 4) // ' %')
        if (added_fraction(body%mass, body%mass_unscaled) > scene%time%added_mass_warn) &
          call log_warn('mass_scaling', 'body ''' // body%name // ''': mass scaling adds ' // &
          str(100.0_wp*added_fraction(body%mass, body%mass_unscaled), 4) // ' % to its mass, above the ' // &
          str(100.0_wp*scene%time%added_mass_warn, 4) // ' % of &time added_mass_warn: its inertia ' // &
          'may change the answer; check that the kinetic energy stays small against the internal energy, ' // &
          'or lower mass_scaling_dt / mass_scaling_factor')
      end associate
    end do
    ! (MS-2): the damping matrix stays alpha M of the deck's masses
    where (model%mass > 0.0_wp) model%alpha = model%alpha*(m0/model%mass)
  end subroutine apply_mass_scaling

  !> The key that set the target step, with its value, for messages.
  function target_key(scene) result(s)
    type(scene_t), intent(in) :: scene
    character(len=:), allocatable :: s
    if (scene%time%mass_scaling_dt > 0.0_wp) then
      s = 'mass_scaling_dt = ' // str(scene%time%mass_scaling_dt)
    else
      s = 'mass_scaling_factor = ' // str(scene%time%mass_scaling_factor)
    end if
  end function target_key

  !> (m - m0)/m0, 0 for a massless body.
  pure real(wp) function added_fraction(m, m0) result(f)
    real(wp), intent(in) :: m, m0
    f = 0.0_wp
    if (m0 > 0.0_wp) f = (m - m0)/m0
  end function added_fraction
end module raccord_mass_scaling
