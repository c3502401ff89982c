!> The scene: everything a run is asked to do, as read from the deck.
!>
!> The deck is a file of Fortran namelist groups (doc/user-guide.md lists
!> every key with its unit); raccord_deck fills this type and checks each
!> value on its own; checks that need the mesh (set names, element types)
!> are made when the model is built.
!>
!> Units are consistent and chosen by the user; the examples use mm, s, N,
!> MPa and t/mm^3 (tonne per cubic millimetre), so that N = t mm / s^2.
module raccord_scene
  use raccord_kinds, only: wp, name_len, path_len
  use raccord_material, only: KIN_SMALL, MAT_LINEAR, VOL_AUTO
  use raccord_strings, only: str
  implicit none
  private

  integer, parameter, public :: MAX_TABLE = 256   !< most points of an amplitude table

  !> &run: what the run is called, where results go, and when it stops to
  !> write a checkpoint (doc/hpc.md, section 10).
  type, public :: run_spec_t
    character(len=:), allocatable :: title
    character(len=:), allocatable :: output_dir     !< folder for results and log (resolved)
    real(wp) :: wall_clock = 0.0_wp                 !< wall seconds before checkpoint and exit 5; 0 = none
    integer :: checkpoint_every = 0                 !< steps between checkpoints; 0 = none
  end type run_spec_t

  !> &mesh: the mesh file.
  type, public :: mesh_spec_t
    character(len=:), allocatable :: file           !< path, resolved against the deck's folder
    character(len=:), allocatable :: format         !< 'auto', 'gmsh' or 'abaqus'
    real(wp) :: scale = 1.0_wp                      !< factor applied to coordinates on reading
  end type mesh_spec_t

  !> &body: one deformable body made of the elements of one element set.
  type, public :: body_spec_t
    character(len=:), allocatable :: name
    character(len=:), allocatable :: elset          !< element set (Gmsh physical surface, Abaqus ELSET)
    real(wp) :: young = 0.0_wp                      !< E [stress]
    real(wp) :: poisson = 0.0_wp                    !< nu [-]
    real(wp) :: density = 0.0_wp                    !< rho [mass/length^3]
    logical :: plane_stress = .false.               !< hypothesis = 'plane_stress' (default plane strain)
    !> hypothesis = 'axisymmetric': x is the radius r >= 0, y the axis;
    !> forces are totals over 2 pi (doc/theory-axisymmetric.md)
    logical :: axisymmetric = .false.
    integer :: kinematics = KIN_SMALL               !< kinematics = 'small' | 'finite' (raccord_material)
    integer :: material = MAT_LINEAR                !< material = 'linear_elastic' | 'neo_hooke' | 'svk' | 'j2'
    integer :: volumetric = VOL_AUTO                !< volumetric = 'auto' | 'full' | 'mean_dilatation'
    real(wp) :: yield_stress = 0.0_wp               !< material = 'j2': initial yield stress [stress]
    real(wp) :: hardening = 0.0_wp                  !< material = 'j2': linear isotropic hardening H [stress]
    real(wp) :: thickness = 1.0_wp                  !< out-of-plane thickness [length]
    real(wp) :: velocity(2) = 0.0_wp                !< initial velocity [length/time]
    real(wp) :: body_force(2) = 0.0_wp              !< force per unit volume [force/length^3]
    real(wp) :: damping = -1.0_wp                   !< mass-proportional alpha [1/time]; the &time
                                                    !< damping when not given (resolved on reading)
  end type body_spec_t

  integer, parameter, public :: BC_FIXED = 1         !< listed components held at zero
  integer, parameter, public :: BC_DISPLACEMENT = 2  !< listed components follow value*amplitude(t)
  integer, parameter, public :: BC_TRACTION = 3      !< traction vector value*amplitude(t) on a surface
  integer, parameter, public :: BC_PRESSURE = 4      !< pressure (positive pushes inward) on a surface

  !> &boundary: one condition on a node set or surface.
  type, public :: bc_spec_t
    character(len=:), allocatable :: set            !< node set or surface name
    integer :: kind = 0                             !< BC_* above
    logical :: comp(2) = .false.                    !< components concerned (x, y) for fixed/displacement
    real(wp) :: value(2) = 0.0_wp                   !< displacement [length] or traction [stress]
    real(wp) :: pressure = 0.0_wp                   !< pressure [stress]
    character(len=:), allocatable :: amplitude      !< amplitude name, '' for constant 1
  end type bc_spec_t

  !> &amplitude: a piecewise-linear time table, constant beyond its ends.
  type, public :: amplitude_spec_t
    character(len=:), allocatable :: name
    integer :: npoint = 0
    real(wp), allocatable :: t(:), a(:)
  end type amplitude_spec_t

  !> &time: duration, step and damping.
  type, public :: time_spec_t
    real(wp) :: t_end = 0.0_wp                      !< end time [time]
    real(wp) :: dt = 0.0_wp                         !< fixed step [time]; 0 = safety*stable step
    real(wp) :: safety = 0.9_wp                     !< fraction of the stable step used
    real(wp) :: damping = 0.0_wp                    !< default mass-proportional alpha of the bodies [1/time]
    !> Mass scaling (raccord_mass_scaling, doc/scene-reference.md): the step
    !> the run should take [time] (0: none), or that step as a factor of the
    !> unscaled one (0: none); elements whose own safety * stable step is
    !> below it get their density scaled up to reach it.
    real(wp) :: mass_scaling_dt = 0.0_wp
    real(wp) :: mass_scaling_factor = 0.0_wp
    real(wp) :: added_mass_warn = 0.05_wp           !< warn when a body's added mass passes this fraction
    !> quasi-static check of a mass-scaled run: warn when the kinetic energy
    !> passes this fraction of the largest internal energy so far (0: off),
    !> from the time kinetic_check_from * t_end on
    real(wp) :: kinetic_ratio_warn = 0.05_wp
    real(wp) :: kinetic_check_from = 0.5_wp
  end type time_spec_t

  !> &output: what is written, and how often.
  type, public :: output_spec_t
    integer :: frames = 20                          !< number of result frames over the run (plus t=0)
    integer :: history_every = 0                    !< steps between history lines; 0 = about 1000 lines
    real(wp) :: progress_seconds = 10.0_wp          !< wall seconds between progress lines
    logical :: stress = .true.                      !< write nodal stresses in frames
  end type output_spec_t

  integer, parameter, public :: METHOD_NTS = 1      !< node-to-segment matching
  integer, parameter, public :: METHOD_MORTAR = 2   !< mortar (integral) matching
  integer, parameter, public :: MULT_P1 = 1, MULT_P0 = 2, MULT_DUAL = 3

  !> &contact_pair: one slave/master surface pair.
  type, public :: contact_spec_t
    character(len=:), allocatable :: slave, master  !< surface names
    integer :: method = METHOD_NTS
    integer :: multiplier = MULT_P1                 !< mortar multiplier space
    !> mortar: the conditions bear on each multiplier and its own weighted
    !> gap (conditions = 'weighted') instead of the paper's (19) on G1 lambda
    !> and the nodal gap (conditions = 'nodal', the default)
    logical :: weighted = .false.
    !> mortar on 3-node (Q8) slave edges: multipliers on the edges' corner
    !> nodes only (edge_multipliers = 'corners') instead of on every trace
    !> node ('all_nodes', the default); doc/theory-contact-mortar.md, section 1
    logical :: corners = .false.
    !> Mortar, Q8 slave, with friction: the tangential multipliers and
    !> conditions on the corner nodes only, the normal ones on every trace
    !> node (edge_multipliers = 'tangential_corners'; doc/reproduction.md,
    !> "The Q8 stick zigzag: tangential corner multipliers")
    logical :: tcorners = .false.
    real(wp) :: friction = 0.0_wp                   !< Coulomb coefficient mu; 0 = frictionless
    real(wp) :: search_distance = 0.0_wp            !< 0 = automatic (from the surface element sizes)
    !> relative residual of (19) at which the multiplier solve takes an
    !> iterate whose active sets have not settled after 30 iterations
    !> (raccord_solver_conditions, holds_to_roundoff); 1e-12: round-off
    real(wp) :: tolerance = 1.0e-12_wp
    integer :: max_iterations = 200                 !< cap on solver sweeps per step
  end type contact_spec_t

  !> The whole scene.
  type, public :: scene_t
    character(len=:), allocatable :: path           !< deck file
    character(len=:), allocatable :: dir            !< deck's folder (relative paths resolve here)
    type(run_spec_t) :: run
    type(mesh_spec_t) :: mesh
    type(body_spec_t), allocatable :: bodies(:)
    type(bc_spec_t), allocatable :: bcs(:)
    type(amplitude_spec_t), allocatable :: amplitudes(:)
    type(time_spec_t) :: time
    type(output_spec_t) :: output
    type(contact_spec_t), allocatable :: contacts(:)
  end type scene_t

  public :: name_len, path_len, multiplier_name

contains

  !> The deck's spelling of a multiplier space (MULT_*): 'P1', 'P0', 'dual'.
  pure function multiplier_name(multiplier) result(name)
    integer, intent(in) :: multiplier
    character(len=:), allocatable :: name
    select case (multiplier)
    case (MULT_P1)
      name = 'P1'
    case (MULT_P0)
      name = 'P0'
    case (MULT_DUAL)
      name = 'dual'
    case default
      name = 'unknown_' // str(multiplier)
    end select
  end function multiplier_name
end module raccord_scene
