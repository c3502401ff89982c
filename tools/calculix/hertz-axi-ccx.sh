#!/bin/sh
# CalculiX comparison of the axisymmetric Hertz case (tests/axisymmetric/data,
# doc/verification.md section 15.4): a sphere R = 10 mm on a block, the same
# Q4 mesh as CAX4 elements, static, frictionless surface-to-surface contact
# with the block top as slave, the sphere's flat top driven down 0.15 mm.
#
#   sh tools/calculix/hertz-axi-ccx.sh [OUTDIR] [MESH]
#
# OUTDIR  default results/hertz_axi/calculix; gets mesh.inp, hertz_axi.inp,
#         the ccx outputs and ccx_force.txt: the axial reaction of the
#         sphere's top as ccx prints it and times 180 (see below).
# MESH    default tests/axisymmetric/data/hertz_axi_q4.msh.
#
# The model: tools/calculix/msh2inp.awk writes the mesh as CPE4, turned to
# CAX4 here (x = r, y the axis, as raccord reads it); E = 200000 MPa,
# nu = 0.3; block bottom clamped, the axis nodes held radially (raccord
# does this itself); sphere top u_z = -0.15 mm; contact
# PRESSURE-OVERCLOSURE=LINEAR, K = 1e7 MPa/mm (penetration about 7e-4 mm at
# the peak); one *STATIC step, NLGEOM off. ccx 2.20 expands CAX4 into a
# wedge of bricks and prints forces for that segment: the reaction times
# 180 matched raccord's ring total to 0.5 % (2-degree segment, inferred
# from that match, not from the manual). Node-to-surface contact (HARD,
# K = 1e8 or 1e9) did not converge on this mesh, with the top driven or a
# pressure on it (increment below the minimum at 10-35 % of the load).
# CSTR of surface-to-surface contact is printed per slave face point and
# too noisy there for a pressure profile; only the force is compared.
# Exit 0 when done or when ccx is not installed (message, nothing written),
# 1 when ccx fails.
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:-results/hertz_axi/calculix}
mesh=${2:-$root/tests/axisymmetric/data/hertz_axi_q4.msh}
ccx=${CCX:-ccx}
if ! command -v "$ccx" > /dev/null 2>&1; then
  echo "hertz-axi-ccx: CalculiX (ccx) is not installed; skipping the comparison (Debian: apt-get install calculix-ccx)"
  exit 0
fi
[ -f "$mesh" ] || { echo "hertz-axi-ccx: no mesh $mesh" >&2; exit 1; }
mesh=$(cd "$(dirname "$mesh")" && pwd)/$(basename "$mesh")
mkdir -p "$out"
out=$(cd "$out" && pwd)
cd "$out"
rm -f ccx_force.txt hertz_axi.dat hertz_axi.frd hertz_axi.sta

awk -f "$root/tools/calculix/msh2inp.awk" "$mesh" | sed 's/TYPE=CPE4,/TYPE=CAX4,/' > mesh.inp
cat > hertz_axi.inp <<EOF
*HEADING
raccord axisymmetric Hertz: sphere on a block, CAX4, surface-to-surface, slave = block top (written by tools/calculix/hertz-axi-ccx.sh)
** units: mm, N, MPa; x = r, y the axis
*INCLUDE, INPUT=mesh.inp
*MATERIAL, NAME=STEEL
*ELASTIC
200000., 0.3
*SOLID SECTION, ELSET=sphere, MATERIAL=STEEL
*SOLID SECTION, ELSET=block, MATERIAL=STEEL
*SURFACE INTERACTION, NAME=FRICTIONLESS
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR
${CCX_K:-1e7}
*CONTACT PAIR, INTERACTION=FRICTIONLESS, TYPE=SURFACE TO SURFACE
S_block_top, S_sphere_arc
*BOUNDARY
block_bottom, 1, 2
block_axis, 1, 1
sphere_axis, 1, 1
*STEP
*STATIC
0.05, 1.0, 1e-9, 0.05
*BOUNDARY
sphere_top, 2, 2, -0.15
*NODE PRINT, NSET=sphere_top, TOTALS=ONLY
RF
*END STEP
EOF

start=$(date +%s)
if ! "$ccx" -i hertz_axi > ccx.log 2>&1 || grep -q '\*ERROR' ccx.log; then
  echo "hertz-axi-ccx: ccx failed; see $out/ccx.log and hertz_axi.sta" >&2
  grep -A2 '\*ERROR' ccx.log >&2 || true
  exit 1
fi
ry=$(awk '/total force .* for set SPHERE_TOP/ { getline; getline; ry = $2 } END { print ry }' hertz_axi.dat)
awk -v ry="$ry" 'BEGIN { printf "# sphere top axial reaction: as printed, times 180 (ring total)\n%.8e %.8e\n", ry, 180*ry }' \
  > ccx_force.txt
echo "hertz-axi-ccx: sphere top reaction $ry N as printed, $(tail -n 1 ccx_force.txt | cut -d' ' -f2) N times 180; $(( $(date +%s) - start )) s"
