#!/bin/sh
# The numbers of doc/reproduction.md, "The paper's test with finite strain":
# the finite-strain decks input/paper/finite_*.nml against the small-strain
# decks of the same scenes (Fig. 1(b), Fig. 2(a)) and against CalculiX with
# NLGEOM (tools/calculix/finite-ccx.sh), at maximum indentation.
#
#   sh postproc/paper/finite-numbers.sh RUNS [CCX_FINITE_FILE] [CCX_SMALL_FILE] > finite-numbers.txt
#
# RUNS holds <deck>/<deck>.contact1.txt and .history.txt (tools/paper-figures.sh
# RUNS folder). Frame 20 (t = T). Normal stress as in numbers.sh: 'pressure'
# (col 5) for node-to-segment, lambda_n (col 9) for mortar; both are
# Cauchy tractions (force over the current length). The CalculiX files are
# two columns x p (compression positive); missing ones are skipped.
set -eu
runs=$1
ccxf=${2:-}
ccxs=${3:-}
frame=20

. "$(dirname "$0")/numbers-lib.sh"

# pair M: the small-strain deck of finite_M
small_of() { case "$1" in nts_*) echo "fig1b_$1" ;; *) echo "fig2a_$1" ;; esac; }
col_of() { case "$1" in nts_*) echo 5 ;; *) echo 9 ;; esac; }
pairs="nts_slave_block nts_slave_disc mortar_p1_slave_block mortar_p1_slave_disc"

# centre NAME: the block top at the slave node nearest x = 0 (slave = block
# decks only): its deformed y, so the layer's thickness there (the block
# spans y in [-0.3, 0]: input/paper/paper.geo) and its nominal compression
centre() {
  block "$1" | awk -v name="$1" '
    { a = ($2 < 0 ? -$2 : $2); if (!n++ || a < best) { best = a; y = $3; x = $2 } }
    END { printf "%-34s block top at x = %+.4f: y = %+.5f mm, layer thickness %.4f mm (nominal compression %.1f %%)\n", \
      name, x, y, 0.3 + y, -100 * y / 0.3 }'
}

# ccx_stats FILE LABEL: peak, contact x range and integral of a two-column profile
ccx_stats() {
  awk -v name="$2" '/^#/ { if ($0 ~ /Ry/) ry = $0; next } NF >= 2 { n++; x[n] = $1; p[n] = $2 }
    END { pk = 0; l = 1e30; r = -1e30; F = 0
      for (i = 1; i <= n; i++) { if (p[i] > pk) { pk = p[i]; xp = x[i] } if (p[i] > 0) { if (x[i] < l) l = x[i]; if (x[i] > r) r = x[i] }
        if (i > 1) F += 0.5 * (p[i] + p[i-1]) * (x[i] - x[i-1]) }
      printf "%-34s peak %8.1f MPa at x = %+.4f  x in [%+.4f, %+.4f], width %.4f mm  integral %7.1f N/mm\n", name, pk, xp, l, r, r - l, F
      if (ry != "") printf "%-34s %s\n", "", ry }' "$1"
}

# done_run NAME: true when the run completed (its final profile and history exist)
done_run() { [ -f "$(prof "$1")" ] && [ -f "$(hist "$1")" ]; }
# why_not NAME: one line on a run that did not complete, with its log's first error
why_not() {
  err=$(grep -m 1 'ERROR' "$runs/$1/$1.log" 2>/dev/null | sed 's/^ERROR \[raccord\] //' || true)
  printf '%-34s did not complete: %s\n' "$1" "${err:-no run}"
}

# as_run FILE NAME: a two-column profile as a one-frame contact profile RUNS/NAME/NAME.contact1.txt
as_run() {
  mkdir -p "$runs/$2"
  { echo "# frame $frame  time 0"
    awk '!/^#/ && NF >= 2 { printf "0 %s 0 0 %s 0 %d 0 %s 0\n", $1, $2, ($2 > 0), $2 }' "$1"; } > "$runs/$2/$2.contact1.txt"
}

