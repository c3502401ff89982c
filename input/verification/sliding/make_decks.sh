#!/bin/sh
# Write the sliding decks (doc/scenes.md, section "sliding").
set -e
cd "$(dirname "$0")"
deck() {  # NAME MESH TITLE METHOD MULTIPLIER FRICTION
  cat > "$1.nml" <<EOD
! Block sliding on a block: $3.
! Slider 1 x 0.5 mm on a base 4 x 0.5 mm (bottom clamped), same material,
! plane strain. 1) 0 .. 5e-6 s: pressure 10 MPa on the slider top, N = 10 N/mm.
! 2) 1e-5 .. 2e-5 s: traction (8, 0) MPa on the slider's right side, pulling
! F = 4 N/mm > mu N = 3 N/mm for mu = 0.3 (sliding from F = 3, t = 1.75e-5 s);
! held to 6e-5 s. Expected while sliding: tangential contact force = mu N
! (3 N/mm for mu = 0.3, 0 for mu = 0). Damping alpha = 1.2e7 1/s (lowest
! period about 1e-6 s) limits the slider to about 21 mm/s (mu = 0.3) or
! 85 mm/s (mu = 0). Units: mm, s, N, MPa, t/mm^3. Written by make_decks.sh.
&run
  title = 'sliding: $3'
/
&mesh
  file = '$2'
/
&body
  name = 'base', elset = 'base'
  young = 200000.0, poisson = 0.3, density = 7.8e-9, hypothesis = 'plane_strain'
/
&body
  name = 'slider', elset = 'slider'
  young = 200000.0, poisson = 0.3, density = 7.8e-9, hypothesis = 'plane_strain'
/
&amplitude
  name = 'press', time = 0.0, 5.0e-6, value = 0.0, 1.0
/
&amplitude
  name = 'pull', time = 1.0e-5, 2.0e-5, value = 0.0, 1.0
/
&boundary
  set = 'base_bottom', type = 'fixed', components = 'xy'
/
&boundary
  set = 'slider_top', type = 'pressure', pressure = 10.0, amplitude = 'press'
/
&boundary
  set = 'slider_right', type = 'traction', value = 8.0, 0.0, amplitude = 'pull'
/
&time
  t_end = 6.0e-5, safety = 0.9, damping = 1.2e7
/
&output
  frames = 30
/
&contact_pair
  slave = 'slider_bottom', master = 'base_top'
  method = '$4', multiplier = '$5', friction = $6
/
EOD
  echo "$1.nml"
}
deck q4_mortar_p1_mu030 sliding_q4.msh "Q4, mortar P1, mu = 0.3"       mortar P1 0.3
deck q4_mortar_p0_mu030 sliding_q4.msh "Q4, mortar P0, mu = 0.3"       mortar P0 0.3
deck q4_nts_mu030       sliding_q4.msh "Q4, node-to-segment, mu = 0.3" node_to_segment P1 0.3
deck q4_mortar_p1_mu000 sliding_q4.msh "Q4, mortar P1, mu = 0"         mortar P1 0.0
deck q4_nts_mu000       sliding_q4.msh "Q4, node-to-segment, mu = 0"   node_to_segment P1 0.0
deck q8_mortar_p1_mu030 sliding_q8.msh "Q8, mortar P1, mu = 0.3"       mortar P1 0.3
deck q8_mortar_p1_mu000 sliding_q8.msh "Q8, mortar P1, mu = 0"         mortar P1 0.0
