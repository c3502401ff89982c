#!/bin/sh
# CalculiX comparison of the paper's test with finite strain (issue #13;
# doc/reproduction.md, "The paper's test with finite strain"): the scene of
# tools/calculix/fig1b-ccx.sh with NLGEOM and both bodies neo-Hooke, as the
# raccord decks input/paper/finite_*.nml.
#
#   sh tools/calculix/finite-ccx.sh [OUTDIR] [MESH]
#
# OUTDIR  default results/paper/calculix-finite; gets mesh.inp, finite.inp,
#         the ccx outputs (finite.dat, .frd, .sta, ccx.log) and
#         ccx_pressure.txt: two columns, deformed x (mm) and contact
#         pressure (MPa, compression positive) of every block-top node at
#         the full indentation, sorted by x, which postproc/paper/finite.gp
#         overlays.
# MESH    default input/paper/paper_q4_fine.msh (the mesh of the raccord
#         finite_* decks); any 4-node paper mesh works.
#
# The model differs from fig1b-ccx.sh only in:
# - *HYPERELASTIC, NEO HOOKE for both bodies, W = C10 (Ibar1 - 3) +
#   (J - 1)^2 / D1, with C10 = G/2 = E / (4 (1 + nu)) and D1 = 2/K =
#   6 (1 - 2 nu) / E from the E and nu of each body (computed below):
#   raccord's neo_hooke is this law by construction (src/element/raccord_material.f90);
# - *STEP, NLGEOM (total displacement, current geometry); the *STATIC step
#   starts at 0.01 of the load, increments at most 0.02 and at least 1e-7,
#   up to INC=1000 increments, and *CONTROLS lets an increment iterate up
#   to 50 times and be cut back up to 20 times (ccx defaults 16 and 5).
#   What was tried on paper_q4_fine.msh (doc/reproduction.md): with
#   fig1b-ccx.sh's increments (0.05 from 0.05) and default controls ccx
#   stops at 0.945 of the load ("too many cutbacks"); with K = 3.5e6 at
#   0.979 after 5 minutes; with the settings here it reaches 0.99974
#   (indentation 0.15806 mm) and then cuts back below the minimum. The
#   coarse and mid meshes reach 1.0. A step that ends at or above
#   CCX_MIN_TIME (default 0.999) of the load is accepted and its last
#   converged increment extracted, its time written in ccx_pressure.txt
#   (the 4e-5 mm of indentation missing move the peak by about 0.05 %);
#   below that the script fails.
# Everything else is fig1b-ccx.sh's: CPE4 (ccx expands them to bricks),
# block bottom clamped, disc top held in x and driven to uy = -0.1581 mm,
# frictionless *CONTACT PAIR, TYPE=NODE TO SURFACE, slave = block top,
# master = disc arc, PRESSURE-OVERCLOSURE=HARD as a linear penalty
# K = 3.5e7 MPa/mm (CCX_K overrides).
# Exit 0 when done or when ccx is not installed (message, nothing written),
# 1 when ccx fails or does not converge.
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:-results/paper/calculix-finite}
mesh=${2:-$root/input/paper/paper_q4_fine.msh}
ccx=${CCX:-ccx}
if ! command -v "$ccx" > /dev/null 2>&1; then
  echo "finite-ccx: CalculiX (ccx) is not installed; skipping the comparison (Debian: apt-get install calculix-ccx)"
  exit 0
fi
[ -f "$mesh" ] || { echo "finite-ccx: no mesh $mesh" >&2; exit 1; }
mesh=$(cd "$(dirname "$mesh")" && pwd)/$(basename "$mesh")
mkdir -p "$out"
out=$(cd "$out" && pwd)
cd "$out"
rm -f ccx_pressure.txt finite.dat finite.frd finite.sta

# C10 = G/2, D1 = 2/K (the Abaqus/CalculiX neo-Hooke from E and nu)
nh() { awk -v e="$1" -v nu="$2" 'BEGIN { printf "%.10g, %.10g\n", e / (4 * (1 + nu)), 6 * (1 - 2 * nu) / e }'; }

