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
ok = check["errors"] == 0 and check["broken"] == 0 and check["images"] >= 8 and check["charts"] >= 3 and check["bars"] >= 5
print("ok: report loads, images decode, charts draw" if ok else "FAIL: report self-check")
# Every chart has tick labels on its axes and data elements (checked in the DOM
# by the page's own script, and here in the markup).
good = check["bare"] == [] and check["whiskers"] >= 4 and check["overlays"] >= 4 and check["colourbars"] == 2
print(("ok: " if good else "FAIL: ") + "every chart has ticks and data, speedup whiskers, overlays on frames, colour bars")
ok = ok and good
charts = re.findall(r'<div class="?chart"? id="([^"]+)">(.*?)</div>', dom, re.S)
for cid, svg in charts:
    ticks = len(re.findall(r'class="tick"', svg))
    data = len(re.findall(r'class="(?:bar|point|box)"', svg))
    if ticks < 2 or data < 1:
        print(f"FAIL: chart {cid}: {ticks} tick labels, {data} data elements"); ok = False
# Offline: nothing is fetched from elsewhere; no raw JSON dumped in the page.
external = re.findall(r'(?:src|href)="(?!data:|#)[^"]*"', dom)
if external:
    print("FAIL: the report refers to outside resources:", external[:3]); ok = False
if 'id="raw"' in dom or '"schema": "foveate-bench/1"' in dom:
    print("FAIL: raw JSON in the page"); ok = False
if "data:image/jpeg" not in dom:
    print("FAIL: full frames should be JPEG"); ok = False
if "Not measured" not in dom:  # the --no-metrics fallback has no quality sections
    # The error against eccentricity, the temporal table, and periphery crops
    # placed where the error is largest, at least 10 degrees from the gaze.
    places = re.findall(r"in the periphery at \(\d+, \d+\), ([0-9.]+)(?:&deg;|\u00b0)", dom)
    degrees = [float(p) for p in places]
    wanted = ["chart-speed", "chart-frame-times", "chart-pareto", "chart-quality", "chart-acuity",
              "chart-jnd", "chart-flip", "chart-eccentricity", "chart-band-ssim", "chart-band-flip"]
    have = [c for c, _ in charts]
    missing = [w for w in wanted if w not in have]
    if missing:
        print("FAIL: charts missing:", missing); ok = False
    # SSIM's axis spans the data: its first tick is not 0.
    ssim = dict(charts).get("chart-quality", "")
    first = re.search(r'class="tick"[^>]*>([^<]+)<', ssim)
    if not first or float(first.group(1)) <= 0:
        print("FAIL: the SSIM axis starts at", first.group(1) if first else None); ok = False
    # Pareto front marked on the scatter.
    if 'class="pareto"' not in dict(charts).get("chart-pareto", ""):
        print("FAIL: no Pareto front"); ok = False
    good = ('id="chart-eccentricity"' in dom and 'id="flicker"' in dom and len(degrees) >= 4
            and all(d >= 10 for d in degrees))
    print(("ok: " if good else "FAIL: ") + "eccentricity chart, temporal table, periphery crops at "
          + str(degrees) + " degrees")
    ok = ok and good
sys.exit(0 if ok else 1)
PY
[[ $? == 0 ]] || exit 1
# A sweep: its speed curve joins the points sorted by the swept value, with a
# marker on each, and the quality-against-speed scatter marks the Pareto front.
"$FOVEATE" bench --scene cheap --size 96x54 --frames 1 --warmup 0 --techniques layered \
  --sweep slope=0.015:0.035:0.01 --quiet --out "$tmp/s" > /dev/null || { echo "FAIL: sweep bench"; exit 1; }
python3 - "$tmp/s/report.html" <<'PY'
import re, sys
page = open(sys.argv[1], encoding="utf-8").read()
charts = dict(re.findall(r'<div class="?chart"? id="([^"]+)">(.*?)</div>', page, re.S))
speed, quality = charts.get("chart-sweep-speed", ""), charts.get("chart-sweep-quality", "")
pts = re.search(r'<polyline class="line"[^>]*points="([^"]*)"', speed)
xs = [float(p.split(",")[0]) for p in pts.group(1).split()] if pts else []
ok = len(xs) == 3 and xs == sorted(xs) and speed.count('class="point"') == 3
ok = ok and 'class="pareto"' in quality and quality.count('class="point"') == 3
print(("ok: " if ok else "FAIL: ") + f"sweep line sorted by x with markers {xs}, Pareto front on the scatter")
sys.exit(0 if ok else 1)
PY
