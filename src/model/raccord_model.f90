!> The discrete model a run integrates: bodies (blocks of elastic elements),
!> lumped masses, supports (fixed or driven displacement components),
!> surface loads, body forces, initial velocities and damping.
!>
!> Built once from the scene and the mesh by build_model
!> (raccord_model_build); read-only in the time loop.
module raccord_model
  use raccord_kinds, only: wp
  use raccord_elastic_block, only: elastic_block_t
  use raccord_amplitude, only: interpolate_table
  use raccord_threads, only: requested_thread_count
  use raccord_edge_load, only: add_edge_traction, add_edge_traction_axi
  implicit none
  private

  public :: amplitude_at, requested_threads, set_model_threads, follower_load_force

  !> One deformable body: the elements of one element set, one material;
  !> one elastic block per element type present (Q4 and/or Q8).
  type, public :: body_t
    character(len=:), allocatable :: name
    integer, allocatable :: elems(:)                   !< mesh element indices
    type(elastic_block_t), allocatable :: blocks(:)
    real(wp) :: density = 0.0_wp
    real(wp) :: mass = 0.0_wp                          !< total mass (with thickness)
    real(wp) :: w2_bound = 0.0_wp                      !< element bound on omega_max^2
    ! Mass scaling (raccord_mass_scaling): mass is the scaled total.
    real(wp) :: mass_unscaled = 0.0_wp                 !< total mass at the deck's density
    integer :: nscaled = 0                             !< elements whose density was scaled
    real(wp) :: scale_max = 1.0_wp                     !< largest density factor s_e
  end type body_t

  !> Mass scaling of the model (raccord_mass_scaling): the target, and the
  !> unscaled step it replaced.
  type, public :: mass_scaling_t
    logical :: active = .false.
    real(wp) :: dt_target = 0.0_wp                     !< the step the run is to take
    real(wp) :: w2_target = 0.0_wp                     !< omega^2 of an element scaled to it
    real(wp) :: w2_unscaled = 0.0_wp                   !< model w2_bound before scaling
  end type mass_scaling_t

  !> A support: components of a node set held at value*amplitude(t)
  !> (value 0 for a fixed condition). Its constrained degrees of freedom
  !> are listed in model%cdof_* with this support's index.
  type, public :: support_t
    character(len=:), allocatable :: set
    logical :: driven = .false.                        !< displacement condition (not fixed)
    real(wp) :: value(2) = 0.0_wp
    integer :: amplitude = 0                           !< index in model%amplitudes, 0 = constant 1
    integer, allocatable :: nodes(:)                   !< nodes of the set (for mean displacement output)
  end type support_t

  !> A surface load: consistent nodal forces at unit amplitude.
  type, public :: surface_load_t
    character(len=:), allocatable :: set
    integer :: amplitude = 0
    integer, allocatable :: nodes(:)
    real(wp), allocatable :: force(:,:)                !< (2, size(nodes)) at amplitude 1, on the undeformed surface
    !> A pressure on edges of finite-strain bodies follows the surface: its
    !> nodal forces are those of the deformed edges, recomputed every step
    !> (follower_load_force). The edges, as positions in nodes(:) (start,
    !> end, mid; mid 0 on a 2-node edge), which of them follow, and each
    !> edge's thickness (plane bodies).
    logical :: follower = .false.
    logical :: axisymmetric = .false.
    real(wp) :: pressure = 0.0_wp
    integer, allocatable :: edges(:,:)                 !< (3, nedge)
    logical, allocatable :: edge_follows(:)            !< (nedge)
    real(wp), allocatable :: edge_thickness(:)         !< (nedge)
  end type surface_load_t

  !> A time table (copied from the scene).
  type, public :: amplitude_t
    character(len=:), allocatable :: name
    real(wp), allocatable :: t(:), a(:)
  end type amplitude_t

  !> The whole model.
  type, public :: model_t
    integer :: nnode = 0
    integer :: nelem = 0                               !< elements in bodies
    real(wp), allocatable :: x(:,:)                    !< (2, nnode) reference coordinates
    real(wp), allocatable :: mass(:)                   !< lumped nodal mass
    real(wp), allocatable :: minv(:)                   !< 1/mass, 0 on nodes in no body
    real(wp), allocatable :: minv_dof(:,:)             !< (2, nnode) 1/mass per dof, 0 where motion is prescribed
    integer, allocatable :: dof_cdof(:,:)              !< (2, nnode) index in the cdof_* lists, 0 if free
    integer, allocatable :: node_body(:)               !< body of each node (0: none)
    type(body_t), allocatable :: bodies(:)
    type(amplitude_t), allocatable :: amplitudes(:)
    type(support_t), allocatable :: supports(:)
    ! Constrained degrees of freedom, one entry each: node, component, support.
    integer :: ncdof = 0
    integer, allocatable :: cdof_node(:), cdof_comp(:), cdof_support(:)
    type(surface_load_t), allocatable :: loads(:)
    real(wp), allocatable :: f_body(:,:)               !< (2, nnode) body-force nodal forces
    real(wp), allocatable :: v0(:,:)                   !< (2, nnode) initial velocity
    real(wp), allocatable :: alpha(:)                  !< (nnode) mass-proportional damping [1/time], per body
    real(wp) :: w2_bound = 0.0_wp                      !< max over bodies of the element bound
    real(wp) :: w2_small = 0.0_wp                      !< the same over the small-strain bodies only
    type(mass_scaling_t) :: scaling                    !< mass scaling, when the scene asks for it
    !> Threads of the per-node loops (1: serial); set_model_threads sets it
    !> with the blocks' count.
    integer :: nthreads = 1
    ! Active effects: the step loop does only what is switched on here.
    logical :: has_body_force = .false.
    logical :: has_loads = .false.
    logical :: has_damping = .false.
    logical :: has_supports = .false.
    !> Some body is finite strain: its stored energy enters the energy
    !> account and the stable step follows its deformation (variable step).
    logical :: has_finite = .false.
    !> The bodies are axisymmetric (&body hypothesis = 'axisymmetric'): x is
    !> the radius, forces are totals over 2 pi (doc/theory-axisymmetric.md)
    logical :: axisymmetric = .false.
    !> Some body is J2 elastoplastic: its plastic work is a term of the
    !> energy balance, its internal variables part of the state
    logical :: has_plastic = .false.
    !> nodes of finite-strain and j2 bodies (their stored energy replaces 1/2 u' f_int)
    integer, allocatable :: finite_nodes(:)
  end type model_t

contains

  !> Nodal forces f(2, size(ld%nodes)) at amplitude 1 of a surface load
  !> whose pressure follows the surface: the edges of finite-strain bodies
  !> at their deformed place x + u (normal and length, and the radius of an
  !> axisymmetric ring), the others on the undeformed mesh, summed in the
  !> order build_load sums them (so that f equals ld%force at u = 0).
  pure subroutine follower_load_force(ld, x, u, f)
    type(surface_load_t), intent(in) :: ld
    real(wp), intent(in) :: x(:,:), u(:,:)
    real(wp), intent(out) :: f(:,:)
    real(wp) :: xe(2, 3), fe(2, 3)
    integer :: k, j, nen, n
    f = 0.0_wp
    do k = 1, size(ld%edges, 2)
      nen = 2
      if (ld%edges(3, k) > 0) nen = 3
      xe = 0.0_wp
      do j = 1, nen
        n = ld%nodes(ld%edges(j, k))
        xe(:, j) = x(:, n)
        if (ld%edge_follows(k)) xe(:, j) = xe(:, j) + u(:, n)
      end do
      if (ld%axisymmetric) then
        call add_edge_traction_axi(nen, xe, [0.0_wp, 0.0_wp], ld%pressure, fe)
      else
        call add_edge_traction(nen, xe, [0.0_wp, 0.0_wp], ld%pressure, ld%edge_thickness(k), fe)
      end if
      do j = 1, nen
        f(:, ld%edges(j, k)) = f(:, ld%edges(j, k)) + fe(:, j)
      end do
    end do
  end subroutine follower_load_force

  !> Value at time t of the model's amplitude idx (0: the constant 1).
  pure real(wp) function amplitude_at(model, idx, t) result(a)
    type(model_t), intent(in) :: model
    integer, intent(in) :: idx
    real(wp), intent(in) :: t
    if (idx == 0) then
      a = 1.0_wp
    else
      a = interpolate_table(model%amplitudes(idx)%t, model%amplitudes(idx)%a, t)
    end if
  end function amplitude_at

  !> Threads a run asks for: OMP_NUM_THREADS validated and capped at the
  !> available processors (raccord_threads); unset, 1, so that a run, a
  !> test or one case of a sweep never takes every core unasked
  !> (doc/performance.md, "Threading"). Always 1 in a build without OpenMP.
  integer function requested_threads() result(n)
    n = requested_thread_count()
  end function requested_threads

  !> Run the model's loops on n threads (n < 1 counts as 1): the per-node
  !> loops of the time step and the element loops of every block. The
  !> results do not depend on n, bit for bit (raccord_elastic_block,
  !> raccord_central_difference).
  subroutine set_model_threads(model, n)
    type(model_t), intent(inout) :: model
    integer, intent(in) :: n
    integer :: ib, k
    model%nthreads = max(1, n)
    if (.not. allocated(model%bodies)) return
    do ib = 1, size(model%bodies)
      if (.not. allocated(model%bodies(ib)%blocks)) cycle
      do k = 1, size(model%bodies(ib)%blocks)
        model%bodies(ib)%blocks(k)%nthreads = model%nthreads
      end do
    end do
  end subroutine set_model_threads
end module raccord_model
