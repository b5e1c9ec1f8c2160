#!/usr/bin/env bash
# Stereo head-mounted displays on the command line: `render --stereo` and
# `bench --stereo` with every technique on the hmd-quest2 preset, the
# side-by-side output, per-eye figures in the JSON and Markdown, and the
# errors for bad stereo input (exit 1, naming the input and the reason).
set -u
fail=0
check() { if ! eval "$2"; then echo "FAIL: $1"; fail=1; else echo "ok: $1"; fi; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
px() { python3 "$FOVEATE_SOURCE_DIR/tests/cli/pngpixel.py" "$@"; }

# Every technique renders both eyes of a mesh scene, side by side.
for t in native layered logpolar checkerboard lodmask inset vrs; do
  if "$FOVEATE" render --scene guenter --display hmd-quest2 --stereo --size 64x48 --frames 2 \
       --technique "$t" --vergence 1.5 --json --out "$tmp/$t" > "$tmp/$t.json" 2> "$tmp/$t.err" &&
     [[ "$(px "$tmp/$t/frame-0001.png" size)" == "128 48" ]]; then :; else
    echo "FAIL: render --stereo with $t: $(cat "$tmp/$t.err")"; fail=1
  fi
done
echo "ok: every technique renders both eyes (128x48 for two 64x48 eyes)"
check "render --json reports each eye" 'python3 - "$tmp/layered.json" <<PY
import json, sys
j = json.load(open(sys.argv[1]))
s = j["stereo"]
assert j["size"] == [128, 48] and s["eye_size"] == [64, 48], j
assert s["ipd_mm"] == 63.5 and s["vergence_m"] == 1.5, s
for e in ("left", "right"):
    assert 0 < s["eyes"][e]["pixel_ratio"] < 1.1, s  # little to save at 64x48
assert abs(j["shaded_pixels_per_frame"] - s["eyes"]["left"]["shaded_pixels_per_frame"]
           - s["eyes"]["right"]["shaded_pixels_per_frame"]) < 1e-6, j
PY'

# The two eyes of a mesh scene differ; a Shadertoy scene is the same image per eye.
check "mesh scene: the eyes differ" '[[ "$(px "$tmp/native/frame-0000.png" 20,30 40,20)" != "$(px "$tmp/native/frame-0000.png" 84,30 104,20)" ]]'
"$FOVEATE" render --scene cheap --display hmd-quest2 --stereo --size 48x32 --out "$tmp/st" > /dev/null
check "Shadertoy scene: the same image per eye" '[[ "$(px "$tmp/st/frame-0000.png" 5,5 20,16 40,30)" == "$(px "$tmp/st/frame-0000.png" 53,5 68,16 88,30)" ]]'

# bench: per stereo frame times, per-eye and combined quality.
"$FOVEATE" bench --scene guenter --display hmd-quest2 --stereo --size 64x48 --frames 2 --warmup 1 \
  --techniques native,layered,vrs --out "$tmp/b" --quiet > /dev/null 2> "$tmp/b.err"
check "bench --stereo writes results" '[[ -s "$tmp/b/results.json" && -s "$tmp/b/report.html" ]] || { cat "$tmp/b.err"; false; }'
check "bench JSON has each eye and the combined figures" 'python3 - "$tmp/b/results.json" <<PY
import json, sys
j = json.load(open(sys.argv[1]))
s = j["stereo"]
assert s["output_size"] == [128, 48] and s["eye_size"] == [64, 48], s
assert s["left"]["fov_deg"]["left"] == -s["right"]["fov_deg"]["right"], s
assert s["vergence_m"] == "inf", s
gl, gr = s["sample_gaze_px"]["left"], s["sample_gaze_px"]["right"]
assert abs(gl[0] + gr[0] - 64) < 1e-6 and gl[0] > 32, s   # mirrored axes, parallel gaze
for r in j["results"]:
    eyes = r["eyes"]
    assert abs(eyes["left"]["shaded_pixels"] + eyes["right"]["shaded_pixels"] - r["shaded_pixels"]) < 1e-6, r
    if r["technique"] != "native":
        # Each eye judged over the 2 frames; the combined figures over both eyes, 4 frames.
        for e in ("left", "right"):
            assert eyes[e]["quality"]["frames"] == 2 and 0 < eyes[e]["quality"]["ssim"] <= 1, eyes[e]
        q = r["quality"]
        assert q["frames"] == 4, q
        mean = (eyes["left"]["quality"]["ssim"] + eyes["right"]["quality"]["ssim"]) / 2
        assert abs(q["ssim"] - mean) < 1e-6, (q["ssim"], mean)
PY'
check "bench Markdown has the per-eye table" 'grep -q "| layered | left |" "$tmp/b/results.md" && grep -q "| layered | right |" "$tmp/b/results.md" && grep -q "per stereo frame" "$tmp/b/results.md"'

# view: both eyes side by side in the window, the combined gaze mapped to each eye.
if command -v Xvfb >/dev/null; then
  source "$(dirname "$0")/xvfb_server.sh"
  start_xvfb
  "$FOVEATE" view --scene guenter --display hmd-quest2 \
    --stereo --size 160x120 --technique layered --gaze 0.5,0.5 --vergence 1 \
    --commands "frames 2; print-state; display desktop-1080p; quit" > "$tmp/view.json" 2> "$tmp/view.err"
  check "view --stereo shows both eyes and each eye's gaze" 'python3 - "$tmp/view.json" <<PY
import json, sys
j = json.loads(open(sys.argv[1]).readline())
l, r = j["stereo"]["left_px"], j["stereo"]["right_px"]
# The left eye looks right of its image centre (its axis is right of centre,
# and it converges inwards at 1 m), the right eye mirrors it.
assert l[0] > 80 and r[0] < 80 and abs(l[0] + r[0] - 160) < 1e-6, j["stereo"]
assert j["native_pixels"] == 2 * 160 * 120, j["native_pixels"]
PY'
  check "view --stereo refuses a display switch" 'grep -q "display of a stereo view is fixed" "$tmp/view.err"'
else
  echo "FAIL: Xvfb is missing (scripts/setup.sh installs xvfb)"; fail=1
fi

expect_error() {  # name, exit code, expected text, args...
  local name=$1 code=$2 text=$3; shift 3
  local err rc
  err=$("$FOVEATE" "$@" 2>&1); rc=$?
  if [[ $rc -eq $code && "$err" == *"$text"* ]]; then echo "ok: $name"; else echo "FAIL: $name (exit $rc): $err"; fail=1; fi
}
expect_error "a monocular headset is not stereo" 1 "--stereo: display 'hmd-quest3': not a stereo head-mounted display" \
  render --scene cheap --display hmd-quest3 --stereo --size 32x32 --out "$tmp/x"
expect_error "a desktop is not stereo" 1 "not a stereo head-mounted display" \
  bench --scene cheap --display desktop-1080p --stereo --size 32x32 --out "$tmp/x"
cat > "$tmp/ipd0.json" <<J
{"width_px": 64, "height_px": 64, "fov_deg": {"left": -50, "right": 45, "up": 45, "down": -50}, "ipd_mm": 0}
J
expect_error "IPD of 0" 1 "ipd_mm" render --scene cheap --display "$tmp/ipd0.json" --stereo --size 32x32 --out "$tmp/x"
cat > "$tmp/noipd.json" <<J
{"width_px": 64, "height_px": 64, "fov_deg": {"left": -50, "right": 45, "up": 45, "down": -50}}
J
expect_error "no IPD" 1 "needs an inter-pupillary distance ipd_mm > 0" render --scene cheap --display "$tmp/noipd.json" --stereo --size 32x32 --out "$tmp/x"
cat > "$tmp/wide.json" <<J
{"width_px": 64, "height_px": 64, "fov_deg": {"left": -50, "right": 45, "up": 95, "down": -50}, "ipd_mm": 63}
J
expect_error "an angle out of range" 1 "fov_deg.up" render --scene cheap --display "$tmp/wide.json" --stereo --size 32x32 --out "$tmp/x"
cat > "$tmp/crossed.json" <<J
{"width_px": 64, "height_px": 64, "fov_deg": {"left": 40, "right": 30, "up": 45, "down": -50}, "ipd_mm": 63}
J
expect_error "right edge left of the left edge" 1 "fov_deg.right (30) must be greater than fov_deg.left (40)" \
  render --scene cheap --display "$tmp/crossed.json" --stereo --size 32x32 --out "$tmp/x"
expect_error "vergence of 0" 1 "--vergence: expected a distance in metres > 0" \
  render --scene cheap --display hmd-quest2 --stereo --vergence 0 --size 32x32 --out "$tmp/x"
expect_error "vergence without --stereo" 1 "--vergence: only with --stereo" \
  render --scene cheap --display hmd-quest2 --vergence 2 --size 32x32 --out "$tmp/x"
expect_error "supersampled reference with stereo" 1 "--reference: the supersampled reference is monocular" \
  render --scene cheap --display hmd-quest2 --stereo --reference ssaa:2 --size 32x32 --out "$tmp/x"
expect_error "bench reference with stereo" 1 "--reference: the supersampled reference is monocular" \
  bench --scene cheap --display hmd-quest2 --stereo --reference ssaa:2 --size 32x32 --out "$tmp/x"
expect_error "side-by-side video with stereo" 1 "--side-by-side: not available with --stereo" \
  render --scene cheap --display hmd-quest2 --stereo --video "$tmp/x.mp4" --side-by-side --size 32x32
check "no output left behind by the errors" '[[ ! -e "$tmp/x/frame-0000.png" && ! -e "$tmp/x.mp4" ]]'
exit $fail
