#!/bin/sh
# One regression test: run a paper deck, reduce it (extract.sh) and compare
# it with tests/reference (compare.awk). Called by CTest (CMakeLists.txt).
#
#   sh tests/regression/run-regression.sh RACCORD DECK REFDIR WORKDIR [TOL]
#
# TOL (default 1e-3): relative to the peak of each compared quantity.
set -eu
exe=$1 deck=$2 refdir=$3 work=$4 tol=${5:-1e-3}
here=$(cd "$(dirname "$0")" && pwd)
name=$(basename "$deck" .nml)
rm -rf "$work"
"$exe" --quiet --output "$work/run" "$deck" || { echo "regression: raccord failed on $deck (exit $?); log $work/run/$name.log"; exit 1; }
sh "$here/extract.sh" "$work/run" "$name" "$work"
status=0
for kind in profile reaction; do
  ref=$refdir/$name.$kind.txt
  [ -f "$ref" ] || { echo "regression: no reference $ref (sh tools/regen-references.sh)"; exit 1; }
  echo "$name.$kind:"
  awk -v tol="$tol" -f "$here/compare.awk" "$ref" "$work/$name.$kind.txt" || status=1
done
exit $status
