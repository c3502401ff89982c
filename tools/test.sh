#!/bin/sh
# Command 2 of README: build the test configuration (Check: -O2 with run-time
# checks, no floating-point traps; see CMakeLists.txt) and run the
# test suite under CTest, leaving out the studies labelled slow.
# Pass extra ctest arguments after the script name, e.g. -R mesh or -L slow.
set -eu
cd "$(dirname "$0")/.."
sh tools/install-packages.sh
cmake -S . -B build-test -DCMAKE_BUILD_TYPE=Check
cmake --build build-test -j "$(nproc)"
if [ "$#" -gt 0 ]; then
  ctest --test-dir build-test --output-on-failure -j "$(nproc)" "$@"
else
  ctest --test-dir build-test --output-on-failure -j "$(nproc)" -LE slow
fi
