#!/bin/sh
# The profile-guided contact build (tools/build-pgo.sh, CTest pgo_build):
#   - bad usage (an unknown option, a missing -t deck) exits 2; a bad
#     RACCORD_PGO and RACCORD_PGO=USE without a profile stop the
#     configure with a message naming the fix;
#   - the quick build (-q, with a -t deck trained on too) ends with a
#     program, and its profile holds the contact sources only (the element
#     kernels stay as in the plain build);
#   - that program and the test build's agree on a frictionless and a
#     frictional scene to round-off: every history column (but the
#     round-off energy balance) and every contact profile column within
#     1e-6 of its peak, the same rows (a wrong or miscompiled contact step
#     differs by far more).
#
#   sh pgo_cases.sh SOURCE_DIR CMAKE RACCORD WORK_DIR
set -eu
src=$1
cmake=$2
plain=$3
work=$4
rm -rf "$work"
mkdir -p "$work"
fail() { echo "pgo_build: $*"; exit 1; }

# Bad usage and bad configurations.
set +e
sh "$src/tools/build-pgo.sh" -x > "$work/usage.txt" 2>&1
rc=$?
set -e
[ $rc -eq 2 ] || fail "build-pgo.sh -x exited $rc, not 2"
grep -q 'unknown option -x' "$work/usage.txt" || fail "no message for -x: $(cat "$work/usage.txt")"
set +e
sh "$src/tools/build-pgo.sh" -t "$work/none.nml" > "$work/usage2.txt" 2>&1
rc=$?
set -e
[ $rc -eq 2 ] || fail "build-pgo.sh -t with a missing deck exited $rc, not 2"
grep -q 'no such deck' "$work/usage2.txt" || fail "no message for a missing -t deck: $(cat "$work/usage2.txt")"
if "$cmake" -S "$src" -B "$work/bad" -DCMAKE_BUILD_TYPE=Release -DRACCORD_PGO=maybe > "$work/bad.txt" 2>&1; then
  fail "RACCORD_PGO=maybe was configured"
fi
grep -q 'give OFF, GENERATE or USE' "$work/bad.txt" || fail "no message for RACCORD_PGO=maybe: $(tail -n 5 "$work/bad.txt")"
if "$cmake" -S "$src" -B "$work/bad2" -DCMAKE_BUILD_TYPE=Release -DRACCORD_PGO=USE \
  -DRACCORD_PGO_DIR="$work/none" > "$work/bad2.txt" 2>&1; then
  fail "RACCORD_PGO=USE without a profile was configured"
fi
grep -q 'no training profile' "$work/bad2.txt" || fail "no message for USE without a profile: $(tail -n 5 "$work/bad2.txt")"

# The quick build.
sh "$src/tools/build-pgo.sh" -q -t "$src/input/verification/patch/q4_nts_slave_upper.nml" "$work/build" \
  > "$work/build.txt" 2>&1 || { cat "$work/build.txt"; fail "build-pgo.sh -q failed"; }
grep -q 'trained on .*q4_nts_slave_upper.nml' "$work/build.txt" || fail "the -t deck was not trained on: $(cat "$work/build.txt")"
[ -x "$work/build/raccord" ] || fail "no program $work/build/raccord"
n=$(ls "$work/build/pgo-profile" | grep -c '\.gcda$' || true)
[ "$n" -gt 0 ] || fail "no profile in $work/build/pgo-profile"
others=$(ls "$work/build/pgo-profile" | grep '\.gcda$' | grep -v '#src#contact#' || true)
[ -z "$others" ] || fail "profile beyond src/contact: $others"
echo "pgo_build: quick build done, $n contact sources profiled"

# The same scenes with both programs.
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
for deck in verification/patch/q4_mortar_p1_slave_upper.nml verification/sliding/q4_mortar_p1_mu030.nml; do
  name=$(basename "$deck" .nml)
  dir=$src/input/$(dirname "$deck")
  (cd "$dir" && "$plain" -q -o "$work/plain/$name" "$src/input/$deck") || fail "plain run of $deck failed"
  (cd "$dir" && "$work/build/raccord" -q -o "$work/pgo/$name" "$src/input/$deck") || fail "profile-guided run of $deck failed"
  for f in "$name.history.txt" "$name.contact1.txt"; do
    awk -v file="$f" -v tol=1e-6 '
      FNR == 1 { k++ }
      /^# [0-9]+ energy_balance/ { skip[$2] = 1 }
      /^# [0-9]+ (kinetic|internal|[a-z_]*_work)$/ { energy[$2] = 1 }
      /^#/ || NF == 0 { next }
      k == 1 { na++; for (c = 1; c <= NF; c++) { a[na, c] = $c; v = $c < 0 ? -$c : $c; if (v > pk[c]) pk[c] = v }; nc = NF; next }
      { nb++; for (c = 1; c <= NF; c++) b[nb, c] = $c }
      END {
        if (na == 0 || na != nb) { printf "pgo_build: %s: %d rows against %d\n", file, nb, na; exit 1 }
        # the energies and works against the largest of them (a work that
        # stays at round-off, as contact work in a patch test, has no scale
        # of its own)
        emax = 0
        for (c in energy) if (pk[c] > emax) emax = pk[c]
        for (c in energy) pk[c] = emax
        worst = 0
        for (c = 1; c <= nc; c++) {
          if (skip[c] || pk[c] == 0) continue
          for (i = 1; i <= na; i++) { d = a[i, c] - b[i, c]; if (d < 0) d = -d; if (d / pk[c] > worst) { worst = d / pk[c]; wc = c } }
        }
        printf "pgo_build: %s: %d rows, largest difference %.2e of its column peak (column %d)\n", file, na, worst, wc
        exit worst <= tol ? 0 : 1
      }' "$work/plain/$name/$f" "$work/pgo/$name/$f" || fail "$f differs beyond round-off"
  done
done
echo "pgo_build: passed"
