#!/usr/bin/env bash
# Shadertoy content as users bring it: legacy names, errors against the
# user's file and line, unbound channels, iDate, hostile files (regex
# killers, BOM, FIFOs, huge images, huge files) and multipass projects.
# Images are checked pixel by pixel (tests/cli/pngpixel.py).
set -u
fail=0
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
data="$FOVEATE_SOURCE_DIR/tests/data/shadertoy"
px() { python3 "$FOVEATE_SOURCE_DIR/tests/cli/pngpixel.py" "$@"; }
ok() { echo "ok: $1"; }
bad() { echo "FAIL: $1"; fail=1; }
# near NAME "R G B A" "R G B A": every component within 2 codes.
near() {
  if python3 -c "
import sys
a=[int(v) for v in sys.argv[1].split()]; b=[int(v) for v in sys.argv[2].split()]
sys.exit(0 if len(a)==len(b) and all(abs(x-y)<=2 for x,y in zip(a,b)) else 1)" "$2" "$3"; then
    ok "$1"; else bad "$1: got '$2', expected '$3'"; fi
}
expect_error() {  # name, exit code, expected text, args...
  local name=$1 code=$2 text=$3; shift 3
  local err rc
  err=$(timeout 60 "$FOVEATE" "$@" 2>&1); rc=$?
  if [[ $rc -eq $code && "$err" == *"$text"* ]]; then ok "$name"; else bad "$name (exit $rc): $err"; fi
}
render() { timeout 120 "$FOVEATE" render --size 64x36 "$@"; }

# 1. Legacy names, unchanged shaders.
render --scene "$data/legacy_names.glsl" --time 1 --out "$tmp/l" > /dev/null 2> "$tmp/l.err" || bad "legacy names render"
near "texture2D reads iChannel0 (top-left red)" "$(px "$tmp/l/frame-0000.png" 8,4)" "255 0 0 255"
near "texture2D reads iChannel0 (bottom-right white)" "$(px "$tmp/l/frame-0000.png" 24,30)" "255 255 255 255"
near "iGlobalTime, iSampleRate, iChannelTime" "$(px "$tmp/l/frame-0000.png" 48,4)" "127 127 64 255"
near "textureCube on a 2D channel reads it as a panorama" "$(px "$tmp/l/frame-0000.png" 48,30)" "0 255 0 255"
# (the note that 64x36 leaves foveation nothing to save is not a warning)
[[ -z "$(grep -v '^foveate: note: ' "$tmp/l.err")" ]] && ok "no warning when every sampled channel is bound" || bad "unexpected stderr: $(cat "$tmp/l.err")"
render --scene "$data/own_legacy.glsl" --time 1 --channel "$data/quadrants.png" --out "$tmp/o" > /dev/null || bad "own legacy definitions render"
near "a shader's own texture2D macro, textureCube and iGlobalTime uniform" "$(px "$tmp/o/frame-0000.png" 8,4)" "64 127 191 255"

render --scene "$data/own_uniforms.glsl" --time 1 --channel "$data/quadrants.png" --out "$tmp/ou" > /dev/null || bad "a shader declaring Shadertoy's uniforms renders"
near "a shader's own declarations of Shadertoy's uniforms are set" "$(px "$tmp/ou/frame-0000.png" 8,4)" "127 127 127 255"
for t in native "layered --param msaa=1" logpolar checkerboard inset; do
  render --scene "$data/short_macros.glsl" --technique $t --overwrite --out "$tmp/sm" > /dev/null 2>&1 || bad "short macro names with $t"
  near "short macro names do not leak into $t" "$(px "$tmp/sm/frame-0000.png" 32,18)" "255 127 0 255"
done

render --scene "$data/vscode_channel.glsl" --channel "$data/quadrants.png" --out "$tmp/vs" > /dev/null 2> "$tmp/vs.err" || bad "#iChannel directive: $(cat "$tmp/vs.err")"
grep -q "vscode_channel.glsl:4: ignoring the '#iChannel' directive" "$tmp/vs.err" && ok "a '#iChannel' line is ignored with a warning naming file and line" || bad "#iChannel warning: $(cat "$tmp/vs.err")"
near "... and the channel comes from --channel" "$(px "$tmp/vs/frame-0000.png" 8,4)" "255 0 0 255"
near "... and the rest of the shader runs" "$(px "$tmp/vs/frame-0000.png" 48,4)" "0 0 255 255"

