#include "foveate/bench/merge.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <set>

#include "foveate/core/error.hpp"
#include "shard_check.hpp"

namespace foveate::bench {

namespace {

template <class T>
T value_at(const nlohmann::json& j, const char* key, const std::string& where) {
  const auto it = j.find(key);
  if (it == j.end()) throw Error(where + ": " + key + ": missing");
  try {
    return it->get<T>();
  } catch (const nlohmann::json::exception&) {
    throw Error(where + ": " + key + ": unexpected type");
  }
}

double as_number(const nlohmann::json& v) { return v.is_number() ? v.get<double>() : std::nan(""); }

double number_or_nan(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  return it == j.end() || !it->is_number() ? std::nan("") : it->get<double>();
}

TechniqueResult read_result(const nlohmann::json& r, const std::string& where) {
  TechniqueResult t;
  t.technique = value_at<std::string>(r, "technique", where);
  t.run_index = r.value("run_index", 0);
  t.sweep_value = r.value("sweep_value", 0.0);
  const std::string label = r.value("label", t.technique);
  if (label != t.technique && r.find("sweep_value") == r.end()) t.label = label;
  const nlohmann::json parameters = r.value("parameters", nlohmann::json::object());
  for (const auto& [k, v] : parameters.items()) t.parameters.emplace_back(k, as_number(v));
  for (const auto& v : r.value("frame_ms", nlohmann::json::array()))
    t.frame_ms.push_back(as_number(v));
  t.median_ms = number_or_nan(r, "median_ms");
  t.p90_ms = number_or_nan(r, "p90_ms");
  t.mean_ms = number_or_nan(r, "mean_ms");
  t.speedup = number_or_nan(r, "speedup");
  if (const auto ci = r.find("speedup_ci95"); ci != r.end() && ci->size() == 2) {
    t.speedup_lo = as_number((*ci)[0]);
    t.speedup_hi = as_number((*ci)[1]);
  }
  t.shaded_pixels = number_or_nan(r, "shaded_pixels");
  t.native_pixels = number_or_nan(r, "native_pixels");
  t.pixel_ratio = number_or_nan(r, "pixel_ratio");
  t.bound_share = number_or_nan(r, "bound_share");
  for (const auto& p : r.value("parts", nlohmann::json::array()))
    t.parts.push_back({p.value("name", ""), number_or_nan(p, "pixels")});
  if (const auto ps = r.find("passes"); ps != r.end() && ps->is_array()) {
    for (const auto& p : *ps) t.passes.push_back({p.value("name", ""), number_or_nan(p, "ms")});
  }
  if (const auto q = r.find("quality"); q != r.end() && q->is_object() && !q->empty())
    t.metrics = metrics::quality_summary_from_json(*q);
  if (const auto eyes = r.find("eyes"); eyes != r.end() && eyes->is_object()) {
    for (const char* name : {"left", "right"}) {
      const nlohmann::json& e = eyes->at(name);
      TechniqueResult::Eye eye;
      eye.shaded_pixels = number_or_nan(e, "shaded_pixels");
      eye.native_pixels = number_or_nan(e, "native_pixels");
      eye.pixel_ratio = number_or_nan(e, "pixel_ratio");
      if (const auto q = e.find("quality"); q != e.end() && q->is_object() && !q->empty())
        eye.metrics = metrics::quality_summary_from_json(*q);
      t.eyes.push_back(eye);
    }
  }
  return t;
}

void read_options(const nlohmann::json& j, const std::string& where, BenchResult& b) {
  BenchOptions& o = b.options;
  const nlohmann::json& size = j.at("size");
  o.session.size = {size[0].get<int>(), size[1].get<int>()};
  o.session.scene = b.scene;
  o.session.display = b.display.name;
  const nlohmann::json& acuity = j.at("acuity");
  o.session.acuity.slope = acuity.value("slope", o.session.acuity.slope);
  o.session.acuity.w0_deg = acuity.value("w0_deg", o.session.acuity.w0_deg);
  if (j.contains("margin") && j["margin"].is_number()) o.session.margin = j["margin"].get<double>();
  const std::string gaze = j.value("gaze", "centre");
  o.session.gaze = gaze == "centre" ? "" : gaze;
  o.session.fps = j.value("fps_clock", 60.0);
  o.frames = value_at<int>(j, "frames", where);
  const std::string reference = j.value("reference", "native");
  o.reference = reference.rfind("ssaa:", 0) == 0 ? std::stoi(reference.substr(5)) : 1;
  b.warmup = j.value("warmup", 0);
  o.warmup = b.warmup;
  b.memory_groups = j.value("memory_groups", 1);
  if (const auto sw = j.find("sweep"); sw != j.end() && sw->is_object()) {
    o.sweep.key = sw->value("key", "");
    o.sweep.values = sw->value("values", std::vector<double>{});
  }
  if (const auto sh = j.find("shard"); sh != j.end() && sh->contains("count")) {
    o.shard.index = sh->value("index", 0);
    o.shard.count = sh->value("count", 1);
  }
  if (const auto s = j.find("settings"); s != j.end()) {
    o.image_metrics = s->value("image_metrics", true);
    o.diagnostics = s->value("diagnostics", true);
    o.passes = s->value("passes", false);
    o.session.stereo = s->value("stereo", false);
  }
}

}  // namespace

BenchResult read_bench_results(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object() || j.value("schema", "") != "foveate-bench/1") {
    throw Error(where + ": not a foveate benchmark's results (schema foveate-bench/1)");
  }
  BenchResult b;
  b.scene = value_at<std::string>(j, "scene", where);
  b.renderer = j.value("renderer", "");
  b.display = Display::from_json(j.at("display"), where + ": display");
  const nlohmann::json env = j.value("environment", nlohmann::json::object());
  b.environment.command = j.value("command", "");
  b.environment.version = env.value("foveate_version", "");
  b.environment.date_utc = env.value("date_utc", "");
  b.environment.renderer = env.value("renderer", b.renderer);
  b.environment.gl_version = env.value("gl_version", "");
  b.environment.cpu_model = env.value("cpu_model", "");
  b.environment.cores = env.value("cpu_cores", 0u);
  if (const auto o = env.find("others_cpu_share"); o != env.end() && o->is_number())
    b.environment.others_cpu_share = o->get<double>();
  b.environment.pass_by_pass = env.value("pass_by_pass", false);
  b.environment.timed_apart = env.value("timed_apart", false);
  b.environment.variables = env.value("variables", std::map<std::string, std::string>{});
  b.skipped = j.value("skipped", std::vector<std::string>{});
  b.gaze_fallback = j.value("gaze_fallback", false);
  b.fallback_frames = j.value("gaze_fallback_frames", std::vector<int>{});
  b.gaze_report = j.value("gaze_report", nlohmann::json()).is_string()
                      ? j["gaze_report"].get<std::string>()
                      : std::string();
  if (const auto sv = j.find("savings"); sv != j.end() && sv->is_object()) {
    b.savings.pixel_bound = sv->value("pixel_bound", 1.0);
    b.savings.margin = sv->value("margin", 1.0);
    b.savings.nothing_to_save = sv->value("little_to_save", false);
  }
  read_options(j, where, b);
  b.settings_key = j.value("settings", nlohmann::json::object()).dump();
  for (const auto& r : value_at<nlohmann::json>(j, "results", where)) {
    b.results.push_back(read_result(r, where));
    b.techniques.push_back(b.results.back().technique);
  }
  return b;
}

