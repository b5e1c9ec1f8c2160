// What foveate tune writes (tune.json, tune.md, params.json, report.html),
// reading it back, and joining shards.
#include <cctype>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "foveate/bench/report.hpp"
#include "foveate/bench/svg_plot.hpp"
#include "foveate/bench/tune.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"
#include "foveate/techniques/palette.hpp"
#include "report_common.hpp"
#include "shard_check.hpp"

namespace foveate::bench {

namespace {

nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

double number_at(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  return it == j.end() || !it->is_number() ? std::nan("") : it->get<double>();
}

// What shards of one tune run share.
nlohmann::json tune_settings(const TuneOptions& o) {
  const SessionOptions& s = o.bench.session;
  return {{"scenes", o.scenes},
          {"techniques", o.techniques ? nlohmann::json(*o.techniques) : nlohmann::json()},
          {"bound_jod", o.bound_jod},
          {"grid", o.grid || o.shard.count > 1},
          {"size", {s.size.width, s.size.height}},
          {"display", s.display},
          {"photometry",
           {{"peak_cd_m2", number(s.photometry.peak_cd_m2.value_or(std::nan("")))},
            {"contrast_ratio", number(s.photometry.contrast_ratio.value_or(std::nan("")))},
            {"ambient_lux", number(s.photometry.ambient_lux.value_or(std::nan("")))},
            {"reflectivity", number(s.photometry.reflectivity.value_or(std::nan("")))}}},
          {"acuity", {{"slope", s.acuity.slope}, {"w0_deg", s.acuity.w0_deg}}},
          {"gaze", s.gaze},
          {"fps", s.fps},
          {"frames", o.bench.frames},
          {"warmup", o.bench.warmup},
          {"reference", o.bench.reference},
          {"values", o.values},
          {"shards", o.shard.count}};
}

std::string params_text(const std::map<std::string, double>& p) {
  if (p.empty()) return "defaults";
  std::string s;
  for (const auto& [k, v] : p) s += (s.empty() ? "" : ", ") + k + "=" + format_number(v, 4);
  return s;
}

std::vector<std::string> techniques_of(const TuneResult& r) {
  std::set<std::string> set;
  for (const TunePoint& p : r.points) set.insert(p.technique);
  return {set.begin(), set.end()};
}

}  // namespace

std::string tune_settings_key(const TuneOptions& options) { return tune_settings(options).dump(); }

nlohmann::json tune_json(const TuneResult& r) {
  nlohmann::json points = nlohmann::json::array();
  for (const TunePoint& p : r.points) {
    points.push_back({{"scene", p.scene},
                      {"technique", p.technique},
                      {"params", p.params},
                      {"stage", p.stage},
                      {"speedup", number(p.speedup)},
                      {"speedup_ci95", {number(p.speedup_lo), number(p.speedup_hi)}},
                      {"jod", number(p.jod)},
                      {"below_native", number(p.below_native)},
                      {"pixel_ratio", number(p.pixel_ratio)},
                      {"within_bound", p.within_bound}});
  }
  nlohmann::json native = nlohmann::json::object();
  for (const auto& [scene, jod] : r.native_jod) native[scene] = number(jod);
  nlohmann::json chosen = nlohmann::json::object();
  for (const auto& [t, p] : r.chosen) chosen[t] = p;
  return {{"schema", kTuneSchema},
          {"command", r.environment.command},
          {"environment",
           {{"foveate_version", r.environment.version},
            {"date_utc", r.environment.date_utc},
            {"renderer", r.environment.renderer},
            {"cpu_model", r.environment.cpu_model},
            {"cpu_cores", r.environment.cores},
            {"variables", r.environment.variables}}},
          {"renderer", r.renderer},
          {"settings", tune_settings(r.options)},
          {"shard", r.merged_shards > 0 ? nlohmann::json{{"merged", r.merged_shards}}
                                        : nlohmann::json{{"index", r.options.shard.index},
                                                         {"count", r.options.shard.count}}},
          {"native_jod", native},
          {"warmup_frames", r.warmup},
          {"points", points},
          {"chosen", chosen},
          {"verdict", r.verdict}};
}

TuneResult read_tune_results(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object() || j.value("schema", "") != kTuneSchema) {
    throw Error(where + ": not a foveate tune run's results (schema " + kTuneSchema + ")");
  }
  TuneResult r;
  const nlohmann::json s = j.value("settings", nlohmann::json::object());
  TuneOptions& o = r.options;
  o.scenes = s.value("scenes", std::vector<std::string>{});
  if (s.contains("techniques") && s["techniques"].is_array())
    o.techniques = s["techniques"].get<std::vector<std::string>>();
  o.bound_jod = s.value("bound_jod", 0.25);
  o.grid = s.value("grid", false);
  if (const auto size = s.find("size"); size != s.end() && size->size() == 2)
    o.bench.session.size = {(*size)[0].get<int>(), (*size)[1].get<int>()};
  o.bench.session.display = s.value("display", o.bench.session.display);
  o.bench.session.gaze = s.value("gaze", "");
  o.bench.session.fps = s.value("fps", 60.0);
  o.bench.frames = s.value("frames", o.bench.frames);
  o.bench.warmup = s.value("warmup", o.bench.warmup);
  o.bench.reference = s.value("reference", o.bench.reference);
  o.values = s.value("values", std::map<std::string, std::vector<double>>{});
  if (const auto sh = j.find("shard"); sh != j.end() && sh->contains("count")) {
    o.shard.index = sh->value("index", 0);
    o.shard.count = sh->value("count", 1);
  }
  const nlohmann::json env = j.value("environment", nlohmann::json::object());
  r.environment.command = j.value("command", "");
  r.environment.version = env.value("foveate_version", "");
  r.environment.date_utc = env.value("date_utc", "");
  r.environment.renderer = env.value("renderer", "");
  r.environment.cpu_model = env.value("cpu_model", "");
  r.environment.cores = env.value("cpu_cores", 0u);
  r.environment.variables = env.value("variables", std::map<std::string, std::string>{});
  r.renderer = j.value("renderer", "");
  r.warmup = j.value("warmup_frames", 0);
  const nlohmann::json native_jod = j.value("native_jod", nlohmann::json::object());
  for (const auto& [scene, jod] : native_jod.items())
    r.native_jod[scene] = jod.is_number() ? jod.get<double>() : std::nan("");
  for (const auto& p : j.value("points", nlohmann::json::array())) {
    TunePoint t;
    t.scene = p.value("scene", "");
    t.technique = p.value("technique", "");
    t.params = p.value("params", std::map<std::string, double>{});
    t.stage = p.value("stage", 1);
    t.speedup = number_at(p, "speedup");
    // Absent from the files of foveate before 2026-11-28: unknown.
    const nlohmann::json ci = p.value("speedup_ci95", nlohmann::json::array());
    const auto bound = [&](size_t i) {
      return ci.is_array() && ci.size() == 2 && ci[i].is_number() ? ci[i].get<double>()
                                                                  : std::nan("");
    };
    t.speedup_lo = bound(0);
    t.speedup_hi = bound(1);
    t.jod = number_at(p, "jod");
    t.below_native = number_at(p, "below_native");
    t.pixel_ratio = number_at(p, "pixel_ratio");
    t.within_bound = p.value("within_bound", false);
    r.points.push_back(t);
  }
  choose_parameters(r);
  r.settings_key = s.dump();
  return r;
}

