#!/bin/sh
# Write the bar-impact decks (doc/scenes.md, section "impact").
set -e
cd "$(dirname "$0")"
deck() {  # NAME MESH TITLE SLAVE MASTER METHOD MULTIPLIER
  cat > "$1.nml" <<EOD
! Impact of two identical bars: $3.
! Bars 10 x 1 mm, E = 200000 MPa, nu = 0 (plane stress), rho = 7.8e-9 t/mm^3:
! c = sqrt(E/rho) = 5.064e6 mm/s. Gap 0.01 mm, velocities +-5.0e4 mm/s
! (about 1 % of c): contact from t0 = 1.0e-7 s for 2L/c = 3.949e-6 s, contact
! stress rho c v = 1975 MPa; afterwards the bars separate with their
! velocities exchanged (+-v reversed), stress-free. No damping; energy must
! not grow, momentum is exchanged exactly. Units: mm, s, N, MPa, t/mm^3.
! Written by make_decks.sh.
&run
  title = 'impact: $3'
/
&mesh
  file = '$2'
/
&body
  name = 'left_bar', elset = 'left_bar'
  young = 200000.0, poisson = 0.0, density = 7.8e-9, hypothesis = 'plane_stress'
  velocity = 5.0e4, 0.0
/
&body
  name = 'right_bar', elset = 'right_bar'
  young = 200000.0, poisson = 0.0, density = 7.8e-9, hypothesis = 'plane_stress'
  velocity = -5.0e4, 0.0
/
&time
  t_end = 6.0e-6, safety = 0.9, damping = 0.0
/
&output
  frames = 60, history_every = 1
/
&contact_pair
  slave = '$4', master = '$5'
  method = '$6', multiplier = '$7', friction = 0.0
/
EOD
  echo "$1.nml"
}
M=impact_q4.msh
deck nts       $M "matching ends, node-to-segment" left_bar_end right_bar_end node_to_segment P1
deck mortar_p1 $M "matching ends, mortar P1"       left_bar_end right_bar_end mortar P1
deck mortar_p0 $M "matching ends, mortar P0"       left_bar_end right_bar_end mortar P0
N=impact_q4_nonmatching.msh
deck nonmatching_nts_slave_left        $N "non-matching ends 10:7, node-to-segment, slave = left (fine)"  left_bar_end right_bar_end node_to_segment P1
deck nonmatching_nts_slave_right       $N "non-matching ends 10:7, node-to-segment, slave = right (coarse)" right_bar_end left_bar_end node_to_segment P1
deck nonmatching_mortar_p1_slave_left  $N "non-matching ends 10:7, mortar P1, slave = left (fine)"  left_bar_end right_bar_end mortar P1
deck nonmatching_mortar_p1_slave_right $N "non-matching ends 10:7, mortar P1, slave = right (coarse)" right_bar_end left_bar_end mortar P1
deck nonmatching_mortar_p0_slave_left  $N "non-matching ends 10:7, mortar P0, slave = left (fine)"  left_bar_end right_bar_end mortar P0
