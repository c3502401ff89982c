#!/bin/sh
# Cost of finite strain on the paper's test (doc/accuracy-cost.md, "small
# against finite"): each finite deck input/paper/finite_<m>.nml is run right
# after the small-strain deck of the same scene and mesh (Fig. 1(b) or 2(a)),
# one run at a time, so that the two see the same machine load.
#
#   sh postproc/paper/finite-cost.sh EXE RUNS [PAIR ...]
#
# EXE   the raccord executable (Release build)
# RUNS  folder of the runs: RUNS/<deck>/ (the folder tools/paper-figures.sh
#       draws from; existing runs of these decks are replaced)
# PAIR  any of nts_slave_block nts_slave_disc mortar_p1_slave_block
#       mortar_p1_slave_disc (default: all four; fine mesh), or
#       coarse_mortar_p1_slave_block (the coarse pair of tests/finite)
#
# Prints one line per run: wall and CPU (user + system) seconds of the
# raccord process (/usr/bin/time when present, else the shell's date for
# the wall time only), the steps and elements from the log, and CPU ns per
# element per step; then the finite/small ratios per pair. POSIX sh + awk.
set -eu
exe=$1 runs=$2
shift 2
pairs=${*:-nts_slave_block nts_slave_disc mortar_p1_slave_block mortar_p1_slave_disc}
root=$(cd "$(dirname "$0")/../.." && pwd)
mkdir -p "$runs"

# run DECK: run it and print "DECK wall cpu steps elements"
run() {
  d=$1
  rm -rf "${runs:?}/$d"
  if [ -x /usr/bin/time ]; then
    /usr/bin/time -f '%e %U %S' -o "$runs/$d.time" "$exe" --quiet --output "$runs/$d" "$root/input/paper/$d.nml" ||
      { echo "finite-cost: $d failed; log: $runs/$d/$d.log" >&2; exit 1; }
    set -- $(tail -n 1 "$runs/$d.time")
    wall=$1 cpu=$(awk -v u="$2" -v s="$3" 'BEGIN { printf "%.2f", u + s }')
  else
    t0=$(date +%s)
    "$exe" --quiet --output "$runs/$d" "$root/input/paper/$d.nml" ||
      { echo "finite-cost: $d failed; log: $runs/$d/$d.log" >&2; exit 1; }
    wall=$(( $(date +%s) - t0 )) cpu=NA
  fi
  rm -f "$runs/$d.time"
  log=$runs/$d/$d.log
  steps=$(sed -n 's/.*done: \([0-9]*\) steps in.*/\1/p' "$log" | tail -n 1)
  nel=$(sed -n 's/^mesh .*nodes, \([0-9]*\) elements.*/\1/p' "$log" | head -n 1)
  echo "$d $wall $cpu $steps $nel"
}

printf '%-30s %8s %8s %7s %6s %10s   load average before the pair\n' run wall_s cpu_s steps elems cpu_ns/el/st
for p in $pairs; do
  case "$p" in
    nts_*) small=fig1b_$p ;;
    mortar_p1_*) small=fig2a_$p ;;
    coarse_mortar_p1_slave_block) small=reg_mortar_p1_slave_block ;;
    *) echo "finite-cost: unknown pair '$p'" >&2; exit 2 ;;
  esac
  load=$(cut -d ' ' -f 1-3 /proc/loadavg 2>/dev/null || echo '?')
  for d in "$small" "finite_$p"; do
    run "$d"
  done | awk -v load="$load" '
    { n++; name[n] = $1; w[n] = $2; c[n] = $3; s[n] = $4; e[n] = $5
      ns = (c[n] == "NA") ? "NA" : sprintf("%.0f", 1e9 * c[n] / (s[n] * e[n]))
      printf "%-30s %8s %8s %7d %6d %10s   %s\n", $1, $2, $3, $4, $5, ns, (n == 1 ? load : "") }
    END { if (n == 2) printf "%-30s wall x %.2f, cpu x %s, steps x %.2f\n", "  finite / small", w[2] / w[1], \
            (c[1] == "NA" ? "NA" : sprintf("%.2f", c[2] / c[1])), s[2] / s[1] }'
done
