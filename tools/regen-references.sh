#!/bin/sh
# Regenerate the regression references tests/reference/ after an INTENDED
# change of the physics or numerics (doc/reproduction.md, "Regression"):
# never to make a failing test pass without knowing why it fails.
#
#   sh tools/regen-references.sh [DECK ...]
#
# DECK: names of input/paper/reg_*.nml (default: all of them). Builds the
# Check configuration (what the test suite runs; in $RACCORD_BUILD, default
# build-test/), runs each deck, writes tests/reference/<deck>.profile.txt and
# .reaction.txt, and prints the differences against the old references in
# the comparator's words (paste them into the commit message).
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${RACCORD_BUILD:-$root/build-test}
case "$build" in /*) ;; *) build=$root/$build ;; esac
ref=$root/tests/reference
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Check > /dev/null
cmake --build "$build" --target raccord -j "$(nproc 2>/dev/null || echo 2)" > /dev/null
names=${*:-$(cd "$root/input/paper" && ls reg_*.nml | sed 's/\.nml$//')}
work=$(mktemp -d "${TMPDIR:-/tmp}/raccord-regen.XXXXXX")
trap 'rm -rf "$work"' EXIT
mkdir -p "$ref"
for name in $names; do
  name=${name%.nml}
  deck=$root/input/paper/$name.nml
  [ -f "$deck" ] || { echo "regen-references: no deck $deck" >&2; exit 2; }
  "$build/raccord" --quiet --output "$work/$name" "$deck"
  sh "$root/tests/regression/extract.sh" "$work/$name" "$name" "$work/new"
  for kind in profile reaction; do
    if [ -f "$ref/$name.$kind.txt" ]; then
      echo "$name.$kind, new against old reference:"
      awk -v tol=1e-3 -f "$root/tests/regression/compare.awk" "$ref/$name.$kind.txt" "$work/new/$name.$kind.txt" || true
    else
      echo "$name.$kind: new reference"
    fi
    cp "$work/new/$name.$kind.txt" "$ref/$name.$kind.txt"
  done
done
echo "regen-references: wrote $(echo $names | wc -w) x 2 files in tests/reference/; review 'git diff tests/reference' before committing"
