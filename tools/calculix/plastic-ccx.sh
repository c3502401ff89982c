#!/bin/sh
# CalculiX comparison of the paper's test with a plastic layer (issue #14;
# doc/reproduction.md, "The paper's test with a plastic layer"): the scene
# of tools/calculix/fig1b-ccx.sh with the block J2 elastoplastic (*PLASTIC),
# small strain, loaded to the full indentation and unloaded, as the raccord
# decks input/paper/plastic_*.nml.
#
#   sh tools/calculix/plastic-ccx.sh [OUTDIR] [MESH]
#
# OUTDIR  default results/paper/calculix-plastic; gets mesh.inp,
#         plastic.inp, the ccx outputs (plastic.dat, .frd, .sta, ccx.log),
#         and, sorted by x:
#         ccx_pressure.txt  deformed x (mm) and contact pressure (MPa,
#                           compression positive) of every block-top node
#                           at the full indentation (end of step 1);
#         ccx_residual.txt  reference x (mm), u_x and u_y (mm) of every
#                           block-top node after the unloading (end of
#                           step 2): the residual surface profile;
#         ccx_force.txt     indentation (mm, the disc top's descent) and
#                           disc-top reaction (N/mm, compression positive)
#                           at every increment of both steps;
#         ccx_numbers.txt   the numbers test_plastic_paper compares with:
#                           disc-top reaction at full depth, peak pressure,
#                           u_y of the block top at x = 0 after unloading,
#                           the work of the disc-top force over the cycle.
# MESH    default input/paper/paper_q4_fine.msh (the mesh of the raccord
#         plastic_* decks); paper_q4_coarse.msh is the test's mesh.
#
# The model differs from fig1b-ccx.sh only in:
# - the block: *ELASTIC 7000, 0.3 and *PLASTIC (von Mises, isotropic
#   hardening) as a table of yield stress against equivalent plastic
#   strain: SY at 0 and SY + H * 10 at 10 (linear hardening; ccx holds the
#   last value beyond the table, which no run reaches), SY = 700 and
#   H = 70 MPa as make_decks.sh (CCX_SY, CCX_H override). The disc stays
#   elastic.
# - two *STATIC steps, NLGEOM off (small strain, as raccord's
#   kinematics = 'small'): the disc top driven to uy = -0.1581 mm, then
#   back to 0 (contact opens on the way); increments from 0.01, at most
#   0.02 of a step, at least 1e-7, up to 1000 per step.
# Everything else is fig1b-ccx.sh's: CPE4 (ccx expands them to bricks,
# fully integrated: no mean dilatation, unlike raccord's j2 Q4 default),
# block bottom clamped, disc top held in x, frictionless *CONTACT PAIR,
# TYPE=NODE TO SURFACE, slave = block top, master = disc arc,
# PRESSURE-OVERCLOSURE=HARD as a linear penalty K = 3.5e7 MPa/mm (CCX_K).
# CCX_EXTRACT_ONLY=1 skips the ccx run and extracts from the plastic.dat
# already in OUTDIR (the fine mesh takes about 40 minutes).
# Exit 0 when done or when ccx is not installed (message, nothing written),
# 1 when ccx fails.
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:-results/paper/calculix-plastic}
mesh=${2:-$root/input/paper/paper_q4_fine.msh}
ccx=${CCX:-ccx}
sy=${CCX_SY:-700}
hm=${CCX_H:-70}
if ! command -v "$ccx" > /dev/null 2>&1; then
  echo "plastic-ccx: CalculiX (ccx) is not installed; skipping the comparison (Debian: apt-get install calculix-ccx)"
  exit 0
