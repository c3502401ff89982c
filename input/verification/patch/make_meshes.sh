#!/bin/sh
# Regenerate the patch-test meshes from patch.geo (Gmsh 4.8.4); .msh committed.
set -e
cd "$(dirname "$0")"
gmsh patch.geo -2 -format msh41 -setnumber order 1 -o patch_q4.msh > /dev/null
gmsh patch.geo -2 -format msh41 -setnumber order 2 -o patch_q8.msh > /dev/null
echo patch_q4.msh patch_q8.msh
