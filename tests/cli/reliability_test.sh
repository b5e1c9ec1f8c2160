#!/usr/bin/env bash
# Hostile and extreme input (issue 13): every case ends with the documented
# exit code (1 = bad input, 2 = bad usage) and a message naming the input;
# nothing hangs, crashes or silently renders something wrong.
set -u
fail=0
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
data="$FOVEATE_SOURCE_DIR/tests/data/shadertoy"
# name, expected exit code, expected text, args... (each run bounded in time)
expect() {
  local name=$1 code=$2 text=$3; shift 3
  local err rc
  err=$(timeout 60 "$FOVEATE" "$@" 2>&1); rc=$?
  if [[ $rc -eq $code && "$err" == *"$text"* ]]; then echo "ok: $name"; else
    echo "FAIL: $name (exit $rc, expected $code with '$text'): $err"; fail=1; fi
}

# ---- usage errors exit 2, help and version 0
expect "unknown option: exit 2" 2 "--bogus" render --scene cheap --out "$tmp/u" --bogus
expect "missing required option: exit 2" 2 "--scene is required" render --out "$tmp/u"
expect "value of the wrong type: exit 2" 2 "--frames" render --scene cheap --out "$tmp/u" --frames abc
expect "20-digit --frames: exit 2" 2 "--frames" render --scene cheap --out "$tmp/u" --frames 99999999999999999999
expect "no subcommand: exit 2" 2 "A subcommand is required"
out=$("$FOVEATE" demo --size 0x0 --out "$tmp/d0" 2>/dev/null); rc=$?
if [[ $rc -eq 1 && -z "$out" ]]; then echo "ok: demo checks its options before its header"; else echo "FAIL: demo printed '$out' (exit $rc)"; fail=1; fi
expect "--help: exit 0" 0 "Usage" render --help
expect "--version: exit 0" 0 "foveate" --version

# ---- caps
expect "sweep with too many values names the limit" 1 "over the limit of 50" \
  bench --scene cheap --size 32x32 --sweep slope=1e16:2e16:1 --out "$tmp/s1"
"$FOVEATE" bench --scene cheap --size 32x18 --frames 1 --warmup 0 --no-metrics --quiet --techniques native \
  --sweep slope=1e16:1e16:1 --out "$tmp/s2" > /dev/null 2>&1 & pid=$!
for _ in $(seq 600); do kill -0 $pid 2>/dev/null || break; sleep 0.1; done
if kill -0 $pid 2>/dev/null; then kill $pid; echo "FAIL: a sweep whose step does not change the value runs on"; fail=1
else echo "ok: a sweep whose step does not change the value ends"; fi
expect "plan --step 1e-9 is capped, naming the limit and how to raise it" 1 "over the limit of 10000" plan --step 1e-9
expect "... and says --max-grid" 1 "--max-grid" plan --step 1e-9
expect "plan --sweep with a tiny step is capped too" 1 "over the limit" plan --step 1e-7 --sweep "$tmp/sweep.csv"
expect "a small --max-grid refuses a step within the default" 1 "over the limit of 20" plan --step 0.5 --max-grid 20
out=$("$FOVEATE" plan --step 0.5 --max-grid 50 2>&1); rc=$?
if [[ $rc -eq 0 && "$out" == *"pixel ratio"* ]]; then echo "ok: --max-grid raises the limit"; else echo "FAIL: --max-grid: $out"; fail=1; fi
expect "bad --max-grid" 1 "--max-grid" plan --max-grid 0
printf 'time_s,x,y\n' > "$tmp/big.csv"
head -c 2200000 /dev/zero | tr '\0' '\n' >> "$tmp/big.csv"
FOVEATE_MAX_TRACE_MB=1 expect "a trace over the size limit names it and how to raise it" 1 "FOVEATE_MAX_TRACE_MB" gaze stats "$tmp/big.csv"
FOVEATE_MAX_TRACE_MB=1 expect "... and the limit" 1 "over the limit of 1.0 MiB" gaze stats "$tmp/big.csv"
FOVEATE_MAX_TRACE_MB=lots expect "a bad FOVEATE_MAX_TRACE_MB" 1 "FOVEATE_MAX_TRACE_MB" gaze stats "$tmp/big.csv"

