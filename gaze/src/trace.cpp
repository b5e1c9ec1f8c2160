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

namespace foveate::gaze {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string trim(const std::string& s) {
  size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return s.substr(a, b - a);
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// Splits one CSV record; fields may be quoted ("a,b" and "" for a quote).
/// Returns false on an unterminated quote.
bool split_csv(const std::string& line, std::vector<std::string>& out) {
  out.clear();
  std::string field;
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"') {
        if (i + 1 < line.size() && line[i + 1] == '"') {
          field += '"';
          ++i;
        } else {
          quoted = false;
        }
      } else {
        field += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.push_back(trim(field));
      field.clear();
    } else {
      field += c;
    }
  }
  out.push_back(trim(field));
  return !quoted;
}

std::string where_line(const std::string& where, size_t line) {
  return where + ":" + std::to_string(line);
}

const char* unit_name(TimeUnit u) { return u == TimeUnit::kMilliseconds ? "ms" : "s"; }
const char* unit_name(PosUnit u) { return u == PosUnit::kPixels ? "pixels" : "normalized"; }

/// Combines what the header says with what the options say; conflicts are errors.
template <typename Unit>
Unit resolve(Unit from_header, Unit from_options, Unit fallback, const std::string& where,
             const std::string& what) {
  if (from_header != Unit::kAuto && from_options != Unit::kAuto && from_header != from_options) {
    throw Error(where + ": the header gives " + what + " in " + unit_name(from_header) +
                " but the options say " + unit_name(from_options));
  }
  if (from_header != Unit::kAuto) return from_header;
  if (from_options != Unit::kAuto) return from_options;
  return fallback;
}

struct Builder {
  Trace trace;
  SampleValidator validator;
  bool have_origin = false;
  std::vector<double> latency;
  bool with_latency = false;

  explicit Builder(double margin) : validator(margin) {}

  void add(GazeSample s, double latency_ms = kNaN) {
    if (!validator.accept(s)) return;
    if (!have_origin) {
      trace.time_origin_s = s.time_s;
      have_origin = true;
    }
    s.time_s -= trace.time_origin_s;
    trace.samples.push_back(s);
    latency.push_back(latency_ms);
  }

  Trace finish(const std::string& where, PosUnit pos_unit) {
    trace.dropped = validator.counts();
    if (with_latency) trace.latency_ms = std::move(latency);
    if (trace.samples.empty()) {
      std::string msg = where + ": no usable gaze sample (" + trace.dropped.summary() + ")";
      if (trace.dropped.out_of_range > 0 && pos_unit == PosUnit::kNormalized) {
        msg += "; if the positions are pixels, name the columns x_px,y_px or choose pixel units";
      }
      throw Error(msg);
    }
    return std::move(trace);
  }
};

bool parse_number(const std::string& field, double& out) {
  if (field.empty()) {
    out = kNaN;  // a missing value: dropped as non-finite, counted
    return true;
  }
  char* end = nullptr;
  out = std::strtod(field.c_str(), &end);
  return end == field.c_str() + field.size();
}

bool parse_bool(const std::string& field, bool& out) {
  const std::string f = lower(field);
  if (f.empty() || f == "1" || f == "true" || f == "yes") {
    out = true;
  } else if (f == "0" || f == "false" || f == "no") {
    out = false;
  } else {
    return false;
  }
  return true;
}

bool parse_screen(const std::string& text, int& w, int& h) {
  const auto x = text.find_first_of("xX");
  if (x == std::string::npos) return false;
  char* e1 = nullptr;
  char* e2 = nullptr;
  const std::string a = trim(text.substr(0, x)), b = trim(text.substr(x + 1));
  const long lw = std::strtol(a.c_str(), &e1, 10), lh = std::strtol(b.c_str(), &e2, 10);
  if (a.empty() || b.empty() || *e1 != '\0' || *e2 != '\0' || lw < 1 || lh < 1 || lw > 65536 ||
      lh > 65536) {
    return false;
  }
  w = static_cast<int>(lw);
  h = static_cast<int>(lh);
  return true;
}

struct Column {
  int index = -1;
  std::string name;
};

}  // namespace

