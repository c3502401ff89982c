#!/bin/sh
# Install the Debian packages raccord needs to build, test and plot.
# Runs apt-get only when a package is missing; uses sudo when not root.
set -eu
packages="gfortran cmake make liblapack-dev libblas-dev libhdf5-dev hdf5-tools gnuplot-nox"
# Optional extras: gmsh (to remesh input/*.geo) and calculix-ccx (comparisons).
if [ "${RACCORD_EXTRAS:-0}" = 1 ]; then packages="$packages gmsh calculix-ccx"; fi
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
