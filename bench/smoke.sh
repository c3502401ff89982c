#!/bin/sh
# Smoke test of raccord_bench (CTest bench_smoke): a tiny Q4 and Q8 case,
# small strain and finite strain (Q4f, Q8f), elastic and J2 (Q4p, Q4pf, ...),
# on 1 and 2 threads must print both lines and the ceiling line per case,
# with positive timings, speed-ups that are numbers (not judged: on a
# loaded machine 2 threads can print 0.00), and an energy balance at
# round-off for small strain, below 1e-6 for finite strain (O(dt^2), doc/theory-finite.md), below 1e-4 for J2 (the
# plastic work is a term of the balance, closed to the step error of the
# kinks at yield onset, doc/theory-plasticity.md section 6) (the benchmark's own
# check that the kernel it times is right). Timings are not judged: a test
# asserts no speed.
set -eu
bench=$1
# A bad argument: the message and exit 1, no ERROR STOP backtrace; --clock
# cpu without --threads times one thread, with --threads 2 it is refused.
if err=$("$bench" --clock cpu --threads 2 100 2>&1); then echo "bench_smoke: --clock cpu --threads 2 was accepted"; exit 1; fi
echo "$err" | grep -q 'give --threads 1' || { echo "bench_smoke: no message for --clock cpu --threads 2: $err"; exit 1; }
if echo "$err" | grep -q -e Backtrace -e 'ERROR STOP'; then echo "bench_smoke: a bad argument printed a backtrace: $err"; exit 1; fi
cpu=$(OPENBLAS_NUM_THREADS=1 "$bench" --clock cpu --type q4 --repeat 1 --min-time 0.01 200) || {
  echo "bench_smoke: --clock cpu without --threads failed"; exit 1; }
echo "$cpu" | awk '$1 == "Q4" { n++; if ($4 != 1) bad = 1 } END { exit (n == 1 && !bad) ? 0 : 1 }' || {
  echo "bench_smoke: --clock cpu without --threads should time one thread, one line:"; echo "$cpu"; exit 1; }
out=$(OPENBLAS_NUM_THREADS=1 "$bench" --type all --kinematics all --material all --threads 2 --repeat 2 --min-time 0.01 2000) || {
  echo "bench_smoke: raccord_bench failed"; exit 1; }
echo "$out"
echo "$out" | awk '
  $1 ~ /^Q[48]p?f?$/ {
    lines[$1 " " $4]++
    for (i = 6; i <= 14; i++) if (!($i + 0 >= 0) || $i == "NaN") { print "bench_smoke: bad column " i " in: " $0; bad = 1 }
    # timings > 0; the speed-ups (columns 13, 14) need only be numbers >= 0
    # (checked above): on a loaded machine 2 threads can print 0.00
    if ($6 + 0 <= 0 || $8 + 0 <= 0) { print "bench_smoke: a timing is not positive: " $0; bad = 1 }
    b = $18 + 0; if (b < 0) b = -b
    tol = ($1 ~ /p/) ? 1e-4 : (($1 ~ /f/) ? 1e-6 : 1e-9)
    if (!(b < tol)) { print "bench_smoke: energy balance " $18 " is above " tol ": " $0; bad = 1 }
  }
  /^# ceiling Q[48]p?f? / {
    ceil[$3]++
    if (!match($0, /give [0-9.]+x/) || !match($0, /runs at [0-9.]+ of/)) { print "bench_smoke: ceiling line without figures: " $0; bad = 1 }
  }
  END {
    split("Q4,Q8,Q4f,Q8f,Q4p,Q8p,Q4pf,Q8pf", types, ",")
    for (k in types) {
      for (t = 1; t <= 2; t++) if (lines[types[k] " " t] != 1) {
        print "bench_smoke: expected one line for " types[k] " on " t " thread(s)"; bad = 1 }
      if (ceil[types[k]] != 1) { print "bench_smoke: expected one ceiling line for " types[k]; bad = 1 }
    }
    exit bad
  }'
