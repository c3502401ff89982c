#!/bin/sh
# Write the plane-strain Taylor decks (doc/scenes.md, section "Taylor").
set -e
cd "$(dirname "$0")"
deck() {  # NAME MESH KINEMATICS METHOD TITLE
  cat > "$1.nml" <<EOD
! Plane-strain Taylor test: $5.
! Half of a copper-like bar 2 x 10 mm (x >= 0, symmetry line x = 0 held in
! x) moving at 100 m/s (1.0e5 mm/s) in -y onto a wall 0.01 mm below it.
! Bar: E = 117000 MPa, nu = 0.35, rho = 8.93e-9 t/mm^3, j2 with
! sigma_y0 = 400 MPa, H = 100 MPa (the constants usually given to the
! copper of the Taylor bar benchmark, used in plane strain here). Wall: the same nu, E and rho both 100
! times the bar's (the same wave speed, so the same stable step; 100 times
! the impedance, so its face moves about 1 % of the bar's speed), bottom
! held: "rigid-ish". Frictionless contact. Initial kinetic energy 446.49
! N mm per mm of thickness. No damping. Units: mm, s, N, MPa, t/mm^3.
! Written by make_decks.sh.
&run
  title = 'Taylor, plane strain: $5'
/
&mesh
  file = '$2'
/
&body
  name = 'bar', elset = 'bar'
  young = 117000.0, poisson = 0.35, density = 8.93e-9
  kinematics = '$3', material = 'j2', yield_stress = 400.0, hardening = 100.0
  velocity = 0.0, -1.0e5
/
&body
  name = 'wall', elset = 'wall'
  young = 1.17e7, poisson = 0.35, density = 8.93e-7
/
&boundary set = 'bar_axis', type = 'fixed', components = 'x' /
&boundary set = 'wall_axis', type = 'fixed', components = 'x' /
&boundary set = 'wall_bottom', type = 'fixed', components = 'xy' /
&time
  t_end = 3.0e-5, safety = 0.9, damping = 0.0
/
&output
  frames = 30, history_every = 10
/
&contact_pair
  slave = 'bar_face', master = 'wall_top'
  method = '$4', multiplier = 'P1', friction = 0.0
/
EOD
  echo "$1.nml"
}
M=taylor_q4.msh
deck finite_mortar $M finite mortar          "finite strain, mortar P1"
deck finite_nts    $M finite node_to_segment "finite strain, node-to-segment"
deck small_mortar  $M small  mortar          "small strain, mortar P1"
deck small_nts     $M small  node_to_segment "small strain, node-to-segment"
# The comparison scene of tools/calculix/taylor-ccx.sh: no wall, the face
# held at y = g (a rigid frictionless wall from t = 0, exact while the face
# stays in contact; the face nodes start at rest, the rest of the bar at
# 100 m/s). The wall body stays in the mesh, untouched.
sed -e "s/^! Plane-strain Taylor test: .*/! Plane-strain Taylor test: finite strain, the face held at y = g (no contact)./" \
    -e "s/^  title = .*/  title = 'Taylor, plane strain: finite strain, face held'/" \
    -e "s/ in -y onto a wall 0.01 mm below it\./ in -y; its face (y = 0.01) held in y from t = 0./" \
    -e "s/ Frictionless contact\./ The wall is not touched (no contact)./" \
    -e "/^&boundary set = 'bar_axis'/a\\
\&boundary set = 'bar_face', type = 'fixed', components = 'y' /" \
    -e '/^&contact_pair/,$d' finite_mortar.nml > finite_fixed_face.nml
echo finite_fixed_face.nml
