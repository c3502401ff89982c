#!/bin/sh
# Write the decks of the paper scene (Baillet & Sassi 2003, section 4).
# Every deck shares the same materials, densities, load cycle and damping
# (doc/scenes.md, section "paper"); they differ by mesh and contact pair.
set -e
cd "$(dirname "$0")"

T=2.0e-5        # loading time to maximum indentation (about 40 lowest periods)
ALPHA=2.5e7     # mass-proportional damping of the block, about 2 omega_1 of the block
# The disc is not damped: it is driven rigidly from its top, and mass damping
# on it is a drag alpha*M*v (840 N/mm at alpha = ALPHA and the mean speed
# 0.1581/T, of the order of the contact force during the loading; zero at
# t = T, where the load is at rest), not a quasi-static model. Exception,
# the Fig. 3 decks (DISC_ALPHA below): a node that sticks keeps its
# tangential state for the rest of the load, so the ringing of an undamped
# disc while the contact zone grows is frozen into the stick tractions as a
# node-to-node zigzag (4.3 % of the peak at mu = 0.5; doc/reproduction.md,
# Fig. 3). There the disc gets 2 omega_1 of its own lowest mode (period
# about 1.3e-6 s: 1.0e7 1/s), a drag of 530 N/mm at most, about 0 at t = T.
DISC_ALPHA=
PAIRX=          # extra &contact_pair keys of the next decks (Fig. 4(b))
T2=$(awk "BEGIN { printf \"%.1e\", 2*$T }")   # end of the cycle
# The cycle 0 -> 1 -> 0 follows (1 - cos(pi t/T))/2 sampled at 41 points:
# zero velocity at the start, at maximum indentation and at the end, so the
# driven disc is never jerked (a kinked table reverses its velocity in one
# step, an inertial spike of M*2v/dt on the reactions).
CYCLE_T=$(awk "BEGIN { for (k = 0; k <= 40; k++) printf \"%s%.6e\", (k ? \", \" : \"\"), k*$T/20 }")
CYCLE_A=$(awk "BEGIN { for (k = 0; k <= 40; k++) printf \"%s%.6f\", (k ? \", \" : \"\"), (1 - cos(3.14159265358979*k/20))/2 }")

# deck NAME MESH TITLE SLAVE MASTER METHOD MULTIPLIER FRICTION [KINEMATICS]
# KINEMATICS 'finite' makes both bodies neo-Hooke, finite strain (the
# decks finite_*: doc/reproduction.md, "The paper's test with finite
# strain"); 'plastic' makes the block J2 elastoplastic, small strain (the
# decks plastic_*: "The paper's test with a plastic layer"); left out,
# both bodies are small strain with Hooke's law.
deck() {
  BLK=""
  if [ "${9:-small}" = plastic ]; then
    # the block only: the disc stays elastic (its von Mises stress is far
    # below any yield stress of interest here)
    BLK="
  material = 'j2', yield_stress = $SY, hardening = $HMOD"
    FIN=""
    FINNOTE="
! Plastic layer: the block is J2 elastoplastic, small strain, yield stress
! $SY MPa with linear isotropic hardening H = $HMOD MPa (E2/100), mean
! dilatation (volumetric = 'auto'); the disc stays elastic. The cycle
! unloads the layer: the disc comes back up to where it started and
! leaves contact on the way, above the dent it made. CalculiX with
! *PLASTIC on the same mesh: tools/calculix/plastic-ccx.sh
! (doc/reproduction.md, \"The paper's test with a plastic layer\")."
  elif [ "${9:-small}" = finite ]; then
    FIN="
  kinematics = 'finite', material = 'neo_hooke'"
    FINNOTE="
! Finite strain: both bodies neo-Hooke (W = C10 (Ibar1 - 3) + (J - 1)^2 / D1,
! C10 = G/2, D1 = 2/K from young and poisson; total Lagrangian, mean
! dilatation on Q4), as CalculiX with NLGEOM and *HYPERELASTIC, NEO HOOKE
! (tools/calculix/finite-ccx.sh)."
  else
    FIN=""
    FINNOTE=""
  fi
  if [ -n "$DISC_ALPHA" ]; then
    DISCDAMP=", damping = $DISC_ALPHA"
    DISCNOTE="the disc,
! driven rigidly from its top, is damped too (alpha = $DISC_ALPHA 1/s, about
! 2 omega_1 of the disc): stuck nodes keep the tangential state of their
! history, and an undamped disc's ringing is frozen into it. The damping
! is a drag alpha*M*v on the disc's motion (at most 530 N/mm, about 0 at
! t = T), carried by disc_top: judge the force by contact1_Fy."
  else
    DISCDAMP=""
    DISCNOTE="the disc,
! driven rigidly from its top, is not damped (mass damping would drag it)."
  fi
  cat > "$1.nml" <<EOD
! Baillet & Sassi (2003), section 4: $3.
! Disc part (radius 1 mm, E1 = 70000 MPa) driven 0.1581 mm into a block
! 1.8 x 0.3 mm (E2 = 7000 MPa) and back; plane strain, nu = 0.3.
! Densities are not in the paper: 2.7e-9 and 1.2e-9 t/mm^3 (aluminium-like,
! polymer-like); loading time T = $T s against a lowest period of about
! 5e-7 s (block, 4 x 0.3 mm / sqrt(E2/rho2)) and damping of the block
! alpha = $ALPHA 1/s make the run quasi-static (doc/scenes.md); $DISCNOTE
! Maximum indentation at t = T,
! which is result frame 20 of 40. Units: mm, s, N, MPa, t/mm^3.$FINNOTE
! Written by make_decks.sh; edit that script, not this file.
&run
  title = 'paper: $3'
/
&mesh
  file = '$2'
/
&body
  name = 'disc', elset = 'disc'
  young = 70000.0, poisson = 0.3, density = 2.7e-9
  hypothesis = 'plane_strain'$DISCDAMP$FIN
/
&body
  name = 'block', elset = 'block'
  young = 7000.0, poisson = 0.3, density = 1.2e-9
  hypothesis = 'plane_strain', damping = $ALPHA$FIN$BLK
/
&amplitude
  name = 'cycle'
  time = $CYCLE_T
  value = $CYCLE_A
/
&boundary
  set = 'block_bottom', type = 'fixed', components = 'xy'      ! Gamma_u^2 clamped
/
&boundary
  set = 'disc_top', type = 'displacement', components = 'xy'   ! Gamma_u^1 driven
  value = 0.0, -0.1581, amplitude = 'cycle'
/
&time
  t_end = $T2, safety = 0.9
/
&output
  frames = 40
/
&contact_pair
  slave = '$4', master = '$5'
  method = '$6', multiplier = '$7', friction = $8$PAIRX
/
EOD
  echo "$1.nml"
}

