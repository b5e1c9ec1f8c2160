// The benchmark's single-file HTML report: every chart with axes, ticks and
// units, images as JPEG (crops of small frames as PNG), opens offline.
#include <algorithm>
#include <sstream>

#include "foveate/bench/report.hpp"
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

std::string html_head(const BenchResult& b) {
  std::ostringstream h;
  const PixelSize size = b.options.session.size;
  const RunEnvironment& env = b.environment;
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>foveate bench: "
    << b.scene
    << "</title>\n<style>body{font-family:sans-serif;margin:24px;max-width:1400px;color:#222}"
       "table{border-collapse:collapse;margin:12px 0}td,th{border:1px solid #ccc;padding:4px "
       "8px;text-align:right}"
       "th{background:#f0f0f0}td:first-child{text-align:left}.crops{display:flex;flex-wrap:wrap;"
       "gap:16px}"
       ".crops figure{margin:0}.crops img{image-rendering:pixelated;border:1px solid #999}"
       "figcaption{font-size:12px;color:#555}.note{color:#555;font-size:13px}"
       ".warn{color:#a00}.chart{margin:8px 0}</style></"
       "head><body>\n";
  h << "<h1>foveate benchmark: " << b.scene << "</h1>\n<p class=note>" << size.width << "&times;"
    << size.height << " on " << b.display.name << " geometry (field of view kept), renderer "
    << b.renderer << ", MAR slope " << format_fixed(b.options.session.acuity.slope, 4) << ", gaze "
    << (b.options.session.gaze.empty() ? "centre" : b.options.session.gaze) << ", "
    << b.options.frames << " measured frames after " << b.warmup
    << " warm-up, techniques interleaved frame by frame in an order shuffled every frame. Speedup "
       "is the ratio of mean frame times (95 % bootstrap interval); the pixel bound is native "
       "pixels / shaded pixels.</p>\n"
    << "<p class=note>Command: <code>" << escape_html(env.command) << "</code>; foveate "
    << escape_html(env.version) << ", " << escape_html(env.date_utc) << ", CPU "
    << escape_html(env.cpu_model) << " (" << env.cores << " cores), load "
    << format_fixed(env.load_start[0], 2) << " (1 min) at the start, "
    << format_fixed(env.load_end[0], 2) << " at the end.</p>\n";
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
  h << "<table id=\"results\"><tr><th>technique</th><th>JOD</th><th>below native</th>"
       "<th>speedup</th><th>95 % CI</th><th>mean ms</th><th>median ms</th><th>p90 ms</th>"
       "<th>shaded px</th><th>pixel ratio</th><th>share of bound</th>";
  for (const QualityColumn& c : kQualityColumns) h << "<th>" << c.title << "</th>";
  h << "</tr>\n";
  for (const TechniqueResult& r : b.results) {
    const auto jod_cell = [](double v) { return std::isfinite(v) ? format_fixed(v, 3) : "-"; };
    h << "<tr><td>" << label(b, r) << "</td><td>" << jod_cell(jod_of(r)) << "</td><td>"
      << jod_cell(jod_below_native(b, r)) << "</td><td>" << format_fixed(r.speedup, 2)
      << "x</td><td>" << format_fixed(r.speedup_lo, 2) << "-" << format_fixed(r.speedup_hi, 2)
      << "</td><td>" << format_fixed(r.mean_ms, 2) << "</td><td>" << format_fixed(r.median_ms, 2)
      << "</td><td>" << format_fixed(r.p90_ms, 2) << "</td><td>" << format_fixed(r.shaded_pixels, 0)
      << "</td><td>" << format_fixed(r.pixel_ratio, 3) << "</td><td>"
      << format_fixed(100 * r.bound_share, 0) << " %</td>";
    for (const QualityColumn& c : kQualityColumns) h << "<td>" << quality_cell(r, c) << "</td>";
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
    h << "<tr><td>" << label(b, r) << "</td><td style=\"text-align:left\">";
    h << pass_list(r, " ms") << "</td><td>" << format_fixed(100 * resolve_ms(r) / r.mean_ms, 1)
      << " %</td></tr>\n";
  }
  h << "</table>\n";
  return h.str();
}

