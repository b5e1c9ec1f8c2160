#!/usr/bin/env bash
# Command-line behaviour with a lens display (lens.hpp): `foveate rates` and
# `foveate plan` through the lens against the same display without it, the
# lens presets, and errors in a display file's "lens".
set -u
fail=0
check() { if ! eval "$2"; then echo "FAIL: $1"; fail=1; else echo "ok: $1"; fi; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
byte() { od -An -tu1 -j "$2" -N1 "$1" | tr -d ' '; }

# A buffer 1:1 with its panel at the lens centre: 700 px over 90 deg is
# f = 350 px per tangent, the panel 350 px per tangent; the DK1's K.
body='"width_px": 700, "height_px": 700, "fov_h_deg": 90'
lens='"lens": {"panel_px": [600, 600], "center_px": [300, 300], "px_per_tan": 350, "radius_unit_px": 300, "k": [0.22, 0.24]}'
echo "{\"name\": \"lab\", $body, $lens}" > "$tmp/lens.json"
echo "{\"name\": \"lab\", $body}" > "$tmp/bare.json"

# Gaze at x = 0.98 * 700 = 686, 336 px right of the axis: tan 0.96 (43.8 deg).
# There the panel point is r = 259 px out (rho = 0.863, solving
# tan = r / 350 (1 + 0.22 rho^2 + 0.24 rho^4)) and the buffer has
# f dtan/dr = 1 + 0.66 rho^2 + 1.2 rho^4 = 2.16 pixels per panel pixel along
# x, f tan / r = 1.30 along y: the MAR alone needs 1x1 at the gaze, the panel allows 2x1
# (Vulkan value 1 << 2 = 4). Tile (686 / 16, 350 / 16) = (42, 21), 44 a row.
out=$("$FOVEATE" rates --display "$tmp/lens.json" --gaze 0.98,0.5 --out "$tmp/l.bin")
"$FOVEATE" rates --display "$tmp/bare.json" --gaze 0.98,0.5 --out "$tmp/b.bin" >/dev/null
check "without the lens the gaze tile is 1x1" '[[ $(byte "$tmp/b.bin" $((21*44+42))) -eq 0 ]]'
check "through the lens the gaze tile is 2x1" '[[ $(byte "$tmp/l.bin" $((21*44+42))) -eq 4 ]]'
check "rates prints the panel at the gaze and the tiles it relaxed" '[[ "$out" == *"through the lens: at the gaze (43."*"the buffer has 2.16 and 1.30"*"tiles coarser than without the lens"* ]]'
"$FOVEATE" rates --display "$tmp/lens.json" --gaze 0.98,0.5 --out "$tmp/l.json" >/dev/null
check "rates json: the lens section" 'python3 - "$tmp/l.json" <<PY
import json, sys
j = json.load(open(sys.argv[1]))
l = j["lens"]
assert l["tiles_coarser_than_without_lens"] > 0, l
assert j["pixel_ratio"] < l["pixel_ratio_without_lens"], l
assert 2.0 < l["oversampling_at_gaze"]["radial"] < 2.2, l
assert j["display"]["lens"]["k"] == [0.22, 0.24, 0.0], j["display"]
PY'
# On the axis the buffer is 1:1 with the panel: nothing changes near the gaze.
out=$("$FOVEATE" rates --display "$tmp/lens.json" --gaze 0.5,0.5 --out "$tmp/c.bin")
"$FOVEATE" rates --display "$tmp/bare.json" --gaze 0.5,0.5 --out "$tmp/cb.bin" >/dev/null
check "on the axis: 1.00 buffer pixels per panel pixel" '[[ "$out" == *"(0.0 deg from the lens axis)"*"has 1.00 and 1.00 pixels per panel pixel"* ]]'
check "on the axis: the gaze tile and its row out to 10 tiles are as without the lens" 'for i in $(seq 21 31); do [[ $(byte "$tmp/c.bin" $((21*44+i))) -eq $(byte "$tmp/cb.bin" $((21*44+i))) ]] || exit 1; done'

# plan: the fovea's layer through the lens at the off-axis gaze is coarser
# than native; without --gaze the plan holds for any gaze (the axis: 1:1).
out=$("$FOVEATE" plan --display "$tmp/lens.json" --size 700x700 --gaze 0.98,0.5 --margin 1)
check "plan prints the lens and the plan without it" '[[ "$out" == *"planned for this gaze"*"without the lens: s = 1.000"* ]]'
"$FOVEATE" plan --display "$tmp/lens.json" --size 700x700 --gaze 0.98,0.5 --margin 1 --json > "$tmp/p.json"
check "plan json: layer 1 coarser than without the lens, fewer pixels" 'python3 - "$tmp/p.json" <<PY
import json, sys
j = json.load(open(sys.argv[1]))
l = j["lens"]
assert l["planned_for"] == "this gaze"
assert l["without_lens"]["sampling_factors"][0] == 1.0
assert j["layers"][0]["sampling_factor"] > 1.05, j["layers"][0]
assert j["total_pixels"] < l["without_lens"]["total_pixels"]
PY'
out=$("$FOVEATE" plan --display "$tmp/lens.json" --size 700x700)
check "plan without --gaze: any gaze, the same as without the lens" '[[ "$out" == *"planned for any gaze"*"(the lens saves 0.0 % of the layer pixels)"* ]]'

# Presets: the DK1's published lens and the Quest 2 example lens.
q=$("$FOVEATE" rates --display hmd-quest2-lens --gaze 0.95,0.5 --margin 1 --out "$tmp/q.bin")
check "hmd-quest2-lens relaxes tiles far off the axis" '[[ "$q" == *"through the lens"*"tiles coarser than without the lens (0.0755 without it)"* && "$q" == *"native pixels = 0.0737"* ]]'
p=$("$FOVEATE" rates --display hmd-quest2 --gaze 0.95,0.5 --margin 1 --out "$tmp/q0.bin")
check "hmd-quest2 (no lens) is unchanged" '[[ "$p" == *"native pixels = 0.0755"* && "$p" != *"through the lens"* ]]'
"$FOVEATE" plan --display hmd-rift-dk1 --size 1097x1372 --json > "$tmp/dk1.json"
check "hmd-rift-dk1: the SDK's buffer and lens in the plan's display" 'python3 - "$tmp/dk1.json" <<PY
import json, sys
d = json.load(open(sys.argv[1]))["display"]
assert (d["width_px"], d["height_px"]) == (1097, 1372), d
assert d["lens"]["k"] == [0.22, 0.24, 0.0] and d["lens"]["panel_px"] == [640, 800], d["lens"]
PY'

bad() {  # bad TEXT LENS-JSON: rates with that lens exits 1 naming TEXT, writes nothing
  local text=$1
  echo "{\"name\": \"lab\", $body, \"lens\": $2}" > "$tmp/badlens.json"
  rm -f "$tmp/bad.bin"
  err=$("$FOVEATE" rates --display "$tmp/badlens.json" --out "$tmp/bad.bin" 2>&1); rc=$?
  check "bad lens exits 1 naming '$text'" '[[ $rc -eq 1 && "$err" == *"$text"* && ! -e "$tmp/bad.bin" ]]'
}
bad "lens.k: the view angle stops growing" '{"panel_px": [600, 600], "center_px": [300, 300], "px_per_tan": 350, "k": [-1]}'
bad "lens.k: expected an array of 1 to 3 numbers" '{"panel_px": [600, 600], "center_px": [300, 300], "px_per_tan": 350, "k": []}'
bad "lens.panel_px: required" '{"center_px": [300, 300], "px_per_tan": 350, "k": [0.2]}'
bad "lens.px_per_tan" '{"panel_px": [600, 600], "center_px": [300, 300], "px_per_tan": -3, "k": [0.2]}'
bad "lens.center_px: must lie on the panel" '{"panel_px": [600, 600], "center_px": [900, 300], "px_per_tan": 350, "k": [0.2]}'
exit $fail
