#!/usr/bin/env bash
# Command-line behaviour of `foveate plan`: output, JSON fields, files and errors.
set -u
fail=0
check() { if ! eval "$2"; then echo "FAIL: $1"; fail=1; else echo "ok: $1"; fi; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

out=$("$FOVEATE" plan --quality A --margin 1)  # the paper's plan
check "table shows the paper's geometry" '[[ "$out" == *"e* (half field of view) = 23.37"* && "$out" == *"0.0516"* ]]'
check "table shows the half-rate ratio 13.3" '[[ "$out" == *"half rate = 13.3"* ]]'

json=$("$FOVEATE" plan --quality B --json --margin 1)
json2=$("$FOVEATE" plan --json --margin 2)
check "json: acuity is the model judged by, planned_acuity the margin's" 'python3 -c "import json,sys; j=json.loads(sys.argv[1]); assert j[\"margin\"]==2 and abs(j[\"acuity\"][\"slope\"]-0.0275)<1e-9 and abs(j[\"planned_acuity\"][\"slope\"]-0.01375)<1e-9 and abs(j[\"planned_acuity\"][\"w0_deg\"]*2-j[\"acuity\"][\"w0_deg\"])<1e-12" "$json2"'
check "json has layers and ratios" 'python3 -c "import json,sys; j=json.loads(sys.argv[1]); assert len(j[\"layers\"])==3; assert abs(j[\"pixel_ratio_half_rate\"]-9.8)<0.5; assert abs(j[\"display\"][\"half_fov_deg\"]-23.4)<0.05; [l[k] for l in j[\"layers\"] for k in (\"radius_deg\",\"sampling_factor\",\"width_px\",\"height_px\",\"pixels\")]" "$json"'

"$FOVEATE" plan --sweep "$tmp/sweep.csv" >/dev/null
check "sweep csv written" '[[ $(head -1 "$tmp/sweep.csv") == fov_deg,* && $(wc -l < "$tmp/sweep.csv") -eq 24 ]]'
"$FOVEATE" plan --sweep "$tmp/sweep.svg" >/dev/null
check "sweep svg written" 'grep -q "<polyline" "$tmp/sweep.svg"'

echo '{"width_px": 1920, "height_px": 1080, "width_mm": 510, "distance_mm": -1}' > "$tmp/bad.json"
err=$("$FOVEATE" plan --display "$tmp/bad.json" 2>&1); rc=$?
check "bad display file: non-zero exit" '[[ $rc -ne 0 ]]'
check "bad display file: names file and field" '[[ "$err" == *bad.json* && "$err" == *distance_mm* ]]'
echo '{"width_px": 1920,' > "$tmp/trunc.json"
err=$("$FOVEATE" plan --display "$tmp/trunc.json" 2>&1); rc=$?
check "truncated display file is an error" '[[ $rc -ne 0 && "$err" == *"invalid JSON"* ]]'

for args in "--layers 0" "--layers 9" "--slope -1" "--slope abc" "--quality Z" "--quality A --slope 0.02" "--gaze 12" "--size 0x10" "--sweep out.txt" "--display nope"; do
  err=$("$FOVEATE" plan $args 2>&1); rc=$?
  check "bad value '$args' fails with a message" '[[ $rc -ne 0 && -n "$err" ]]'
done
check "version" '[[ $("$FOVEATE" --version) == foveate* ]]'
"$FOVEATE" plan --help | grep -q -- --sweep
check "help lists options" '[[ $? -eq 0 ]]'
[[ ! -e "$tmp/sweep.csv.tmp"* ]]
exit $fail
