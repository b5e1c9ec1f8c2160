#!/usr/bin/env bash
# `foveate view` in a real window under Xvfb: the panel (Dear ImGui) beside the
# image, driven by a script through the same actions as the panel; the state
# it prints and the screenshots it takes are checked.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
source "$(dirname "$0")/xvfb_server.sh"
start_xvfb
fail=0
xvfb() { "$@"; }  # every command runs on the script's one Xvfb server
check() {  # check NAME COMMAND...
  local name=$1; shift
  if out=$("$@" 2>&1); then echo "ok: $name"; else echo "FAIL: $name: $out"; fail=1; fi
}

# One short session: --param values from the command line, a parameter set by
# the script, technique switches away and back, split screen, A/B.
xvfb "$FOVEATE" view --scene cheap --size 320x180 --gaze 0.5,0.5 --technique layered \
  --param layered.transition=0.3 --param logpolar.blur=0.5 --commands "
    frames 2
    param layers=3            # the current technique's (layered)
    technique logpolar
    print-state
    param sigma=1.5
    technique layered
    measure
    frames 3
    print-state
    screenshot $tmp/shot.png
    technique logpolar; print-state
    technique layered
    split on; divider 0.25; frames 2
    screenshot $tmp/split.png; print-state
    split off; ab native; frames 1; print-state
    quit" > "$tmp/out.jsonl" 2> "$tmp/err.txt"
rc=$?
if [[ $rc -eq 0 ]]; then echo "ok: scripted view ran"; else echo "FAIL: scripted view (exit $rc): $(cat "$tmp/err.txt")"; fail=1; fi
if grep -q "Space A/B" "$tmp/err.txt" && ! grep -q "Space A/B" "$tmp/out.jsonl"; then
  echo "ok: the key list goes to stderr at startup"
else
  echo "FAIL: key list not on stderr only: $(cat "$tmp/err.txt")"; fail=1
fi

check "state lines: parameters persist across switches, measurements present" python3 - "$tmp/out.jsonl" <<'PY'
import json, sys
lines = open(sys.argv[1]).read().splitlines()
states = [json.loads(l) for l in lines]   # every stdout line is JSON
assert len(states) == 5, f"expected 5 state lines, got {len(states)}: {lines}"
s1, s2, s3, s4, s5 = states
# 1: logpolar keeps its --param; layered's script value is remembered.
assert s1["technique"] == "logpolar", s1["technique"]
assert s1["params"]["blur"] == 0.5, s1["params"]
assert s1["overrides_by_technique"]["layered"] == {"layers": 3, "transition": 0.3}, s1
# 2: back on layered: the script's layers=3 and --param transition=0.3 both kept.
assert s2["technique"] == "layered"
assert s2["params"]["layers"] == 3 and s2["params"]["transition"] == 0.3, s2["params"]
assert s2["overrides"] == {"layers": 3, "transition": 0.3}, s2["overrides"]
assert s2["frame_ms"] > 0 and s2["native_ms"] > 0, s2
assert abs(s2["speedup"] - s2["native_ms"] / s2["frame_ms"]) < 1e-9 * s2["speedup"] + 1e-12, s2
assert s2["shaded_pixels"] > 0 and s2["native_pixels"] == 320 * 180, s2
assert abs(s2["shaded_share"] - s2["shaded_pixels"] / s2["native_pixels"]) < 1e-12, s2
assert s2["quality"] == "A" and s2["slope"] == 0.0275 and s2["display"] == "desktop-1080p", s2
assert s2["margin"] is None and s2["params"]["margin"] == 1.5, s2  # layered's own
assert s2["gaze"]["x_px"] == 160 and s2["gaze"]["y_px"] == 90 and s2["gaze"]["valid"], s2["gaze"]
assert "fixed" in s2["gaze"]["source"], s2["gaze"]
labels = [e["label"] for e in s2["legend"]]
assert any(l.startswith("layer 1") for l in labels) and "gaze" in labels, labels
assert all(e["colour"].startswith("#") and len(e["colour"]) == 7 for e in s2["legend"])
# 3: logpolar again: sigma set by the script before the switch, blur from --param.
assert s3["technique"] == "logpolar" and s3["params"]["sigma"] == 1.5 and s3["params"]["blur"] == 0.5, s3["params"]
assert any("native disc" in e["label"] for e in s3["legend"]), s3["legend"]
# 4: split screen at a quarter; 5: A/B flipped to native.
assert s4["split"] is True and s4["divider"] == 0.25 and s4["shown"] == "split", s4
assert s5["split"] is False and s5["shown"] == "native", s5
PY

