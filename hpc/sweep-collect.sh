#!/bin/sh
# Collects a sweep folder into one table: per case its number, name, state and
# the last row's value of each history column named (doc/hpc.md).
#
#   sh hpc/sweep-collect.sh SWEEPDIR [COLUMN...]
#
# COLUMN  a column name of <case>.history.txt (its '# N name' header), e.g.
#         time internal left_Rx contact1_N
# State: done (case.h5), incomplete (case.incomplete.h5: raccord stopped on an
# error), killed (case.h5.part: the process died), refused (--check failed),
# not-run. Values are read from the complete history only (a dash otherwise).
# Output: tab-separated, one header line starting with '#'; then the
# parameters of each case as in cases.txt. gnuplot, awk and spreadsheets read it.
set -u
hpc_prog=sweep-collect.sh
hpc_dir=$(cd "$(dirname "$0")" && pwd)
. "$hpc_dir/lib.sh"

[ $# -ge 1 ] || { sed -n '2,/^set -u/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2; exit 1; }
sweep=$1
shift
[ -f "$sweep/cases.txt" ] || { echo "$hpc_prog: $sweep/cases.txt missing" >&2; exit 1; }

printf '# case\tname\tstate'
for c in "$@"; do printf '\t%s' "$c"; done
printf '\tparameters\n'
awk -F '\t' '$1 ~ /^[0-9]+$/' "$sweep/cases.txt" | while IFS="$(printf '\t')" read -r num name params; do
  d=$sweep/$name
  if hpc_case_done "$d"; then state=done
  elif [ -f "$d/case.incomplete.h5" ]; then state=incomplete
  elif [ -f "$d/case.h5.part" ]; then state=killed
  elif [ -f "$d/check.txt" ] && grep -q ERROR "$d/check.txt"; then state=refused
  else state=not-run
  fi
  values=
  if [ "$state" = done ] && [ -f "$d/case.history.txt" ]; then
    values=$(awk -v want="$*" '
      BEGIN { n = split(want, w, " ") }
      $1 == "#" && $2 ~ /^[0-9]+$/ { col[$3] = $2; next }
      $1 !~ /^#/ && NF { for (i = 1; i <= NF; i++) last[i] = $i }
      END { for (i = 1; i <= n; i++) printf "\t%s", ((w[i] in col) ? last[col[w[i]]] : "no-such-column") }' "$d/case.history.txt")
  else
    for c in "$@"; do values="$values	-"; done
  fi
  printf '%s\t%s\t%s%s\t%s\n' "$num" "$name" "$state" "$values" "$params"
done