# 2. Compile errors against the user's file and line.
expect_error "syntax error: file and line" 1 "syntax_error.glsl:4:" render --scene "$data/syntax_error.glsl" --out "$tmp/x"
expect_error "undeclared name: the user's file and line" 1 "semantic_error.glsl:3:19: error: \`undeclared_thing' undeclared" render --scene "$data/semantic_error.glsl" --out "$tmp/x"
err=$("$FOVEATE" render --size 64x36 --scene "$data/semantic_error.glsl" --out "$tmp/x" 2>&1)
[[ "$err" != *prelude* ]] && ok "the prelude is not blamed" || bad "prelude blamed: $err"
expect_error "mainImage with the wrong signature" 1 "bad_signature.glsl:2: mainImage(out vec3 fragColor, in vec2 fragCoord): expected" render --scene "$data/bad_signature.glsl" --out "$tmp/x"
expect_error "main() instead of mainImage" 1 "no_main_image.glsl:2: defines main()" render --scene "$data/no_main_image.glsl" --out "$tmp/x"

# 3. A sampled channel with nothing bound: one warning naming it and the file.
render --scene "$data/unbound_channel.glsl" --channel "$data/quadrants.png" --reference ssaa:2 --out "$tmp/u" > /dev/null 2> "$tmp/u.err" || bad "unbound channel render"
[[ $(grep -c "warning: .*unbound_channel.glsl: samples iChannel1 but no image or buffer is bound" "$tmp/u.err") -eq 1 ]] \
  && ok "one warning for the unbound iChannel1" || bad "warning: $(cat "$tmp/u.err")"
grep -q "iChannel3\|iChannel0" "$tmp/u.err" && bad "warned for a bound or commented channel" || ok "no warning for a bound channel or one in a comment"
near "the unbound channel reads black" "$(px "$tmp/u/frame-0000.png" 8,4)" "127 0 0 255"
render --scene "$data/unbound_channel.glsl" --channel "$data/quadrants.png" --quiet --out "$tmp/uq" > /dev/null 2> "$tmp/uq.err" || bad "unbound channel render, --quiet"
[[ ! -s "$tmp/uq.err" ]] && ok "--quiet silences the scene's warning" || bad "--quiet printed: $(cat "$tmp/uq.err")"

# 4. iDate: fixed by default in render, set by --date, rolls over midnight.
render --scene "$data/clock.glsl" --out "$tmp/d0" > /dev/null
near "default iDate 2026-01-01" "$(px "$tmp/d0/frame-0000.png" 8,4)" "133 0 6 255"
near "default time of day 00:00" "$(px "$tmp/d0/frame-0000.png" 48,4)" "0 0 0 255"
render --scene "$data/clock.glsl" --date 2025-03-14T12:00 --out "$tmp/d1" > /dev/null
near "--date sets the day" "$(px "$tmp/d1/frame-0000.png" 8,4)" "127 26 89 255"
near "--date sets the time of day" "$(px "$tmp/d1/frame-0000.png" 48,4)" "127 127 127 255"
render --scene "$data/clock.glsl" --date "2025-12-31 23:59:59" --time 2 --out "$tmp/d2" > /dev/null
near "the scene clock carries the date over midnight" "$(px "$tmp/d2/frame-0000.png" 8,4)" "133 0 6 255"
expect_error "bad --date" 1 "--date: '2025-02-29'" render --scene "$data/clock.glsl" --date 2025-02-29 --out "$tmp/x"
"$FOVEATE" view --help | grep -A2 -- "--date" | grep -q "default now" && ok "view defaults to the real clock" || bad "view --help on --date"
"$FOVEATE" render --help | grep -A2 -- "--date" | grep -q "default 2026-01-01" && ok "render documents its fixed date" || bad "render --help on --date"
"$FOVEATE" bench --help | grep -q -- "--date" && ok "bench has --date" || bad "bench --help on --date"

