#!/bin/sh
# Smoke test of raccord_bench (CTest bench_smoke): a tiny Q4 and Q8 case on
# 1 and 2 threads must print both lines and the ceiling line per case, with
# positive timings and speed-ups and an energy balance at round-off (the
# benchmark's own check that the kernel it times is right). Timings are not
# judged: a test asserts no speed.
set -eu
bench=$1
out=$(OPENBLAS_NUM_THREADS=1 "$bench" --type all --threads 2 --repeat 2 --min-time 0.01 2000) || {
  echo "bench_smoke: raccord_bench failed"; exit 1; }
echo "$out"
echo "$out" | awk '
  $1 == "Q4" || $1 == "Q8" {
    lines[$1 " " $4]++
    for (i = 6; i <= 14; i++) if (!($i + 0 >= 0) || $i == "NaN") { print "bench_smoke: bad column " i " in: " $0; bad = 1 }
    if ($6 + 0 <= 0 || $8 + 0 <= 0 || $13 + 0 <= 0 || $14 + 0 <= 0) { print "bench_smoke: a timing or speed-up is not positive: " $0; bad = 1 }
    b = $18 + 0; if (b < 0) b = -b
    if (!(b < 1e-9)) { print "bench_smoke: energy balance " $18 " is not round-off: " $0; bad = 1 }
  }
  /^# ceiling Q[48] / {
    ceil[$3]++
    if (!match($0, /give [0-9.]+x/) || !match($0, /runs at [0-9.]+ of/)) { print "bench_smoke: ceiling line without figures: " $0; bad = 1 }
  }
  END {
    split("Q4 1,Q4 2,Q8 1,Q8 2", want, ",")
    for (k in want) if (lines[want[k]] != 1) { print "bench_smoke: expected one line for " want[k] " thread(s)"; bad = 1 }
    if (ceil["Q4"] != 1 || ceil["Q8"] != 1) { print "bench_smoke: expected one ceiling line per type"; bad = 1 }
    exit bad
  }'