# ---- inputs that are not regular files are refused before they are opened
mkfifo "$tmp/fifo"
expect "display JSON that is a FIFO" 1 "fifo: the display JSON is a named pipe" plan --display "$tmp/fifo"
expect "camera path that is a FIFO" 1 "fifo: the camera path is a named pipe" render --scene cheap --size 32x32 --camera-path "$tmp/fifo" --out "$tmp/f"
expect "gaze trace that is a FIFO (render)" 1 "the gaze trace is a named pipe" render --scene cheap --size 32x32 --gaze "trace:$tmp/fifo" --out "$tmp/f"
expect "gaze trace that is a FIFO (stats)" 1 "the gaze trace is a named pipe" gaze stats "$tmp/fifo"
expect "gaze trace that is a device" 1 "/dev/zero: the gaze trace is a character device" gaze stats /dev/zero
expect "gaze trace that is a directory" 1 "the gaze trace is a directory" gaze stats "$tmp"
expect "display JSON that is a directory" 1 "the display JSON is a directory" plan --display "$tmp"
expect "image that is a FIFO (compare)" 1 "the image is a named pipe" compare "$tmp/fifo" "$tmp/fifo"

# ---- the watchdog: a frame over --frame-timeout stops the run, naming scene and frame
start=$(date +%s)
expect "a frame over --frame-timeout: exit 1 naming the scene and the frame" 1 \
  "scene 'slow.glsl': frame 0 (native) did not finish within 1 s (--frame-timeout)" \
  render --scene "$data/slow.glsl" --size 64x36 --frame-timeout 1 --out "$tmp/slow"
took=$(( $(date +%s) - start ))
if [[ $took -lt 30 ]]; then echo "ok: the watchdog stopped it in ${took} s"; else echo "FAIL: the watchdog took ${took} s"; fail=1; fi
# The process ends without unwinding, yet leaves neither its lock nor the
# folders it created (empty) behind.
if [[ ! -e "$tmp/slow" ]]; then echo "ok: no frame, lock or folder left"; else echo "FAIL: left $(ls -A "$tmp/slow")"; fail=1; fi
expect "bench under the watchdog" 1 "did not finish within 1 s" \
  bench --scene "$data/slow.glsl" --size 64x36 --frame-timeout 1 --techniques native --quiet --out "$tmp/slowb/deeper"
if [[ ! -e "$tmp/slowb" ]]; then echo "ok: bench left no folder"; else echo "FAIL: bench left $tmp/slowb"; fail=1; fi
expect "bad --frame-timeout" 1 "--frame-timeout: expected 0 (no limit) to 86400 seconds, got -1" \
  render --scene cheap --size 32x32 --frame-timeout -1 --out "$tmp/x"
expect "--frame-timeout 0 turns it off" 0 "rendered 1 frame" render --scene cheap --size 32x32 --frame-timeout 0 --out "$tmp/w0"

# ---- outputs: errors name the path and the reason, exit 1
echo "a file" > "$tmp/afile"
expect "--out on an existing file" 1 "--out $tmp/afile: exists and is not a folder" render --scene cheap --size 32x32 --out "$tmp/afile"
expect "--out below a file" 1 "cannot create the folder: Not a directory" render --scene cheap --size 32x32 --out "$tmp/afile/sub"
expect "--out in /proc" 1 "--out /proc/foveate-out: cannot create the folder" render --scene cheap --size 32x32 --out /proc/foveate-out
expect "--out /proc" 1 "--out /proc: cannot write into the folder" render --scene cheap --size 32x32 --out /proc
expect "bench --out on an existing file" 1 "exists and is not a folder" bench --scene cheap --size 32x32 --out "$tmp/afile"
expect "--out named like a file" 1 "--out $tmp/frame.png: names a file (.png), but --out is the folder the outputs are written into; give a folder, e.g. --out $tmp/frame" render --scene cheap --size 32x32 --out "$tmp/frame.png"
if [[ -e "$tmp/frame.png" ]]; then echo "FAIL: --out named like a file left a folder"; fail=1; else
  echo "ok: --out named like a file: nothing created"; fi
