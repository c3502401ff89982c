!> Build the discrete model from the scene and the mesh, checking everything
!> that needs both (set names, element types, conflicting conditions).
module raccord_model_build
  use raccord_kinds, only: wp
  use raccord_error, only: error_t, raise_error, prefix_error, EXIT_INPUT
  use raccord_log, only: log_info, log_warn
  use raccord_strings, only: str
  use raccord_mesh, only: mesh_t, nodes_per_element, element_name, find_node_set, find_elem_set, &
    find_surface, ELEM_Q4, ELEM_Q8
  use raccord_mesh_names, only: not_found_text
  use raccord_scene, only: scene_t, bc_spec_t, BC_FIXED, BC_DISPLACEMENT, BC_TRACTION, BC_PRESSURE
  use raccord_elastic_block, only: init_elastic_block, claim_first_touch, add_lumped_mass, add_body_force, max_eigenvalue_bound, &
    make_finite, finite_w2_at_rest, make_plastic, make_axisymmetric
  use raccord_material, only: KIN_FINITE, MAT_NEO_HOOKE, MAT_J2, VOL_AUTO, VOL_FULL, VOL_MEAN
  use raccord_plasticity, only: j2_t
  use raccord_edge_load, only: add_edge_traction, add_edge_traction_axi
  use raccord_model, only: model_t, body_t, support_t, surface_load_t, amplitude_t, requested_threads, set_model_threads
  use raccord_mass_scaling, only: apply_mass_scaling
  implicit none
  private

  public :: build_model, surface_nodes

