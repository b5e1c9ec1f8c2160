// results.json (schema in docs/bench-json.md).
#include <cmath>
#include <nlohmann/json.hpp>

#include "foveate/bench/merge.hpp"
#include "foveate/bench/report.hpp"
#include "foveate/core/stats.hpp"
#include "report_common.hpp"

namespace foveate::bench {

namespace {

// `{}` where quality was not measured (native itself, no metrics).
nlohmann::json quality_json(const std::optional<metrics::QualitySummary>& q) {
  return q ? metrics::to_json(*q) : nlohmann::json::object();
}

nlohmann::json result_json(const BenchResult& b, const TechniqueResult& r) {
  nlohmann::json params = nlohmann::json::object();
  for (const auto& [k, v] : r.parameters) params[k] = v;
  nlohmann::json parts = nlohmann::json::array();
  for (const PixelPart& p : r.parts) parts.push_back({{"name", p.name}, {"pixels", p.pixels}});
  nlohmann::json j = {{"technique", r.technique},
                      {"label", label(b, r)},
                      {"run_index", r.run_index},
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
                      {"quality", quality_json(r.metrics)},
                      {"frame_ms", r.frame_ms}};
  j["passes"] = nullptr;
  j["resolve_share"] = nullptr;
  if (!r.passes.empty()) {
    nlohmann::json passes = nlohmann::json::array();
    for (const gpu::PassTime& p : r.passes)
      passes.push_back({{"name", p.name}, {"ms", p.ms}, {"share", p.ms / r.mean_ms}});
    j["passes"] = passes;
    j["resolve_share"] = resolve_ms(r) / r.mean_ms;
  }
  if (!b.options.sweep.key.empty()) j["sweep_value"] = r.sweep_value;
  if (!r.eyes.empty()) {
    // Stereo: time is per stereo frame and the figures above cover both
    // eyes; here each eye's own.
    for (Eye e : kEyes) {
      const TechniqueResult::Eye& eye = r.eyes[static_cast<size_t>(e)];
      j["eyes"][eye_name(e)] = {{"shaded_pixels", eye.shaded_pixels},
                                {"native_pixels", eye.native_pixels},
                                {"pixel_ratio", eye.pixel_ratio},
                                {"quality", quality_json(eye.metrics)}};
    }
  }
  // GPU timer queries only where the renderer reports meaningful ones.
  j["gpu_median_ms"] = nullptr;
  if (!r.gpu_ms.empty()) j["gpu_median_ms"] = quantile(r.gpu_ms, 0.5);
  return j;
}

nlohmann::json stereo_json(const BenchResult& b) {
  if (!b.stereo) return nullptr;
  const PixelSize size = b.options.session.size;
  const std::optional<double> v = b.options.session.vergence_m;
  return {{"ipd_mm", b.stereo->ipd_mm},
          {"eye_size", {size.width, size.height}},
          {"output_size", {2 * size.width, size.height}},
          {"vergence_m", v && std::isfinite(*v) ? nlohmann::json(*v) : nlohmann::json("inf")},
          {"left", b.stereo->left},
          {"right", b.stereo->right},
          {"sample_gaze_px",
           {{"left", {b.sample_eye_gaze_px[0].x, b.sample_eye_gaze_px[0].y}},
            {"right", {b.sample_eye_gaze_px[1].x, b.sample_eye_gaze_px[1].y}}}}};
}

nlohmann::json environment_json(const RunEnvironment& e) {
  return {{"foveate_version", e.version},
          {"date_utc", e.date_utc},
          {"renderer", e.renderer},
          {"gl_version", e.gl_version},
          {"cpu_model", e.cpu_model},
          {"cpu_cores", e.cores},
          {"load_average_start", e.load_start},
          {"load_average_end", e.load_end},
          {"others_cpu_share",
           e.others_cpu_share >= 0 ? nlohmann::json(e.others_cpu_share) : nlohmann::json()},
          {"pass_by_pass", e.pass_by_pass},
          {"timed_apart", e.timed_apart},
          {"variables", e.variables}};
}

}  // namespace

// What must be equal for shards of one benchmark to be merged (bench_json's
// "settings"): everything that decides the frames and how they are judged.
nlohmann::json bench_settings_json(const BenchResult& b) {
  const BenchOptions& o = b.options;
  const SessionOptions& s = o.session;
  nlohmann::json runs = nlohmann::json::array();
  for (const RunSpec& r : o.runs)
    runs.push_back({{"technique", r.technique}, {"params", r.params}});
  nlohmann::json params = nlohmann::json::object();
  for (const auto& [t, kv] : o.params.per_technique) params[t] = kv;
  return {{"scene", s.scene},
          {"size", {s.size.width, s.size.height}},
          {"display", b.display},
          {"acuity", {{"slope", s.acuity.slope}, {"w0_deg", s.acuity.w0_deg}}},
          {"margin", s.margin ? nlohmann::json(*s.margin) : nlohmann::json()},
          {"gaze", s.gaze},
          {"fps", s.fps},
          {"start_time_s", s.start_time_s},
          {"stereo", s.stereo},
          {"techniques", o.techniques ? nlohmann::json(*o.techniques) : nlohmann::json()},
          {"params", params},
          {"runs", runs},
          {"sweep", {{"key", o.sweep.key}, {"values", o.sweep.values}}},
          {"frames", o.frames},
          {"warmup", o.warmup},
          {"reference", o.reference},
          {"image_metrics", o.image_metrics},
          {"diagnostics", o.diagnostics},
          {"passes", o.passes},
          {"shards", o.shard.count}};
}

nlohmann::json bench_json(const BenchResult& b) {
  nlohmann::json results = nlohmann::json::array();
  for (const TechniqueResult& r : b.results) results.push_back(result_json(b, r));
  nlohmann::json sweep = nullptr;
  if (!b.options.sweep.key.empty())
    sweep = {{"key", b.options.sweep.key}, {"values", b.options.sweep.values}};
  const SessionOptions& s = b.options.session;
  return {{"schema", "foveate-bench/1"},
          {"command", b.environment.command},
          {"environment", environment_json(b.environment)},
          {"renderer", b.renderer},
          {"scene", b.scene},
          {"size", {s.size.width, s.size.height}},
          {"display", b.display},
          {"acuity", {{"slope", s.acuity.slope}, {"w0_deg", s.acuity.w0_deg}}},
          {"margin", s.margin ? nlohmann::json(*s.margin) : nlohmann::json()},
          {"gaze", s.gaze.empty() ? "centre" : s.gaze},
          {"gaze_fallback", b.gaze_fallback},
          {"gaze_fallback_frames", b.fallback_frames},
          {"gaze_report", b.gaze_report.empty() ? nlohmann::json() : nlohmann::json(b.gaze_report)},
          {"savings",
           {{"pixel_bound", b.savings.pixel_bound},
            {"margin", b.savings.margin},
            {"little_to_save", b.savings.nothing_to_save}}},
          {"skipped", b.skipped},
          {"reference", b.options.reference > 1 ? "ssaa:" + std::to_string(b.options.reference)
                                                : std::string("native")},
          {"frames", b.options.frames},
          {"warmup", b.warmup},
          {"fps_clock", s.fps},
          {"sweep", sweep},
          {"stereo", stereo_json(b)},
          {"shard", b.merged_shards > 0 ? nlohmann::json{{"merged", b.merged_shards}}
                                        : nlohmann::json{{"index", b.options.shard.index},
                                                         {"count", b.options.shard.count}}},
          {"memory_groups", b.memory_groups},
          {"settings", bench_settings_json(b)},
          {"results", results}};
}

}  // namespace foveate::bench
