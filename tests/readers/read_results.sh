#!/bin/sh
# Run a deck and read its results with a reader users use (CMakeLists.txt).
#
#   sh tests/readers/read_results.sh meshio|paraview RACCORD DECK WORKDIR
#
# Exit 77 (skipped) when the reader is not installed.
set -eu
reader=$1 exe=$2 deck=$3 work=$4
here=$(cd "$(dirname "$0")" && pwd)
name=$(basename "$deck" .nml)

# The Python that has the modules, or none.
find_python() {
  for py in python3 /usr/bin/python3; do
    if command -v "$py" > /dev/null 2>&1 && "$py" -c "$1" > /dev/null 2>&1; then
      echo "$py"
      return
    fi
  done
}

case $reader in
  meshio)
    run=$(find_python 'import meshio, h5py')
    [ -n "$run" ] || { echo "SKIP: no python3 with meshio and h5py (Debian: python3-meshio python3-h5py)"; exit 77; }
    script=$here/read_meshio.py ;;
  paraview)
    run=""
    for pv in pvpython pvbatch; do
      if command -v $pv > /dev/null 2>&1; then run=$pv; break; fi
    done
    [ -n "$run" ] || { echo "SKIP: no pvpython or pvbatch (Debian: paraview)"; exit 77; }
    script=$here/read_paraview.py ;;
  *) echo "read_results.sh: unknown reader $reader"; exit 2 ;;
esac

rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)
"$exe" --quiet --output "$work" "$deck" || { echo "raccord failed on $deck (exit $?)"; exit 1; }
echo "reading $work/$name with $run"
"$run" "$script" "$work/$name"
