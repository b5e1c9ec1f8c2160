#!/usr/bin/env bash
# Builds the libFuzzer targets (cmake --preset fuzz: clang-15, ASan + UBSan)
# and runs each for a fixed time over its seed corpus (tests/fuzz/corpus/NAME).
# Any finding (a crash, an exception other than foveate::Error, a sanitizer
# report, an input slower than the timeout, memory over the limit) fails the
# script; the input that caused it is left in build/fuzz/findings/.
#
#   scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]     (default: 10 s, every target)
#
# Inputs the fuzzer finds interesting go to build/fuzz/corpus-work/NAME (kept
# between runs); the seeds in the repository are not changed.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-10}
shift || true

cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$(nproc)"

bin=build/fuzz/tests/fuzz
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  for d in tests/fuzz/corpus/*/; do targets+=("$(basename "$d")"); done
fi

mkdir -p build/fuzz/findings
failed=()
printf '%-26s %8s %12s %8s  %s\n' target seconds executions corpus result
for t in "${targets[@]}"; do
  [ -x "$bin/$t" ] || { echo "fuzz: no target $t in $bin" >&2; exit 2; }
  work=build/fuzz/corpus-work/$t
  log=build/fuzz/$t.log
  mkdir -p "$work"
  status=ok
  # tests/fuzz/NAME.flags: extra libFuzzer flags of one target, one a line.
  extra=()
  if [ -f "tests/fuzz/$t.flags" ]; then mapfile -t extra < <(grep -v '^#' "tests/fuzz/$t.flags"); fi
  # -timeout: one input slower than 5 s is a hang; -rss_limit_mb: 2 GB.
  if ! "$bin/$t" -max_total_time="$seconds" -timeout=5 -rss_limit_mb=2048 -print_final_stats=1 \
      "${extra[@]}" -artifact_prefix="build/fuzz/findings/$t-" "$work" "tests/fuzz/corpus/$t" >"$log" 2>&1; then
    status=FINDING
    failed+=("$t")
  fi
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo '?')
  corpus=$(grep -o 'corp: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*$' || echo '?')
  printf '%-26s %8s %12s %8s  %s\n' "$t" "$seconds" "${execs:-?}" "${corpus:-?}" "$status"
done

if [ ${#failed[@]} -gt 0 ]; then
  for t in "${failed[@]}"; do
    echo "---- $t: build/fuzz/$t.log"
    grep -E 'ERROR|SUMMARY|runtime error|what\(\)|Test unit written' "build/fuzz/$t.log" | head -20
  done
  echo "fuzz: findings in ${failed[*]} (inputs in build/fuzz/findings/)" >&2
  exit 1
fi
echo "fuzz: ${#targets[@]} targets ran ${seconds} s each with no finding"
