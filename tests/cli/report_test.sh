#!/usr/bin/env bash
# The HTML reports opened offline in headless Chromium: a tiny benchmark's
# report.html, `foveate report` combining benchmarks and shards into one
# page, and `plan --sweep`'s SVG. Each page loads without console messages or
# script errors, every image decodes, and every chart has a title, axis
# titles, tick labels clear of the axis title, data, full width and an SVG
# download; the charts are also SVG files beside the page. Skipped (77) where
# Chromium is not installed.
set -u
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
browser=$(command -v chromium || command -v chromium-browser || true)
if [[ -z "$browser" ]]; then echo "SKIP: chromium is missing (apt-get install chromium)"; exit 77; fi
fail=0
# render PAGE NAME: the DOM after load in $tmp/NAME.html, the browser's log in $tmp/NAME.log.
render() {
  timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync \
    --user-data-dir="$tmp/profile-$2" --window-size=1400,1000 --enable-logging=stderr --v=0 \
    --virtual-time-budget=5000 --dump-dom "file://$1" > "$tmp/$2.html" 2> "$tmp/$2.log"
}
# A page's console: the report logs nothing, so any console line is a failure.
no_console() {
  if grep -q "CONSOLE" "$tmp/$1.log"; then
    echo "FAIL: console messages in $1: $(grep CONSOLE "$tmp/$1.log" | head -3)"; fail=1
  else
    echo "ok: no console messages in $1"
  fi
}

bench() {
  "$FOVEATE" bench --size 96x54 --frames 2 --warmup 1 --quiet "$@" > /dev/null 2> "$tmp/err.txt" || {
    echo "FAIL: bench $*: $(cat "$tmp/err.txt")"; exit 1; }
}
bench --scene cheap --passes --out "$tmp/b"
render "$tmp/b/report.html" b
no_console b
python3 - "$tmp/b.html" "$tmp/b" <<'PY' || fail=1
import html, json, os, re, sys
import xml.etree.ElementTree as ET
dom, folder = open(sys.argv[1], encoding="utf-8").read(), sys.argv[2]
m = re.search(r'data-selfcheck="([^"]*)"', dom)
if not m:
    print("FAIL: the report's self-check did not run (no data-selfcheck on <body>)"); sys.exit(1)
check = json.loads(html.unescape(m.group(1)))
print("report self-check:", check)
ok = True
def expect(cond, what):
    global ok
    print(("ok: " if cond else "FAIL: ") + what)
    ok = ok and cond
expect(check["errors"] == 0 and check["broken"] == 0 and check["images"] >= 8,
       "no script errors, every image decodes")
expect(check["charts"] >= 8 and check["bare"] == [],
       "every chart has a title, an axis title, tick labels and data")
expect(check["overlaps"] == [], "no tick label runs into its axis title: %s" % check["overlaps"])
expect(check["narrow"] == [], "every chart spans the page's width: %s" % check["narrow"])
expect(check["downloads"] == check["charts"], "every chart has an SVG download")
expect(check["whiskers"] >= 4 and check["overlays"] >= 4 and check["colourbars"] == 2,
       "speedup whiskers, overlays on frames, colour bars")
expect(check["overlay_legends"] >= 4, "the overlays' legends are in the page")
charts = dict(re.findall(r'<div class="chart" id="([^"]+)">(.*?)</div>', dom, re.S))
for want in ["chart-speed", "chart-frame-times", "chart-timeline", "chart-passes", "chart-pareto",
             "chart-quality", "chart-acuity", "chart-jnd", "chart-eccentricity", "chart-band-ssim"]:
    expect(want in charts, "chart " + want)
# The per-pass stacked chart: a bar per pass of each run and its legend; the
# timeline: one line per run with a point per measured frame.
passes = charts.get("chart-passes", "")
expect(passes.count('class="bar"') >= 4 and 'class="legend"' in passes, "passes stacked with a legend")
timeline = charts.get("chart-timeline", "")
expect(timeline.count('class="line"') >= 3 and timeline.count('class="point"') >= 6,
       "a timeline line per technique, a point per frame")
