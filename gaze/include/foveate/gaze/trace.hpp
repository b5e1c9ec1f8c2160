#pragma once
// Gaze recordings: reading (CSV with a header, Pupil Capture's exported
// gaze_positions.csv, JSON), writing (the project's CSV and JSON forms) and
// interpolation at render time.
//
// The project's CSV form:
//   # foveate gaze trace            (comment lines start with '#')
//   # screen_px: 1920x1080          (optional: the pixel size for pixel units)
//   time_s,x,y,confidence,valid
//   0.000000,0.500000,0.500000,1.000,1
// Column names choose the units: time_s / time_ms (also t, time, timestamp,
// with _s or _ms), x / y (normalized) or x_px / y_px (pixels); confidence,
// valid and latency_ms are optional; other columns are ignored. Units that the
// header does not say come from TraceOptions (default seconds, normalized).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "foveate/gaze/gaze.hpp"

namespace foveate::gaze {

enum class TimeUnit { kAuto, kSeconds, kMilliseconds };
enum class PosUnit { kAuto, kNormalized, kPixels };

struct TraceOptions {
  TimeUnit time_unit = TimeUnit::kAuto;  ///< when the header does not say: seconds
  PosUnit pos_unit = PosUnit::kAuto;     ///< when the header does not say: normalized
  /// Screen size for pixel units when the file does not give one (# screen_px: WxH).
  int width_px = 1920;
  int height_px = 1080;
  double off_screen_limit = 0.25;  ///< SampleValidator's
  /// A row that cannot be read (too few fields, not a number, a last line cut
  /// off mid-write) is an error; otherwise it is skipped with a warning.
  bool strict = false;
};

/// The largest trace file read, in MiB; FOVEATE_MAX_TRACE_MB raises it.
inline constexpr std::uint64_t kMaxTraceMiB = 512;

struct Trace {
  std::vector<GazeSample> samples;  ///< accepted samples, strictly increasing times, first at 0
  std::vector<double> latency_ms;   ///< per sample when the file has latency_ms, else empty
  DropCounts dropped;               ///< samples dropped while reading
  double time_origin_s = 0.0;       ///< the original timestamp of the first sample (seconds)
  std::string format;               ///< "csv", "pupil-csv" or "json"
  /// Rows skipped because they could not be read ("FILE:LINE: why"; the first
  /// few, then a count of the rest), for the caller to show.
  std::vector<std::string> warnings;
  std::uint64_t skipped_rows = 0;  ///< rows skipped (all of them, not only those in warnings)

  [[nodiscard]] double duration_s() const {
    return samples.empty() ? 0.0 : samples.back().time_s - samples.front().time_s;
  }
};

/// Reads a trace file; the format is detected from the extension (.json) and
/// the CSV header (Pupil's gaze_timestamp / norm_pos_x columns). Errors read
/// "FILE:LINE: what is wrong"; bad samples are dropped and counted, never fatal,
/// but a file with no usable sample is an error. A CSV row that cannot be read
/// is skipped and named in Trace::warnings (an error with options.strict); the
/// file must be a regular file of at most kMaxTraceMiB (FOVEATE_MAX_TRACE_MB).
Trace load_trace(const std::string& path, const TraceOptions& options = {});
/// The same from text; `where` names the source in messages.
Trace parse_trace_csv(const std::string& text, const std::string& where,
                      const TraceOptions& options = {});
Trace parse_trace_json(const std::string& text, const std::string& where,
                       const TraceOptions& options = {});

/// The project's CSV form (normalized units, seconds, with latency_ms when present).
std::string trace_to_csv(const Trace& trace);
/// The JSON form: {"format": "foveate-gaze", "time_unit": "s", "position_unit":
/// "normalized", "samples": [[t, x, y, confidence, valid], ...]}.
std::string trace_to_json(const Trace& trace);

/// What happens after the last sample.
enum class TraceEnd { kHold, kLoop };

struct InterpolationOptions {
  /// Samples further apart than this are a dropout: no interpolation across it,
  /// the gaze is reported invalid inside the gap.
  double max_gap_s = 0.1;
  TraceEnd end = TraceEnd::kHold;
};

/// The gaze at trace time t: linear interpolation between the two valid
/// samples around t; invalid inside invalid stretches and dropouts; before the
/// first sample the first, after the last the last (or looped). The returned
/// time is t (the sample is what the tracker would have given at t).
GazeSample interpolate(const Trace& trace, double t_s, const InterpolationOptions& options = {});

/// Replay of a trace against the render clock.
class TraceSource final : public GazeSource {
 public:
  TraceSource(Trace trace, std::string name, InterpolationOptions options = {});
  GazeSample sample(double t_s) override;
  [[nodiscard]] std::string describe() const override;
  [[nodiscard]] std::string report() const override;
  [[nodiscard]] const Trace& trace() const { return trace_; }

 private:
  Trace trace_;
  std::string name_;
  InterpolationOptions options_;
};

}  // namespace foveate::gaze
