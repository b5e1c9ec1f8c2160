#pragma once
// foveate tune: for every technique, the fastest parameters whose
// FovVideoVDP JOD stays within a bound of native's (both judged against the
// supersampled reference) on every scene given, searched over the parameters
// the techniques declare as trading quality for time (ParamDecl::tune).
//
// The search, per scene, in benchmarks that render every candidate beside
// native (timed in the same run, interleaved) and share the reference frames:
//  1. every tuned value of the planning margin, the other parameters at their
//     defaults;
//  2. from each technique's best point of stage 1 (the fastest within the
//     bound, else the closest to it), every other tuned parameter's values one
//     at a time, and the margin one step either side;
//  3. on that same point, the changes of stage 2 that kept the bound and
//     gained speed, combined;
//     and those that raised JOD, combined, at every margin below the best
//     point's (quality one parameter buys can pay for a coarser plan);
//  4. (several scenes) each scene's best settings on the other scenes;
//  5. the settings the choice falls between (within the bound, within 15 %
//     of the fastest one's speed, at most three per technique) timed again
//     side by side in one benchmark per scene, replacing their earlier
//     points: timings of different benchmarks differ by the machine's noise.
// Every stage of a scene shares its reference frames.
// A shard (TuneOptions::shard) runs a fixed grid instead (stage 1 crossed with
// stage 2's one-at-a-time changes at every margin), its slice of it, so that
// shards need nothing from each other; merge_tune_shards joins them.
#include <functional>
#include <map>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "foveate/bench/bench.hpp"
#include "foveate/bench/params_file.hpp"

namespace foveate::bench {

inline constexpr const char* kTuneSchema = "foveate-tune/1";

struct TuneOptions {
  /// The frames and how they are judged: size, display, gaze, clock, frames,
  /// warm-up, reference (ssaa:4 by default here), planning margin left unset.
  BenchOptions bench = default_bench();
  std::vector<std::string> scenes{"guenter", "raymarch"};
  /// Unset: every registered technique but native that a scene can run.
  std::optional<std::vector<std::string>> techniques;
  double bound_jod = 0.25;  ///< allowed distance below native's JOD
  /// Evaluate the fixed grid (every margin crossed with one other parameter
  /// changed at a time) instead of the staged search; shards always do.
  bool grid = false;
  Shard shard;
  /// The values tune tries for a parameter instead of those it declares
  /// (`foveate techniques` lists them): KEY (every technique tuned that
  /// declares it) or TECHNIQUE.KEY, each list ascending and checked as a
  /// sweep's; a parameter declared but not tuned becomes tuned. TECHNIQUE.KEY
  /// wins over KEY.
  std::map<std::string, std::vector<double>> values;
  /// The staged search (stages 1-5), not the fixed grid that `grid` and
  /// shards evaluate: only it times the contenders again in stage 5.
  [[nodiscard]] bool staged() const { return !grid && shard.count == 1; }

  static BenchOptions default_bench();
};

/// Settings within this share of the fastest one's speed tie with it in
/// tune's choice (timings of one setting differ by about that much between
/// runs): TuneResult::chosen.
inline constexpr double kTuneSpeedTie = 0.05;

/// One evaluated candidate on one scene.
struct TunePoint {
  std::string scene;
  std::string technique;
  std::map<std::string, double> params;  ///< the tuned keys' values (others at defaults)
  int stage = 1;
  double speedup = 0;
  /// The speedup's 95 % interval over the benchmark's frames
  /// (results.json's speedup_ci95): settings whose intervals overlap were
  /// not told apart by that run.
  double speedup_lo = 0, speedup_hi = 0;
  double jod = 0;
  double below_native = 0;  ///< native's JOD minus this one's
  double pixel_ratio = 1;
  bool within_bound = false;
};

struct TuneResult {
  TuneOptions options;
  RunEnvironment environment;
  std::string renderer;
  std::map<std::string, double> native_jod;  ///< per scene
  /// Warm-up frames of every benchmark of the run (the measured frames
  /// follow): the most any candidate needs to settle, at least
  /// options.bench.warmup.
  int warmup = 0;
  std::vector<TunePoint> points;
  /// Per technique: the fastest setting within the bound on every scene (by
  /// the geometric mean of its speedups), where settings within 5 % of its
  /// speed tie with it: of those the one with the least worst distance below
  /// native (within 0.01 JOD), then the fewest pixels, then the fastest. A
  /// technique with none within the bound keeps its closest setting and says
  /// so in `verdict`.
  TechniqueParams chosen;
  std::map<std::string, std::string> verdict;
  int merged_shards = 0;
  /// The settings shards of one run must share (tune.json's "settings", as text).
  std::string settings_key;
};

struct TuneCallbacks {
  BenchCallbacks bench;
  /// Before each benchmark: the scene, the stage and how many candidates.
  std::function<void(const std::string& scene, int stage, int candidates)> stage;
};

/// Throws an OptionError naming the field of a bad value.
void validate(const TuneOptions& options);
TuneResult run_tune(const TuneOptions& options, const TuneCallbacks& callbacks = {});

/// The front of one technique on one scene: its points no other point of it
/// beats in both speed and JOD, by speedup.
std::vector<TunePoint> tune_front(const TuneResult& r, const std::string& scene,
                                  const std::string& technique);
/// The best point of one technique on one scene: the fastest within the
/// bound, else the one closest to it; of stage `stage` only when it is above
/// 0. Stages 2 and 3 start from stage 1's: stage 2 changes one parameter of
/// it at a time, so stage 3 combines those changes on it, even where one of
/// them is now the faster point (they are not single changes of that one).
const TunePoint* tune_best_point(const std::vector<TunePoint>& points, const std::string& scene,
                                 const std::string& technique, int stage = 0);
/// Stage 3 of the search for one technique on one scene, from the point stage
/// 2 started from (tune_best_point of stage 1) and its stage-2 points (one
/// tuned parameter changed at a time from it): the changes that kept the
/// bound and gained speed, together (when there are two or more), and the
/// changes that raised JOD by more than 0.02, together at every margin below
/// that point's, the nearest first (quality one parameter buys can pay for a
/// coarser plan). `axes`: each tuned key and its values,
/// the margin's ascending.
std::vector<std::map<std::string, double>> tune_combinations(
    const std::vector<TunePoint>& stage2, const TunePoint& best,
    const std::vector<std::pair<std::string, std::vector<double>>>& axes);
/// Stage 5 of the search for one technique: the settings its choice falls
/// between, to be timed again side by side. Its best setting (within the
/// bound on every scene it ran on, fastest by the geometric mean of its
/// speedups) and the next ones within the bound whose speed is at least 0.85
/// of the best's, at most three in all, best first; none when fewer than two.
std::vector<std::map<std::string, double>> tune_contenders(const TuneResult& r,
                                                           const std::string& technique);
/// Chooses `chosen` and `verdict` from the points (run_tune and merging do).
void choose_parameters(TuneResult& r);

nlohmann::json tune_json(const TuneResult& r);
/// TuneResult::settings_key of a run with these options.
std::string tune_settings_key(const TuneOptions& options);
TuneResult read_tune_results(const nlohmann::json& j, const std::string& where);
/// Joins a tune run's shards (same version and settings, each once).
TuneResult merge_tune_shards(const std::vector<TuneResult>& shards,
                             const std::vector<std::string>& names);
std::string tune_markdown(const TuneResult& r);
/// tune.json, tune.md, params.json (the chosen parameters, for
/// --params-file) and report.html (every technique's front per scene) in `dir`.
void write_tune_report(const TuneResult& r, const std::string& dir);

}  // namespace foveate::bench
