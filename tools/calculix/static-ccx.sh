#!/bin/sh
# raccord against CalculiX static on unstructured Gmsh meshes (Q4 and Q8,
# plane strain, axisymmetric, finite strain): runs static-ccx.py with a
# python3 that has numpy, h5py and meshio.
#
#   sh tools/calculix/static-ccx.sh RACCORD WORKDIR [CASE ...]
#
# Exit 0 every case within its bound, 1 one outside or a run failed, 77
# skipped (ccx, gmsh or the Python modules missing). CTest: static_ccx.
here=$(cd "$(dirname "$0")" && pwd)
for py in python3 /usr/bin/python3; do
  if command -v "$py" > /dev/null 2>&1 && "$py" -c 'import numpy, h5py, meshio' > /dev/null 2>&1; then
    mkdir -p "$2" && exec "$py" "$here/static-ccx.py" "$@"
  fi
done
echo "SKIP: no python3 with numpy, h5py and meshio (Debian: python3-h5py python3-meshio)"
exit 77
