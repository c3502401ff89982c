#!/bin/sh
# A Release build of raccord whose contact code (src/contact) is optimised
# with a profile of typical scenes (doc/user-guide.md, section 2;
# doc/performance.md, "Profile-guided contact build"): instrument it,
# train it, rebuild it with the profile.
#
#   sh tools/build-pgo.sh [-q] [-t DECK]... [BUILD_DIR]
#
# BUILD_DIR  the build folder (default build-pgo, next to build/); its
#            raccord is the optimised program at the end. The profile goes
#            to BUILD_DIR/pgo-profile (emptied first).
# -t DECK    train on this scene deck too, run whole (-q: for 2 s): add
#            the scenes you will run, the profile speeds up the branches
#            the training takes (repeatable)
# -q         quick training (every scene for 2 s of wall clock): for a
#            check of the script, not for the build you run.
#
# The training runs, one thread each, in a scratch folder: the paper's
# Fig. 2(a) (mortar P1), Fig. 1(b) (node-to-segment), Fig. 3 (mortar P1,
# mu = 0.2) and Fig. 4(b) (Q8, mortar P1, mu = 0.2, tangential corners)
# whole (about a minute and a half instrumented), then 2 s of each of
# eight scenes with other contact paths (Q8 mortar and node-to-segment,
# P0, friction on a cylinder, finite strain and J2, ironing, a pin in a
# hole), then the -t decks. A scene whose contact paths the training does
# not take can run slower than with the plain build: Fig. 4(b) trained for
# 2 s only ran its matching a tenth slower (doc/performance.md). The rest
# of the program is the plain Release build's. Contact results agree with
# the plain build to round-off (products fused differently), not bit for
# bit. Exit 0 when the optimised program was built, 1 when a step failed
# (the message names it), 2 on bad usage.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
quick=0
build=
extra=
while [ $# -gt 0 ]; do
  case "$1" in
  -q) quick=1; shift ;;
  -t) [ $# -ge 2 ] || { echo "build-pgo: -t needs a scene deck" >&2; exit 2; }
      [ -f "$2" ] || { echo "build-pgo: -t $2: no such deck" >&2; exit 2; }
      extra="$extra $(cd "$(dirname "$2")" && pwd)/$(basename "$2")"; shift 2 ;;
  -h|--help) sed -n '2,30p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
  -*) echo "build-pgo: unknown option $1 (see --help)" >&2; exit 2 ;;
  *) [ -z "$build" ] || { echo "build-pgo: one build folder, not '$build' and '$1'" >&2; exit 2; }; build=$1; shift ;;
  esac
done
[ -n "$build" ] || build=$root/build-pgo
case "$build" in /*) ;; *) build=$(pwd)/$build ;; esac
profile=$build/pgo-profile
jobs=$(nproc 2>/dev/null || echo 2)
fail() { echo "build-pgo: $*" >&2; exit 1; }

echo "build-pgo: 1/3 instrumented build in $build"
rm -rf "$profile"
mkdir -p "$profile"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DRACCORD_PGO=GENERATE -DRACCORD_PGO_DIR="$profile" \
  > "$build/pgo-configure.log" 2>&1 || fail "configure failed, see $build/pgo-configure.log"
cmake --build "$build" --target raccord -j "$jobs" > "$build/pgo-build.log" 2>&1 ||
  fail "instrumented build failed, see $build/pgo-build.log"

work=$(mktemp -d "${TMPDIR:-/tmp}/build-pgo.XXXXXX") || fail "no scratch folder"
trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
# train DECK [SECONDS]: run DECK (relative to input/, or an absolute path)
# from its own folder (its mesh paths are relative to it), whole or for
# SECONDS of wall clock (then it stops with its checkpoint, exit 5).
train() {
  case "$1" in /*) deck=$1 ;; *) deck=$root/input/$1 ;; esac
  [ -f "$deck" ] || fail "no training scene $deck"
  name=$(basename "$1" .nml)
  limit=
  [ $# -lt 2 ] || limit="--wall-clock $2"
  set +e
  (cd "$(dirname "$deck")" && "$build/raccord" -q $limit -o "$work/$name" "$deck") > "$work/$name.out" 2>&1
  rc=$?
  set -e
  [ $rc -eq 0 ] || [ $rc -eq 5 ] || fail "training run $1 failed (exit $rc): $(tail -n 3 "$work/$name.out")"
  echo "build-pgo:   trained on $1"
}
echo "build-pgo: 2/3 training (one thread)"
# The main scenes and the -t decks whole (-q: 2 s each; $main_limit is
# then train's SECONDS), the others 2 s.
main_limit=
[ $quick -eq 0 ] || main_limit=2
for d in paper/fig2a_mortar_p1_slave_block.nml paper/fig1b_nts_slave_block.nml paper/fig3_mortar_p1_mu020.nml \
  paper/fig4b_q8_mortar_p1_mu020.nml; do
  train "$d" $main_limit
done
for d in verification/hertz/q8_mortar_p1_slave_block.nml verification/hertz/q8_nts_slave_block.nml \
  verification/hertz/q4_mortar_p0_slave_block.nml verification/cattaneo/q4_mortar_p1_slave_cylinder.nml \
  verification/taylor/finite_mortar.nml verification/taylor/small_nts.nml verification/ironing/ironing_mortar_mu030.nml \
  examples/pin_hole.nml; do
  train "$d" 2
done
for d in $extra; do
  train "$d" $main_limit
done
ls "$profile" | grep -q '\.gcda$' || fail "the training wrote no profile into $profile"

echo "build-pgo: 3/3 optimised build with the profile"
cmake -S "$root" -B "$build" -DRACCORD_PGO=USE > "$build/pgo-configure.log" 2>&1 ||
  fail "configure failed, see $build/pgo-configure.log"
cmake --build "$build" --target raccord -j "$jobs" > "$build/pgo-build.log" 2>&1 ||
  fail "optimised build failed, see $build/pgo-build.log"
echo "build-pgo: done: $build/raccord (its contact code profile-guided)"
