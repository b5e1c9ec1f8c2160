#!/usr/bin/env bash
# Command-line behaviour of `foveate rates`: the shading-rate image's bytes for
# hand-worked tiles (see tests/core/shading_rate_test.cpp for the numbers), the
# three encodings, JSON, preview, options and errors.
set -u
fail=0
check() { if ! eval "$2"; then echo "FAIL: $1"; fail=1; else echo "ok: $1"; fi; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# byte FILE INDEX: the unsigned value of one byte.
byte() { od -An -tu1 -j "$2" -N1 "$1" | tr -d ' '; }

# The hand-worked tiles are for the model itself (--margin 1).
out=$("$FOVEATE" rates --display desktop-1080p --gaze 960,540 --tile 16 --api vulkan --margin 1 --out "$tmp/v.bin")
check "vulkan: 120x68 tiles, one byte each" '[[ $(stat -c %s "$tmp/v.bin") -eq 8160 ]]'
# Tile (60,33) holds the gaze: 1x1 = 0. Tile (70,33), e = 4.1 deg: 2x2 = 5.
# Tile (110,33), 20 degrees right of the gaze: 4x4 = (2 << 2 | 2) = 10.
check "vulkan: tile at the gaze is 1x1 (0)" '[[ $(byte "$tmp/v.bin" $((33*120+60))) -eq 0 ]]'
check "vulkan: tile at 4 deg is 2x2 (5)" '[[ $(byte "$tmp/v.bin" $((33*120+70))) -eq 5 ]]'
check "vulkan: tile at 20 deg is 4x4 (10)" '[[ $(byte "$tmp/v.bin" $((33*120+110))) -eq 10 ]]'
check "prints the fraction per rate and the pixel ratio" '[[ "$out" == *"4x4"*"%"* && "$out" == *"shaded samples / native pixels = 0.1"* ]]'

"$FOVEATE" rates --api d3d12 --margin 1 --out "$tmp/d.bin" >/dev/null
check "d3d12 bytes equal vulkan's (same encoding)" 'cmp -s "$tmp/v.bin" "$tmp/d.bin"'

# gl-nv: rows bottom-to-top, the grid anchored at the bottom-left; the gaze row
# y = 540 is GL row 539 / 16 = 33. Palette indices: 1x1 0, 2x2 3, 4x4 6.
"$FOVEATE" rates --api gl-nv --margin 1 --out "$tmp/g.bin" >/dev/null
check "gl-nv: palette indices" '[[ $(byte "$tmp/g.bin" $((33*120+60))) -eq 0 && $(byte "$tmp/g.bin" $((33*120+70))) -eq 3 && $(byte "$tmp/g.bin" $((33*120+110))) -eq 6 ]]'
check "gl-nv: top tile row is the last" '[[ $(byte "$tmp/g.bin" $((67*120))) -eq 6 && $(stat -c %s "$tmp/g.bin") -eq 8160 ]]'

"$FOVEATE" rates --api gl-nv --gaze 100,30 --size 320x160 --margin 1 --out "$tmp/g.json" --preview "$tmp/p.png" >/dev/null
check "json: size, tile, api, grid, legend" 'python3 - "$tmp/g.json" <<PY
import json, sys
j = json.load(open(sys.argv[1]))
assert j["size"] == [320, 160] and j["tile"] == 16 and j["api"] == "gl-nv", j["size"]
assert j["row_order"] == "bottom-to-top"
assert len(j["grid"]) == 10 and all(len(r) == 20 for r in j["grid"])
leg = {e["rate"]: e for e in j["legend"]}
assert [leg[r]["value"] for r in ["1x1","1x2","2x1","2x2","2x4","4x2","4x4"]] == [0,1,2,3,4,5,6]
assert leg["4x4"]["gl_enum"] == 0x956B and leg["1x1"]["gl_enum"] == 0x9565
assert abs(sum(e["fraction"] for e in j["legend"]) - 1) < 1e-9
# The gaze (100, 30) is in GL row (159 - 30) // 16 = 8, column 6: 1x1.
assert j["grid"][8][6] == 0
assert 0 < j["pixel_ratio"] < 1
PY'
check "preview is a 320x160 PNG" 'python3 -c "import struct,sys; d=open(sys.argv[1],\"rb\").read(24); assert d[:8]==b\"\x89PNG\r\n\x1a\n\"; assert struct.unpack(\">II\", d[16:24])==(320,160)" "$tmp/p.png"'

"$FOVEATE" rates --size 320x180 --tile 8 --out "$tmp/s.bin" >/dev/null
check "size and tile: 40x23 tiles" '[[ $(stat -c %s "$tmp/s.bin") -eq 920 ]]'
"$FOVEATE" rates --rates 1x1,2x2 --out "$tmp/r.bin" >/dev/null
check "only supported rates (0 and 5)" '[[ -z $(od -An -tu1 -v "$tmp/r.bin" | tr -s " " "\n" | grep -v -x -e "" -e 0 -e 5) ]]'
ratio() { "$FOVEATE" rates --out "$tmp/x.bin" "$@" | sed -n "s/.*native pixels = \([0-9.]*\).*/\1/p"; }
a=$(ratio); b=$(ratio --latency-ms 30); q=$(ratio --quality B)
check "latency margin shades more ($a < $b)" 'python3 -c "import sys; assert float(sys.argv[1]) < float(sys.argv[2])" $a $b'
check "quality B shades more than A ($a < $q)" 'python3 -c "import sys; assert float(sys.argv[1]) < float(sys.argv[2])" $a $q'
p=$(ratio --acuity B)
check "--acuity B is --quality B ($p = $q)" '[[ -n "$p" && "$p" == "$q" ]]'
err=$("$FOVEATE" rates --out "$tmp/x.bin" --acuity B --slope 0.02 2>&1); rc=$?
check "--acuity and --slope together: exit 1, both named" '[[ $rc -ne 0 && "$err" == *"--acuity and --slope"* ]]'
# Unless --margin says otherwise, kStaticRatesMargin (1.5: where the model's
# rates alone hold parity), finer than the model itself; not the vrs
# technique's own margin (1), which content-adaptive refinement makes up for.
one=$(ratio --margin 1); own=$(ratio --margin 1.5)
check "default margin is 1.5 ($a = $own > $one)" 'python3 -c "import sys; assert sys.argv[1] == sys.argv[2] and float(sys.argv[1]) > float(sys.argv[3])" $a $own $one'
"$FOVEATE" rates --out "$tmp/m.json" >/dev/null
check "json records the margin and the judged acuity" 'python3 -c "import json,sys; j=json.load(open(sys.argv[1])); assert j[\"margin\"] == 1.5 and j[\"acuity\"][\"slope\"] == 0.0275" "$tmp/m.json"'

bad() {  # bad EXPECTED-RC TEXT ARGS...: fails with that code, names TEXT, writes nothing
  local want=$1 text=$2; shift 2
  rm -f "$tmp/bad.bin"
  err=$("$FOVEATE" rates "$@" 2>&1); rc=$?
  check "bad '$*' exits $want naming $text" '[[ $rc -eq $want && "$err" == *"$text"* && ! -e "$tmp/bad.bin" ]]'
}
bad 1 "--tile: expected 8, 16 or 32 pixels, got 12" --tile 12 --out "$tmp/bad.bin"
bad 1 "--api" --api metal --out "$tmp/bad.bin"
bad 1 "--out" --out "$tmp/bad.txt"
bad 1 "1x1" --rates 2x2,4x4 --out "$tmp/bad.bin"
bad 1 "--rates" --rates 1x1,3x3 --out "$tmp/bad.bin"
bad 1 "--latency-ms" --latency-ms -5 --out "$tmp/bad.bin"
bad 1 "--gaze" --gaze abc --out "$tmp/bad.bin"
bad 1 "outside the 640x360 image" --size 640x360 --gaze 5000,200 --out "$tmp/bad.bin"
bad 1 "--preview" --preview "$tmp/p.jpg" --out "$tmp/bad.bin"
bad 1 "--size" --size 0x10 --out "$tmp/bad.bin"
bad 1 "nope" --display nope --out "$tmp/bad.bin"
bad 1 "slope" --slope -1 --out "$tmp/bad.bin"
bad 1 "--margin" --margin 0.5 --out "$tmp/bad.bin"
err=$("$FOVEATE" rates 2>&1); rc=$?
check "missing --out is a usage error" '[[ $rc -ne 0 && $rc -ne 1 && $rc -ne 3 && "$err" == *"--out"* ]]'
err=$("$FOVEATE" rates --tile abc --out "$tmp/bad.bin" 2>&1); rc=$?
check "non-numeric --tile is a usage error" '[[ $rc -ne 0 && $rc -ne 3 && "$err" == *"--tile"* ]]'
err=$("$FOVEATE" rates --out "$tmp/half.bin" --preview "$tmp/no/such/p.png" 2>&1); rc=$?
check "a preview that cannot be written: exit 1, naming it, and no rates file" \
  '[[ $rc -eq 1 && "$err" == *"no/such/p.png"* && ! -e "$tmp/half.bin" ]]'
mkdir -p "$tmp/folder.bin"
err=$("$FOVEATE" rates --out "$tmp/folder.bin" 2>&1); rc=$?
check "--out a folder: exit 1, saying so" '[[ $rc -eq 1 && "$err" == *"is a directory; give a file name"* ]]'
"$FOVEATE" rates --help | grep -q -- "--latency-ms"
check "help lists options" '[[ $? -eq 0 ]]'
exit $fail