TuneResult merge_tune_shards(const std::vector<TuneResult>& shards,
                             const std::vector<std::string>& names) {
  if (shards.empty()) throw Error("no shards given");
  const TuneResult& first = shards.front();
  const int count = first.options.shard.count;
  std::set<int> seen;
  for (size_t i = 0; i < shards.size(); ++i) {
    const TuneResult& s = shards[i];
    if (s.merged_shards > 0) throw Error(names[i] + ": already a merged result");
    check_same_build(s.environment, names[i], first.environment, names[0]);
    if (s.settings_key != first.settings_key) {
      throw Error(names[i] + ": other settings than " + names[0] +
                  " (scenes, techniques, bound, size, display, frames or reference differ): not "
                  "shards of one tune run");
    }
    if (!seen.insert(s.options.shard.index).second) {
      throw Error(names[i] + ": shard " + std::to_string(s.options.shard.index + 1) + "/" +
                  std::to_string(count) + " given twice");
    }
  }
  detail::check_every_shard(seen, count, names[0]);
  TuneResult out = first;
  out.points.clear();
  for (const TuneResult& s : shards) {
    out.points.insert(out.points.end(), s.points.begin(), s.points.end());
    for (const auto& [scene, jod] : s.native_jod) out.native_jod.emplace(scene, jod);
  }
  out.merged_shards = count;
  choose_parameters(out);
  return out;
}

