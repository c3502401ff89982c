!> Small-strain Hooke elements, one material and one element type per block
!> (doc/theory-elements.md; method.md section 2 for the lumped mass and the
!> stable step).
!>
!> Hot-loop design (theory section 6). Elements are processed in chunks of
!> chunk_len: gather -> kernel vectorised across the chunk -> scatter, with
!> the per-element data stored chunk-major (element index first inside a
!> chunk) so the kernel streams it with unit stride.
!>
!> Q4 (theory eqs. 6.2-6.5): the small-strain plane kernel, the exact
!> split of the fully integrated stiffness, is raccord_q4_kernel's; the
!> block builds its 11 reals per element, q4(chunk_len, nq4, nchunk)
!> (init_q4_data), and keeps the cold map coefficients geo(6, nel), which
!> serve mass, body force, stiffness and stress.
!>
!> Q8 (theory eq. 6.1): at every Gauss point g, with
!> H = sqrt(w_g detJ h) J^-1 (2x2, 4 reals) and the natural derivatives
!> D_a(g) = dN_a/d(xi, eta), the same for every element,
!>   sqrt(c) grad u = (sum_a u_a D_a^T) H,   sqrt(c) sigma = C : sym(.)
!>   f_a += (sqrt(c) sigma) H^T D_a          (c = w_g detJ h)
!> which is f = K u with K = sum_g c B^T C B (eq. 3.2). The small-strain
!> plane Q8 kernel (raccord_q8_kernel, eqs. 6.6-6.10) computes the same
!> forces by sum factorisation over the tensor 3x3 rule, rebuilding J at the
!> points from the element's coordinates, which it gathers through conn
!> with u from the block's copy of the node coordinates xn (the step is
!> memory-bound at 1e5 elements, doc/performance.md "Q8 element step"), so
!> such a block stores no per-element geometry at all: the element
!> stiffness, masses, body force and stress output rebuild H and c at a
!> point from xn too. The other Q8 kernels (finite strain, j2,
!> axisymmetric) read H stored h(chunk_len, 4, ngp, nchunk) and c(ngp, nel)
!> (store_gauss_maps).
!>
!> Threading (OpenMP, doc/performance.md "Threading"): consecutive chunks
!> form groups (group_len chunks, up to 32, fixed by the element count) and
!> the groups are coloured once at set-up (raccord_colouring) so that the
!> groups of one colour share no node. The internal force and the stress
!> recovery run colour after colour, the groups of a colour shared among
!> the threads, each group's chunks gathered, computed and scattered in
!> order by one thread: no two threads write the same node, and the order
!> in which contributions add up at a node is the colour order, the same for
!> any thread count (serial runs included), so the results are bitwise
!> independent of the thread count. Groups rather than single chunks keep
!> neighbouring chunks together in one pass (the nodes they share stay in
!> cache) while leaving tens of groups per colour to share out.
!> The thread count is the block's nthreads (1 unless set).
!>
!> Fresh forces without a zeroing pass: the first contribution to a node,
!> in the fixed colour order (and, over a model's blocks, in block order),
!> comes from one known group. claim_first_touch records, per group, the
!> nodes it touches first; add_internal_force(..., fresh=.true.) sets those
!> to zero just before the group scatters into them, while they are in
!> cache anyway. That is the same arithmetic as zeroing f first (0 + x = x),
!> so the bits do not change, and it saves a whole pass over f per step.
module raccord_elastic_block
  use raccord_kinds, only: wp
  use raccord_error, only: error_t, raise_error, EXIT_INPUT
  use raccord_strings, only: str
  use raccord_mesh, only: ELEM_Q4, ELEM_Q8, nodes_per_element, element_name
  use raccord_quadrature, only: gauss_legendre
  use raccord_shape, only: shape_quad, node_natural_coords
  use raccord_colouring, only: colour_chunks, chunk_elements
  use raccord_material, only: moduli_t, make_moduli, KIN_SMALL, KIN_FINITE, MAT_LINEAR, MAT_NEO_HOOKE, MAT_SVK, &
    VOL_FULL, VOL_MEAN, MAT_J2, material_name
  use raccord_finite_kernel, only: kernel_finite_q4, kernel_finite_q8, fin_chunk_len
  use raccord_plasticity, only: j2_t, nhist
  use raccord_axi_kernel, only: kernel_axi_q4, kernel_axi_q8
  use raccord_q4_kernel, only: kernel_q4, nq4, q4_bx1, q4_bx2, q4_by1, q4_by2, q4_g1, q4_m11, q4_m12, q4_m22
  use raccord_q8_kernel, only: kernel_q8, gather_q8, scatter_q8
  implicit none
  private

  public :: init_elastic_block, add_internal_force, claim_first_touch, element_stiffness
  public :: add_lumped_mass, add_body_force, max_eigenvalue_bound, add_nodal_stress
  public :: make_finite, init_watch, watch_energy, watch_w2, watch_inverted, finite_w2_at_rest
  public :: make_plastic, init_plastic, settle_plastic, watch_dissipation, reports_energy
  public :: add_nodal_plastic
  public :: element_eigenvalue_bounds, scale_element_density, finite_w2_elements
  public :: make_axisymmetric

  !> Elements per chunk of the internal-force kernel (a multiple of the SIMD width).
  integer, parameter :: chunk_len = fin_chunk_len
  !> Blocks with fewer chunks run on the calling thread only (the same
  !> colour order, so the same bits): a parallel region and the barrier
  !> after each colour cost a few microseconds, the work of 1024 Q4
  !> elements about 40 (doc/performance.md, "Threading").
  integer, parameter :: min_parallel_chunks = 32
  !> Chunks per colouring group: nchunk/group_divisor, within 1..max_group.
  integer, parameter :: max_group = 32, group_divisor = 64
  integer, parameter :: max_nen = 8, max_gp = 9
  !> The kernel of a block, chosen once (make_finite, init_elastic_block):
  !> small-strain Q4 split, small-strain Q8, finite strain (Q4 or Q8),
  !> J2 plasticity (small or finite strain, Q4 or Q8).
  integer, parameter :: KERN_Q4 = 1, KERN_Q8 = 2, KERN_FINITE_Q4 = 3, KERN_FINITE_Q8 = 4
  integer, parameter :: KERN_J2_SMALL_Q4 = 5, KERN_J2_SMALL_Q8 = 6, KERN_J2_FINITE_Q4 = 7, KERN_J2_FINITE_Q8 = 8
  !> J2 plasticity on axisymmetric blocks (small strain, Q4 and Q8)
  integer, parameter :: KERN_J2_AXI_Q4 = 9, KERN_J2_AXI_Q8 = 10
  !> small-strain axisymmetric Q4 and Q8 (make_axisymmetric, raccord_axi_kernel)
  integer, parameter :: KERN_AXI_Q4 = 21, KERN_AXI_Q8 = 22
  !> finite strain on axisymmetric blocks: hyperelastic (23, 24) and J2
  !> (11, 12, in the J2 range) (raccord_finite_axi_kernel)
  integer, parameter :: KERN_FINITE_AXI_Q4 = 23, KERN_FINITE_AXI_Q8 = 24
  integer, parameter :: KERN_J2_FINITE_AXI_Q4 = 11, KERN_J2_FINITE_AXI_Q8 = 12
  !> Q4 map x(xi, eta) = x0 + a xi + b eta + c xi eta (eq. 6.2): geo(1:6, e) =
  !> (a_x, b_x, c_x, a_y, b_y, c_y).
  integer, parameter :: ngeo = 6

  !> One material, one element type, many elements.
  type, public :: elastic_block_t
    integer :: etype = 0                 !< ELEM_Q4 or ELEM_Q8
    integer :: nen = 0                   !< nodes per element
    integer :: ngp = 0                   !< Gauss points per element (4 or 9)
    integer :: nel = 0                   !< number of elements
    integer, allocatable :: conn(:,:)    !< (nen, nel) global node indices
    real(wp) :: young = 0.0_wp, poisson = 0.0_wp, thickness = 1.0_wp
    logical :: plane_stress = .false.
    !> kinematics (KIN_SMALL, KIN_FINITE), material (MAT_*) and volumetric
    !> treatment (VOL_FULL, VOL_MEAN) of the block's body (raccord_material)
    integer :: kinematics = KIN_SMALL, material = MAT_LINEAR, volumetric = VOL_FULL
    type(moduli_t) :: moduli
    type(j2_t) :: j2                     !< yield stress and hardening of a j2 body (make_plastic)
    real(wp) :: density = 0.0_wp         !< reference density rho0 (finite strain: wave speed)
    integer, private :: kernel = 0
    integer, allocatable :: ids(:)       !< mesh element ids (messages), set by the model builder
    !> threads of the element loops (1: serial); set_model_threads sets it
    !> from OMP_NUM_THREADS for a model's blocks
    integer :: nthreads = 1
    real(wp), private :: lam = 0.0_wp    !< in-plane Lame lambda (plane stress: 2 lam mu/(lam + 2 mu))
    real(wp), private :: mu = 0.0_wp     !< shear modulus
    integer, private :: nchunk = 0
    integer, private :: group_len = 1                !< chunks per colouring group
    integer, private :: ncolour = 0
    integer, allocatable, private :: colour_ptr(:)   !< (ncolour + 1) colour c: colour_group(ptr(c):ptr(c+1)-1)
    integer, allocatable, private :: colour_group(:) !< group indices sorted by colour
    !> nodes the k-th group in colour order touches first (claim_first_touch):
    !> zero_node(zero_ptr(k) : zero_ptr(k+1)-1)
    integer, allocatable, private :: zero_ptr(:), zero_node(:)
    real(wp), allocatable, private :: wts(:)         !< (ngp) Gauss weights
    real(wp), allocatable, private :: nref(:,:)      !< (nen, ngp) shape functions at the Gauss points
    real(wp), allocatable, private :: dnref(:,:,:)   !< (2, nen, ngp) natural derivatives at the Gauss points
    real(wp), allocatable, private :: extrap(:,:)    !< (nen, ngp) Gauss point -> node extrapolation
    real(wp), allocatable, private :: gxi(:,:)       !< (2, ngp) natural coordinates of the Gauss points
    ! Q4 only
    real(wp), allocatable, private :: q4(:,:,:)      !< (chunk_len, nq4, nchunk) hot kernel data (eqs. 6.2-6.5)
    integer, private :: q4_shift = 0                 !< axisymmetric Q4: its chunks start at q4(1 + q4_shift, 1, ic)
    real(wp), allocatable, private :: geo(:,:)       !< (ngeo, nel) map coefficients (eq. 6.2), cold
    ! Q8 (and axisymmetric Q4) with a kernel other than the plane small-strain
    ! Q8 one (store_gauss_maps, make_axisymmetric)
    real(wp), allocatable, private :: h(:,:,:,:)     !< (chunk_len, 4, ngp, nchunk) sqrt(c) J^-1, column-major
    real(wp), allocatable, private :: c(:,:)         !< (ngp, nel) w detJ thickness
    !> (2, up to the block's highest node) the small-strain plane Q8 block's
    !> only geometry: a copy of the node coordinates, read through conn by its kernel (raccord_q8_kernel)
    !> and by the set-up and output routines (which rebuild J at a point);
    !> dropped when the block gets another kernel (store_gauss_maps)
    real(wp), allocatable, private :: xn(:,:)
    ! Finite strain only (Q4 and Q8)
    !> (chunk_len, 4, ngp, nchunk) reference geometry of the finite kernel:
    !> Q8, J0^-1 column-major per Gauss point; Q4, the exact split of the
    !> bilinear gradients, grad N_a = b_a + gamma_a grad h (raccord_finite_kernel)
    real(wp), allocatable, private :: pg(:,:,:,:)
    real(wp), allocatable, private :: cw(:,:,:)      !< (chunk_len, ngp, nchunk) c = w det J0 thickness
    real(wp), allocatable, private :: vol0(:,:)      !< (chunk_len, nchunk) reference volume V_e
    real(wp), allocatable, private :: diag(:,:,:)    !< (chunk_len, 4, nchunk) X3 - X1, X4 - X2
    !> (chunk_len, nchunk) 1/rho of each element for the kernel's wave-speed
    !> estimate: 1/rho0, or 1/(s_e rho0) under mass scaling (scale_element_density)
    real(wp), allocatable, private :: rinv(:,:)
    ! Axisymmetric only (Q4 and Q8; make_axisymmetric): h and c above hold
    ! sqrt(c) J^-1 and c = w detJ 2 pi r_g for Q4 too
    !> x is the radius, y the axis; integrals over 2 pi r (doc/theory-axisymmetric.md)
    logical :: axisymmetric = .false.
    real(wp), allocatable, private :: hoop(:,:,:)    !< (chunk_len, ngp, nchunk) sqrt(c)/r_g
    logical, allocatable, private :: on_axis(:,:)    !< (nen, nel) node at r = 0 (u_r held at 0)
    ! Axisymmetric finite strain only (raccord_elastic_block_finite_axi)
    real(wp), allocatable, private :: rr(:,:,:)      !< (chunk_len, ngp, nchunk) 1/R_g
    real(wp), allocatable, private :: hfac(:,:)      !< (chunk_len, nchunk) hoop factor of the step estimate
  end type elastic_block_t

  !> What the finite-strain kernel reports per chunk each step (the caller
  !> owns it, one per block, and reads it after the forces):
  !> stored energy, smallest J and its element, largest omega^2 estimate.
  type, public :: block_watch_t
    real(wp), allocatable :: energy(:), jmin(:), w2(:)
    integer, allocatable :: jmin_el(:)
    real(wp), allocatable :: dissip(:)   !< j2 blocks: plastic work of the step per chunk
    !> j2 blocks, (chunk_len, nchunk): the element's return was plastic at
    !> a Gauss point at the last forces
    logical, allocatable :: active(:,:)
  end type block_watch_t

  !> The internal variables of a j2 block (raccord_plasticity, nhist per
  !> Gauss point, chunk-major like the kernel data), updated in place by
  !> each force evaluation. The caller owns it (one per block, in the run's
  !> state).
  type, public :: block_plastic_t
    real(wp), allocatable :: h(:,:,:,:)   !< (chunk_len, nhist, ngp, nchunk)
    !> (nchunk) small strain, plane: the chunk's internal variables are all
    !> still 0 (never yielded), so the kernel may skip their traffic
    !> (raccord_plastic_kernel); set by init_plastic and the kernel, and
    !> recomputed from h by settle_plastic after h is read back
    logical, allocatable :: virgin(:)
    logical :: track = .false.            !< the block's kernel uses virgin
  end type block_plastic_t

  !> Element-level work: raccord_elastic_block_element.f90 (a submodule).
  !> q4_detj and add_element_stress, private, are called from this module
  !> too; they are defined there because gfortran gives a private procedure
  !> defined here no symbol that a submodule can link to.
  interface
    !> Element stiffness ke(2 nen, 2 nen) = sum_g c B^T C B (theory eq. 3.2),
    !> dof order (x1, y1, x2, y2, ...).
    pure module subroutine element_stiffness(blk, e, ke)
      type(elastic_block_t), intent(in) :: blk
      integer, intent(in) :: e
      real(wp), intent(out) :: ke(:,:)
    end subroutine element_stiffness
    !> m(nnode) += lumped nodal masses (thickness included).
    pure module subroutine add_lumped_mass(blk, density, m, scale)
      type(elastic_block_t), intent(in) :: blk
      real(wp), intent(in) :: density
      !> mass scaling: element e's density times scale(e) (raccord_mass_scaling)
      real(wp), intent(in), optional :: scale(:)
      real(wp), intent(inout) :: m(:)
    end subroutine add_lumped_mass
    !> f(2, nnode) += consistent nodal forces of a constant force per unit
    !> volume b(2) (theory eq. 5.2).
    pure module subroutine add_body_force(blk, b, f)
      type(elastic_block_t), intent(in) :: blk
      real(wp), intent(in) :: b(2)
      real(wp), intent(inout) :: f(:,:)
    end subroutine add_body_force
    !> Per-element bound lambda_max(Ke, Me) of each element (theory eq. 4.3).
    module subroutine element_eigenvalue_bounds(blk, density, w2)
      type(elastic_block_t), intent(in) :: blk
      real(wp), intent(in) :: density
      real(wp), intent(out) :: w2(:)
    end subroutine element_eigenvalue_bounds

    !> Each element's wave-speed estimate omega_e^2 = 4 c^2 / L^2 of the
    !> finite-strain kernel on the undeformed mesh (finite_w2_at_rest is
    !> their largest), with the block's current densities.
    module subroutine finite_w2_elements(blk, w2)
      type(elastic_block_t), intent(in) :: blk
      real(wp), intent(out) :: w2(:)
    end subroutine finite_w2_elements

    !> Mass scaling of a finite-strain block: element e's wave-speed
    !> estimate uses the density scale(e)*rho0 (raccord_mass_scaling).
    module subroutine scale_element_density(blk, scale)
      type(elastic_block_t), intent(inout) :: blk
      real(wp), intent(in) :: scale(:)
    end subroutine scale_element_density

    !> Upper bound of omega_max^2 of the assembled lumped system (theory
    !> eq. 4.3); stable step dt <= 2/sqrt(w2).
    module function max_eigenvalue_bound(blk, density) result(w2)
      type(elastic_block_t), intent(in) :: blk
      real(wp), intent(in) :: density
      real(wp) :: w2
    end function max_eigenvalue_bound
    !> detJ of the Q4 map (eq. 6.2) at (xi, eta).
    pure module function q4_detj(geo, xi, eta) result(detj)
      real(wp), intent(in) :: geo(ngeo), xi, eta
      real(wp) :: detj
    end function q4_detj
    !> The nodal stress contributions of element e (add_nodal_stress).
    pure module subroutine add_element_stress(blk, e, u, s, wsum)
      type(elastic_block_t), intent(in) :: blk
      integer, intent(in) :: e
      real(wp), intent(in) :: u(:,:)
      real(wp), intent(inout) :: s(:,:), wsum(:)
    end subroutine add_element_stress
    !> The nodal Cauchy stress (strain = .false.) or logarithmic strain
    !> contributions of finite-strain element e.
    pure module subroutine add_element_finite(blk, e, u, strain, s, wsum)
      type(elastic_block_t), intent(in) :: blk
      integer, intent(in) :: e
      real(wp), intent(in) :: u(:,:)
      logical, intent(in) :: strain
      real(wp), intent(inout) :: s(:,:), wsum(:)
    end subroutine add_element_finite
    !> The nodal small-strain contributions of small-strain element e.
    pure module subroutine add_element_small_strain(blk, e, u, s, wsum)
      type(elastic_block_t), intent(in) :: blk
      integer, intent(in) :: e
      real(wp), intent(in) :: u(:,:)
      real(wp), intent(inout) :: s(:,:), wsum(:)
    end subroutine add_element_small_strain
    !> H = sqrt(c) J^-1 and c at every Gauss point of a Q8 block (theory
    !> eq. 6.1), stored if h and c are allocated (a plane small-strain Q8
    !> block checks detJ only). Fails (EXIT_INPUT) on detJ <= 0, naming the
    !> element.
    module subroutine init_gauss_maps(blk, x, err)
      type(elastic_block_t), intent(inout) :: blk
      real(wp), intent(in) :: x(:,:)
      type(error_t), intent(inout) :: err
    end subroutine init_gauss_maps
    !> H and c of a Q8 block whose kernel is no longer the plane small-strain
    !> one (make_finite, make_plastic, make_axisymmetric): allocated (if not
    !> yet), filled by init_gauss_maps, and the coordinate copy xn dropped.
    module subroutine store_gauss_maps(blk, x, err)
      type(elastic_block_t), intent(inout) :: blk
      real(wp), intent(in) :: x(:,:)
      type(error_t), intent(inout) :: err
    end subroutine store_gauss_maps
    !> Turn a block set up by init_elastic_block into a finite-strain block
    !> (total Lagrangian, doc/theory-finite.md) of the given material
    !> (MAT_NEO_HOOKE or MAT_SVK) and volumetric treatment (VOL_FULL or
    !> VOL_MEAN), reference density rho0. Plane strain only: plane stress is
    !> refused (EXIT_INPUT). The small-strain data stay: they give the initial
    !> stable step (at F = I both laws have Hooke's tangent).
    module subroutine make_finite(blk, x, material, volumetric, density, err)
      type(elastic_block_t), intent(inout) :: blk
      real(wp), intent(in) :: x(:,:)
      integer, intent(in) :: material, volumetric
      real(wp), intent(in) :: density
      type(error_t), intent(inout) :: err
    end subroutine make_finite
    !> Turn a small-strain block set up by init_elastic_block (thickness 1,
    !> plane strain) into an axisymmetric block: x is the radius r >= 0, y
    !> the axis; every integral carries 2 pi r (doc/theory-axisymmetric.md).
    !> Nodes at r = 0 are the caller's to hold radially (raccord_model_build).
    !> Fails (EXIT_INPUT) on r < 0, naming the element.
    module subroutine make_axisymmetric(blk, x, err)
      type(elastic_block_t), intent(inout) :: blk
      real(wp), intent(in) :: x(:,:)
      type(error_t), intent(inout) :: err
    end subroutine make_axisymmetric
    !> ke += the hoop terms of the axisymmetric element stiffness
    !> (B rows tt with rr, zz, tt), dof order as element_stiffness.
    pure module subroutine axi_hoop_stiffness(blk, e, ke)
      type(elastic_block_t), intent(in) :: blk
      integer, intent(in) :: e
      real(wp), intent(inout) :: ke(:,:)
    end subroutine axi_hoop_stiffness
    !> Zero the rows and columns of the radial dofs of element e's nodes on
    !> the axis (held there, they take no part in the element eigenvalue).
    pure module subroutine axi_drop_axis_dofs(blk, e, ke)
      type(elastic_block_t), intent(in) :: blk
      integer, intent(in) :: e
      real(wp), intent(inout) :: ke(:,:)
    end subroutine axi_drop_axis_dofs
    !> The nodal stress (strain = .false.) or strain contributions of
    !> axisymmetric element e: (rr, zz, rz, tt).
    pure module subroutine add_element_axi(blk, e, u, strain, s, wsum)
      type(elastic_block_t), intent(in) :: blk
      integer, intent(in) :: e
      real(wp), intent(in) :: u(:,:)
      logical, intent(in) :: strain
      real(wp), intent(inout) :: s(:,:), wsum(:)
    end subroutine add_element_axi
    !> Allocate a block's watch (one entry per chunk).
    module subroutine init_watch(blk, watch)
      type(elastic_block_t), intent(in) :: blk
      type(block_watch_t), intent(out) :: watch
    end subroutine init_watch
    !> The finite-strain block's omega^2 estimate on its undeformed mesh
    !> (the kernel's current-length estimate at u = 0), for the plan's step.
    module function finite_w2_at_rest(blk, nnode) result(w2)
      type(elastic_block_t), intent(in) :: blk
      integer, intent(in) :: nnode
      real(wp) :: w2
    end function finite_w2_at_rest
    !> Stored energy of the block at the last forces, summed in chunk order.
    pure module real(wp) function watch_energy(watch) result(w)
      type(block_watch_t), intent(in) :: watch
    end function watch_energy
    !> Largest omega^2 estimate of the block at the last monitored forces.
    pure module real(wp) function watch_w2(watch) result(w2)
      type(block_watch_t), intent(in) :: watch
    end function watch_w2
    !> The block's first inverted element (J <= 0 at a Gauss point) at the
    !> last forces, 0 if none; jmin its smallest J.
    pure module subroutine watch_inverted(watch, e, jmin)
      type(block_watch_t), intent(in) :: watch
      integer, intent(out) :: e
      real(wp), intent(out) :: jmin
    end subroutine watch_inverted
    !> The reference data of the finite-strain and j2 kernels (pg, cw,
    !> vol0, diag; raccord_finite_kernel), from the block's geometry.
    module subroutine init_reference_data(blk, x, err)
      type(elastic_block_t), intent(inout) :: blk
      real(wp), intent(in) :: x(:,:)
      type(error_t), intent(inout) :: err
    end subroutine init_reference_data
    !> Turn a block set up by init_elastic_block into a J2 elastoplastic
    !> block (raccord_plastic_kernel, doc/theory-plasticity.md): small or
    !> finite kinematics, yield stress and hardening j2, volumetric treatment
    !> (VOL_MEAN or VOL_FULL), reference density. Plane stress is refused
    !> (EXIT_INPUT).
    module subroutine make_plastic(blk, x, kinematics, j2, volumetric, density, err)
      type(elastic_block_t), intent(inout) :: blk
      real(wp), intent(in) :: x(:,:)
      integer, intent(in) :: kinematics, volumetric
      type(j2_t), intent(in) :: j2
      real(wp), intent(in) :: density
      type(error_t), intent(inout) :: err
    end subroutine make_plastic
    !> The internal variables of a virgin j2 block.
    module subroutine init_plastic(blk, plastic)
      type(elastic_block_t), intent(in) :: blk
      type(block_plastic_t), intent(out) :: plastic
    end subroutine init_plastic
    !> plastic%virgin from plastic%h, after h was set from outside (a
    !> checkpoint): a chunk is virgin when all its internal variables are 0.
    module subroutine settle_plastic(plastic)
      type(block_plastic_t), intent(inout) :: plastic
    end subroutine settle_plastic
    !> Plastic work of the last forces' step, summed in chunk order.
    pure module real(wp) function watch_dissipation(watch) result(w)
      type(block_watch_t), intent(in) :: watch
    end function watch_dissipation
    !> s(1, nnode) += the mean equivalent plastic strain of each element
    !> after the last return, y(1, nnode) += 1 for the elements whose return
    !> was plastic at a Gauss point then (watch%active); wsum += 1 per
    !> element and node.
    module subroutine add_nodal_plastic(blk, plastic, watch, s, y, wsum)
      type(elastic_block_t), intent(in) :: blk
      type(block_plastic_t), intent(in) :: plastic
      type(block_watch_t), intent(in) :: watch
      real(wp), intent(inout) :: s(:,:), y(:,:), wsum(:)
    end subroutine add_nodal_plastic
    !> One chunk through the block's J2 kernel (raccord_plastic_kernel): the
    !> forces fe, Gauss-point stresses sg, active flags, elastic energy en,
    !> plastic work dis (and for finite strain jm, jel, w2 as the finite
    !> kernel; small strain: jm = 1, jel = 0, w2 = 0) of chunk ic, whose nc
    !> elements' internal variables hist are updated in place.
    pure module subroutine j2_chunk(blk, ic, nc, mon, hist, virgin, ue, fe, sg, act, en, dis, jm, jel, w2)
      type(elastic_block_t), intent(in) :: blk
      integer, intent(in) :: ic, nc
      logical, intent(in) :: mon
      real(wp), intent(inout) :: hist(chunk_len, nhist, *)
      logical, intent(inout) :: virgin
      real(wp), intent(in) :: ue(chunk_len, 2, max_nen)
      real(wp), intent(inout) :: fe(chunk_len, 2, max_nen)
      real(wp), intent(out) :: sg(chunk_len, 4, *), act(chunk_len), en, dis, jm, w2
      integer, intent(out) :: jel
    end subroutine j2_chunk
    !> The nodal stress contributions of the elements of group grp of a j2
    !> block (add_nodal_stress): the kernel's Gauss-point stresses
    !> extrapolated to the nodes.
    module subroutine add_group_j2_stress(blk, grp, u, plastic, s, wsum)
      type(elastic_block_t), intent(in) :: blk
      integer, intent(in) :: grp
      real(wp), intent(in) :: u(:,:)
      type(block_plastic_t), intent(in) :: plastic
      real(wp), intent(inout) :: s(:,:), wsum(:)
    end subroutine add_group_j2_stress
    ! Axisymmetric finite strain (raccord_elastic_block_finite_axi)
    !> The kernel data of an axisymmetric finite-strain or finite j2 block
    !> (after init_reference_data): 1/R_g and the hoop factor of the step.
    module subroutine init_finite_axi(blk, err)
      type(elastic_block_t), intent(inout) :: blk
      type(error_t), intent(inout) :: err
    end subroutine init_finite_axi
    !> One chunk through the axisymmetric finite kernel, as j2_chunk (the
    !> block's law; hist is left alone by the hyperelastic laws).
    pure module subroutine finite_axi_chunk(blk, ic, nc, mon, hist, ue, fe, sg, act, en, dis, jm, jel, w2)
      type(elastic_block_t), intent(in) :: blk
      integer, intent(in) :: ic, nc
      logical, intent(in) :: mon
      real(wp), intent(inout) :: hist(chunk_len, nhist, *)
      real(wp), intent(in) :: ue(chunk_len, 2, max_nen)
      real(wp), intent(inout) :: fe(chunk_len, 2, max_nen)
      real(wp), intent(out) :: sg(chunk_len, 4, *), act(chunk_len), en, dis, jm, w2
      integer, intent(out) :: jel
    end subroutine finite_axi_chunk
    !> The same for a hyperelastic block (no internal variables).
    pure module subroutine finite_axi_elastic_chunk(blk, ic, nc, mon, ue, fe, en, jm, jel, w2)
      type(elastic_block_t), intent(in) :: blk
      integer, intent(in) :: ic, nc
      logical, intent(in) :: mon
      real(wp), intent(in) :: ue(chunk_len, 2, max_nen)
      real(wp), intent(inout) :: fe(chunk_len, 2, max_nen)
      real(wp), intent(out) :: en, jm, w2
      integer, intent(out) :: jel
    end subroutine finite_axi_elastic_chunk
    !> Each element's omega^2 estimate of the axisymmetric finite kernel at
    !> rest (finite_w2_elements of an axisymmetric block).
    module subroutine finite_axi_w2_elements(blk, w2)
      type(elastic_block_t), intent(in) :: blk
      real(wp), intent(out) :: w2(:)
    end subroutine finite_axi_w2_elements
    !> Nodal Cauchy stress (rr, zz, rz, tt) or logarithmic strain of the
    !> elements of group grp of an axisymmetric finite-strain block.
    module subroutine add_group_finite_axi(blk, grp, u, strain, s, wsum)
      type(elastic_block_t), intent(in) :: blk
      integer, intent(in) :: grp
      real(wp), intent(in) :: u(:,:)
      logical, intent(in) :: strain
      real(wp), intent(inout) :: s(:,:), wsum(:)
    end subroutine add_group_finite_axi
    !> s(4, nnode) += (sxx, syy, sxy, szz) of each element extrapolated from
    !> its Gauss points to its nodes (theory eq. 7.1); wsum(nnode) += 1 per
    !> contribution, so s/wsum is the nodal average. szz = nu (sxx + syy) in
    !> plane strain, 0 in plane stress. Threaded as add_internal_force, in
    !> colour order (the same bits for any thread count).
    !> (raccord_elastic_block_stress)
    module subroutine add_nodal_stress(blk, u, s, wsum, strain, plastic)
      type(elastic_block_t), intent(in) :: blk
      real(wp), intent(in) :: u(:,:)
      real(wp), intent(inout) :: s(:,:), wsum(:)
      !> the strain instead (small strain, or logarithmic in finite strain)
      logical, intent(in), optional :: strain
      !> j2 blocks: their internal variables (the stress is the return's from
      !> a copy of them at u); required for their stress
      type(block_plastic_t), intent(in), optional :: plastic
    end subroutine add_nodal_stress
    !> Q4 data of every element: map coefficients (cold) and the kernel's
    !> beta, gamma, M (hot), theory eqs. 6.2-6.5. Fails (EXIT_INPUT) on
    !> detJ <= 0 at a Gauss point, naming the element.
    !> (raccord_elastic_block_q4)
    module subroutine init_q4_data(blk, x, err)
      type(elastic_block_t), intent(inout) :: blk
      real(wp), intent(in) :: x(:,:)
      type(error_t), intent(inout) :: err
    end subroutine init_q4_data
    !> Set up a block: validate the input, tabulate the reference element
    !> and its Gauss rule (2x2 for Q4, 3x3 for Q8, theory section 2), the
    !> stress extrapolation (eq. 7.1), the colouring and first touches, and
    !> the kernel's element data. Errors (EXIT_INPUT): unknown element
    !> type, bad connectivity, bad material, detJ <= 0 at a Gauss point
    !> (naming the element). (raccord_elastic_block_init)
    module subroutine init_elastic_block(blk, etype, conn, x, young, poisson, plane_stress, thickness, err)
      type(elastic_block_t), intent(out) :: blk
      integer, intent(in) :: etype
      integer, intent(in) :: conn(:,:)
      real(wp), intent(in) :: x(:,:)
      real(wp), intent(in) :: young, poisson, thickness
      logical, intent(in) :: plane_stress
      type(error_t), intent(inout) :: err
    end subroutine init_elastic_block
  end interface

contains

  !> Record, for each group in colour order, the nodes of this block that
  !> nobody touched before it: claimed(n) is true for nodes an earlier
  !> group (of this block or of a block claimed before) touches, and is set
  !> here for every node of this block. Over several blocks that share f,
  !> claim them in the order add_internal_force is called on them.
  subroutine claim_first_touch(blk, claimed)
    type(elastic_block_t), intent(inout) :: blk
    logical, intent(inout) :: claimed(:)
    integer, allocatable :: first(:)
    integer :: k, e, e0, e1, a, node, nfirst
    allocate(first(blk%nen*blk%nel))
    if (allocated(blk%zero_ptr)) deallocate(blk%zero_ptr)
    allocate(blk%zero_ptr(size(blk%colour_group) + 1))
    nfirst = 0
    do k = 1, size(blk%colour_group)
      blk%zero_ptr(k) = nfirst + 1
      call chunk_elements(blk%colour_group(k), blk%group_len*chunk_len, blk%nel, e0, e1)
      do e = e0, e1
        do a = 1, blk%nen
          node = blk%conn(a, e)
          if (claimed(node)) cycle
          claimed(node) = .true.
          nfirst = nfirst + 1
          first(nfirst) = node
        end do
      end do
    end do
    blk%zero_ptr(size(blk%colour_group) + 1) = nfirst + 1
    blk%zero_node = first(1:nfirst)
  end subroutine claim_first_touch

  !> f(2, nnode) += K u over the block's elements (theory eq. 6.1).
  !> Gather -> chunk kernel -> scatter; no allocation (chunk buffers are
  !> fixed-size locals, one set per thread). Colour after colour, the groups
  !> of a colour shared among blk%nthreads threads; one parallel
  !> region per call, the implicit barrier at the end of each colour's loop
  !> keeps two colours from overlapping. With fresh = .true. each group
  !> first sets the nodes it claimed (claim_first_touch) to zero, so that
  !> over the blocks claimed together f = K u without zeroing f beforehand
  !> (nodes no block claims are left as they are).
  !> On one thread (or below min_parallel_chunks) the loop runs without a
  !> parallel region: its worksharing directives are orphaned and cost
  !> nothing, where a region with a false `if` still makes a team of one
  !> whose barriers and end each make a futex system call in libgomp.
  subroutine add_internal_force(blk, u, f, fresh, watch, monitor, plastic)
    type(elastic_block_t), intent(in) :: blk
    real(wp), intent(in) :: u(:,:)
    real(wp), intent(inout) :: f(:,:)
    logical, intent(in), optional :: fresh
    !> finite strain and j2: per-chunk energy, smallest J, (with monitor)
    !> omega^2 and plastic work
    type(block_watch_t), intent(inout), optional :: watch
    logical, intent(in), optional :: monitor
    !> j2 blocks: the internal variables, updated by the return (required
    !> for a j2 block)
    type(block_plastic_t), intent(inout), optional :: plastic
    logical :: reset, mon
    reset = .false.
    if (present(fresh)) reset = fresh
    mon = .false.
    if (present(monitor)) mon = monitor
    if (blk%material == MAT_J2 .and. .not. present(plastic)) error stop 'add_internal_force: a j2 block needs its plastic state'
    if (blk%nthreads > 1 .and. blk%nchunk >= min_parallel_chunks) then
      !$omp parallel num_threads(blk%nthreads) default(shared)
      call force_colours(blk, u, f, reset, mon, watch, plastic)
      !$omp end parallel
    else
      call force_colours(blk, u, f, reset, mon, watch, plastic)
    end if
  end subroutine add_internal_force

  !> The colour loop of add_internal_force, run by every thread of the
  !> team (or by the caller alone): the groups of a colour are shared out by
  !> an orphaned `omp do`, whose implicit barrier ends the colour.
  subroutine force_colours(blk, u, f, reset, mon, watch, plastic)
    type(elastic_block_t), intent(in) :: blk
    real(wp), intent(in) :: u(:,:)
    real(wp), intent(inout) :: f(:,:)
    logical, intent(in) :: reset, mon
    type(block_watch_t), intent(inout), optional :: watch
    type(block_plastic_t), intent(inout), optional :: plastic
    real(wp) :: ue(chunk_len, 2, max_nen), fe(chunk_len, 2, max_nen), en, jm, w2, dis
    real(wp) :: sgp(chunk_len, 4, max_gp), act(chunk_len), xe(chunk_len, 2, max_nen)
    integer :: col, k, grp, ic, e0, nc, i, a, node, nen, j, jel
    logical :: watched
    nen = blk%nen
    watched = present(watch)
    dis = 0.0_wp
    colours: do col = 1, blk%ncolour
      !$omp do schedule(static)
      groups: do k = blk%colour_ptr(col), blk%colour_ptr(col + 1) - 1
        grp = blk%colour_group(k)
        if (reset) then
          do j = blk%zero_ptr(k), blk%zero_ptr(k + 1) - 1
            f(1, blk%zero_node(j)) = 0.0_wp
            f(2, blk%zero_node(j)) = 0.0_wp
          end do
        end if
        chunks: do ic = (grp - 1)*blk%group_len + 1, min(grp*blk%group_len, blk%nchunk)
          e0 = (ic - 1)*chunk_len
          nc = min(chunk_len, blk%nel - e0)
          if (blk%kernel == KERN_Q8) then
            ! the plane Q8 kernel gathers its geometry with u (one pass over
            ! conn); gather_q8 and scatter_q8 take the (2, nnode) node arrays
            ! as explicit-shape (2, *), passed without a copy as they are
            ! contiguous
            call gather_q8(nc, blk%conn(:, e0 + 1:e0 + nc), u, blk%xn, ue, xe)
          else
            do a = 1, nen
              do i = 1, nc
                node = blk%conn(a, e0 + i)
                ue(i, 1, a) = u(1, node)
                ue(i, 2, a) = u(2, node)
              end do
            end do
          end if
          ! the block's kernel, chosen once when the model was built
          select case (blk%kernel)
          case (KERN_Q4)
            call kernel_q4(nc, blk%lam, blk%mu, blk%q4(:, :, ic), ue, fe)
          case (KERN_Q8)
            call kernel_q8(nc, blk%lam, blk%mu, blk%gxi(1, 3), blk%wts, blk%thickness, xe, ue, fe)
          case (KERN_FINITE_Q4)
            call kernel_finite_q4(nc, blk%material, blk%volumetric, blk%moduli, blk%dnref, blk%pg(:, :, :, ic), &
              blk%cw(:, :, ic), blk%vol0(:, ic), blk%diag(:, :, ic), blk%rinv(:, ic), blk%thickness, mon, ue, fe, en, jm, jel, w2)
          case (KERN_FINITE_Q8)
            call kernel_finite_q8(nc, blk%material, blk%volumetric, blk%moduli, blk%dnref, blk%pg(:, :, :, ic), &
              blk%cw(:, :, ic), blk%vol0(:, ic), blk%diag(:, :, ic), blk%rinv(:, ic), blk%thickness, mon, ue, fe, en, jm, jel, w2)
          case (KERN_J2_SMALL_Q4:KERN_J2_FINITE_AXI_Q8)
            call j2_chunk(blk, ic, nc, mon, plastic%h(:, :, :, ic), plastic%virgin(ic), ue, fe, sgp, act, en, dis, jm, jel, w2)
          case (KERN_AXI_Q4)
            call kernel_axi_q4(nc, blk%lam, blk%mu, blk%q4(1 + blk%q4_shift, 1, ic), ue, fe)
          case (KERN_AXI_Q8)
            call kernel_axi_q8(nc, blk%lam, blk%mu, blk%nref, blk%dnref, blk%h(:, :, :, ic), blk%hoop(:, :, ic), ue, fe)
          case (KERN_FINITE_AXI_Q4, KERN_FINITE_AXI_Q8)
            call finite_axi_elastic_chunk(blk, ic, nc, mon, ue, fe, en, jm, jel, w2)
          end select
          if (watched .and. reports_energy(blk)) then
            watch%energy(ic) = en
            watch%jmin(ic) = jm
            watch%jmin_el(ic) = jel
            if (mon) watch%w2(ic) = w2
            if (blk%material == MAT_J2) then
              watch%dissip(ic) = dis
              watch%active(:, ic) = act > 0.0_wp
            end if
          end if
          if (blk%kernel == KERN_Q8) then
            call scatter_q8(nc, blk%conn(:, e0 + 1:e0 + nc), fe, f)
          else
            do a = 1, nen
              do i = 1, nc
                node = blk%conn(a, e0 + i)
                f(1, node) = f(1, node) + fe(i, 1, a)
                f(2, node) = f(2, node) + fe(i, 2, a)
              end do
            end do
          end if
        end do chunks
      end do groups
      !$omp end do
    end do colours
  end subroutine force_colours

  !> The block's kernel reports its stored energy (and more) through a
  !> block_watch_t: finite strain and j2 blocks; the linear blocks' energy
  !> is 1/2 u' f_int.
  pure logical function reports_energy(blk)
    type(elastic_block_t), intent(in) :: blk
    reports_energy = blk%kinematics == KIN_FINITE .or. blk%material == MAT_J2
  end function reports_energy

end module raccord_elastic_block
