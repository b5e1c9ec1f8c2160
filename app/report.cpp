// Benchmark outputs: JSON (schema in docs/bench-json.md), CSV, a Markdown
// table and a single-file HTML report that opens offline.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "bench.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"
#include "foveate/core/stats.hpp"
#include "output_dir.hpp"
#include "report_media.hpp"
#include "svg_plot.hpp"

namespace foveate::app {

namespace {

// The quality columns of the CSV, Markdown and HTML tables, read from the
// typed summary (the JSON writes all of it through metrics::to_json).
struct QualityColumn {
  const char* csv;    ///< CSV header
  const char* title;  ///< Markdown and HTML header
  int digits;
  double (*get)(const metrics::QualitySummary&);
};
constexpr QualityColumn kQualityColumns[] = {
    {"psnr_db", "PSNR dB", 2, [](const metrics::QualitySummary& q) { return q.mean.psnr_db; }},
    {"ssim", "SSIM", 4, [](const metrics::QualitySummary& q) { return q.mean.ssim; }},
    {"acuity_rmse", "acuity RMSE", 3,
     [](const metrics::QualitySummary& q) { return q.mean.acuity_rmse; }},
    {"jnd_mean", "JND mean", 3, [](const metrics::QualitySummary& q) { return q.mean.jnd_mean; }},
    {"visible_fraction", "visible (JND ≥ 1)", 4,
     [](const metrics::QualitySummary& q) { return q.mean.visible_fraction; }},
    {"flicker_ratio", "flicker", 2,
     [](const metrics::QualitySummary& q) { return q.flicker.ratio; }},
};

/// A quality figure, or NaN where not measured (native itself, --no-metrics).
double quality_value(const TechniqueResult& r, double (*get)(const metrics::QualitySummary&)) {
  return r.metrics ? get(*r.metrics) : std::nan("");
}
double quality_value(const TechniqueResult& r, const QualityColumn& c) {
  return quality_value(r, c.get);
}
double mean_ssim(const metrics::QualitySummary& q) { return q.mean.ssim; }
double mean_acuity_rmse(const metrics::QualitySummary& q) { return q.mean.acuity_rmse; }

// `{}` where quality was not measured (native itself, --no-metrics).
nlohmann::json quality_json(const TechniqueResult& r) {
  return r.metrics ? metrics::to_json(*r.metrics) : nlohmann::json::object();
}

std::string quality_cell(const TechniqueResult& r, const QualityColumn& c) {
  const double v = quality_value(r, c);
  return std::isfinite(v) ? fmt(v, c.digits) : "-";
}

std::string label(const BenchResult& b, const TechniqueResult& r) {
  if (b.options.sweep.key.empty() || r.technique == "native") return r.technique;
  return r.technique + " @ " + b.options.sweep.key + "=" + fmt(r.sweep_value, 4);
}

nlohmann::json to_json(const BenchResult& b) {
  nlohmann::json results = nlohmann::json::array();
  for (const TechniqueResult& r : b.results) {
    nlohmann::json params = nlohmann::json::object();
    for (const auto& [k, v] : r.parameters) params[k] = v;
    nlohmann::json parts = nlohmann::json::array();
    for (const PixelPart& p : r.parts) parts.push_back({{"name", p.name}, {"pixels", p.pixels}});
    nlohmann::json j = {{"technique", r.technique},
                        {"label", label(b, r)},
                        {"parameters", params},
                        {"median_ms", r.median_ms},
                        {"p90_ms", r.p90_ms},
                        {"mean_ms", r.mean_ms},
                        {"speedup", r.speedup},
                        {"speedup_ci95", {r.speedup_lo, r.speedup_hi}},
                        {"shaded_pixels", r.shaded_pixels},
                        {"native_pixels", r.native_pixels},
                        {"pixel_ratio", r.pixel_ratio},
                        {"pixel_speedup_bound", 1.0 / r.pixel_ratio},
                        {"bound_share", r.bound_share},
                        {"parts", parts},
                        {"quality", quality_json(r)},
                        {"frame_ms", r.frame_ms}};
    if (!b.options.sweep.key.empty()) j["sweep_value"] = r.sweep_value;
    // GPU timer queries only where the renderer reports meaningful ones.
    j["gpu_median_ms"] = nullptr;
    if (!r.gpu_ms.empty()) j["gpu_median_ms"] = quantile(r.gpu_ms, 0.5);
    results.push_back(j);
  }
  nlohmann::json sweep = nullptr;
  if (!b.options.sweep.key.empty())
    sweep = {{"key", b.options.sweep.key}, {"values", b.options.sweep.values}};
  return {
      {"schema", "foveate-bench/1"},
      {"command", b.options.command_line},
      {"renderer", b.renderer},
      {"scene", b.scene},
      {"size", {b.options.session.size.width, b.options.session.size.height}},
      {"display", b.display},
      {"acuity",
       {{"slope", b.options.session.acuity.slope}, {"w0_deg", b.options.session.acuity.w0_deg}}},
      {"gaze", b.options.gaze.empty() ? "centre" : b.options.gaze},
      {"reference", b.options.reference > 1 ? "ssaa:" + std::to_string(b.options.reference)
                                            : std::string("native")},
      {"frames", b.options.frames},
      {"warmup", b.options.warmup},
      {"fps_clock", b.options.session.fps},
      {"sweep", sweep},
      {"results", results}};
}

std::string csv(const BenchResult& b) {
  std::ostringstream s;
  s << "technique,label,sweep_value,median_ms,p90_ms,speedup,speedup_lo,speedup_hi,shaded_pixels,"
       "native_pixels,pixel_ratio,bound_share";
  for (const QualityColumn& c : kQualityColumns) s << ',' << c.csv;
  s << '\n';
  for (const TechniqueResult& r : b.results) {
    s << r.technique << ',' << '"' << label(b, r) << '"' << ',' << r.sweep_value << ','
      << r.median_ms << ',' << r.p90_ms << ',' << r.speedup << ',' << r.speedup_lo << ','
      << r.speedup_hi << ',' << r.shaded_pixels << ',' << r.native_pixels << ',' << r.pixel_ratio
      << ',' << r.bound_share;
    for (const QualityColumn& c : kQualityColumns) {
      const double v = quality_value(r, c);
      s << ',' << (std::isfinite(v) ? std::to_string(v) : std::string());
    }
    s << '\n';
  }
  return s.str();
}

std::string html(const BenchResult& b) {
  const nlohmann::json j = to_json(b);
  std::ostringstream h;
  const int W = b.options.session.size.width, H = b.options.session.size.height;
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>foveate bench: "
    << b.scene
    << "</title>\n<style>body{font-family:sans-serif;margin:24px;max-width:1400px;color:#222}"
       "table{border-collapse:collapse;margin:12px 0}td,th{border:1px solid #ccc;padding:4px "
       "8px;text-align:right}"
       "th{background:#f0f0f0}td:first-child{text-align:left}.crops{display:flex;flex-wrap:wrap;"
       "gap:16px}"
       ".crops figure{margin:0}.crops img{image-rendering:pixelated;border:1px solid #999}"
       "figcaption{font-size:12px;color:#555}.note{color:#555;font-size:13px}</style></"
       "head><body>\n";
  h << "<h1>foveate benchmark: " << b.scene << "</h1>\n<p class=note>" << W << "&times;" << H
    << " on " << b.display.name << " geometry (field of view kept), renderer " << b.renderer
    << ", MAR slope " << fmt(b.options.session.acuity.slope, 4) << ", gaze "
    << (b.options.gaze.empty() ? "centre" : b.options.gaze) << ", " << b.options.frames
    << " measured frames after " << b.options.warmup
    << " warm-up, techniques interleaved frame by frame. Speedup is the ratio of median frame "
       "times (95 % bootstrap "
       "interval); the pixel bound is native pixels / shaded pixels.</p>\n";
  h << "<table id=\"results\"><tr><th>technique</th><th>median ms</th><th>p90 "
       "ms</th><th>speedup</th><th>95 % CI</th>"
       "<th>shaded px</th><th>pixel ratio</th><th>share of bound</th>";
  for (const QualityColumn& c : kQualityColumns) h << "<th>" << c.title << "</th>";
  h << "</tr>\n";
  for (const TechniqueResult& r : b.results) {
    h << "<tr><td>" << label(b, r) << "</td><td>" << fmt(r.median_ms, 2) << "</td><td>"
      << fmt(r.p90_ms, 2) << "</td><td>" << fmt(r.speedup, 2) << "x</td><td>"
      << fmt(r.speedup_lo, 2) << "-" << fmt(r.speedup_hi, 2) << "</td><td>"
      << fmt(r.shaded_pixels, 0) << "</td><td>" << fmt(r.pixel_ratio, 3) << "</td><td>"
      << fmt(100 * r.bound_share, 0) << " %</td>";
    for (const QualityColumn& c : kQualityColumns) h << "<td>" << quality_cell(r, c) << "</td>";
    h << "</tr>\n";
  }
  h << "</table>\n<h2>Speed</h2>\n";
  std::vector<std::string> names, qnames;
  std::vector<double> speed, bound, ssim, acuity;
  for (const TechniqueResult& r : b.results) {
    names.push_back(label(b, r));
    speed.push_back(r.speedup);
    bound.push_back(1.0 / r.pixel_ratio);
    if (!r.metrics) continue;  // the reference itself (native unless supersampled)
    qnames.push_back(label(b, r));
    ssim.push_back(quality_value(r, mean_ssim));
    acuity.push_back(quality_value(r, mean_acuity_rmse));
  }
  h << "<div class=chart id=\"chart-speed\">"
    << bar_chart(names, speed, bound, "measured speedup", "pixel bound (native / shaded pixels)",
                 "Speedup over native")
    << "</div>\n<h2>Quality</h2>\n";
  if (b.options.image_metrics) {
    h << "<div class=chart id=\"chart-quality\">"
      << bar_chart(qnames, ssim, {}, "SSIM against native (1 = identical)", "", "Image similarity")
      << "</div>\n"
      << "<div class=chart id=\"chart-acuity\">"
      << bar_chart(qnames, acuity, {}, "acuity-filtered RMSE (8-bit units; 0 = no visible loss)",
                   "", "Error the eye can resolve")
      << "</div>\n";
    // Error and visibility against eccentricity, from the summaries' profiles.
    const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                             "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
    std::vector<Series> rmse_series, jnd_series;
    int c = 0;
    for (const TechniqueResult& r : b.results) {
      if (!r.metrics) continue;  // native, when it is the reference, has none
      const metrics::EccentricityProfile& p = r.metrics->mean.profile;
      Series e{label(b, r), colours[c % 10], {}, {}, c >= 10};
      Series v = e;
      ++c;
      for (size_t i = 0; i < p.acuity_rmse.size(); ++i) {
        // Bins with almost no pixels (the screen's far corners) are noise.
        if (!(p.pixels_fraction[i] >= 1e-3)) continue;
        const double x = (static_cast<double>(i) + 0.5) * p.bin_deg;
        e.x.push_back(x);
        e.y.push_back(p.acuity_rmse[i]);
        v.x.push_back(x);
        v.y.push_back(p.jnd_mean[i]);
      }
      rmse_series.push_back(std::move(e));
      jnd_series.push_back(std::move(v));
    }
    if (!rmse_series.empty()) {
      const double bin = b.results.size() > 1 && b.results.back().metrics
                             ? b.results.back().metrics->mean.profile.bin_deg
                             : 1.0;
      ChartOptions oe{"Acuity-filtered error against eccentricity (mean over the frames, " +
                          fmt(bin, 1) + "-degree bins)",
                      "eccentricity (degrees)", "acuity RMSE (8-bit luminance codes)", false};
      ChartOptions ov{"Visibility against eccentricity (Barten CSF, Minkowski beta " +
                          fmt(b.results.back().metrics->mean.contrast.pooling_beta, 0) + ")",
                      "eccentricity (degrees)", "mean JND (1 = just noticeable)", false};
      h << "<div class=chart id=\"chart-eccentricity\">" << svg_line_chart(rmse_series, oe)
        << "</div>\n<div class=chart id=\"chart-eccentricity-jnd\">"
        << svg_line_chart(jnd_series, ov) << "</div>\n";
    }
    // Frame-to-frame change per eccentricity band.
    if (!b.results.empty()) {
      std::vector<const TechniqueResult*> rows;
      for (const TechniqueResult& r : b.results)
        if (r.metrics && !r.metrics->flicker.bands.empty()) rows.push_back(&r);
      if (!rows.empty()) {
        const auto& bands = rows.front()->metrics->flicker.bands;
        h << "<h3>Temporal change per eccentricity band</h3>\n<p class=note>Mean absolute "
             "frame-to-frame change of the luminance codes, technique (native) and their ratio; "
             "with a static camera the technique's change is its convergence, the last pair's "
             "value whether it has settled.</p>\n<table id=\"flicker\"><tr><th>technique</th>";
        for (const metrics::FlickerBand& fb : bands) {
          h << "<th>" << fmt(fb.from_deg, 0)
            << (std::isinf(fb.to_deg) ? "+" : "&ndash;" + fmt(fb.to_deg, 0)) << "&deg;</th>";
        }
        h << "</tr>\n";
        auto cell = [](double v, int digits) { return std::isfinite(v) ? fmt(v, digits) : "-"; };
        for (const TechniqueResult* r : rows) {
          h << "<tr><td>" << label(b, *r) << "</td>";
          for (const metrics::FlickerBand& fb : r->metrics->flicker.bands) {
            h << "<td>" << cell(fb.test_change, 2) << " (" << cell(fb.reference_change, 2)
              << "), &times;" << cell(fb.ratio, 2) << ", last " << cell(fb.test_change_last, 2)
              << "</td>";
          }
          h << "</tr>\n";
        }
        h << "</table>\n";
      }
    }
  } else {
    h << "<p class=note>Not measured (--no-metrics).</p>\n";
  }
  if (!b.options.sweep.key.empty()) {
    std::map<std::string, Series> speed_series, quality_series;
    const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};
    int c = 0;
    for (const TechniqueResult& r : b.results) {
      if (r.technique == "native") continue;
      auto [it, fresh] = speed_series.try_emplace(r.technique);
      if (fresh) {
        it->second.name = r.technique;
        it->second.color = colours[c++ % 6];
        quality_series[r.technique].name = r.technique;
        quality_series[r.technique].color = it->second.color;
      }
      it->second.x.push_back(r.sweep_value);
      it->second.y.push_back(r.speedup);
      quality_series[r.technique].x.push_back(r.speedup);
      quality_series[r.technique].y.push_back(quality_value(r, mean_ssim));
    }
    std::vector<Series> s1, s2;
    for (auto& [k, v] : speed_series) s1.push_back(v);
    for (auto& [k, v] : quality_series) s2.push_back(v);
    ChartOptions o1{"Speedup against " + b.options.sweep.key, b.options.sweep.key,
                    "speedup over native", false};
    ChartOptions o2{"Quality against speed (sweep of " + b.options.sweep.key + ")",
                    "speedup over native", "SSIM", false};
    h << "<h2>Sweep of " << b.options.sweep.key
      << "</h2>\n<div class=chart id=\"chart-sweep-speed\">" << svg_line_chart(s1, o1)
      << "</div>\n<div class=chart id=\"chart-sweep-quality\">" << svg_line_chart(s2, o2)
      << "</div>\n";
  }
  // Crops: at the gaze, and in the periphery where the technique's acuity
  // error in the last frame is largest (native cropped at the same place).
  // What the technique is judged against: native, or the supersampled reference.
  const bool supersampled = !b.reference_sample.empty();
  const Image& ref = supersampled ? b.reference_sample : b.native_sample;
  const std::string ref_name = supersampled ? "reference" : "native";
  const int gx = static_cast<int>(b.sample_gaze_px.x), gy = static_cast<int>(b.sample_gaze_px.y);
  const int cs = std::clamp(std::min(W, H) / 4, 16, 160);
  constexpr double kPeripheryDeg = 10.0;
  h << "<h2>Foveated beside the " << ref_name
    << ", side by side</h2>\n<p class=note>Last measured frame; crops of " << cs << "&times;" << cs
    << " pixels shown at 2&times;: at the gaze, and where the "
    << "technique's acuity-filtered error is largest at least " << fmt(kPeripheryDeg, 0)
    << "&deg; from the gaze (anywhere when nothing lies that far), the " << ref_name
    << " beside it.</p>\n"
       "<div class=crops>";
  h << "<figure>" << img_tag(crop(ref, gx, gy, cs), ref_name + " fovea", 2 * cs) << "<figcaption>"
    << ref_name << ": fovea</figcaption></figure>\n";
  for (const TechniqueResult& r : b.results) {
    if (!supersampled && r.technique == "native") continue;
    const std::string name = label(b, r);
    std::string where;
    int px = gx < W / 2 ? W - 1 : 0, py = gy < H / 2 ? H - 1 : 0;  // without images: the corner
    if (!ref.empty() && r.sample.width == ref.width && r.sample.height == ref.height &&
        b.display.width_px == W && b.display.height_px == H) {
      AcuityModel model = b.options.session.acuity;
      if (b.options.sweep.key == "slope" && r.sweep_value > 0) model.slope = r.sweep_value;
      const metrics::Map err =
          metrics::acuity_difference(ref, r.sample, b.display, b.sample_gaze_px, model);
      const Worst worst = worst_window(err, b.display, b.sample_gaze_px, cs, kPeripheryDeg);
      px = worst.x;
      py = worst.y;
      where = " at (" + std::to_string(px) + ", " + std::to_string(py) + "), " +
              fmt(worst.ecc_deg, 1) + "&deg;, mean |acuity error| " + fmt(worst.mean_error, 2) +
              " codes";
    }
    h << "<figure>" << img_tag(crop(r.sample, gx, gy, cs), name + " fovea", 2 * cs) << " "
      << img_tag(crop(ref, px, py, cs), ref_name + " periphery", 2 * cs) << " "
      << img_tag(crop(r.sample, px, py, cs), name + " periphery", 2 * cs) << "<figcaption>" << name
      << ": fovea | " << ref_name << " and " << name << " in the periphery" << where
      << "</figcaption></figure>\n";
  }
  h << "</div>\n<h2>Error heat maps</h2>\n<p class=note>Left: absolute difference to the "
    << ref_name
    << " (black "
       "= none, white = "
       "64/255 or more). Right: the difference after both images are low-pass filtered to what the "
       "eye resolves at "
       "each eccentricity.</p>\n<div class=crops>";
  for (const TechniqueResult& r : b.results) {
    if (r.heatmap.empty()) continue;
    h << "<figure>" << img_tag(r.heatmap, label(b, r) + " error", std::min(W, 480)) << " "
      << img_tag(r.acuity_heatmap, label(b, r) + " acuity error", std::min(W, 480))
      << "<figcaption>" << label(b, r) << "</figcaption></figure>\n";
  }
  h << "</div>\n<h2>Full frames</h2>\n<div class=crops>";
  if (supersampled) {
    h << "<figure>" << img_tag(ref, "reference frame", std::min(W, 640))
      << "<figcaption>reference (" << b.options.reference << "&times;" << b.options.reference
      << " supersampled native)</figcaption></figure>";
  }
  h << "<figure>" << img_tag(b.native_sample, "native frame", std::min(W, 640))
    << "<figcaption>native</figcaption></figure>";
  for (const TechniqueResult& r : b.results) {
    if (r.technique != "native") {
      h << "<figure>" << img_tag(r.sample, label(b, r) + " frame", std::min(W, 640))
        << "<figcaption>" << label(b, r) << "</figcaption></figure>";
    }
  }
  h << "</div>\n<h2>Raw results</h2>\n<pre id=\"raw\">" << j.dump(2).substr(0, 20000) << "</pre>\n";
  // A self-check a browser runs on load (used by the tests, harmless otherwise):
  // how many images decoded, how many charts drew, and any script errors.
  h << "<script>\nvar foveateErrors = 0;\nwindow.addEventListener('error', function () { "
       "foveateErrors++; });\n"
       "window.addEventListener('load', function () {\n"
       "  var imgs = Array.prototype.slice.call(document.images);\n"
       "  var broken = imgs.filter(function (i) { return !i.complete || i.naturalWidth === 0; "
       "}).length;\n"
       "  var charts = document.querySelectorAll('.chart svg').length;\n"
       "  var bars = document.querySelectorAll('.chart svg rect.bar').length;\n"
       "  document.body.setAttribute('data-selfcheck', JSON.stringify({images: imgs.length, "
       "broken: broken, "
       "charts: charts, bars: bars, errors: foveateErrors}));\n"
       "});\n</script>\n</body></html>\n";
  return h.str();
}

}  // namespace

