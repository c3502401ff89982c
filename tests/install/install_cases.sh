#!/bin/sh
# The installed raccord works on its own (README, "Installing"):
#
#   sh tests/install/install_cases.sh CMAKE BUILDDIR WORKDIR
#
# installs BUILDDIR into WORKDIR/prefix, checks the layout, runs the
# installed example deck with the installed program, runs it again through
# the installed hpc/run-case.sh with no raccord on PATH and no $RACCORD (it
# must find PREFIX/bin/raccord), and plots the history with the installed
# postproc script when gnuplot is there. Exit 0 when every check passes.
set -u
cmake=$1 build=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)
prefix=$work/prefix
fails=0
check() {
  what=$1
  shift
  if "$@"; then echo "pass  $what"; else echo "FAIL  $what"; fails=$((fails + 1)); fi
}

"$cmake" --install "$build" --prefix "$prefix" > "$work/install.log" 2>&1
check "cmake --install into $prefix" test $? = 0
share=$prefix/share/raccord
for f in bin/raccord share/raccord/hpc/run-case.sh share/raccord/hpc/lib.sh share/raccord/hpc/slurm/raccord-array.sbatch \
         share/raccord/hpc/examples/bar.sweep share/raccord/postproc/plot-history.sh share/raccord/postproc/history.gp \
         share/raccord/postproc/paper/fig2a.gp share/raccord/input/examples/bar_wave.nml \
         share/raccord/input/paper/fig2a_mortar_p1_slave_block.nml share/raccord/input/paper/paper_q4.msh \
         share/doc/raccord/README.md share/doc/raccord/doc/output-format.md; do
  check "installed $f" test -s "$prefix/$f"
done
check "bin/raccord is executable" test -x "$prefix/bin/raccord"
check "no sources or CMake files under share/raccord" \
  sh -c "[ -z \"\$(find '$share' -name '*.f90' -o -name CMakeLists.txt | head -n 1)\" ]"

# The example deck with the installed program (its mesh is found next to it).
"$prefix/bin/raccord" --quiet --output "$work/run" "$share/input/examples/bar_wave.nml"
check "installed raccord runs the installed example (exit $?)" test -s "$work/run/bar_wave.h5"

# The installed hpc runner finds the installed program by itself.
found=$(env -u RACCORD PATH=/usr/bin:/bin sh -c 'hpc_prog=test; hpc_dir=$1; . "$1/lib.sh"; hpc_find_raccord' sh "$share/hpc")
check "installed hpc/lib.sh finds $prefix/bin/raccord (got $found)" test "$found" = "$prefix/bin/raccord"
env -u RACCORD PATH=/usr/bin:/bin sh "$share/hpc/run-case.sh" -d "$share/input/examples/bar_wave.nml" "$work/case" \
  > "$work/case.out" 2>&1
rc=$?
check "installed hpc/run-case.sh with no raccord on PATH (exit $rc)" test $rc = 0
check "the case ran: $work/case/bar_wave.h5" test -s "$work/case/bar_wave.h5"

# The installed gnuplot script.
if command -v gnuplot > /dev/null 2>&1; then
  sh "$share/postproc/plot-history.sh" "$work/run/bar_wave" png > "$work/plot.out" 2>&1
  check "installed plot-history.sh draws the history" test -s "$work/run/bar_wave.energy.png"
else
  echo "note: no gnuplot, plot-history.sh not tried"
fi
[ "$fails" = 0 ] || { echo "$fails check(s) failed"; exit 1; }
echo "all checks passed"
