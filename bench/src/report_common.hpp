#pragma once
// What the benchmark's writers share: the quality columns, the time spent
// resolving, and the labels of the runs.
#include <cmath>
#include <string>
#include <vector>

#include "foveate/bench/bench.hpp"
#include "foveate/core/format.hpp"
#include "foveate/core/parse.hpp"

namespace foveate::bench {

// The quality columns of the CSV, Markdown and HTML tables, read from the
// typed summary (the JSON writes all of it through metrics::to_json).
struct QualityColumn {
  const char* csv;    ///< CSV header
  const char* title;  ///< Markdown and HTML header
  int digits;
  double (*get)(const metrics::QualitySummary&);
};
inline constexpr QualityColumn kQualityColumns[] = {
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

/// FovVideoVDP's JOD of a run, NaN where not measured.
inline double jod_of(const TechniqueResult& r) {
  return r.metrics && r.metrics->fvvdp ? r.metrics->fvvdp->jod : std::nan("");
}
/// Native's JOD against the reference: 10 when native is the reference itself.
inline double native_jod(const BenchResult& b) {
  for (const TechniqueResult& r : b.results) {
    if (r.technique == "native" && std::isfinite(jod_of(r))) return jod_of(r);
  }
  return b.options.reference > 1 ? std::nan("") : 10.0;
}
/// How far a run's JOD is below native's (0 for native; NaN when unknown).
inline double jod_below_native(const BenchResult& b, const TechniqueResult& r) {
  return r.technique == "native" ? 0.0 : native_jod(b) - jod_of(r);
}

/// A quality figure, or NaN where not measured (native itself, no metrics).
inline double quality_value(const TechniqueResult& r,
                            double (*get)(const metrics::QualitySummary&)) {
  return r.metrics ? get(*r.metrics) : std::nan("");
}
inline double quality_value(const TechniqueResult& r, const QualityColumn& c) {
  return quality_value(r, c.get);
}
inline double mean_ssim(const metrics::QualitySummary& q) { return q.mean.ssim; }
inline double mean_acuity_rmse(const metrics::QualitySummary& q) { return q.mean.acuity_rmse; }

inline std::string quality_cell(const TechniqueResult& r, const QualityColumn& c) {
  const double v = quality_value(r, c);
  return std::isfinite(v) ? format_fixed(v, c.digits) : "-";
}

/// Mean ms per frame in the passes the technique declares as resolving
/// lower-resolution images into the output (TechniqueInfo::resolve_passes).
double resolve_ms(const TechniqueResult& r);

/// Each pass as "name 1.2 (30 %)": its mean ms per frame (followed by
/// `unit`) and its share of the frame, comma-separated.
std::string pass_list(const TechniqueResult& r, const char* unit);

/// "technique", or "technique @ KEY=VALUE" for a swept run.
inline std::string label(const BenchResult& b, const TechniqueResult& r) {
  if (!r.label.empty()) return r.label;
  if (b.options.sweep.key.empty() || r.technique == "native") return r.technique;
  return r.technique + " @ " + b.options.sweep.key + "=" + format_fixed(r.sweep_value, 4);
}

/// The marks a table row carries: " †" on a foveated technique where the
/// size leaves little to save (BenchResult::savings), " ‡" on every row when
/// some frames ran with the gaze in its fallback (BenchResult::fallback_frames).
std::string row_marks(const BenchResult& b, const TechniqueResult& r);
/// What the marks mean, one sentence each (empty when no row is marked).
std::vector<std::string> mark_notes(const BenchResult& b);

/// The HTML report's sections (report_html*.cpp).
std::string html_speed(const BenchResult& b);
std::string html_quality(const BenchResult& b);
std::string html_sweep(const BenchResult& b);
/// A run's colour in every chart: its technique's (techniques/palette.hpp),
/// so that a technique looks the same in every report; the second and later
/// runs of one technique (a sweep's values) take shades of it.
std::string run_colour(const BenchResult& b, const TechniqueResult& r);

/// A chart on the page: the SVG in a div of class "chart" with `id`, and a
/// link that downloads it as `id`.svg (the page's script makes the link
/// from the chart itself, so it works from the page alone; without script
/// it points at the file write_bench_report puts beside the page).
std::string chart_div(const std::string& id, const std::string& svg);

/// A number for a table cell: `digits` significant digits
/// (format_significant), "–" where not measured.
std::string cell(double v, int digits = 3);

}  // namespace foveate::bench
