#!/usr/bin/env bash
# Command-line behaviour of `foveate compare`: FovVideoVDP's JOD for images and
# sequences, the image diagnostics' known answers, JSON, heat maps and errors.
# The test images are written here by a small python3 script (zlib PNG encoder).
set -u
fail=0
check() { if ! eval "$2"; then echo "FAIL: $1"; fail=1; else echo "ok: $1"; fi; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

python3 - "$tmp" <<'EOF'
import random, struct, sys, zlib
d = sys.argv[1]
def png(name, w, h, px):
    raw = b''.join(b'\x00' + bytes(px[y * w * 3:(y + 1) * w * 3]) for y in range(h))
    def chunk(t, data):
        return struct.pack('>I', len(data)) + t + data + struct.pack('>I', zlib.crc32(t + data) & 0xffffffff)
    ihdr = struct.pack('>IIBBBBB', w, h, 8, 2, 0, 0, 0)
    with open(f'{d}/{name}', 'wb') as f:
        f.write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', ihdr) + chunk(b'IDAT', zlib.compress(raw)) + chunk(b'IEND', b''))
random.seed(7)
w, h = 320, 180
ref = [random.randint(30, 220) for _ in range(w * h * 3)]
png('ref.png', w, h, ref)
png('same.png', w, h, ref)
# +-5 on every channel: MSE 25, PSNR = 10 log10(255^2 / 25) = 34.151 dB.
png('noise5.png', w, h, [v + (5 if random.random() < 0.5 else -5) for v in ref])
png('small.png', 100, 50, ref[:100 * 50 * 3])
# Only the left edge changes: far from a gaze on the right, close to a gaze on the left.
edge = list(ref)
for y in range(h):
    for x in range(0, 16):
        for c in range(3):
            edge[(y * w + x) * 3 + c] = 255 - edge[(y * w + x) * 3 + c]
png('edge.png', w, h, edge)
with open(f'{d}/corrupt.png', 'wb') as f:
    f.write(b'\x89PNG\r\n\x1a\n' + b'garbage' * 10)
# Sequences: 6 frames of 160x90 (a moving pattern), the same with noise, and 5 frames.
import os
for name in ('seq_ref', 'seq_same', 'seq_noise', 'seq_short'):
    os.mkdir(f'{d}/{name}')
sw, sh = 160, 90
for i in range(6):
    frame = [(40 + 150 * (((x + 2 * i) // 8 + y // 8) % 2)) for y in range(sh) for x in range(sw) for c in range(3)]
    png(f'seq_ref/frame-{i:04d}.png', sw, sh, frame)
    png(f'seq_same/frame-{i:04d}.png', sw, sh, frame)
    png(f'seq_noise/frame-{i:04d}.png', sw, sh, [min(255, max(0, v + random.randint(-12, 12))) for v in frame])
    if i < 5:
        png(f'seq_short/frame-{i:04d}.png', sw, sh, frame)
with open(f'{d}/seq_ref/notes.txt', 'w') as f:
    f.write('not a frame')
with open(f'{d}/trace.csv', 'w') as f:
    f.write('time_s,x,y,confidence,valid\n0,0.1,0.5,1,1\n0.05,0.9,0.5,1,1\n')
EOF

F="$FOVEATE"
out=$("$F" compare "$tmp/ref.png" "$tmp/same.png"); rc=$?
check "identical: exit 0" '[[ $rc -eq 0 ]]'
check "identical: says so, PSNR inf, SSIM 1" '[[ "$out" == *"identical images"* && "$out" == *"PSNR inf dB"* && "$out" == *"SSIM 1.0000"* ]]'
check "identical: acuity error 0" '[[ "$out" == *"RMSE 0.000"* ]]'
check "identical: FovVideoVDP 10 JOD" '[[ "$out" == *"FovVideoVDP 10.0000 JOD"* ]]'

json=$("$F" compare "$tmp/ref.png" "$tmp/same.png" --json)
check "identical json: psnr null, identical true, ssim 1, acuity 0, JND 0, flip 0" 'python3 -c "
import json,sys; j=json.loads(sys.argv[1])
assert j[\"psnr_db\"] is None and j[\"identical\"] is True and j[\"ssim\"] == 1.0
assert j[\"acuity_rmse\"] == 0 and j[\"jnd_mean\"] == 0 and j[\"visible_fraction\"] == 0 and j[\"flip_mean\"] == 0
assert j[\"jnd_threshold\"] == 1 and j[\"contrast_model\"][\"peak_cd_m2\"] == 200
assert j[\"jod\"] == 10 and j[\"fvvdp\"][\"image\"] and j[\"fvvdp\"][\"foveated\"] and j[\"fvvdp\"][\"frames\"] == 1
assert j[\"fvvdp\"][\"photometry\"] == {\"peak_cd_m2\": 200, \"contrast_ratio\": 1000, \"ambient_lux\": 250, \"reflectivity\": 0.005, \"black_cd_m2\": j[\"fvvdp\"][\"photometry\"][\"black_cd_m2\"]}
assert abs(j[\"fvvdp\"][\"photometry\"][\"black_cd_m2\"] - (250 / 3.141592653589793 * 0.005 + 0.2)) < 1e-9
assert all(v in (0, None) for v in j[\"eccentricity_profile\"][\"acuity_rmse\"])
assert len(j[\"bands\"]) == 4 and all(b[\"identical\"] and b[\"psnr_db\"] is None for b in j[\"bands\"])
assert j[\"bands\"][3][\"to_deg\"] is None and abs(sum(b[\"pixels_fraction\"] for b in j[\"bands\"]) - 1) < 1e-9
" "$json"'

json=$("$F" compare "$tmp/ref.png" "$tmp/noise5.png" --json --quality B)
check "known noise: PSNR 34.151 dB overall and in every band" 'python3 -c "
import json,sys,math; j=json.loads(sys.argv[1]); p=10*math.log10(255**2/25)
assert abs(j[\"psnr_db\"]-p) < 1e-6 and j[\"identical\"] is False, j[\"psnr_db\"]
assert all(abs(b[\"psnr_db\"]-p) < 1e-6 for b in j[\"bands\"])
assert 0.9 < j[\"ssim\"] < 1 and j[\"acuity_rmse\"] > 0 and 0 < j[\"flip_mean\"] < 1
assert j[\"jnd_mean\"] > 0 and 0 <= j[\"visible_fraction\"] <= 1
assert j[\"acuity\"][\"slope\"] == 0.022 and j[\"display\"][\"width_px\"] == 320
assert 5 < j[\"jod\"] < 9.99 and all(b[\"jod\"] < 10 for b in j[\"fvvdp\"][\"bands\"])
" "$json"'

right=$("$F" compare "$tmp/ref.png" "$tmp/edge.png" --gaze 300,90 --json --no-flip)
# A gaze on the images' edge is a position on them, as render and bench take it.
edge=$("$F" compare "$tmp/ref.png" "$tmp/edge.png" --gaze 1.0,0.5 --json --no-flip 2>&1); rc=$?
check "a gaze on the right edge (normalized 1.0) is taken" '[[ $rc -eq 0 && "$edge" == *"jod"* ]]'
err=$("$F" compare "$tmp/ref.png" "$tmp/edge.png" --gaze 100000,5 2>&1); rc=$?
check "a gaze beyond it is refused, naming the range" '[[ $rc -eq 1 && "$err" == *"outside the"*"normalized 0.0..1.0"* ]]'
left=$("$F" compare "$tmp/ref.png" "$tmp/edge.png" --gaze 0.05,0.5 --json --no-flip)
check "gaze moves the change between bands; FLIP skipped" 'python3 -c "
import json,sys; r=json.loads(sys.argv[1]); l=json.loads(sys.argv[2])
assert r[\"bands\"][0][\"identical\"] and not l[\"bands\"][0][\"identical\"]
assert r[\"flip_mean\"] is None and r[\"psnr_db\"] == l[\"psnr_db\"]
assert r[\"acuity_rmse\"] < l[\"acuity_rmse\"]
" "$right" "$left"'

"$F" compare "$tmp/ref.png" "$tmp/noise5.png" --heatmap "$tmp/h.png" --error-heatmap "$tmp/e.png" --acuity-heatmap "$tmp/a.png" --jnd-heatmap "$tmp/j.png" >/dev/null
check "heatmaps written as PNG of the image size" 'python3 -c "
import struct,sys
for p in sys.argv[1:]:
    b=open(p,\"rb\").read(24); assert b[:8]==b\"\\x89PNG\\r\\n\\x1a\\n\"; assert struct.unpack(\">II\", b[16:24])==(320,180)
" "$tmp/h.png" "$tmp/e.png" "$tmp/a.png" "$tmp/j.png"'
check "no temporary files left" '[[ -z $(ls "$tmp" | grep -v -E "\.png$|^seq_|^trace\.csv$") ]]'

err=$("$F" compare "$tmp/ref.png" "$tmp/small.png" 2>&1); rc=$?
check "different sizes: non-zero exit, both sizes named" '[[ $rc -ne 0 && "$err" == *"320x180"* && "$err" == *"100x50"* ]]'
err=$("$F" compare "$tmp/ref.png" "$tmp/missing.png" 2>&1); rc=$?
check "missing file: non-zero exit, file named" '[[ $rc -ne 0 && "$err" == *missing.png* ]]'
err=$("$F" compare "$tmp/corrupt.png" "$tmp/ref.png" 2>&1); rc=$?
check "corrupt file: non-zero exit, file named" '[[ $rc -ne 0 && "$err" == *corrupt.png* ]]'
lo=$("$F" compare "$tmp/ref.png" "$tmp/noise5.png" --json --no-flip --threshold 0.5)
hi=$("$F" compare "$tmp/ref.png" "$tmp/noise5.png" --json --no-flip --threshold 50)
dim=$("$F" compare "$tmp/ref.png" "$tmp/noise5.png" --json --no-flip --peak-luminance 5)
check "--threshold sets the JND counted as visible; --peak-luminance the display's white for both measures" 'python3 -c "
import json,sys; lo,hi,dim=(json.loads(a) for a in sys.argv[1:])
assert lo[\"jnd_threshold\"] == 0.5 and hi[\"jnd_threshold\"] == 50
assert lo[\"visible_fraction\"] > hi[\"visible_fraction\"] and lo[\"jnd_mean\"] == hi[\"jnd_mean\"]
assert dim[\"contrast_model\"][\"peak_cd_m2\"] == 5 and dim[\"jnd_mean\"] < lo[\"jnd_mean\"]
assert dim[\"fvvdp\"][\"photometry\"][\"peak_cd_m2\"] == 5 and dim[\"jod\"] > lo[\"jod\"]
" "$lo" "$hi" "$dim"'

# Sequences: two folders of frames, sorted by name; other files are ignored.
json=$("$F" compare "$tmp/seq_ref" "$tmp/seq_same" --json)
check "identical sequences: 10 JOD, 6 frames, a video at 60 fps" 'python3 -c "
import json,sys; j=json.loads(sys.argv[1]); f=j[\"fvvdp\"]
assert j[\"jod\"] == 10 and f[\"frames\"] == 6 and not f[\"image\"] and f[\"fps\"] == 60 and len(f[\"frame_jod\"]) == 6
assert \"psnr_db\" not in j
" "$json"'
a=$("$F" compare "$tmp/seq_ref" "$tmp/seq_noise" --json)
b=$("$F" compare "$tmp/seq_ref" "$tmp/seq_noise" --json --fps 30)
c=$("$F" compare "$tmp/seq_ref" "$tmp/seq_noise" --json --no-foveation)
d=$("$F" compare "$tmp/seq_ref" "$tmp/seq_noise" --json --gaze "trace:$tmp/trace.csv")
check "noisy sequence: below 10; --fps, --no-foveation and a gaze trace change the answer" 'python3 -c "
import json,sys; a,b,c,d=(json.loads(x) for x in sys.argv[1:])
assert 5 < a[\"jod\"] < 9.99 and b[\"fvvdp\"][\"fps\"] == 30 and b[\"jod\"] != a[\"jod\"]
assert not c[\"fvvdp\"][\"foveated\"] and c[\"jod\"] < a[\"jod\"]
assert d[\"jod\"] != a[\"jod\"] and \"trace\" in d[\"gaze\"]
" "$a" "$b" "$c" "$d"'
"$F" compare "$tmp/seq_ref" "$tmp/seq_noise" --heatmap "$tmp/seqh.png" >/dev/null
check "sequence heat map: a PNG of the frames' size" 'python3 -c "
import struct,sys
b=open(sys.argv[1],\"rb\").read(24); assert struct.unpack(\">II\", b[16:24])==(160,90)
" "$tmp/seqh.png"'
err=$("$F" compare "$tmp/seq_ref" "$tmp/seq_short" 2>&1); rc=$?
check "folders of different lengths: exit 1, both counts named" '[[ $rc -eq 1 && "$err" == *"seq_ref 6"* && "$err" == *"seq_short 5"* ]]'
# A folder `render --reference` wrote holds frame-NNNN and reference-NNNN:
# its frames are judged, never the two interleaved; another mix is refused.
mkdir -p "$tmp/seq_mixed" "$tmp/seq_two"
for f in "$tmp"/seq_noise/frame-*.png; do cp "$f" "$tmp/seq_mixed/"; cp "$tmp/seq_ref/$(basename "$f")" "$tmp/seq_mixed/reference-${f##*-}"; done
mixed=$("$F" compare "$tmp/seq_ref" "$tmp/seq_mixed" --json 2>"$tmp/mixed.err")
check "a folder with frames and references: its 6 frames judged, as the frames alone, and a note" 'python3 -c "
import json,sys; m,a=(json.loads(x) for x in sys.argv[1:3])
assert m[\"fvvdp\"][\"frames\"] == 6 and m[\"jod\"] == a[\"jod\"]
" "$mixed" "$a" && grep -q "leaving out reference-\* (6)" "$tmp/mixed.err"'
cp "$tmp"/seq_ref/frame-0000.png "$tmp/seq_two/a-0.png"; cp "$tmp"/seq_ref/frame-0001.png "$tmp/seq_two/b-0.png"
err=$("$F" compare "$tmp/seq_two" "$tmp/seq_two" 2>&1); rc=$?
check "a folder of two other sequences: exit 1, both named" '[[ $rc -eq 1 && "$err" == *"2 sequences"*"a-* (1), b-* (1)"* ]]'
err=$("$F" compare "$tmp/seq_ref" "$tmp/seq_noise" --jnd-heatmap "$tmp/seq_j.png" --no-flip 2>&1); rc=$?
check "an image pair's diagnostics asked of sequences: exit 1, the flags named, no file" '[[ $rc -eq 1 && "$err" == *"--jnd-heatmap, --no-flip: for an image pair"* && ! -e "$tmp/seq_j.png" ]]'
err=$("$F" compare "$tmp/seq_ref" "$tmp/ref.png" 2>&1); rc=$?
check "a folder against a file: exit 1, says which is which" '[[ $rc -eq 1 && "$err" == *"seq_ref is a folder"* ]]'
err=$("$F" compare "$tmp/ref.png" "$tmp/noise5.png" --peak-luminance 0.1 2>&1); rc=$?
check "white below the black level: exit 1, names --peak-luminance and the black level" '[[ $rc -eq 1 && "$err" == *"--peak-luminance"*"black level"* ]]'
err=$("$F" compare "$tmp/ref.png" "$tmp/noise5.png" --reflectivity 2 2>&1); rc=$?
check "reflectivity out of range: exit 1, flag named" '[[ $rc -eq 1 && "$err" == *"--reflectivity"* ]]'
for args in "--gaze 12" "--quality Z" "--quality A --slope 0.02" "--slope -1" "--display nope" "--threshold -1" "--heatmap-max 0" "--jnd-heatmap-max 0" "--peak-luminance 0.1" "--fps 0" "--contrast-ratio 1" "--ambient-lux -1" "--gaze trace:$tmp/none.csv"; do
  err=$("$F" compare "$tmp/ref.png" "$tmp/same.png" $args 2>&1); rc=$?
  check "bad value '$args' fails with a message" '[[ $rc -ne 0 && -n "$err" ]]'
done
err=$("$F" compare "$tmp/ref.png" 2>&1); rc=$?
check "missing argument fails" '[[ $rc -ne 0 ]]'
"$F" compare --help | grep -q -- --jnd-heatmap && "$F" compare --help | grep -q -- --no-foveation
check "help lists options" '[[ $? -eq 0 ]]'
exit $fail
