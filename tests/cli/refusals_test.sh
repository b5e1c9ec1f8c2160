#!/usr/bin/env bash
# Runs that would measure nothing are refused or reported (issue 29, points 1
# and 5): a gaze off the image, a normalized coordinate out of range, a
# --param for a technique not run, a size that leaves little to save, a gaze
# source that leaves the image during a run, an --out folder holding another
# run's output, and the messages that must name their input.
set -u
. "$(dirname "$0")/cli_lib.sh"

# --- A fixed gaze off the image is a user error in render, bench and view.
run render --scene cheap --size 64x36 --gaze 5000,100 --no-write
check "render --gaze off the image: exit 1 naming --gaze and the size" \
  '[[ $rc -eq 1 && "$err" == *"--gaze"* && "$err" == *"outside the 64x36 image"* ]] || { echo "  rc $rc: $err"; false; }'
run bench --scene cheap --size 64x36 --gaze 5000,100 --frames 1 --techniques layered --out "$tmp/b0"
check "bench --gaze off the image: exit 1, nothing written" \
  '[[ $rc -eq 1 && "$err" == *"outside the 64x36 image"* && ! -e "$tmp/b0/results.json" ]] || { echo "  rc $rc: $err"; false; }'
run view --scene cheap --size 64x36 --gaze fixed:-3,10
check "view --gaze off the image: exit 1 before any window" \
  '[[ $rc -eq 1 && "$err" == *"outside the 64x36 image"* ]] || { echo "  rc $rc: $err"; false; }'
# Normalized: a decimal point; out of [0, 1] is an error, not a pixel.
run render --scene cheap --size 64x36 --gaze 1.5,0.5 --no-write
check "--gaze 1.5,0.5: a normalized coordinate out of range" \
  '[[ $rc -eq 1 && "$err" == *"1.5 is outside 0.0..1.0"* ]] || { echo "  rc $rc: $err"; false; }'
run render --scene cheap --size 64x36 --gaze 0.5,540 --no-write
check "--gaze mixing normalized and pixels is refused" '[[ $rc -eq 1 && "$err" == *"mixes"* ]]'
run render --scene cheap --size 64x36 --gaze 1.0,0.25 --no-write --json
check "--gaze 1.0,0.25 is the right edge, a quarter down" '[[ $rc -eq 0 ]] || { echo "  rc $rc: $err"; false; }'
check "render --help states the rule" '"$F" render --help | tr -s " \n" " " | grep -q "decimal point are normalized"'

# --- A gaze source that leaves the image during a run is counted and reported.
# On the image for 30 ms, then just right of it (within what trackers report).
python3 -c 'print("time_s,x,y"); [print(f"{k / 100:.2f},{0.5 if k < 3 else 1.1},0.5") for k in range(101)]' > "$tmp/away.csv"
run bench --scene cheap --size 64x36 --frames 6 --warmup 0 --techniques layered --no-metrics \
  --gaze "trace:$tmp/away.csv" --out "$tmp/b1"
check "bench with a trace leaving the image runs" '[[ $rc -eq 0 ]] || { echo "  rc $rc: $err"; false; }'
check "...its table marks the rows and says which frames ran in fallback" \
  '[[ "$out" == *"| layered"*"‡"* && "$out" == *"‡ Gaze fallback:"*"of 6 measured frames"* ]] || { echo "$out"; false; }'
