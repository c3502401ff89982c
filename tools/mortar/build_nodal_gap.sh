#!/bin/sh
# Build tools/mortar/nodal_gap.f90 (the nodal gaps of conditions (19) row by row, a diagnostic) against
# a configured and built tree: sh tools/mortar/build_nodal_gap.sh BUILD_DIR
# It uses the library, the test support library (raccord_scene_runner) and the
# HDF5 libraries that tree was linked with. Writes ./nodal_gap.
set -eu
b=$1
here=$(dirname "$0")
hdf=$(sed -n 's/^HDF5_Fortran_LIBRARY_hdf5_fortran:FILEPATH=//p' "$b/CMakeCache.txt")
hdfc=$(sed -n 's/^HDF5_Fortran_LIBRARY_hdf5:FILEPATH=//p' "$b/CMakeCache.txt")
gfortran -O2 -fopenmp -I"$b/modules" "$here/nodal_gap.f90" -o nodal_gap "$b/tests/libraccord_check.a" \
  "$b/libraccord_lib.a" $hdf $hdfc -llapack -lblas -Wl,-rpath,"$(dirname "$hdf")"
