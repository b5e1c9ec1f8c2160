#!/usr/bin/env bash
# scripts/gpu-bench.sh end to end on whatever renderer the tests run on, at
# a tiny size (the binary under test, no release build): the document names
# the renderer and holds a table per scene, the time per pass and the vrs
# comparison against the 4x4 reference; each run's results.json is kept; bad
# arguments are refused with a reason.
set -u
fail=0
check() { if ! eval "$2"; then echo "FAIL: $1"; fail=1; else echo "ok: $1"; fi; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
script="$FOVEATE_SOURCE_DIR/scripts/gpu-bench.sh"

FOVEATE_SKIP_BUILD=1 FOVEATE_BIN="$FOVEATE" bash "$script" --quick --sizes 160x90 --frames 1 \
  --out "$tmp/gpu" >"$tmp/out" 2>"$tmp/err"
check "runs (exit 0)" '[ $? -eq 0 ] || { cat "$tmp/err"; false; }'
doc=$(ls "$tmp"/gpu/*.md 2>/dev/null | head -n1)
check "writes one document named for the renderer" '[ -n "$doc" ] && [ "$(ls "$tmp"/gpu/*.md | wc -l)" -eq 1 ]'
renderer=$(sed -n 's/^# foveate on //p' "$doc")
check "the document names the renderer ($renderer)" '[ -n "$renderer" ] && grep -q "$renderer" "$tmp/gpu/results/"*guenter-160x90.json'
for scene in guenter raymarch mandelbulb; do
  check "a table for $scene" 'grep -q "^## $scene at 160x90" "$doc" && [ -f "$tmp/gpu/results/"*"-$scene-160x90.json" ]'
done
check "lodmask only on guenter (its row and its passes)" '[ "$(grep -c "^| lodmask" "$doc")" -eq 2 ] && [ "$(sed -n "/^## guenter/,/^## raymarch/p" "$doc" | grep -c "^| lodmask")" -eq 2 ]'
check "time per pass" 'grep -q "resolve share" "$doc"'
check "vrs against the 4x4 reference" 'grep -q "vrs.hardware=1.0000" "$doc" && grep -q "ssaa:4" "$doc"'
check "--quick has no quality tables" '! grep -q "^## Quality" "$doc"'
check "says each technique planned with its own margin" 'grep -q "planned with its own margin" "$doc"'

# --margin K reaches every bench, and the document says so.
FOVEATE_SKIP_BUILD=1 FOVEATE_BIN="$FOVEATE" bash "$script" --quick --sizes 160x90 --frames 1 \
  --margin 1 --out "$tmp/gpu1" >/dev/null 2>"$tmp/err1m"
doc1=$(ls "$tmp"/gpu1/*.md 2>/dev/null | head -n1)
check "--margin 1: the papers' plans, in the document, commands and results" \
  '[ -n "$doc1" ] && grep -q "planned with margin 1" "$doc1" && grep -q -- "--passes --margin 1" "$doc1" && grep -q "\"margin\": 1" "$tmp/gpu1/results/"*guenter-160x90.json'

bash "$script" --frames many >/dev/null 2>"$tmp/err1"
check "--frames many: exit 2, named" '[ $? -eq 2 ] && grep -q "frames" "$tmp/err1"'
bash "$script" --bogus >/dev/null 2>"$tmp/err2"
check "unknown argument: exit 2, named" '[ $? -eq 2 ] && grep -q "bogus" "$tmp/err2"'
bash "$script" --help >"$tmp/help"
check "--help describes the run" 'grep -q "quality tables" "$tmp/help"'
exit $fail
