#!/bin/sh
# CalculiX comparison of Fig. 1(b) (Baillet & Sassi 2003, section 4.1, where
# the paper compares its code with ABAQUS): the paper scene, static,
# frictionless node-to-surface contact with the block top as slave.
#
#   sh tools/calculix/fig1b-ccx.sh [OUTDIR] [MESH]
#
# OUTDIR  default results/paper/calculix; gets mesh.inp, fig1b.inp, the ccx
#         outputs (fig1b.dat, .frd, .sta, ccx.log) and ccx_pressure.txt:
#         two columns, deformed x (mm) and contact pressure (MPa, compression
#         positive) of every block-top node at the full indentation, sorted
#         by x, which postproc/paper/fig1b.gp overlays.
# MESH    default input/paper/paper_q4_fine.msh (the mesh of the raccord
#         Fig. 1(b) decks); any 4-node paper mesh works (paper_q4.msh: 1 s).
#
# The model (doc/reproduction.md, "CalculiX"):
# - the Gmsh mesh extruded into one layer of C3D8 bricks, thickness 1, with
#   uz = 0 on every node: plane strain (tools/calculix/msh2inp.awk, extrude=1);
# - E1 = 70000, E2 = 7000 MPa, nu = 0.3; block bottom clamped, disc top held
#   in x and driven to uy = -0.1581 mm in one *STATIC step, NLGEOM off (small
#   strain, as raccord's elements), automatic increments from 0.05;
# - *CONTACT PAIR, TYPE=NODE TO SURFACE, slave = block top faces, master =
#   disc arc faces, PRESSURE-OVERCLOSURE=HARD, which ccx applies to
#   node-to-surface contact as a linear penalty: K = 3.5e7 MPa/mm (5000 E2;
#   penetration at the peak about 1e-4 mm, 6e-4 of the indentation). The
#   default K (500 E2) gives a peak 0.5 % lower; K = 3.5e8 did not converge
#   (increment below the minimum).
# Exit 0 when done or when ccx is not installed (message, nothing written),
# 1 when ccx fails.
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:-results/paper/calculix}
mesh=${2:-$root/input/paper/paper_q4_fine.msh}
ccx=${CCX:-ccx}
if ! command -v "$ccx" > /dev/null 2>&1; then
  echo "fig1b-ccx: CalculiX (ccx) is not installed; skipping the comparison (Debian: apt-get install calculix-ccx)"
  exit 0
fi
[ -f "$mesh" ] || { echo "fig1b-ccx: no mesh $mesh" >&2; exit 1; }
mesh=$(cd "$(dirname "$mesh")" && pwd)/$(basename "$mesh")
mkdir -p "$out"
out=$(cd "$out" && pwd)
cd "$out"
rm -f ccx_pressure.txt fig1b.dat fig1b.frd fig1b.sta

awk -v extrude=1 -f "$root/tools/calculix/msh2inp.awk" "$mesh" > mesh.inp
cat > fig1b.inp <<EOF
*HEADING
raccord paper scene, Fig. 1(b): node-to-surface, slave = block top ($(basename "$mesh"), written by tools/calculix/fig1b-ccx.sh)
** units: mm, N, MPa; one layer of C3D8, thickness 1 mm, uz = 0: plane strain
*INCLUDE, INPUT=mesh.inp
*MATERIAL, NAME=M_DISC
*ELASTIC
70000., 0.3
*MATERIAL, NAME=M_BLOCK
*ELASTIC
7000., 0.3
*SOLID SECTION, ELSET=disc, MATERIAL=M_DISC
*SOLID SECTION, ELSET=block, MATERIAL=M_BLOCK
*SURFACE INTERACTION, NAME=FRICTIONLESS
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD
${CCX_K:-3.5e7}, 1.0
*CONTACT PAIR, INTERACTION=FRICTIONLESS, TYPE=NODE TO SURFACE
S_block_top, S_disc_arc
*BOUNDARY
block_bottom, 1, 2
disc_top, 1, 1
all_nodes, 3, 3
*STEP
*STATIC
0.05, 1.0, 1e-6, 0.05
*BOUNDARY
disc_top, 2, 2, -0.1581
*NODE PRINT, NSET=block_top
U
*NODE PRINT, NSET=disc_top, TOTALS=ONLY
RF
*CONTACT PRINT
CSTR
*NODE FILE
U
*CONTACT FILE
CSTR
*END STEP
EOF

start=$(date +%s)
if ! "$ccx" -i fig1b > ccx.log 2>&1 || grep -q '\*ERROR' ccx.log; then
  echo "fig1b-ccx: ccx failed; see $out/ccx.log and fig1b.sta" >&2
  grep -A2 '\*ERROR' ccx.log >&2 || true
  exit 1
fi

# Pressure at the last time of the step, on the z = 0 layer (node <= offset),
# at the deformed x = x0 + ux of each block-top node.
awk '
  FNR == 1 { file++ }
  file == 1 && /^\*\* offset/ { off = $3 + 0; next }
  file == 1 && /^\*NODE$/ { innode = 1; next }
  file == 1 && /^\*/ { innode = 0; next }
  file == 1 && innode { sub(/,.*/, "", $1); split($0, a, /, */); x0[a[1] + 0] = a[2]; next }
  file == 2 && /displacements \(vx,vy,vz\) for set BLOCK_TOP/ { blk = "u"; t = $NF; next }
  file == 2 && /contact stress/ { blk = "p"; t = $NF; next }
  file == 2 && /^ *$/ { next }
  file == 2 && NF == 4 && $1 ~ /^[0-9]+$/ {
    if (blk == "u") { ux[t, $1 + 0] = $2; if ($1 + 0 <= off) top[$1 + 0] = 1 }
    if (blk == "p") p[t, $1 + 0] = $2
    last = t; next
  }
  file == 2 { blk = "" }
  END {
    print "# CalculiX node-to-surface, slave = block top, time " last ": x (mm, deformed), pressure (MPa)"
    for (n in top) printf "%.10g %.10g\n", x0[n] + ux[last, n], ((last, n) in p) ? p[last, n] : 0
  }' mesh.inp fig1b.dat | sort -g -k1,1 > ccx_pressure.txt
rf=$(awk '/total force .* for set DISC_TOP/ { getline; getline; ry = $2 } END { print ry }' fig1b.dat)
echo "fig1b-ccx: wrote $out/ccx_pressure.txt ($(grep -vc '^#' ccx_pressure.txt) block-top nodes; disc top reaction Ry = $rf N per mm; $(( $(date +%s) - start )) s)"
