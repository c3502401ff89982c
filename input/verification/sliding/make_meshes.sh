#!/bin/sh
# Regenerate the sliding meshes from sliding.geo (Gmsh 4.8.4); .msh committed.
set -e
cd "$(dirname "$0")"
gmsh sliding.geo -2 -format msh41 -o sliding_q4.msh > /dev/null                                              # base h 0.05, slider h 1/14
gmsh sliding.geo -2 -format msh41 -setnumber nb 40 -setnumber ns 7 -setnumber order 2 -o sliding_q8.msh > /dev/null   # same node spacing, Q8
echo sliding_q4.msh sliding_q8.msh
