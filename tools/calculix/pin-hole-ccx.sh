#!/bin/sh
# CalculiX reference for the pin in a hole with clearance
# (tests/contact/test_closed.f90, doc/verification.md, "Closed contact
# surfaces"): the same mesh, static, frictionless surface-to-surface
# contact, the pin's outer loop as slave.
#
#   sh tools/calculix/pin-hole-ccx.sh DIR
#
# DIR holds pin_mesh.inp, written by `test_closed CalculiX DIR`: *NODE,
# *ELEMENT (CPE4, ELSET pin and plate), the node sets pin_bore, pin_surf,
# pin_xaxis, hole, plate_outer, the element-face surfaces S_pin and S_hole,
# and pin_load.inp (*BOUNDARY: the bore driven rigidly in x; a traction on
# the bore, the in-memory test's load, left the pin's rigid motion to the
# contact springs alone and ccx diverged in the first increment).
# Writes DIR/pin_hole.inp, runs ccx there and writes DIR/ccx_result.txt:
#   arc_deg  rf_bore_x  rf_plate_x
# arc_deg the largest |theta| (about the pin's centre, deformed) of a pin
# surface node whose gap to the deformed hole polygon is below 1e-3 of the
# clearance, rf_bore_x and rf_plate_x the x reactions of the driven bore
# (the contact resultant on the pin, with its sign) and of the clamped plate
# edge (they balance).
#
# The model: E = 1000, nu = 0.3, CPE4 thickness 1 (ccx expands them into
# bricks); plate edge clamped, the pin's nodes on y = 0 held in y, the bore
# driven in x in one *STATIC step (NLGEOM off, small strain as raccord's
# elements); PRESSURE-OVERCLOSURE=LINEAR with K = 1e6 (penetration at the
# peak pressure about 1e-5, 3e-4 of the pin's displacement).
# Exit 0 when done or when ccx is not installed (message, no result file),
# 1 when ccx fails.
set -eu
dir=${1:?usage: pin-hole-ccx.sh DIR}
ccx=${CCX:-ccx}
# No result file unless this run makes one (the caller reads its absence as
# a skip).
rm -f "$dir/ccx_result.txt"
if ! command -v "$ccx" > /dev/null 2>&1; then
  echo "pin-hole-ccx: CalculiX (ccx) is not installed; skipping the comparison (Debian: apt-get install calculix-ccx)"
  exit 0
fi
cd "$dir"
rm -f ccx_result.txt pin_hole.dat pin_hole.frd pin_hole.sta
cat > pin_hole.inp <<EOF
*HEADING
raccord pin in a hole with clearance, frictionless (written by tools/calculix/pin-hole-ccx.sh)
*INCLUDE, INPUT=pin_mesh.inp
*MATERIAL, NAME=M
*ELASTIC
1000., 0.3
*SOLID SECTION, ELSET=pin, MATERIAL=M
1.
*SOLID SECTION, ELSET=plate, MATERIAL=M
1.
*SURFACE INTERACTION, NAME=SI
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR
${CCX_K:-1e6}
*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE
S_pin, S_hole
*BOUNDARY
plate_outer, 1, 2
pin_xaxis, 2, 2
*STEP
*STATIC
0.05, 1.0, 1e-6, 0.1
*INCLUDE, INPUT=pin_load.inp
*NODE PRINT, NSET=pin_bore
U
*NODE PRINT, NSET=pin_surf
U
*NODE PRINT, NSET=hole
U
*NODE PRINT, NSET=plate_outer, TOTALS=ONLY
RF
*NODE PRINT, NSET=pin_bore, TOTALS=ONLY
RF
*END STEP
EOF
start=$(date +%s)
if ! "$ccx" -i pin_hole > ccx.log 2>&1 || grep -q '\*ERROR' ccx.log; then
  echo "pin-hole-ccx: ccx failed; see $dir/ccx.log and pin_hole.sta" >&2
  grep -A2 '\*ERROR' ccx.log >&2 || true
  exit 1