# One colour per technique, the palette's: layered blue, native grey, in every chart.
def bar_fill(svg, row):
    f = re.search(r'fill="(#[0-9a-f]{6})"[^>]*><title>' + re.escape(row) + ',', svg)
    return f.group(1) if f else None
speed = charts.get("chart-speed", "")
expect(bar_fill(speed, "layered") == "#0072b2" and bar_fill(speed, "native") == "#555555",
       "layered blue and native grey in the speed chart")
expect('stroke="#0072b2"' in timeline, "layered blue in the timeline")
# Lossless images; nothing fetched from elsewhere.
expect("data:image/jpeg" not in dom and "data:image/png" in dom, "images are PNG, none JPEG")
external = re.findall(r'(?:src|href)="(?!data:|#|blob:)[^"]*"', dom)
expect(not external, "no outside resources: %s" % external[:3])
# Numbers for people: no raw doubles or printf exponents in the text.
text = re.sub(r"<[^>]*>", " ", re.sub(r"<(script|style)[^>]*>.*?</\1>", " ", dom, flags=re.S))
raw = re.findall(r"\d\.\d{6,}|\d[eE][-+]\d\d", text)
expect(not raw, "no raw numbers in the page: %s" % raw[:5])
# Each chart also as a file beside the page: well-formed SVG with its parts.
ns = "{http://www.w3.org/2000/svg}"
for cid in charts:
    path = os.path.join(folder, cid + ".svg")
    if not os.path.exists(path):
        expect(False, path + " written"); continue
    root = ET.parse(path).getroot()
    classes = [e.get("class") for e in root.iter()]
    good = root.tag == ns + "svg" and "title" in classes and "axis-label" in classes and classes.count("tick") >= 2
    if not good: expect(False, path + ": an SVG with a title, an axis title and ticks")
expect(True, "%d chart files beside the page" % len(charts))
sys.exit(0 if ok else 1)
PY

# A sweep: its speed curve joins the points sorted by the swept value, with a
# marker on each, and the quality-against-speed scatter marks the Pareto front.
"$FOVEATE" bench --scene cheap --size 96x54 --frames 1 --warmup 0 --techniques layered \
  --sweep slope=0.015:0.035:0.01 --quiet --out "$tmp/s" > /dev/null || { echo "FAIL: sweep bench"; exit 1; }
python3 - "$tmp/s/report.html" <<'PY' || fail=1
import re, sys
page = open(sys.argv[1], encoding="utf-8").read()
charts = dict(re.findall(r'<div class="chart" id="([^"]+)">(.*?)</div>', page, re.S))
speed, quality = charts.get("chart-sweep-speed", ""), charts.get("chart-sweep-quality", "")
pts = re.search(r'<polyline class="line"[^>]*points="([^"]*)"', speed)
xs = [float(p.split(",")[0]) for p in pts.group(1).split()] if pts else []
ok = len(xs) == 3 and xs == sorted(xs) and speed.count('class="point"') == 3
ok = ok and 'class="pareto"' in quality and quality.count('class="point"') == 3
# The swept runs are shades of layered's blue, each its own.
fills = re.findall(r'<circle class="point"[^>]*fill="(#[0-9a-f]{6})"', quality)
ok = ok and len(set(fills)) == 3 and "#0072b2" in fills
print(("ok: " if ok else "FAIL: ") + f"sweep line sorted by x with markers {xs}, Pareto front, shades {fills}")
sys.exit(0 if ok else 1)
PY

# foveate report: two benchmarks of different scenes and the two shards of a
# third on one page, the shards merged into one benchmark.
bench --scene cheap --techniques layered --out "$tmp/c1"
bench --scene raymarch --techniques logpolar --no-metrics --out "$tmp/c2"
bench --scene cheap --techniques layered,logpolar --no-metrics --shard 1/2 --out "$tmp/k1"
bench --scene cheap --techniques layered,logpolar --no-metrics --shard 2/2 --out "$tmp/k2"
"$FOVEATE" report "$tmp/c1" "$tmp/c2/results.json" "$tmp/k1" "$tmp/k2" --out "$tmp/all" \
  > /dev/null 2> "$tmp/report.err" || { echo "FAIL: foveate report: $(cat "$tmp/report.err")"; fail=1; }
