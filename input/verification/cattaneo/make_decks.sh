#!/bin/sh
# Write the Cattaneo-Mindlin decks (doc/scenes.md, section "cattaneo").
# Geometry and meshes: ../hertz (cylinder R = 10 on a block 80 x 40), identical
# materials. Normal phase: the flat top is driven down by 0.17 mm (uniform, so
# the cylinder cannot roll), estimated to give P ~ 8000 N/mm; tangential phase:
# traction 60 MPa x 20 mm = Q = 1200 N/mm = 0.5 mu P with mu = 0.3.
set -e
cd "$(dirname "$0")"
deck() {  # NAME MESH TITLE SLAVE MASTER MULTIPLIER
  cat > "$1.nml" <<EOD
! Cattaneo-Mindlin partial slip: $3.
! Hertz geometry (../hertz), same material both bodies, mu = 0.3.
! 1) 0 .. 2.5e-4 s: the cylinder top is driven down by 0.17 mm (y only; x free).
!    The uniform top displacement stops the cylinder from rolling. The
!    estimate 0.17 mm gives P ~ 8000 N/mm (+-15 %); P is measured (reaction of
!    cylinder_top, or the sum of the normal contact forces).
! 2) 3.5e-4 .. 6e-4 s: traction (60, 0) MPa on the 20 mm top: Q = 1200 N/mm
!    = 0.5 mu P. Hold to 7.5e-4 s, compare the last frame: stick zone
!    c/a = sqrt(1 - Q/(mu P)) = 0.707 for P = 8000 (use the measured P).
! Lowest period about 5e-5 s, alpha = 2.5e5 1/s. Units: mm, s, N, MPa, t/mm^3.
! Written by make_decks.sh.
&run
  title = 'cattaneo: $3'
/
&mesh
  file = '$2'
/
&body
  name = 'cylinder', elset = 'cylinder'
  young = 200000.0, poisson = 0.3, density = 7.8e-9, hypothesis = 'plane_strain'
/
&body
  name = 'block', elset = 'block'
  young = 200000.0, poisson = 0.3, density = 7.8e-9, hypothesis = 'plane_strain'
/
&amplitude
  name = 'normal', time = 0.0, 2.5e-4, value = 0.0, 1.0
/
&amplitude
  name = 'tangential', time = 3.5e-4, 6.0e-4, value = 0.0, 1.0
/
&boundary
  set = 'block_bottom', type = 'fixed', components = 'xy'
/
&boundary
  set = 'cylinder_top', type = 'displacement', components = 'y'
  value = 0.0, -0.17, amplitude = 'normal'
/
&boundary
  set = 'cylinder_top', type = 'traction', value = 60.0, 0.0, amplitude = 'tangential'
/
&time
  t_end = 7.5e-4, safety = 0.9, damping = 2.5e5
/
&output
  frames = 30
/
&contact_pair
  slave = '$4', master = '$5'
  method = 'mortar', multiplier = '$6', friction = 0.3
/
EOD
  echo "$1.nml"
}
H=../hertz
deck q4_mortar_p1_slave_block    $H/hertz_q4.msh "Q4, mortar P1, slave = block top"    block_top cylinder_arc P1
deck q4_mortar_p1_slave_cylinder $H/hertz_q4.msh "Q4, mortar P1, slave = cylinder arc" cylinder_arc block_top P1
deck q4_mortar_p0_slave_block    $H/hertz_q4.msh "Q4, mortar P0, slave = block top"    block_top cylinder_arc P0
deck q8_mortar_p1_slave_block    $H/hertz_q8.msh "Q8, mortar P1, slave = block top"    block_top cylinder_arc P1
deck reg_mortar_p1_slave_block   $H/hertz_q4_coarse.msh "regression, coarse Q4, mortar P1, slave = block top" block_top cylinder_arc P1
