#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine, builds foveate (debug, warnings as
# errors), checks that the installed package works for programs outside the
# tree (find_package(foveate)), and runs every test with CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
jobs=$(nproc)
cmake --preset debug >/dev/null
cmake --build --preset debug -j "$jobs"

# The installed package works for consumers: a planner program and a user's
# own scene foveated by a technique.
prefix=$(pwd)/build/debug-install
rm -rf "$prefix" build/consumer build/own_renderer
cmake --install build/debug --prefix "$prefix" >/dev/null
cmake -S examples/consumer -B build/consumer -G Ninja -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build build/consumer >/dev/null
./build/consumer/consumer
cmake -S examples/own_renderer -B build/own_renderer -G Ninja -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build build/own_renderer >/dev/null
(cd build/own_renderer && ./own_renderer layered own_renderer.png && ./own_renderer letterbox letterbox.png)
echo "installed package: consumer and own_renderer built with find_package(foveate) and ran"

ctest --preset debug -j "$jobs"
