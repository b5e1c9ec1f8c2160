#pragma once
// What the trace readers (trace.cpp: JSON, trace_csv.cpp: CSV) share: small
// text helpers, unit resolution and the builder that validates samples.
#include <cctype>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "foveate/core/error.hpp"
#include "foveate/gaze/trace.hpp"

namespace foveate::gaze::detail {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

inline std::string trim(const std::string& s) {
  size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return s.substr(a, b - a);
}

inline std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

inline const char* unit_name(TimeUnit u) { return u == TimeUnit::kMilliseconds ? "ms" : "s"; }
inline const char* unit_name(PosUnit u) { return u == PosUnit::kPixels ? "pixels" : "normalized"; }

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

  explicit Builder(double off_screen_limit) : validator(off_screen_limit) {}

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
      std::string msg = where + ": no usable gaze sample (" + trace.dropped.summary();
      if (trace.skipped_rows > 0) {
        msg += "; " + std::to_string(trace.skipped_rows) +
               " row(s) could not be read, the first: " + trace.warnings.front();
      }
      msg += ")";
      if (trace.dropped.out_of_range > 0 && pos_unit == PosUnit::kNormalized) {
        msg += "; if the positions are pixels, name the columns x_px,y_px or choose pixel units";
      }
      throw Error(msg);
    }
    return std::move(trace);
  }
};

}  // namespace foveate::gaze::detail