# 5. Hostile files.
{ cat "$data/legacy_names.glsl"; echo "void"; head -c 50000 /dev/zero | tr '\0' '\n'; echo "helper() {}"; } > "$tmp/newlines.glsl"
expect_error "50,000 newlines inside a declaration: no crash" 0 "rendered 1 frame" render --scene "$tmp/newlines.glsl" --channel "$data/quadrants.png" --out "$tmp/n"
python3 -c "print('void mainImage(out vec4 fragColor, in vec2 ' + 'x' * 300000 + ') { fragColor = vec4(1.0); }')" > "$tmp/longname.glsl"
err=$(timeout 60 "$FOVEATE" render --size 64x36 --scene "$tmp/longname.glsl" --out "$tmp/ln" 2>&1); rc=$?
[[ $rc -eq 0 || ( $rc -eq 1 && "$err" == *longname.glsl* ) ]] && ok "a 300,000-character parameter name: no crash (exit $rc)" || bad "long name (exit $rc): ${err:0:300}"
python3 -c "print('void mainImage(out vec4 fragColor, in vec2 c) { fragColor = vec4(' + 'y' * 300000 + '); }')" > "$tmp/longerr.glsl"
expect_error "a driver error quoting a 300,000-character name" 1 "longerr.glsl:1:" render --scene "$tmp/longerr.glsl" --out "$tmp/x"
render --scene "$data/bom.glsl" --out "$tmp/b" > /dev/null || bad "BOM shader renders"
near "a UTF-8 BOM is skipped" "$(px "$tmp/b/frame-0000.png" 8,4)" "0 255 0 255"
{ echo "void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }"; head -c 1100000 /dev/zero | tr '\0' ' '; } > "$tmp/big.glsl"
expect_error "a shader over the size limit" 1 "over the limit of 1.0 MiB" render --scene "$tmp/big.glsl" --out "$tmp/x"
mkfifo "$tmp/pipe.glsl" "$tmp/pipe.png"
expect_error "a FIFO as the shader is refused, not opened" 1 "$tmp/pipe.glsl: the shader is a named pipe (FIFO), not a regular file" render --scene "$tmp/pipe.glsl" --out "$tmp/x"
expect_error "a FIFO as a channel is refused, not opened" 1 "$tmp/pipe.png: the iChannel0 image is a named pipe" render --scene "$data/channels.glsl" --channel "$tmp/pipe.png" --out "$tmp/x"
cp "$data/channels.glsl" "$tmp/side.glsl"; mkfifo "$tmp/side.json"
expect_error "a FIFO as the channels file beside a shader is refused" 1 "$tmp/side.json: the channels file is a named pipe" render --scene "$tmp/side.glsl" --out "$tmp/x"
mkfifo "$tmp/project.json"
expect_error "a FIFO as a project is refused" 1 "$tmp/project.json: the Shadertoy project is a named pipe" render --scene "$tmp/project.json" --out "$tmp/x"
mkdir "$tmp/dir.glsl"
expect_error "a directory as the shader" 1 "is a directory, not a regular file" render --scene "$tmp/dir.glsl" --out "$tmp/x"
# A PNG whose header says 20000x20000 (no pixel data): refused from the header.
python3 -c "
import struct, zlib, sys
ihdr = struct.pack('>IIBBBBB', 20000, 20000, 8, 6, 0, 0, 0)
chunk = lambda t, d: struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d))
open(sys.argv[1], 'wb').write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', ihdr) + chunk(b'IEND', b''))" "$tmp/huge.png"
start=$(date +%s)
expect_error "a 20000x20000 channel image is refused naming the file and channel" 1 "iChannel1 image '$tmp/huge.png': 20000x20000 pixels, over the limit of 16384 pixels a side" render --scene "$data/unbound_channel.glsl" --channel "$data/quadrants.png" --channel "$tmp/huge.png" --out "$tmp/x"
(( $(date +%s) - start < 10 )) && ok "refused before decoding" || bad "the huge image took $(( $(date +%s) - start )) s"

# 6. Multipass projects: feedback, pass order, Common, images, techniques.
mp="$data/multipass"
render --scene "$mp/counter.json" --frames 5 --reference ssaa:2 --out "$tmp/m" > /dev/null || bad "multipass render"
near "frame 0: Buffer A = 1, Buffer B = 1, iFrame 0" "$(px "$tmp/m/frame-0000.png" 32,18)" "26 3 0 255"
near "frame 1: Buffer A = 2, Buffer B = 3, iFrame 1" "$(px "$tmp/m/frame-0001.png" 32,18)" "51 8 26 255"
near "frame 4: Buffer A = 5, Buffer B = 15, iFrame 4" "$(px "$tmp/m/frame-0004.png" 32,18)" "127 38 102 255"
near "an image channel in a project" "$(px "$tmp/m/frame-0004.png" 2,2)" "255 0 0 255"
near "the supersampled reference runs its own buffers" "$(px "$tmp/m/reference-0004.png" 32,18)" "127 38 102 255"
for t in "inset" "layered --param half_rate=0" "logpolar"; do
  render --scene "$mp/counter.json" --frames 5 --technique $t --overwrite --out "$tmp/t" > /dev/null || bad "multipass with $t"
  near "multipass with $t: buffers once per frame" "$(px "$tmp/t/frame-0004.png" 32,18)" "127 38 102 255"
done
cat > "$tmp/cycle.json" <<JSON
{"passes": [{"name": "Common", "file": "$mp/common.glsl"},
            {"name": "Buffer A", "file": "$mp/sum_b.glsl", "iChannel0": "Buffer B", "iChannel1": "Buffer A"},
            {"name": "Buffer B", "file": "$mp/count_a.glsl", "iChannel0": "Buffer B"},
            {"name": "Image", "file": "$mp/image.glsl", "iChannel0": "Buffer B", "iChannel1": "Buffer A",
             "iChannel2": "$data/quadrants.png"}]}
