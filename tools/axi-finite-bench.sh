#!/bin/sh
# Cost of the axisymmetric finite-strain kernels against their plane-strain
# twins (doc/performance.md, "Axisymmetric finite strain"): the same mesh
# and deck run with hypothesis = 'plane_strain' and 'axisymmetric', neo-Hooke
# and j2, back to back, REPEAT times; prints raccord's own figure of each run
# (ns per element per step, output included, from the log's "done:" line).
#
#   sh tools/axi-finite-bench.sh RACCORD [OUTDIR] [REPEAT]
#
# Meshes: 160 x 80 Q4 (12800 elements) and 80 x 40 Q8 (3200) on
# [0, 2] x [0, 1] (touching the axis), E = 1000, nu = 0.3, rho = 1, the top
# pushed down 2 % over t_end = 0.1 (about 470 steps Q4, 780 Q8), one frame.
set -eu
raccord=$1
out=${2:-results/axi_finite_bench}
rep=${3:-3}
mkdir -p "$out"
cd "$out"
here=$(cd "$(dirname "$0")" && pwd)
mesh() { # FILE NX NY TYPE
  sh "$here/rect-mesh-inp.sh" "$4" "$2" "$3" 0 2 0 1 10 bottom=bottom top=top > "$1"
}
mesh q4.inp 160 80 CAX4
mesh q8.inp 80 40 CAX8
echo "# repeat type law hypothesis ns_per_element_step steps"
i=1
while [ "$i" -le "$rep" ]; do
  for t in q4 q8; do
    for law in nh j2; do
      mat="material = 'neo_hooke'"
      [ "$law" = j2 ] && mat="material = 'j2', yield_stress = 5.0"
      for h in plane_strain axisymmetric; do
        name=${t}_${h}_${law}
        cat > "$name.nml" <<EOD
&mesh file = '$t.inp' /
&body name = 'body', young = 1000.0, poisson = 0.3, density = 1.0, hypothesis = '$h', kinematics = 'finite', $mat /
&amplitude name = 'ramp', time = 0.0, 0.1, value = 0.0, 1.0 /
&boundary set = 'bottom', type = 'fixed', components = 'y' /
&boundary set = 'top', type = 'displacement', components = 'y', value = 0.0, -0.02, amplitude = 'ramp' /
&time t_end = 0.1 /
&output frames = 1 /
EOD
        "$raccord" -q -o "o_$name" "$name.nml" > /dev/null 2>&1 || { echo "run $name failed"; exit 1; }
        awk -v r="$i" -v t="$t" -v l="$law" -v h="$h" '/done:/ {
          s = $0; sub(/.*done: /, "", s); split(s, a, " "); n = $0; sub(/.*\(/, "", n); split(n, b, " ")
          print r, t, l, h, b[1], a[1] }' "o_$name/$name.log"
      done
    done
  done
  i=$((i + 1))
done
