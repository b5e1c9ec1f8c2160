// The CSV forms of a gaze trace: the project's (with a header naming the
// units), and Pupil Capture's exported gaze_positions.csv. A row that cannot
// be read is skipped with a warning naming its line (an error with
// TraceOptions::strict); a last line cut off mid-write is dropped likewise.
#include <algorithm>
#include <cstdlib>
#include <optional>

#include "foveate/core/error.hpp"
#include "trace_parse.hpp"

namespace foveate::gaze {

using namespace detail;

namespace {

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

/// A data row that cannot be read: skipped with a warning, or an error.
struct RowProblem {
  std::string what;
};

/// Warnings kept in Trace::warnings; the rest are counted.
constexpr size_t kMaxRowWarnings = 10;

struct Column {
  int index = -1;
  std::string name;
};

/// What a header says: the columns and the units.
struct CsvHeader {
  std::vector<std::string> names;
  size_t line = 0;
  Column t, x, y, conf, valid, latency;
  bool pupil = false;
  TimeUnit time_unit = TimeUnit::kSeconds;
  PosUnit pos_unit = PosUnit::kNormalized;
  size_t needed = 0;  ///< fields a row must have
};

/// Reads the header line `fields` (line `line_no`, text `t`).
CsvHeader read_header(const std::vector<std::string>& fields, size_t line_no, const std::string& t,
                      const std::string& where, const TraceOptions& options) {
  CsvHeader h;
  h.names = fields;
  h.line = line_no;
  const std::string at = where_line(where, line_no);
  TimeUnit htu = TimeUnit::kAuto;
  PosUnit hpu = PosUnit::kAuto;
  for (size_t i = 0; i < fields.size(); ++i) {
    const std::string n = lower(fields[i]);
    auto set = [&](Column& c) {
      if (c.index >= 0) {
        throw Error(at + ": columns '" + c.name + "' and '" + fields[i] +
                    "' both give the same value");
      }
      c = {static_cast<int>(i), fields[i]};
    };
    if (n == "gaze_timestamp") {
      set(h.t);
      h.pupil = true;
    } else if (n == "norm_pos_x") {
      set(h.x);
    } else if (n == "norm_pos_y") {
      set(h.y);
    } else if (n == "time" || n == "t" || n == "timestamp" || n == "time_s" || n == "t_s" ||
               n == "timestamp_s") {
      set(h.t);
      if (n.size() > 2 && n.ends_with("_s")) htu = TimeUnit::kSeconds;
    } else if (n == "time_ms" || n == "t_ms" || n == "timestamp_ms") {
      set(h.t);
      htu = TimeUnit::kMilliseconds;
    } else if (n == "x" || n == "gaze_x" || n == "x_norm") {
      set(h.x);
      if (n == "x_norm") hpu = PosUnit::kNormalized;
    } else if (n == "x_px" || n == "gaze_x_px") {
      set(h.x);
      hpu = PosUnit::kPixels;
    } else if (n == "y" || n == "gaze_y" || n == "y_norm") {
      set(h.y);
    } else if (n == "y_px" || n == "gaze_y_px") {
      set(h.y);
    } else if (n == "confidence" || n == "conf") {
      set(h.conf);
    } else if (n == "valid") {
      set(h.valid);
    } else if (n == "latency_ms") {
      set(h.latency);
    }
  }
  if (h.t.index < 0 || h.x.index < 0 || h.y.index < 0) {
    throw Error(at +
                ": the header needs a time column (time_s or time_ms), x and y (or x_px, y_px; "
                "or Pupil's gaze_timestamp, norm_pos_x, norm_pos_y); got '" +
                t + "'");
  }
  if (h.pupil) {
    if (h.x.name != "norm_pos_x" || h.y.name != "norm_pos_y") {
      throw Error(at + ": a Pupil export (gaze_timestamp) needs norm_pos_x and norm_pos_y");
    }
    htu = TimeUnit::kSeconds;
    hpu = PosUnit::kNormalized;
  }
  h.time_unit = resolve(htu, options.time_unit, TimeUnit::kSeconds, at, "time");
  h.pos_unit = resolve(hpu, options.pos_unit, PosUnit::kNormalized, at, "positions");
  for (const Column* c : {&h.t, &h.x, &h.y, &h.conf, &h.valid, &h.latency}) {
    h.needed = std::max(h.needed, static_cast<size_t>(c->index + 1));
  }
  return h;
}

/// Adds the data row `fields` to `b`; throws a RowProblem where it cannot.
void read_row(const std::vector<std::string>& fields, bool split_ok, const CsvHeader& h, int width,
              int height, Builder& b) {
  if (!split_ok) throw RowProblem{"unterminated quoted field"};
  if (fields.size() < h.needed) {
    throw RowProblem{"expected " + std::to_string(h.names.size()) +
                     " fields as in the header (line " + std::to_string(h.line) + "), got " +
                     std::to_string(fields.size())};
  }
  auto number = [&](const Column& c, double fallback) {
    if (c.index < 0) return fallback;
    const std::string& f = fields[c.index];
    double v = 0;
    if (!parse_number(f, v)) throw RowProblem{c.name + ": '" + f + "' is not a number"};
    return v;
  };
  GazeSample s;
  s.time_s = number(h.t, kNaN);
  if (h.time_unit == TimeUnit::kMilliseconds) s.time_s *= 1e-3;
  s.pos = {number(h.x, kNaN), number(h.y, kNaN)};
  if (h.pupil) s.pos.y = 1.0 - s.pos.y;  // Pupil: origin bottom-left
  if (h.pos_unit == PosUnit::kPixels) s.pos = {s.pos.x / width, s.pos.y / height};
  s.confidence = number(h.conf, 1.0);
  if (h.conf.index >= 0 && fields[h.conf.index].empty()) s.confidence = 1.0;
  if (h.valid.index >= 0 && !parse_bool(fields[h.valid.index], s.valid)) {
    throw RowProblem{"valid: expected 1/0 or true/false, got '" + fields[h.valid.index] + "'"};
  }
  b.add(s, number(h.latency, kNaN));
}

/// A row that cannot be read: an error with --strict, else skipped with a
/// warning (the first kMaxRowWarnings of them) and counted.
void skip_row(Builder& b, std::string what, bool cut_off, const TraceOptions& options) {
  if (cut_off) what += " (the last line is cut off: no newline at its end)";
  if (options.strict) throw Error(what + "; rejected by --strict");
  ++b.trace.skipped_rows;
  if (b.trace.warnings.size() < kMaxRowWarnings) b.trace.warnings.push_back(what + "; row skipped");
}

}  // namespace

Trace parse_trace_csv(const std::string& text, const std::string& where,
                      const TraceOptions& options) {
  Builder b(options.off_screen_limit);
  int width = options.width_px, height = options.height_px;
  std::vector<std::string> fields;
  std::optional<CsvHeader> header;
  size_t line_no = 0, pos = 0;
  while (pos < text.size()) {
    size_t nl = text.find('\n', pos);
    if (nl == std::string::npos) nl = text.size();
    std::string line = text.substr(pos, nl - pos);
    const bool cut_off = nl == text.size();  // the last line, without its newline
    pos = nl + 1;
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line_no == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line = line.substr(3);  // BOM
    const std::string t = trim(line);
    if (t.empty()) continue;
    if (t[0] == '#') {
      const std::string c = lower(trim(t.substr(1)));
      if (c.rfind("screen_px:", 0) == 0 && !parse_screen(c.substr(10), width, height)) {
        throw Error(where_line(where, line_no) + ": screen_px: expected WIDTHxHEIGHT, got '" +
                    trim(t.substr(1)).substr(10) + "'");
      }
      continue;
    }
    const bool split_ok = split_csv(line, fields);
    if (!header) {
      if (!split_ok) throw Error(where_line(where, line_no) + ": unterminated quoted field");
      header = read_header(fields, line_no, t, where, options);
      b.with_latency = header->latency.index >= 0;
      b.trace.format = header->pupil ? "pupil-csv" : "csv";
      continue;
    }
    try {
      read_row(fields, split_ok, *header, width, height, b);
    } catch (const RowProblem& p) {
      skip_row(b, where_line(where, line_no) + ": " + p.what, cut_off, options);
    }
  }
  if (b.trace.skipped_rows > kMaxRowWarnings) {
    b.trace.warnings.push_back(where + ": " +
                               std::to_string(b.trace.skipped_rows - kMaxRowWarnings) +
                               " more rows skipped");
  }
  if (!header) throw Error(where + ": empty file: expected a header line and samples");
  return b.finish(where, header->pos_unit);
}

}  // namespace foveate::gaze