check "...results.json lists those frames and the gaze report" 'python3 -c "
import json, sys
j = json.load(open(sys.argv[1]))
f = j[\"gaze_fallback_frames\"]
assert f and all(0 <= k < 6 for k in f), f
assert \"off the image\" in j[\"gaze_report\"], j[\"gaze_report\"]
" "$tmp/b1/results.json"'
run render --scene cheap --size 64x36 --frames 6 --technique layered --gaze "trace:$tmp/away.csv" --no-write
check "render reports the frames off the image" '[[ "$out" =~ [1-9][0-9]*\ off\ the\ image ]] || { echo "$out"; false; }'

# --- The savings note: whenever the planner's bound is under 1.5x.
# (plan plans layered, at its own margin 1.5 by default: 1.76x at 960x540;
# render at its technique's margin, here given; techniques at the strictest
# own margin, lodmask's and marwarp's 2.)
for cmd in "render --scene cheap --technique layered --margin 3 --no-write" "techniques" "plan --margin 3"; do
  run $cmd --size 960x540
  check "$cmd at 960x540 notes that there is little to save" \
    '[[ $rc -eq 0 && "$err" == *"little or nothing to save"* && "$err" == *"under 1.5x"* ]] || { echo "  rc $rc: $err"; false; }'
done
run plan --size 1920x1080
check "plan at 1920x1080 gives no such note" '[[ $rc -eq 0 && "$err" != *"little or nothing to save"* ]]'
run bench --scene cheap --size 64x36 --frames 1 --warmup 0 --techniques layered --no-metrics --out "$tmp/b2"
check "bench marks the runs of a size with little to save" \
  '[[ "$out" == *"| layered †"* && "$out" == *"† Little to save"* && "$out" != *"| native †"* ]] || { echo "$out"; false; }'
check "...and results.json says so" 'python3 -c "
import json, sys
s = json.load(open(sys.argv[1]))[\"savings\"]
assert s[\"little_to_save\"] and s[\"pixel_bound\"] < 1.5 and s[\"margin\"] == 1.5, s
" "$tmp/b2/results.json"'

# --- A --param for a technique that is not run.
run render --scene cheap --size 64x36 --technique layered --param logpolar.sigma=2 --no-write
check "--param for a technique not run: exit 1 naming it" \
  '[[ $rc -eq 1 && "$err" == *"--param logpolar.sigma"* && "$err" == *"not among the techniques run (layered)"* ]] || { echo "  rc $rc: $err"; false; }'
run bench --scene cheap --size 64x36 --techniques layered --param logpolar.sigma=2 --frames 1 --out "$tmp/b3"
check "bench: the same" '[[ $rc -eq 1 && "$err" == *"not among the techniques run"* ]] || { echo "  rc $rc: $err"; false; }'
run bench --scene cheap --size 64x36 --techniques layered --reference ssaa:4 --no-metrics --frames 1 --out "$tmp/b4"
check "bench --reference ssaa with --no-metrics: exit 1 naming both, nothing written" \
  '[[ $rc -eq 1 && "$err" == *"--reference: the supersampled reference is what the image metrics judge against, and --no-metrics turns them off"* && ! -e "$tmp/b4" ]] || { echo "  rc $rc: $err"; false; }'
run render --scene cheap --size 64x36 --technique layered --param layered.sigma=2 --no-write
check "a key the technique does not declare" '[[ $rc -eq 1 && "$err" == *"layered has no parameter '"'"'sigma'"'"'"* ]] || { echo "  rc $rc: $err"; false; }'
run render --scene cheap --size 64x36 --technique vrs --param vrs.edge_samples=3 --no-write
check "a value between a parameter's listed ones, naming them" '[[ $rc -eq 1 && "$err" == *"vrs parameter edge_samples=3: must be 2 or 4"* ]] || { echo "  rc $rc: $err"; false; }'

# --- plan --margin: by default layered's own, as render plans it.
run plan --size 1920x1080
check "plan says it plans at layered's own margin by default" '[[ "$out" == *"planned at margin 1.5"* ]] || { echo "$out"; false; }'
run plan --size 1920x1080 --margin 1
check "plan --margin 1 is the paper's plan" '[[ "$out" == *"planned at margin 1 (the paper'"'"'s plan"* ]] || { echo "$out"; false; }'
run plan --margin 0.5
check "plan --margin out of range is an error" '[[ $rc -eq 1 && "$err" == *"--margin"* ]] || { echo "  rc $rc: $err"; false; }'
python3 - "$F" <<'PY' && echo "ok: plan's default margin is layered's own in 'techniques'" || { echo "FAIL: plan and techniques disagree on layered's margin"; fail=1; }
import json, subprocess, sys
f = sys.argv[1]
plan = json.loads(subprocess.run([f, "plan", "--json"], capture_output=True, text=True, check=True).stdout)
tech = json.loads(subprocess.run([f, "techniques", "--json"], capture_output=True, text=True, check=True).stdout)
tech = tech["techniques"] if isinstance(tech, dict) else tech
layered = next(t for t in tech if t["name"] == "layered")
margin = [p for p in layered["parameters"] if p["key"] == "margin"][0]
value = margin.get("value", margin.get("default"))
assert plan["margin"] == value, (plan["margin"], margin)
PY

# --- An --out folder holding another run's output.
run render --scene cheap --size 64x36 --frames 3 --out "$tmp/r"
check "a first render into a new folder" '[[ $rc -eq 0 && -s "$tmp/r/frame-0002.png" ]] || { echo "  rc $rc: $err"; false; }'
check "...leaves no lock file behind" '[[ ! -e "$tmp/r/.foveate.lock" ]]'
run render --scene cheap --size 32x18 --frames 1 --out "$tmp/r"
check "a second render into it is refused, naming --out and --overwrite" \
  '[[ $rc -eq 1 && "$err" == *"--out $tmp/r: holds the output of an earlier run (frame-0000.png and 2 more)"* && "$err" == *"--overwrite"* ]] || { echo "  rc $rc: $err"; false; }'
check "...and leaves the first run's frames alone" '[[ -s "$tmp/r/frame-0002.png" && ! -e "$tmp/r/.foveate.lock" ]]'
run render --scene cheap --size 32x18 --frames 1 --out "$tmp/r" --overwrite
check "--overwrite replaces them and says so" \
  '[[ $rc -eq 0 && "$err" == *"removed the earlier run'"'"'s output (frame-0000.png and 2 more)"* ]] || { echo "  rc $rc: $err"; false; }'
check "...so that only the new run's frames are left" '[[ "$(ls -A "$tmp/r")" == "frame-0000.png" ]] || { ls -A "$tmp/r"; false; }'
mkdir -p "$tmp/other" && echo keep > "$tmp/other/notes.txt"
run render --scene cheap --size 32x18 --frames 1 --out "$tmp/other"
check "a folder with other files only is not another run's output" '[[ $rc -eq 0 && -s "$tmp/other/notes.txt" ]]'
run bench --scene cheap --size 32x18 --frames 1 --warmup 0 --techniques layered --no-metrics --out "$tmp/b2"
check "bench refuses its own earlier output too" '[[ $rc -eq 1 && "$err" == *"holds the output of an earlier run"* ]] || { echo "  rc $rc: $err"; false; }'
printf 'v 0 0 0\nv 1 0 0\nf 1 2 3\n' > "$tmp/bad.obj"
run render --scene "$tmp/bad.obj" --size 32x18 --frames 1 --out "$tmp/new/a/b"
check "a run that fails before writing removes the folders it made for --out" \
  '[[ $rc -eq 1 && "$err" == *"bad.obj"* && ! -e "$tmp/new" ]] || { echo "  rc $rc: $err"; ls -R "$tmp/new"; false; }'
mkdir -p "$tmp/mine"
run render --scene "$tmp/bad.obj" --size 32x18 --frames 1 --out "$tmp/mine"
check "...but never a folder that was there before" '[[ $rc -eq 1 && -d "$tmp/mine" ]]'

# --- Messages that name their input and the reason.
cat > "$tmp/tiny.json" <<'JSON'
{"name": "tiny", "width_px": 64, "height_px": 36, "width_mm": 2, "distance_mm": 590}
JSON
run plan --display "$tmp/tiny.json" --size 64x36 --layers 3
check "a display too small for the plan is named by its file" \
  '[[ $rc -eq 1 && "$err" == *"$tmp/tiny.json"*"too small for 3 layers"* ]] || { echo "  rc $rc: $err"; false; }'
head -c 300 "$FOVEATE_SOURCE_DIR/tests/data/models/quad.gltf" > "$tmp/cut.gltf"
run render --scene "$tmp/cut.gltf" --size 32x18 --no-write
check "a truncated glTF: its file and the reason" \
  '[[ $rc -eq 1 && "$err" == *"$tmp/cut.gltf"* && "$err" == *"truncated or corrupt"* ]] || { echo "  rc $rc: $err"; false; }'
run render --scene cheap --size 64x36 --technique checkerboard --param checkerboard.r1=30 --param checkerboard.r2=10 --no-write
check "decreasing checkerboard thresholds show their values" \
  '[[ $rc -eq 1 && "$err" == *"must not decrease, got 30, 10,"* ]] || { echo "  rc $rc: $err"; false; }'

# --- A memory limit that holds not even native and one judged run.
run bench --scene cheap --size 640x360 --frames 1 --warmup 0 --techniques layered --memory-limit 20M --out "$tmp/b-mem"
check "bench --memory-limit too small: exit 1 naming the flag and the size, nothing written" \
  '[[ $rc -eq 1 && "$err" == *"--memory-limit: 20 MiB holds not even native and one run"* && "$err" == *"--size"* && ! -e "$tmp/b-mem/results.json" ]] || { echo "  rc $rc: $err"; false; }'
run bench --scene cheap --size 64x36 --frames 1 --warmup 0 --techniques layered --memory-limit lots --out "$tmp/b-mem"
check "bench --memory-limit lots: exit 1 naming the flag" \
  '[[ $rc -eq 1 && "$err" == *"--memory-limit"* ]] || { echo "  rc $rc: $err"; false; }'

exit $fail
