#!/bin/sh
# raccord under GNU time, for the accuracy-cost study (tools/accuracy-cost.sh
# gives this script to hpc/sweep-local.sh as the raccord executable).
# Arguments are raccord's. A run with --output DIR writes DIR/time.txt, one
# line "wall_s user_s sys_s maxrss_kB" of the raccord process; other calls
# (--check, --help) pass straight through. The real executable is
# $RACCORD_REAL. TERM, INT and HUP are passed on to raccord itself (GNU time
# does not pass them on), so a stopped sweep leaves no raccord behind.
set -u
real=${RACCORD_REAL:?timed-raccord.sh: set RACCORD_REAL to the raccord executable}
out=
prev=
for a in "$@"; do
  case "$prev" in -o | --output) out=$a ;; esac
  prev=$a
done
if [ -z "$out" ] || [ ! -x /usr/bin/time ]; then exec "$real" "$@"; fi
mkdir -p "$out" || exit 4
rm -f "$out/time.txt"
/usr/bin/time -f '%e %U %S %M' -o "$out/time.txt.part" "$real" "$@" &
tpid=$!
stop() {
  trap '' TERM INT HUP
  pkill -TERM -P "$tpid" 2>/dev/null || kill -TERM "$tpid" 2>/dev/null
  wait "$tpid" 2>/dev/null
  exit "$1"
}
trap 'stop 143' TERM
trap 'stop 130' INT
trap 'stop 129' HUP
wait "$tpid"
code=$?
if [ "$code" -eq 0 ] && [ -s "$out/time.txt.part" ]; then
  tail -n 1 "$out/time.txt.part" > "$out/time.txt"
fi
rm -f "$out/time.txt.part"
exit "$code"
