#!/bin/sh
# Command 1 of README: install the packages, build raccord (Release) and run
# the default scene, the paper's Fig. 2(a). Runs land in results/paper/runs/,
# the figure in results/paper/figures/.
set -eu
cd "$(dirname "$0")/.."
sh tools/install-packages.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$(nproc)"
# The default scene, the paper's Fig. 2(a) (input/paper/fig2a_mortar_p1_slave_block.nml
# and its slave = disc twin, two runs side by side, about 15 s each), drawn in
# results/paper/figures/fig2a.png and .pdf (tools/paper-figures.sh).
sh tools/paper-figures.sh results/paper fig2a
