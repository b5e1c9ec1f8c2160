// The benchmark's single-file HTML report: every chart full width with a
// title, axes, ticks, units and a legend, each downloadable as SVG (and
// written as one beside the page); images as PNG; numbers with a few
// significant digits; opens offline.
#include <algorithm>
#include <cctype>
#include <sstream>

#include "foveate/bench/report.hpp"
#include "foveate/bench/svg_plot.hpp"
#include "report_common.hpp"
#include "report_media.hpp"

namespace foveate::bench {

namespace {

std::string escape_html(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

// Charts fill the page's width (their viewBox keeps their proportions);
// images keep their pixels (crops are shown enlarged).
constexpr const char* kStyle =
    "<style>body{font-family:sans-serif;margin:24px;max-width:1400px;color:#222}"
    "table{border-collapse:collapse;margin:12px 0}td,th{border:1px solid #ccc;padding:4px "
    "8px;text-align:right}th{background:#f0f0f0}td:first-child{text-align:left;white-space:nowrap}"
    ".crops{display:flex;flex-wrap:wrap;gap:16px}.crops figure{margin:0}"
    ".crops img{image-rendering:pixelated;border:1px solid #999}"
    "figcaption{font-size:12px;color:#555}.note{color:#555;font-size:13px}.warn{color:#a00}"
    ".chart{margin:12px 0 20px;width:100%}.chart>svg{display:block;width:100%;height:auto}"
    ".chart a.download{font-size:12px;color:#555}"
    ".swatch{display:inline-block;width:12px;height:12px;margin-right:6px;vertical-align:-1px}"
    "ul.legend{list-style:none;padding:0;margin:4px 0;font-size:12px;color:#333}"
    "ul.legend li{display:inline-block;margin-right:12px}"
    "ul.legend svg{vertical-align:-1px;margin-right:4px}"
    "section.run{border-top:2px solid #ccc;margin-top:32px}</style>\n";

// A run's colour beside its name in a table or caption.
std::string swatch(const std::string& colour) {
  return "<span class=\"swatch\" style=\"background:" + colour + "\"></span>";
}

std::string page_head(const std::string& title) {
  return "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" +
         escape_html(title) + "</title>\n" + kStyle + "</head><body>\n";
}

// What was run, where and how: the settings, the command and the machine.
std::string run_intro(const BenchResult& b) {
  std::ostringstream h;
  const PixelSize size = b.options.session.size;
  const RunEnvironment& env = b.environment;
  h << "<p class=note>" << size.width << "&times;" << size.height << " on " << b.display.name
    << " geometry (field of view kept), renderer " << b.renderer << ", MAR slope "
    << cell(b.options.session.acuity.slope, 3) << " deg/deg, gaze "
    << (b.options.session.gaze.empty() ? "centre" : b.options.session.gaze) << ", "
    << b.options.frames << " measured frames after " << b.warmup
    << " warm-up, techniques interleaved frame by frame in an order shuffled every frame. Speedup "
       "is the ratio of mean frame times (95 % bootstrap interval); the pixel bound is native "
       "pixels / shaded pixels.</p>\n"
    << "<p class=note>Command: <code>" << escape_html(env.command) << "</code>; foveate "
    << escape_html(env.version) << ", " << escape_html(env.date_utc) << ", CPU "
    << escape_html(env.cpu_model) << " (" << env.cores << " cores), load "
    << cell(env.load_start[0], 2) << " (1 min) at the start, " << cell(env.load_end[0], 2)
    << " at the end"
    << (env.others_cpu_share >= 0
            ? "; other processes used " + format_percent(env.others_cpu_share, 2) +
                  " of the CPU during it"
            : std::string())
    << (env.pass_by_pass
            ? "; every measured frame ran pass by pass (glFinish around each pass), as a "
              "software renderer's pipelined frames depend on the technique before "
              "them"
            : "")
    << (env.timed_apart
            ? "; the frames were timed in a pass that read nothing back, then rendered again "
              "from the start to be judged"
            : "")
    << ".</p>\n";
  if (auto busy = busy_machine(env)) {
    busy->front() = static_cast<char>(std::toupper(static_cast<unsigned char>(busy->front())));
    h << "<p class=warn>" << escape_html(*busy) << ".</p>\n";
  }
  for (const auto& [name, value] : env.variables)
    h << "<p class=note>Run with " << escape_html(name) << "=" << escape_html(value) << ".</p>\n";
  for (const std::string& s : b.skipped)
    h << "<p class=note>Left out of the default list: " << escape_html(s) << ".</p>\n";
  if (b.gaze_fallback)
    h << "<p class=warn>The live gaze source never answered: every frame used the fallback gaze "
         "(allowed for this run).</p>\n";
  for (const std::string& n : mark_notes(b)) h << "<p class=warn>" << escape_html(n) << "</p>\n";
  return h.str();
}

std::string html_results_table(const BenchResult& b) {
  std::ostringstream h;
  // FovVideoVDP first: a speedup counts at the quality it keeps.
  h << "<p class=note>JOD: FovVideoVDP (Mantiuk et al. 2021), foveated at each frame's gaze, "
       "against the "
    << (b.options.reference > 1 ? "supersampled reference" : "native frames")
    << "; 10 = no visible difference, one JOD apart = 75 % of observers prefer the higher. "
       "'Below native' is native's JOD minus the technique's.</p>\n";
  h << "<table id=\"results\"><tr><th>technique</th><th>JOD</th><th>below native (JOD)</th>"
       "<th>speedup</th><th>95 % CI</th><th>mean</th><th>median</th><th>p90</th>"
       "<th>shaded px</th><th>pixel ratio</th><th>share of bound</th>";
  for (const QualityColumn& c : kQualityColumns) h << "<th>" << c.title << "</th>";
  h << "</tr>\n";
  for (const TechniqueResult& r : b.results) {
    h << "<tr><td>" << swatch(run_colour(b, r)) << escape_html(label(b, r)) << "</td><td>"
      << cell(jod_of(r), 4) << "</td><td>" << cell(jod_below_native(b, r), 2) << "</td><td>"
      << cell(r.speedup) << "x</td><td>" << cell(r.speedup_lo) << "&ndash;" << cell(r.speedup_hi)
      << "x</td><td>" << format_quantity(r.mean_ms, "ms") << "</td><td>"
      << format_quantity(r.median_ms, "ms") << "</td><td>" << format_quantity(r.p90_ms, "ms")
      << "</td><td>" << format_fixed(r.shaded_pixels, 0) << "</td><td>" << cell(r.pixel_ratio)
      << "</td><td>" << format_percent(r.bound_share, 2) << "</td>";
    for (const QualityColumn& c : kQualityColumns)
      h << "<td>" << cell(quality_value(r, c), 4) << "</td>";
    h << "</tr>\n";
  }
  h << "</table>\n";
  return h.str();
}

std::string html_passes_table(const BenchResult& b) {
  if (!b.options.passes) return {};
  std::ostringstream h;
  h << "<h2>Where the time goes</h2>\n<p class=note>Mean ms per frame of each pass (share of "
       "the frame); "
    << (b.renderer.find("llvmpipe") != std::string::npos ? "each pass bracketed with glFinish"
                                                         : "GPU timestamp queries")
    << ". Resolve = composite, reconstruction, temporal, warps, blurs, upscales and copies.</p>\n"
    << "<table id=\"passes\"><tr><th>technique</th><th>passes</th><th>resolve share</th></tr>\n";
  for (const TechniqueResult& r : b.results) {
    h << "<tr><td>" << swatch(run_colour(b, r)) << escape_html(label(b, r))
      << "</td><td style=\"text-align:left\">";
    for (size_t i = 0; i < r.passes.size(); ++i) {
      const gpu::PassTime& p = r.passes[i];
      h << (i ? ", " : "") << escape_html(p.name) << ' ' << format_quantity(p.ms, "ms", 2) << " ("
        << format_percent(p.ms / r.mean_ms, 2) << ")";
    }
    h << "</td><td>" << format_percent(resolve_ms(r) / r.mean_ms, 2) << "</td></tr>\n";
  }
  h << "</table>\n";
  return h.str();
}

// The layers or regions of each technique over its last frame.
std::string html_overlays(const BenchResult& b) {
  std::ostringstream h;
  h << "<h2>Layers and regions</h2>\n<p class=note>Each technique's last measured frame with "
       "its layer or region borders and the gaze, as its overlay draws them; below each, what "
       "each colour and shape marks.</p>\n<div class=crops>";
  const int width = b.options.session.size.width;
  for (const TechniqueResult& r : b.results) {
    if (r.technique == "native" || r.overlay.empty()) continue;
    h << "<figure>"
      << overlay_figure(r.sample, r.overlay, label(b, r) + " overlay", std::min(width, 480))
      << "<figcaption>" << swatch(run_colour(b, r)) << escape_html(label(b, r))
      << "</figcaption></figure>\n";
  }
  h << "</div>\n";
  return h.str();
}

}  // namespace

namespace {

// What the techniques are judged against in the images: native, or the
// supersampled reference.
struct ImageReference {
  const Image& image;
  std::string name;
};

ImageReference image_reference(const BenchResult& b) {
  if (!b.reference_sample.empty()) return {b.reference_sample, "reference"};
  return {b.native_sample, "native"};
}

// One technique's crops: at the gaze, and in the periphery where its acuity
// error in the last frame is largest (the reference cropped at the same place).
std::string crop_figure(const BenchResult& b, const TechniqueResult& r, int cs,
                        double periphery_deg) {
  const ImageReference ref = image_reference(b);
  const int W = b.options.session.size.width, H = b.options.session.size.height;
  const int gx = static_cast<int>(b.sample_gaze_px.x), gy = static_cast<int>(b.sample_gaze_px.y);
  const std::string name = label(b, r);
  std::string where;
  int px = gx < W / 2 ? W - 1 : 0, py = gy < H / 2 ? H - 1 : 0;  // without images: the corner
  // (Stereo samples hold two eyes side by side: no single display to judge them with.)
  if (!ref.image.empty() && r.sample.width == ref.image.width &&
      r.sample.height == ref.image.height && r.sample.width == W && b.display.width_px == W &&
      b.display.height_px == H) {
    AcuityModel model = b.options.session.acuity;
    if (b.options.sweep.key == "slope" && r.sweep_value > 0) model.slope = r.sweep_value;
    const metrics::Map err =
        metrics::acuity_difference(ref.image, r.sample, b.display, b.sample_gaze_px, model);
    const Worst worst = worst_window(err, b.display, b.sample_gaze_px, cs, periphery_deg);
    px = worst.x;
    py = worst.y;
    where = " at (" + std::to_string(px) + ", " + std::to_string(py) + "), " +
            format_fixed(worst.ecc_deg, 1) + "&deg;, mean |acuity error| " +
            format_quantity(worst.mean_error, "codes");
  }
  std::ostringstream h;
  h << "<figure>" << img_tag(crop(r.sample, gx, gy, cs), name + " fovea", 2 * cs) << " "
    << img_tag(crop(ref.image, px, py, cs), ref.name + " periphery", 2 * cs) << " "
    << img_tag(crop(r.sample, px, py, cs), name + " periphery", 2 * cs) << "<figcaption>" << name
    << ": fovea | " << ref.name << " and " << name << " in the periphery" << where
    << "</figcaption></figure>\n";
  return h.str();
}

std::string html_crops(const BenchResult& b) {
  const ImageReference ref = image_reference(b);
  const int W = b.options.session.size.width, H = b.options.session.size.height;
  const int gx = static_cast<int>(b.sample_gaze_px.x), gy = static_cast<int>(b.sample_gaze_px.y);
  const int cs = std::clamp(std::min(W, H) / 4, 16, 160);
  constexpr double kPeripheryDeg = 10.0;
  std::ostringstream h;
  h << "<h2>Foveated beside the " << ref.name
    << ", side by side</h2>\n<p class=note>Last measured frame; crops of " << cs << "&times;" << cs
    << " pixels shown at 2&times;: at the gaze, and where the "
    << "technique's acuity-filtered error is largest at least " << format_fixed(kPeripheryDeg, 0)
    << "&deg; from the gaze (anywhere when nothing lies that far), the " << ref.name
    << " beside it.</p>\n"
       "<div class=crops>";
  h << "<figure>" << img_tag(crop(ref.image, gx, gy, cs), ref.name + " fovea", 2 * cs)
    << "<figcaption>" << ref.name << ": fovea</figcaption></figure>\n";
  for (const TechniqueResult& r : b.results) {
    if (b.reference_sample.empty() && r.technique == "native") continue;
    h << crop_figure(b, r, cs, kPeripheryDeg);
  }
  h << "</div>\n";
  return h.str();
}

// FovVideoVDP's distortion map of each technique's last frame, and a crop at
// 2x where it is worst (the largest mean distortion in a window).
std::string fvvdp_heatmaps(const BenchResult& b) {
  const int W = b.options.session.size.width, H = b.options.session.size.height;
  const int cs = std::clamp(std::min(W, H) / 4, 16, 160);
  std::ostringstream h;
  h << "<h2>Where the difference is visible</h2>\n<p class=note>FovVideoVDP's distortion "
       "map of the last measured frame over the reference: green where the difference is "
       "invisible, yellow half a JOD, red one JOD or more; beside it, "
    << cs << "&times;" << cs << " pixels at 2&times; where it is worst.</p>\n<div class=crops>";
  for (const TechniqueResult& r : b.results) {
    if (r.fvvdp_heatmap.empty()) continue;
    h << "<figure>"
      << img_tag(r.fvvdp_heatmap, label(b, r) + " FovVideoVDP", std::min(W, 480), 480);
    if (r.fvvdp_distortion.width == W && r.fvvdp_distortion.height == H) {
      const Worst worst = worst_window(r.fvvdp_distortion, b.display, b.sample_gaze_px, cs, 0.0);
      h << " "
        << img_tag(crop(r.fvvdp_heatmap, worst.x, worst.y, cs), label(b, r) + " worst", 2 * cs)
        << " " << img_tag(crop(r.sample, worst.x, worst.y, cs), label(b, r) + " there", 2 * cs)
        << "<figcaption>" << label(b, r) << ": worst at (" << worst.x << ", " << worst.y << "), "
        << format_fixed(worst.ecc_deg, 1) << "&deg; from the gaze, mean "
        << format_quantity(worst.mean_error, "JOD") << " there</figcaption>";
    } else {
      h << "<figcaption>" << label(b, r) << "</figcaption>";
    }
    h << "</figure>\n";
  }
  h << "</div>\n";
  return h.str();
}

std::string html_heatmaps_and_frames(const BenchResult& b) {
  const ImageReference ref = image_reference(b);
  const int W = b.options.session.size.width;
  std::ostringstream h;
  h << fvvdp_heatmaps(b);
  h << "<h2>Error heat maps</h2>\n<p class=note>Left: absolute difference to the " << ref.name
    << " (largest over R, G, B). Right: the difference after both images are low-pass filtered "
       "to what the eye resolves at each eccentricity.</p>\n"
    << colour_bar(64, "absolute difference (8-bit codes), left", "heat-difference") << " "
    << colour_bar(16, "acuity-filtered difference (8-bit codes), right", "heat-acuity")
    << "\n<div class=crops>";
  for (const TechniqueResult& r : b.results) {
    if (r.heatmap.empty()) continue;
    h << "<figure>" << img_tag(r.heatmap, label(b, r) + " error", std::min(W, 480), 480) << " "
      << img_tag(r.acuity_heatmap, label(b, r) + " acuity error", std::min(W, 480), 480)
      << "<figcaption>" << label(b, r) << "</figcaption></figure>\n";
  }
  h << "</div>\n<h2>Full frames</h2>\n<div class=crops>";
  if (!b.reference_sample.empty()) {
    h << "<figure>" << img_tag(ref.image, "reference frame", std::min(W, 640), 640)
      << "<figcaption>reference (" << b.options.reference << "&times;" << b.options.reference
      << " supersampled native)</figcaption></figure>";
  }
  h << "<figure>" << img_tag(b.native_sample, "native frame", std::min(W, 640), 640)
    << "<figcaption>native</figcaption></figure>";
  for (const TechniqueResult& r : b.results) {
    if (r.technique != "native") {
      h << "<figure>" << img_tag(r.sample, label(b, r) + " frame", std::min(W, 640), 640)
        << "<figcaption>" << label(b, r) << "</figcaption></figure>";
    }
  }
  h << "</div>\n<p class=note>The numbers: results.json (schema foveate-bench/1), results.csv and "
       "results.md beside this page; each chart as an SVG file of its own (chart-*.svg).</p>\n";
  return h.str();
}

// On load: each chart's download link made from the chart itself (so it
// works from the page alone), then a self-check (used by the tests, harmless
// otherwise): images decoded, charts drawn, charts without a title, axis
// title, tick labels or data, script errors.
constexpr const char* kScript = R"(<script>
var foveateErrors = 0;
window.addEventListener('error', function () { foveateErrors++; });
window.addEventListener('load', function () {
  var charts = Array.prototype.slice.call(document.querySelectorAll('.chart > svg'));
  charts.forEach(function (svg) {
    var link = svg.parentNode.querySelector('a.download');
    if (!link) return;
    var text = '<?xml version="1.0" encoding="UTF-8"?>\n' + new XMLSerializer().serializeToString(svg);
    link.href = URL.createObjectURL(new Blob([text], {type: 'image/svg+xml'}));
  });
  var imgs = Array.prototype.slice.call(document.images);
  var broken = imgs.filter(function (i) { return !i.complete || i.naturalWidth === 0; }).length;
  var bare = charts.filter(function (c) {
    return c.querySelectorAll('text.tick').length < 2 || c.querySelectorAll('text.title').length !== 1 ||
      c.querySelectorAll('text.axis-label').length < 1 ||
      c.querySelectorAll('.bar, .point, .box, .line').length === 0;
  }).map(function (c) { return c.parentNode.id; });
  // y tick labels that run into the rotated y axis title or off the chart.
  var overlaps = charts.filter(function (c) {
    var title = c.querySelector('text.axis-label[transform]'), box = c.getBoundingClientRect();
    var ticks = c.querySelectorAll('text.tick[text-anchor="end"]');
    return Array.prototype.some.call(ticks, function (t) {
      var r = t.getBoundingClientRect();
      return r.left < box.left || (title && r.left < title.getBoundingClientRect().right);
    });
  }).map(function (c) { return c.parentNode.id; });
  var narrow = charts.filter(function (c) {
    return c.getBoundingClientRect().width < 0.95 * document.body.clientWidth;
  }).map(function (c) { return c.parentNode.id; });
  document.body.setAttribute('data-selfcheck', JSON.stringify({images: imgs.length,
    broken: broken, charts: charts.length, bare: bare, narrow: narrow, overlaps: overlaps,
    downloads: document.querySelectorAll('.chart a.download[href^="blob:"]').length,
    bars: document.querySelectorAll('.chart svg rect.bar').length,
    whiskers: document.querySelectorAll('.chart svg .whisker').length,
    legends: document.querySelectorAll('.chart svg .legend').length,
    overlays: document.querySelectorAll('svg.overlay .shape').length,
    overlay_legends: document.querySelectorAll('ul.legend li').length,
    colourbars: document.querySelectorAll('svg.colourbar').length, errors: foveateErrors}));
});
</script>
</body></html>
)";

// One benchmark's sections, after its heading. Results read back from
// results.json carry no images: their image sections are left out.
std::string run_body(const BenchResult& b) {
  const std::string figures =
      b.native_sample.empty()
          ? "<p class=note>Frames, crops and heat maps are not kept in results.json: they are "
            "in this benchmark's own report.html.</p>\n"
          : html_overlays(b) + html_crops(b) + html_heatmaps_and_frames(b);
  return run_intro(b) + html_results_table(b) + html_passes_table(b) + html_speed(b) +
         html_quality(b) + html_sweep(b) + figures;
}

// The ids (and chart files) of one benchmark's sections made unique in a
// page of several: "chart-speed" becomes "r2-chart-speed".
std::string prefix_ids(std::string html, const std::string& prefix) {
  // Each attribute that names an id, up to where the id starts.
  for (const std::string lead : {"id=\"", "href=\"", "download=\"", "url(#"}) {
    const bool chart_only = lead == "href=\"" || lead == "download=\"";  // links to chart files
    for (size_t at = html.find(lead); at != std::string::npos; at = html.find(lead, at + 1)) {
      const size_t start = at + lead.size();
      if (chart_only && html.compare(start, 6, "chart-") != 0) continue;
      html.insert(start, prefix);
    }
  }
  return html;
}

// Every run of every benchmark in one table and one chart, each row named
// by its benchmark.
std::string combined_summary(const std::vector<BenchResult>& results,
                             const std::vector<std::string>& names) {
  std::ostringstream h;
  h << "<h2>All runs</h2>\n<table id=\"summary\"><tr><th>benchmark</th><th>scene</th>"
       "<th>size</th><th>technique</th><th>JOD</th><th>speedup</th><th>95 % CI</th>"
       "<th>mean</th><th>pixel ratio</th></tr>\n";
  std::vector<std::string> rows, colours;
  BarSeries speed{.name = "measured speedup (95 % bootstrap interval)"};
  for (size_t i = 0; i < results.size(); ++i) {
    const BenchResult& b = results[i];
    const PixelSize size = b.options.session.size;
    for (const TechniqueResult& r : b.results) {
      h << "<tr><td><a href=\"#r" << i + 1 << "\">" << i + 1 << "</a> " << escape_html(names[i])
        << "</td><td>" << escape_html(b.scene) << "</td><td>" << size.width << "&times;"
        << size.height << "</td><td>" << swatch(run_colour(b, r)) << escape_html(label(b, r))
        << "</td><td>" << cell(jod_of(r), 4) << "</td><td>" << cell(r.speedup) << "x</td><td>"
        << cell(r.speedup_lo) << "&ndash;" << cell(r.speedup_hi) << "x</td><td>"
        << format_quantity(r.mean_ms, "ms") << "</td><td>" << cell(r.pixel_ratio) << "</td></tr>\n";
      if (r.technique == "native") continue;
      rows.push_back(std::to_string(i + 1) + " " + b.scene + ": " + label(b, r));
      colours.push_back(run_colour(b, r));
      speed.values.push_back(r.speedup);
      speed.lo.push_back(r.speedup_lo);
      speed.hi.push_back(r.speedup_hi);
    }
  }
  h << "</table>\n";
  speed.colors = colours;
  if (!rows.empty()) {
    h << chart_div("chart-all-speed",
                   svg_bar_chart(rows, {speed},
                                 {.title = "Speedup over each benchmark's own native",
                                  .value_label = "speedup over native (x, mean frame times)",
                                  .unit = "x"}));
  }
  return h.str();
}

}  // namespace

std::string bench_html(const BenchResult& b) {
  return page_head("foveate bench: " + b.scene) + "<h1>foveate benchmark: " + escape_html(b.scene) +
         "</h1>\n" + run_body(b) + kScript;
}

std::string combined_html(const std::vector<BenchResult>& results,
                          const std::vector<std::string>& names) {
  std::ostringstream h;
  h << page_head("foveate report: " + std::to_string(results.size()) + " benchmarks")
    << "<h1>foveate report: " << results.size() << " benchmarks</h1>\n<ol>";
  for (size_t i = 0; i < results.size(); ++i) {
    const PixelSize size = results[i].options.session.size;
    h << "<li><a href=\"#r" << i + 1 << "\">" << escape_html(results[i].scene) << ", " << size.width
      << "&times;" << size.height << "</a>: " << escape_html(names[i]) << "</li>";
  }
  h << "</ol>\n<p class=note>Each benchmark's speedups are against its own native, measured "
       "in the same run; numbers from different machines or loads compare only as "
       "ratios.</p>\n"
    << combined_summary(results, names);
  for (size_t i = 0; i < results.size(); ++i) {
    const std::string id = "r" + std::to_string(i + 1);
    h << "<section class=\"run\" id=\"" << id << "\"><h1>" << i + 1 << ". "
      << escape_html(results[i].scene) << "</h1>\n<p class=note>From " << escape_html(names[i])
      << ".</p>\n"
      << prefix_ids(run_body(results[i]), id + "-") << "</section>\n";
  }
  h << kScript;
  return h.str();
}

std::vector<std::pair<std::string, std::string>> report_figures(const std::string& html) {
  std::vector<std::pair<std::string, std::string>> out;
  const std::string open = "<div class=\"chart\" id=\"";
  for (size_t at = html.find(open); at != std::string::npos; at = html.find(open, at + 1)) {
    const size_t id_start = at + open.size(), id_end = html.find('"', id_start);
    const size_t svg = html.find("<svg", id_end), end = html.find("</svg>", svg);
    if (id_end == std::string::npos || svg == std::string::npos || end == std::string::npos) break;
    out.emplace_back(
        html.substr(id_start, id_end - id_start) + ".svg",
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + html.substr(svg, end + 6 - svg) + "\n");
  }
  return out;
}

}  // namespace foveate::bench
