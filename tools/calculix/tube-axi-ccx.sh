#!/bin/sh
# CalculiX comparison of the axisymmetric finite-strain tube
# (doc/verification.md, "Axisymmetric finite strain"): a long neo-Hooke tube
# A = 1, B = 2, a slice of height 0.2 held in z on both faces, its bore
# driven out to 1.5 A; CAX8, 8 elements through the wall (the mesh of
# tests/axisymmetric/test_axi_finite_runs.f90, test_tube), static, NLGEOM.
#
#   sh tools/calculix/tube-axi-ccx.sh [OUTDIR] [NU] [TYPE] [BORE]
#
# OUTDIR  default results/tube_axi/calculix; gets tube.inp, the ccx outputs
#         and ccx_result.txt: the outer radial displacement u(b) (node 17,
#         r = 2, z = 0), and the radial reaction of the bore as ccx prints it
#         and times 180 (ccx expands CAX8 into a 2-degree wedge, as
#         tools/calculix/hertz-axi-ccx.sh). The displacement is the quantity
#         compared: the reaction times 180 is 3.6 % below the Lame closed
#         form of the same mesh at a small bore displacement (0.005) with
#         *ELASTIC too, so that factor does not hold for this model
#         (doc/verification.md).
# NU      Poisson's ratio, default 0.45 (E = 1); *HYPERELASTIC, NEO HOOKE
#         with C10 = G/2, D1 = 2/K, the same law as raccord's neo_hooke.
# TYPE    CAX8 (default, 8 x 1 elements) or CAX4 (16 x 2).
# BORE    the bore's radial displacement, default 0.5.
# Exit 0 when done or when ccx is not installed (message, nothing written),
# 1 when ccx fails.
set -eu
out=${1:-results/tube_axi/calculix}
nu=${2:-0.45}
etype=${3:-CAX8}
bore=${4:-0.5}
ccx=${CCX:-ccx}
if ! command -v "$ccx" > /dev/null 2>&1; then
  echo "tube-axi-ccx: CalculiX (ccx) is not installed; skipping the comparison (Debian: apt-get install calculix-ccx)"
  exit 0
fi
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
cd "$out"
rm -f ccx_result.txt tube.dat tube.frd tube.sta

# 8 x 1 CAX8 or 16 x 2 CAX4 on [1, 2] x [0, 0.2], nodes numbered as write_mesh_inp does
{
echo "*HEADING"
echo "raccord axisymmetric neo-Hooke tube, bore driven to 1.5 A (written by tools/calculix/tube-axi-ccx.sh)"
if [ "$etype" = CAX8 ]; then nx=8; ny=1; else nx=16; ny=2; fi
sh "$here/../rect-mesh-inp.sh" "$etype" "$nx" "$ny" 1 2 0 0.2 12 bore=left faces=bottom+top
awk -v nu="$nu" -v bore="$bore" 'BEGIN {
  g = 1.0 / (2.0 * (1.0 + nu)); k = 1.0 / (3.0 * (1.0 - 2.0 * nu))
  print "*MATERIAL, NAME=RUBBER"
  print "*HYPERELASTIC, NEO HOOKE"
  printf "%.12e, %.12e\n", g / 2.0, 2.0 / k
  print "*SOLID SECTION, ELSET=body, MATERIAL=RUBBER"
  print "*BOUNDARY"
  print "faces, 2, 2"
  print "*STEP, NLGEOM, INC=1000"
  print "*STATIC"
  print "0.05, 1.0, 1e-6, 0.05"
  print "*BOUNDARY"
  print "bore, 1, 1, " bore
  print "*NODE PRINT, NSET=bore, TOTALS=ONLY"
  print "RF"
  print "*NODE PRINT, NSET=faces"
  print "U"
  print "*END STEP"
}'
} > tube.inp

if ! "$ccx" -i tube > ccx.log 2>&1 || grep -q '\*ERROR' ccx.log; then
  echo "tube-axi-ccx: ccx failed; see $out/ccx.log and tube.sta" >&2
  grep -A2 '\*ERROR' ccx.log >&2 || true
  exit 1
fi
# u(b) at node 17 and the bore's total force, from the last increment's blocks
awk '/displacements \(vx,vy,vz\) for set FACES/ { blk = 1; next }
  /total force/ { blk = 0; getline; getline; fr = $1 }
  blk && $1 == 17 { ub = $2 }
  END { printf "u(b) %.8e; bore radial force, ccx as printed %.8e, times 180 %.8e\n", ub, fr, 180 * fr }' \
  tube.dat | tee ccx_result.txt
