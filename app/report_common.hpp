#pragma once
// What the benchmark's writers share (report.cpp: JSON, CSV, Markdown;
// report_html.cpp: the HTML page): the quality columns and the labels.
#include <cmath>
#include <iterator>
#include <string>

#include "bench.hpp"
#include "cli_util.hpp"

namespace foveate::app {

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

/// A quality figure, or NaN where not measured (native itself, --no-metrics).
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
  return std::isfinite(v) ? fmt(v, c.digits) : "-";
}

inline bool is_resolve_pass(const std::string& name) {
  for (const char* k : {"composite", "reconstruct", "temporal", "inverse", "resolve", "copy",
                        "warp", "blur", "upscale"}) {
    if (name.find(k) != std::string::npos) return true;
  }
  return false;
}

inline double resolve_ms(const TechniqueResult& r) {
  double ms = 0;
  for (const gpu::PassTime& p : r.passes)
    if (is_resolve_pass(p.name)) ms += p.ms;
  return ms;
}

inline std::string label(const BenchResult& b, const TechniqueResult& r) {
  if (b.options.sweep.key.empty() || r.technique == "native") return r.technique;
  return r.technique + " @ " + b.options.sweep.key + "=" + fmt(r.sweep_value, 4);
}

/// The HTML report.
std::string report_html(const BenchResult& b);

}  // namespace foveate::app
