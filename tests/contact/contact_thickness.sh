#!/bin/sh
# Contact stresses are per unit area whatever the body's thickness: the
# shipped patch decks (input/verification/patch, non-matching Q4, mortar
# P1 and P0, and Q8 mortar P1) run with thickness = 1 and 2.5 on both
# bodies. Masses and loads scale with t, so the motion is the same and
# the contact pressure of every slave node at the last frame must be the
# same to round-off (1e-9 relative), while the contact resultant
# (history contact1_Fy, a force of the whole thickness like the
# reactions) must be 2.5 times larger. Before the fix the pressure and
# the multipliers of the t = 2.5 run read 2.5 times too large.
#   sh contact_thickness.sh RACCORD SOURCE_DIR WORK_DIR
set -eu
raccord=$1; src=$2; work=$3
rm -rf "$work"; mkdir -p "$work"
cp "$src/input/verification/patch/patch_q4.msh" "$src/input/verification/patch/patch_q8.msh" "$work/"
cd "$work"
fail=0
for case in q4_mortar_p1_slave_upper q4_mortar_p0_slave_lower q8_mortar_p1_slave_upper; do
  for t in 1.0 2.5; do
    sed -e "s|hypothesis = 'plane_strain'|hypothesis = 'plane_strain', thickness = $t|" \
      "$src/input/verification/patch/$case.nml" > "${case}_t$t.nml"
    "$raccord" -q -o out "${case}_t$t.nml"
    # columns 5 (pressure) and 9 (lambda_n) of the last frame's closed nodes
    awk '/^# frame/ {n = 0; next} NF >= 10 && $7 > 0 {n++; p[n] = $5; l[n] = $9} END {for (i = 1; i <= n; i++) print p[i], l[i]}' \
      "out/${case}_t$t.contact1.txt" > "p_$t.txt"
    col=$(awk '/^# [0-9]+ contact1_Fy$/ {print $2}' "out/${case}_t$t.history.txt")
    tail -n 1 "out/${case}_t$t.history.txt" | awk -v c="$col" '{print $c}' > "f_$t.txt"
  done
  if ! paste p_1.0.txt p_2.5.txt | awk -v name="$case" '
      {n++; for (k = 1; k <= 2; k++) {d = $k - $(k + 2); if (d < 0) d = -d; r = d / ($k > 0 ? $k : -$k); if (r > w) w = r}}
      END {printf "%s: %d closed nodes, pressure and lambda_n at t = 2.5 against t = 1: max rel diff %.2e\n", name, n, w;
           exit !(n > 0 && w <= 1e-9)}'; then
    echo "FAIL: $case: contact stresses depend on the thickness"; fail=1
  fi
  if ! paste f_1.0.txt f_2.5.txt | awk -v name="$case" '
      {r = $2 / $1; printf "%s: contact1_Fy %.10g (t = 1), %.10g (t = 2.5), ratio %.12g\n", name, $1, $2, r;
       exit !(r > 2.5 - 2.5e-9 && r < 2.5 + 2.5e-9)}'; then
    echo "FAIL: $case: the resultant is not that of the whole thickness"; fail=1
  fi
done
exit $fail
