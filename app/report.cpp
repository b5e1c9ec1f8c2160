// Benchmark outputs: JSON (schema in docs/bench-json.md), CSV, a Markdown
// table and a single-file HTML report that opens offline.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "bench.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"
#include "foveate/core/parse.hpp"
#include "foveate/core/stats.hpp"
#include "output_dir.hpp"
#include "report_common.hpp"

namespace foveate::app {

namespace {

// `{}` where quality was not measured (native itself, --no-metrics).
nlohmann::json quality_json(const TechniqueResult& r) {
  return r.metrics ? metrics::to_json(*r.metrics) : nlohmann::json::object();
}

nlohmann::json to_json(const BenchResult& b) {
  nlohmann::json results = nlohmann::json::array();
  for (const TechniqueResult& r : b.results) {
    nlohmann::json params = nlohmann::json::object();
    for (const auto& [k, v] : r.parameters) params[k] = v;
    nlohmann::json parts = nlohmann::json::array();
    for (const PixelPart& p : r.parts) parts.push_back({{"name", p.name}, {"pixels", p.pixels}});
    nlohmann::json j = {{"technique", r.technique},
                        {"label", label(b, r)},
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
                        {"quality", quality_json(r)},
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
        j["eyes"][eye_name(e)] = {
            {"shaded_pixels", eye.shaded_pixels},
            {"native_pixels", eye.native_pixels},
            {"pixel_ratio", eye.pixel_ratio},
            {"quality", eye.metrics ? metrics::to_json(*eye.metrics) : nlohmann::json::object()}};
      }
    }
    // GPU timer queries only where the renderer reports meaningful ones.
    j["gpu_median_ms"] = nullptr;
    if (!r.gpu_ms.empty()) j["gpu_median_ms"] = quantile(r.gpu_ms, 0.5);
    results.push_back(j);
  }
  nlohmann::json sweep = nullptr;
  if (!b.options.sweep.key.empty())
    sweep = {{"key", b.options.sweep.key}, {"values", b.options.sweep.values}};
  nlohmann::json stereo = nullptr;
  if (b.stereo) {
    const double v = b.options.session.vergence_m;
    stereo = {{"ipd_mm", b.stereo->ipd_mm},
              {"eye_size", {b.options.session.size.width, b.options.session.size.height}},
              {"output_size", {2 * b.options.session.size.width, b.options.session.size.height}},
              {"vergence_m", std::isfinite(v) ? nlohmann::json(v) : nlohmann::json("inf")},
              {"left", b.stereo->left},
              {"right", b.stereo->right},
              {"sample_gaze_px",
               {{"left", {b.sample_eye_gaze_px[0].x, b.sample_eye_gaze_px[0].y}},
                {"right", {b.sample_eye_gaze_px[1].x, b.sample_eye_gaze_px[1].y}}}}};
  }
  return {
      {"schema", "foveate-bench/1"},
      {"command", b.environment.command},
      {"environment",
       {{"foveate_version", b.environment.version},
        {"date_utc", b.environment.date_utc},
        {"renderer", b.environment.renderer},
        {"gl_version", b.environment.gl_version},
        {"cpu_model", b.environment.cpu_model},
        {"cpu_cores", b.environment.cores},
        {"load_average_start", b.environment.load_start},
        {"load_average_end", b.environment.load_end}}},
      {"renderer", b.renderer},
      {"scene", b.scene},
      {"size", {b.options.session.size.width, b.options.session.size.height}},
      {"display", b.display},
      {"acuity",
       {{"slope", b.options.session.acuity.slope}, {"w0_deg", b.options.session.acuity.w0_deg}}},
      {"margin",
       b.options.session.margin ? nlohmann::json(*b.options.session.margin) : nlohmann::json()},
      {"gaze", b.options.gaze.empty() ? "centre" : b.options.gaze},
      {"gaze_fallback", b.gaze_fallback},
      {"skipped", b.skipped},
      {"reference", b.options.reference > 1 ? "ssaa:" + std::to_string(b.options.reference)
                                            : std::string("native")},
      {"frames", b.options.frames},
      {"warmup", b.warmup},
      {"fps_clock", b.options.session.fps},
      {"sweep", sweep},
      {"stereo", stereo},
      {"results", results}};
}

std::string csv(const BenchResult& b) {
  std::ostringstream s;
  s << "technique,label,sweep_value,mean_ms,median_ms,p90_ms,speedup,speedup_lo,speedup_hi,shaded_"
       "pixels,"
       "native_pixels,pixel_ratio,bound_share";
  for (const QualityColumn& c : kQualityColumns) s << ',' << c.csv;
  s << '\n';
  for (const TechniqueResult& r : b.results) {
    s << r.technique << ',' << '"' << label(b, r) << '"' << ',' << format_number(r.sweep_value)
      << ',' << format_number(r.mean_ms, 3) << ',' << format_number(r.median_ms, 3) << ','
      << format_number(r.p90_ms, 3) << ',' << format_number(r.speedup, 4) << ','
      << format_number(r.speedup_lo, 4) << ',' << format_number(r.speedup_hi, 4) << ','
      << format_number(r.shaded_pixels, 1) << ',' << format_number(r.native_pixels, 0) << ','
      << format_number(r.pixel_ratio) << ',' << format_number(r.bound_share, 4);
    for (const QualityColumn& c : kQualityColumns) {
      const double v = quality_value(r, c);
      s << ',' << (std::isfinite(v) ? format_number(v) : std::string());
    }
    s << '\n';
  }
  return s.str();
}

std::string passes_markdown(const BenchResult& b) {
  if (!b.options.passes) return {};
  std::ostringstream s;
  s << "\nTime per pass, ms per frame (share of the frame). Resolve = composite, reconstruction, "
       "temporal, warps, blurs, upscales and copies.\n\n| technique | passes | resolve share "
       "|\n|---|---|---:|\n";
  for (const TechniqueResult& r : b.results) {
    s << "| " << label(b, r) << " | ";
    for (size_t i = 0; i < r.passes.size(); ++i) {
      const gpu::PassTime& p = r.passes[i];
      s << (i ? ", " : "") << p.name << ' ' << fmt(p.ms, 1) << " ("
        << fmt(100 * p.ms / r.mean_ms, 0) << " %)";
    }
    s << " | " << fmt(100 * resolve_ms(r) / r.mean_ms, 1) << " % |\n";
  }
  return s.str();
}

}  // namespace