# A small PNG reader (8-bit RGB/RGBA, not interlaced) for the screenshots.
cat > "$tmp/png.py" <<'PY'
import struct, zlib
def read(path):
    d = open(path, "rb").read()
    assert d[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat = 8, b""
    while pos < len(d):
        n, t = struct.unpack(">I4s", d[pos:pos + 8])
        body = d[pos + 8:pos + 8 + n]
        if t == b"IHDR":
            w, h, depth, ctype, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and ctype in (2, 6) and interlace == 0
        if t == b"IDAT":
            idat += body
        pos += 12 + n
    bpp = 4 if ctype == 6 else 3
    raw, stride, rows, prev = zlib.decompress(idat), w * bpp, [], bytearray(w * bpp)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c; pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line); prev = line
    return w, h, lambda x, y: tuple(rows[y][x * bpp:x * bpp + 3])
PY

# The screenshot: the image top-left (320x180), the panel right of it (its
# opaque background, ImGui's dark WindowBg 0.06 = 15, and white text).
check "screenshot shows the scene and the panel" python3 - "$tmp/shot.png" "$tmp" <<'PY'
import sys; sys.path.insert(0, sys.argv[2]); import png
w, h, px = png.read(sys.argv[1])
# The panel's width beside the image; as tall as the panel needs (at least 560).
assert w == 320 + 380 and h >= 560, (w, h)
panel = [px(x, y) for x in range(330, w - 20, 2) for y in range(30, h, 2)]
bg = sum(1 for p in panel if max(abs(c - 15) for c in p) <= 2) / len(panel)
text = sum(1 for p in panel if min(p) >= 200) / len(panel)
assert bg > 0.3, f"panel background share {bg:.2f}"
assert text > 0.005, f"panel text share {text:.4f}"
scene = [px(x, y) for x in range(4, 316, 2) for y in range(4, 176, 2)]
dark = sum(1 for p in scene if max(p) <= 30) / len(scene)
mean = [sum(p[i] for p in scene) / len(scene) for i in range(3)]
var = sum((sum(p) / 3 - sum(mean) / 3) ** 2 for p in scene) / len(scene)
# The cheap scene: a bright sky over a green-grey ground with orange shapes.
assert dark < 0.01, f"{dark:.2f} of the image is dark (not rendered?)"
assert min(mean) > 90 and var > 50, (mean, var)
below = [px(x, y) for x in range(4, 316, 4) for y in range(200, 550, 4)]
assert all(max(abs(c - q) for c, q in zip(p, (15, 15, 18))) <= 2 for p in below), "below the image: not the clear colour"
PY

check "split screenshot shows the divider at a quarter of the width" python3 - "$tmp/split.png" "$tmp" <<'PY'
import sys; sys.path.insert(0, sys.argv[2]); import png
w, h, px = png.read(sys.argv[1])
col = [px(80, y) for y in range(20, 70)]  # above the handle, below the labels
white = sum(1 for p in col if min(p) >= 190) / len(col)
assert white > 0.9, f"divider column at x=80: {white:.2f} white"
other = [px(200, y) for y in range(20, 70)]
assert sum(1 for p in other if min(p) >= 190) / len(other) < 0.5, "x=200 is white too"
PY

# Real input through X (xdotool): keys switch technique (3 = logpolar), split
# (S) and the overlay (O); the mouse over the image is the gaze.
if command -v xdotool >/dev/null; then
  cat > "$tmp/keys.sh" <<'SH'
"$FOVEATE" view --scene cheap --size 320x180 --commands "frames 1; wait 4; print-state; quit" > "$1" 2>/dev/null &
pid=$!
wid=$(xdotool search --sync --name foveate | head -1)
xdotool windowfocus --sync "$wid" 2>/dev/null || true
xdotool mousemove --window "$wid" 80 45
sleep 0.5
xdotool key --delay 100 3 s o
wait $pid
SH
  FOVEATE="$FOVEATE" xvfb bash "$tmp/keys.sh" "$tmp/keys.jsonl"
  check "keys and mouse: technique 3, split, overlay off, gaze at the mouse" python3 -c "
import json; s = json.loads(open('$tmp/keys.jsonl').read())
assert (s['technique'], s['split'], s['overlay']) == ('logpolar', True, False), s
g = s['gaze']; assert g['source'].startswith('mouse') and abs(g['x_px'] - 80) <= 3 and abs(g['y_px'] - 45) <= 3, g"
else
  echo "FAIL: xdotool is missing (scripts/setup.sh installs it)"; fail=1
fi

# The gaze holds its last place on the image while the mouse is over the
# panel or out of the window, and while frozen (F); the state says which.
xvfb "$FOVEATE" view --scene cheap --size 320x180 --technique layered --commands "
    mouse 100 50; frames 3; print-state
    mouse 500 100; frames 3; print-state    # over the panel
    mouse off; frames 3; print-state        # out of the window
    mouse 200 120; frames 3; print-state
    freeze on; mouse 40 30; frames 3; print-state
    freeze off; frames 3; print-state
    quit" > "$tmp/hold.jsonl" 2> "$tmp/hold.err" || { echo "FAIL: gaze hold run: $(cat "$tmp/hold.err")"; fail=1; }
