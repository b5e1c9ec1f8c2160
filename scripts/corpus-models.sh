#!/usr/bin/env bash
# Renders every model file under a folder with `foveate render` (one small
# frame each, with a time limit) and tallies what happened:
#   ok       exit 0 and a non-blank frame (the model covers some of the frame
#            and is lit, not black)
#   blank    exit 0 but nothing of the model is visible, or it is black
#   error    exit 1 with foveate's message (the reason is tallied)
#   crash    any other exit status (internal error 3, a signal)
#   timeout  still running after the time limit
# Usage: scripts/corpus-models.sh FOLDER [RESULTS.tsv]
# Environment: FOVEATE (the binary; default build/release then build/debug),
# SIZE (default 96x64), TIMEOUT seconds (default 60).
set -u
dir=${1:?usage: scripts/corpus-models.sh FOLDER [RESULTS.tsv]}
results=${2:-/dev/stdout}
here=$(cd "$(dirname "$0")/.." && pwd)
if [[ -z "${FOVEATE:-}" ]]; then
  for b in "$here/build/release/app/foveate" "$here/build/debug/app/foveate"; do
    [[ -x "$b" ]] && FOVEATE=$b && break
  done
fi
[[ -x "${FOVEATE:-}" ]] || { echo "corpus-models: no foveate binary (set FOVEATE)" >&2; exit 2; }
size=${SIZE:-96x64}
limit=${TIMEOUT:-60}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

# Decodes the frame (8-bit RGB/RGBA PNG, as foveate writes it) and prints
# "ok" or "blank <why>": the background of the mesh scenes below the horizon
# is one flat colour, so model pixels are those that differ from the most
# common colour of the lower 85 % of the frame.
cat > "$tmp/check.py" <<'EOF'
import struct, sys, zlib
from collections import Counter
data = open(sys.argv[1], 'rb').read()
pos, idat = 8, b''
while pos < len(data):
    n, kind = struct.unpack('>I4s', data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + n]
    if kind == b'IHDR':
        w, h, depth, ctype = struct.unpack('>IIBB', body[:10])
    elif kind == b'IDAT':
        idat += body
    pos += 12 + n
bpp = {2: 3, 6: 4}[ctype]
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
            p = a + b - c
            pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
    rows.append(line)
    prev = line
px = [tuple(r[x * bpp:x * bpp + 3]) for r in rows[int(h * 0.15):] for x in range(w)]
bg = Counter(px).most_common(1)[0][0]
model = [p for p in px if max(abs(p[k] - bg[k]) for k in range(3)) > 10]
frac = len(model) / len(px)
light = sum(max(p) for p in model) / len(model) if model else 0
if frac < 0.005:
    print(f"blank nothing visible ({100 * frac:.2f} % of the frame)")
elif light < 25:
    print(f"blank black (mean {light:.0f})")
else:
    print(f"ok {100 * frac:.1f} % covered")
EOF

models=()
while IFS= read -r -d '' f; do models+=("$f"); done < <(
  find "$dir" -type f \( -iname '*.obj' -o -iname '*.ply' -o -iname '*.stl' -o -iname '*.off' \
    -o -iname '*.dae' -o -iname '*.gltf' -o -iname '*.glb' -o -iname '*.fbx' -o -iname '*.3ds' \
    -o -iname '*.x' -o -iname '*.ac' -o -iname '*.amf' -o -iname '*.nff' -o -iname '*.ase' \
    -o -iname '*.lwo' -o -iname '*.blend' -o -iname '*.3mf' -o -iname '*.x3d' -o -iname '*.ms3d' \
    -o -iname '*.md2' -o -iname '*.md3' -o -iname '*.md5mesh' -o -iname '*.smd' -o -iname '*.b3d' \
    -o -iname '*.irrmesh' -o -iname '*.cob' -o -iname '*.dxf' -o -iname '*.raw' -o -iname '*.ogex' \
    -o -iname '*.q3o' -o -iname '*.xgl' -o -iname '*.zgl' -o -iname '*.ter' -o -iname '*.hmp' \) \
    -print0 | sort -z)

printf 'status\tfile\tdetail\n' > "$tmp/results.tsv"
declare -A count=()
for f in "${models[@]}"; do
  rm -rf "$tmp/out"
  timeout -k 5 "$limit" "$FOVEATE" render --scene "$f" --size "$size" --frames 1 \
    --out "$tmp/out" > /dev/null 2> "$tmp/err"
  rc=$?
  rel=${f#"$dir"/}
  if [[ $rc -eq 124 || $rc -eq 137 ]]; then
    status=timeout detail="over ${limit} s"
  elif [[ $rc -eq 0 ]]; then
    detail=$(python3 "$tmp/check.py" "$tmp/out/frame-0000.png" 2>&1)
    status=${detail%% *}
    detail=${detail#* }
    warnings=$(grep -c "warning" "$tmp/err")
    [[ $warnings -gt 0 ]] && detail="$detail; $warnings warning(s): $(grep -m1 warning "$tmp/err" | sed "s|$dir/||g" | cut -c1-160)"
  elif [[ $rc -eq 1 ]]; then
    status=error
    detail=$(grep -m1 "error" "$tmp/err" | sed "s|$dir/||g; s|^foveate: error: ||" | cut -c1-200)
  else
    status=crash
    detail="exit $rc: $(tail -n1 "$tmp/err" | cut -c1-200)"
  fi
  count[$status]=$(( ${count[$status]:-0} + 1 ))
  printf '%s\t%s\t%s\n' "$status" "$rel" "$detail" >> "$tmp/results.tsv"
done
cat "$tmp/results.tsv" > "$results"
{
  echo "corpus-models: ${#models[@]} files under $dir"
  for s in ok blank error crash timeout; do printf '  %-8s %d\n' "$s" "${count[$s]:-0}"; done
} >&2
[[ ${count[crash]:-0} -eq 0 && ${count[timeout]:-0} -eq 0 ]]
