#!/bin/sh
# Regenerate the Hertz meshes from hertz.geo (Gmsh 4.8.4 was used); the .msh
# files are committed. nb / nc = block / cylinder interface elements in |x| < 2.
set -e
cd "$(dirname "$0")"
mesh() {  # name nb nc hmax order
  gmsh hertz.geo -2 -format msh41 -setnumber nb "$2" -setnumber nc "$3" \
       -setnumber hmax "$4" -setnumber order "$5" -o "$1.msh" > "$1.log" 2>&1 \
    || { cat "$1.log"; exit 1; }
  if grep "Blossom recombination completed" "$1.log" | grep -qv " 0 triangles"; then
    echo "$1: triangles left after recombination" >&2; exit 1
  fi
  rm -f "$1.log"; echo "$1.msh"
}
mesh hertz_q4_coarse 24 28 4.0 1   # regression: h = a/6 .. a/7
mesh hertz_q4        60 70 3.0 1   # h = a/14 (block), a/17 (cylinder)
mesh hertz_q8        30 36 4.0 2   # Q8, node spacing about that of hertz_q4
mesh hertz_q8_coarse 12 14 5.0 2   # regression Q8: node spacing of hertz_q4_coarse
