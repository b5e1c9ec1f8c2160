#!/usr/bin/env bash
# --video on render and bench: the file decoded back with ffprobe / ffmpeg has
# the frames, size, codec and colours it should; bad paths are clear errors
# and leave nothing behind.
set -u
fail=0
check() { if ! eval "$2"; then echo "FAIL: $1"; fail=1; else echo "ok: $1"; fi; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

if ! command -v ffprobe >/dev/null || ! command -v ffmpeg >/dev/null; then
  echo "ffmpeg/ffprobe not installed (scripts/setup.sh installs them)"; exit 1
fi
probe() {  # file -> "codec width height frames pix_fmt rate"
  ffprobe -v error -count_frames -select_streams v:0 \
    -show_entries stream=codec_name,width,height,nb_read_frames,pix_fmt,r_frame_rate \
    -of default=nw=1:nk=1 "$1" | tr '\n' ' ' | sed 's/ $//'
}
# The RGB of pixel (x, y) of frame `n` (0-based) of a video, decoded by ffmpeg.
pixel() {  # file n x y
  local w
  w=$(ffprobe -v error -select_streams v:0 -show_entries stream=width -of default=nw=1:nk=1 "$1")
  ffmpeg -v error -i "$1" -vf "select=eq(n\,$2)" -vframes 1 -f rawvideo -pix_fmt rgb24 - |
    od -An -v -tu1 -w3 | sed -n "$(( $4 * w + $3 + 1 ))p" | xargs
}
near() {  # "r g b" "r g b" tolerance
  local a=($1) b=($2)
  [[ ${#a[@]} -eq 3 ]] || return 1
  for i in 0 1 2; do
    local d=$(( a[i] - b[i] )); (( d < 0 )) && d=$(( -d ))
    (( d <= $3 )) || return 1
  done
}

# A shader with two known colours: left half (204, 51, 26), right half (26, 77, 230).
cat > "$tmp/halves.glsl" <<'EOF'
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  fragColor = fragCoord.x < 0.5 * iResolution.x ? vec4(0.8, 0.2, 0.1, 1.0)
                                                : vec4(0.1, 0.3, 0.9, 1.0);
}
EOF

"$FOVEATE" render --scene "$tmp/halves.glsl" --size 64x36 --frames 4 --fps 25 \
  --video "$tmp/plain.mp4" > "$tmp/out.txt" 2> "$tmp/err.txt"
check "render --video exits 0" '[[ $? -eq 0 ]]'
check "render --video: H.264 yuv420p, 64x36, 4 frames at 25 fps" \
  '[[ "$(probe "$tmp/plain.mp4")" == "h264 64 36 yuv420p 25/1 4" ]] || { echo "  got: $(probe "$tmp/plain.mp4")"; false; }'
check "the encoder is named on stderr" 'grep -q "H.264 (libx264)" "$tmp/err.txt"'
check "no temporary file is left" '[[ -z "$(ls "$tmp" | grep tmp-)" ]]'
check "frame 0 decodes to the shader's left colour" \
  'near "$(pixel "$tmp/plain.mp4" 0 8 18)" "204 51 26" 12 || { echo "  got: $(pixel "$tmp/plain.mp4" 0 8 18)"; false; }'
check "frame 3 decodes to the shader's right colour" \
  'near "$(pixel "$tmp/plain.mp4" 3 56 18)" "26 77 230" 12 || { echo "  got: $(pixel "$tmp/plain.mp4" 3 56 18)"; false; }'

# Side by side: twice the width, native on the left, the gaze ring on both halves.
"$FOVEATE" render --scene "$tmp/halves.glsl" --size 64x36 --frames 3 --technique layered \
  --side-by-side --video "$tmp/sbs.mp4" --out "$tmp/png" > /dev/null 2>&1
check "--side-by-side doubles the width" '[[ "$(probe "$tmp/sbs.mp4")" == "h264 128 36 yuv420p 60/1 3" ]] || { echo "  got: $(probe "$tmp/sbs.mp4")"; false; }'
check "--video with --out writes the PNG frames too" '[[ -s "$tmp/png/frame-0002.png" ]]'
# The gaze (centre, 32,18) is ringed at radius 6: (38, 18) left, (102, 18) right.
check "the gaze ring is drawn on the native half" 'near "$(pixel "$tmp/sbs.mp4" 0 38 18)" "255 255 255" 70'
check "the gaze ring is drawn on the technique's half" 'near "$(pixel "$tmp/sbs.mp4" 0 102 18)" "255 255 255" 70'
check "away from the ring the right half shows the scene" 'near "$(pixel "$tmp/sbs.mp4" 0 70 4)" "204 51 26" 12'

# Odd sizes are padded to even ones (yuv420p).
"$FOVEATE" render --scene cheap --size 65x37 --frames 2 --video "$tmp/odd.mp4" > /dev/null 2> "$tmp/err.txt"
check "an odd size is padded to 66x38 and says so" '[[ "$(probe "$tmp/odd.mp4")" == "h264 66 38 yuv420p 60/1 2" ]] && grep -q "padded" "$tmp/err.txt"'

# bench: the measured frames, techniques tiled; native first with --side-by-side.
"$FOVEATE" bench --scene cheap --size 64x36 --frames 3 --warmup 1 --techniques layered \
  --no-metrics --quiet --side-by-side --video "$tmp/bench.mp4" --out "$tmp/b" > /dev/null 2> "$tmp/err.txt"
check "bench --side-by-side: native | layered, the measured frames" '[[ "$(probe "$tmp/bench.mp4")" == "h264 128 36 yuv420p 60/1 3" ]] || { echo "  got: $(probe "$tmp/bench.mp4")"; false; }'
check "bench names the video on stderr" 'grep -q "video: $tmp/bench.mp4: 3 frame(s)" "$tmp/err.txt"'
"$FOVEATE" bench --scene cheap --size 64x36 --frames 2 --warmup 0 --techniques native,layered,logpolar,inset \
  --no-metrics --quiet --video "$tmp/grid.mkv" --overwrite --out "$tmp/b" > /dev/null 2>&1
check "bench with four techniques: two rows of two (.mkv)" '[[ "$(probe "$tmp/grid.mkv" | cut -d" " -f1-3)" == "h264 128 72" ]] || { echo "  got: $(probe "$tmp/grid.mkv")"; false; }'

expect_error() {  # name, expected text, args...
  local name=$1 text=$2; shift 2
  local err rc
  err=$("$FOVEATE" "$@" 2>&1); rc=$?
  if [[ $rc -eq 1 && "$err" == *"$text"* ]]; then echo "ok: $name"; else echo "FAIL: $name (exit $rc): $err"; fail=1; fi
}
: > "$tmp/afile"
expect_error "a folder that cannot be created" "--video: /proc/foveate-nope/x.mp4: cannot create the folder" \
  render --scene cheap --size 32x32 --video /proc/foveate-nope/x.mp4
expect_error "a file in the way of the folder" "$tmp/afile/x.mp4" \
  render --scene cheap --size 32x32 --video "$tmp/afile/x.mp4"
mkdir -p "$tmp/ro" && chmod 555 "$tmp/ro"
if [[ $(id -u) -ne 0 ]]; then
  expect_error "a read-only folder" "$tmp/ro/x.mp4: cannot write" render --scene cheap --size 32x32 --video "$tmp/ro/x.mp4"
fi
expect_error "a folder as the file" "is a directory" render --scene cheap --size 32x32 --video "$tmp"
expect_error "an unknown container" "cannot tell the video container" render --scene cheap --size 32x32 --video "$tmp/x.nope"
expect_error "bench: an unwritable video path" "--video: /proc/foveate-nope/b.mp4" \
  bench --scene cheap --size 32x32 --frames 1 --techniques layered --quiet --video /proc/foveate-nope/b.mp4 --out "$tmp/b2"
# A failure after the video was opened leaves nothing under its name or a temporary one.
mkdir -p "$tmp/v"
expect_error "a scene error after the video was opened" "syntax_error.glsl" \
  render --scene "$FOVEATE_SOURCE_DIR/tests/data/shadertoy/syntax_error.glsl" --size 32x32 --video "$tmp/v/bad.mp4"
check "...and nothing is left in the video's folder" '[[ -z "$(ls -A "$tmp/v")" ]]'

err=$("$FOVEATE" render --scene cheap --size 32x32 --side-by-side --out "$tmp/x" 2>&1); rc=$?
check "--side-by-side without --video is a usage error" '[[ $rc -ne 0 && $rc -ne 1 && $rc -ne 3 && "$err" == *"--video"* ]]'
err=$("$FOVEATE" render --scene cheap --size 32x32 2>&1); rc=$?
check "render without --out, --video or --no-write is a usage error" '[[ $rc -ne 0 && $rc -ne 1 && $rc -ne 3 && "$err" == *"--out, --video or --no-write"* ]]'

exit $fail
