#!/bin/sh
# Regenerate the meshes of the paper scene from paper.geo (Gmsh 4.8.4 was used).
# The .msh files are committed so nobody needs Gmsh to run the decks.
#   hb  = block top element size in |x| < 0.7, nd = disc arc elements in |x| < 0.7,
#   hcd = disc element size at the flat top, order = 1 (Q4) or 2 (Q8).
set -e
cd "$(dirname "$0")"
mesh() {  # name hb nd hcd order
  gmsh paper.geo -2 -format msh41 -setnumber hb "$2" -setnumber nd "$3" \
       -setnumber hcd "$4" -setnumber order "$5" -o "$1.msh" > "$1.log" 2>&1 \
    || { cat "$1.log"; exit 1; }
  if grep -q "triangles" "$1.log" && grep "Blossom recombination completed" "$1.log" | grep -qv " 0 triangles"; then
    echo "$1: triangles left after recombination" >&2; exit 1
  fi
  rm -f "$1.log"
  echo "$1.msh"
}
mesh paper_q4_coarse 0.05 20  0.15 1   # regression: a few seconds
mesh paper_q4        0.02 56  0.08 1   # standard: block h 0.02, disc arc h 0.0277
mesh paper_q4_fine   0.01 112 0.05 1   # figures: block h 0.01, disc arc h 0.0138
mesh paper_q8        0.04 28  0.16 2   # Q8 with the node spacing of paper_q4
