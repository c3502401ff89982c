#!/bin/sh
# Regenerate the Taylor-test meshes from taylor.geo (Gmsh 4.8.4); .msh committed.
# Structured (transfinite, recombined): quadrilaterals only.
set -e
cd "$(dirname "$0")"
gmsh taylor.geo -2 -format msh41 -o taylor_q4.msh > /dev/null    # bar 8 x 80, wall 24 x 8, h = 0.125
gmsh taylor.geo -2 -format msh41 -setnumber nx 16 -setnumber ny 160 -setnumber nw 48 -setnumber nd 16 \
  -o taylor_q4_fine.msh > /dev/null                               # h = 0.0625
echo taylor_q4.msh taylor_q4_fine.msh
