#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine, builds foveate (debug, warnings as errors)
# and runs every test; then installs the package and builds a consumer program
# against it with find_package(foveate).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
jobs=$(nproc)
cmake --preset debug >/dev/null
cmake --build --preset debug -j "$jobs"
ctest --preset debug -j "$jobs"

# The installed package works for a consumer.
prefix=$(pwd)/build/debug-install
rm -rf "$prefix" build/consumer
cmake --install build/debug --prefix "$prefix" >/dev/null
cmake -S examples/consumer -B build/consumer -G Ninja -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build build/consumer >/dev/null
./build/consumer/consumer
echo "consumer: built against the installed package and ran"
rm -rf build/own_renderer
cmake -S examples/own_renderer -B build/own_renderer -G Ninja -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build build/own_renderer >/dev/null
(cd build/own_renderer && ./own_renderer layered own_renderer.png)
echo "own_renderer: a user scene foveated through the installed package"