F=paper_q4_fine.msh
# Fig. 1(b): node-to-segment, frictionless, slave on each body in turn
deck fig1b_nts_slave_block  $F "Fig. 1(b), node-to-segment, slave = block top" block_top disc_arc node_to_segment P1 0.0
deck fig1b_nts_slave_disc   $F "Fig. 1(b), node-to-segment, slave = disc arc"  disc_arc block_top node_to_segment P1 0.0
# Fig. 2(a): mortar P1, frictionless, slave on each body
deck fig2a_mortar_p1_slave_block $F "Fig. 2(a), mortar P1, slave = block top" block_top disc_arc mortar P1 0.0
deck fig2a_mortar_p1_slave_disc  $F "Fig. 2(a), mortar P1, slave = disc arc"  disc_arc block_top mortar P1 0.0
# Fig. 2(b): mortar P0 against P1 (P1: fig2a_mortar_p1_slave_block)
deck fig2b_mortar_p0_slave_block $F "Fig. 2(b), mortar P0, slave = block top" block_top disc_arc mortar P0 0.0
deck fig2b_mortar_p0_slave_disc  $F "Fig. 2(b), mortar P0, slave = disc arc"  disc_arc block_top mortar P0 0.0
# Fig. 3: mortar P0 and P1 with Coulomb friction, slave = block top; the
# disc damped at 2 omega_1 of its own lowest mode (see DISC_ALPHA above)
DISC_ALPHA=1.0e7
for mu in 0.1 0.2 0.5; do
  tag=$(echo "$mu" | tr -d .)0
  deck fig3_mortar_p0_mu$tag $F "Fig. 3, mortar P0, mu = $mu, slave = block top" block_top disc_arc mortar P0 $mu
  deck fig3_mortar_p1_mu$tag $F "Fig. 3, mortar P1, mu = $mu, slave = block top" block_top disc_arc mortar P1 $mu
done
DISC_ALPHA=""
# The load cycle's friction run: the Fig. 3 deck at mu = 0.2 with the disc
# undamped, whose loading and unloading branches show the dissipation of
# friction (the damped disc's drag is of the same size; doc/reproduction.md,
# "The load cycle"). Its stick tractions zigzag: Fig. 3 uses the damped deck.
deck cycle_mortar_p1_mu020 $F "the load cycle, mortar P1, mu = 0.2, slave = block top, disc undamped" block_top disc_arc mortar P1 0.2
# Fig. 4(a): Q4 against Q8 with the same interface node spacing, mortar P1, frictionless
deck fig4a_q4_mortar_p1 paper_q4.msh "Fig. 4(a), Q4, mortar P1, slave = block top" block_top disc_arc mortar P1 0.0
deck fig4a_q8_mortar_p1 paper_q8.msh "Fig. 4(a), Q8, mortar P1, slave = block top" block_top disc_arc mortar P1 0.0
# Fig. 4(b): Q8, mortar P0 and P1, mu = 0.2, the tangential multipliers at
# the corners of the Q8 edges only (with one on every trace node the stick
# traction zigzags by 13 % of its peak from node to node: doc/reproduction.md,
# "The Q8 stick zigzag: tangential corner multipliers")
PAIRX="
  edge_multipliers = 'tangential_corners'"