// The layers or regions of each technique over its last frame.
std::string html_overlays(const BenchResult& b) {
  std::ostringstream h;
  h << "<h2>Layers and regions</h2>\n<p class=note>Each technique's last measured frame with "
       "its layer or region borders and the gaze, as its overlay draws them (colours are the "
       "technique's own: see its section of the README).</p>\n<div class=crops>";
  const int width = b.options.session.size.width;
  for (const TechniqueResult& r : b.results) {
    if (r.technique == "native" || r.overlay.empty()) continue;
    h << "<figure>"
      << overlay_figure(r.sample, r.overlay, label(b, r) + " overlay", std::min(width, 480))
      << "<figcaption>" << label(b, r) << "</figcaption></figure>\n";
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
            format_fixed(worst.mean_error, 2) + " codes";
  }
  std::ostringstream h;
  h << "<figure>" << img_tag(crop(r.sample, gx, gy, cs), name + " fovea", 2 * cs, cs <= 64) << " "
    << img_tag(crop(ref.image, px, py, cs), ref.name + " periphery", 2 * cs, cs <= 64) << " "
    << img_tag(crop(r.sample, px, py, cs), name + " periphery", 2 * cs, cs <= 64) << "<figcaption>"
    << name << ": fovea | " << ref.name << " and " << name << " in the periphery" << where
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
  h << "<figure>" << img_tag(crop(ref.image, gx, gy, cs), ref.name + " fovea", 2 * cs, cs <= 64)
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
      << img_tag(r.fvvdp_heatmap, label(b, r) + " FovVideoVDP", std::min(W, 480), false, 480);
    if (r.fvvdp_distortion.width == W && r.fvvdp_distortion.height == H) {
      const Worst worst = worst_window(r.fvvdp_distortion, b.display, b.sample_gaze_px, cs, 0.0);
      h << " "
        << img_tag(crop(r.fvvdp_heatmap, worst.x, worst.y, cs), label(b, r) + " worst", 2 * cs,
                   true)
        << " "
        << img_tag(crop(r.sample, worst.x, worst.y, cs), label(b, r) + " there", 2 * cs, true)
        << "<figcaption>" << label(b, r) << ": worst at (" << worst.x << ", " << worst.y << "), "
        << format_fixed(worst.ecc_deg, 1) << "&deg; from the gaze, mean "
        << format_fixed(worst.mean_error, 3) << " JOD there</figcaption>";
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
    << colour_bar(64, "absolute difference (8-bit codes), left") << " "
    << colour_bar(16, "acuity-filtered difference (8-bit codes), right") << "\n<div class=crops>";
  for (const TechniqueResult& r : b.results) {
    if (r.heatmap.empty()) continue;
    h << "<figure>" << img_tag(r.heatmap, label(b, r) + " error", std::min(W, 480), false, 480)
      << " "
      << img_tag(r.acuity_heatmap, label(b, r) + " acuity error", std::min(W, 480), false, 480)
      << "<figcaption>" << label(b, r) << "</figcaption></figure>\n";
  }
  h << "</div>\n<h2>Full frames</h2>\n<div class=crops>";
  if (!b.reference_sample.empty()) {
    h << "<figure>" << img_tag(ref.image, "reference frame", std::min(W, 640), false, 640)
      << "<figcaption>reference (" << b.options.reference << "&times;" << b.options.reference
      << " supersampled native)</figcaption></figure>";
  }
  h << "<figure>" << img_tag(b.native_sample, "native frame", std::min(W, 640), false, 640)
    << "<figcaption>native</figcaption></figure>";
  for (const TechniqueResult& r : b.results) {
    if (r.technique != "native") {
      h << "<figure>" << img_tag(r.sample, label(b, r) + " frame", std::min(W, 640), false, 640)
        << "<figcaption>" << label(b, r) << "</figcaption></figure>";
    }
  }
  h << "</div>\n<p class=note>The numbers: results.json (schema foveate-bench/1), results.csv and "
       "results.md beside this page.</p>\n";
  return h.str();
}

// A self-check a browser runs on load (used by the tests, harmless otherwise):
// images decoded, charts drawn, charts without tick labels or data, script errors.
constexpr const char* kSelfCheck =
    "<script>\nvar foveateErrors = 0;\nwindow.addEventListener('error', function () { "
    "foveateErrors++; });\n"
    "window.addEventListener('load', function () {\n"
    "  var imgs = Array.prototype.slice.call(document.images);\n"
    "  var broken = imgs.filter(function (i) { return !i.complete || i.naturalWidth === 0; "
    "}).length;\n"
    "  var charts = Array.prototype.slice.call(document.querySelectorAll('.chart svg'));\n"
    "  var bare = charts.filter(function (c) { return c.querySelectorAll('text.tick').length < "
    "2 "
    "|| c.querySelectorAll('.bar, .point, .box').length === 0; }).map(function (c) { return "
    "c.parentNode.id; });\n"
    "  document.body.setAttribute('data-selfcheck', JSON.stringify({images: imgs.length, "
    "broken: broken, charts: charts.length, bare: bare, "
    "bars: document.querySelectorAll('.chart svg rect.bar').length, "
    "whiskers: document.querySelectorAll('.chart svg .whisker').length, "
    "overlays: document.querySelectorAll('svg.overlay .shape').length, "
    "colourbars: document.querySelectorAll('svg.colourbar').length, errors: foveateErrors}));\n"
    "});\n</script>\n</body></html>\n";

}  // namespace

std::string bench_html(const BenchResult& b) {
  return html_head(b) + html_results_table(b) + html_passes_table(b) + html_speed(b) +
         html_quality(b) + html_sweep(b) + html_overlays(b) + html_crops(b) +
         html_heatmaps_and_frames(b) + kSelfCheck;
}

}  // namespace foveate::bench
