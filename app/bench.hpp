#pragma once
// The benchmark: the same frames (camera, time, gaze) rendered with each
// technique in one process, interleaved frame by frame, timed with a steady
// clock around glFinish, and compared with native for quality.
#include <optional>
#include <string>
#include <vector>

#include "foveate/core/image.hpp"
#include "foveate/metrics/metrics.hpp"
#include "session.hpp"

namespace foveate::app {

/// The most values one --sweep may have (each is a full run of the frames).
inline constexpr int kMaxSweepValues = 50;

/// --sweep KEY=FROM:TO:STEP: the MAR slope, a parameter of every technique
/// that declares it, or one technique's (TECHNIQUE.KEY).
struct Sweep {
  std::string key;        ///< as given ("slope", "KEY", "TECHNIQUE.KEY"); empty = no sweep
  std::string technique;  ///< empty = every technique that declares `param`
  std::string param;      ///< empty when the slope is swept
  std::vector<double> values;
  /// Parses and checks the text (at most 50 values; the key must exist).
  static Sweep parse(const std::string& text);
  [[nodiscard]] bool empty() const { return key.empty(); }
  /// Whether the run of `technique` is repeated for every value.
  [[nodiscard]] bool applies_to(const std::string& technique) const;
};

struct BenchOptions {
  SessionOptions session;
  std::vector<std::string> techniques{"native", "layered", "logpolar", "checkerboard", "inset"};
  ParamArgs params;
  std::string gaze;  ///< gaze spec (see --gaze)
  int frames = 10;
  int warmup = 2;
  /// What the image metrics judge against: 1 = native itself, N > 1 = native
  /// with N x N supersampling (SupersampledReference), which native is then
  /// judged against too.
  int reference = 1;
  bool image_metrics = true;  ///< compare every frame with native (PSNR, SSIM, acuity error, ...)
  std::string out;            ///< output directory
  bool progress = true;
  Sweep sweep;
  std::string command_line;
};

struct TechniqueResult {
  std::string technique;
  double sweep_value = 0.0;
  std::vector<std::pair<std::string, double>> parameters;
  std::vector<double> frame_ms;
  std::vector<double> gpu_ms;  ///< GL_TIME_ELAPSED per frame on a real GPU (empty on llvmpipe)
  double median_ms = 0, p90_ms = 0, mean_ms = 0;
  double speedup = 1, speedup_lo = 1, speedup_hi = 1;
  double shaded_pixels = 0, native_pixels = 0;
  std::vector<PixelPart> parts;  ///< mean per frame
  double pixel_ratio = 1;        ///< shaded / native
  double bound_share = 1;        ///< speedup / (native / shaded)
  /// Quality against native over the measured frames; empty for native itself
  /// and with --no-metrics.
  std::optional<metrics::QualitySummary> metrics;
  Image sample;  ///< last frame, for the report
  Image heatmap;
  Image acuity_heatmap;
};

struct BenchResult {
  BenchOptions options;
  std::string renderer;
  std::string scene;
  Display display;
  std::vector<TechniqueResult> results;
  Image native_sample;
  Image reference_sample;  ///< the supersampled reference's last frame (empty when native is)
  Vec2d sample_gaze_px;
  std::string gaze_report;
};

BenchResult run_bench(const BenchOptions& options);
/// Writes results.json, results.csv, results.md and report.html into options.out.
void write_bench_outputs(const BenchResult& result);
std::string bench_markdown(const BenchResult& result);

}  // namespace foveate::app