Trace parse_trace_csv(const std::string& text, const std::string& where,
                      const TraceOptions& options) {
  Builder b(options.margin);
  int width = options.width_px, height = options.height_px;
  std::vector<std::string> header, fields;
  size_t header_line = 0;
  Column ct, cx, cy, cconf, cvalid, clat;
  bool pupil = false;
  TimeUnit tu = TimeUnit::kSeconds;
  PosUnit pu = PosUnit::kNormalized;
  size_t needed = 0;

  size_t line_no = 0, pos = 0;
  while (pos < text.size()) {
    size_t nl = text.find('\n', pos);
    if (nl == std::string::npos) nl = text.size();
    std::string line = text.substr(pos, nl - pos);
    pos = nl + 1;
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line_no == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line = line.substr(3);  // BOM
    const std::string t = trim(line);
    if (t.empty()) continue;
    if (t[0] == '#') {
      const std::string c = lower(trim(t.substr(1)));
      if (c.rfind("screen_px:", 0) == 0) {
        if (!parse_screen(c.substr(10), width, height)) {
          throw Error(where_line(where, line_no) + ": screen_px: expected WIDTHxHEIGHT, got '" +
                      trim(t.substr(1)).substr(10) + "'");
        }
      }
      continue;
    }
    if (!split_csv(line, fields)) {
      throw Error(where_line(where, line_no) + ": unterminated quoted field");
    }
    if (header.empty()) {
      header = fields;
      header_line = line_no;
      TimeUnit htu = TimeUnit::kAuto;
      PosUnit hpu = PosUnit::kAuto;
      for (size_t i = 0; i < header.size(); ++i) {
        const std::string n = lower(header[i]);
        const int idx = static_cast<int>(i);
        auto set = [&](Column& c) {
          if (c.index >= 0) {
            throw Error(where_line(where, line_no) + ": columns '" + c.name + "' and '" +
                        header[i] + "' both give the same value");
          }
          c = {idx, header[i]};
        };
        if (n == "gaze_timestamp") {
          set(ct);
          pupil = true;
        } else if (n == "norm_pos_x") {
          set(cx);
        } else if (n == "norm_pos_y") {
          set(cy);
        } else if (n == "time" || n == "t" || n == "timestamp" || n == "time_s" || n == "t_s" ||
                   n == "timestamp_s") {
          set(ct);
          if (n.size() > 2 && n.ends_with("_s")) htu = TimeUnit::kSeconds;
        } else if (n == "time_ms" || n == "t_ms" || n == "timestamp_ms") {
          set(ct);
          htu = TimeUnit::kMilliseconds;
        } else if (n == "x" || n == "gaze_x" || n == "x_norm") {
          set(cx);
          if (n == "x_norm") hpu = PosUnit::kNormalized;
        } else if (n == "x_px" || n == "gaze_x_px") {
          set(cx);
          hpu = PosUnit::kPixels;
        } else if (n == "y" || n == "gaze_y" || n == "y_norm") {
          set(cy);
        } else if (n == "y_px" || n == "gaze_y_px") {
          set(cy);
        } else if (n == "confidence" || n == "conf") {
          set(cconf);
        } else if (n == "valid") {
          set(cvalid);
        } else if (n == "latency_ms") {
          set(clat);
        }
      }
      if (ct.index < 0 || cx.index < 0 || cy.index < 0) {
        throw Error(where_line(where, line_no) +
                    ": the header needs a time column (time_s or time_ms), x and y (or x_px, y_px; "
                    "or Pupil's gaze_timestamp, norm_pos_x, norm_pos_y); got '" +
                    t + "'");
      }
      if (pupil) {
        if (cx.name != "norm_pos_x" || cy.name != "norm_pos_y") {
          throw Error(where_line(where, line_no) +
                      ": a Pupil export (gaze_timestamp) needs norm_pos_x and norm_pos_y");
        }
        htu = TimeUnit::kSeconds;
        hpu = PosUnit::kNormalized;
      }
      tu = resolve(htu, options.time_unit, TimeUnit::kSeconds, where_line(where, line_no), "time");
      pu = resolve(hpu, options.pos_unit, PosUnit::kNormalized, where_line(where, line_no),
                   "positions");
      for (const Column* c : {&ct, &cx, &cy, &cconf, &cvalid, &clat}) {
        needed = std::max(needed, static_cast<size_t>(c->index + 1));
      }
      b.with_latency = clat.index >= 0;
      b.trace.format = pupil ? "pupil-csv" : "csv";
      continue;
    }
    if (fields.size() < needed) {
      throw Error(where_line(where, line_no) + ": expected " + std::to_string(header.size()) +
                  " fields as in the header (line " + std::to_string(header_line) + "), got " +
                  std::to_string(fields.size()));
    }
    auto number = [&](const Column& c, double fallback) {
      if (c.index < 0) return fallback;
      const std::string& f = fields[c.index];
      double v = 0;
      if (!parse_number(f, v)) {
        throw Error(where_line(where, line_no) + ": " + c.name + ": '" + f + "' is not a number");
      }
      return v;
    };
    GazeSample s;
    s.time_s = number(ct, kNaN);
    if (tu == TimeUnit::kMilliseconds) s.time_s *= 1e-3;
    s.pos = {number(cx, kNaN), number(cy, kNaN)};
    if (pupil) s.pos.y = 1.0 - s.pos.y;  // Pupil: origin bottom-left
    if (pu == PosUnit::kPixels) s.pos = {s.pos.x / width, s.pos.y / height};
    s.confidence = number(cconf, 1.0);
    if (cconf.index >= 0 && fields[cconf.index].empty()) s.confidence = 1.0;
    if (cvalid.index >= 0 && !parse_bool(fields[cvalid.index], s.valid)) {
      throw Error(where_line(where, line_no) + ": valid: expected 1/0 or true/false, got '" +
                  fields[cvalid.index] + "'");
    }
    b.add(s, number(clat, kNaN));
  }
  if (header.empty()) throw Error(where + ": empty file: expected a header line and samples");
  return b.finish(where, pu);
}