contains

  !> Build `model` from `scene` and `mesh`; every failure names the scene
  !> group and the set or element concerned.
  subroutine build_model(scene, mesh, model, err)
    type(scene_t), intent(in) :: scene
    type(mesh_t), intent(in) :: mesh
    type(model_t), intent(out) :: model
    type(error_t), intent(inout) :: err
    integer, allocatable :: elem_body(:)

    model%nnode = mesh%nnode
    model%x = mesh%x
    model%axisymmetric = scene%bodies(1)%axisymmetric    ! one hypothesis per scene (read_deck)
    if (model%axisymmetric) then
      call check_axisymmetric_mesh(scene, mesh, model, err)
      if (err%failed()) return
    else if (allocated(mesh%axi_types)) then
      if (len(mesh%axi_types) > 0) call log_warn('build_model', 'mesh ' // mesh%source // ' has axisymmetric ' // &
        'elements (' // mesh%axi_types // '), read as Q4/Q8, but the bodies are plane; write hypothesis = ' // &
        '''axisymmetric'' in each &body if the model is axisymmetric')
    end if
    call copy_amplitudes(scene, model)
    call build_bodies(scene, mesh, model, elem_body, err)
    if (err%failed()) return
    call check_block_names(scene, model, err)
    if (err%failed()) return
    call claim_nodes(model)
    call build_boundaries(scene, mesh, model, elem_body, err)
    if (err%failed()) return
    call check_pair_surfaces(scene, mesh, err)
    if (err%failed()) return
    if (model%axisymmetric) then
      call hold_axis_nodes(scene, mesh, model, err)
      if (err%failed()) return
    end if
    model%has_damping = any(model%alpha > 0.0_wp)
    call set_model_threads(model, requested_threads())
    if (model%nthreads > 1) call log_info('build_model', 'threads: ' // str(model%nthreads) // &
      ' (OMP_NUM_THREADS)')
  end subroutine build_model

  !> The deck's check of its pairs compares the names as written; in an
  !> Abaqus mesh an unquoted label is found in any case, so 'Top' and
  !> 'TOP' can be one surface there (doc/mesh-formats.md). A pair whose slave and master are one surface,
  !> or two pairs on the same slave and master surfaces, are refused here
  !> by the surfaces the names resolve to. Names that resolve to no
  !> surface are left to init_contact_pairs, which says what they are.
  subroutine check_pair_surfaces(scene, mesh, err)
    type(scene_t), intent(in) :: scene
    type(mesh_t), intent(in) :: mesh
    type(error_t), intent(inout) :: err
    integer, allocatable :: ks(:), km(:)
    integer :: i, j, np
    character(len=:), allocatable :: where, source
    if (.not. allocated(scene%contacts)) return
    source = '(built in memory)'
    if (allocated(mesh%source)) source = mesh%source
    np = size(scene%contacts)
    allocate(ks(np), km(np))
    do i = 1, np
      ks(i) = find_surface(mesh, scene%contacts(i)%slave)
      km(i) = find_surface(mesh, scene%contacts(i)%master)
      if (ks(i) == 0 .or. km(i) == 0) cycle
      where = 'scene ' // scene%path // ': &contact_pair #' // str(i) // ' (slave ''' // &
        trim(scene%contacts(i)%slave) // ''', master ''' // trim(scene%contacts(i)%master) // ''')'
      if (ks(i) == km(i)) then
        call raise_error(err, EXIT_INPUT, where // ': slave and master are the same surface ''' // &
          mesh%surfaces(ks(i))%name // ''' of mesh ' // source // name_rule(mesh) // &
          '; give the pair two surfaces, one on each body')
        return
      end if
      do j = 1, i - 1
        if (ks(j) /= ks(i) .or. km(j) /= km(i)) cycle
        call raise_error(err, EXIT_INPUT, where // ': the same slave and master surfaces (''' // &
          mesh%surfaces(ks(i))%name // ''', ''' // mesh%surfaces(km(i))%name // ''') as &contact_pair #' // &
          str(j) // name_rule(mesh) // '; give each pair once (two-pass contact swaps slave and master ' // &
          'in the second pair)')
        return
      end do
    end do
  end subroutine check_pair_surfaces

  !> The lookup rule, for messages on names that resolve alike.
  pure function name_rule(mesh) result(s)
    type(mesh_t), intent(in) :: mesh
    character(len=:), allocatable :: s
    s = ''
    if (mesh%ignore_case) s = ' (in an Abaqus mesh a deck name finds an unquoted label in any case)'
  end function name_rule

  !> Each node's internal force starts from the first block, in the order
  !> compute_forces visits them, that touches it; claiming across the
  !> blocks lets compute_forces skip zeroing f_int (raccord_elastic_block).
  subroutine claim_nodes(model)
    type(model_t), intent(inout) :: model
    logical, allocatable :: claimed(:)
    integer :: ib, k
    allocate(claimed(model%nnode), source=.false.)
    do ib = 1, size(model%bodies)
      do k = 1, size(model%bodies(ib)%blocks)
        call claim_first_touch(model%bodies(ib)%blocks(k), claimed)
      end do
    end do
  end subroutine claim_nodes

  subroutine copy_amplitudes(scene, model)
    type(scene_t), intent(in) :: scene
    type(model_t), intent(inout) :: model
    integer :: k, n
    if (.not. allocated(scene%amplitudes)) then
      allocate(model%amplitudes(0))
      return
    end if
    allocate(model%amplitudes(size(scene%amplitudes)))
    do k = 1, size(scene%amplitudes)
      n = scene%amplitudes(k)%npoint
      model%amplitudes(k)%name = scene%amplitudes(k)%name
      model%amplitudes(k)%t = scene%amplitudes(k)%t(1:n)
      model%amplitudes(k)%a = scene%amplitudes(k)%a(1:n)
    end do
  end subroutine copy_amplitudes

  !> The results file names a body's elements after the body, and a body
  !> with Q4 and Q8 elements NAME_1 (Q4) and NAME_2 (Q8): another body may
  !> not take one of those names (found here, before the run starts, rather
  !> than when the results file is opened).
  subroutine check_block_names(scene, model, err)
    type(scene_t), intent(in) :: scene
    type(model_t), intent(in) :: model
    type(error_t), intent(inout) :: err
    integer :: ib, jb, k
    character(len=:), allocatable :: block
    do ib = 1, size(model%bodies)
      if (size(model%bodies(ib)%blocks) < 2) cycle
      do k = 1, size(model%bodies(ib)%blocks)
        block = model%bodies(ib)%name // '_' // str(k)
        do jb = 1, size(model%bodies)
          if (model%bodies(jb)%name /= block) cycle
          call raise_error(err, EXIT_INPUT, 'scene ' // scene%path // ': &body ''' // model%bodies(jb)%name // &
            ''': body ''' // model%bodies(ib)%name // ''' has Q4 and Q8 elements, which the results file keeps ' // &
            'as the blocks ''' // model%bodies(ib)%name // '_1'' (Q4) and ''' // model%bodies(ib)%name // &
            '_2'' (Q8), and this body''s name is one of them; rename one of the two bodies')
          return
        end do
      end do
    end do
  end subroutine check_block_names

  !> Bodies: elastic blocks per element type, lumped masses, stable-step
  !> bound, initial velocities and body forces.
  subroutine build_bodies(scene, mesh, model, elem_body, err)
    type(scene_t), intent(in) :: scene
    type(mesh_t), intent(in) :: mesh
    type(model_t), intent(inout) :: model
    integer, allocatable, intent(out) :: elem_body(:)
    type(error_t), intent(inout) :: err
    integer :: ib, ks, e, k, nb, nen, nblk, et, i, nfree, vol
    integer, allocatable :: elems(:), conn(:,:)
    integer :: types(2)
    real(wp) :: m_before
    character(len=:), allocatable :: where

    nb = size(scene%bodies)
    allocate(model%bodies(nb))
    allocate(elem_body(mesh%nelem), source=0)
    allocate(model%mass(mesh%nnode), source=0.0_wp)
    allocate(model%node_body(mesh%nnode), source=0)
    allocate(model%v0(2, mesh%nnode), source=0.0_wp)
    allocate(model%f_body(2, mesh%nnode), source=0.0_wp)
    allocate(model%alpha(mesh%nnode), source=0.0_wp)
    types = [ELEM_Q4, ELEM_Q8]

    do ib = 1, nb
      associate (spec => scene%bodies(ib), body => model%bodies(ib))
        where = 'scene ' // scene%path // ': &body ''' // trim(spec%name) // ''''
        ks = find_elem_set(mesh, spec%elset)
        if (ks == 0) then
          call raise_error(err, EXIT_INPUT, where // ': elset ''' // trim(spec%elset) // ''' ' // &
            not_found_text(mesh, spec%elset, 'elem') // '. Set elset to the element set of the body''s ' // &
            'elements (Gmsh: a physical surface; Abaqus: *ELSET or ELSET= on *ELEMENT).')
          return
        end if
        elems = mesh%esets(ks)%elems
        if (size(elems) == 0) then
          call raise_error(err, EXIT_INPUT, where // ': element set ''' // trim(spec%elset) // ''' is empty.')
          return
        end if
        do k = 1, size(elems)
          e = elems(k)
          if (elem_body(e) /= 0) then
            call raise_error(err, EXIT_INPUT, where // ': element ' // str(mesh%elem_id(e)) // &
              ' already belongs to body ''' // model%bodies(elem_body(e))%name // &
              '''; each element belongs to one body.')
            return
          end if
          elem_body(e) = ib
        end do
        body%name = trim(spec%name)
        body%elems = elems
        body%density = spec%density

        ! One elastic block per element type present in the set.
        nblk = count([(any(mesh%etype(elems) == types(i)), i = 1, 2)])
        allocate(body%blocks(nblk))
        nblk = 0
        do i = 1, 2
          et = types(i)
          if (.not. any(mesh%etype(elems) == et)) cycle
          nblk = nblk + 1
          nen = nodes_per_element(et)
          conn = mesh%conn(1:nen, pack(elems, mesh%etype(elems) == et))
          call init_elastic_block(body%blocks(nblk), et, conn, model%x, spec%young, spec%poisson, &
            spec%plane_stress, spec%thickness, err)
          if (err%failed()) then
            call prefix_error(err, where // ' (' // element_name(et) // ' elements)')
            return
          end if
          if (spec%axisymmetric) then
            call make_axisymmetric(body%blocks(nblk), model%x, err)
            if (err%failed()) then
              call prefix_error(err, where // ' (' // element_name(et) // ' elements)')
              return
            end if
          end if
          if (spec%material == MAT_J2) then
            ! The body's kernel: J2 plasticity, small or finite strain; Q4
            ! with mean dilatation (B-bar), Q8 fully integrated, unless the
            ! deck says otherwise (doc/theory-plasticity.md, section 4).
            vol = spec%volumetric
            if (vol == VOL_AUTO) vol = merge(VOL_MEAN, VOL_FULL, et == ELEM_Q4)
            call make_plastic(body%blocks(nblk), mesh%x, spec%kinematics, j2_t(spec%yield_stress, spec%hardening), &
              vol, spec%density, err)
            if (err%failed()) then
              call prefix_error(err, where // ' (' // element_name(et) // ' elements)')
              return
            end if
            model%has_plastic = .true.
            if (spec%kinematics == KIN_FINITE) model%has_finite = .true.
          else if (spec%kinematics == KIN_FINITE) then
            ! The body's kernel: finite strain, its material, and for
            ! neo-Hooke Q4 mean dilatation unless the deck says otherwise.
            vol = spec%volumetric
            if (vol == VOL_AUTO) vol = merge(VOL_MEAN, VOL_FULL, spec%material == MAT_NEO_HOOKE .and. et == ELEM_Q4)
            call make_finite(body%blocks(nblk), mesh%x, spec%material, vol, spec%density, err)
            if (err%failed()) then
              call prefix_error(err, where // ' (' // element_name(et) // ' elements)')
              return
            end if
            model%has_finite = .true.
          end if
          body%blocks(nblk)%ids = mesh%elem_id(pack(elems, mesh%etype(elems) == et))
          m_before = sum(model%mass)
          call add_lumped_mass(body%blocks(nblk), spec%density, model%mass)
          body%mass = body%mass + (sum(model%mass) - m_before)
          body%w2_bound = max(body%w2_bound, max_eigenvalue_bound(body%blocks(nblk), spec%density))
          ! finite strain: the step follows the current-length estimate,
          ! a little below the exact element bound (method brief 5.1)
          if (spec%kinematics == KIN_FINITE) &
            body%w2_bound = max(body%w2_bound, finite_w2_at_rest(body%blocks(nblk), mesh%nnode))
          if (any(spec%body_force /= 0.0_wp)) then
            call add_body_force(body%blocks(nblk), spec%body_force, model%f_body)
            model%has_body_force = .true.
          end if
          do k = 1, size(conn, 2)
            model%node_body(conn(:, k)) = ib
            ! A body without damping of its own takes the &time damping.
            model%alpha(conn(:, k)) = merge(spec%damping, scene%time%damping, spec%damping >= 0.0_wp)
            model%v0(1, conn(:, k)) = spec%velocity(1)
            model%v0(2, conn(:, k)) = spec%velocity(2)
          end do
        end do
        model%nelem = model%nelem + size(elems)
        model%w2_bound = max(model%w2_bound, body%w2_bound)
        if (spec%kinematics /= KIN_FINITE) model%w2_small = max(model%w2_small, body%w2_bound)
      end associate
    end do

    nfree = count(elem_body == 0)
    if (nfree > 0) call log_warn('build_model', str(nfree) // ' mesh elements belong to no &body and are ignored')
    ! &time mass_scaling_dt / mass_scaling_factor: scaled masses and bounds
    call apply_mass_scaling(scene, model, err)
    if (err%failed()) return
    allocate(model%minv(mesh%nnode), source=0.0_wp)
    where (model%mass > 0.0_wp) model%minv = 1.0_wp/model%mass
    ! Nodes of finite-strain and j2 bodies: their stored energy replaces
    ! 1/2 u' f_int in the energy account (raccord_central_difference).
    block
      logical, allocatable :: fin(:)
      allocate(fin(mesh%nnode), source=.false.)
      do ib = 1, size(model%bodies)
        if (scene%bodies(ib)%kinematics /= KIN_FINITE .and. scene%bodies(ib)%material /= MAT_J2) cycle
        fin = fin .or. model%node_body == ib
      end do
      model%finite_nodes = pack([(i, i = 1, mesh%nnode)], fin)
    end block
  end subroutine build_bodies

  !> Supports and surface loads from the &boundary groups.
  subroutine build_boundaries(scene, mesh, model, elem_body, err)
    type(scene_t), intent(in) :: scene
    type(mesh_t), intent(in) :: mesh
    type(model_t), intent(inout) :: model
    integer, intent(in) :: elem_body(:)
    type(error_t), intent(inout) :: err
    integer :: k, nbc, nsup, nload
    integer, allocatable :: owner(:,:)
    integer, allocatable :: cnode(:), ccomp(:), csup(:)

    nbc = 0
    if (allocated(scene%bcs)) nbc = size(scene%bcs)
    nsup = count([(scene%bcs(k)%kind == BC_FIXED .or. scene%bcs(k)%kind == BC_DISPLACEMENT, k = 1, nbc)])
    nload = nbc - nsup
    allocate(model%supports(nsup), model%loads(nload))
    allocate(owner(2, mesh%nnode), source=0)
    allocate(cnode(0), ccomp(0), csup(0))
    nsup = 0
    nload = 0
    do k = 1, nbc
      select case (scene%bcs(k)%kind)
      case (BC_FIXED, BC_DISPLACEMENT)
        nsup = nsup + 1
        call build_support(scene, scene%bcs(k), k, mesh, model, nsup, owner, cnode, ccomp, csup, err)
      case (BC_TRACTION, BC_PRESSURE)
        nload = nload + 1
        call build_load(scene, scene%bcs(k), k, mesh, model, elem_body, model%loads(nload), err)
      end select
      if (err%failed()) return
    end do
    model%ncdof = size(cnode)
    ! A constrained component starts from the support's motion, not from the
    ! body's initial velocity (else energy would vanish at the first step).
    do k = 1, model%ncdof
      model%v0(ccomp(k), cnode(k)) = 0.0_wp
    end do
    model%cdof_node = cnode
    model%cdof_comp = ccomp
    model%cdof_support = csup
    ! Prescribed dofs are infinitely massive for the contact correction.
    allocate(model%minv_dof(2, mesh%nnode), model%dof_cdof(2, mesh%nnode))
    model%minv_dof(1, :) = model%minv
    model%minv_dof(2, :) = model%minv
    model%dof_cdof = 0
    do k = 1, model%ncdof
      model%minv_dof(ccomp(k), cnode(k)) = 0.0_wp
      model%dof_cdof(ccomp(k), cnode(k)) = k
    end do
    model%has_supports = model%ncdof > 0
    model%has_loads = nload > 0
  end subroutine build_boundaries

  subroutine build_support(scene, bc, ibc, mesh, model, isup, owner, cnode, ccomp, csup, err)
    type(scene_t), intent(in) :: scene
    type(bc_spec_t), intent(in) :: bc
    integer, intent(in) :: ibc, isup
    type(mesh_t), intent(in) :: mesh
    type(model_t), intent(inout) :: model
    integer, intent(inout) :: owner(:,:)
    integer, allocatable, intent(inout) :: cnode(:), ccomp(:), csup(:)
    type(error_t), intent(inout) :: err
    integer, allocatable :: nodes(:)
    integer :: i, c, n, other, nskip
    character(len=:), allocatable :: where

    where = 'scene ' // scene%path // ': &boundary #' // str(ibc) // ' (set ''' // trim(bc%set) // ''')'
    call resolve_node_set(mesh, bc%set, nodes, where, err)
    if (err%failed()) return
    associate (sup => model%supports(isup))
      sup%set = trim(bc%set)
      sup%driven = bc%kind == BC_DISPLACEMENT
      sup%value = 0.0_wp
      if (sup%driven) sup%value = bc%value
      call resolve_amplitude(model, bc%amplitude, sup%amplitude)
      nskip = count(model%node_body(nodes) == 0)
      if (nskip > 0) call log_warn('build_model', where // ': ' // str(nskip) // &
        ' nodes belong to no body and are skipped')
      sup%nodes = pack(nodes, model%node_body(nodes) /= 0)
      do i = 1, size(sup%nodes)
        n = sup%nodes(i)
        do c = 1, 2
          if (.not. bc%comp(c)) cycle
          other = owner(c, n)
          if (other /= 0) then
            ! Two fixed conditions on one component agree; anything else is ambiguous.
            if (.not. sup%driven .and. .not. model%supports(other)%driven) cycle
            call raise_error(err, EXIT_INPUT, where // ': node ' // str(mesh%node_id(n)) // ' component ' // &
              trim(merge('x', 'y', c == 1)) // ' is already constrained by the condition on set ''' // &
              model%supports(other)%set // '''; constrain each component of a node once ' // &
              '(remove the node from one set or drop the component from one condition).')
            return
          end if
          owner(c, n) = isup
          cnode = [cnode, n]
          ccomp = [ccomp, c]
          csup = [csup, isup]
        end do
      end do
    end associate
  end subroutine build_support

  subroutine build_load(scene, bc, ibc, mesh, model, elem_body, load, err)
    type(scene_t), intent(in) :: scene
    type(bc_spec_t), intent(in) :: bc
    integer, intent(in) :: ibc
    type(mesh_t), intent(in) :: mesh
    type(model_t), intent(in) :: model
    integer, intent(in) :: elem_body(:)
    type(surface_load_t), intent(out) :: load
    type(error_t), intent(inout) :: err
    integer :: is, k, e, nen, ib, j
    real(wp) :: xe(2, 3), fe(2, 3), traction(2), pressure
    real(wp), allocatable :: f(:,:)
    logical, allocatable :: touched(:)
    integer, allocatable :: pos(:)
    character(len=:), allocatable :: where

    where = 'scene ' // scene%path // ': &boundary #' // str(ibc) // ' (set ''' // trim(bc%set) // ''')'
    is = find_surface(mesh, bc%set)
    if (is == 0) then
      call raise_error(err, EXIT_INPUT, where // ': set ''' // trim(bc%set) // ''' ' // &
        not_found_text(mesh, bc%set, 'surface') // '. A traction or pressure acts on a surface ' // &
        '(Gmsh: a physical curve; Abaqus: *SURFACE, TYPE=ELEMENT).')
      return
    end if
    if (mesh%surfaces(is)%nedge == 0) then
      call raise_error(err, EXIT_INPUT, where // ': surface ''' // trim(bc%set) // ''' has no edges; ' // &
        'give it its edges in the mesh (Abaqus: data lines under *SURFACE) or load another surface.')
      return
    end if
    traction = 0.0_wp
    pressure = 0.0_wp
    if (bc%kind == BC_TRACTION) traction = bc%value
    if (bc%kind == BC_PRESSURE) pressure = bc%pressure
    allocate(f(2, mesh%nnode), source=0.0_wp)
    allocate(touched(mesh%nnode), source=.false.)
    associate (surf => mesh%surfaces(is))
      load%pressure = pressure
      load%axisymmetric = model%axisymmetric
      allocate(load%edges(3, surf%nedge), source=0)
      allocate(load%edge_follows(surf%nedge), source=.false.)
      allocate(load%edge_thickness(surf%nedge), source=1.0_wp)
      do k = 1, surf%nedge
        e = surf%elem(k)
        if (e <= 0) then
          call raise_error(err, EXIT_INPUT, where // ': edge ' // str(k) // ' (nodes ' // &
            str(mesh%node_id(surf%edge(1, k))) // ', ' // str(mesh%node_id(surf%edge(2, k))) // &
            ') lies inside the mesh (shared by two elements); a load surface must be on a body''s boundary.')
          return
        end if
        ib = elem_body(e)
        if (ib == 0) then
          call raise_error(err, EXIT_INPUT, where // ': edge ' // str(k) // ' belongs to element ' // &
            str(mesh%elem_id(e)) // ', which is in no &body.')
          return
        end if
        ! a 2-node edge of a surface that also has 3-node edges (Q4 and
        ! Q8 bodies) has mid = 0
        nen = 2
        if (surf%nen_edge == 3) then
          if (surf%edge(3, k) > 0) nen = 3
        end if
        xe = 0.0_wp
        do j = 1, nen
          xe(:, j) = mesh%x(:, surf%edge(j, k))
        end do
        fe = 0.0_wp
        if (model%axisymmetric) then
          call add_edge_traction_axi(nen, xe, traction, pressure, fe)
        else
          call add_edge_traction(nen, xe, traction, pressure, scene%bodies(ib)%thickness, fe)
        end if
        do j = 1, nen
          f(:, surf%edge(j, k)) = f(:, surf%edge(j, k)) + fe(:, j)
          touched(surf%edge(j, k)) = .true.
        end do
        ! a pressure on a finite-strain body acts on the deformed surface
        ! (as Abaqus and CalculiX apply it with NLGEOM); a traction stays
        ! a force per undeformed area in a fixed direction
        load%edges(1:nen, k) = surf%edge(1:nen, k)
        load%edge_follows(k) = bc%kind == BC_PRESSURE .and. scene%bodies(ib)%kinematics == KIN_FINITE
        load%edge_thickness(k) = scene%bodies(ib)%thickness
      end do
    end associate
    load%set = trim(bc%set)
    call resolve_amplitude(model, bc%amplitude, load%amplitude)
    load%nodes = pack([(j, j = 1, mesh%nnode)], touched)
    load%force = f(:, load%nodes)
    load%follower = any(load%edge_follows)
    ! the edges' nodes as positions in load%nodes
    allocate(pos(mesh%nnode), source=0)
    pos(load%nodes) = [(j, j = 1, size(load%nodes))]
    do k = 1, size(load%edges, 2)
      do j = 1, 3
        if (load%edges(j, k) > 0) load%edges(j, k) = pos(load%edges(j, k))
      end do
    end do
  end subroutine build_load

  !> An axisymmetric mesh lies in x = r >= 0: a node of a body at r < 0 is
  !> refused, naming it; nodes within round-off of the axis (|r| <= 1e-10
  !> of the mesh's extent) are put on it (r = 0 exactly), where
  !> hold_axis_nodes holds them radially.
  subroutine check_axisymmetric_mesh(scene, mesh, model, err)
    type(scene_t), intent(in) :: scene
    type(mesh_t), intent(in) :: mesh
    type(model_t), intent(inout) :: model
    type(error_t), intent(inout) :: err
    logical, allocatable :: used(:)
    real(wp) :: tol
    integer :: ib, ks, k, e, n
    allocate(used(mesh%nnode), source=.false.)
    do ib = 1, size(scene%bodies)
      ks = find_elem_set(mesh, scene%bodies(ib)%elset)
      if (ks == 0) cycle                  ! build_bodies reports it
      do k = 1, size(mesh%esets(ks)%elems)
        e = mesh%esets(ks)%elems(k)
        associate (c => mesh%conn(:, e))
          used(pack(c, c > 0)) = .true.
        end associate
      end do
    end do
    tol = 1.0e-10_wp*max(maxval(abs(mesh%x)), tiny(1.0_wp))
    do n = 1, mesh%nnode
      if (.not. used(n)) cycle
      if (model%x(1, n) < -tol) then
        call raise_error(err, EXIT_INPUT, 'scene ' // scene%path // ': hypothesis = ''axisymmetric'': node ' // &
          str(mesh%node_id(n)) // ' of mesh ' // mesh%source // ' lies at r = x = ' // str(model%x(1, n)) // &
          ' < 0; x is the radius and y the axis of symmetry, so an axisymmetric section lies in x >= 0 ' // &
          '(mesh the half section on the side x >= 0, or mirror the mesh in x)')
        return
      end if
      if (abs(model%x(1, n)) <= tol) model%x(1, n) = 0.0_wp
    end do
  end subroutine check_axisymmetric_mesh

  !> Nodes on the axis (r = 0) have u_r = 0 by symmetry: a fixed support on
  !> their x component, set 'axis' (its reaction, a ring total, is the
  !> radial force the symmetry takes, about 0). A deck that also fixes x
  !> there is accepted (the same condition); a deck that drives x there to
  !> a non-zero value is refused.
  subroutine hold_axis_nodes(scene, mesh, model, err)
    type(scene_t), intent(in) :: scene
    type(mesh_t), intent(in) :: mesh
    type(model_t), intent(inout) :: model
    type(error_t), intent(inout) :: err
    type(support_t), allocatable :: sup(:)
    integer, allocatable :: nodes(:), add(:)
    integer :: i, n, k, j, nsup
    nodes = pack([(i, i = 1, model%nnode)], model%node_body /= 0 .and. model%x(1, :) == 0.0_wp)
    if (size(nodes) == 0) return
    allocate(add(0))
    do i = 1, size(nodes)
      n = nodes(i)
      k = model%dof_cdof(1, n)
      if (k == 0) then
        add = [add, n]
        cycle
      end if
      associate (other => model%supports(model%cdof_support(k)))
        if (other%driven .and. other%value(1) /= 0.0_wp) then
          call raise_error(err, EXIT_INPUT, 'scene ' // scene%path // ': &boundary on set ''' // other%set // &
            ''' drives the radial (x) displacement of node ' // str(mesh%node_id(n)) // ', which lies on the ' // &
            'axis (r = 0), where symmetry holds it at 0; drop component x for the axis nodes of that set')
          return
        end if
      end associate
    end do
    call log_info('build_model', 'axisymmetric: ' // str(size(nodes)) // ' nodes on the axis (r = 0) held ' // &
      'radially (u_r = 0), ' // str(size(nodes) - size(add)) // ' of them already by the deck')
    if (size(add) == 0) return
    nsup = size(model%supports) + 1
    allocate(sup(nsup))
    sup(1:nsup - 1) = model%supports
    sup(nsup)%set = 'axis'
    sup(nsup)%driven = .false.
    sup(nsup)%nodes = add
    call move_alloc(sup, model%supports)
    model%cdof_node = [model%cdof_node, add]
    model%cdof_comp = [model%cdof_comp, [(1, j = 1, size(add))]]
    model%cdof_support = [model%cdof_support, [(nsup, j = 1, size(add))]]
    do j = 1, size(add)
      model%ncdof = model%ncdof + 1
      model%v0(1, add(j)) = 0.0_wp
      model%minv_dof(1, add(j)) = 0.0_wp
      model%dof_cdof(1, add(j)) = model%ncdof
    end do
    model%has_supports = .true.
  end subroutine hold_axis_nodes

  !> Nodes of a node set, or of a surface of that name.
  subroutine resolve_node_set(mesh, name, nodes, where, err)
    type(mesh_t), intent(in) :: mesh
    character(len=*), intent(in) :: name, where
    integer, allocatable, intent(out) :: nodes(:)
    type(error_t), intent(inout) :: err
    integer :: k
    k = find_node_set(mesh, name)
    if (k /= 0) then
      nodes = mesh%nsets(k)%nodes
    else
      k = find_surface(mesh, name)
      if (k == 0) then
        call raise_error(err, EXIT_INPUT, where // ': set ''' // trim(name) // ''' ' // &
          not_found_text(mesh, name, 'node_or_surface') // '. A boundary condition acts on nodes or ' // &
          'edges: fix the set name, or add the set to the mesh (Gmsh: a physical curve or point; ' // &
          'Abaqus: *NSET or *SURFACE).')
        return
      end if
      nodes = surface_nodes(mesh, k)
    end if
    if (size(nodes) == 0) call raise_error(err, EXIT_INPUT, where // ': set ''' // trim(name) // ''' is empty.')
  end subroutine resolve_node_set

  !> Unique nodes of surface k, in order of first appearance.
  function surface_nodes(mesh, k) result(nodes)
    type(mesh_t), intent(in) :: mesh
    integer, intent(in) :: k
    integer, allocatable :: nodes(:)
    logical, allocatable :: seen(:)
    integer :: i, j, n, cnt
    allocate(seen(mesh%nnode), source=.false.)
    allocate(nodes(3*mesh%surfaces(k)%nedge))
    cnt = 0
    do i = 1, mesh%surfaces(k)%nedge
      do j = 1, mesh%surfaces(k)%nen_edge
        n = mesh%surfaces(k)%edge(j, i)
        if (n <= 0) cycle
        if (seen(n)) cycle
        seen(n) = .true.
        cnt = cnt + 1
        nodes(cnt) = n
      end do
    end do
    nodes = nodes(1:cnt)
  end function surface_nodes

  !> Index of the named amplitude ('' -> 0 = constant 1). The deck reader
  !> has checked that the name exists.
  subroutine resolve_amplitude(model, name, idx)
    type(model_t), intent(in) :: model
    character(len=*), intent(in) :: name
    integer, intent(out) :: idx
    integer :: k
    idx = 0
    if (len_trim(name) == 0) return
    do k = 1, size(model%amplitudes)
      if (model%amplitudes(k)%name == trim(name)) then
        idx = k
        return
      end if
    end do
  end subroutine resolve_amplitude
end module raccord_model_build