fi
# The last block of each set in the .dat (the end of the step); node
# coordinates from pin_mesh.inp; the clearance from the hole and pin radii.
awk '
  FNR == 1 { file++ }
  file == 1 && /^\*/ { sec = tolower($0); insec = (sec ~ /^\*node$/ || sec ~ /^\*node,/) ? 1 : 0; next }
  file == 1 && insec { gsub(/,/, " "); x[$1] = $2; y[$1] = $3; next }
  file == 2 && /displacements \(vx,vy,vz\) for set/ { set = $5; getline; mode = 1; next }
  file == 2 && /total force \(fx,fy,fz\) for set/ { st = $6; getline; getline; rf[st] = $1; mode = 0; next }
  file == 2 && mode == 1 && NF >= 3 && $1 ~ /^[0-9]+$/ { ux[set, $1] = $2; uy[set, $1] = $3; has[set, $1] = 1; next }
  file == 2 && NF == 0 { mode = 0 }
  END {
    n = 0; s = 0
    for (k in has) { split(k, a, SUBSEP); if (a[1] == "PIN_BORE") { n++; s += ux["PIN_BORE", a[2]] } }
    upin = s / n
    # Hole polygon (deformed), ordered by angle.
    nh = 0
    for (k in has) { split(k, a, SUBSEP); if (a[1] == "HOLE") { i = a[2]; nh++; hx[nh] = x[i] + ux["HOLE", i]; hy[nh] = y[i] + uy["HOLE", i]; ht[nh] = atan2(hy[nh], hx[nh]) } }
    for (i = 2; i <= nh; i++) { tx = hx[i]; ty = hy[i]; tt = ht[i]; j = i - 1
      while (j >= 1 && ht[j] > tt) { hx[j+1] = hx[j]; hy[j+1] = hy[j]; ht[j+1] = ht[j]; j-- }
      hx[j+1] = tx; hy[j+1] = ty; ht[j+1] = tt }
    rh = 0; for (i = 1; i <= nh; i++) rh += sqrt(hx[i]^2 + hy[i]^2); rh /= nh
    rp = 0; np = 0; cx = 0
    for (k in has) { split(k, a, SUBSEP); if (a[1] == "PIN_SURF") { i = a[2]; np++; cx += x[i] } }
    cx /= np
    for (k in has) { split(k, a, SUBSEP); if (a[1] == "PIN_SURF") { i = a[2]; rp += sqrt((x[i] - cx)^2 + y[i]^2) } }
    rp /= np; clear = rh - rp
    arc = 0
    for (k in has) {
      split(k, a, SUBSEP); if (a[1] != "PIN_SURF") continue
      i = a[2]; px = x[i] + ux["PIN_SURF", i]; py = y[i] + uy["PIN_SURF", i]
      # Signed distance to the hole polygon: the chord the node'"'"'s angle falls on.
      t = atan2(py, px); j = 1
      while (j < nh && ht[j + 1] < t) j++
      j2 = (j < nh) ? j + 1 : 1; if (t < ht[1]) { j = nh; j2 = 1 }
      ex = hx[j2] - hx[j]; ey = hy[j2] - hy[j]; l = sqrt(ex^2 + ey^2)
      g = (ex * (py - hy[j]) - ey * (px - hx[j])) / l   # > 0 inside the hole (the gap)
      if (g < 1e-3 * clear) { th = atan2(py, px - cx - upin); if (th < 0) th = -th; if (th > arc) arc = th }
    }
    printf "# arc_deg rf_bore_x rf_plate_x (tools/calculix/pin-hole-ccx.sh)\n%.6f %.10e %.10e\n", arc * 45 / atan2(1, 1), rf["PIN_BORE"], rf["PLATE_OUTER"]
  }' pin_mesh.inp pin_hole.dat > ccx_result.txt
echo "pin-hole-ccx: $(tail -n 1 ccx_result.txt) (arc in degrees, bore and plate reactions x); $(( $(date +%s) - start )) s"
