#!/bin/sh
# Install the Debian packages raccord needs to build, test and plot.
# Runs apt-get only when a package is missing; uses sudo when not root.
set -eu
# python3-h5py and python3-meshio: the results read as Python users read
# them (tests/readers; about 40 MB with numpy). gmsh: the accuracy-cost
# study (study_quick) and contact_meshes mesh their .geo files with it;
# calculix-ccx: the independent code static_ccx compares against. Without
# them the suite is not the one CI runs (study_quick fails, the other two
# skip).
packages="gfortran cmake make liblapack-dev libblas-dev libhdf5-dev hdf5-tools gnuplot-nox python3-h5py python3-meshio gmsh calculix-ccx"
# Optional extra: paraview (pvpython: tests/readers then also reads the
# results with ParaView's readers; several hundred MB, so not by default).
if [ "${RACCORD_EXTRAS:-0}" = 1 ]; then packages="$packages paraview"; fi
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
