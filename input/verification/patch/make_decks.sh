#!/bin/sh
# Write the contact patch-test decks (doc/scenes.md, section "patch").
set -e
cd "$(dirname "$0")"
deck() {  # NAME MESH TITLE SLAVE MASTER METHOD MULTIPLIER
  cat > "$1.nml" <<EOD
! Contact patch test: $3.
! Two blocks 1 x 0.5 mm, same material, non-matching interface (5 : 20
! elements, graded), frictionless. 10 MPa on the upper top; lower bottom held
! in y, one corner of each block held in x, sides free. Exact: uniform
! sigma_yy = -10 MPa, sigma_xx = sigma_xy = 0 in both blocks, contact pressure
! 10 MPa everywhere, u_x = 1.95e-5 x (plane strain, nu = 0.3).
! Ramp over 4e-6 s, hold to 8e-6 s; lowest period about 8e-7 s (4 x 1 mm /
! sqrt(E/rho)), alpha = 1.6e7 1/s. Units: mm, s, N, MPa, t/mm^3.
! Written by make_decks.sh.
&run
  title = 'patch: $3'
/
&mesh
  file = '$2'
/
&body
  name = 'lower', elset = 'lower'
  young = 200000.0, poisson = 0.3, density = 7.8e-9, hypothesis = 'plane_strain'
/
&body
  name = 'upper', elset = 'upper'
  young = 200000.0, poisson = 0.3, density = 7.8e-9, hypothesis = 'plane_strain'
/
&amplitude
  name = 'ramp', time = 0.0, 4.0e-6, value = 0.0, 1.0
/
&boundary
  set = 'lower_bottom', type = 'fixed', components = 'y'
/
&boundary
  set = 'lower_anchor', type = 'fixed', components = 'x'
/
&boundary
  set = 'upper_anchor', type = 'fixed', components = 'x'
/
&boundary
  set = 'upper_top', type = 'pressure', pressure = 10.0, amplitude = 'ramp'
/
&time
  t_end = 8.0e-6, safety = 0.9, damping = 1.6e7
/
&output
  frames = 8
/
&contact_pair
  slave = '$4', master = '$5'
  method = '$6', multiplier = '$7', friction = 0.0
/
EOD
  echo "$1.nml"
}
for m in q4 q8; do
  M=patch_$m.msh; Q=$(echo $m | tr q Q)
  deck ${m}_nts_slave_upper       $M "$Q, node-to-segment, slave = upper (fine)"  upper_bottom lower_top node_to_segment P1
  deck ${m}_nts_slave_lower       $M "$Q, node-to-segment, slave = lower (coarse)" lower_top upper_bottom node_to_segment P1
  deck ${m}_mortar_p1_slave_upper $M "$Q, mortar P1, slave = upper (fine)"  upper_bottom lower_top mortar P1
  deck ${m}_mortar_p1_slave_lower $M "$Q, mortar P1, slave = lower (coarse)" lower_top upper_bottom mortar P1
  deck ${m}_mortar_p0_slave_upper $M "$Q, mortar P0, slave = upper (fine)"  upper_bottom lower_top mortar P0
  deck ${m}_mortar_p0_slave_lower $M "$Q, mortar P0, slave = lower (coarse)" lower_top upper_bottom mortar P0
done
