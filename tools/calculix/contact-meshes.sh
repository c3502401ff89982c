#!/bin/sh
# raccord's contact on unstructured, renumbered, turned Gmsh / Abaqus meshes
# against closed forms (Hertz line and point contact, patch test): runs
# contact-meshes.py with a python3 that has numpy, h5py and meshio.
#
#   sh tools/calculix/contact-meshes.sh RACCORD WORKDIR [--quick | CASE ...]
#
# Exit 0 every case within its bound, 1 one outside or a run failed, 77
# skipped (gmsh or the Python modules missing). CTest: contact_meshes
# (--quick), contact_meshes_all (slow).
here=$(cd "$(dirname "$0")" && pwd)
for py in python3 /usr/bin/python3; do
  if command -v "$py" > /dev/null 2>&1 && "$py" -c 'import numpy, h5py, meshio' > /dev/null 2>&1; then
    mkdir -p "$2" && exec "$py" "$here/contact-meshes.py" "$@"
  fi
done
echo "SKIP: no python3 with numpy, h5py and meshio (Debian: python3-h5py python3-meshio)"
exit 77