fi
[ -f "$mesh" ] || { echo "plastic-ccx: no mesh $mesh" >&2; exit 1; }
mesh=$(cd "$(dirname "$mesh")" && pwd)/$(basename "$mesh")
mkdir -p "$out"
out=$(cd "$out" && pwd)
cd "$out"
if [ "${CCX_EXTRACT_ONLY:-0}" = 1 ]; then
  [ -s plastic.dat ] || { echo "plastic-ccx: CCX_EXTRACT_ONLY=1 but no $out/plastic.dat" >&2; exit 1; }
else
rm -f ccx_pressure.txt ccx_residual.txt ccx_numbers.txt ccx_force.txt plastic.dat plastic.frd plastic.sta

awk -f "$root/tools/calculix/msh2inp.awk" "$mesh" > mesh.inp
out_requests='*NODE PRINT, NSET=block_top
U
*NODE PRINT, NSET=disc_top, TOTALS=ONLY
RF
*CONTACT PRINT
CSTR
*NODE FILE
U
*EL FILE
S, PE
*CONTACT FILE
CSTR'
cat > plastic.inp <<EOF
*HEADING
raccord paper scene with a plastic layer: J2 block, small strain, load and unload, node-to-surface, slave = block top ($(basename "$mesh"), written by tools/calculix/plastic-ccx.sh)
** units: mm, N, MPa; CPE4 plane strain, thickness 1 mm
*INCLUDE, INPUT=mesh.inp
*MATERIAL, NAME=M_DISC
*ELASTIC
70000., 0.3
** block: E = 7000 MPa, nu = 0.3; von Mises, yield stress $sy MPa, linear
** isotropic hardening H = $hm MPa: (yield stress, equivalent plastic strain)
*MATERIAL, NAME=M_BLOCK
*ELASTIC
7000., 0.3
*PLASTIC, HARDENING=ISOTROPIC
$sy, 0.
$(awk -v s="$sy" -v h="$hm" 'BEGIN { printf "%.10g, 10.\n", s + 10 * h }')
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
** step 1: load to the full indentation
*STEP, INC=1000
*STATIC
0.01, 1.0, 1e-7, 0.02
*BOUNDARY
disc_top, 2, 2, -0.1581
$out_requests
*END STEP
** step 2: unload, the disc top back to where it started
*STEP, INC=1000
*STATIC
0.01, 1.0, 1e-7, 0.02
*BOUNDARY
disc_top, 2, 2, 0.
$out_requests
*END STEP
EOF

start=$(date +%s)
if ! "$ccx" -i plastic > ccx.log 2>&1 || grep -q '\*ERROR' ccx.log; then
  echo "plastic-ccx: ccx failed; see $out/ccx.log and plastic.sta" >&2
  grep -A2 '\*ERROR' ccx.log >&2 || true
  exit 1
fi
fi

# Full indentation: the end of step 1, total time 1.
if ! awk -v what='J2 block, small strain, node-to-surface, slave = block top, full indentation' -v at=1 \
    -f "$root/tools/calculix/ccx-pressure.awk" mesh.inp plastic.dat > ccx_pressure.tmp; then
  rm -f ccx_pressure.tmp
  exit 1