grep -q "3 benchmarks" "$tmp/report.err" && echo "ok: report says what it wrote" || { echo "FAIL: report's message: $(cat "$tmp/report.err")"; fail=1; }
render "$tmp/all/report.html" all
no_console all
python3 - "$tmp/all.html" "$tmp/all" <<'PY' || fail=1
import html, json, os, re, sys
dom, folder = open(sys.argv[1], encoding="utf-8").read(), sys.argv[2]
m = re.search(r'data-selfcheck="([^"]*)"', dom)
check = json.loads(html.unescape(m.group(1))) if m else {}
print("combined self-check:", check)
ok = bool(check) and check["errors"] == 0 and check["broken"] == 0 and check["bare"] == [] \
    and check["overlaps"] == [] and check["downloads"] == check["charts"]
print(("ok: " if ok else "FAIL: ") + "combined page loads, every chart drawn with its parts")
ids = re.findall(r'\sid="([^"]+)"', dom)
dups = sorted({i for i in ids if ids.count(i) > 1})
sections = re.findall(r'<section class="run" id="(r\d)"', dom)
summary = re.search(r'<table id="summary">(.*?)</table>', dom, re.S)
rows = [[re.sub(r"<[^>]*>", "", c).strip() for c in r.split("</td>")]
        for r in summary.group(1).split("<tr>")[2:]] if summary else []
# (benchmark, scene, technique) of each row: both shards' runs under the third.
have = {(r[0].split()[0], r[1], r[3]) for r in rows if len(r) >= 4}
want = {("1", "cheap", "layered"), ("2", "raymarch", "logpolar"), ("3", "cheap", "layered"),
        ("3", "cheap", "logpolar")}
good = not dups and sections == ["r1", "r2", "r3"] and want <= have
good = good and "k1/results.json and 1 other shard" in dom and "not kept in results.json" in dom
good = good and os.path.exists(os.path.join(folder, "chart-all-speed.svg")) \
    and os.path.exists(os.path.join(folder, "r2-chart-speed.svg"))
print(("ok: " if good else "FAIL: ") + f"3 sections {sections}, rows {sorted(have)}, shards merged, ids unique {dups[:3]}, charts beside it")
sys.exit(0 if ok and good else 1)
PY
err=$("$FOVEATE" report "$tmp/nowhere" --out "$tmp/x" 2>&1) && { echo "FAIL: a missing input was accepted"; fail=1; }
[[ "$err" == *nowhere* ]] && echo "ok: a missing input is named" || { echo "FAIL: error without the input: $err"; fail=1; }

# plan --sweep's figure: its y tick labels clear of the y axis title in a browser.
"$FOVEATE" plan --sweep "$tmp/sweep.svg" > /dev/null 2>&1 || { echo "FAIL: plan --sweep"; fail=1; }
{
  echo '<!DOCTYPE html><html><body><div class="chart" id="sweep">'
  cat "$tmp/sweep.svg"
  cat <<'HTML'
</div><script>
window.addEventListener('load', function () {
  var bad = [];
  document.querySelectorAll('svg svg').forEach(function (c, i) {
    var title = c.querySelector('text.axis-label[transform]');
    c.querySelectorAll('text.tick[text-anchor="end"]').forEach(function (t) {
      var r = t.getBoundingClientRect();
      if (r.left < 0 || r.left < title.getBoundingClientRect().right) bad.push(i + ':' + t.textContent);
    });
  });
  document.body.setAttribute('data-overlaps', JSON.stringify(bad));
});
</script></body></html>
HTML
} > "$tmp/sweep-page.html"
render "$tmp/sweep-page.html" sweep
if grep -q 'data-overlaps="\[\]"' "$tmp/sweep.html"; then
  echo "ok: plan --sweep's y tick labels clear of the axis title"
else
  echo "FAIL: plan --sweep's y labels overlap: $(grep -o 'data-overlaps="[^"]*"' "$tmp/sweep.html")"; fail=1
fi
exit $fail
