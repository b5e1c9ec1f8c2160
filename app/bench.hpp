#pragma once
// The benchmark: the same frames (camera, time, gaze) rendered with each
// technique in one process, interleaved frame by frame, timed with a steady
// clock around glFinish, and compared with native for quality.
#include <array>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "foveate/core/image.hpp"
#include "foveate/gpu/profiler.hpp"
#include "foveate/metrics/metrics.hpp"
#include "run_environment.hpp"
#include "session.hpp"

namespace foveate::app {

/// The most values one --sweep may have (each is a full run of the frames).
inline constexpr int kMaxSweepValues = 50;

/// --sweep KEY=FROM:TO:STEP: the MAR slope, a parameter of every technique
/// that declares it, or one technique's (TECHNIQUE.KEY).
struct Sweep {
  std::string key;        ///< as given ("slope", "KEY", "TECHNIQUE.KEY"); empty = no sweep
  std::string technique;  ///< empty = every technique that declares `param`
  std::string param;      ///< empty when the slope or the margin is swept
  std::vector<double> values;
  /// Parses and checks the text (at most 50 values; the key must exist).
  static Sweep parse(const std::string& text);
  [[nodiscard]] bool empty() const { return key.empty(); }
  /// Whether the run of `technique` is repeated for every value.
  [[nodiscard]] bool applies_to(const std::string& technique) const;
};

/// The order in which `runs` techniques render each of `frames` measured
/// frames: a permutation per frame, shuffled anew every frame from a fixed
/// seed (the same sequence every run), so that no technique is always first
/// or always follows the same one (on llvmpipe a pass can pay for the one
/// before it).
std::vector<std::vector<size_t>> interleaved_orders(size_t runs, int frames);

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
  /// Time every pass (--passes): bracketed with glFinish on software
  /// renderers, timestamp queries on a GPU. Adds a little to frame times.
  bool passes = false;
  Sweep sweep;
  std::string command_line;
  /// A video of the measured frames (empty = none): the reported runs tiled
  /// side by side (VideoWriter, tile); with `side_by_side`, native first even
  /// when not listed, and the gaze marked on every tile.
  std::string video;
  bool side_by_side = false;
  /// Leave out the techniques the scene cannot run (the default list) instead
  /// of refusing them.
  bool skip_unfit = false;
  /// A live gaze source (pupil) that does not answer within connect_timeout_s
  /// is an error unless this is set; then the fallback gaze is measured.
  bool allow_fallback = false;
  double connect_timeout_s = 3.0;
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
  /// With --passes: mean ms per frame of each pass, in the order first seen,
  /// ending with "other" (the frame's time outside every timed pass).
  std::vector<gpu::PassTime> passes;
  double pixel_ratio = 1;  ///< shaded / native
  double bound_share = 1;  ///< speedup / (native / shaded)
  /// Quality against native over the measured frames; empty for native itself
  /// and with --no-metrics.
  std::optional<metrics::QualitySummary> metrics;
  Image sample;  ///< last frame, for the report
  std::vector<OverlayShape>
      overlay;  ///< the technique's layers or regions at the last frame's gaze
  Image heatmap;
  Image acuity_heatmap;
  /// Stereo (--stereo): each eye's pixels and quality (left, right); the
  /// fields above are then both eyes together (time per stereo frame,
  /// pixels summed, quality over both eyes' frames) and the images are the
  /// two eyes side by side.
  struct Eye {
    double shaded_pixels = 0, native_pixels = 0, pixel_ratio = 1;
    std::optional<metrics::QualitySummary> metrics;
  };
  std::vector<Eye> eyes;  ///< empty unless stereo
};

struct BenchResult {
  BenchOptions options;
  RunEnvironment environment;
  int warmup = 0;  ///< warm-up frames run: options.warmup or more (Technique::settle_frames)
  std::string renderer;
  std::string scene;
  Display display;
  std::vector<TechniqueResult> results;
  Image native_sample;
  Image reference_sample;  ///< the supersampled reference's last frame (empty when native is)
  Vec2d sample_gaze_px;
  std::string gaze_report;
  std::string video_summary;         ///< one line about the video written (empty = none)
  std::vector<std::string> skipped;  ///< techniques left out of the default list, with the reason
  bool gaze_fallback = false;        ///< the live gaze source never answered (--allow-fallback)
  /// Stereo runs: both eyes' displays (display above is the left eye's).
  std::optional<StereoDisplay> stereo;
  std::array<Vec2d, 2> sample_eye_gaze_px{};  ///< each eye's gaze at the last frame
};

BenchResult run_bench(const BenchOptions& options);
/// The results as results.json holds them (schema in docs/bench-json.md).
nlohmann::json bench_json(const BenchResult& result);
/// Writes results.json, results.csv, results.md and report.html into options.out.
void write_bench_outputs(const BenchResult& result);
std::string bench_markdown(const BenchResult& result);

}  // namespace foveate::app