echo "# raccord: the paper's test with finite strain (postproc/paper/finite-numbers.sh), frame $frame (t = T)"
echo
echo "## 1. Peak, contact width (x extent of the active slave nodes), integral of the stress over x: small, then finite"
for m in $pairs; do
  stats "$(small_of $m)" "$(col_of $m)"
  if done_run "finite_$m"; then stats "finite_$m" "$(col_of $m)"; else why_not "finite_$m"; fi
done
echo
echo "## 2. Forces at t = T (contact1_Fy: vertical contact force; block_bottom_Ry: the support under the layer)"
for m in $pairs; do
  hist_at "$(small_of $m)"
  if done_run "finite_$m"; then hist_at "finite_$m"; else why_not "finite_$m"; fi
done
echo
echo "## 3. Finite against small, same scene: max |dp| / p_max (p_max the larger peak, the finite one)"
for m in $pairs; do
  if done_run "finite_$m"; then diff2 "$(small_of $m)" "$(col_of $m)" "finite_$m" "$(col_of $m)" "small / finite, $m"; fi
done
echo
echo "## 4. Slave/master asymmetry with finite strain"
if done_run finite_nts_slave_disc; then diff2 finite_nts_slave_block 5 finite_nts_slave_disc 5 "finite NTS, pressure"; fi
diff2 finite_mortar_p1_slave_block 9 finite_mortar_p1_slave_disc 9 "finite mortar P1, lambda_n"
diff2 finite_mortar_p1_slave_block 5 finite_nts_slave_block 5 "finite mortar P1 / NTS, pressure, slave = block"
echo
echo "## 5. The layer under the disc centre"
centre fig1b_nts_slave_block
centre finite_nts_slave_block
centre fig2a_mortar_p1_slave_block
centre finite_mortar_p1_slave_block
if [ -n "$ccxf" ] && [ -s "$ccxf" ]; then
  echo
  echo "## 6. CalculiX with NLGEOM, neo-Hooke bodies (node-to-surface, slave = block, $(basename "$(dirname "$ccxf")")/$(basename "$ccxf"))"
  ccx_stats "$ccxf" "calculix finite"
  as_run "$ccxf" ccx_finite
  diff2 finite_nts_slave_block 5 ccx_finite 5 "raccord finite NTS slave = block / CalculiX"
  if done_run finite_nts_slave_disc; then diff2 finite_nts_slave_disc 5 ccx_finite 5 "raccord finite NTS slave = disc / CalculiX"; fi
  diff2 finite_mortar_p1_slave_block 9 ccx_finite 5 "raccord finite mortar P1 slave = block / CalculiX"
  diff2 finite_mortar_p1_slave_disc 9 ccx_finite 5 "raccord finite mortar P1 slave = disc / CalculiX"
  if [ -n "$ccxs" ] && [ -s "$ccxs" ]; then
    ccx_stats "$ccxs" "calculix small (fig1b)"
    as_run "$ccxs" ccx_small
    diff2 ccx_small 5 ccx_finite 5 "CalculiX small / CalculiX finite"
  fi
fi
# A run that stopped: its last frame beside the runs that completed, at that frame
for m in $pairs; do
  inc=$runs/finite_$m/finite_$m.contact1.incomplete.txt
  done_run "finite_$m" || [ ! -f "$inc" ] || {
    last=$(awk '/^# frame/ { f = $3; t = $5 } END { print f }' "$inc")
    echo
    echo "## 7. finite_$m stopped; its last frame $last against the complete runs at that frame"
    mkdir -p "$runs/partial_finite_$m"
    cp "$inc" "$runs/partial_finite_$m/partial_finite_$m.contact1.txt"
    frame=$last
    stats "partial_finite_$m" "$(col_of $m)"
    stats "$(small_of $m)" "$(col_of $m)"
    case "$m" in *_slave_disc) other=finite_${m%_slave_disc}_slave_block ;; *) other=finite_${m%_slave_block}_slave_disc ;; esac
    if done_run "$other"; then
      stats "$other" "$(col_of $m)"
      diff2 "$other" "$(col_of $m)" "partial_finite_$m" "$(col_of $m)" "$other / finite_$m (frame $last)"
    fi
    frame=20
  }
done
