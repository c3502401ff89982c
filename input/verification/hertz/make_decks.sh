#!/bin/sh
# Write the Hertz decks (doc/scenes.md, section "hertz").
# Steel-like, both bodies: E = 200000 MPa, nu = 0.3, rho = 7.8e-9 t/mm^3, plane strain.
# Load: 400 MPa on the 20 mm flat top = P = 8000 N/mm, ramped over 2.5e-4 s
# (5 lowest periods of about 5e-5 s), held to 4e-4 s; damping alpha = 2.5e5 1/s
# (about 2 omega_1). Expected: a = 0.9628 mm, p0 = 5290 MPa.
set -e
cd "$(dirname "$0")"
deck() {  # NAME MESH TITLE SLAVE MASTER METHOD MULTIPLIER
  cat > "$1.nml" <<EOD
! Hertz line contact, frictionless: $3.
! Cylinder R = 10 mm (lower half-disc) on a block 80 x 40 mm, same material.
! P = 400 MPa x 20 mm = 8000 N/mm; E* = E/(2(1-nu^2)) = 109890 MPa;
! Hertz: a = sqrt(4PR/(pi E*)) = 0.9628 mm, p0 = 2P/(pi a) = 5290 MPa.
! The cylinder axis x = 0 is held in x (symmetry; it removes the free sliding
! and rolling of the cylinder). Quasi-static: ramp over 2.5e-4 s, hold to
! 4e-4 s, lowest period about 5e-5 s, alpha = 2.5e5 1/s. Compare the last
! frame. Units: mm, s, N, MPa, t/mm^3. Written by make_decks.sh.
&run
  title = 'hertz: $3'
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
  name = 'ramp', time = 0.0, 2.5e-4, value = 0.0, 1.0
/
&boundary
  set = 'block_bottom', type = 'fixed', components = 'xy'
/
&boundary
  set = 'cylinder_axis', type = 'fixed', components = 'x'
/
&boundary
  set = 'cylinder_top', type = 'pressure', pressure = 400.0, amplitude = 'ramp'
/
&time
  t_end = 4.0e-4, safety = 0.9, damping = 2.5e5
/
&output
  frames = 16
/
&contact_pair
  slave = '$4', master = '$5'
  method = '$6', multiplier = '$7', friction = 0.0
/
EOD
  echo "$1.nml"
}
for m in q4 q8; do
  M=hertz_$m.msh; Q=$(echo $m | tr q Q)
  deck ${m}_nts_slave_block       $M "$Q, node-to-segment, slave = block top"    block_top cylinder_arc node_to_segment P1
  deck ${m}_nts_slave_cylinder    $M "$Q, node-to-segment, slave = cylinder arc" cylinder_arc block_top node_to_segment P1
  deck ${m}_mortar_p1_slave_block    $M "$Q, mortar P1, slave = block top"    block_top cylinder_arc mortar P1
  deck ${m}_mortar_p1_slave_cylinder $M "$Q, mortar P1, slave = cylinder arc" cylinder_arc block_top mortar P1
  deck ${m}_mortar_p0_slave_block    $M "$Q, mortar P0, slave = block top"    block_top cylinder_arc mortar P0
  deck ${m}_mortar_p0_slave_cylinder $M "$Q, mortar P0, slave = cylinder arc" cylinder_arc block_top mortar P0
done
C=hertz_q4_coarse.msh
deck reg_nts_slave_block       $C "regression, coarse Q4, node-to-segment, slave = block top" block_top cylinder_arc node_to_segment P1
deck reg_mortar_p1_slave_block $C "regression, coarse Q4, mortar P1, slave = block top"       block_top cylinder_arc mortar P1
deck reg_q8_mortar_p1_slave_block hertz_q8_coarse.msh "regression, coarse Q8, mortar P1, slave = block top" block_top cylinder_arc mortar P1
