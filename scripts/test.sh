#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine, builds foveate (debug, warnings as
# errors), checks that the installed package works for programs outside the
# tree (find_package(foveate)), runs every test with CTest, then builds the
# fuzz targets and runs each for a short fixed time (scripts/fuzz.sh;
# FOVEATE_FUZZ_SECONDS per target, default 10).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
jobs=$(nproc)
cmake --preset debug >/dev/null
cmake --build --preset debug -j "$jobs"

# The installed package works for consumers: a planner program, a user's
# own scene foveated by a technique, and a benchmark run with a technique of
# the program's own, its report written.
prefix=$(pwd)/build/debug-install
rm -rf "$prefix" build/consumer build/own_renderer build/bench_consumer
cmake --install build/debug --prefix "$prefix" >/dev/null
cmake -S examples/consumer -B build/consumer -G Ninja -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build build/consumer >/dev/null
./build/consumer/consumer
cmake -S examples/own_renderer -B build/own_renderer -G Ninja -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build build/own_renderer >/dev/null
(cd build/own_renderer && ./own_renderer layered own_renderer.png && ./own_renderer letterbox letterbox.png)
cmake -S examples/bench_consumer -B build/bench_consumer -G Ninja -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build build/bench_consumer >/dev/null
(cd build/bench_consumer && ./bench_consumer report >/dev/null && test -s report/report.html && test -s report/results.json)
echo "installed package: consumer, own_renderer and bench_consumer built with find_package(foveate) and ran"

# FovVideoVDP's reference values (../shared/fvvdp beside the clone, as in CI):
# when they are there, the tests that read them must run, not skip.
if [ -f ../shared/fvvdp/cases.json ]; then
  export FOVEATE_FVVDP_CASES_REQUIRED=1
fi
ctest --preset debug -j "$jobs"

# Every parser of user data under libFuzzer (ASan + UBSan) for a short while:
# about 1 min of build and 10 s per target.
# Every target but mesh_import_fuzz: that one fuzzes libassimp itself (not
# instrumented, not ours to fix) and finds its crashes at random, which would
# make CI fail by chance; run it by hand (tests/fuzz/README.md).
ci_targets=()
for d in tests/fuzz/corpus/*/; do
  t=$(basename "$d")
  [ "$t" = mesh_import_fuzz ] || ci_targets+=("$t")
done
bash scripts/fuzz.sh "${FOVEATE_FUZZ_SECONDS:-10}" "${ci_targets[@]}"
