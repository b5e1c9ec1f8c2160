#!/usr/bin/env bash
# `foveate tune`, `bench --shard`, `merge` and `--params-file` as a user runs
# them: the files written, the parameters a later run takes, shards joined,
# and clear errors with a non-zero exit on bad input.
set -u
fail=0
check() { if ! eval "$2"; then echo "FAIL: $1"; fail=1; else echo "ok: $1"; fi; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
F="$FOVEATE"
small=(--size 96x54 --frames 2 --warmup 1 --reference ssaa:2)

# Every benchmark of the search sets its session up again; a note is said once.
"$F" tune --scenes cheap --techniques inset --bound 0.5 "${small[@]}" --out "$tmp/n" > /dev/null 2> "$tmp/n.err"
check "tune's notes are said once" '[[ $(grep -c "note: at 96x54" "$tmp/n.err") -eq 1 ]]'
err=$("$F" tune --scenes cheap --techniques lodmask "${small[@]}" --out "$tmp/none" 2>&1); rc=$?
check "tune with nothing that can run: exit 1, naming why, no output" \
  '[[ $rc -eq 1 && "$err" == *"none of the techniques searched can run on --scenes: lodmask on cheap"* && ! -e "$tmp/none" ]]'

"$F" tune --scenes cheap --techniques layered,inset --bound 0.5 "${small[@]}" --out "$tmp/t" --quiet > "$tmp/t.md"
check "tune writes tune.json, tune.md, params.json and report.html" '[[ -s "$tmp/t/tune.json" && -s "$tmp/t/tune.md" && -s "$tmp/t/params.json" && -s "$tmp/t/report.html" ]]'
check "tune's chart is an SVG file beside its report, linked from it" '[[ -s "$tmp/t/chart-tune-cheap.svg" ]] && grep -q "download=\"chart-tune-cheap.svg\"" "$tmp/t/report.html"'
check "tune prints each technique's choice" 'grep -q "^| layered |" "$tmp/t.md" && grep -q "^| inset |" "$tmp/t.md"'
check "tune.json: points with speedup and JOD, native's JOD, a choice per technique" 'python3 -c "
import json,sys; j=json.load(open(sys.argv[1]))
assert j[\"schema\"] == \"foveate-tune/1\" and \"cheap\" in j[\"native_jod\"]
assert len(j[\"points\"]) >= 12 and all(\"jod\" in p and \"speedup\" in p for p in j[\"points\"])
assert set(j[\"chosen\"]) == {\"layered\", \"inset\"}
" "$tmp/t/tune.json"'
"$F" bench --scene cheap --size 64x36 --frames 1 --techniques native,layered --params-file "$tmp/t/params.json" --out "$tmp/b" --quiet > /dev/null
check "bench takes the chosen parameters (--params-file)" 'python3 -c "
import json,sys; t=json.load(open(sys.argv[1])); b=json.load(open(sys.argv[2]))
chosen=t[\"chosen\"][\"layered\"]; got=[r for r in b[\"results\"] if r[\"technique\"]==\"layered\"][0][\"parameters\"]
assert all(abs(got[k]-v) < 1e-9 for k,v in chosen.items()), (chosen, got)
" "$tmp/t/tune.json" "$tmp/b/results.json"'
err=$("$F" render --scene cheap --size 64x36 --technique vrs --params-file "$tmp/t/params.json" --out "$tmp/pf_none" --quiet 2>&1); rc=$?
check "--params-file with none of the techniques run: exit 1, names the file's and the run's, no output" '[[ $rc -eq 1 && "$err" == *"holds parameters for inset, layered, none for the techniques run (vrs)"* && ! -e "$tmp/pf_none" ]]'
"$F" bench --scene cheap --size 64x36 --frames 1 --techniques native,layered --params-file "$tmp/t/params.json" --param layered.margin=3 --out "$tmp/b2" --quiet > /dev/null
check "--param overrides --params-file" 'python3 -c "
import json,sys; b=json.load(open(sys.argv[1]))
assert [r for r in b[\"results\"] if r[\"technique\"]==\"layered\"][0][\"parameters\"][\"margin\"] == 3
" "$tmp/b2/results.json"'
"$F" bench --scene cheap --size 64x36 --frames 1 --techniques native,layered,inset --params-file "$tmp/t/params.json" --margin 1.75 --out "$tmp/b3" --quiet > /dev/null
check "--margin overrides every technique's margin in --params-file" 'python3 -c "
import json,sys; b=json.load(open(sys.argv[1]))
assert all(r[\"parameters\"][\"margin\"] == 1.75 for r in b[\"results\"] if r[\"technique\"] != \"native\"), b[\"results\"]
" "$tmp/b3/results.json"'
"$F" bench --scene cheap --size 64x36 --frames 1 --techniques native,layered --params-file "$tmp/t/params.json" --param margin=3.5 --out "$tmp/b4" --quiet > /dev/null
check "--param KEY=V for every technique overrides the file's TECHNIQUE.KEY" 'python3 -c "
import json,sys; b=json.load(open(sys.argv[1]))
assert [r for r in b[\"results\"] if r[\"technique\"]==\"layered\"][0][\"parameters\"][\"margin\"] == 3.5
" "$tmp/b4/results.json"'

# Shards of a benchmark, merged: the runs of one run, native's JOD and each run's.
"$F" bench --scene cheap "${small[@]}" --techniques native,layered,inset,checkerboard --out "$tmp/whole" --quiet > /dev/null
for k in 1 2; do
  "$F" bench --scene cheap "${small[@]}" --techniques native,layered,inset,checkerboard --shard $k/2 --out "$tmp/s$k" --quiet > /dev/null
done
"$F" merge "$tmp/s2" "$tmp/s1/results.json" --out "$tmp/m" --quiet > "$tmp/m.md"
check "merge writes one result and report" '[[ -s "$tmp/m/results.json" && -s "$tmp/m/report.html" ]] && grep -Eq "^\| checkerboard( †)? \|" "$tmp/m.md"'
check "merged shards: the same runs, pixels and JOD as one run" 'python3 -c "
import json,sys; a=json.load(open(sys.argv[1])); b=json.load(open(sys.argv[2]))
assert b[\"shard\"] == {\"merged\": 2}
ra=[(r[\"technique\"], r[\"shaded_pixels\"], r[\"quality\"][\"jod\"]) for r in a[\"results\"]]
rb=[(r[\"technique\"], r[\"shaded_pixels\"], r[\"quality\"][\"jod\"]) for r in b[\"results\"]]
assert ra == rb, (ra, rb)
" "$tmp/whole/results.json" "$tmp/m/results.json"'
err=$("$F" merge "$tmp/s1" --out "$tmp/m2" 2>&1); rc=$?
check "merge of one shard of two: exit 1, names the shard given and the one missing" \
  '[[ $rc -eq 1 && "$err" == *"s1/results.json: one of 2 shards, and shard 2 of 2 is not given"* ]]'
err=$("$F" report "$tmp/s1" --out "$tmp/r2" 2>&1); rc=$?
check "report of one shard of two: the same, without a merge command named" \
  '[[ $rc -eq 1 && "$err" == *"shard 2 of 2 is not given"* && "$err" != *"merge:"* ]]'
err=$("$F" merge "$tmp/s1" "$tmp/whole" --out "$tmp/m3" 2>&1); rc=$?
check "merge of a shard and a whole run: exit 1, names the file" '[[ $rc -eq 1 && "$err" == *"whole"* ]]'
err=$("$F" merge "$tmp/s1" "$tmp/t" --out "$tmp/m4" 2>&1); rc=$?
check "merge of a bench and a tune result: exit 1" '[[ $rc -eq 1 && "$err" == *"tune"* ]]'

for args in "--shard 3/2" "--shard 0/2" "--shard x" ; do
  err=$("$F" bench --scene cheap --size 64x36 --frames 1 $args --out "$tmp/x" 2>&1); rc=$?
  check "bench $args: exit 1, names --shard" '[[ $rc -eq 1 && "$err" == *"--shard"* ]]'
done
echo '{"schema": "foveate-params/1", "techniques": {"layered": {"margin": 9}}}' > "$tmp/bad.json"
err=$("$F" bench --scene cheap --size 64x36 --frames 1 --params-file "$tmp/bad.json" --out "$tmp/x" 2>&1); rc=$?
check "a parameter out of range in --params-file: exit 1, names the file and entry" '[[ $rc -eq 1 && "$err" == *"--params-file"*"bad.json"*"layered.margin"* ]]'
err=$("$F" tune --scenes cheap --bound 0 --out "$tmp/x" 2>&1); rc=$?
check "tune --bound 0: exit 1, names --bound" '[[ $rc -eq 1 && "$err" == *"--bound"* ]]'
err=$("$F" tune --scenes cheap --techniques native --out "$tmp/x" 2>&1); rc=$?
check "tune native: exit 1" '[[ $rc -eq 1 && "$err" == *"native"* ]]'
"$F" tune --scenes cheap --techniques inset --bound 0.5 "${small[@]}" --values margin=2,1 --values inset.scale=0.45 --out "$tmp/tv" --quiet > "$tmp/tv.md"
check "tune --values: the margins and scale searched are those given" 'python3 -c "
import json,sys
j=json.load(open(sys.argv[1]))
assert {p[\"params\"][\"margin\"] for p in j[\"points\"]} == {1, 2}
assert {p[\"params\"].get(\"scale\") for p in j[\"points\"]} <= {None, 0.45}
assert j[\"settings\"][\"values\"] == {\"inset.scale\": [0.45], \"margin\": [1, 2]}
" "$tmp/tv/tune.json" && grep -q "Values searched instead of the declared ones: inset.scale=0.45 margin=1,2." "$tmp/tv.md"'
for args in "vrs.adapt=0.3" "margin=1,1" "margin=1,x" "margin=" "margin=9"; do
  err=$("$F" tune --scenes cheap --techniques inset --values "$args" --out "$tmp/x" 2>&1); rc=$?
  check "tune --values $args: exit 1, names --values" '[[ $rc -eq 1 && "$err" == *"--values"* ]]'
done
err=$("$F" tune --scenes cheap --techniques inset --values margin=1 --values margin=2 --out "$tmp/x" 2>&1); rc=$?
check "tune --values for one key twice: exit 1" '[[ $rc -eq 1 && "$err" == *"margin is given twice"* ]]'
"$F" tune --help | grep -q -- --bound && "$F" merge --help | grep -q -- --out
check "help lists the options" '[[ $? -eq 0 ]]'
exit $fail