deck fig4b_q8_mortar_p0_mu020 paper_q8.msh "Fig. 4(b), Q8, mortar P0, mu = 0.2, slave = block top" block_top disc_arc mortar P0 0.2
deck fig4b_q8_mortar_p1_mu020 paper_q8.msh "Fig. 4(b), Q8, mortar P1, mu = 0.2, slave = block top" block_top disc_arc mortar P1 0.2
PAIRX=
# Regression: the coarse mesh, a few seconds each
C=paper_q4_coarse.msh
deck reg_nts_slave_block       $C "regression, coarse, node-to-segment, slave = block top" block_top disc_arc node_to_segment P1 0.0
deck reg_nts_slave_disc        $C "regression, coarse, node-to-segment, slave = disc arc"  disc_arc block_top node_to_segment P1 0.0
deck reg_mortar_p1_slave_block $C "regression, coarse, mortar P1, slave = block top" block_top disc_arc mortar P1 0.0
deck reg_mortar_p1_slave_disc  $C "regression, coarse, mortar P1, slave = disc arc"  disc_arc block_top mortar P1 0.0
deck reg_mortar_p0_slave_block $C "regression, coarse, mortar P0, slave = block top" block_top disc_arc mortar P0 0.0
deck reg_mortar_p1_mu020       $C "regression, coarse, mortar P1, mu = 0.2, slave = block top" block_top disc_arc mortar P1 0.2
# Node-to-segment with the disc as slave on the mid mesh: on the coarse one the
# polygonal arc's geometric error lets contact give back 1.6e-3 of the peak
# internal energy (4.5e-5 here, 2.9e-5 on the fine mesh; doc/verification.md).
deck reg_nts_slave_disc_mid    paper_q4.msh "regression, mid mesh, node-to-segment, slave = disc arc"  disc_arc block_top node_to_segment P1 0.0
# Finite strain (issue #13): the Fig. 1(b) and Fig. 2(a) scenes, same fine
# mesh, both bodies neo-Hooke; profiles beside the small-strain ones in
# postproc/paper/finite.gp.
deck finite_nts_slave_block       $F "finite strain, node-to-segment, slave = block top" block_top disc_arc node_to_segment P1 0.0 finite
deck finite_nts_slave_disc        $F "finite strain, node-to-segment, slave = disc arc"  disc_arc block_top node_to_segment P1 0.0 finite
deck finite_mortar_p1_slave_block $F "finite strain, mortar P1, slave = block top" block_top disc_arc mortar P1 0.0 finite
deck finite_mortar_p1_slave_disc  $F "finite strain, mortar P1, slave = disc arc"  disc_arc block_top mortar P1 0.0 finite
# ... and on the coarse mesh for tests/finite (test_finite_paper), beside reg_mortar_p1_slave_block
deck finite_coarse_mortar_p1_slave_block $C "finite strain, coarse, mortar P1, slave = block top" block_top disc_arc mortar P1 0.0 finite
# Plastic layer (issue #14): the block J2, small strain. SY = E2/10 is a
# fifth of the elastic layer's peak pressure (3430 MPa): the layer yields
# at about a quarter of the indentation (doc/reproduction.md, "The
# paper's test with a plastic layer"); H = E2/100.
SY=700.0
HMOD=70.0
# The fine-mesh decks load four times slower than the others (T = 8e-5 s):
# plastic flow follows the path, and at T = 2e-5 s the explicit run's
# mid-load overshoot (+3.7 % of the force) leaves extra plastic flow at
# the contact edge (peak +14 % over CalculiX's static run; +2.3 % at
# 8e-5 s; doc/reproduction.md). The coarse test deck keeps T = 2e-5 s.
T=8.0e-5
T2=$(awk "BEGIN { printf \"%.1e\", 2*$T }")
CYCLE_T=$(awk "BEGIN { for (k = 0; k <= 40; k++) printf \"%s%.6e\", (k ? \", \" : \"\"), k*$T/20 }")
deck plastic_mortar_p1_slave_block $F "plastic layer, mortar P1, slave = block top" block_top disc_arc mortar P1 0.0 plastic
deck plastic_nts_slave_block       $F "plastic layer, node-to-segment, slave = block top" block_top disc_arc node_to_segment P1 0.0 plastic
# ... and on the coarse mesh for tests/plastic (test_plastic_paper), at
# T = 2e-5 s (4 s in the Check build; at 8e-5 s the coarse run meets a
# spurious mortar activation on unloading, doc/reproduction.md)
T=2.0e-5
T2=$(awk "BEGIN { printf \"%.1e\", 2*$T }")
CYCLE_T=$(awk "BEGIN { for (k = 0; k <= 40; k++) printf \"%s%.6e\", (k ? \", \" : \"\"), k*$T/20 }")
deck plastic_coarse_mortar_p1_slave_block $C "plastic layer, coarse, mortar P1, slave = block top" block_top disc_arc mortar P1 0.0 plastic
