#!/bin/sh
# Smoke test of raccord_bench_contact (CTest bench_contact_smoke): --help
# answers with the usage and exit 0, a bad argument exits 1 with a message,
# and a tiny run prints one line per method and friction with positive
# figures. Timings are not judged: a test asserts no speed.
set -eu
bench=$1
"$bench" --help | grep -q '^usage: raccord_bench_contact' || { echo "bench_contact_smoke: --help gives no usage"; exit 1; }
if err=$("$bench" many 2>&1); then echo "bench_contact_smoke: a bad step count was accepted"; exit 1; fi
if echo "$err" | grep -q -e Backtrace -e 'ERROR STOP'; then echo "bench_contact_smoke: a bad argument printed a backtrace: $err"; exit 1; fi
out=$("$bench" 20 40) || { echo "bench_contact_smoke: the run failed"; exit 1; }
echo "$out"
echo "$out" | awk '
  $1 == "node_to_segment" || $1 == "mortar" {
    n++
    c = ($1 == "mortar") ? 1 : 0
    if ($(6 + c) + 0 <= 0 || $(7 + c) + 0 <= 0 || $(9 + c) + 0 <= 0) { print "bench_contact_smoke: a timing is not positive: " $0; bad = 1 }
  }
  END { if (n != 4) { print "bench_contact_smoke: expected 4 case lines, got " n; bad = 1 }; exit bad }'
