#!/usr/bin/env bash
# `foveate render`, `scenes`, `techniques` and `bench` as a user runs them:
# outputs, and clear errors with a non-zero exit on bad input.
set -u
fail=0
check() { if ! eval "$2"; then echo "FAIL: $1"; fail=1; else echo "ok: $1"; fi; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
data="$FOVEATE_SOURCE_DIR/tests/data/shadertoy"

"$FOVEATE" scenes > "$tmp/scenes.txt"
check "scenes lists the built-ins" 'grep -q raymarch "$tmp/scenes.txt" && grep -q detail "$tmp/scenes.txt" && grep -q cheap "$tmp/scenes.txt"'
"$FOVEATE" techniques > "$tmp/tech.txt"
check "techniques lists each with parameters" 'for t in native layered logpolar checkerboard lodmask inset; do grep -q "^$t " "$tmp/tech.txt" || exit 1; done; grep -q "sigma" "$tmp/tech.txt"'

"$FOVEATE" render --scene cheap --size 64x36 --frames 2 --technique layered --overlay --out "$tmp/r" > "$tmp/out.txt"
check "render writes the frames" '[[ -s "$tmp/r/frame-0000.png" && -s "$tmp/r/frame-0001.png" ]]'
check "render reports shaded pixels" 'grep -q "shaded pixels" "$tmp/out.txt"'
"$FOVEATE" render --scene "$data/channels.glsl" --size 64x32 --mouse 48,10 --out "$tmp/s" >/dev/null
check "render a Shadertoy file with a channel and the mouse" '[[ -s "$tmp/s/frame-0000.png" ]]'
"$FOVEATE" render --scene "$data/missing_texture.glsl" --channel "$data/quadrants.png" --size 32x32 --out "$tmp/c" >/dev/null
check "render with --channel" '[[ -s "$tmp/c/frame-0000.png" ]]'

# Every gaze source drives every technique (guenter has meshes, so lodmask runs too).
"$FOVEATE" gaze synth --seed 4 --seconds 2 --out "$tmp/trace.csv" > /dev/null
# (A fixed gaze off the image is refused: refusals_test.sh.)
for src in "fixed:0.3,0.4" "synthetic:2" "trace:$tmp/trace.csv" "nearest" "63,0"; do
  for t in layered logpolar checkerboard lodmask inset; do
    if "$FOVEATE" render --scene guenter --size 64x36 --frames 2 --technique "$t" --gaze "$src" \
         --overwrite --out "$tmp/g" > "$tmp/g.txt" 2>&1 && [[ -s "$tmp/g/frame-0001.png" ]]; then :; else
      echo "FAIL: gaze $src with $t: $(cat "$tmp/g.txt")"; fail=1
    fi
  done
done
echo "ok: every gaze source drives every technique"

expect_error() {  # name, expected text, args...
  local name=$1 text=$2; shift 2
  local err rc
  err=$("$FOVEATE" "$@" 2>&1); rc=$?
  if [[ $rc -ne 0 && "$err" == *"$text"* ]]; then echo "ok: $name"; else echo "FAIL: $name (exit $rc): $err"; fail=1; fi
}
expect_error "shader syntax error names file and line" "syntax_error.glsl:4:" render --scene "$data/syntax_error.glsl" --size 32x32 --out "$tmp/x"
expect_error "shader without mainImage" "mainImage" render --scene "$data/no_main_image.glsl" --size 32x32 --out "$tmp/x"
expect_error "missing texture" "does-not-exist.png" render --scene "$data/missing_texture.glsl" --size 32x32 --out "$tmp/x"
expect_error "missing channel file" "nope.png" render --scene "$data/channels.glsl" --channel "$tmp/nope.png" --size 32x32 --out "$tmp/x"
echo "not an image" > "$tmp/bad.png"
expect_error "unreadable texture" "bad.png" render --scene "$data/channels.glsl" --channel "$tmp/bad.png" --size 32x32 --out "$tmp/x"
expect_error "unknown scene" "not a built-in scene" render --scene nosuch --size 32x32 --out "$tmp/x"
expect_error "size zero" "--size" render --scene cheap --size 0x32 --out "$tmp/x"
expect_error "size too large" "--size" render --scene cheap --size 40000x32 --out "$tmp/x"
expect_error "size garbage" "--size" render --scene cheap --size big --out "$tmp/x"
expect_error "unknown technique" "unknown technique" render --scene cheap --size 32x32 --technique warp --out "$tmp/x"
expect_error "unknown parameter" "no such parameter" render --scene cheap --size 32x32 --technique layered --param sigma=2 --out "$tmp/x"
expect_error "parameter out of range" "out of range" render --scene cheap --size 32x32 --technique layered --param layers=12 --out "$tmp/x"
expect_error "parameter not a number" "not a number" render --scene cheap --size 32x32 --technique layered --param layers=three --out "$tmp/x"
expect_error "frames zero" "--frames" render --scene cheap --size 32x32 --frames 0 --out "$tmp/x"
expect_error "bad gaze" "--gaze" render --scene cheap --size 32x32 --gaze left --out "$tmp/x"
expect_error "mouse off the image" "--mouse: '500,10' is (500, 10) px, outside the 64x32 image" render --scene "$data/channels.glsl" --size 64x32 --mouse 500,10 --out "$tmp/x"
expect_error "missing gaze trace" "nope.csv" render --scene cheap --size 32x32 --gaze "trace:$tmp/nope.csv" --out "$tmp/x"
expect_error "mouse without a window" "window" render --scene cheap --size 32x32 --gaze mouse --out "$tmp/x"
expect_error "lodmask on a shader scene" "has no meshes" render --scene cheap --size 32x32 --technique lodmask --out "$tmp/x"
expect_error "bad camera path" "channels.json" render --scene cheap --size 32x32 --camera-path "$data/channels.json" --out "$tmp/x"
check "no partial files left" '[[ -z "$(find "$tmp" -name "*.tmp-*")" ]]'

"$FOVEATE" bench --scene cheap --size 96x54 --frames 3 --warmup 1 --no-metrics --quiet --out "$tmp/b" > "$tmp/bench.txt"
check "bench writes json, csv, md, html" '[[ -s "$tmp/b/results.json" && -s "$tmp/b/results.csv" && -s "$tmp/b/results.md" && -s "$tmp/b/report.html" ]]'
check "bench json has the documented fields" 'python3 -c "
import json,sys
j=json.load(open(sys.argv[1]))
assert j[\"schema\"]==\"foveate-bench/1\"
names=[r[\"technique\"] for r in j[\"results\"]]
assert names[0]==\"native\" and \"layered\" in names, names
for r in j[\"results\"]:
  for k in (\"technique\",\"median_ms\",\"speedup\",\"pixel_ratio\",\"quality\",\"speedup_ci95\",\"frame_ms\"): assert k in r, k
  assert len(r[\"frame_ms\"])==3
  assert r[\"speedup_ci95\"][0] <= r[\"speedup\"] <= r[\"speedup_ci95\"][1] + 1e-9
assert j[\"results\"][0][\"speedup\"]==1.0
" "$tmp/b/results.json"'
"$FOVEATE" bench --scene cheap --size 96x54 --frames 2 --warmup 0 --no-metrics --quiet --techniques layered --sweep slope=0.02:0.04:0.01 --out "$tmp/sw" > /dev/null
check "sweep runs each value" 'python3 -c "
import json,sys
j=json.load(open(sys.argv[1]))
vals=[r[\"sweep_value\"] for r in j[\"results\"] if r[\"technique\"]==\"layered\"]
assert [round(v,3) for v in vals]==[0.02,0.03,0.04], vals
" "$tmp/sw/results.json"'
"$FOVEATE" bench --scene cheap --size 96x54 --frames 1 --warmup 0 --no-metrics --quiet --techniques layered --sweep layered.margin=2,1 --out "$tmp/sl" > /dev/null
check "a listed sweep runs each value, in ascending order" 'python3 -c "
import json,sys
j=json.load(open(sys.argv[1]))
assert [r[\"sweep_value\"] for r in j[\"results\"] if r[\"technique\"]==\"layered\"]==[1,2]
assert j[\"sweep\"][\"values\"]==[1,2], j[\"sweep\"]
" "$tmp/sl/results.json"'
"$FOVEATE" bench --scene cheap --size 64x36 --frames 2 --warmup 0 --quiet --techniques native,inset --reference ssaa:2 --out "$tmp/ref" > /dev/null
check "bench judges native too against a supersampled reference" 'python3 -c "
import json,sys
j=json.load(open(sys.argv[1]))
assert j[\"reference\"]==\"ssaa:2\", j[\"reference\"]
for r in j[\"results\"]:
  assert r[\"quality\"].get(\"frames\")==2, (r[\"technique\"], r[\"quality\"])
" "$tmp/ref/results.json"'
"$FOVEATE" render --scene cheap --size 64x36 --frames 2 --reference ssaa:2 --out "$tmp/rr" > /dev/null
check "render writes the reference frames beside its own" '[[ -s "$tmp/rr/reference-0000.png" && -s "$tmp/rr/reference-0001.png" && -s "$tmp/rr/frame-0001.png" ]]'
expect_error "bad reference" "--reference" bench --scene cheap --size 32x32 --reference ssaa:12 --out "$tmp/x"
expect_error "bad sweep" "--sweep" bench --scene cheap --size 32x32 --sweep layers=1:2 --out "$tmp/x"
expect_error "sweep of an unknown key" "no technique has" bench --scene cheap --size 32x32 --sweep warp=1:2:1 --out "$tmp/x"
expect_error "a value listed twice" "--sweep margin: 1 is listed twice" bench --scene cheap --size 32x32 --sweep margin=1,2,1 --out "$tmp/x"
expect_error "a listed value that is no number" "--sweep: 'x' is not a number" bench --scene cheap --size 32x32 --sweep margin=1,x --out "$tmp/x"
expect_error "a swept margin with --margin" "--sweep margin and --margin: the sweep sets each run's margin" bench --scene cheap --size 32x32 --sweep margin=1,2 --margin 1.5 --out "$tmp/x"
expect_error "an empty listed value" "--sweep: '' is not a number" bench --scene cheap --size 32x32 --sweep margin=1, --out "$tmp/x"
exit $fail