JSON
render --scene "$tmp/cycle.json" --frames 3 --out "$tmp/c" > /dev/null || bad "a cycle between buffers renders"
# A reads B's last frame (0, 1, 2): A = 0, 1, 3; B counts 1, 2, 3.
near "a cycle reads the last frame" "$(px "$tmp/c/frame-0002.png" 32,18)" "77 8 51 255"
project() { echo "{\"passes\": [$1]}" > "$tmp/p.json"; }
img="{\"name\": \"Image\", \"file\": \"$mp/image.glsl\"}"
project "{\"name\": \"Buffer A\", \"file\": \"$tmp/nope.glsl\"}, $img"
expect_error "missing pass file" 1 "$tmp/nope.glsl: cannot open the Buffer A pass: No such file" render --scene "$tmp/p.json" --out "$tmp/x"
project "{\"name\": \"Image\", \"file\": \"$mp/image.glsl\", \"iChannel0\": \"Buffer C\"}"
expect_error "binding to a buffer the project lacks" 1 "passes[0].iChannel0: 'Buffer C' is not a pass of this project (it has no buffers)" render --scene "$tmp/p.json" --out "$tmp/x"
project "{\"name\": \"Buffer E\", \"file\": \"$mp/count_a.glsl\"}, $img"
expect_error "unknown pass name" 1 "'Buffer E' is not a Shadertoy pass" render --scene "$tmp/p.json" --out "$tmp/x"
project "{\"name\": \"Buffer A\", \"file\": \"$mp/count_a.glsl\"}"
expect_error "no Image pass" 1 "no \"Image\" pass" render --scene "$tmp/p.json" --out "$tmp/x"
project "$img, $img"
expect_error "two Image passes" 1 "a second 'Image' pass" render --scene "$tmp/p.json" --out "$tmp/x"
project "{\"name\": \"Common\", \"file\": \"$mp/common.glsl\", \"iChannel0\": \"Buffer A\"}, $img"
expect_error "channels on Common" 1 "the Common part has no channels" render --scene "$tmp/p.json" --out "$tmp/x"
project "{\"name\": \"Buffer A\", \"file\": \"$data/semantic_error.glsl\"}, $img"
expect_error "a buffer's compile error names its file and line" 1 "Buffer A" render --scene "$tmp/p.json" --out "$tmp/x"
expect_error "... and the line" 1 "semantic_error.glsl:3:19" render --scene "$tmp/p.json" --out "$tmp/x"
project "{\"name\": \"Image\", \"file\": \"$mp/image.glsl\", \"iChannel2\": \"$tmp/huge.png\"}"
expect_error "a project's huge image" 1 "passes[0].iChannel2 image '$tmp/huge.png': 20000x20000" render --scene "$tmp/p.json" --out "$tmp/x"
project "{\"name\": \"Image\", \"file\": \"$mp/image.glsl\", \"colour\": 1}"
expect_error "unknown key in a pass" 1 "colour" render --scene "$tmp/p.json" --out "$tmp/x"
echo '{"iChannel0": "quadrants.png"}' > "$tmp/notproject.json"
expect_error "a channels file is not a project" 1 "not a Shadertoy project: no \"passes\"" render --scene "$tmp/notproject.json" --out "$tmp/x"
expect_error "--channel with a project" 1 "--channel is for a single shader" render --scene "$mp/counter.json" --channel "$data/quadrants.png" --out "$tmp/x"
render --scene "$mp/counter.json" --frames 1 --out "$tmp/w" 2> "$tmp/w.err" > /dev/null
[[ -z "$(grep -v '^foveate: note: ' "$tmp/w.err")" ]] && ok "no warning when a project binds what it samples" || bad "project stderr: $(cat "$tmp/w.err")"
project "{\"name\": \"Buffer A\", \"file\": \"$mp/count_a.glsl\"}, {\"name\": \"Image\", \"file\": \"$mp/image.glsl\", \"iChannel0\": \"Buffer A\", \"iChannel2\": \"$data/quadrants.png\"}"
render --scene "$tmp/p.json" --overwrite --out "$tmp/w" 2> "$tmp/w.err" > /dev/null
grep -q "count_a.glsl: samples iChannel0 but no image or buffer" "$tmp/w.err" && grep -q "image.glsl: samples iChannel1" "$tmp/w.err" \
  && ok "a project's unbound channels are warned per pass" || bad "project warnings: $(cat "$tmp/w.err")"
exit $fail