check "the gaze follows the mouse over the image and holds elsewhere or when frozen" python3 - "$tmp/hold.jsonl" <<'PY'
import json, sys
s = [json.loads(l) for l in open(sys.argv[1]).read().splitlines()]
assert len(s) == 6, len(s)
want = [("following", 100, 50), ("held", 100, 50), ("held", 100, 50), ("following", 200, 120),
        ("frozen", 200, 120), ("following", 40, 30)]
for i, (st, (hold, x, y)) in enumerate(zip(s, want)):
    g = st["gaze"]
    assert g["hold"] == hold, (i, g)
    assert abs(g["x_px"] - x) <= 3 and abs(g["y_px"] - y) <= 3, (i, g)
    assert not g["fallback"], (i, g)  # never the filter's fallback (the centre, a wider fovea)
PY

# The window fits the screen (Xvfb's 1280x800): at 1600x900 the image is shown
# scaled beside the panel, and the mouse maps back to the image's pixels.
xvfb "$FOVEATE" view --scene cheap --size 1600x900 --technique layered --commands "
    frames 1; mouse 300 200; frames 3; print-state; quit" > "$tmp/fit.jsonl" 2> "$tmp/fit.err" \
  || { echo "FAIL: fit run: $(cat "$tmp/fit.err")"; fail=1; }
check "the window fits the screen, the image scaled, the gaze where the mouse is" python3 - "$tmp/fit.jsonl" <<'PY'
import json, sys
s = json.loads(open(sys.argv[1]).read().splitlines()[0])
w, scr, k = s["window"], s["screen"], s["display_scale"]
assert (scr["width"], scr["height"]) == (1280, 800), scr
assert w["width"] <= 1280 and w["height"] <= 800, w
assert 0 < k < 1 and round(1600 * k) + 380 <= 1280, k
g = s["gaze"]
assert abs(g["x_px"] - 300 / k) <= 4 and abs(g["y_px"] - 200 / k) <= 4, (g, k)
# The panel fits the window, or scrolls: never cut off.
p = s["panel"]
assert p["content_height"] <= w["height"] or p["scrolls"], (p, w)
PY
check "at 320x180 the window is as tall as the panel needs, within the screen" python3 - "$tmp/hold.jsonl" <<'PY'
import json, sys
s = json.loads(open(sys.argv[1]).read().splitlines()[0])
w, p = s["window"], s["panel"]
assert w["height"] <= 800 and (p["content_height"] <= w["height"] + 1 or (w["height"] >= 760 and p["scrolls"])), (w, p)
PY

# Frame-time graphs, the parameters saved to a file that --params-file reads,
# and the command line the panel copies, which starts the same viewer.
xvfb "$FOVEATE" view --scene cheap --size 320x180 --technique layered --slope 0.02 --commands "
    param layers=3; param logpolar.sigma=1.5; measure; frames 12
    save-params $tmp/params.json; print-state; quit" > "$tmp/save.jsonl" 2> "$tmp/save.err" \
  || { echo "FAIL: save run: $(cat "$tmp/save.err")"; fail=1; }
check "the parameters file holds what was set; the graphs have frames" python3 - "$tmp/save.jsonl" "$tmp/params.json" <<'PY'
import json, sys
s = json.loads(open(sys.argv[1]).read().splitlines()[0])
f = json.load(open(sys.argv[2]))
assert f["schema"] == "foveate-params/1", f
assert f["techniques"]["layered"]["layers"] == 3 and f["techniques"]["logpolar"]["sigma"] == 1.5, f
h = s["history_frames"]
assert h.get("layered", 0) >= 2 and h.get("native", 0) >= 1, h
c = s["command_line"]
for part in ["--scene cheap", "--size 320x180", "--slope 0.02", "--technique layered",
             "--param layered.layers=3", "--param logpolar.sigma=1.5"]:
    assert part in c, (part, c)
PY
xvfb "$FOVEATE" view --scene cheap --size 320x180 --technique checkerboard --params-file "$tmp/params.json" \
  --commands "frames 1; technique layered; frames 1; print-state; quit" > "$tmp/load.jsonl" 2> "$tmp/load.err"
