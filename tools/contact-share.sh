#!/bin/sh
# Contact's share of a run (issue #16, item 1; doc/performance.md): the
# processor time of search, matching, enforce_contact and the multiplier
# solve against the whole run, for the paper's three target decks or the
# decks given.
#
#   sh tools/contact-share.sh [-b RACCORD] [-r ROUNDS] [DECK.nml ...]
#
# -b RACCORD  the binary (default build/raccord of the Release build)
# -r ROUNDS   runs per deck (default 1); each round runs the decks in turn
# DECK.nml    default input/paper/fig2a_mortar_p1_slave_block.nml,
#             fig1b_nts_slave_block.nml, fig3_mortar_p1_mu020.nml
#
# With `perf` (Debian linux-perf) each run is sampled at 1 kHz on the
# cpu-clock (processor time, one thread): "contact" is the samples in the
# contact modules of src/contact (pattern CONTACT below; libc's memset and
# memmove are left out of both, as in doc/performance.md). Without perf
# only the run's log is read: its wall-clock shares of "search and
# matching" and "multiplier solve", which swing with the machine's load.
# Prints one line per run; exit 0 when every run finished, 1 otherwise,
# 2 on bad usage.
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$root/build/raccord
rounds=1
while [ $# -gt 0 ]; do
  case "$1" in
  -b) [ $# -ge 2 ] || { echo "contact-share: -b needs a binary" >&2; exit 2; }; bin=$2; shift 2 ;;
  -r) [ $# -ge 2 ] || { echo "contact-share: -r needs a number" >&2; exit 2; }; rounds=$2; shift 2 ;;
  -h|--help) sed -n '2,21p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
  -*) echo "contact-share: unknown option $1 (see --help)" >&2; exit 2 ;;
  *) break ;;
  esac
done
case "$rounds" in ''|*[!0-9]*) echo "contact-share: -r takes a whole number, not '$rounds'" >&2; exit 2 ;; esac
[ -x "$bin" ] || { echo "contact-share: no executable $bin (build it: cmake --build build)" >&2; exit 2; }
# the runs start in each deck's folder (its mesh paths are relative to it)
case "$bin" in /*) ;; *) bin=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin") ;; esac
if [ $# -eq 0 ]; then
  set -- "$root/input/paper/fig2a_mortar_p1_slave_block.nml" "$root/input/paper/fig1b_nts_slave_block.nml" \
    "$root/input/paper/fig3_mortar_p1_mu020.nml"
fi
for d in "$@"; do
  [ -f "$d" ] || { echo "contact-share: no deck $d" >&2; exit 2; }
done
# the contact modules' symbols (gfortran: __<module>_MOD_<name>; internal
# procedures appear by their own name: corner_xi here, the others found by
# their place in the program, below). The line shape functions
# (raccord_shape's shape_line, called by the matching of 3-node edges) are
# counted too; in the time loop only edge loads call them besides contact,
# and none of the paper's decks has one.
CONTACT='contact_verlet|contact_search|contact_surface|raccord_mortar|mortar_segments|node_to_segment|raccord_segment|constraint_set|corner_xi|contact_pair|multiplier_solver|band_solver|delassus|_form_MOD|solver_|g1_runs|raccord_shape_MOD_shape_line'
LEFT_OUT='memset|memmove'
have_perf=0
if command -v perf >/dev/null 2>&1 && perf record -q -e cpu-clock -o /dev/null true >/dev/null 2>&1; then have_perf=1; fi
work=$(mktemp -d "${TMPDIR:-/tmp}/contact-share.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT
# Local symbols without a module name (gfortran's internal procedures,
# put.0.isra.0 of the saddle form, and the clones gcc makes of them) are
# counted with the module whose procedures follow them in the program
# (gcc emits a module's internal procedures just before its own): the
# contact ones listed in $work/local.txt. Without nm, by name only.
: >"$work/local.txt"
if command -v nm >/dev/null 2>&1; then
  nm -n --defined-only "$bin" 2>/dev/null | awk -v pat="$CONTACT" '
    $2 ~ /^[tT]$/ {
      if ($3 ~ /_MOD_/) { for (i = 1; i <= n; i++) if ($3 ~ pat) print pend[i]; n = 0 }
      else pend[++n] = $3
    }' >"$work/local.txt"
fi
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
status=0
if [ $have_perf -eq 1 ]; then
  printf '%-34s %5s %9s %9s %8s   %s\n' deck round 'run s' 'contact s' share 'log: matching + solve (wall clock)'
else
  echo "contact-share: perf not found or not permitted; the log's wall-clock shares only" >&2
  printf '%-34s %5s   %s\n' deck round 'log: matching + solve (wall clock)'
fi
r=1
while [ "$r" -le "$rounds" ]; do
  for d in "$@"; do
    name=$(basename "$d" .nml)
    out=$work/$name.$r
    (
      cd "$(dirname "$d")" || exit 1
      if [ $have_perf -eq 1 ]; then
        perf record -q -F 1000 -e cpu-clock -o "$out.data" "$bin" -q -o "$out" "$(basename "$d")" >"$out.stdout" 2>&1
      else
        "$bin" -q -o "$out" "$(basename "$d")" >"$out.stdout" 2>&1
      fi
    ) || { echo "contact-share: $d failed (log $out/$name.log)" >&2; status=1; continue; }
    logshare=$(awk '/search and matching/ {
        for (i = 1; i <= NF; i++) if ($i ~ /^\(/ && $(i+1) ~ /^%\)/) { v = $i; gsub(/[(]/, "", v); s[++n] = v }
      } END { if (n >= 2) printf "%s + %s %%", s[1], s[2]; else printf "?" }' "$out/$name.log")
    if [ $have_perf -eq 1 ]; then
      perf report -i "$out.data" --stdio --no-children --sort symbol -n 2>/dev/null >"$out.report"
      awk -v pat="$CONTACT" -v left="$LEFT_OUT" -v name="$name" -v r="$r" -v logs="$logshare" -v lf="$work/local.txt" '
        BEGIN { while ((getline l < lf) > 0) local[l] = 1 }
        /^#/ || NF < 3 { next }
        { n = $2 + 0; sym = $0; id = "" ; for (i = 1; i < NF; i++) if ($i == "[.]") { id = $(i + 1); break } }
        sym ~ left { next }
        { all += n; if (sym ~ pat || (id in local)) c += n }
        END { if (all == 0) { print name ": no samples" > "/dev/stderr"; exit 1 }
              printf "%-34s %5d %9.2f %9.2f %7.1f%%   %s\n", name, r, all/1000, c/1000, 100*c/all, logs }' "$out.report" || status=1
    else
      printf '%-34s %5d   %s\n' "$name" "$r" "$logshare"
    fi
  done
  r=$((r + 1))
done
exit $status
