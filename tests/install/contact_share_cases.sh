#!/bin/sh
# tools/contact-share.sh (CTest contact_share): --help answers with exit 0,
# a bad option or a missing binary exits 2 with a message, and a run on a
# small contact scene prints its line: with perf, the run's and the
# contact's seconds and a share between 0 and 100 %; without perf (or not
# permitted), the log's two wall-clock shares.
#
#   sh contact_share_cases.sh SOURCE_DIR RACCORD
set -eu
src=$1
bin=$2
tool=$src/tools/contact-share.sh
fail() { echo "contact_share: $*"; exit 1; }
sh "$tool" --help | grep -q 'contact-share.sh \[-b RACCORD\]' || fail "--help gives no usage"
set +e
out=$(sh "$tool" -x 2>&1); rc=$?
[ $rc -eq 2 ] || fail "-x exited $rc, not 2"
echo "$out" | grep -q 'unknown option -x' || fail "no message for -x: $out"
out=$(sh "$tool" -b /nonexistent/raccord 2>&1); rc=$?
[ $rc -eq 2 ] || fail "a missing binary exited $rc, not 2"
echo "$out" | grep -q 'no executable' || fail "no message for a missing binary: $out"
out=$(sh "$tool" -b "$bin" "$src/input/verification/patch/q4_mortar_p1_slave_upper.nml" 2>&1); rc=$?
set -e
echo "$out"
[ $rc -eq 0 ] || fail "the run exited $rc"
echo "$out" | awk '
  $1 == "q4_mortar_p1_slave_upper" {
    n++
    if ($0 ~ /%.*%.*%/) {            # perf: run s, contact s, share, then the log
      if (!($3 > 0) || !($4 >= 0) || $4 > $3) bad = 1
      s = $5; sub(/%/, "", s); if (!(s >= 0 && s <= 100)) bad = 1
    } else if ($0 !~ /[0-9.]+ \+ [0-9.]+ %/) bad = 1
  }
  END { exit (n == 1 && !bad) ? 0 : 1 }' || fail "no well-formed line for the scene"
echo "contact_share: passed"