check "--params-file reads the saved file" python3 -c "
import json; s = json.loads(open('$tmp/load.jsonl').read().splitlines()[0])
assert s['overrides_by_technique']['layered'] == {'layers': 3} and s['overrides_by_technique']['logpolar'] == {'sigma': 1.5}, s"
cmd=$(python3 -c "import json; print(json.loads(open('$tmp/save.jsonl').read().splitlines()[0])['command_line'])")
eval "xvfb \"\$FOVEATE\" ${cmd#foveate } --commands 'frames 1; print-state; quit'" > "$tmp/again.jsonl" 2> "$tmp/again.err"
check "the copied command line starts the same viewer" python3 - "$tmp/save.jsonl" "$tmp/again.jsonl" <<'PY'
import json, sys
a, b = (json.loads(open(p).read().splitlines()[0]) for p in sys.argv[1:3])
for k in ["technique", "slope", "overrides_by_technique", "display", "command_line"]:
    assert a[k] == b[k], (k, a[k], b[k])
PY

# Refusals: a technique the scene cannot run; a bad command; a bad value.
err=$(xvfb "$FOVEATE" view --scene cheap --size 160x90 --technique lodmask --frames 1 2>&1); rc=$?
if [[ $rc -eq 1 && "$err" == *lodmask*meshes* ]]; then echo "ok: lodmask on a scene without meshes is refused"; else echo "FAIL: lodmask (exit $rc): $err"; fail=1; fi
err=$(xvfb "$FOVEATE" view --scene cheap --size 160x90 --commands "frames 1; zoom 2" 2>&1); rc=$?
if [[ $rc -eq 1 && "$err" == *"--commands: command 2 'zoom 2': unknown command"* ]]; then echo "ok: an unknown command is named"; else echo "FAIL: unknown command (exit $rc): $err"; fail=1; fi
err=$(xvfb "$FOVEATE" view --scene cheap --size 160x90 --commands "frames 1; param layers=9; quit" 2>&1); rc=$?
if [[ $rc -eq 1 && "$err" == *"command 2 'param layers=9'"*"out of range [1, 6]"* ]]; then echo "ok: a value out of range is refused"; else echo "FAIL: param out of range (exit $rc): $err"; fail=1; fi
printf 'frames 1\nslope x\n' > "$tmp/bad.txt"
err=$("$FOVEATE" view --scene cheap --script "$tmp/bad.txt" 2>&1); rc=$?
if [[ $rc -eq 1 && "$err" == *"--script $tmp/bad.txt: command 2 'slope x'"*"not a number"* ]]; then echo "ok: a bad script is refused before a window opens"; else echo "FAIL: bad script (exit $rc): $err"; fail=1; fi
help=$("$FOVEATE" view --help)
if [[ "$help" == *"Space A/B"* && "$help" == *"print-state"* && "$help" == *"split screen"* ]]; then echo "ok: --help lists keys and script commands"; else echo "FAIL: view --help: $help"; fail=1; fi

# --screenshot on exit, and no display at all: a clear error, not a crash.
xvfb "$FOVEATE" view --scene cheap --size 160x90 --technique checkerboard --frames 3 --screenshot "$tmp/last.png" > "$tmp/o.txt" 2>&1
rc=$?
if [[ $rc -eq 0 && -s "$tmp/last.png" ]]; then echo "ok: --screenshot on exit"; else echo "FAIL: view --screenshot (exit $rc): $(cat "$tmp/o.txt")"; fail=1; fi
# --margin: the viewer's techniques are planned for the finer acuity too.
for m in 1 2; do
  xvfb "$FOVEATE" view --scene cheap --size 640x360 --technique checkerboard --margin $m \
    --commands "frames 1; print-state; quit" > "$tmp/margin$m.json" 2>/dev/null
done
check "--margin plans the viewer's technique for a finer acuity" python3 - "$tmp/margin1.json" "$tmp/margin2.json" <<'PY'
import json, sys
a, b = (json.loads(open(p).read().splitlines()[0]) for p in sys.argv[1:3])
assert a["margin"] == 1 and b["margin"] == 2, (a["margin"], b["margin"])
assert b["params"]["r1"] > a["params"]["r1"], (a["params"]["r1"], b["params"]["r1"])
PY
err=$(DISPLAY= WAYLAND_DISPLAY= "$FOVEATE" view --scene cheap --frames 1 2>&1); rc=$?
if [[ $rc -eq 1 && "$err" == *"cannot open a window: "*" (is there a display?"* && "$err" != *"  "* ]]; then echo "ok: no display gives a clear error"; else echo "FAIL: no display (exit $rc): $err"; fail=1; fi
# view refuses what render refuses: lodmask on a scene without meshes.
err=$(xvfb "$FOVEATE" view --scene cheap --size 64x36 --technique lodmask --frames 1 2>&1); rc=$?
if [[ $rc -eq 1 && "$err" == *"technique lodmask needs a scene with mesh"* && "$err" == *"has no meshes"* ]]; then echo "ok: view refuses lodmask on a scene without meshes"; else echo "FAIL: view lodmask without meshes (exit $rc): $err"; fail=1; fi
exit $fail
