// The charts of the HTML report: speed (per run, per pass, per frame),
// quality (overall, against eccentricity, temporal change per band) and
// sweeps. Every run is drawn in its technique's colour (run_colour).
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "foveate/bench/svg_plot.hpp"
#include "foveate/techniques/palette.hpp"
#include "report_common.hpp"

namespace foveate::bench {

namespace {

// The runs with quality figures, and their labels.
struct Judged {
  std::vector<std::string> names;
  std::vector<std::string> colours;
  std::vector<const TechniqueResult*> results;
};

Judged judged_runs(const BenchResult& b) {
  Judged j;
  for (const TechniqueResult& r : b.results) {
    if (!r.metrics) continue;
    j.names.push_back(label(b, r));
    j.colours.push_back(run_colour(b, r));
    j.results.push_back(&r);
  }
  return j;
}

// FovVideoVDP: the JOD of every run, and per eccentricity band.
std::string jod_charts(const BenchResult& b, const Judged& judged) {
  BarSeries jod{.name = "FovVideoVDP JOD", .colors = judged.colours};
  std::vector<Series> bands;
  for (size_t i = 0; i < judged.results.size(); ++i) {
    const TechniqueResult& r = *judged.results[i];
    jod.values.push_back(jod_of(r));
    Series s{judged.names[i], judged.colours[i], {}, {}, false};
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
  h << chart_div("chart-jod",
                 svg_bar_chart(
                     judged.names, {jod},
                     {.title = "Visible difference from the " +
                               std::string(b.reference_sample.empty() ? "native frames"
                                                                      : "supersampled reference"),
                      .value_label = "FovVideoVDP JOD (10 = none; the axis spans the data)",
                      .from_zero = false,
                      .digits = 4,
                      .unit = "JOD"}))
    << "<p class=note>Per eccentricity band: the JOD the sequence would get were the "
       "whole image like the band, drawn at the band's centre (the last band 5 degrees past its "
       "start).</p>\n"
    << chart_div("chart-jod-bands", svg_line_chart(bands, {.title = "JOD per eccentricity band",
                                                           .x_label = "eccentricity (degrees)",
                                                           .y_label = "FovVideoVDP JOD",
                                                           .y_from_zero = false}));
  return h.str();
}

std::string quality_bars(const BenchResult& b, const Judged& judged, bool& have_flip) {
  auto series_of = [&](double (*get)(const metrics::QualitySummary&), const char* name) {
    BarSeries s{.name = name, .colors = judged.colours};
    for (const TechniqueResult* r : judged.results) s.values.push_back(quality_value(*r, get));
    return s;
  };
  const BarSeries ssim = series_of(mean_ssim, "SSIM");
  const BarSeries acuity = series_of(mean_acuity_rmse, "acuity RMSE");
  const BarSeries jnd =
      series_of([](const metrics::QualitySummary& q) { return q.mean.jnd_mean; }, "JND");
  const BarSeries flip =
      series_of([](const metrics::QualitySummary& q) { return q.mean.flip_mean; }, "FLIP");
  const std::vector<std::string>& names = judged.names;
  std::ostringstream h;
  h << chart_div(
           "chart-quality",
           svg_bar_chart(
               names, {ssim},
               {.title = "Image similarity (the axis spans the data, not 0-1)",
                .value_label = "SSIM against the " +
                               std::string(b.reference_sample.empty() ? "native" : "reference") +
                               " (1 = identical)",
                .from_zero = false,
                .digits = 4}))
    << chart_div("chart-acuity",
                 svg_bar_chart(names, {acuity},
                               {.title = "Error the eye can resolve",
                                .value_label = "acuity-filtered RMSE (8-bit luminance codes; 0 = "
                                               "no visible loss)",
                                .unit = "codes"}))
    << chart_div("chart-jnd",
                 svg_bar_chart(names, {jnd},
                               {.title = "Visibility of the difference",
                                .value_label = "mean JND (Barten CSF; 1 = just noticeable)",
                                .unit = "JND"}));
  have_flip = false;
  for (double v : flip.values) have_flip = have_flip || std::isfinite(v);
  if (have_flip) {
    h << chart_div(
        "chart-flip",
        svg_bar_chart(names, {flip},
                      {.title = "FLIP (NVIDIA's perceptual error at the gaze's pixels per degree)",
                       .value_label = "mean FLIP (0 = identical, 1 = maximal)"}));
  }
  return h.str();
}

// Per eccentricity band: SSIM and FLIP at each band's centre; acuity RMSE
// and JND in 1-degree bins.
std::string eccentricity_charts(const Judged& judged, bool have_flip) {
  std::vector<Series> band_ssim, band_flip, rmse_series, jnd_series;
  for (size_t i = 0; i < judged.results.size(); ++i) {
    const metrics::QualityReport& m = judged.results[i]->metrics->mean;
    Series s{judged.names[i], judged.colours[i], {}, {}, false};
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
  h << "<h3>Against eccentricity</h3>\n"
    << chart_div(
           "chart-eccentricity",
           svg_line_chart(rmse_series,
                          {.title = "Acuity-filtered error against eccentricity (" +
                                    format_significant(last.profile.bin_deg, 2) + "-degree bins)",
                           .x_label = "eccentricity (degrees)",
                           .y_label = "acuity RMSE (8-bit codes)"}))
    << chart_div("chart-eccentricity-jnd",
                 svg_line_chart(jnd_series,
                                {.title = "Visibility against eccentricity (Barten CSF, "
                                          "Minkowski beta " +
                                          format_significant(last.contrast.pooling_beta, 2) + ")",
                                 .x_label = "eccentricity (degrees)",
                                 .y_label = "mean JND (1 = just noticeable)"}))
    << chart_div("chart-band-ssim",
                 svg_line_chart(band_ssim, {.title = "SSIM per eccentricity band (at the band's "
                                                     "centre; the last band drawn 5 degrees past "
                                                     "its start)",
                                            .x_label = "eccentricity (degrees)",
                                            .y_label = "SSIM",
                                            .y_from_zero = false}));
  if (have_flip) {
    h << chart_div("chart-band-flip",
                   svg_line_chart(band_flip, {.title = "FLIP per eccentricity band",
                                              .x_label = "eccentricity (degrees)",
                                              .y_label = "mean FLIP"}));
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
  for (const TechniqueResult* r : rows) {
    h << "<tr><td>" << label(b, *r) << "</td>";
    for (const metrics::FlickerBand& fb : r->metrics->flicker.bands) {
      h << "<td>" << cell(fb.test_change) << " (" << cell(fb.reference_change) << "), &times;"
        << cell(fb.ratio) << ", last " << cell(fb.test_change_last) << "</td>";
    }
    h << "</tr>\n";
  }
  h << "</table>\n";
  return h.str();
}

// Where each run's frame time goes: one stacked bar per run, a segment per
// pass (the same pass the same colour in every row), "other" the time
// outside every pass.
std::string passes_chart(const BenchResult& b) {
  if (!b.options.passes) return {};
  std::vector<std::string> rows, pass_names;
  for (const TechniqueResult& r : b.results) {
    if (r.passes.empty()) continue;
    rows.push_back(label(b, r));
    for (const gpu::PassTime& p : r.passes) {
      if (std::find(pass_names.begin(), pass_names.end(), p.name) == pass_names.end())
        pass_names.push_back(p.name);
    }
  }
  if (rows.empty()) return {};
  // "other" last, in grey: it is no pass of its own.
  const auto other = std::find(pass_names.begin(), pass_names.end(), "other");
  if (other != pass_names.end()) pass_names.erase(other), pass_names.push_back("other");
  // Paul Tol's muted and light schemes: passes are not techniques, so not
  // their colours; as many as a frame of the built-in techniques has passes.
  static const char* const kPassColours[] = {"#332288", "#88ccee", "#44aa99", "#117733", "#999933",
                                             "#ddcc77", "#cc6677", "#882255", "#aa4499", "#77aadd",
                                             "#ee8866", "#eedd88", "#ffaabb", "#99ddff", "#44bb99",
                                             "#bbcc33", "#aaaa00"};
  constexpr size_t kPassCount = std::size(kPassColours);
  std::vector<StackSegment> segments;
  for (size_t k = 0; k < pass_names.size(); ++k) {
    StackSegment g{
        pass_names[k], pass_names[k] == "other" ? "#bbbbbb" : kPassColours[k % kPassCount], {}};
    for (const TechniqueResult& r : b.results) {
      if (r.passes.empty()) continue;
      double ms = std::nan("");
      for (const gpu::PassTime& p : r.passes)
        if (p.name == pass_names[k]) ms = p.ms;
      g.values.push_back(ms);
    }
    segments.push_back(std::move(g));
  }
  return chart_div("chart-passes",
                   svg_stacked_bars(rows, segments,
                                    {.title = "Where the time goes: mean time per frame in each "
                                              "pass",
                                     .value_label = "mean time per frame (ms)",
                                     .unit = "ms"}));
}

}  // namespace

std::string html_speed(const BenchResult& b) {
  std::ostringstream h;
  h << "<h2>Speed</h2>\n";
  std::vector<std::string> names, colours;
  std::vector<Series> timeline;
  std::vector<std::vector<double>> frame_ms;
  for (const TechniqueResult& r : b.results) {
    names.push_back(label(b, r));
    colours.push_back(run_colour(b, r));
    frame_ms.push_back(r.frame_ms);
    Series t{names.back(), colours.back(), {}, r.frame_ms, false};
    for (size_t k = 0; k < r.frame_ms.size(); ++k) t.x.push_back(double(k + 1));
    timeline.push_back(std::move(t));
  }
  BarSeries speed{.name = "measured speedup (95 % bootstrap interval)", .colors = colours};
  BarSeries bound{
      .name = "pixel bound (native / shaded pixels)", .colors = colours, .opacity = 0.35};
  for (const TechniqueResult& r : b.results) {
    speed.values.push_back(r.speedup);
    speed.lo.push_back(r.speedup_lo);
    speed.hi.push_back(r.speedup_hi);
    bound.values.push_back(1.0 / r.pixel_ratio);
  }
  h << chart_div("chart-speed",
                 svg_bar_chart(names, {speed, bound},
                               {.title = "Speedup over native",
                                .value_label = "speedup over native (x, mean frame times)",
                                .unit = "x"}))
    << chart_div("chart-frame-times",
                 svg_box_plot(names, frame_ms,
                              {.title = "Frame times: every measured frame (dots), quartiles "
                                        "(box), median (line)",
                               .x_label = "frame time (ms, steady clock around glFinish)"},
                              colours))
    << "<p class=note>Each measured frame in the order it ran: the techniques take turns frame "
       "by frame, so a spike shared by all is the machine, one of a technique's own is "
       "the technique.</p>\n"
    << chart_div("chart-timeline",
                 svg_line_chart(timeline, {.title = "Frame time per measured frame",
                                           .x_label = "measured frame",
                                           .y_label = "frame time (ms)"}))
    << passes_chart(b);
  const Judged judged = judged_runs(b);
  if (b.options.image_metrics && !judged.results.empty()) {
    // Speed against quality: one marker per technique (or swept value).
    std::vector<ScatterPoint> pts;
    for (size_t i = 0; i < judged.results.size(); ++i) {
      const double jod = jod_of(*judged.results[i]);
      if (std::isfinite(jod))
        pts.push_back({judged.names[i], judged.colours[i], judged.results[i]->speedup, jod});
    }
    if (!pts.empty()) {
      h << "<h2>Speed against quality</h2>\n<p class=note>The Pareto front: no other run is both "
           "faster and closer to the reference (FovVideoVDP, JOD; native's "
        << cell(native_jod(b), 4) << ").</p>\n"
        << chart_div("chart-pareto",
                     svg_scatter(pts,
                                 {.title = "Speed against visible quality (upper right is better)",
                                  .x_label = "speedup over native (x)",
                                  .y_label = "FovVideoVDP JOD (10 = no visible difference)",
                                  .y_from_zero = false},
                                 true));
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
  for (const TechniqueResult& r : b.results) {
    if (r.technique == "native") continue;
    auto [it, fresh] = speed_series.try_emplace(r.technique);
    if (fresh) {
      it->second.name = r.technique;
      it->second.color = technique_colour_hex(r.technique);
    }
    it->second.x.push_back(r.sweep_value);
    it->second.y.push_back(r.speedup);
    if (r.metrics && std::isfinite(jod_of(r)))
      sweep_points.push_back({label(b, r), run_colour(b, r), r.speedup, jod_of(r)});
  }
  std::vector<Series> lines;
  for (auto& [k, v] : speed_series) lines.push_back(v);
  std::ostringstream h;
  h << "<h2>Sweep of " << key << "</h2>\n"
    << chart_div("chart-sweep-speed",
                 svg_line_chart(lines, {.title = "Speedup against " + key,
                                        .x_label = key,
                                        .y_label = "speedup over native (x)"}));
  if (!sweep_points.empty()) {
    h << chart_div("chart-sweep-quality",
                   svg_scatter(sweep_points,
                               {.title = "Visible quality against speed (sweep of " + key + ")",
                                .x_label = "speedup over native (x)",
                                .y_label = "FovVideoVDP JOD",
                                .y_from_zero = false},
                               true));
  }
  return h.str();
}

}  // namespace foveate::bench
