#!/usr/bin/env bash
# Command-line behaviour of `foveate compare`: known answers, JSON, heatmaps and errors.
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
EOF

F="$FOVEATE"
out=$("$F" compare "$tmp/ref.png" "$tmp/same.png"); rc=$?
check "identical: exit 0" '[[ $rc -eq 0 ]]'
check "identical: says so, PSNR inf, SSIM 1" '[[ "$out" == *"identical images"* && "$out" == *"PSNR inf dB"* && "$out" == *"SSIM 1.0000"* ]]'
check "identical: acuity error 0" '[[ "$out" == *"RMSE 0.000"* ]]'

json=$("$F" compare "$tmp/ref.png" "$tmp/same.png" --json)
check "identical json: psnr null, identical true, ssim 1, acuity 0, JND 0, flip 0" 'python3 -c "
import json,sys; j=json.loads(sys.argv[1])
assert j[\"psnr_db\"] is None and j[\"identical\"] is True and j[\"ssim\"] == 1.0
assert j[\"acuity_rmse\"] == 0 and j[\"jnd_mean\"] == 0 and j[\"visible_fraction\"] == 0 and j[\"flip_mean\"] == 0
assert j[\"jnd_threshold\"] == 1 and j[\"contrast_model\"][\"peak_cd_m2\"] == 100
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
" "$json"'

right=$("$F" compare "$tmp/ref.png" "$tmp/edge.png" --gaze 300,90 --json --no-flip)
left=$("$F" compare "$tmp/ref.png" "$tmp/edge.png" --gaze 0.05,0.5 --json --no-flip)
check "gaze moves the change between bands; FLIP skipped" 'python3 -c "
import json,sys; r=json.loads(sys.argv[1]); l=json.loads(sys.argv[2])
assert r[\"bands\"][0][\"identical\"] and not l[\"bands\"][0][\"identical\"]
assert r[\"flip_mean\"] is None and r[\"psnr_db\"] == l[\"psnr_db\"]
assert r[\"acuity_rmse\"] < l[\"acuity_rmse\"]
" "$right" "$left"'

"$F" compare "$tmp/ref.png" "$tmp/noise5.png" --heatmap "$tmp/h.png" --acuity-heatmap "$tmp/a.png" --jnd-heatmap "$tmp/j.png" >/dev/null
check "heatmaps written as PNG of the image size" 'python3 -c "
import struct,sys
for p in sys.argv[1:]:
    b=open(p,\"rb\").read(24); assert b[:8]==b\"\\x89PNG\\r\\n\\x1a\\n\"; assert struct.unpack(\">II\", b[16:24])==(320,180)
" "$tmp/h.png" "$tmp/a.png" "$tmp/j.png"'
check "no temporary files left" '[[ -z $(ls "$tmp" | grep -v "\.png$") ]]'

err=$("$F" compare "$tmp/ref.png" "$tmp/small.png" 2>&1); rc=$?
check "different sizes: non-zero exit, both sizes named" '[[ $rc -ne 0 && "$err" == *"320x180"* && "$err" == *"100x50"* ]]'
err=$("$F" compare "$tmp/ref.png" "$tmp/missing.png" 2>&1); rc=$?
check "missing file: non-zero exit, file named" '[[ $rc -ne 0 && "$err" == *missing.png* ]]'
err=$("$F" compare "$tmp/corrupt.png" "$tmp/ref.png" 2>&1); rc=$?
check "corrupt file: non-zero exit, file named" '[[ $rc -ne 0 && "$err" == *corrupt.png* ]]'
lo=$("$F" compare "$tmp/ref.png" "$tmp/noise5.png" --json --no-flip --threshold 0.5)
hi=$("$F" compare "$tmp/ref.png" "$tmp/noise5.png" --json --no-flip --threshold 50)
dim=$("$F" compare "$tmp/ref.png" "$tmp/noise5.png" --json --no-flip --peak-luminance 5)
check "--threshold sets the JND counted as visible; --peak-luminance the CSF's adaptation" 'python3 -c "
import json,sys; lo,hi,dim=(json.loads(a) for a in sys.argv[1:])
assert lo[\"jnd_threshold\"] == 0.5 and hi[\"jnd_threshold\"] == 50
assert lo[\"visible_fraction\"] > hi[\"visible_fraction\"] and lo[\"jnd_mean\"] == hi[\"jnd_mean\"]
assert dim[\"contrast_model\"][\"peak_cd_m2\"] == 5 and dim[\"jnd_mean\"] < lo[\"jnd_mean\"]
" "$lo" "$hi" "$dim"'
for args in "--gaze 12" "--quality Z" "--quality A --slope 0.02" "--slope -1" "--display nope" "--threshold -1" "--heatmap-max 0" "--jnd-heatmap-max 0" "--peak-luminance 0.1"; do
  err=$("$F" compare "$tmp/ref.png" "$tmp/same.png" $args 2>&1); rc=$?
  check "bad value '$args' fails with a message" '[[ $rc -ne 0 && -n "$err" ]]'
done
err=$("$F" compare "$tmp/ref.png" 2>&1); rc=$?
check "missing argument fails" '[[ $rc -ne 0 ]]'
"$F" compare --help | grep -q -- --jnd-heatmap
check "help lists options" '[[ $? -eq 0 ]]'
exit $fail
