#!/bin/sh
# The program with J2 elastoplastic bodies (material = 'j2').
# usage: plastic_cases.sh CASE RACCORD SOURCE_DIR WORK_DIR
# CASE        refuse, outputs, restart
# refuse      j2 keys without j2, j2 without yield_stress, bad values and
#             plane stress exit 2 before anything is written, naming the key
# outputs     the plan names the material; the results carry
#             equivalent_plastic_strain and yielded, the history plastic_work
# restart     a j2 slider (finite strain) pressed and dragged on a steel
#             base with friction, stopped by SIGUSR1 in mid-run and restarted:
#             its results equal the continuous run's bit for bit
# Needs sh, awk, cmp, h5dump and h5diff (hdf5-tools); 77 = skipped.
set -u

case_name=$1
raccord=$2
src=$3
work=$4

. "$src/tests/support/cases.sh"

need_tools h5dump h5diff h5ls
fresh_work

# block DECK BODY_KEYS: the unit block of tests/finite/data, steel-like,
# bottom held in y, sides in x, top driven down 1 % and back.
block() {
  cat > "$1" <<EOD
&mesh file = '$src/tests/finite/data/block.msh' /
&body name = 'block', young = 210000.0, poisson = 0.3, density = 7.8e-9, $2 /
&amplitude name = 'cycle', time = 0.0, 2.0e-5, 4.0e-5, value = 0.0, 1.0, 0.0 /
&boundary set = 'bottom', type = 'fixed', components = 'y' /
&boundary set = 'left', type = 'fixed', components = 'x' /
&boundary set = 'right', type = 'fixed', components = 'x' /
&boundary set = 'top', type = 'displacement', components = 'y', value = 0.0, -0.01, amplitude = 'cycle' /
&time t_end = 4.0e-5, damping = 5.0e6 /
&output frames = 4 /
EOD
}

case "$case_name" in
refuse)
  refused yield_without_j2 "yield_stress = 240.0" "yield_stress is a key of material = 'j2'" "material = 'j2'"
  refused hardening_without_j2 "kinematics = 'finite', material = 'neo_hooke', hardening = 10.0" \
    "hardening is a key of material = 'j2'"
  refused j2_without_yield "material = 'j2'" "yield_stress" "yield_stress = <initial yield stress>"
  refused j2_zero_yield "material = 'j2', yield_stress = 0.0" "the yield stress must be > 0"
  refused j2_softening "material = 'j2', yield_stress = 240.0, hardening = -100.0" "hardening modulus must be >= 0"
  refused j2_plane_stress "material = 'j2', yield_stress = 240.0, hypothesis = 'plane_stress'" \
    "plane strain only" "hypothesis = 'plane_strain'"
  # (finite j2 in axisymmetry is built: tests/axisymmetric/test_axi_finite.f90)
  refused svk_axisymmetric_mean "kinematics = 'finite', material = 'svk', volumetric = 'mean_dilatation', hypothesis = 'axisymmetric'" \
    "mean dilatation is built for neo_hooke only"
  refused j2_bad_volumetric "material = 'j2', yield_stress = 240.0, volumetric = 'reduced'" \
    "unknown volumetric treatment 'reduced'"
  ;;
outputs)
  block ok.nml "material = 'j2', yield_stress = 240.0, hardening = 2000.0"
  "$raccord" --check ok.nml > check.txt 2>&1
  code=$?
  check "--check of a j2 body: exit 0 (got $code)" test "$code" -eq 0
  check "--check names the material, its yield stress and the Q4 treatment" has check.txt \
    "small strain, j2 (Q4 mean_dilatation), sigma_y0 = 240"
  check "--check writes the keys back" has check.txt "yield_stress = 240"
  "$raccord" -q -o out ok.nml > run.txt 2>&1
  code=$?
  check "run: exit 0 (got $code)" test "$code" -eq 0
  [ "$code" -eq 0 ] || { cat run.txt; finish; }
  check "the history has a plastic_work column" has out/ok.history.txt "plastic_work"
  check "the log reports the plastic work" has out/ok.log "plastic work"
  h5ls -r out/ok.h5 > h5ls.txt
  check "frames carry equivalent_plastic_strain" has h5ls.txt "/frames/000004/equivalent_plastic_strain"
  check "frames carry yielded" has h5ls.txt "/frames/000004/yielded"
  check "the XDMF shows equivalent_plastic_strain" has out/ok.xmf 'Name="equivalent_plastic_strain"'
  check "the XDMF shows yielded" has out/ok.xmf 'Name="yielded"'
  # 1 % confined compression yields the whole block: ebar > 0 at every node
  h5dump -d /frames/000004/equivalent_plastic_strain -y -w 0 out/ok.h5 | \
    awk '/DATA/ { on = 1; next } on && /}/ { exit } on { gsub(/,/, " "); for (i = 1; i <= NF; i++) print $i }' > ebar.txt
  check "equivalent plastic strain > 0 at all 25 nodes" \
    test "$(awk '$1 > 1e-3 { n++ } END { print n + 0 }' ebar.txt)" -eq 25
  plastic=$(awk '!/^#/ { w = $NF } END { print w }' out/ok.history.txt)
  check "plastic work > 0 (got $plastic)" awk -v w="$plastic" 'BEGIN { exit !(w > 0) }'
  ;;
restart)
  deck() {
    mkdir -p "$1"
    cat > "$1/slide.nml" <<EOD
! A j2 slider (finite strain) on a steel base, mu = 0.3: pressed past yield, pulled right, then back.
&mesh file = '$src/input/verification/sliding/sliding_q4.msh' /
&body name = 'base', elset = 'base', young = 200000.0, poisson = 0.3, density = 7.8e-9 /
&body name = 'slider', elset = 'slider', young = 20000.0, poisson = 0.3, density = 2.7e-9,
  kinematics = 'finite', material = 'j2', yield_stress = 60.0, hardening = 2000.0 /
&amplitude name = 'press', time = 0.0, 4.0e-5, value = 0.0, 1.0 /
&amplitude name = 'pull', time = 5.0e-5, 8.0e-5, 1.2e-4, value = 0.0, 1.0, -1.0 /
&boundary set = 'base_bottom', type = 'fixed', components = 'xy' /
&boundary set = 'slider_top', type = 'pressure', pressure = 100.0, amplitude = 'press' /
&boundary set = 'slider_right', type = 'traction', value = 40.0, 0.0, amplitude = 'pull' /
&time t_end = 1.3e-4, damping = 2.0e6 /
&output frames = 13, history_every = 7 /
&contact_pair slave = 'slider_bottom', master = 'base_top', friction = 0.3, method = 'mortar' /
EOD
  }
  deck cont
  "$raccord" -q -o cont cont/slide.nml > cont/run.out 2>&1
  code=$?
  check "continuous run: exit 0 (got $code)" test "$code" -eq 0
  [ "$code" -eq 0 ] || { cat cont/run.out; finish; }
  check "the slider is j2 with finite strain" has cont/slide.log "finite strain, j2"
  plastic=$(awk '!/^#/ { w = $NF } END { print w }' cont/slide.history.txt)
  check "the slider yields (plastic work $plastic > 0)" awk -v w="$plastic" 'BEGIN { exit !(w > 0) }'
  deck usr1
  usr1_restart_equals slide
  ;;
*)
  echo "unknown case $case_name" >&2
  exit 2
  ;;
esac
finish