std::string bench_markdown(const BenchResult& b) {
  std::ostringstream s;
  s << "| technique | mean ms | median ms | p90 ms | speedup (95 % CI) | shaded px | pixel ratio "
       "| share of bound |";
  for (const QualityColumn& c : kQualityColumns) s << ' ' << c.title << " |";
  s << "\n|---|---:|---:|---:|---:|---:|---:|---:|";
  for (size_t i = 0; i < std::size(kQualityColumns); ++i) s << "---:|";
  s << '\n';
  for (const TechniqueResult& r : b.results) {
    s << "| " << label(b, r) << " | " << fmt(r.mean_ms, 2) << " | " << fmt(r.median_ms, 2) << " | "
      << fmt(r.p90_ms, 2) << " | " << fmt(r.speedup, 2) << "x (" << fmt(r.speedup_lo, 2) << "-"
      << fmt(r.speedup_hi, 2) << ") | " << fmt(r.shaded_pixels, 0) << " | " << fmt(r.pixel_ratio, 3)
      << " | " << fmt(100 * r.bound_share, 0) << " % |";
    for (const QualityColumn& c : kQualityColumns) s << ' ' << quality_cell(r, c) << " |";
    s << '\n';
  }
  if (b.stereo) {
    s << "\nStereo: " << b.options.session.size.width << 'x' << b.options.session.size.height
      << " per eye, IPD " << fmt(b.stereo->ipd_mm, 1)
      << " mm. Times above are per stereo frame (both eyes), pixels both eyes' and quality over "
         "both eyes' frames; per eye:\n\n| technique | eye | shaded px | pixel ratio |";
    for (const QualityColumn& c : kQualityColumns) s << ' ' << c.title << " |";
    s << "\n|---|---|---:|---:|";
    for (size_t i = 0; i < std::size(kQualityColumns); ++i) s << "---:|";
    s << '\n';
    for (const TechniqueResult& r : b.results) {
      for (Eye e : kEyes) {
        if (r.eyes.size() != 2) continue;
        const TechniqueResult::Eye& eye = r.eyes[static_cast<size_t>(e)];
        s << "| " << label(b, r) << " | " << eye_name(e) << " | " << fmt(eye.shaded_pixels, 0)
          << " | " << fmt(eye.pixel_ratio, 3) << " |";
        for (const QualityColumn& c : kQualityColumns) {
          const double v = eye.metrics ? c.get(*eye.metrics) : std::nan("");
          s << ' ' << (std::isfinite(v) ? fmt(v, c.digits) : std::string("-")) << " |";
        }
        s << '\n';
      }
    }
  }
  s << passes_markdown(b);
  return s.str();
}

nlohmann::json bench_json(const BenchResult& b) { return to_json(b); }

void write_bench_outputs(const BenchResult& b) {
  namespace fs = std::filesystem;
  make_output_dir(b.options.out, "--out");
  const fs::path dir(b.options.out);
  write_file_atomic((dir / "results.json").string(), bench_json(b).dump(2) + "\n");
  write_file_atomic((dir / "results.csv").string(), csv(b));
  write_file_atomic((dir / "results.md").string(), bench_markdown(b));
  write_file_atomic((dir / "report.html").string(), report_html(b));
}

}  // namespace foveate::app