awk -f "$root/tools/calculix/msh2inp.awk" "$mesh" > mesh.inp
cat > finite.inp <<EOF
*HEADING
raccord paper scene with finite strain: neo-Hooke bodies, NLGEOM, node-to-surface, slave = block top ($(basename "$mesh"), written by tools/calculix/finite-ccx.sh)
** units: mm, N, MPa; CPE4 plane strain, thickness 1 mm
*INCLUDE, INPUT=mesh.inp
** disc: E = 70000 MPa, nu = 0.3; C10, D1
*MATERIAL, NAME=M_DISC
*HYPERELASTIC, NEO HOOKE
$(nh 70000 0.3)
** block: E = 7000 MPa, nu = 0.3; C10, D1
*MATERIAL, NAME=M_BLOCK
*HYPERELASTIC, NEO HOOKE
$(nh 7000 0.3)
*SOLID SECTION, ELSET=disc, MATERIAL=M_DISC
1.
*SOLID SECTION, ELSET=block, MATERIAL=M_BLOCK
1.
*SURFACE INTERACTION, NAME=FRICTIONLESS
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD
${CCX_K:-3.5e7}, 1.0
*CONTACT PAIR, INTERACTION=FRICTIONLESS, TYPE=NODE TO SURFACE
S_block_top, S_disc_arc
*BOUNDARY
block_bottom, 1, 2
disc_top, 1, 1
*STEP, NLGEOM, INC=1000
*CONTROLS, PARAMETERS=TIME INCREMENTATION
8, 10, 9, 50, 10, 4, 12, 20
*STATIC
0.01, 1.0, 1e-7, 0.02
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
*EL FILE
S, E
*CONTACT FILE
CSTR
*END STEP
EOF

start=$(date +%s)
"$ccx" -i finite > ccx.log 2>&1 || true
# The last converged increment (a .sta line whose attempt column has no U)
tlast=$(awk 'NF >= 7 && $1 ~ /^[0-9]+$/ && $3 ~ /^[0-9]+$/ { t = $5 } END { print t + 0 }' finite.sta 2>/dev/null || echo 0)
if grep -q '\*ERROR' ccx.log; then
  if awk -v t="$tlast" -v m="${CCX_MIN_TIME:-0.999}" 'BEGIN { exit !(t < m) }'; then
    echo "finite-ccx: ccx failed at step time $tlast of 1.0; see $out/ccx.log and finite.sta" >&2
    grep -A2 '\*ERROR' ccx.log >&2 || true
    exit 1
  fi
  echo "finite-ccx: ccx stopped at step time $tlast of 1.0 (at least ${CCX_MIN_TIME:-0.999}): the last converged increment is used"
fi

# Pressure at the last time of the step, at the deformed x of each block-top node.
if ! awk -v what='NLGEOM, neo-Hooke bodies, node-to-surface, slave = block top' \
    -f "$root/tools/calculix/ccx-pressure.awk" mesh.inp finite.dat > ccx_pressure.tmp; then
  rm -f ccx_pressure.tmp
  exit 1
fi
rf=$(awk '/total force .* for set DISC_TOP/ { getline; getline; ry = $2 } END { print ry }' finite.dat)
{ head -n 1 ccx_pressure.tmp
  echo "# step time $tlast: indentation $(awk -v t="$tlast" 'BEGIN { printf "%.6f", 0.1581 * t }') mm; disc_top reaction Ry = $rf N/mm"
  tail -n +2 ccx_pressure.tmp | sort -g -k1,1; } > ccx_pressure.txt
rm -f ccx_pressure.tmp
echo "finite-ccx: wrote $out/ccx_pressure.txt ($(grep -vc '^#' ccx_pressure.txt) block-top nodes; disc top reaction Ry = $rf N per mm; $(( $(date +%s) - start )) s, $(awk 'NF >= 7 && $1 ~ /^[0-9]+$/ { n++ } END { print n }' finite.sta) increments)"