expect "bench --out named like a file" 1 "names a file (.json)" bench --scene cheap --size 32x32 --out "$tmp/results.json"
mkdir "$tmp/kept.png"
expect "--out: an existing folder named like a file is used" 0 "rendered 1 frame" render --scene cheap --size 32x32 --out "$tmp/kept.png"
if [[ $(id -u) -ne 0 ]]; then
  mkdir "$tmp/ro"; chmod 555 "$tmp/ro"
  expect "--out in a read-only folder" 1 "cannot write into the folder" render --scene cheap --size 32x32 --out "$tmp/ro"
  chmod 755 "$tmp/ro"
fi

# ---- an output folder is locked by the run using it
"$FOVEATE" render --scene "$data/slow.glsl" --size 64x36 --frame-timeout 20 --out "$tmp/busy" > /dev/null 2>&1 & busy=$!
for _ in $(seq 100); do [[ -s "$tmp/busy/.foveate.lock" ]] && break; sleep 0.1; done
expect "a second run into a folder in use" 1 "--out $tmp/busy: the folder is in use by another foveate run (pid $busy)" \
  render --scene cheap --size 32x32 --out "$tmp/busy"
expect "... bench too" 1 "the folder is in use by another foveate run" bench --scene cheap --size 32x32 --quiet --out "$tmp/busy"
kill $busy 2>/dev/null; wait $busy 2>/dev/null
expect "the folder is free again once the run ended" 0 "rendered 1 frame" render --scene cheap --size 32x32 --out "$tmp/busy"

# ---- JSON values the parser cannot hold name the file and the key
printf '{"name": "x", "width_px": 100, "height_px": 100, "width_mm": 1e999, "distance_mm": 500}' > "$tmp/d1.json"
expect "1e999 in a display JSON" 1 "d1.json: the number 1e999 at byte 66 (key width_mm) is out of range" plan --display "$tmp/d1.json"
printf '{"loop": false, "keyframes": [{"t": 0, "position": [0, -1e999, 5]}]}' > "$tmp/c1.json"
expect "1e999 in a camera path" 1 "(key keyframes[0].position[1]) is out of range" render --scene cheap --size 32x32 --camera-path "$tmp/c1.json" --out "$tmp/x"
printf '{"samples": [[0, 0.5, 0.5], [1e999, 0.5, 0.5]]}' > "$tmp/t1.json"
expect "1e999 in a JSON trace" 1 "(key samples[1][0]) is out of range" gaze stats "$tmp/t1.json"
printf '{"name": "x", "width_px": 99999999999999999999, "height_px": 100, "width_mm": 100, "distance_mm": 500}' > "$tmp/d2.json"
expect "a 20-digit integer is out of range, not a fraction" 1 "width_px: 1e+20 is out of range [1, 65536]" plan --display "$tmp/d2.json"
printf '{"name": "x", "width_px": 12345678901234567890, "height_px": 100, "width_mm": 100, "distance_mm": 500}' > "$tmp/d3.json"
expect "a 20-digit integer within uint64 is out of range" 1 "width_px: 12345678901234567890 is out of range" plan --display "$tmp/d3.json"
printf '{"name": "x", "width_px": 100.5, "height_px": 100, "width_mm": 100, "distance_mm": 500}' > "$tmp/d4.json"
expect "a fraction is still a fraction" 1 "width_px: expected an integer, got a fraction" plan --display "$tmp/d4.json"

# ---- values beyond a limit say the limit
expect "--fps 1000000 names the limit" 1 "--fps: expected a rate above 0 and at most 10000 frames per second, got 1e+06" \
  render --scene cheap --size 32x32 --fps 1000000 --out "$tmp/x"
expect "--margin 0.5 names the range" 1 "--margin: expected a factor from 1 to 4" \
  render --scene cheap --size 32x32 --margin 0.5 --out "$tmp/x"
expect "--param msaa beyond the GL implementation" 1 "supports G-buffer MSAA of at most" \
  render --scene guenter --size 32x32 --technique layered --param msaa=8 --out "$tmp/x"

# ---- a camera looking straight down renders the scene (not an empty frame)
printf '{"loop": false, "keyframes": [{"t": 0, "position": [0, 6, 0], "target": [0, 0, 0]}]}' > "$tmp/down.json"
# ---- a camera path for a shader that reads no camera would change nothing: refused
expect "a camera path for a shader without a camera" 1 "down.json: a camera path for scene 'slow.glsl', whose shader reads no camera" \
  render --scene "$data/slow.glsl" --size 32x32 --camera-path "$tmp/down.json" --out "$tmp/nocam"
