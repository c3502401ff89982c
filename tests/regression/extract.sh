#!/bin/sh
# Reduce a run of a paper deck to the two small text files the regression
# compares (doc/reproduction.md, section "Regression"):
#   <name>.profile.txt   contact profile at result frame 20 (t = T, maximum
#                        indentation): one line per slave node, columns
#                        s0 x y pressure shear status lambda_n lambda_t
#   <name>.reaction.txt  disc_top_Ry and contact1_N at 20 times t_k = k t_end / 20,
#                        k = 1..20 (linear interpolation in the history)
#
#   sh tests/regression/extract.sh RUNDIR NAME DESTDIR
#
# RUNDIR holds NAME.contact1.txt and NAME.history.txt. 9 significant digits.
set -eu
run=$1 name=$2 dest=$3
prof=$run/$name.contact1.txt
hist=$run/$name.history.txt
for f in "$prof" "$hist"; do
  [ -f "$f" ] || { echo "extract: $f does not exist (did the run complete?)" >&2; exit 1; }
done
mkdir -p "$dest"
awk -v fr=20 '
  FNR == 1 { fn = FILENAME; sub(/.*\//, "", fn) }
  /^# frame/ { f = $3; if (f == fr) printf "# %s frame %s time %s\n# s0 x y pressure shear status lambda_n lambda_t\n", fn, $3, $5; next }
  /^#/ { next }
  f == fr && NF >= 10 { printf "%.9g %.9g %.9g %.9g %.9g %d %.9g %.9g\n", $1, $2, $3, $5, $6, $7, $9, $10; n++ }
  END { if (!n) { print "extract: no frame " fr " in " FILENAME > "/dev/stderr"; exit 1 } }' "$prof" > "$dest/$name.profile.txt"
awk '
  FNR == 1 { fn = FILENAME; sub(/.*\//, "", fn) }
  $1 == "#" && $2 ~ /^[0-9]+$/ { c[$3] = $2; next }
  /^#/ { next }
  { n++; t[n] = $(c["time"]); r[n] = $(c["disc_top_Ry"]); q[n] = $(c["contact1_N"]) }
  END {
    if (!n || !("disc_top_Ry" in c)) { print "extract: no disc_top_Ry in " FILENAME > "/dev/stderr"; exit 1 }
    printf "# %s: time disc_top_Ry contact1_N at 20 sampled times\n", fn
    j = 1
    for (k = 1; k <= 20; k++) {
      tk = k * t[n] / 20
      while (j < n - 1 && t[j + 1] < tk) j++
      w = (t[j + 1] > t[j]) ? (tk - t[j]) / (t[j + 1] - t[j]) : 0
      if (w > 1) w = 1
      printf "%.9g %.9g %.9g\n", tk, r[j] + w * (r[j + 1] - r[j]), q[j] + w * (q[j + 1] - q[j])
    }
  }' "$hist" > "$dest/$name.reaction.txt"