std::string bench_markdown(const BenchResult& b) {
  std::ostringstream s;
  s << "| technique | median ms | p90 ms | speedup (95 % CI) | shaded px | pixel ratio | share of "
       "bound |";
  for (const QualityColumn& c : kQualityColumns) s << ' ' << c.title << " |";
  s << "\n|---|---:|---:|---:|---:|---:|---:|";
  for (size_t i = 0; i < std::size(kQualityColumns); ++i) s << "---:|";
  s << '\n';
  for (const TechniqueResult& r : b.results) {
    s << "| " << label(b, r) << " | " << fmt(r.median_ms, 2) << " | " << fmt(r.p90_ms, 2) << " | "
      << fmt(r.speedup, 2) << "x (" << fmt(r.speedup_lo, 2) << "-" << fmt(r.speedup_hi, 2) << ") | "
      << fmt(r.shaded_pixels, 0) << " | " << fmt(r.pixel_ratio, 3) << " | "
      << fmt(100 * r.bound_share, 0) << " % |";
    for (const QualityColumn& c : kQualityColumns) s << ' ' << quality_cell(r, c) << " |";
    s << '\n';
  }
  return s.str();
}

void write_bench_outputs(const BenchResult& b) {
  namespace fs = std::filesystem;
  make_output_dir(b.options.out, "--out");
  const fs::path dir(b.options.out);
  write_file_atomic((dir / "results.json").string(), to_json(b).dump(2) + "\n");
  write_file_atomic((dir / "results.csv").string(), csv(b));
  write_file_atomic((dir / "results.md").string(), bench_markdown(b));
  write_file_atomic((dir / "report.html").string(), html(b));
}

}  // namespace foveate::app