for scene in cheap guenter; do
  "$FOVEATE" render --scene "$scene" --size 64x36 --camera-path "$tmp/down.json" --out "$tmp/down-$scene" > /dev/null 2>&1
  "$FOVEATE" render --scene "$scene" --size 64x36 --out "$tmp/default-$scene" > /dev/null 2>&1
  # An empty frame is one colour: its PNG compresses to almost nothing.
  size=$(stat -c %s "$tmp/down-$scene/frame-0000.png" 2>/dev/null || echo 0)
  if [[ $size -gt 1000 ]]; then echo "ok: $scene seen from straight above has content ($size bytes)"; else
    echo "FAIL: $scene seen from straight above is empty ($size bytes)"; fail=1; fi
done

# ---- logpolar at tiny and flat sizes: native where the disc covers the screen,
# and never a black (unshaded) pixel
cat > "$tmp/png.py" <<'PY'
import struct, sys, zlib
def load(path):
    d = open(path, "rb").read(); i = 8; idat = b""
    while i < len(d):
        n = struct.unpack(">I", d[i:i + 4])[0]; t = d[i + 4:i + 8]
        if t == b"IHDR": w, h, _, ct = struct.unpack(">IIBB", d[i + 8:i + 18])
        if t == b"IDAT": idat += d[i + 8:i + 8 + n]
        i += 12 + n
    raw = zlib.decompress(idat); bpp = 4 if ct == 6 else 3; stride = w * bpp
    rows, prev, k = [], bytearray(stride), 0
    for _ in range(h):
        f = raw[k]; line = bytearray(raw[k + 1:k + 1 + stride]); k += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0; b = prev[x]; c = prev[x - bpp] if x >= bpp else 0
            if f == 1: line[x] = (line[x] + a) & 255
            elif f == 2: line[x] = (line[x] + b) & 255
            elif f == 3: line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c; pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line); prev = line
    return [tuple(r[x * bpp:x * bpp + 3]) for r in rows for x in range(w)]
native, test = load(sys.argv[1]), load(sys.argv[2])
diff = max(max(abs(p - q) for p, q in zip(a, b)) for a, b in zip(native, test))
black = sum(1 for p in test if p == (0, 0, 0) and p not in native)
print(diff, black)
PY
for size in 1x1 2x2 3x3 8x1 1x8 16x2 2x16 200x3; do
  "$FOVEATE" render --scene cheap --size $size --out "$tmp/lpn-$size" > /dev/null
  "$FOVEATE" render --scene cheap --size $size --technique logpolar --out "$tmp/lpl-$size" > /dev/null
  read -r diff black < <(python3 "$tmp/png.py" "$tmp/lpn-$size/frame-0000.png" "$tmp/lpl-$size/frame-0000.png")
  case $size in 1x1|2x2|3x3) want="diff=0";; *) want="no black";; esac
  if [[ ( $want == "diff=0" && $diff -eq 0 ) || ( $want == "no black" && $black -eq 0 && $diff -lt 80 ) ]]; then
    echo "ok: logpolar at $size ($want: max difference $diff, $black black)"; else
    echo "FAIL: logpolar at $size: max difference $diff from native, $black black pixels"; fail=1; fi
done

# ---- techniques: every default lies within its declared range, at any size
for size in 64x36 1x1 16384x16384; do
  "$FOVEATE" techniques --size $size > "$tmp/tech.txt"
  # [min..max], or the listed values: [2 or 4], [1, 2, 4, 9 or 16].
  if awk '/^  [a-z_0-9]+ +=/ { v=$3; match($0, /\[[^]]*\]$/); r=substr($0, RSTART+1, RLENGTH-2)
      if (r ~ /\.\./) { split(r, b, "\\.\\."); if (v+0 < b[1]+0 || v+0 > b[2]+0) { print; bad=1 } }
      else { n=split(r, b, /, | or /); ok=0; for (i=1; i<=n; i++) if (v+0 == b[i]+0) ok=1; if (!ok) { print; bad=1 } } } END { exit bad }' "$tmp/tech.txt"; then
    echo "ok: defaults within their ranges at $size"; else echo "FAIL: a default outside its range at $size"; fail=1; fi
done
exit $fail
