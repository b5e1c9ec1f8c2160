#pragma once
// Gaze sources behind one interface: a sample is a time, a position in
// normalized display coordinates (origin top-left, 0..1 across the screen), a
// confidence and a validity flag. Sources: fixed point, mouse, trace replay,
// a synthetic viewer, a nearest-object path and live Pupil Capture/Service.
//
// Bad samples (NaN or infinite values, out-of-range positions or confidences,
// timestamps that go backwards or repeat) are dropped and counted in one place,
// SampleValidator, which trace replay, the Pupil source and the filter share.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "foveate/core/display.hpp"

namespace foveate::gaze {

struct GazeSample {
  double time_s = 0.0;      ///< seconds (render clock for live sources, trace time for files)
  Vec2d pos{0.5, 0.5};      ///< normalized, origin top-left
  double confidence = 1.0;  ///< 0..1
  bool valid = true;        ///< false during blinks and tracking loss

  /// The position in pixels of a width x height screen (origin top-left).
  [[nodiscard]] Vec2d pixels(int width, int height) const;
};

class GazeSource {
 public:
  virtual ~GazeSource() = default;
  /// Gaze at render clock time t (seconds since the run started). Called once
  /// per frame with t non-decreasing.
  virtual GazeSample sample(double t_s) = 0;
  [[nodiscard]] virtual std::string describe() const = 0;
  /// What the source dropped or counted so far (may be empty).
  [[nodiscard]] virtual std::string report() const { return {}; }
};

/// What a source may need from the renderer.
struct GazeContext {
  Display display;  ///< the render display: pixel <-> normalized and degrees
  /// Normalized mouse position; empty function when there is no window, nullopt
  /// when the mouse is outside it.
  std::function<std::optional<Vec2d>()> mouse;
  /// Normalized screen positions of scene objects at time t, nearest first;
  /// empty function (or empty result) when the scene has none.
  std::function<std::vector<Vec2d>(double t_s)> objects;
  /// trace:FILE: a row that cannot be read is an error (TraceOptions::strict).
  bool strict_traces = false;
  /// Receives warnings (rows of a trace skipped, "FILE:LINE: why"); none shown when empty.
  std::function<void(const std::string&)> warn;
};

/// Parses a gaze spec and creates the source:
///   fixed:X,Y (or X,Y)  a point on the image: whole numbers are pixels, numbers with a
///                        decimal point normalized (0.0..1.0; parse_point_on_image)
///   trace:FILE           CSV, Pupil gaze_positions.csv or JSON, interpolated at render time
///   synthetic[:SEED]     the seeded synthetic viewer
///   pupil[:HOST[:PORT]]  live Pupil Capture / Service (default 127.0.0.1:50020)
///   mouse                the window's mouse (needs ctx.mouse)
///   nearest              looks at the nearest scene object (needs ctx.objects)
/// Throws foveate::Error with a clear message on a bad spec.
std::unique_ptr<GazeSource> make_gaze_source(const std::string& spec, const GazeContext& ctx);

/// Checks what can be checked of `spec` before a source is made, for an
/// image of width x height pixels: a fixed point must lie on it. Throws
/// foveate::Error with the reason.
void check_gaze_spec(const std::string& spec, int width, int height);

/// The help text for --gaze (one line per form).
const char* gaze_spec_help();

/// Exact visual angle in degrees between two normalized screen positions.
double angle_between_deg(const Display& display, Vec2d a, Vec2d b);

// ------------------------------------------------------------ dropped samples

enum class DropReason { kNonFinite, kOutOfRange, kBackwards, kDuplicate };
const char* to_string(DropReason reason);

struct DropCounts {
  std::uint64_t non_finite = 0;  ///< NaN or infinite time, position or confidence
  std::uint64_t out_of_range =
      0;                        ///< position beyond the off-screen limit, confidence outside 0..1
  std::uint64_t backwards = 0;  ///< timestamp earlier than the previous sample's
  std::uint64_t duplicate = 0;  ///< timestamp equal to the previous sample's

  [[nodiscard]] std::uint64_t total() const {
    return non_finite + out_of_range + backwards + duplicate;
  }
  void add(DropReason reason);
  DropCounts& operator+=(const DropCounts& o);
  /// "3 dropped (1 non-finite, 2 backwards)" or "none dropped".
  [[nodiscard]] std::string summary() const;
};

/// Checks samples in arrival order. Accepted samples advance the clock; a
/// dropped sample never does.
class SampleValidator {
 public:
  /// Positions are allowed `off_screen_limit` beyond the screen on each side
  /// (normalized: 1 = a screen's width or height; trackers legitimately
  /// report gaze slightly off the display).
  explicit SampleValidator(double off_screen_limit = 0.25);
  /// The reason the sample must be dropped (and counts it), or nullopt.
  std::optional<DropReason> check(const GazeSample& s);
  bool accept(const GazeSample& s) { return !check(s).has_value(); }
  /// Forget the previous timestamp (a tracker restarted with a new clock).
  void reset_clock() { have_last_ = false; }
  [[nodiscard]] const DropCounts& counts() const { return counts_; }
  [[nodiscard]] std::uint64_t accepted() const { return accepted_; }
  [[nodiscard]] double off_screen_limit() const { return off_screen_limit_; }

 private:
  double off_screen_limit_;
  bool have_last_ = false;
  double last_time_ = 0.0;
  DropCounts counts_;
  std::uint64_t accepted_ = 0;
};

}  // namespace foveate::gaze
