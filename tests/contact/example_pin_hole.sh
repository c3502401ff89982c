#!/bin/sh
# The example deck input/examples/pin_hole.nml (a pin in a clearance hole,
# both contact surfaces closed loops, read from the Gmsh mesh) run end to
# end: it is accepted, the plan names the loops, and at the end of the hold
# the bore's and the plate edge's x reactions balance (at rest) to 1e-5
# (measured 1.2e-6: the hold's last ringing),
# some slave nodes are in contact and the energy balance is exact (1e-10);
# the summary's search counters are in range.
#   sh example_pin_hole.sh RACCORD SOURCE_DIR WORK_DIR
set -eu
raccord=$1; src=$2; work=$3
rm -rf "$work"; mkdir -p "$work"
cp "$src/input/examples/pin_hole.nml" "$src/input/examples/pin_hole.msh" "$work/"
cd "$work"
"$raccord" pin_hole.nml > stdout.txt 2>&1 || { echo "FAIL: raccord exited $?"; tail -5 stdout.txt; exit 1; }
grep -q 'slave pin_surface (48 nodes), master hole (48 segments), mortar matching' stdout.txt \
  || { echo "FAIL: the plan does not name the closed pair"; grep 'contact pair' stdout.txt; exit 1; }
# The run summary's search counters (doc/user-guide.md): the lists built at
# least once and at most once per step, and per step some near slave items
# (no more than the surface has), listed master segments and constraints.
grep 'contact pair 1 search: ' stdout.txt | sed 's/.*search: //' | awk '
  { print "search counters: " $0
    for (i = 1; i <= NF; i++) { w[i] = $i; sub(/,$/, "", w[i]) }
    # candidate lists built B times in S steps; per step X slave segments with list candidates of N, Y listed master segments of M, Z constraints
    b = w[4]; s = w[7]; x = w[11]; n = w[18]; y = w[19]; m = w[24]; z = w[25]; seen = 1
    ok = b >= 1 && b <= s && s > 0 && x > 0 && x <= n && y > 0 && y <= m && z > 0 && z <= n + 2 && $0 ~ /constraints$/ }
  END { if (!seen || !ok) { print "FAIL: no search counters in the summary, or out of range"; exit 1 } }'
awk '
  /^# [0-9]+ / { col[$3] = $2; next }
  /^#/ { next }
  { for (i = 1; i <= NF; i++) v[i] = $i }
  END {
    rb = v[col["pin_bore_Rx"]]; rp = v[col["plate_edge_Rx"]]; bal = v[col["energy_balance_rel"]]; act = v[col["contact1_active"]]
    printf "bore Rx %.6e, plate edge Rx %.6e, |sum|/|bore| %.2e, active %d, balance %.2e\n", rb, rp, (rb + rp < 0 ? -(rb + rp) : rb + rp) / (rb < 0 ? -rb : rb), act, bal
    ok = ((rb + rp) ^ 2 <= (1e-5 * rb) ^ 2) && act > 0 && bal ^ 2 < 1e-20
    if (!ok) { print "FAIL: reactions, contact or energy balance"; exit 1 }
    print "pass: example pin_hole"
  }' results/pin_hole/pin_hole.history.txt
