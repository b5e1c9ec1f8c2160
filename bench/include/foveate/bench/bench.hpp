#pragma once
// The benchmark: the same frames (camera, time, gaze) rendered with each
// technique in one process, interleaved frame by frame in an order shuffled
// every frame (interleaved_orders), timed with a steady clock around
// glFinish, and judged against a reference for quality.
#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "foveate/bench/environment.hpp"
#include "foveate/bench/params.hpp"
#include "foveate/bench/savings.hpp"
#include "foveate/bench/session.hpp"
#include "foveate/bench/sweep.hpp"
#include "foveate/core/image.hpp"
#include "foveate/gpu/profiler.hpp"
#include "foveate/metrics/metrics.hpp"

namespace foveate::bench {

/// A run of one technique with parameters of its own (foveate tune's
/// candidates): its own keys only, over its declared defaults.
struct RunSpec {
  std::string technique;
  std::map<std::string, double> params;
  /// How tables name the run; empty: "technique {key=value, ...}".
  std::string label;
};

/// One of several independent jobs a benchmark is split into: job `index`
/// (0-based) of `count` measures every count-th run (native in every job,
/// as each job's baseline); `foveate merge` joins the jobs' results.
struct Shard {
  int index = 0;
  int count = 1;
};
/// "K/N" (job K of N, 1-based, as `--shard` takes it); throws OptionError
/// (field "shard") for other text. validate() checks the range.
Shard parse_shard(const std::string& text);

/// Supersampled reference frames kept between benchmarks of the same frames
/// (tune's stages): frame k's image, rendered once.
struct ReferenceFrames {
  std::map<int, Image> frames;
};

struct BenchOptions {
  SessionOptions session;
  /// The techniques to measure; unset, every registered technique the scene
  /// can run (each one left out is said in a note and in the result).
  /// Native always runs, as the reference for speed.
  std::optional<std::vector<std::string>> techniques;
  ParamOverrides params;
  /// Explicit runs instead of `techniques` x `sweep` (native is added).
  std::vector<RunSpec> runs;
  /// Runs made only for how long they take to settle, never rendered: the
  /// warm-up lasts as long as theirs too, so that benchmarks of different
  /// runs measure the same frames (tune's stages). Those the scene cannot
  /// run are left out.
  std::vector<RunSpec> settle_runs;
  /// Explicit runs of a technique the scene cannot run (lodmask without
  /// meshes) are left out with a note instead of failing the benchmark.
  bool skip_unrunnable = false;
  Shard shard;
  /// With reference > 1: frames of the reference already rendered by a
  /// benchmark with the same session options are taken from here, and new
  /// ones added (null: rendered every time).
  std::shared_ptr<ReferenceFrames> reference_frames;
  int frames = 12;  ///< measured frames per technique
  int warmup = 2;   ///< at least; each technique warms up as long as it needs
  /// What the image metrics judge against: 1 = native itself, N > 1 = native
  /// with N x N supersampling (SupersampledNative), which native is then
  /// judged against too.
  int reference = 1;
  bool image_metrics = true;  ///< compare every frame with the reference (PSNR, SSIM, ...)
  /// Where every frame is read back (image metrics, video): time the frames
  /// in a pass that reads nothing back, then render them again to read them
  /// (RunEnvironment::timed_apart). Off, they are read back and judged
  /// between the timed renders, in one pass: cheaper, and on llvmpipe 5-12 %
  /// slower frames for the foveated techniques (tune's search, whose
  /// contenders stage 5 times again apart).
  bool time_apart = true;
  /// With image metrics: the diagnostics (PSNR, SSIM, acuity error, JND,
  /// FLIP, flicker) besides FovVideoVDP; off, FovVideoVDP alone (tune).
  bool diagnostics = true;
  /// Time every pass: bracketed with glFinish on software renderers,
  /// timestamp queries on a GPU. Adds a little to frame times.
  bool passes = false;
  Sweep sweep;
  std::string command;  ///< what started the run, recorded in the results
  /// A video of the measured frames (empty = none): the reported runs tiled
  /// side by side; with `side_by_side`, native first even when not listed,
  /// and the gaze marked on every tile.
  std::string video;
  bool side_by_side = false;
  /// A live gaze source (pupil) that does not answer within connect_timeout_s
  /// is an error unless this is set; then the fallback gaze is measured.
  bool allow_fallback = false;
  double connect_timeout_s = 3.0;
  /// The memory the judged runs may hold at once, in bytes (FovVideoVDP
  /// keeps about 200 bytes a pixel per run: 0.45 GB at 1920x1080); 0 = 70 %
  /// of what the machine has available when the benchmark starts. Runs that
  /// need more together are judged in groups, one group after another, each
  /// timed against its own native (as shards are), and joined into one
  /// result (BenchResult::memory_groups).
  double memory_limit_bytes = 0;
  /// Which group of this shard's runs to measure: run_bench deals them out
  /// (every count-th run from index) when they do not fit together.
  Shard group;
};

struct TechniqueResult {
  std::string technique;
  std::string label;  ///< an explicit run's label (RunSpec); empty otherwise
  /// The run's place among all runs of the benchmark (native 0), the same in
  /// every shard, so that merged shards keep the order of one run.
  int run_index = 0;
  double sweep_value = 0.0;
  std::vector<std::pair<std::string, double>> parameters;
  std::vector<double> frame_ms;
  std::vector<double> gpu_ms;  ///< GL_TIME_ELAPSED per frame on a real GPU (empty on llvmpipe)
  double median_ms = 0, p90_ms = 0, mean_ms = 0;
  double speedup = 1, speedup_lo = 1, speedup_hi = 1;
  double shaded_pixels = 0, native_pixels = 0;
  std::vector<PixelPart> parts;  ///< mean per frame
  /// With BenchOptions::passes: mean ms per frame of each pass, in the order
  /// first seen, ending with "other" (the frame's time outside every pass).
  std::vector<gpu::PassTime> passes;
  double pixel_ratio = 1;  ///< shaded / native
  double bound_share = 1;  ///< speedup / (native / shaded)
  /// Quality against the reference over the measured frames; empty for
  /// native judged against itself and without image metrics.
  std::optional<metrics::QualitySummary> metrics;
  Image sample;                       ///< last frame, for the report
  std::vector<OverlayShape> overlay;  ///< its layers or regions at the last frame's gaze
  /// FovVideoVDP's distortion map of the last frame over the reference
  /// (green invisible, red 1 JOD); empty without image metrics.
  Image fvvdp_heatmap;
  metrics::Map fvvdp_distortion;  ///< the map itself (JOD), mono runs
  Image heatmap;
  Image acuity_heatmap;
  /// Stereo: each eye's pixels and quality (left, right); the fields above
  /// are then both eyes together (time per stereo frame, pixels summed,
  /// quality over both eyes' frames) and the images the two eyes side by side.
  struct Eye {
    double shaded_pixels = 0, native_pixels = 0, pixel_ratio = 1;
    std::optional<metrics::QualitySummary> metrics;
  };
  std::vector<Eye> eyes;  ///< empty unless stereo
};

struct BenchResult {
  BenchOptions options;
  std::vector<std::string> techniques;  ///< those measured, as listed or by default
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
  bool gaze_fallback = false;        ///< the live gaze source never answered (allow_fallback)
  /// The measured frames (0-based) whose gaze lay off the image or was the
  /// gaze filter's fallback: every technique ran its fallback there, so
  /// their figures measure that, not foveation.
  std::vector<int> fallback_frames;
  /// The planner's bound at this size for the finest plan the run makes
  /// (check_savings): under kLittleToSaveBound the techniques have little to
  /// save, and the table marks them.
  SavingsCheck savings;
  /// Stereo runs: both eyes' displays (display above is the left eye's).
  std::optional<StereoDisplay> stereo;
  std::array<Vec2d, 2> sample_eye_gaze_px{};  ///< each eye's gaze at the last frame
  /// A result merged from this many shards (merge_shards); 0 for one run.
  int merged_shards = 0;
  /// The groups the runs were judged in to stay within the memory limit
  /// (BenchOptions::memory_limit_bytes): 1 = all at once.
  int memory_groups = 1;
  /// What shards of one benchmark share (results.json's "settings", as text;
  /// set by read_bench_results, empty for a result in memory).
  std::string settings_key;
};

/// What a benchmark tells its front end while it runs.
struct BenchCallbacks {
  SessionCallbacks session;
  /// Before the first frame: the steps the run will take, `metrics_steps`
  /// of them judging frames (as slow as rendering them on a CPU).
  std::function<void(int steps, int metrics_steps)> start;
  /// One step done: what it was, and its kind ("metrics", or empty).
  std::function<void(const std::string& detail, const std::string& kind)> step;
  /// Every frame rendered and judged.
  std::function<void()> finish;
};

/// Throws an OptionError naming the field of the first bad value (run_bench
/// checks them all before it creates anything).
void validate(const BenchOptions& options);

/// "technique {key=value, ...}": an explicit run's label when it has none.
std::string run_spec_label(const RunSpec& spec);

/// The memory the machine has available now, in bytes (Linux's
/// MemAvailable, else the free physical pages); 0 when it cannot tell.
double available_memory_bytes();

/// About how many bytes one run of `options` holds while it is judged (its
/// technique's targets and its quality series); 0 without image metrics.
double judged_run_bytes(const BenchOptions& options);

/// How many groups run_bench judges this shard's runs in, so that each
/// group's runs, native included, hold at most `limit_bytes` (0 = no limit:
/// one group). Throws an OptionError naming "memory_limit" when not even
/// native and one run fit, and "video" when a video (every run's frames
/// tiled) would need more than one group.
int judging_groups(const BenchOptions& options, double limit_bytes);

/// Runs the benchmark. Throws an OptionError naming the field of a bad value.
BenchResult run_bench(const BenchOptions& options, const BenchCallbacks& callbacks = {});

}  // namespace foveate::bench
