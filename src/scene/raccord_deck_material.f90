!> Scene deck reader, what a body is made of: &body kinematics, material,
!> volumetric, and the j2 keys yield_stress and hardening, checked against
!> each other (doc/scene-reference.md; doc/theory-finite.md and
!> doc/theory-plasticity.md for the kernels they choose). Split from
!> raccord_deck, whose read_body calls these; messages follow its form
!>   <deck>:<line>: &<group> '<name>': <what is wrong>; <how to fix it>
module raccord_deck_material
  use raccord_kinds, only: wp
  use raccord_error, only: error_t
  use raccord_material, only: KIN_SMALL, KIN_FINITE, MAT_LINEAR, MAT_NEO_HOOKE, MAT_SVK, MAT_J2, VOL_AUTO, VOL_FULL, &
    VOL_MEAN
  use raccord_deck_scan, only: deck_block_t
  use raccord_deck_checks, only: bad_value, missing_key, UNSET
  use raccord_scene, only: body_spec_t
  implicit none
  private

  public :: read_constitution, read_plastic

contains

  !> &body kinematics, material and volumetric: the body's kernel (element
  !> x hypothesis x kinematics x material, doc/theory-finite.md). Small
  !> strain goes with linear_elastic, finite strain with neo_hooke or svk;
  !> other pairs are refused with what to write instead.
  subroutine read_constitution(deck, blk, label, kinematics, material, volumetric, spec, err)
    character(len=*), intent(in) :: deck, label, kinematics, material, volumetric
    type(deck_block_t), intent(in) :: blk
    type(body_spec_t), intent(inout) :: spec
    type(error_t), intent(inout) :: err
    select case (kinematics)
    case ('small')
      spec%kinematics = KIN_SMALL
    case ('finite')
      spec%kinematics = KIN_FINITE
    case default
      call bad_value(deck, blk, label, 'kinematics', 'unknown kinematics ''' // trim(kinematics) // '''', &
        'use ''small'' (small strain, the default) or ''finite'' (large strain and rotation)', err)
      return
    end select
    select case (material)
    case ('linear_elastic')
      spec%material = MAT_LINEAR
    case ('neo_hooke')
      spec%material = MAT_NEO_HOOKE
    case ('svk')
      spec%material = MAT_SVK
    case ('j2')
      spec%material = MAT_J2
    case default
      call bad_value(deck, blk, label, 'material', 'unknown material ''' // trim(material) // '''', &
        'use ''linear_elastic'' (small strain), ''neo_hooke'' or ''svk'' (finite strain), or ''j2'' ' // &
        '(von Mises plasticity, small or finite strain)', err)
      return
    end select
    select case (volumetric)
    case ('auto')
      spec%volumetric = VOL_AUTO
    case ('full')
      spec%volumetric = VOL_FULL
    case ('mean_dilatation')
      spec%volumetric = VOL_MEAN
    case default
      call bad_value(deck, blk, label, 'volumetric', 'unknown volumetric treatment ''' // trim(volumetric) // '''', &
        'use ''auto'' (mean dilatation for neo_hooke Q4, full integration otherwise), ''full'' or ' // &
        '''mean_dilatation''', err)
      return
    end select
    if (spec%kinematics == KIN_FINITE .and. spec%material == MAT_LINEAR) then
      call bad_value(deck, blk, label, 'kinematics', 'finite strain needs a hyperelastic material, ' // &
        'and material is ''linear_elastic''', 'write material = ''neo_hooke'' (or ''svk'') beside ' // &
        'kinematics = ''finite'', or kinematics = ''small'' for Hooke''s law', err)
    else if (spec%material == MAT_J2 .and. spec%plane_stress) then
      call bad_value(deck, blk, label, 'hypothesis', 'J2 plasticity is built for plane strain only, ' // &
        'and for axisymmetric bodies', &
        'write hypothesis = ''plane_strain'' for an elastoplastic body', err)
    else if (spec%kinematics == KIN_SMALL .and. spec%material /= MAT_LINEAR .and. spec%material /= MAT_J2) then
      call bad_value(deck, blk, label, 'material', 'material ''' // trim(material) // ''' is a finite-strain law ' // &
        'and kinematics is ''small''', 'write kinematics = ''finite'' beside material = ''' // trim(material) // &
        ''', or material = ''linear_elastic'' for small strain', err)
    else if (spec%kinematics == KIN_FINITE .and. spec%plane_stress) then
      call bad_value(deck, blk, label, 'hypothesis', 'finite strain is built for plane strain only, ' // &
        'and for axisymmetric bodies', &
        'write hypothesis = ''plane_strain'', or kinematics = ''small'' for a plane-stress body', err)
    else if (spec%kinematics == KIN_SMALL .and. spec%material /= MAT_J2 .and. spec%volumetric /= VOL_AUTO) then
      call bad_value(deck, blk, label, 'volumetric', 'the volumetric treatment is a finite-strain option ' // &
        '(and a j2 one)', 'leave volumetric out for a small-strain elastic body', err)
    else if (spec%material == MAT_SVK .and. spec%volumetric == VOL_MEAN) then
      call bad_value(deck, blk, label, 'volumetric', 'mean dilatation is built for neo_hooke only', &
        'write volumetric = ''full'' (or leave it out) for an svk body', err)
    end if
  end subroutine read_constitution

  !> &body yield_stress and hardening: required (yield_stress) and allowed
  !> only with material = 'j2' (doc/theory-plasticity.md).
  subroutine read_plastic(deck, blk, label, yield_stress, hardening, spec, err)
    character(len=*), intent(in) :: deck, label
    type(deck_block_t), intent(in) :: blk
    real(wp), intent(in) :: yield_stress, hardening
    type(body_spec_t), intent(inout) :: spec
    type(error_t), intent(inout) :: err
    if (spec%material /= MAT_J2) then
      if (yield_stress /= UNSET) then
        call bad_value(deck, blk, label, 'yield_stress', 'yield_stress is a key of material = ''j2''', &
          'write material = ''j2'' for an elastoplastic body, or leave yield_stress out', err)
      else if (hardening /= UNSET) then
        call bad_value(deck, blk, label, 'hardening', 'hardening is a key of material = ''j2''', &
          'write material = ''j2'' for an elastoplastic body, or leave hardening out', err)
      end if
      return
    end if
    if (yield_stress == UNSET) then
      call missing_key(deck, blk, label, 'yield_stress', 'yield_stress = <initial yield stress>, e.g. 240.0 (MPa)', err)
    else if (.not. (yield_stress > 0.0_wp)) then
      call bad_value(deck, blk, label, 'yield_stress', 'the yield stress must be > 0', &
        'give the initial (von Mises) yield stress in stress units, e.g. yield_stress = 240.0', err)
    else if (hardening /= UNSET .and. .not. (hardening >= 0.0_wp)) then
      call bad_value(deck, blk, label, 'hardening', 'the hardening modulus must be >= 0 (softening is not built)', &
        'give the slope H of yield stress against equivalent plastic strain, e.g. hardening = 2000.0, ' // &
        'or 0 (the default) for perfect plasticity', err)
    end if
    if (err%failed()) return
    spec%yield_stress = yield_stress
    spec%hardening = 0.0_wp
    if (hardening /= UNSET) spec%hardening = hardening
  end subroutine read_plastic
end module raccord_deck_material
