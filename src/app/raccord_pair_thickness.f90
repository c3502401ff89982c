!> The rule on the thicknesses of a contact pair's two plane bodies
!> (doc/scene-reference.md, &contact_pair): they must be equal.
!>
!> A pair's multipliers are forces over the whole out-of-plane thickness,
!> and the pair reports its contact pressure and shear per unit of one
!> thickness (raccord_contact_pair, the slave body's). Two plane bodies of
!> different thicknesses have no one contact width: the slave's pressure
!> is then not the master's, and a plane (2D) model cannot say over which
!> width they touch (a thin plate on the middle of a thick block, or at
!> its edge, load the block differently out of plane). Such a pair ran
!> without a word, its stresses those of the slave's thickness; it is
!> refused, naming the pair and both thicknesses, before the first step.
!> Axisymmetric bodies have no thickness (forces are totals over 2 pi).
module raccord_pair_thickness
  use raccord_kinds, only: wp
  use raccord_error, only: error_t, raise_error, EXIT_INPUT
  use raccord_strings, only: str
  use raccord_scene, only: scene_t
  use raccord_model, only: model_t
  use raccord_contact_pair, only: contact_pair_t
  implicit none
  private

  public :: check_pair_thickness

contains

  !> Refuse (EXIT_INPUT) the first pair whose slave and master bodies have
  !> different thicknesses. `pairs` are those init_contact_pairs built from
  !> scene%contacts, in the same order; each surface lies on one body
  !> (init_contact_pairs refused a surface on no body), the body of its
  !> first node. Thicknesses are compared exactly: both are the deck's
  !> numbers (1.0 when not given), not results of arithmetic.
  subroutine check_pair_thickness(scene, model, pairs, err)
    type(scene_t), intent(in) :: scene
    type(model_t), intent(in) :: model
    type(contact_pair_t), intent(in) :: pairs(:)
    type(error_t), intent(inout) :: err
    integer :: k, bs, bm
    real(wp) :: ts, tm
    if (model%axisymmetric) return
    do k = 1, size(pairs)
      bs = model%node_body(pairs(k)%slave%node(1))
      bm = model%node_body(pairs(k)%master%node(1))
      if (bs <= 0 .or. bm <= 0) cycle
      ts = scene%bodies(bs)%thickness
      tm = scene%bodies(bm)%thickness
      if (ts == tm) cycle
      call raise_error(err, EXIT_INPUT, 'scene ' // scene%path // ': &contact_pair #' // str(k) // &
        ' (slave ''' // trim(scene%contacts(k)%slave) // ''', master ''' // trim(scene%contacts(k)%master) // &
        '''): the slave body ''' // model%bodies(bs)%name // ''' has thickness = ' // str(ts, 6) // &
        ', the master body ''' // model%bodies(bm)%name // ''' thickness = ' // str(tm, 6) // &
        '; two plane bodies in contact must have the same thickness (a 2D model has no one contact width ' // &
        'for two, and the contact pressure would be per unit of the slave''s only): give both &body groups ' // &
        'the thickness over which they touch')
      return
    end do
  end subroutine check_pair_thickness
end module raccord_pair_thickness
