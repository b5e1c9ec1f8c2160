#!/usr/bin/env bash
# The smaller points of issue 29: video files get the mode PNGs get, the
# tiles of side-by-side videos are labelled, no lock file stays behind,
# "did you mean" for misspelled options, scenes and techniques, progress
# only for work longer than a second, a text legend in the rates preview.
set -u
. "$(dirname "$0")/cli_lib.sh"
umask 022

# --- File modes: a video like the PNG frames beside it.
have_video=1
command -v ffmpeg >/dev/null && command -v ffprobe >/dev/null || have_video=0
run render --scene cheap --size 64x36 --frames 2 --technique layered --out "$tmp/r" \
  --video "$tmp/r.mp4" --side-by-side
if [[ $rc -eq 0 && -e "$tmp/r.mp4" ]]; then
  check "the video's mode is the PNG frames' (644)" \
    '[[ "$(stat -c %a "$tmp/r.mp4")" == 644 && "$(stat -c %a "$tmp/r/frame-0000.png")" == 644 ]] || { stat -c "%a %n" "$tmp/r.mp4" "$tmp/r/frame-0000.png"; false; }'
else
  echo "ok: (no video encoder in this build: $err)"
  have_video=0
fi
check "no lock file is left in the output folder" '[[ ! -e "$tmp/r/.foveate.lock" ]]'

# --- Labelled tiles: each half names its technique in its bottom-left corner.
pixel() {  # file n x y
  local w
  w=$(ffprobe -v error -select_streams v:0 -show_entries stream=width -of default=nw=1:nk=1 "$1")
  ffmpeg -v error -i "$1" -vf "select=eq(n\,$2)" -vframes 1 -f rawvideo -pix_fmt rgb24 - |
    od -An -v -tu1 -w3 | sed -n "$(( $4 * w + $3 + 1 ))p" | xargs
}
dark() { local a=($1); [[ ${#a[@]} -eq 3 ]] && (( a[0] < 70 && a[1] < 70 && a[2] < 70 )); }
light() { local a=($1); [[ ${#a[@]} -eq 3 ]] && (( a[0] > 150 && a[1] > 150 && a[2] > 150 )); }
cat > "$tmp/red.glsl" <<'GLSL'
void mainImage(out vec4 fragColor, in vec2 fragCoord) { fragColor = vec4(0.8, 0.2, 0.1, 1.0); }
GLSL
if [[ $have_video -eq 1 ]]; then
  "$F" render --scene "$tmp/red.glsl" --size 64x36 --frames 1 --technique layered \
    --side-by-side --video "$tmp/sbs.mp4" > /dev/null 2>&1
  # Labels are 9 px high at this size (rows 27-35): a dark box, light letters.
  check "the native half is labelled (dark box inside the N)" 'dark "$(pixel "$tmp/sbs.mp4" 0 3 29)" || { echo "  got: $(pixel "$tmp/sbs.mp4" 0 3 29)"; false; }'
  check "...with a light letter" 'light "$(pixel "$tmp/sbs.mp4" 0 1 31)" || { echo "  got: $(pixel "$tmp/sbs.mp4" 0 1 31)"; false; }'
  check "the technique's half is labelled" 'light "$(pixel "$tmp/sbs.mp4" 0 65 31)" && dark "$(pixel "$tmp/sbs.mp4" 0 67 31)" || { echo "  got: $(pixel "$tmp/sbs.mp4" 0 65 31) / $(pixel "$tmp/sbs.mp4" 0 67 31)"; false; }'
  "$F" bench --scene "$tmp/red.glsl" --size 64x36 --frames 1 --warmup 0 --techniques layered,inset \
    --no-metrics --quiet --video "$tmp/b.mp4" --out "$tmp/b" > /dev/null 2>&1
  check "bench's tiles are labelled too (the L of layered, the I of inset)" 'light "$(pixel "$tmp/b.mp4" 0 1 31)" && light "$(pixel "$tmp/b.mp4" 0 67 31)" && dark "$(pixel "$tmp/b.mp4" 0 65 31)" || { echo "  got: $(pixel "$tmp/b.mp4" 0 1 31) / $(pixel "$tmp/b.mp4" 0 67 31)"; false; }'
fi

# --- "did you mean".
run render --sise 64x36 --scene cheap --no-write
check "a misspelled option gets a suggestion" '[[ $rc -eq 2 && "$err" == *"did you mean '"'"'--size'"'"'"* ]] || { echo "  rc $rc: $err"; false; }'
run render --scene chep --size 64x36 --no-write
check "a misspelled scene" '[[ $rc -eq 1 && "$err" == *"did you mean '"'"'cheap'"'"'"* ]] || { echo "  rc $rc: $err"; false; }'
run render --scene cheap --technique layerd --size 64x36 --no-write
check "a misspelled technique" '[[ $rc -eq 1 && "$err" == *"did you mean '"'"'layered'"'"'"* ]] || { echo "  rc $rc: $err"; false; }'
run bench --techniques native,logpolr --scene cheap --size 64x36 --out "$tmp/x"
check "a misspelled technique in bench's list" '[[ $rc -eq 1 && "$err" == *"did you mean '"'"'logpolar'"'"'"* ]] || { echo "  rc $rc: $err"; false; }'
run rendr --scene cheap
check "a misspelled command" '[[ $rc -eq 2 && "$err" == *"did you mean '"'"'render'"'"'"* ]] || { echo "  rc $rc: $err"; false; }'
err=$("$FOVEATE" bogus 2>&1); rc=$?
check "an unknown command is named" '[[ $rc -eq 2 && "$err" == *"'"'"'bogus'"'"' is not a command"* ]] || { echo "  rc $rc: $err"; false; }'

# --- Progress only for work longer than a second.
# Checked only where the work did take under a second (a loaded machine may
# take longer, and then progress is due).
quick() {  # name, args...: no progress lines from a command done within a second
  local name=$1; shift
  local t0 t1
  t0=$(date +%s%N); run "$@"; t1=$(date +%s%N)
  if (( (t1 - t0) / 1000000 >= 1000 )); then echo "ok: $name (skipped: took over a second here)"; return; fi
  check "$name" '[[ $rc -eq 0 && "$err" != *"done in"* && "$err" != *"left"* ]] || { echo "  rc $rc: $err"; false; }'
}
quick "plan --sweep (half a second of work) prints no progress" plan --sweep "$tmp/fov.svg"
quick "a quick render prints no progress" render --scene cheap --size 32x18 --frames 3 --out "$tmp/p"

# --- rates.png: each swatch of the legend is named.
"$F" rates --api gl-nv --gaze 100,30 --size 320x160 --out "$tmp/g.json" --preview "$tmp/p.png" > /dev/null
px=$(python3 "$FOVEATE_SOURCE_DIR/tests/cli/pngpixel.py" "$tmp/p.png" 6,122 4,122 5,122)
check "the legend's first swatch is labelled 1X1 (a white '1' on a dark box)" \
  '[[ "$(sed -n 1p <<< "$px")" == "255 255 255 255" && "$(sed -n 2p <<< "$px")" == "16 16 16 255" ]] || { echo "  got: $px"; false; }'

exit $fail
