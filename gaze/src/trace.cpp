#include "foveate/gaze/trace.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <nlohmann/json.hpp>
#include <utility>

#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"
#include "foveate/core/json_read.hpp"
#include "trace_parse.hpp"

namespace foveate::gaze {

using namespace detail;

namespace {

/// What a JSON trace's object form says about its samples.
struct JsonTraceHeader {
  TimeUnit time_unit = TimeUnit::kAuto;
  PosUnit pos_unit = PosUnit::kAuto;
  const nlohmann::json* samples = nullptr;
};

/// Reads the object form's fields (format, units, screen size, samples).
JsonTraceHeader read_json_header(const nlohmann::json& j, const std::string& where, int& width,
                                 int& height) {
  JsonTraceHeader h;
  JsonReader r(j, where);
  std::string format, tunit, punit;
  if (r.string("format", format) && format != "foveate-gaze") {
    throw Error(r.path("format") + ": expected \"foveate-gaze\", got \"" + format + "\"");
  }
  if (r.string("time_unit", tunit)) {
    if (tunit == "s") {
      h.time_unit = TimeUnit::kSeconds;
    } else if (tunit == "ms") {
      h.time_unit = TimeUnit::kMilliseconds;
    } else {
      throw Error(r.path("time_unit") + ": expected \"s\" or \"ms\", got \"" + tunit + "\"");
    }
  }
  if (r.string("position_unit", punit)) {
    if (punit == "normalized") {
      h.pos_unit = PosUnit::kNormalized;
    } else if (punit == "px") {
      h.pos_unit = PosUnit::kPixels;
    } else {
      throw Error(r.path("position_unit") + ": expected \"normalized\" or \"px\", got \"" + punit +
                  "\"");
    }
  }
  if (const nlohmann::json* sp = r.get("screen_px")) {
    if (!sp->is_array() || sp->size() != 2 || !(*sp)[0].is_number_integer() ||
        !(*sp)[1].is_number_integer() || (*sp)[0].get<long long>() < 1 ||
        (*sp)[1].get<long long>() < 1 || (*sp)[0].get<long long>() > 65536 ||
        (*sp)[1].get<long long>() > 65536) {
      throw Error(r.path("screen_px") + ": expected [width, height] in pixels");
    }
    width = (*sp)[0].get<int>();
    height = (*sp)[1].get<int>();
  }
  h.samples = r.get("samples");
  if (!h.samples) throw Error(where + ": samples: missing");
  r.finish();
  return h;
}

double json_number(const nlohmann::json& v, const std::string& path, double fallback) {
  if (v.is_null()) return fallback;
  if (!v.is_number()) throw Error(path + ": expected a number or null, got " + v.type_name());
  return v.get<double>();
}

/// One sample, [t, x, y(, confidence(, valid))] or {"t", "x", "y", ...}, at
/// path `p`; its latency (NaN where none) in `latency_ms`.
GazeSample read_json_sample(const nlohmann::json& e, const std::string& p, double& latency_ms,
                            Builder& b) {
  GazeSample s;
  latency_ms = kNaN;
  if (e.is_array()) {
    if (e.size() < 3 || e.size() > 5) {
      throw Error(p + ": expected [t, x, y] or [t, x, y, confidence(, valid)]");
    }
    s.time_s = json_number(e[0], p + "[0]", kNaN);
    s.pos = {json_number(e[1], p + "[1]", kNaN), json_number(e[2], p + "[2]", kNaN)};
    if (e.size() > 3) s.confidence = json_number(e[3], p + "[3]", 1.0);
    if (e.size() > 4) {
      if (!e[4].is_boolean() && !e[4].is_number_integer()) {
        throw Error(p + "[4]: valid: expected true/false or 1/0");
      }
      s.valid = e[4].is_boolean() ? e[4].get<bool>() : e[4].get<long long>() != 0;
    }
  } else if (e.is_object()) {
    JsonReader r(e, p);
    const nlohmann::json* t = r.get("t");
    if (!t) t = r.get("time");
    if (!t) throw Error(p + ": missing \"t\"");
    const nlohmann::json* x = r.get("x");
    const nlohmann::json* y = r.get("y");
    if (!x || !y) throw Error(p + ": missing \"x\" or \"y\"");
    s.time_s = json_number(*t, p + ".t", kNaN);
    s.pos = {json_number(*x, p + ".x", kNaN), json_number(*y, p + ".y", kNaN)};
    if (const nlohmann::json* c = r.get("confidence"))
      s.confidence = json_number(*c, p + ".confidence", 1.0);
    if (const nlohmann::json* l = r.get("latency_ms")) {
      latency_ms = json_number(*l, p + ".latency_ms", kNaN);
      b.with_latency = true;
    }
    r.boolean("valid", s.valid);
    r.finish();
  } else {
    throw Error(p + ": expected an array [t, x, y, ...] or an object {\"t\", \"x\", \"y\"}");
  }
  return s;
}

}  // namespace

Trace parse_trace_json(const std::string& text, const std::string& where,
                       const TraceOptions& options) {
  const nlohmann::json j = parse_json(text, where);
  Builder b(options.off_screen_limit);
  b.trace.format = "json";
  int width = options.width_px, height = options.height_px;
  JsonTraceHeader h;
  h.samples = &j;
  if (j.is_object()) h = read_json_header(j, where, width, height);
  const nlohmann::json& samples = *h.samples;
  if (!samples.is_array()) throw Error(where + ": samples: expected an array");
  const TimeUnit tu = resolve(h.time_unit, options.time_unit, TimeUnit::kSeconds, where, "time");
  const PosUnit pu =
      resolve(h.pos_unit, options.pos_unit, PosUnit::kNormalized, where, "positions");
  for (size_t i = 0; i < samples.size(); ++i) {
    double latency_ms = kNaN;
    GazeSample s =
        read_json_sample(samples[i], where + ": samples[" + std::to_string(i) + "]", latency_ms, b);
    if (tu == TimeUnit::kMilliseconds) s.time_s *= 1e-3;
    if (pu == PosUnit::kPixels) s.pos = {s.pos.x / width, s.pos.y / height};
    b.add(s, latency_ms);
  }
  return b.finish(where, pu);
}

Trace load_trace(const std::string& path, const TraceOptions& options) {
  const std::string text =
      read_file(path, "gaze trace", limit_from_env_mib("FOVEATE_MAX_TRACE_MB", kMaxTraceMiB),
                "set FOVEATE_MAX_TRACE_MB to raise it");
  std::string ext = path.size() >= 5 ? lower(path.substr(path.size() - 5)) : std::string();
  const std::string first = trim(text.substr(0, std::min<size_t>(text.size(), 64)));
  if (ext == ".json" || (!first.empty() && (first[0] == '{' || first[0] == '['))) {
    return parse_trace_json(text, path, options);
  }
  return parse_trace_csv(text, path, options);
}

std::string trace_to_csv(const Trace& trace) {
  const bool lat = trace.latency_ms.size() == trace.samples.size() && !trace.samples.empty();
  std::string out =
      "# foveate gaze trace: time in seconds, positions normalized (origin top-left)\n";
  out += lat ? "time_s,x,y,confidence,valid,latency_ms\n" : "time_s,x,y,confidence,valid\n";
  char buf[160];
  for (size_t i = 0; i < trace.samples.size(); ++i) {
    const GazeSample& s = trace.samples[i];
    std::snprintf(buf, sizeof buf, "%.6f,%.6f,%.6f,%.4f,%d", s.time_s, s.pos.x, s.pos.y,
                  s.confidence, s.valid ? 1 : 0);
    out += buf;
    if (lat) {
      if (std::isfinite(trace.latency_ms[i])) {
        std::snprintf(buf, sizeof buf, ",%.3f", trace.latency_ms[i]);
        out += buf;
      } else {
        out += ",";
      }
    }
    out += '\n';
  }
  return out;
}

std::string trace_to_json(const Trace& trace) {
  nlohmann::json j;
  j["format"] = "foveate-gaze";
  j["time_unit"] = "s";
  j["position_unit"] = "normalized";
  nlohmann::json a = nlohmann::json::array();
  for (const GazeSample& s : trace.samples) {
    a.push_back({s.time_s, s.pos.x, s.pos.y, s.confidence, s.valid});
  }
  j["samples"] = std::move(a);
  return j.dump() + "\n";
}

GazeSample interpolate(const Trace& trace, double t_s, const InterpolationOptions& options) {
  const auto& v = trace.samples;
  if (v.empty()) return {t_s, {0.5, 0.5}, 0.0, false};
  const double t0 = v.front().time_s, t1 = v.back().time_s;
  double t = t_s;
  if (options.end == TraceEnd::kLoop && t1 > t0 && t > t1) t = t0 + std::fmod(t - t0, t1 - t0);
  auto at = [&](const GazeSample& s) { return GazeSample{t_s, s.pos, s.confidence, s.valid}; };
  if (t <= t0) return at(v.front());
  if (t >= t1) return at(v.back());
  const auto it = std::upper_bound(v.begin(), v.end(), t,
                                   [](double x, const GazeSample& s) { return x < s.time_s; });
  const GazeSample& b = *it;
  const GazeSample& a = *(it - 1);
  if (b.time_s - a.time_s > options.max_gap_s) return {t_s, a.pos, 0.0, false};  // dropout
  // The tracker reports a until b arrives when either end is not a valid sample.
  if (!a.valid || !b.valid) return at(a);
  const double u = (t - a.time_s) / (b.time_s - a.time_s);
  return {t_s,
          {a.pos.x + u * (b.pos.x - a.pos.x), a.pos.y + u * (b.pos.y - a.pos.y)},
          a.confidence + u * (b.confidence - a.confidence),
          true};
}

TraceSource::TraceSource(Trace trace, std::string name, InterpolationOptions options)
    : trace_(std::move(trace)), name_(std::move(name)), options_(options) {}

GazeSample TraceSource::sample(double t_s) { return interpolate(trace_, t_s, options_); }

std::string TraceSource::describe() const {
  char buf[160];
  std::snprintf(buf, sizeof buf, " (%s, %zu samples over %.2f s)", trace_.format.c_str(),
                trace_.samples.size(), trace_.duration_s());
  return "trace " + name_ + buf;
}

std::string TraceSource::report() const {
  // Rows the file could not give a sample for are counted here too: their
  // warnings went by when the file was read, and the run's summary is what
  // is left to say that the trace played had gaps.
  std::string s = "trace " + name_ + ": " + trace_.dropped.summary();
  if (trace_.skipped_rows > 0)
    s += ", " + std::to_string(trace_.skipped_rows) + " unreadable row" +
         (trace_.skipped_rows == 1 ? "" : "s") + " skipped";
  return s;
}

}  // namespace foveate::gaze