fi
{ head -n 1 ccx_pressure.tmp; tail -n +2 ccx_pressure.tmp | sort -g -k1,1; } > ccx_pressure.txt
rm -f ccx_pressure.tmp
# Disc-top reaction at the end of each step (total times 1 and 2).
rf1=$(awk '/total force .* for set DISC_TOP/ { t = $NF; getline; getline; if (t + 0 == 1) ry = $2 } END { print ry }' plastic.dat)
rf2=$(awk '/total force .* for set DISC_TOP/ { t = $NF; getline; getline; ry = $2 } END { print ry }' plastic.dat)
# After unloading: block-top displacements at the last time printed.
awk 'FNR == 1 { file++ }
  file == 1 && /^\*NODE$/ { innode = 1; next }
  file == 1 && /^\*NSET, NSET=block_top$/ { inset = 1; innode = 0; next }
  file == 1 && /^\*/ { innode = 0; inset = 0; next }
  file == 1 && innode { split($0, a, /, */); x0[a[1] + 0] = a[2]; next }
  file == 1 && inset { n = split($0, a, /, */); for (k = 1; k <= n; k++) if (a[k] != "") top[a[k] + 0] = 1; next }
  file == 2 && /displacements \(vx,vy,vz\) for set BLOCK_TOP/ { blk = 1; t = $NF; next }
  file == 2 && /^ *$/ { next }
  file == 2 && blk && NF == 4 && $1 ~ /^[0-9]+$/ { ux[t, $1 + 0] = $2; uy[t, $1 + 0] = $3; last = t; next }
  file == 2 { blk = 0 }
  END {
    print "# CalculiX J2 block, small strain, after unloading (time " last "): x0 (mm), ux, uy (mm) of the block top"
    for (n in top) printf "%.10g %.10g %.10g\n", x0[n], ux[last, n], uy[last, n]
  }' mesh.inp plastic.dat > ccx_residual.tmp
{ head -n 1 ccx_residual.tmp; tail -n +2 ccx_residual.tmp | sort -g -k1,1; } > ccx_residual.txt
rm -f ccx_residual.tmp
# Work done on the bodies over the cycle, the trapezoidal sum of Ry d(uy)
# over the increments (uy = -0.1581 t in step 1, -0.1581 (2 - t) in
# step 2): the energy the cycle leaves in the layer, dissipated by plastic
# flow or stored in its residual stresses (the disc ends unloaded).
wcyc=$(awk '/total force .* for set DISC_TOP/ { t = $NF; getline; getline; u = (t <= 1) ? -0.1581 * t : -0.1581 * (2 - t)
  w += 0.5 * ($2 + pr) * (u - pu); pr = $2; pu = u } END { printf "%.6g", w }' plastic.dat)
awk '/total force .* for set DISC_TOP/ { t = $NF; getline; getline; u = (t <= 1) ? 0.1581 * t : 0.1581 * (2 - t)
  if (!n++) print "# CalculiX J2 block, small strain: indentation (mm), disc-top reaction (N/mm), total time"
  printf "%.8g %.8g %s\n", u, -$2, t }' plastic.dat > ccx_force.txt
# the run time of ccx (kept from the run when only extracting)
if [ "${CCX_EXTRACT_ONLY:-0}" = 1 ]; then
  secs=$(awk '$1 == "seconds" { print $2 }' ccx_numbers.txt 2>/dev/null || true)
  secs=${secs:-unknown}
else
  secs=$(( $(date +%s) - start ))
fi
peak=$(awk '!/^#/ && $2 > p { p = $2; x = $1 } END { printf "%.6g %.6g", p, x }' ccx_pressure.txt)
uy0=$(awk '!/^#/ { a = ($1 < 0) ? -$1 : $1; if (!n++ || a < b) { b = a; u = $3 } } END { printf "%.6g", u }' ccx_residual.txt)
ninc=$(awk 'NF >= 7 && $1 ~ /^[0-9]+$/ && $3 ~ /^[0-9]+$/ { n++ } END { print n + 0 }' plastic.sta)
{ echo "# plastic-ccx.sh, $(basename "$mesh"), $("$ccx" -v 2>/dev/null | grep -i version | head -n 1 || true), SY = $sy, H = $hm, K = ${CCX_K:-3.5e7}"
  echo "force_at_full_depth $rf1"
  echo "force_after_unload $rf2"
  echo "peak_pressure_and_x $peak"
  echo "residual_uy_at_centre $uy0"
  echo "work_of_cycle $wcyc"
  echo "increments $ninc"
  echo "seconds $secs"; } > ccx_numbers.txt.tmp
mv ccx_numbers.txt.tmp ccx_numbers.txt
cat ccx_numbers.txt
echo "plastic-ccx: wrote $out/ccx_pressure.txt, ccx_residual.txt, ccx_force.txt and ccx_numbers.txt"
