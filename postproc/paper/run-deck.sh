#!/bin/sh
# Run one raccord deck into RUNS/<deck stem>/ (helper of tools/paper-figures.sh,
# called through xargs -P 2 so that two decks run at a time).
#
#   sh postproc/paper/run-deck.sh EXE RUNS DECK
#
# Prints one line per deck; on failure the tail of the log and exit 1 (xargs
# then carries on with the other decks and returns 123).
set -u
exe=$1 runs=$2 deck=$3
name=$(basename "$deck" .nml)
start=$(date +%s)
if "$exe" --quiet --output "$runs/$name" "$deck"; then
  echo "paper-figures: ran $name ($(( $(date +%s) - start )) s)"
else
  rc=$?
  echo "paper-figures: $name FAILED (exit $rc); log: $runs/$name/$name.log" >&2
  tail -n 5 "$runs/$name/$name.log" >&2 2>/dev/null || true
  exit 1
fi
