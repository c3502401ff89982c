#!/bin/sh
# Install the Debian packages raccord needs to build, test and plot.
# Runs apt-get only when a package is missing; uses sudo when not root.
set -eu
# python3-h5py and python3-meshio: the results read as Python users read
# them (tests/readers; about 40 MB with numpy).
packages="gfortran cmake make liblapack-dev libblas-dev libhdf5-dev hdf5-tools gnuplot-nox python3-h5py python3-meshio"
# Optional extras: gmsh (to remesh input/*.geo), calculix-ccx (comparisons)
# and paraview (pvpython: tests/readers reads the results with ParaView's
# readers; several hundred MB, so not by default).
if [ "${RACCORD_EXTRAS:-0}" = 1 ]; then packages="$packages gmsh calculix-ccx paraview"; fi
missing=""
for p in $packages; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
echo "installing:$missing"
SUDO=""
[ "$(id -u)" = 0 ] || SUDO=sudo
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq $missing
