#!/usr/bin/env bash
# Renders every Shadertoy shader (*.glsl, *.frag) in a folder at 64x36 for 2
# frames, each under a time limit, and tallies how many render and why the
# others fail (the first line of each error, grouped).
#   scripts/corpus-shadertoy.sh FOLDER [FOVEATE] [SECONDS]
# FOVEATE defaults to build/debug/app/foveate, SECONDS (per shader) to 60.
# Channels: a shader's NAME.json beside it is used as usual; otherwise every
# iChannel gets tests/data/shadertoy/quadrants.png, so that shaders that read
# a texture have one. Prints one line per shader, then the tally.
set -u
dir=${1:?usage: corpus-shadertoy.sh FOLDER [FOVEATE] [SECONDS]}
root=$(cd "$(dirname "$0")/.." && pwd)
foveate=${2:-$root/build/debug/app/foveate}
limit=${3:-60}
tex="$root/tests/data/shadertoy/quadrants.png"
out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
ok=0; failed=0; uniform=0
declare -A reasons
shopt -s nullglob
for f in "$dir"/*.glsl "$dir"/*.frag; do
  name=$(basename "$f")
  channels=()
  [[ -f "${f%.*}.json" ]] || channels=(--channel "$tex" --channel "$tex" --channel "$tex" --channel "$tex")
  err=$(timeout "$limit" "$foveate" render --scene "$f" "${channels[@]}" --size 64x36 --frames 2 \
          --out "$out/frames" 2>&1 >/dev/null)
  rc=$?
  if [[ $rc -eq 0 && -s "$out/frames/frame-0001.png" ]]; then
    ok=$((ok + 1))
    # A frame of one colour is worth a look (it may be right: a shader that
    # waits for input, or one that fills the screen).
    colours=$(python3 -c "
import sys; sys.path.insert(0, sys.argv[1])
from pngpixel import read_png
w, h, bpp, rows = read_png(sys.argv[2])
print(len({bytes(r[i:i + bpp]) for r in rows for i in range(0, w * bpp, bpp)}))" \
      "$root/tests/cli" "$out/frames/frame-0001.png" 2>/dev/null || echo "?")
    if [[ "$colours" == 1 ]]; then uniform=$((uniform + 1)); echo "ok      $name (one colour)"
    else echo "ok      $name"; fi
  else
    failed=$((failed + 1))
    if [[ $rc -eq 124 ]]; then reason="timeout after ${limit} s"
    elif [[ $rc -ge 128 ]]; then reason="crash (signal $((rc - 128)))"
    else
      # The first error line, without file names, line numbers and quoted names.
      reason=$(printf '%s\n' "$err" | grep -v '^foveate: warning' | grep -v 'does not compile:$' | grep -m1 -E 'error' \
                 | sed -E 's/^.*(error|ERROR)[^:]*: *//; s/`[^'"'"']*'"'"'/NAME/g; s/'"'"'[^'"'"']*'"'"'/NAME/g' | cut -c1-90)
      [[ -n "$reason" ]] || reason="exit $rc: $(printf '%s' "$err" | head -c 80)"
    fi
    reasons[$reason]=$(( ${reasons[$reason]:-0} + 1 ))
    echo "FAILED  $name: $reason"
  fi
  rm -rf "$out/frames"
done
echo
echo "rendered: $ok ($uniform of one colour), failed: $failed, of $((ok + failed))"
for r in "${!reasons[@]}"; do echo "  ${reasons[$r]}x $r"; done | sort -rn
