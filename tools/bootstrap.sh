#!/bin/sh
# Command 1 of README: install the packages, build raccord (Release) and run
# the default scene. Results land in results/<scene>/.
set -eu
cd "$(dirname "$0")/.."
sh tools/install-packages.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$(nproc)"
./build/raccord input/examples/bar_wave.nml
