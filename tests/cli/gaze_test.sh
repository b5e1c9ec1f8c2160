#!/usr/bin/env bash
# Command-line behaviour of `foveate gaze`: synth, stats, errors and help.
set -u
fail=0
check() { if ! eval "$2"; then echo "FAIL: $1"; fail=1; else echo "ok: $1"; fi; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

out=$("$FOVEATE" gaze synth --seed 5 --seconds 4 --rate 100 --out "$tmp/a.csv"); rc=$?
check "synth writes a CSV" '[[ $rc -eq 0 && $(head -2 "$tmp/a.csv" | tail -1) == "time_s,x,y,confidence,valid" && $(wc -l < "$tmp/a.csv") -eq 403 ]]'
check "synth reports what it generated" '[[ "$out" == *"401 samples at 100 Hz"* && "$out" == *saccades* ]]'
"$FOVEATE" gaze synth --seed 5 --seconds 4 --rate 100 --out "$tmp/b.csv" >/dev/null
check "same seed, same trace" 'cmp -s "$tmp/a.csv" "$tmp/b.csv"'
"$FOVEATE" gaze synth --seed 6 --seconds 4 --rate 100 --out "$tmp/c.csv" >/dev/null
check "another seed, another trace" '! cmp -s "$tmp/a.csv" "$tmp/c.csv"'
"$FOVEATE" gaze synth --seed 5 --seconds 2 --out "$tmp/a.json" >/dev/null
check "synth writes JSON" 'python3 -c "import json,sys; j=json.load(open(sys.argv[1])); assert j[\"format\"]==\"foveate-gaze\" and len(j[\"samples\"])==241" "$tmp/a.json"'

out=$("$FOVEATE" gaze stats "$tmp/a.csv"); rc=$?
check "stats: rate and counts" '[[ $rc -eq 0 && "$out" == *"401 samples over 4.00 s, 100.0 Hz"* && "$out" == *"none dropped"* && "$out" == *"saccades"* && "$out" == *"fixations"* ]]'
json=$("$FOVEATE" gaze stats "$tmp/a.json" --json)
check "stats --json" 'python3 -c "import json,sys; j=json.loads(sys.argv[1]); assert j[\"samples\"]==241 and abs(j[\"rate_hz\"]-120)<1e-6 and j[\"ivt\"][\"saccades\"]>0 and j[\"dropped\"][\"total\"]==0" "$json"'

# A hand-made trace: a saccade, a blink, a gap, and one bad sample of each kind.
cat > "$tmp/h.csv" <<'CSV'
time_ms,x_px,y_px,confidence,latency_ms
0,576,540,1,10
10,576,540,1,12
20,576,540,1,12
30,576,540,1,12
40,576,540,1,12
50,576,540,1,12
60,576,540,1,12
70,576,540,1,12
80,1344,540,1,12
90,1344,540,1,12
100,1344,540,1,12
110,1344,540,0,12
120,1344,540,0,12
130,1344,540,1,12
140,1344,540,1,12
150,1344,540,1,12
160,1344,540,1,12
170,1344,540,1,12
180,1344,540,1,12
190,1344,540,1,12
190,1344,540,1,12
185,1344,540,1,12
195,nan,540,1,12
196,99999,540,1,12
400,1344,540,1,40
410,1344,540,1,12
CSV
out=$("$FOVEATE" gaze stats "$tmp/h.csv")
check "stats: dropped by reason" '[[ "$out" == *"4 dropped (1 non-finite, 1 out-of-range, 1 backwards in time, 1 duplicate time)"* ]]'
check "stats: dropouts" '[[ "$out" == *"dropouts: 2, 0.240 s in total, longest 210 ms"* ]]'
check "stats: one saccade, fixations" '[[ "$out" == *"1 saccades"* && "$out" == *"2 fixations"* ]]'
check "stats: latency" '[[ "$out" == *"latency: median 12.0 ms"* && "$out" == *"max 40.0 ms"* ]]'
check "stats: lost samples" '[[ "$out" == *"lost samples (invalid or confidence < 0.60): 2"* ]]'

# Bad files: FILE:LINE and a non-zero exit, never a crash.
# A row that cannot be read is skipped with a warning naming FILE:LINE;
# --strict makes it an error.
printf 'time_s,x,y\n0,0.5,0.5\n0.1,abc,0.5\n0.2,0.5,0.5\n' > "$tmp/bad.csv"
out=$("$FOVEATE" gaze stats "$tmp/bad.csv" 2>"$tmp/warn.txt"); rc=$?
check "bad number: skipped, warning with FILE:LINE" '[[ $rc -eq 0 && "$(cat "$tmp/warn.txt")" == *"warning: $tmp/bad.csv:3: x: '"'"'abc'"'"' is not a number; row skipped"* && "$out" == *"2 samples"* && "$out" == *"could not be read (skipped): 1"* ]]'
err=$("$FOVEATE" gaze stats --strict "$tmp/bad.csv" 2>&1); rc=$?
check "bad number with --strict: FILE:LINE, exit 1" '[[ $rc -eq 1 && "$err" == *"bad.csv:3: x: '"'"'abc'"'"' is not a number; rejected by --strict"* ]]'
json=$("$FOVEATE" gaze stats --json "$tmp/bad.csv" 2>/dev/null)
check "stats --json counts skipped rows" 'python3 -c "import json,sys; assert json.loads(sys.argv[1])[\"skipped_rows\"]==1" "$json"'
printf 'time_s,x,y\n0,0.5\n' > "$tmp/short.csv"
err=$("$FOVEATE" gaze stats "$tmp/short.csv" 2>&1); rc=$?
check "short line and nothing else: FILE:LINE, exit 1" '[[ $rc -eq 1 && "$err" == *"no usable gaze sample"* && "$err" == *"short.csv:2: expected 3 fields"* ]]'
# A recorder killed mid-write: the last line is cut off (no newline).
printf 'time_s,x,y,confidence,valid\n0,0.5,0.5,1,1\n0.1,0.5,0.5,1,1\n0.2,0.5' > "$tmp/cut.csv"
out=$("$FOVEATE" gaze stats "$tmp/cut.csv" 2>"$tmp/warn.txt"); rc=$?
check "cut-off last line: dropped with a warning naming it" '[[ $rc -eq 0 && "$out" == *"2 samples"* && "$(cat "$tmp/warn.txt")" == *"cut.csv:4: expected 5 fields"*"the last line is cut off"*"row skipped"* ]]'
err=$("$FOVEATE" gaze stats --strict "$tmp/cut.csv" 2>&1); rc=$?
check "cut-off last line with --strict: exit 1" '[[ $rc -eq 1 && "$err" == *"cut.csv:4:"*"cut off"*"--strict"* ]]'
err=$("$FOVEATE" render --scene cheap --size 32x18 --gaze "trace:$tmp/cut.csv" --out "$tmp/rc" 2>&1); rc=$?
check "render with a cut-off trace: runs, warns" '[[ $rc -eq 0 && "$err" == *"warning: $tmp/cut.csv:4:"* ]]'
err=$("$FOVEATE" render --scene cheap --size 32x18 --gaze "trace:$tmp/cut.csv" --strict --overwrite --out "$tmp/rc" 2>&1); rc=$?
check "render --strict with a cut-off trace: exit 1" '[[ $rc -eq 1 && "$err" == *"--gaze: $tmp/cut.csv:4:"*"--strict"* ]]'
{ echo "time_s,x,y"; for i in $(seq 1 30); do echo "$i,bad,0.5"; done; echo "31,0.5,0.5"; } > "$tmp/many.csv"
"$FOVEATE" gaze stats "$tmp/many.csv" > /dev/null 2>"$tmp/warn.txt"
check "many bad rows: the first ten named, the rest counted" '[[ $(grep -c "row skipped" "$tmp/warn.txt") -eq 10 && "$(cat "$tmp/warn.txt")" == *"20 more rows skipped"* ]]'
printf 'when,where\n1,2\n' > "$tmp/hdr.csv"
err=$("$FOVEATE" gaze stats "$tmp/hdr.csv" 2>&1); rc=$?
check "bad header: FILE:LINE" '[[ $rc -eq 1 && "$err" == *"hdr.csv:1: the header needs"* ]]'
printf 'time_s,x,y\n0,960,540\n' > "$tmp/px.csv"
err=$("$FOVEATE" gaze stats "$tmp/px.csv" 2>&1); rc=$?
check "pixels without saying so: a hint" '[[ $rc -eq 1 && "$err" == *"x_px,y_px"* ]]'
out=$("$FOVEATE" gaze stats "$tmp/px.csv" --units px); rc=$?
check "--units px reads it" '[[ $rc -eq 0 && "$out" == *"1 samples"* ]]'
: > "$tmp/empty.csv"
err=$("$FOVEATE" gaze stats "$tmp/empty.csv" 2>&1); rc=$?
check "empty file" '[[ $rc -eq 1 && "$err" == *"empty file"* ]]'
head -c 3000 /dev/urandom > "$tmp/random.csv"
err=$("$FOVEATE" gaze stats "$tmp/random.csv" 2>&1); rc=$?
check "random bytes: an error, not a crash" '[[ $rc -eq 1 && "$err" == *random.csv* ]]'
printf '{"samples": [[0, 0.5' > "$tmp/trunc.json"
err=$("$FOVEATE" gaze stats "$tmp/trunc.json" 2>&1); rc=$?
check "truncated JSON" '[[ $rc -eq 1 && "$err" == *trunc.json* ]]'
err=$("$FOVEATE" gaze stats "$tmp/missing.csv" 2>&1); rc=$?
check "missing file" '[[ $rc -eq 1 && "$err" == *missing.csv* ]]'

err=$("$FOVEATE" gaze synth --out "$tmp/trace.txt" 2>&1); rc=$?
check "synth --out of another kind is refused" '[[ $rc -eq 1 && "$err" == *"must end in .csv or .json"* && ! -e "$tmp/trace.txt" ]]'
mkdir -p "$tmp/d.csv"
err=$("$FOVEATE" gaze synth --out "$tmp/d.csv" 2>&1); rc=$?
check "synth --out a folder says so" '[[ $rc -eq 1 && "$err" == *"is a directory; give a file name"* ]]'
for args in "synth --out $tmp/x.csv --seconds 0" "synth --out $tmp/x.csv --rate 0" "synth --out $tmp/x.csv --seed -1" \
            "stats $tmp/a.csv --time-unit h" "stats $tmp/a.csv --units mm" "stats $tmp/a.csv --velocity 0" \
            "record --from tobii --out $tmp/r.csv" "record --from pupil:host:0 --out $tmp/r.csv" "synth" "stats"; do
  err=$("$FOVEATE" gaze $args 2>&1); rc=$?
  check "bad arguments '$args' fail with a message" '[[ $rc -ne 0 && -n "$err" ]]'
done
port=$(python3 -c "import socket; s=socket.socket(); s.bind(('127.0.0.1',0)); print(s.getsockname()[1]); s.close()")
err=$(timeout 20 "$FOVEATE" gaze record --from "pupil:127.0.0.1:$port" --out "$tmp/r.csv" --connect-timeout 0.5 2>&1); rc=$?
check "record without a tracker: a clear error in bounded time" '[[ $rc -eq 1 && "$err" == *"cannot reach Pupil Capture"* && ! -e "$tmp/r.csv" ]]'

for sub in stats record synth; do
  h=$("$FOVEATE" gaze $sub --help)
  check "gaze $sub --help" '[[ $? -eq 0 && "$h" == *Usage* ]]'
done
check "stats help names the formats" '[[ $("$FOVEATE" gaze stats --help) == *gaze_positions.csv* ]]'
ls "$tmp" | grep -q tmp- && { echo "FAIL: temporary files left"; fail=1; }
exit $fail
