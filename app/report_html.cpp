// The benchmark's single-file HTML report: every chart with axes, ticks and
// units, images as JPEG (crops of small frames as PNG), opens offline.
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "report_common.hpp"
#include "report_media.hpp"
#include "svg_plot.hpp"

namespace foveate::app {

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
}  // namespace

std::string report_html(const BenchResult& b) {
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
       "figcaption{font-size:12px;color:#555}.note{color:#555;font-size:13px}"
       ".warn{color:#a00}.chart{margin:8px 0}</style></"
       "head><body>\n";
  h << "<h1>foveate benchmark: " << b.scene << "</h1>\n<p class=note>" << W << "&times;" << H
    << " on " << b.display.name << " geometry (field of view kept), renderer " << b.renderer
    << ", MAR slope " << fmt(b.options.session.acuity.slope, 4) << ", gaze "
    << (b.options.gaze.empty() ? "centre" : b.options.gaze) << ", " << b.options.frames
    << " measured frames after " << b.warmup
    << " warm-up, techniques interleaved frame by frame in an order shuffled every frame. Speedup "
       "is the ratio of mean frame times (95 % bootstrap interval); the pixel bound is native "
       "pixels / shaded pixels.</p>\n"
    << "<p class=note>Command: <code>" << escape_html(b.environment.command) << "</code>; foveate "
    << escape_html(b.environment.version) << ", " << escape_html(b.environment.date_utc) << ", CPU "
    << escape_html(b.environment.cpu_model) << " (" << b.environment.cores << " cores), load "
    << fmt(b.environment.load_start[0], 2) << " (1 min) at the start, "
    << fmt(b.environment.load_end[0], 2) << " at the end.</p>\n";
  for (const std::string& s : b.skipped)
    h << "<p class=note>Left out of the default list: " << escape_html(s) << ".</p>\n";
  if (b.gaze_fallback)
    h << "<p class=warn>The live gaze source never answered: every frame used the fallback gaze "
         "(--allow-fallback).</p>\n";
  h << "<table id=\"results\"><tr><th>technique</th><th>mean ms</th><th>median ms</th><th>p90 "
       "ms</th><th>speedup</th><th>95 % CI</th>"
       "<th>shaded px</th><th>pixel ratio</th><th>share of bound</th>";
  for (const QualityColumn& c : kQualityColumns) h << "<th>" << c.title << "</th>";
  h << "</tr>\n";
  for (const TechniqueResult& r : b.results) {
    h << "<tr><td>" << label(b, r) << "</td><td>" << fmt(r.mean_ms, 2) << "</td><td>"
      << fmt(r.median_ms, 2) << "</td><td>" << fmt(r.p90_ms, 2) << "</td><td>" << fmt(r.speedup, 2)
      << "x</td><td>" << fmt(r.speedup_lo, 2) << "-" << fmt(r.speedup_hi, 2) << "</td><td>"
      << fmt(r.shaded_pixels, 0) << "</td><td>" << fmt(r.pixel_ratio, 3) << "</td><td>"
      << fmt(100 * r.bound_share, 0) << " %</td>";
    for (const QualityColumn& c : kQualityColumns) h << "<td>" << quality_cell(r, c) << "</td>";
    h << "</tr>\n";
  }
  h << "</table>\n";
  if (b.options.passes) {
    h << "<h2>Where the time goes</h2>\n<p class=note>Mean ms per frame of each pass (share of "
         "the frame); "
      << (b.renderer.find("llvmpipe") != std::string::npos ? "each pass bracketed with glFinish"
                                                           : "GPU timestamp queries")
      << ". Resolve = composite, reconstruction, temporal, warps, blurs, upscales and copies.</p>\n"
      << "<table id=\"passes\"><tr><th>technique</th><th>passes</th><th>resolve share</th></tr>\n";
    for (const TechniqueResult& r : b.results) {
      h << "<tr><td>" << label(b, r) << "</td><td style=\"text-align:left\">";
      for (size_t i = 0; i < r.passes.size(); ++i) {
        const gpu::PassTime& p = r.passes[i];
        h << (i ? ", " : "") << p.name << ' ' << fmt(p.ms, 1) << " ms ("
          << fmt(100 * p.ms / r.mean_ms, 0) << " %)";
      }
      h << "</td><td>" << fmt(100 * resolve_ms(r) / r.mean_ms, 1) << " %</td></tr>\n";
    }
    h << "</table>\n";
  }

  const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                           "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
  h << "<h2>Speed</h2>\n";
  std::vector<std::string> names, qnames;
  std::vector<const TechniqueResult*> judged;
  BarSeries speed{"measured speedup (95 % bootstrap interval)", "#1f77b4", {}, {}, {}};
  BarSeries bound{"pixel bound (native / shaded pixels)", "#ff7f0e", {}, {}, {}};
  std::vector<std::vector<double>> frame_ms;
  for (const TechniqueResult& r : b.results) {
    names.push_back(label(b, r));
    speed.values.push_back(r.speedup);
    speed.lo.push_back(r.speedup_lo);
    speed.hi.push_back(r.speedup_hi);
    bound.values.push_back(1.0 / r.pixel_ratio);
    frame_ms.push_back(r.frame_ms);
    if (r.metrics) {
      qnames.push_back(label(b, r));
      judged.push_back(&r);
    }
  }
  h << "<div class=chart id=\"chart-speed\">"
    << svg_bar_chart(names, {speed, bound},
                     {"Speedup over native", "speedup over native (x, mean frame times)", true})
    << "</div>\n<div class=chart id=\"chart-frame-times\">"
    << svg_box_plot(names, frame_ms,
                    {"Frame times: every measured frame (dots), quartiles (box), median (line)",
                     "frame time (ms, steady clock around glFinish)", "", false, 760, 0, true})
    << "</div>\n";
  if (b.options.image_metrics && !judged.empty()) {
    // Speed against quality: one marker per technique (or swept value).
    std::vector<ScatterPoint> pts;
    for (size_t i = 0; i < judged.size(); ++i) {
      pts.push_back({qnames[i], colours[i % 10], judged[i]->speedup,
                     quality_value(*judged[i], mean_acuity_rmse)});
    }
    h << "<h2>Speed against quality</h2>\n<div class=chart id=\"chart-pareto\">"
      << svg_scatter(
             pts,
             {"Speed against the error the eye can resolve (lower right is better)",
              "speedup over native (x)", "acuity RMSE (8-bit codes)", false, 760, 440, true},
             false)
      << "</div>\n";
  }
  h << "<h2>Quality</h2>\n";
  if (b.options.image_metrics && !judged.empty()) {
    auto series_of = [&](double (*get)(const metrics::QualitySummary&), const char* name,
                         const char* colour) {
      BarSeries s{name, colour, {}, {}, {}};
      for (const TechniqueResult* r : judged) s.values.push_back(quality_value(*r, get));
      return s;
    };
    const BarSeries ssim = series_of(mean_ssim, "SSIM", "#1f77b4");
    const BarSeries acuity = series_of(mean_acuity_rmse, "acuity RMSE", "#d62728");
    const BarSeries jnd = series_of(
        [](const metrics::QualitySummary& q) { return q.mean.jnd_mean; }, "JND", "#2ca02c");
    const BarSeries flip = series_of(
        [](const metrics::QualitySummary& q) { return q.mean.flip_mean; }, "FLIP", "#9467bd");
    h << "<div class=chart id=\"chart-quality\">"
      << svg_bar_chart(qnames, {ssim},
                       {"Image similarity (the axis spans the data, not 0-1)",
                        "SSIM against the " +
                            std::string(b.reference_sample.empty() ? "native" : "reference") +
                            " (1 = identical)",
                        false, 760, 4})
      << "</div>\n<div class=chart id=\"chart-acuity\">"
      << svg_bar_chart(
             qnames, {acuity},
             {"Error the eye can resolve",
              "acuity-filtered RMSE (8-bit luminance codes; 0 = no visible loss)", true, 760, 2})
      << "</div>\n<div class=chart id=\"chart-jnd\">"
      << svg_bar_chart(qnames, {jnd},
                       {"Visibility of the difference",
                        "mean JND (Barten CSF; 1 = just noticeable)", true, 760, 2})
      << "</div>\n";
    bool have_flip = false;
    for (double v : flip.values) have_flip = have_flip || std::isfinite(v);
    if (have_flip) {
      h << "<div class=chart id=\"chart-flip\">"
        << svg_bar_chart(qnames, {flip},
                         {"FLIP (NVIDIA's perceptual error at the gaze's pixels per degree)",
                          "mean FLIP (0 = identical, 1 = maximal)", true, 760, 4})
        << "</div>\n";
    }
    // Per eccentricity band: SSIM, acuity RMSE and FLIP at each band's centre.
    std::vector<Series> band_ssim, band_flip, rmse_series, jnd_series;
    for (size_t i = 0; i < judged.size(); ++i) {
      const metrics::QualityReport& m = judged[i]->metrics->mean;
      Series s{qnames[i], colours[i % 10], {}, {}, i >= 10};
      Series f = s, e = s, v = s;
      for (const metrics::BandStats& band : m.bands) {
        if (!(band.pixels_fraction > 0)) continue;
        const double x =
            std::isinf(band.to_deg) ? band.from_deg + 5 : 0.5 * (band.from_deg + band.to_deg);
        s.x.push_back(x), s.y.push_back(band.ssim);
        f.x.push_back(x), f.y.push_back(band.flip_mean);
      }
      const metrics::EccentricityProfile& p = m.profile;
      for (size_t k = 0; k < p.acuity_rmse.size(); ++k) {
        // Bins with almost no pixels (the screen's far corners) are noise.
        if (!(p.pixels_fraction[k] >= 1e-3)) continue;
        const double x = (static_cast<double>(k) + 0.5) * p.bin_deg;
        e.x.push_back(x), e.y.push_back(p.acuity_rmse[k]);
        v.x.push_back(x), v.y.push_back(p.jnd_mean[k]);
      }
      band_ssim.push_back(std::move(s));
      band_flip.push_back(std::move(f));
      rmse_series.push_back(std::move(e));
      jnd_series.push_back(std::move(v));
    }
    const metrics::QualityReport& last = judged.back()->metrics->mean;
    h << "<h3>Against eccentricity</h3>\n<div class=chart id=\"chart-eccentricity\">"
      << svg_line_chart(rmse_series, {"Acuity-filtered error against eccentricity (" +
                                          fmt(last.profile.bin_deg, 1) + "-degree bins)",
                                      "eccentricity (degrees)", "acuity RMSE (8-bit codes)", false})
      << "</div>\n<div class=chart id=\"chart-eccentricity-jnd\">"
      << svg_line_chart(jnd_series,
                        {"Visibility against eccentricity (Barten CSF, Minkowski beta " +
                             fmt(last.contrast.pooling_beta, 0) + ")",
                         "eccentricity (degrees)", "mean JND (1 = just noticeable)", false})
      << "</div>\n<div class=chart id=\"chart-band-ssim\">"
      << svg_line_chart(band_ssim, {"SSIM per eccentricity band (at the band's centre; the last "
                                    "band drawn 5 degrees past its start)",
                                    "eccentricity (degrees)", "SSIM", false, 720, 440, false})
      << "</div>\n";
    if (have_flip) {
      h << "<div class=chart id=\"chart-band-flip\">"
        << svg_line_chart(band_flip, {"FLIP per eccentricity band", "eccentricity (degrees)",
                                      "mean FLIP", false})
        << "</div>\n";
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
    std::map<std::string, Series> speed_series;
    std::vector<ScatterPoint> sweep_points;
    int c = 0;
    for (const TechniqueResult& r : b.results) {
      if (r.technique == "native") continue;
      auto [it, fresh] = speed_series.try_emplace(r.technique);
      if (fresh) {
        it->second.name = r.technique;
        it->second.color = colours[c++ % 10];
      }
      it->second.x.push_back(r.sweep_value);
      it->second.y.push_back(r.speedup);
      if (r.metrics)
        sweep_points.push_back(
            {label(b, r), it->second.color, r.speedup, quality_value(r, mean_acuity_rmse)});
    }
    std::vector<Series> s1;
    for (auto& [k, v] : speed_series) s1.push_back(v);
    h << "<h2>Sweep of " << b.options.sweep.key
      << "</h2>\n<div class=chart id=\"chart-sweep-speed\">"
      << svg_line_chart(s1, {"Speedup against " + b.options.sweep.key, b.options.sweep.key,
                             "speedup over native (x)", false})
      << "</div>\n";
    if (!sweep_points.empty()) {
      h << "<div class=chart id=\"chart-sweep-quality\">"
        << svg_scatter(
               sweep_points,
               {"Quality against speed (sweep of " + b.options.sweep.key + ")",
                "speedup over native (x)", "acuity RMSE (8-bit codes)", false, 760, 440, true},
               false)
        << "</div>\n";
    }
  }
  // The layers or regions of each technique over its last frame.
  h << "<h2>Layers and regions</h2>\n<p class=note>Each technique's last measured frame with "
       "its layer or region borders and the gaze, as its overlay draws them (colours are the "
       "technique's own: see its section of the README).</p>\n<div class=crops>";
  for (const TechniqueResult& r : b.results) {
    if (r.technique == "native" || r.overlay.empty()) continue;
    h << "<figure>"
      << overlay_figure(r.sample, r.overlay, label(b, r) + " overlay", std::min(W, 480))
      << "<figcaption>" << label(b, r) << "</figcaption></figure>\n";
  }
  h << "</div>\n";
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
  h << "<figure>" << img_tag(crop(ref, gx, gy, cs), ref_name + " fovea", 2 * cs, cs <= 64)
    << "<figcaption>" << ref_name << ": fovea</figcaption></figure>\n";
  for (const TechniqueResult& r : b.results) {
    if (!supersampled && r.technique == "native") continue;
    const std::string name = label(b, r);
    std::string where;
    int px = gx < W / 2 ? W - 1 : 0, py = gy < H / 2 ? H - 1 : 0;  // without images: the corner
    // (Stereo samples hold two eyes side by side: no single display to judge them with.)
    if (!ref.empty() && r.sample.width == ref.width && r.sample.height == ref.height &&
        r.sample.width == W && b.display.width_px == W && b.display.height_px == H) {
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
    h << "<figure>" << img_tag(crop(r.sample, gx, gy, cs), name + " fovea", 2 * cs, cs <= 64) << " "
      << img_tag(crop(ref, px, py, cs), ref_name + " periphery", 2 * cs, cs <= 64) << " "
      << img_tag(crop(r.sample, px, py, cs), name + " periphery", 2 * cs, cs <= 64)
      << "<figcaption>" << name << ": fovea | " << ref_name << " and " << name
      << " in the periphery" << where << "</figcaption></figure>\n";
  }
  h << "</div>\n<h2>Error heat maps</h2>\n<p class=note>Left: absolute difference to the "
    << ref_name
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
  if (supersampled) {
    h << "<figure>" << img_tag(ref, "reference frame", std::min(W, 640), false, 640)
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
  // A self-check a browser runs on load (used by the tests, harmless otherwise):
  // images decoded, charts drawn, charts without tick labels or data, script errors.
  h << "<script>\nvar foveateErrors = 0;\nwindow.addEventListener('error', function () { "
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
  return h.str();
}

}  // namespace foveate::app
