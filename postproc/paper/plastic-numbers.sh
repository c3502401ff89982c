#!/bin/sh
# Numbers of doc/reproduction.md, "The paper's test with a plastic layer",
# from raccord runs of input/paper/plastic_*.nml and a CalculiX run of
# tools/calculix/plastic-ccx.sh on the same mesh.
#
#   sh postproc/paper/plastic-numbers.sh RUNS [CCXDIR [DECK ...]]
#
# RUNS    folder of the runs, RUNS/<deck>/<deck>.{history,contact1}.txt
# CCXDIR  folder of plastic-ccx.sh's outputs (ccx_numbers.txt,
#         ccx_pressure.txt, ccx_residual.txt); missing: raccord only
# DECK    default plastic_mortar_p1_slave_block plastic_nts_slave_block
# Per deck: the block-bottom reaction at t = T (first history line at or
# after T = t_end/2 of the run's scene), the peak normal stress at frame 20 (mortar: lambda_n,
# node-to-segment: pressure) and its x, the block-top u_y at x = 0 at the
# last frame (the dent), the plastic work at T and at the end, the work
# left in the layer (plastic + internal + kinetic at the end), the least
# contact work over the history lines; then, against CalculiX, the
# relative differences and the largest |dp|/p_max over the block-top
# nodes at t = T and the largest |du_y| after unloading over the dent
# depth (the nodes matched by their order in x: the same mesh nodes).
set -eu
[ "$#" -ge 1 ] || { echo "usage: sh postproc/paper/plastic-numbers.sh RUNS [CCXDIR [DECK ...]]" >&2; exit 2; }
runs=$1
ccx=${2:-}
if [ "$#" -ge 2 ]; then shift 2; else shift "$#"; fi
decks=${*:-plastic_mortar_p1_slave_block plastic_nts_slave_block}
have_ccx=0
[ -n "$ccx" ] && [ -s "$ccx/ccx_numbers.txt" ] && have_ccx=1
if [ "$have_ccx" = 1 ]; then
  head -n 1 "$ccx/ccx_numbers.txt"
  awk '!/^#/ { printf "CalculiX: %s %s\n", $1, $2 }' "$ccx/ccx_numbers.txt"
fi
for d in $decks; do
  h=$runs/$d/$d.history.txt
  c=$runs/$d/$d.contact1.txt
  [ -s "$h" ] && [ -s "$c" ] || { echo "$d: no complete run in $runs/$d" >&2; exit 1; }
  case "$d" in *mortar*) col=9 ;; *) col=5 ;; esac
  # T: half the run's t_end (the resolved scene the run wrote)
  T=$(awk -F= '$1 ~ /^ *t_end *$/ { v = $2; gsub(/[ ,]/, "", v); printf "%.10g", v / 2 }' "$runs/$d/$d.scene.nml" 2>/dev/null || true)
  [ -n "$T" ] || { echo "$d: no t_end in $runs/$d/$d.scene.nml" >&2; exit 1; }
  awk -v T="$T" '!/^#/ && !done && $1 >= T * (1 - 1e-9) { printf "%s reaction_at_T %.2f contact_force_at_T %.2f plastic_at_T %.3f\n", FILENAME ~ /./ ? "" : "", $12, -$20, $26; done = 1 }
    !/^#/ { if ($7 < m) m = $7; if ($4 > ie) ie = $4; last = $0 }
    END { split(last, a); printf "  end: plastic %.3f internal %.3f kinetic %.4f left %.3f; contact work end %.4f, min %.4f (%.2e of the peak internal %.2f)\n", a[26], a[4], a[3], a[26] + a[4] + a[3], a[7], m, m / ie, ie }' "$h" | sed "s/^ reaction/$d: reaction/"
  awk -v col="$col" '/^# frame 20 /{ p = 1; next } /^# frame 21 /{ p = 0 } p && !/^#/ && NF > 5 && $col > m { m = $col; x = $2 } END { printf "  peak at T %.1f MPa at x = %.4f\n", m, x }' "$c"
  awk '/^# frame /{ f = $3; n = 0; next } !/^#/ && NF > 5 { a = ($2 < 0) ? -$2 : $2; if (!n++ || a < best) { best = a; u = $3 } }
    END { printf "  dent at x = 0 after unloading %.5f mm\n", -u }' "$c"
  if [ "$have_ccx" = 1 ]; then
    awk -v col="$col" '/^# frame 20 /{ p = 1; next } /^# frame 21 /{ p = 0 } p && !/^#/ && NF > 5 { print $2, $col }' "$c" | sort -g > plastic-numbers.r.tmp
    grep -v '^#' "$ccx/ccx_pressure.txt" | sort -g > plastic-numbers.c.tmp
    paste -d ' ' plastic-numbers.r.tmp plastic-numbers.c.tmp | awk '{ d = $2 - $4; if (d < 0) d = -d; if (d > dm) { dm = d; xd = $1 } if ($2 > pm) pm = $2; if ($4 > pm) pm = $4; n++ }
      END { printf "  pressure at T against CalculiX: largest |dp| %.1f MPa at x = %.3f, %.4f of the larger peak (%d nodes)\n", dm, xd, dm / pm, n }'
    awk '/^# frame /{ f = $3; next } !/^#/ && NF > 5 { x[f, ++n[f]] = $2; y[f, n[f]] = $3; lf = f } END { for (k = 1; k <= n[lf]; k++) print x[lf, k], y[lf, k] }' "$c" | sort -g > plastic-numbers.r.tmp
    grep -v '^#' "$ccx/ccx_residual.txt" | awk '{ print $1 + $2, $3 }' | sort -g > plastic-numbers.c.tmp
    paste -d ' ' plastic-numbers.r.tmp plastic-numbers.c.tmp | awk '{ d = $2 - $4; if (d < 0) d = -d; if (d > dm) { dm = d; xd = $1 } if (-$4 > dp) dp = -$4; n++ }
      END { printf "  residual surface against CalculiX: largest |du_y| %.5f mm at x = %.3f, %.4f of the dent depth (%d nodes)\n", dm, xd, dm / dp, n }'
    rm -f plastic-numbers.r.tmp plastic-numbers.c.tmp
  fi
done
