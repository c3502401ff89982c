#!/bin/sh
# Regenerate the impact meshes from impact.geo (Gmsh 4.8.4); .msh committed.
set -e
cd "$(dirname "$0")"
gmsh impact.geo -2 -format msh41 -o impact_q4.msh > /dev/null                                  # matching ends, 10 : 10
gmsh impact.geo -2 -format msh41 -setnumber nyr 7 -o impact_q4_nonmatching.msh > /dev/null     # 10 : 7
echo impact_q4.msh impact_q4_nonmatching.msh
