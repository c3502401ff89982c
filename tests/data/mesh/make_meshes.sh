#!/bin/sh
# Regenerate the Gmsh test meshes from their .geo files (Gmsh 4.8 was used).
# The .msh files are committed so the tests do not need Gmsh.
set -e
cd "$(dirname "$0")"
for geo in scene_q4 scene_q8 rect two_groups; do
  gmsh "$geo.geo" -2 -format msh41 -o "$geo.v41.msh" > /dev/null
  gmsh "$geo.geo" -2 -format msh22 -o "$geo.v22.msh" > /dev/null
done
