// The charts of the HTML report: speed, quality (overall, against
// eccentricity, temporal change per band) and sweeps.
#include <cmath>
#include <map>
#include <sstream>

#include "foveate/bench/svg_plot.hpp"
#include "report_common.hpp"

namespace foveate::bench {

namespace {

// The runs with quality figures, and their labels.
struct Judged {
  std::vector<std::string> names;
  std::vector<const TechniqueResult*> results;
};

Judged judged_runs(const BenchResult& b) {
  Judged j;
  for (const TechniqueResult& r : b.results) {
    if (!r.metrics) continue;
    j.names.push_back(label(b, r));
    j.results.push_back(&r);
  }
  return j;
}

// FovVideoVDP: the JOD of every run, and per eccentricity band.
std::string jod_charts(const BenchResult& b, const Judged& judged) {
  BarSeries jod{"FovVideoVDP JOD", "#1f77b4", {}, {}, {}};
  std::vector<Series> bands;
  for (size_t i = 0; i < judged.results.size(); ++i) {
    const TechniqueResult& r = *judged.results[i];
    jod.values.push_back(jod_of(r));
    Series s{judged.names[i], kSeriesColours[i % 10], {}, {}, i >= 10};
    if (r.metrics && r.metrics->fvvdp) {
      for (const metrics::FvvdpBand& band : r.metrics->fvvdp->bands) {
        if (!std::isfinite(band.jod)) continue;
        s.x.push_back(std::isinf(band.to_deg) ? band.from_deg + 5
                                              : 0.5 * (band.from_deg + band.to_deg));
        s.y.push_back(band.jod);
      }
    }
    bands.push_back(std::move(s));
  }
  bool any = false;
  for (double v : jod.values) any = any || std::isfinite(v);
  if (!any) return {};
  std::ostringstream h;
  h << "<div class=chart id=\"chart-jod\">"
    << svg_bar_chart(judged.names, {jod},
                     {"Visible difference from the " + std::string(b.reference_sample.empty()
                                                                       ? "native frames"
                                                                       : "supersampled reference"),
                      "FovVideoVDP JOD (10 = none; the axis spans the data)", false, 760, 3})
    << "</div>\n<p class=note>Per eccentricity band: the JOD the sequence would get were the "
       "whole image like the band, drawn at the band's centre (the last band 5 degrees past its "
       "start).</p>\n<div class=chart id=\"chart-jod-bands\">"
    << svg_line_chart(bands, {"JOD per eccentricity band", "eccentricity (degrees)",
                              "FovVideoVDP JOD", false, 720, 440, false})
    << "</div>\n";
  return h.str();
}

std::string quality_bars(const BenchResult& b, const Judged& judged, bool& have_flip) {
  auto series_of = [&](double (*get)(const metrics::QualitySummary&), const char* name,
                       const char* colour) {
    BarSeries s{name, colour, {}, {}, {}};
    for (const TechniqueResult* r : judged.results) s.values.push_back(quality_value(*r, get));
    return s;
  };
  const BarSeries ssim = series_of(mean_ssim, "SSIM", "#1f77b4");
  const BarSeries acuity = series_of(mean_acuity_rmse, "acuity RMSE", "#d62728");
  const BarSeries jnd =
      series_of([](const metrics::QualitySummary& q) { return q.mean.jnd_mean; }, "JND", "#2ca02c");
  const BarSeries flip = series_of(
      [](const metrics::QualitySummary& q) { return q.mean.flip_mean; }, "FLIP", "#9467bd");
  const std::vector<std::string>& names = judged.names;
  std::ostringstream h;
  h << "<div class=chart id=\"chart-quality\">"
    << svg_bar_chart(
           names, {ssim},
           {"Image similarity (the axis spans the data, not 0-1)",
            "SSIM against the " + std::string(b.reference_sample.empty() ? "native" : "reference") +
                " (1 = identical)",
            false, 760, 4})
    << "</div>\n<div class=chart id=\"chart-acuity\">"
    << svg_bar_chart(
           names, {acuity},
           {"Error the eye can resolve",
            "acuity-filtered RMSE (8-bit luminance codes; 0 = no visible loss)", true, 760, 2})
    << "</div>\n<div class=chart id=\"chart-jnd\">"
    << svg_bar_chart(names, {jnd},
                     {"Visibility of the difference", "mean JND (Barten CSF; 1 = just noticeable)",
                      true, 760, 2})
    << "</div>\n";
  have_flip = false;
  for (double v : flip.values) have_flip = have_flip || std::isfinite(v);
  if (have_flip) {
    h << "<div class=chart id=\"chart-flip\">"
      << svg_bar_chart(names, {flip},
                       {"FLIP (NVIDIA's perceptual error at the gaze's pixels per degree)",
                        "mean FLIP (0 = identical, 1 = maximal)", true, 760, 4})
      << "</div>\n";
  }
  return h.str();
}

// Per eccentricity band: SSIM and FLIP at each band's centre; acuity RMSE
// and JND in 1-degree bins.
std::string eccentricity_charts(const Judged& judged, bool have_flip) {
  std::vector<Series> band_ssim, band_flip, rmse_series, jnd_series;
  for (size_t i = 0; i < judged.results.size(); ++i) {
    const metrics::QualityReport& m = judged.results[i]->metrics->mean;
    Series s{judged.names[i], kSeriesColours[i % 10], {}, {}, i >= 10};
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
  const metrics::QualityReport& last = judged.results.back()->metrics->mean;
  std::ostringstream h;
  h << "<h3>Against eccentricity</h3>\n<div class=chart id=\"chart-eccentricity\">"
    << svg_line_chart(rmse_series, {"Acuity-filtered error against eccentricity (" +
                                        format_fixed(last.profile.bin_deg, 1) + "-degree bins)",
                                    "eccentricity (degrees)", "acuity RMSE (8-bit codes)", false})
    << "</div>\n<div class=chart id=\"chart-eccentricity-jnd\">"
    << svg_line_chart(jnd_series,
                      {"Visibility against eccentricity (Barten CSF, Minkowski beta " +
                           format_fixed(last.contrast.pooling_beta, 0) + ")",
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
  return h.str();
}

// Frame-to-frame change per eccentricity band.
std::string flicker_table(const BenchResult& b) {
  std::vector<const TechniqueResult*> rows;
  for (const TechniqueResult& r : b.results)
    if (r.metrics && !r.metrics->flicker.bands.empty()) rows.push_back(&r);
  if (rows.empty()) return {};
  std::ostringstream h;
  h << "<h3>Temporal change per eccentricity band</h3>\n<p class=note>Mean absolute "
       "frame-to-frame change of the luminance codes, technique (native) and their ratio; "
       "with a static camera the technique's change is its convergence, the last pair's "
       "value whether it has settled.</p>\n<table id=\"flicker\"><tr><th>technique</th>";
  for (const metrics::FlickerBand& fb : rows.front()->metrics->flicker.bands) {
    h << "<th>" << format_fixed(fb.from_deg, 0)
      << (std::isinf(fb.to_deg) ? "+" : "&ndash;" + format_fixed(fb.to_deg, 0)) << "&deg;</th>";
  }
  h << "</tr>\n";
  auto cell = [](double v, int digits) { return std::isfinite(v) ? format_fixed(v, digits) : "-"; };
  for (const TechniqueResult* r : rows) {
    h << "<tr><td>" << label(b, *r) << "</td>";
    for (const metrics::FlickerBand& fb : r->metrics->flicker.bands) {
      h << "<td>" << cell(fb.test_change, 2) << " (" << cell(fb.reference_change, 2) << "), &times;"
        << cell(fb.ratio, 2) << ", last " << cell(fb.test_change_last, 2) << "</td>";
    }
    h << "</tr>\n";
  }
  h << "</table>\n";
  return h.str();
}

}  // namespace

std::string html_speed(const BenchResult& b) {
  std::ostringstream h;
  h << "<h2>Speed</h2>\n";
  std::vector<std::string> names;
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
  }
  h << "<div class=chart id=\"chart-speed\">"
    << svg_bar_chart(names, {speed, bound},
                     {"Speedup over native", "speedup over native (x, mean frame times)", true})
    << "</div>\n<div class=chart id=\"chart-frame-times\">"
    << svg_box_plot(names, frame_ms,
                    {"Frame times: every measured frame (dots), quartiles (box), median (line)",
                     "frame time (ms, steady clock around glFinish)", "", false, 760, 0, true})
    << "</div>\n";
  const Judged judged = judged_runs(b);
  if (b.options.image_metrics && !judged.results.empty()) {
    // Speed against quality: one marker per technique (or swept value).
    std::vector<ScatterPoint> pts;
    for (size_t i = 0; i < judged.results.size(); ++i) {
      const double jod = jod_of(*judged.results[i]);
      if (std::isfinite(jod)) {
        pts.push_back({judged.names[i], kSeriesColours[i % 10], judged.results[i]->speedup, jod});
      }
    }
    if (!pts.empty()) {
      h << "<h2>Speed against quality</h2>\n<p class=note>The Pareto front: no other run is both "
           "faster and closer to the reference (FovVideoVDP, JOD; native's "
        << format_fixed(native_jod(b), 3) << ").</p>\n<div class=chart id=\"chart-pareto\">"
        << svg_scatter(
               pts,
               {"Speed against visible quality (upper right is better)", "speedup over native (x)",
                "FovVideoVDP JOD (10 = no visible difference)", false, 760, 440, false},
               true)
        << "</div>\n";
    }
  }
  return h.str();
}

std::string html_quality(const BenchResult& b) {
  const Judged judged = judged_runs(b);
  if (!b.options.image_metrics || judged.results.empty())
    return "<h2>Quality</h2>\n<p class=note>Not measured (image metrics off).</p>\n";
  bool have_flip = false;
  const std::string bars = quality_bars(b, judged, have_flip);
  return "<h2>Quality</h2>\n" + jod_charts(b, judged) +
         "<h3>Diagnostics</h3>\n<p class=note>foveate's own measures, not calibrated against "
         "observers: where a technique loses detail, not whether a viewer sees it.</p>\n" +
         bars + eccentricity_charts(judged, have_flip) + flicker_table(b);
}

std::string html_sweep(const BenchResult& b) {
  if (b.options.sweep.key.empty()) return {};
  const std::string& key = b.options.sweep.key;
  std::map<std::string, Series> speed_series;
  std::vector<ScatterPoint> sweep_points;
  int c = 0;
  for (const TechniqueResult& r : b.results) {
    if (r.technique == "native") continue;
    auto [it, fresh] = speed_series.try_emplace(r.technique);
    if (fresh) {
      it->second.name = r.technique;
      it->second.color = kSeriesColours[c++ % 10];
    }
    it->second.x.push_back(r.sweep_value);
    it->second.y.push_back(r.speedup);
    if (r.metrics && std::isfinite(jod_of(r)))
      sweep_points.push_back({label(b, r), it->second.color, r.speedup, jod_of(r)});
  }
  std::vector<Series> lines;
  for (auto& [k, v] : speed_series) lines.push_back(v);
  std::ostringstream h;
  h << "<h2>Sweep of " << key << "</h2>\n<div class=chart id=\"chart-sweep-speed\">"
    << svg_line_chart(lines, {"Speedup against " + key, key, "speedup over native (x)", false})
    << "</div>\n";
  if (!sweep_points.empty()) {
    h << "<div class=chart id=\"chart-sweep-quality\">"
      << svg_scatter(sweep_points,
                     {"Visible quality against speed (sweep of " + key + ")",
                      "speedup over native (x)", "FovVideoVDP JOD", false, 760, 440, false},
                     true)
      << "</div>\n";
  }
  return h.str();
}

}  // namespace foveate::bench
