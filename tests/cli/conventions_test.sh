#!/usr/bin/env bash
# CLI conventions (issue 14): one default size and technique list, a note when
# the display leaves nothing to save, --json / --quiet / --verbose everywhere,
# progress off a terminal, numbers for people, refused gazes and silent eye
# trackers, paths and help text that match behaviour. Small sizes only.
set -u
fail=0
check() { if ! eval "$2"; then echo "FAIL: $1"; fail=1; else echo "ok: $1"; fi; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
json_ok() { python3 -c 'import json,sys; json.load(open(sys.argv[1]))' "$1"; }

# --- One default size for every command that renders or derives defaults.
for cmd in render bench demo view techniques plan; do
  "$FOVEATE" $cmd --help > "$tmp/help.txt"
  check "$cmd --size defaults to 1920x1080" 'grep -Eq -- "--size.*1920x1080" "$tmp/help.txt"'
done
"$FOVEATE" techniques > "$tmp/tech.txt"
check "techniques derives for 1920x1080 by default" 'grep -q "desktop-1080p at 1920x1080" "$tmp/tech.txt"'
"$FOVEATE" plan --margin 1 > "$tmp/plan.txt"
check "plan plans 1920x1080 by default" 'grep -q "1920x1080" "$tmp/plan.txt" && grep -q "pixel ratio P\*/P = 8.49x" "$tmp/plan.txt"'

# --- A warm-up longer than asked is said, with the frames measured.
"$FOVEATE" bench --scene cheap --size 320x180 --techniques native,layered --frames 2 --warmup 0 --no-metrics --out "$tmp/wu" > /dev/null 2> "$tmp/wu.txt"
check "bench says it warmed up longer than asked, and why" \
  'grep -q "warm-up of 3 frames, not the 0 asked (--warmup): layered needs 3 to settle" "$tmp/wu.txt" && grep -q "frames 3-4 are measured" "$tmp/wu.txt"'
"$FOVEATE" bench --scene cheap --size 320x180 --techniques native,vrs --frames 2 --warmup 2 --no-metrics --out "$tmp/wu2" > /dev/null 2> "$tmp/wu.txt"
check "no such note when the warm-up asked is long enough" '! grep -q "warm-up of" "$tmp/wu.txt"'

# --- Nothing to save: said once on stderr, with the figure and a size to try.
"$FOVEATE" plan --size 320x180 > /dev/null 2> "$tmp/note.txt"
check "plan at 320x180 notes the 1.00x bound and suggests a size" \
  'grep -q "pixel bound is 1.00x" "$tmp/note.txt" && grep -q "try --size 1280x720" "$tmp/note.txt" && grep -q "6.5 pixels per degree" "$tmp/note.txt"'
"$FOVEATE" render --scene cheap --size 64x36 --technique layered --frames 3 --out "$tmp/r" > /dev/null 2> "$tmp/note.txt"
check "render says it once" '[[ $(grep -c "nothing to save" "$tmp/note.txt") == 1 ]]'
# The note is for the plans of the techniques run: at 640x360 vrs's (margin 1,
# bound 1.78x) has something to save, layered's (1.5, 1.15x) little, and a
# margin given as a parameter is the one named.
"$FOVEATE" render --scene cheap --size 640x360 --technique vrs --no-write > /dev/null 2> "$tmp/note.txt"
check "no note for vrs's plan at 640x360" '! grep -q "nothing to save" "$tmp/note.txt"'
"$FOVEATE" render --scene cheap --size 640x360 --technique layered --no-write > /dev/null 2> "$tmp/note.txt"
check "a note for layered's plan at 640x360, at its margin" 'grep -q "pixel bound is 1.15x at planning margin 1.5" "$tmp/note.txt"'
"$FOVEATE" render --scene cheap --size 640x360 --technique vrs --param vrs.margin=3 --no-write > /dev/null 2> "$tmp/note.txt"
check "a note at the margin a parameter sets" 'grep -q "pixel bound is 1.00x at planning margin 3" "$tmp/note.txt"'
"$FOVEATE" bench --scene cheap --size 640x360 --techniques native,vrs,layered --frames 1 --warmup 0 --no-metrics --out "$tmp/sv" > /dev/null 2> "$tmp/note.txt"
check "bench notes, and records, the finest plan of its runs" \
  'grep -q "planning margin 1.5" "$tmp/note.txt" && grep -q "\"margin\": 1.5" "$tmp/sv/results.json"'
"$FOVEATE" plan --size 1280x720 > /dev/null 2> "$tmp/note.txt"
check "no note where there is something to save" '! grep -q "nothing to save" "$tmp/note.txt"'
"$FOVEATE" plan --size 320x180 --quiet > /dev/null 2> "$tmp/note.txt"
check "--quiet silences the note" '[[ ! -s "$tmp/note.txt" ]]'

# --- One default technique list, the registry's: every technique the scene can
# run (lodmask skipped with a note on a scene without meshes).
"$FOVEATE" techniques --json > "$tmp/registered.json"
"$FOVEATE" bench --scene cheap --size 64x36 --frames 1 --warmup 0 --no-metrics --json --out "$tmp/b" > "$tmp/b.json" 2> "$tmp/b.err"
check "bench --json prints results.json" 'json_ok "$tmp/b.json" && cmp -s <(python3 -c "import json,sys;print(json.load(open(sys.argv[1])))" "$tmp/b.json") <(python3 -c "import json,sys;print(json.load(open(sys.argv[1])))" "$tmp/b/results.json")'
check "the default list skips lodmask on cheap, with a note" \
  'grep -q "skipping lodmask" "$tmp/b.err" && python3 -c "
import json,sys; j=json.load(open(sys.argv[1])); t=[r[\"technique\"] for r in j[\"results\"]]
every=[x[\"name\"] for x in json.load(open(sys.argv[2]))[\"techniques\"]]
sys.exit(0 if t==[n for n in every if n!=\"lodmask\"] and len(t)>=6 and \"lodmask\" in j[\"skipped\"][0] else 1)" "$tmp/b.json" "$tmp/registered.json"'
check "results.json records the full command line" \
  'python3 -c "import json,sys; c=json.load(open(sys.argv[1]))[\"command\"]; sys.exit(0 if \"--size 64x36\" in c and \"--frames 1\" in c and \"--json\" in c else 1)" "$tmp/b.json"'
"$FOVEATE" bench --scene cheap --size 64x36 --frames 1 --warmup 0 --no-metrics --techniques lodmask --out "$tmp/b2" > /dev/null 2> "$tmp/err.txt"; rc=$?
check "lodmask asked for by name on cheap is still refused (exit 1)" '[[ $rc == 1 ]] && grep -q "lodmask" "$tmp/err.txt"'
check "CSV numbers carry no exponent" '! grep -q "e+0" "$tmp/b/results.csv" && grep -q ",2304," "$tmp/b/results.csv"'

# --- --json on every command that prints results.
"$FOVEATE" scenes --json > "$tmp/j1" && check "scenes --json" 'json_ok "$tmp/j1" && grep -q "\"raymarch\"" "$tmp/j1"'
"$FOVEATE" techniques --json --size 640x360 > "$tmp/j2" && check "techniques --json" \
  'python3 -c "import json,sys; j=json.load(open(sys.argv[1])); sys.exit(0 if j[\"size\"]==[640,360] and len(j[\"techniques\"])>=6 else 1)" "$tmp/j2"'
"$FOVEATE" techniques --json --size 640x360 --margin 2 > "$tmp/j2m" && check "techniques --margin 2 derives finer defaults than checkerboard's own 1" \
  'python3 -c "import json,sys; a,b=(json.load(open(p)) for p in sys.argv[1:3]); r1=lambda j: [p[\"value\"] for t in j[\"techniques\"] if t[\"name\"]==\"checkerboard\" for p in t[\"parameters\"] if p[\"key\"]==\"r1\"][0]; sys.exit(0 if b[\"margin\"]==2 and a[\"margin\"] is None and r1(b)>r1(a) else 1)" "$tmp/j2" "$tmp/j2m"'
"$FOVEATE" plan --sweep "$tmp/fov.csv" --step 0.5 --json > "$tmp/j3" && check "plan --sweep --json" \
  'python3 -c "import json,sys; j=json.load(open(sys.argv[1])); sys.exit(0 if len(j[\"rows\"])==23 else 1)" "$tmp/j3" && ! grep -q "e+0" "$tmp/fov.csv"'
"$FOVEATE" render --scene cheap --size 64x36 --json --out "$tmp/r2" > "$tmp/j4" 2> /dev/null && check "render --json" 'json_ok "$tmp/j4"'
"$FOVEATE" compare "$tmp/r/frame-0000.png" "$tmp/r/frame-0001.png" --json > "$tmp/j5" && check "compare --json" 'json_ok "$tmp/j5"'
"$FOVEATE" gaze synth --seed 3 --seconds 1 --out "$tmp/t.csv" > /dev/null
"$FOVEATE" gaze stats "$tmp/t.csv" --json > "$tmp/j6" && check "gaze stats --json" 'json_ok "$tmp/j6"'

# --- --quiet and --verbose on every command.
for cmd in demo plan render scenes techniques view bench compare "gaze stats" "gaze record" "gaze synth"; do
  "$FOVEATE" $cmd --help > "$tmp/help.txt"
  check "$cmd has --quiet and --verbose" 'grep -q -- "--quiet" "$tmp/help.txt" && grep -q -- "--verbose" "$tmp/help.txt"'
done
"$FOVEATE" render --scene cheap --size 64x36 --frames 2 --verbose --out "$tmp/r3" > /dev/null 2> "$tmp/v.txt"
check "--verbose names the renderer and prints a line per frame" 'grep -q "renderer" "$tmp/v.txt" && grep -q "render: frame 1:" "$tmp/v.txt"'

# --- Progress off a terminal: plain lines; none with --quiet. (Work done
# within a second shows none unless --verbose: smaller_test.sh.)
"$FOVEATE" render --scene cheap --size 64x36 --frames 4 --verbose --out "$tmp/r4" > "$tmp/out.txt" 2> "$tmp/p.txt"
check "render --frames prints progress lines" 'grep -q "render: 2/4 frames" "$tmp/p.txt" && grep -q "render: 4/4 frames done in" "$tmp/p.txt" && ! grep -q $'"'"'\r'"'"' "$tmp/p.txt"'
check "paths printed without //" 'grep -q "to $tmp/r4/\$" "$tmp/out.txt" && ! grep -q "//" "$tmp/out.txt"'
"$FOVEATE" render --scene cheap --size 64x36 --frames 4 --quiet --overwrite --out "$tmp/r4/" > /dev/null 2> "$tmp/p.txt"
check "--quiet: no progress" '[[ ! -s "$tmp/p.txt" ]]'

if command -v script > /dev/null; then
  # On a terminal (a pseudo-terminal from util-linux's script): a bar redrawn in place.
  script -qec "\"$FOVEATE\" render --scene cheap --size 64x36 --frames 3 --verbose --out \"$tmp/r5\" > /dev/null" /dev/null > "$tmp/tty.txt" 2>&1
  check "render --frames on a terminal draws a bar" 'grep -q "render \[#" "$tmp/tty.txt" && grep -q $'"'"'\r'"'"'"render \[" "$tmp/tty.txt"'
fi

# --- Numbers for people in errors.
"$FOVEATE" render --scene cheap --size 64x36 --technique layered --param layers=9 --out "$tmp/e" > /dev/null 2> "$tmp/err.txt"; rc=$?
check "a range error prints layers=9 (exit 1)" '[[ $rc == 1 ]] && grep -q "layers=9: out of range \[1, 6\]" "$tmp/err.txt" && ! grep -q "9.0000" "$tmp/err.txt"'
"$FOVEATE" plan --slope 2 > /dev/null 2> "$tmp/err.txt"; rc=$?
check "slope error without trailing zeros" '[[ $rc == 1 ]] && grep -q "got 2$" "$tmp/err.txt"'

# --- compare refuses a gaze outside the images.
"$FOVEATE" compare "$tmp/r/frame-0000.png" "$tmp/r/frame-0001.png" --gaze 960,540 > /dev/null 2> "$tmp/err.txt"; rc=$?
check "compare --gaze outside the image: exit 1 naming --gaze and 64x36" '[[ $rc == 1 ]] && grep -q -- "--gaze" "$tmp/err.txt" && grep -q "64x36" "$tmp/err.txt"'
"$FOVEATE" compare "$tmp/r/frame-0000.png" "$tmp/r/frame-0001.png" --gaze 63,35 > /dev/null
check "compare --gaze on the last pixel is fine" '[[ $? == 0 ]]'

# --- A live gaze source that never answers is an error in bench unless --allow-fallback.
port=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1]); s.close()')
"$FOVEATE" bench --scene cheap --size 64x36 --frames 1 --warmup 0 --no-metrics --techniques layered --gaze "pupil:127.0.0.1:$port" --out "$tmp/p1" > /dev/null 2> "$tmp/err.txt"; rc=$?
check "bench --gaze pupil with nothing listening: exit 1, names --gaze and --allow-fallback" \
  '[[ $rc == 1 ]] && grep -q -- "--gaze pupil:127.0.0.1:$port: no eye tracker answered" "$tmp/err.txt" && grep -q -- "--allow-fallback" "$tmp/err.txt" && [[ ! -e "$tmp/p1/results.json" ]]'
"$FOVEATE" bench --scene cheap --size 64x36 --frames 1 --warmup 0 --no-metrics --techniques layered --gaze "pupil:127.0.0.1:$port" --allow-fallback --out "$tmp/p2" > /dev/null 2> "$tmp/err.txt"; rc=$?
check "with --allow-fallback it measures and records the fallback" \
  '[[ $rc == 0 ]] && grep -q "fallback" "$tmp/err.txt" && python3 -c "import json,sys; sys.exit(0 if json.load(open(sys.argv[1]))[\"gaze_fallback\"] else 1)" "$tmp/p2/results.json"'

# --- Help text that matches behaviour.
"$FOVEATE" render --help > "$tmp/help.txt"
check "render --gaze help lists every kind of source" 'grep -q "X,Y or fixed:X,Y" "$tmp/help.txt" && grep -q "synthetic" "$tmp/help.txt" && grep -q "pupil" "$tmp/help.txt" && grep -q "off by default" "$tmp/help.txt"'
"$FOVEATE" view --help > "$tmp/help.txt"
check "view --overlay help says it is on by default" 'grep -q "on by default, --no-overlay" "$tmp/help.txt"'
exit $fail
