#!/bin/sh
# Runs one case folder of a sweep (made by sweep-gen.sh), or one deck into a
# results folder: skip it if it is complete, else check the deck with
# `raccord --check`, then run `raccord --output CASEDIR DECK`.
# Used by sweep-local.sh and the Slurm templates; doc/hpc.md.
#
#   sh hpc/run-case.sh [-r RACCORD] [-d DECK] CASEDIR
#
# DECK defaults to CASEDIR/case.nml; results are CASEDIR/<stem>.h5 etc., with
# <stem> the deck's name without extension.
#
# Prints one line "case NAME: skipped|done|failed ..." and exits with
# raccord's code (0 also when skipped; 2 when --check refuses the deck).
# Files in CASEDIR: check.txt (--check output), run.out (stdout and stderr of
# the run), attempts.txt (one line per attempt: date, host, job, stage, exit),
# and raccord's own case.h5, case.xmf, case.history.txt, case.log, ...
#
# Environment: RACCORD (the executable); RACCORD_WALLCLOCK_SECONDS or what
# lib.sh's hpc_wallclock_seconds derives from the Slurm job: exported to
# raccord, and passed as --wall-clock when raccord lists that option.
# Restart: when CASEDIR/<stem>.checkpoint.h5 exists (an earlier attempt
# stopped at its limit, or was killed after a periodic checkpoint) and is
# newer than the deck, the run goes on from it (raccord --restart); a deck
# rewritten since starts the case again (raccord deletes the old checkpoint).
# Signals: USR1 is passed on to raccord when it writes checkpoints (lib.sh,
# hpc_raccord_has_checkpoint; it writes one and exits 5), ignored otherwise
# (an older raccord would die on it). TERM is passed on too: a raccord with
# checkpoints stops the same way (exit 5), otherwise it dies and this script
# exits 128+15. INT and HUP stop raccord (TERM) and exit 128+n.
set -u
hpc_prog=run-case.sh
hpc_dir=$(cd "$(dirname "$0")" && pwd)
. "$hpc_dir/lib.sh"

raccord=
deck=
while [ $# -gt 0 ]; do
  case "$1" in
  -r | --raccord) [ $# -ge 2 ] || hpc_die "-r needs a value"; raccord=$2; shift 2 ;;
  -d | --deck) [ $# -ge 2 ] || hpc_die "-d needs a value"; deck=$2; shift 2 ;;
  -*) hpc_die "unknown option '$1' (usage: run-case.sh [-r RACCORD] [-d DECK] CASEDIR)" ;;
  *) break ;;
  esac
done
[ $# -eq 1 ] || hpc_die "usage: run-case.sh [-r RACCORD] [-d DECK] CASEDIR"
dir=${1%/}
name=$(basename "$dir")
[ -n "$deck" ] || deck=$dir/$RACCORD_CASE_STEM.nml
stem=$(basename "$deck")
stem=${stem%.*}
[ -f "$deck" ] || { echo "case $name: failed: no deck $deck"; exit 2; }
mkdir -p "$dir" || { echo "case $name: failed: cannot create $dir"; exit 4; }
raccord=$(hpc_find_raccord "$raccord") || { echo "case $name: failed: no raccord executable (set RACCORD)"; exit 1; }

if hpc_case_done "$dir" "$deck"; then
  echo "case $name: skipped (complete: $dir/$stem.h5)"
  exit 0
fi

attempt() { # stage code
  echo "$(date '+%Y-%m-%dT%H:%M:%S') host=$(uname -n) job=${SLURM_JOB_ID:-none}${SLURM_ARRAY_TASK_ID:+ task=$SLURM_ARRAY_TASK_ID} stage=$1 exit=$2" >> "$dir/attempts.txt"
}

"$raccord" --check "$deck" > "$dir/check.txt" 2>&1
code=$?
if [ "$code" -ne 0 ]; then
  attempt check "$code"
  echo "case $name: failed at check (exit $code): $(hpc_first_error "$dir/check.txt") [$dir/check.txt]"
  exit "$code"
fi

set --
checkpoint=0
if hpc_raccord_has_checkpoint "$raccord"; then checkpoint=1; fi
wall=$(hpc_wallclock_seconds)
if [ -n "$wall" ]; then
  RACCORD_WALLCLOCK_SECONDS=$wall
  export RACCORD_WALLCLOCK_SECONDS
  if [ "$checkpoint" = 1 ]; then set -- --wall-clock "$wall"; fi
fi
ckpt=$dir/$stem.checkpoint.h5
stage=run
if [ "$checkpoint" = 1 ] && [ -f "$ckpt" ] && [ -n "$(find "$ckpt" -newer "$deck" -print 2>/dev/null)" ]; then
  set -- "$@" --restart "$ckpt"
  stage=restart
  echo "case $name: going on from $ckpt"
fi

pid=
got_signal=0
stop() { # signal number
  trap '' TERM INT HUP
  _rc=
  if [ -n "$pid" ]; then kill -TERM "$pid" 2>/dev/null; wait "$pid" 2>/dev/null; _rc=$?; fi
  if [ "$checkpoint" = 1 ] && [ "$_rc" = 5 ]; then
    attempt "$stage" 5
    echo "case $name: stopped by signal $1, checkpoint written (exit 5): resubmit to go on [$dir]"
    exit 5
  fi
  attempt "$stage" "signal-$1"
  echo "case $name: failed: stopped by signal $1 (raccord killed; its .part files are left, a rerun starts again) [$dir]"
  exit $((128 + $1))
}
usr1() {
  got_signal=1
  if [ "$checkpoint" = 1 ] && [ -n "$pid" ]; then
    echo "case $name: SIGUSR1: asking raccord for a checkpoint"
    kill -USR1 "$pid" 2>/dev/null
  else
    echo "case $name: SIGUSR1 ignored (this raccord writes no checkpoint)"
  fi
}
trap 'stop 15' TERM
trap 'stop 2' INT
trap 'stop 1' HUP
trap usr1 USR1

start=$(hpc_now)
"$raccord" "$@" --output "$dir" "$deck" > "$dir/run.out" 2>&1 &
pid=$!
# A trapped signal interrupts wait (status > 128) whether or not raccord
# has ended yet; waiting again returns raccord's own status (127 only if it
# was already collected: then keep what was seen). Asking kill -0 instead
# lost raccord's exit 5 when it ended between the signal and the test.
code=
while :; do
  got_signal=0
  wait "$pid"
  rc=$?
  if [ "$rc" -eq 127 ] && [ -n "$code" ]; then break; fi
  code=$rc
  if [ "$got_signal" = 1 ] && [ "$code" -gt 128 ]; then continue; fi
  break
done
pid=
attempt "$stage" "$code"
secs=$(($(hpc_now) - start))
case "$code" in
0)
  if [ -f "$dir/$stem.h5" ]; then echo "case $name: done (${secs} s) [$dir]"
  else echo "case $name: failed: exit 0 but no $stem.h5 [$dir]"; exit 4; fi ;;
5) echo "case $name: stopped at the wall-clock limit, checkpoint written (exit 5, ${secs} s): resubmit to go on [$dir]" ;;
*) echo "case $name: failed (exit $code, ${secs} s): $(hpc_first_error "$dir/run.out") [$dir/run.out]" ;;
esac
exit "$code"