std::string tune_markdown(const TuneResult& r) {
  std::ostringstream s;
  s << "Within " << format_fixed(r.options.bound_jod, 2)
    << " JOD of native (FovVideoVDP against the "
    << (r.options.bench.reference > 1
            ? "ssaa:" + std::to_string(r.options.bench.reference) + " reference"
            : std::string("native frames"))
    << "), the fastest setting per technique";
  if (r.warmup > 0) {
    s << " (every candidate judged on frames " << r.warmup << "-"
      << r.warmup + r.options.bench.frames - 1 << ", after " << r.warmup << " of warm-up";
    if (r.options.staged() && r.merged_shards == 0) {
      s << "; the search times its candidates while judging them, which slows the foveated "
           "ones on a software renderer, and the settings the choice falls between are timed "
           "again, in a pass of their own";
    }
    s << ")";
  }
  s << "; settings within " << format_number(100.0 * kTuneSpeedTie)
    << " % of its speed tie with it, and of those the one with the most JOD, then the fewest "
       "pixels, is chosen:\n\n";
  if (!r.options.values.empty()) {
    s << "Values searched instead of the declared ones:";
    for (const auto& [key, list] : r.options.values) {
      s << " " << key << "=";
      for (size_t i = 0; i < list.size(); ++i) s << (i ? "," : "") << format_number(list[i], 4);
    }
    s << ".\n\n";
  }
  s << "| technique | chosen | verdict |\n|---|---|---|\n";
  for (const std::string& t : techniques_of(r)) {
    const auto c = r.chosen.find(t);
    s << "| " << t << " | " << (c == r.chosen.end() ? "-" : params_text(c->second)) << " | "
      << (r.verdict.count(t) ? r.verdict.at(t) : "") << " |\n";
  }
  for (const std::string& scene : r.options.scenes) {
    if (!r.native_jod.count(scene)) continue;
    s << "\n"
      << scene << " (native " << format_fixed(r.native_jod.at(scene), 3)
      << " JOD): each technique's front (no other setting of it both faster and better)\n\n"
      << "| technique | setting | speedup (95 % CI) | JOD | below native | pixel ratio |\n"
      << "|---|---|---:|---:|---:|---:|\n";
    for (const std::string& t : techniques_of(r)) {
      for (const TunePoint& p : tune_front(r, scene, t)) {
        // A tune.json of before the intervals were recorded has none.
        const bool ci = std::isfinite(p.speedup_lo) && std::isfinite(p.speedup_hi);
        s << "| " << t << " | " << params_text(p.params) << " | " << format_fixed(p.speedup, 2)
          << "x"
          << (ci ? " (" + format_fixed(p.speedup_lo, 2) + "-" + format_fixed(p.speedup_hi, 2) + ")"
                 : std::string())
          << " | " << format_fixed(p.jod, 3) << " | " << format_fixed(p.below_native, 3)
          << (p.within_bound ? "" : " (over)") << " | " << format_fixed(p.pixel_ratio, 3) << " |\n";
      }
    }
  }
  return s.str();
}

void write_tune_report(const TuneResult& r, const std::string& dir) {
  namespace fs = std::filesystem;
  make_output_dir(dir, "out");
  const fs::path d(dir);
  write_file_atomic((d / "tune.json").string(), tune_json(r).dump(2) + "\n");
  write_file_atomic((d / "tune.md").string(), tune_markdown(r));
  write_params_file((d / "params.json").string(), r.chosen,
                    "foveate tune: the fastest setting within " +
                        format_fixed(r.options.bound_jod, 2) + " JOD of native on " +
                        std::to_string(r.options.scenes.size()) + " scene(s) at " +
                        std::to_string(r.options.bench.session.size.width) + "x" +
                        std::to_string(r.options.bench.session.size.height) + " (" + r.renderer +
                        "); see tune.md");
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>foveate tune"
       "</title><style>body{font-family:sans-serif;margin:24px;max-width:1400px;color:#222}"
       "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:4px 8px}"
       ".note{color:#555;font-size:13px}.chart>svg{display:block;width:100%;height:auto}"
       ".chart a.download{font-size:12px;color:#555}</style></head><body>\n"
       "<h1>foveate tune</h1>\n"
       "<p class=note>Every candidate's speedup over native (same run, interleaved) against its "
       "FovVideoVDP JOD; the ringed points joined by the dashed line are the front over all "
       "techniques. Bound: "
    << format_fixed(r.options.bound_jod, 2) << " JOD below native.</p>\n";
  const std::vector<std::string> techniques = techniques_of(r);
  for (const std::string& scene : r.options.scenes) {
    if (!r.native_jod.count(scene)) continue;
    std::vector<ScatterPoint> pts;
    for (size_t i = 0; i < techniques.size(); ++i) {
      for (const TunePoint& p : r.points) {
        if (p.scene != scene || p.technique != techniques[i] || !std::isfinite(p.jod)) continue;
        pts.push_back({p.technique + " {" + params_text(p.params) + "}",
                       technique_colour_hex(techniques[i]), p.speedup, p.jod});
      }
    }
    // The chart's id names its file beside the page: a scene given as a path
    // keeps only letters, digits, '-' and '_'.
    std::string id = "chart-tune-";
    for (char c : scene) id += std::isalnum(static_cast<unsigned char>(c)) || c == '-' ? c : '_';
    h << "<h2>" << scene
      << "</h2>\n<p class=note>native: " << format_fixed(r.native_jod.at(scene), 3)
      << " JOD; the bound: " << format_fixed(r.native_jod.at(scene) - r.options.bound_jod, 3)
      << ".</p>\n"
      << chart_div(id, svg_scatter(pts,
                                   {.title = "Speed against visible quality on " + scene,
                                    .x_label = "speedup over native (x)",
                                    .y_label = "FovVideoVDP JOD",
                                    .y_from_zero = false},
                                   true));
  }
  h << "<h2>Chosen</h2>\n<pre>" << tune_markdown(r) << "</pre>\n</body></html>\n";
  write_html_report(h.str(), dir);
}

}  // namespace foveate::bench
