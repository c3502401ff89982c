#!/bin/sh
# One table of a problem of the accuracy-cost study (tools/accuracy-cost.sh):
# a line per case of META (case elem method level h t_load), with the errors
# of CASEDIR/eval.txt (raccord_study_eval), the cost from raccord's log
# (elements, steps, wall time, contact time) and from GNU time (time.txt:
# wall, user, sys, peak RSS). '-' where a case has no result yet.
#
#   sh postproc/accuracy-cost/table.sh META SWEEPDIR > TABLE
#
# Columns: case elem method level h nelem steps <errors...> wall_s cpu_s
# ns_el_step (CPU time / (elements x steps)) contact_share (search, matching
# and multiplier solve over raccord's wall time) rss_MB.
set -eu
meta=$1
dir=$2
keys=
while read -r c rest; do
  case "$c" in '#'*) continue ;; esac
  if [ -f "$dir/$c/eval.txt" ]; then keys=$(awk '{ printf "%s ", $1 }' "$dir/$c/eval.txt"); break; fi
done < "$meta"
echo "# case elem method level h nelem steps ${keys}wall_s cpu_s ns_el_step contact_share rss_MB"
grep -v '^#' "$meta" | while read -r c elem meth lev h tl; do
  d=$dir/$c
  awk -v c="$c" -v elem="$elem" -v meth="$meth" -v lev="$lev" -v h="$h" -v keys="$keys" \
      -v evalf="$d/eval.txt" -v logf="$d/case.log" -v timef="$d/time.txt" -v mshdir="$d" '
    BEGIN {
      nelem = "-"; steps = "-"; wall = "-"; contact = 0; havec = 0
      while ((getline line < logf) > 0) {
        if (line ~ /^mesh / && match(line, /[0-9]+ elements/)) nelem = substr(line, RSTART, RLENGTH - 9) + 0
        if (line ~ /done: [0-9]+ steps in/) {
          n = split(line, w, " ")
          for (i = 1; i <= n; i++) { if (w[i] == "done:") steps = w[i + 1]; if (w[i] == "in" && w[i + 2] == "s") wall = w[i + 1] }
        }
        if (line ~ /search and matching/) {
          n = split(line, w, " ")
          for (i = 1; i <= n; i++) {
            if (w[i] == "matching" || w[i] == "solve") { contact += w[i + 1]; havec = 1 }
          }
        }
      }
      nk = split(keys, k, " ")
      while ((getline line < evalf) > 0) { split(line, w, " "); val[w[1]] = w[2] }
      cpu = "-"; rss = "-"; twall = "-"
      if ((getline line < timef) > 0) { split(line, t, " "); twall = t[1]; cpu = t[2] + t[3]; rss = t[4] / 1024 }
      if (wall == "-") wall = twall
      printf "%s %s %s %s %s %s %s", c, elem, meth, lev, h, nelem, steps
      for (i = 1; i <= nk; i++) printf " %s", ((k[i] in val) ? val[k[i]] : "-")
      nsel = "-"
      if (cpu != "-" && steps != "-" && nelem != "-" && steps > 0) nsel = sprintf("%.1f", 1e9 * cpu / (steps * nelem))
      share = "-"
      if (havec && wall != "-" && wall > 0) share = sprintf("%.3f", contact / wall)
      printf " %s %s %s %s %s\n", wall, (cpu == "-" ? "-" : sprintf("%.2f", cpu)), nsel, share, (rss == "-" ? "-" : sprintf("%.1f", rss))
    }'
done