Trace parse_trace_json(const std::string& text, const std::string& where,
                       const TraceOptions& options) {
  const nlohmann::json j = parse_json(text, where);
  Builder b(options.margin);
  b.trace.format = "json";
  TimeUnit htu = TimeUnit::kAuto;
  PosUnit hpu = PosUnit::kAuto;
  int width = options.width_px, height = options.height_px;
  const nlohmann::json* samples = &j;
  if (j.is_object()) {
    JsonReader r(j, where);
    std::string format, tunit, punit;
    if (r.string("format", format) && format != "foveate-gaze") {
      throw Error(r.path("format") + ": expected \"foveate-gaze\", got \"" + format + "\"");
    }
    if (r.string("time_unit", tunit)) {
      if (tunit == "s") {
        htu = TimeUnit::kSeconds;
      } else if (tunit == "ms") {
        htu = TimeUnit::kMilliseconds;
      } else {
        throw Error(r.path("time_unit") + ": expected \"s\" or \"ms\", got \"" + tunit + "\"");
      }
    }
    if (r.string("position_unit", punit)) {
      if (punit == "normalized") {
        hpu = PosUnit::kNormalized;
      } else if (punit == "px") {
        hpu = PosUnit::kPixels;
      } else {
        throw Error(r.path("position_unit") + ": expected \"normalized\" or \"px\", got \"" +
                    punit + "\"");
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
    samples = r.get("samples");
    if (!samples) throw Error(where + ": samples: missing");
    r.finish();
  }
  if (!samples->is_array()) throw Error(where + ": samples: expected an array");
  const TimeUnit tu = resolve(htu, options.time_unit, TimeUnit::kSeconds, where, "time");
  const PosUnit pu = resolve(hpu, options.pos_unit, PosUnit::kNormalized, where, "positions");

  auto num = [&](const nlohmann::json& v, const std::string& path, double fallback) {
    if (v.is_null()) return fallback;
    if (!v.is_number()) throw Error(path + ": expected a number or null, got " + v.type_name());
    return v.get<double>();
  };
  for (size_t i = 0; i < samples->size(); ++i) {
    const nlohmann::json& e = (*samples)[i];
    const std::string p = where + ": samples[" + std::to_string(i) + "]";
    GazeSample s;
    double lat = kNaN;
    if (e.is_array()) {
      if (e.size() < 3 || e.size() > 5) {
        throw Error(p + ": expected [t, x, y] or [t, x, y, confidence(, valid)]");
      }
      s.time_s = num(e[0], p + "[0]", kNaN);
      s.pos = {num(e[1], p + "[1]", kNaN), num(e[2], p + "[2]", kNaN)};
      if (e.size() > 3) s.confidence = num(e[3], p + "[3]", 1.0);
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
      s.time_s = num(*t, p + ".t", kNaN);
      s.pos = {num(*x, p + ".x", kNaN), num(*y, p + ".y", kNaN)};
      if (const nlohmann::json* c = r.get("confidence"))
        s.confidence = num(*c, p + ".confidence", 1.0);
      if (const nlohmann::json* l = r.get("latency_ms")) {
        lat = num(*l, p + ".latency_ms", kNaN);
        b.with_latency = true;
      }
      r.boolean("valid", s.valid);
      r.finish();
    } else {
      throw Error(p + ": expected an array [t, x, y, ...] or an object {\"t\", \"x\", \"y\"}");
    }
    if (tu == TimeUnit::kMilliseconds) s.time_s *= 1e-3;
    if (pu == PosUnit::kPixels) s.pos = {s.pos.x / width, s.pos.y / height};
    b.add(s, lat);
  }
  return b.finish(where, pu);
}

Trace load_trace(const std::string& path, const TraceOptions& options) {
  const std::string text = read_file(path);
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
  return "trace " + name_ + ": " + trace_.dropped.summary();
}

}  // namespace foveate::gaze
