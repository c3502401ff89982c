#!/bin/sh
# Regenerate the axisymmetric Hertz meshes from hertz_axi.geo (Gmsh 4.8.4);
# the .msh files are committed. nb / nc = block / sphere interface elements in r < 2.
set -e
cd "$(dirname "$0")"
mesh() {  # name nb nc hmax order
  gmsh hertz_axi.geo -2 -format msh41 -setnumber nb "$2" -setnumber nc "$3" \
       -setnumber hmax "$4" -setnumber order "$5" -o "$1.msh" > "$1.log" 2>&1 \
    || { cat "$1.log"; exit 1; }
  if grep "Blossom recombination completed" "$1.log" | grep -qv " 0 triangles"; then
    echo "$1: triangles left after recombination" >&2; exit 1
  fi
  rm -f "$1.log"; echo "$1.msh"
}
mesh hertz_axi_q4 "${1:-20}" "${2:-24}" 4.0 1   # h = a/10 (block), a/12 (sphere)
mesh hertz_axi_q8 10 12 4.0 2                   # Q8, node spacing about that of the Q4 mesh
# the mesh study (doc/accuracy-cost.md section 14): coarser and finer interfaces
mesh hertz_axi_q4_L1 10 12 4.0 1
mesh hertz_axi_q4_L3 40 48 4.0 1
