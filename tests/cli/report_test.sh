#!/usr/bin/env bash
# The HTML report of a tiny benchmark, opened offline in headless Chromium:
# it loads without script errors, every image decodes and the charts draw.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
browser=$(command -v chromium || command -v chromium-browser || true)
if [[ -z "$browser" ]]; then echo "FAIL: chromium is missing (scripts/setup.sh installs it)"; exit 1; fi
"$FOVEATE" bench --scene cheap --size 96x54 --frames 2 --warmup 1 --quiet --out "$tmp/b" > /dev/null 2> "$tmp/err.txt" || {
  # Without the metrics module the report is still produced with --no-metrics.
  "$FOVEATE" bench --scene cheap --size 96x54 --frames 2 --warmup 1 --quiet --no-metrics --out "$tmp/b" > /dev/null || exit 1
}
timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
  --disable-background-networking --disable-component-update --disable-sync --user-data-dir="$tmp/profile" \
  --virtual-time-budget=5000 --dump-dom "file://$tmp/b/report.html" > "$tmp/dom.html" 2> "$tmp/chromium.log"
python3 - "$tmp/dom.html" <<'PY'
import html, json, re, sys
dom = open(sys.argv[1], encoding="utf-8").read()
m = re.search(r'data-selfcheck="([^"]*)"', dom)
if not m:
    print("FAIL: the report's self-check did not run (no data-selfcheck on <body>)"); sys.exit(1)
check = json.loads(html.unescape(m.group(1)))
print("report self-check:", check)
ok = check["errors"] == 0 and check["broken"] == 0 and check["images"] >= 8 and check["charts"] >= 1 and check["bars"] >= 5
print("ok: report loads, images decode, charts draw" if ok else "FAIL: report self-check")
if "Not measured" not in dom:  # the --no-metrics fallback has no quality sections
    # The error against eccentricity, the temporal table, and periphery crops
    # placed where the error is largest, at least 10 degrees from the gaze.
    places = re.findall(r"in the periphery at \(\d+, \d+\), ([0-9.]+)(?:&deg;|\u00b0)", dom)
    degrees = [float(p) for p in places]
    good = ('id="chart-eccentricity"' in dom and 'id="flicker"' in dom and len(degrees) >= 4
            and all(d >= 10 for d in degrees))
    print(("ok: " if good else "FAIL: ") + "eccentricity chart, temporal table, periphery crops at "
          + str(degrees) + " degrees")
    ok = ok and good
sys.exit(0 if ok else 1)
PY
