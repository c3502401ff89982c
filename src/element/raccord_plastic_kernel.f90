!> Internal force of J2 elastoplastic elements (doc/theory-plasticity.md),
!> one chunk of elements at a time, small or finite strain, Q4 or Q8.
!>
!> The gradient at every Gauss point and the assembly of the forces are
!> those of the finite-strain kernel ((F-1), (F-2) of raccord_finite_kernel;
!> Q4 with the exact gradient split): only the stress differs. It comes from
!> the return map of raccord_plasticity, on one Gauss point of the whole
!> chunk per call, which updates the internal variables (hist) in place:
!> one read and one write of them per step, the least memory traffic (the
!> J2 step is bound by it on large meshes, doc/performance.md). Computing
!> the forces of a state twice starts the second return on the yield
!> surface, so it changes nothing but round-off; the stress output works
!> on a copy (raccord_elastic_block_plastic).
!>
!> Volumetric treatment (volumetric = 'mean_dilatation', the default for
!> j2): plastic flow is isochoric, so a fully integrated Q4 (and Q8) would
!> lock in fully plastic flow. The pressure is taken on the element's mean
!> volume change:
!>  - small strain, B-bar: theta_bar = sum_g c_g tr(eps_g) / V_e replaces
!>    tr(eps) at every point, sigma_g = s_g + K theta_bar I, and
!>    f = sum_g c_g B_g^T sigma_g is the gradient of sum_g c_g W_e;       (J-1)
!>  - finite strain, mean dilatation as for neo-Hooke (F-3): Jbar =
!>    sum_g c_g J_g / V_e, tau_g = 2G dev eps_e,g + K ln(Jbar) (J_g/Jbar) I,
!>    the volumetric energy V_e (K/2) ln(Jbar)^2.                         (J-2)
!> volumetric = 'full' keeps each point's own trace (for comparison).
!>
!> Per chunk the kernel reports the elastic energy sum c W_e, the plastic
!> work of the step sum c dW_p (P-6, P-7), and in finite strain the
!> smallest J and, with monitor, the largest omega^2 estimate.
module raccord_plastic_kernel
  use raccord_kinds, only: wp
  use raccord_material, only: moduli_t
  use raccord_plasticity, only: j2_t, nhist, j2_small_lanes, j2_hencky_lanes, j2_small_trial_lanes
  use raccord_finite_kernel, only: fin_chunk_len, q4h_row, q4h_col
  implicit none
  private

  public :: kernel_j2_small_q4, kernel_j2_small_q8, kernel_j2_finite_q4, kernel_j2_finite_q8
  public :: kernel_j2_axi_q4, kernel_j2_axi_q8

  integer, parameter :: max_nen = 8, max_gp = 9

contains

  !> fe = internal forces of nc J2 elements of a chunk; sg = Cauchy stress
  !> (xx, yy, xy, zz) at every Gauss point; hist = the internal variables,
  !> updated by this state's return; act = 1 for the elements whose return
  !> was plastic at a Gauss point, else 0; energy = sum c W_e, dissip = sum c
  !> dW_p; jmin/jmin_el/w2 as the finite kernel (jmin = 1 in small strain).
  !> virgin (small strain; finite strain leaves it .false.): on entry, the
  !> chunk's internal variables are all still 0 (never yielded); then, if no
  !> point's elastic trial reaches the yield surface, the return is skipped
  !> and hist is neither read nor written (the same bits: a return with
  !> dgamma = 0 is the identity). On exit, whether they are still all 0.
  !> The other arguments are those of kernel_finite_q4.
  pure subroutine kernel_j2_small_q4(nc, m, j2, mean, dn, pg, cw, vol0, diag, rinv, thickness, monitor, &
      hist, virgin, ue, fe, sg, act, energy, dissip, jmin, jmin_el, w2)
    integer, parameter :: nen = 4, ngp = 4
    real(wp), parameter :: lfac = 1.0_wp
    logical, parameter :: split = .true., finite = .false.
    include 'raccord_plastic_kernel_body.inc'
  end subroutine kernel_j2_small_q4

  pure subroutine kernel_j2_small_q8(nc, m, j2, mean, dn, pg, cw, vol0, diag, rinv, thickness, monitor, &
      hist, virgin, ue, fe, sg, act, energy, dissip, jmin, jmin_el, w2)
    integer, parameter :: nen = 8, ngp = 9
    real(wp), parameter :: lfac = 0.3_wp
    logical, parameter :: split = .false., finite = .false.
    include 'raccord_plastic_kernel_body.inc'
  end subroutine kernel_j2_small_q8

  pure subroutine kernel_j2_finite_q4(nc, m, j2, mean, dn, pg, cw, vol0, diag, rinv, thickness, monitor, &
      hist, virgin, ue, fe, sg, act, energy, dissip, jmin, jmin_el, w2)
    integer, parameter :: nen = 4, ngp = 4
    real(wp), parameter :: lfac = 1.0_wp
    logical, parameter :: split = .true., finite = .true.
    include 'raccord_plastic_kernel_body.inc'
  end subroutine kernel_j2_finite_q4

  pure subroutine kernel_j2_finite_q8(nc, m, j2, mean, dn, pg, cw, vol0, diag, rinv, thickness, monitor, &
      hist, virgin, ue, fe, sg, act, energy, dissip, jmin, jmin_el, w2)
    integer, parameter :: nen = 8, ngp = 9
    real(wp), parameter :: lfac = 0.3_wp
    logical, parameter :: split = .false., finite = .true.
    include 'raccord_plastic_kernel_body.inc'
  end subroutine kernel_j2_finite_q8
  !> Axisymmetric J2 (small strain), on the axisymmetric blocks' data
  !> (raccord_axi_kernel, doc/theory-axisymmetric.md): H = sqrt(c) J^-1 and
  !> the hoop factor sqrt(c)/r_g per Gauss point, c = w detJ 2 pi r_g (cw),
  !> V_e = sum_g c (vol0). The strain (rr, zz, rz, tt), eps_tt = u_r/r, is
  !> the plane-strain return's (xx, yy, xy, zz): the out-of-plane component
  !> is the hoop strain instead of 0; B-bar takes the element's mean of
  !> eps_rr + eps_zz + eps_tt (J-1). Forces f_a += c B^T sigma as the
  !> axisymmetric Hooke kernel; sg = Cauchy (rr, zz, rz, tt).
  pure subroutine kernel_j2_axi_q4(nc, m, j2, mean, nref, dn, h, hoop, cw, vol0, hist, ue, fe, sg, act, &
      energy, dissip)
    integer, parameter :: nen = 4, ngp = 4
    include 'raccord_plastic_axi_body.inc'
  end subroutine kernel_j2_axi_q4

  pure subroutine kernel_j2_axi_q8(nc, m, j2, mean, nref, dn, h, hoop, cw, vol0, hist, ue, fe, sg, act, &
      energy, dissip)
    integer, parameter :: nen = 8, ngp = 9
    include 'raccord_plastic_axi_body.inc'
  end subroutine kernel_j2_axi_q8
end module raccord_plastic_kernel