BenchResult merge_shards(const std::vector<BenchResult>& shards,
                         const std::vector<std::string>& names) {
  if (shards.empty()) throw Error("no shards given");
  const BenchResult& first = shards.front();
  const int count = first.options.shard.count;
  const auto settings_of = [](const BenchResult& r) {
    return r.settings_key.empty() ? bench_settings_json(r).dump() : r.settings_key;
  };
  const std::string settings = settings_of(first);
  std::set<int> seen;
  for (size_t i = 0; i < shards.size(); ++i) {
    const BenchResult& s = shards[i];
    if (s.merged_shards > 0) throw Error(names[i] + ": already a merged result");
    check_same_build(s.environment, names[i], first.environment, names[0]);
    if (s.options.shard.count != count) {
      throw Error(names[i] + ": shard of " + std::to_string(s.options.shard.count) + ", but " +
                  names[0] + " is a shard of " + std::to_string(count));
    }
    if (settings_of(s) != settings) {
      throw Error(names[i] + ": other settings than " + names[0] +
                  " (scene, size, display, frames, reference, techniques, parameters or runs "
                  "differ): not shards of one benchmark");
    }
    if (!seen.insert(s.options.shard.index).second) {
      throw Error(names[i] + ": shard " + std::to_string(s.options.shard.index + 1) + "/" +
                  std::to_string(count) + " given twice");
    }
  }
  detail::check_every_shard(seen, count, names[0]);
  BenchResult out = first;
  out.results.clear();
  out.techniques.clear();
  for (const BenchResult& s : shards) {
    for (const TechniqueResult& r : s.results) {
      // Native from the first shard only; every other run is in one shard.
      if (r.run_index == 0 && &s != &first) continue;
      out.results.push_back(r);
    }
  }
  std::stable_sort(
      out.results.begin(), out.results.end(),
      [](const TechniqueResult& a, const TechniqueResult& b) { return a.run_index < b.run_index; });
  for (const TechniqueResult& r : out.results) out.techniques.push_back(r.technique);
  // Each shard's speedups are its own against its native: one measured
  // beside other work is enough for the merged reports to say so.
  for (const BenchResult& s : shards)
    out.environment.others_cpu_share =
        std::max(out.environment.others_cpu_share, s.environment.others_cpu_share);
  out.merged_shards = count;
  return out;
}

}  // namespace foveate::bench
