#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine, builds foveate (release) and runs the demo.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)" --target foveate
exec ./build/release/app/foveate demo "$@"
