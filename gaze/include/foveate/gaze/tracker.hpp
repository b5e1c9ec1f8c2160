#pragma once
// The gaze tracker: a gaze source, the filter and the latency estimate, giving
// per frame the GazeState that every technique follows. This is the one place
// where samples become the gaze a frame is rendered for; the app, the tests and
// programs outside the tree all go through it.
#include <memory>
#include <optional>
#include <string>

#include "foveate/core/display.hpp"
#include "foveate/core/gaze_state.hpp"
#include "foveate/gaze/filter.hpp"
#include "foveate/gaze/gaze.hpp"
#include "foveate/gaze/latency.hpp"

namespace foveate {

namespace gaze {

/// What the tracker's frames were: how many followed the gaze asked for, and
/// how many did not (held, fallen back, off the image).
struct TrackerCounts {
  int frames = 0;
  int holding = 0;   ///< the last gaze held through a blink or dropout
  int fallback = 0;  ///< the fallback point with a widened fovea
  int saccades = 0;
  int off_image = 0;  ///< the gaze given to the frame lay off the image
};

struct TrackerOptions {
  FilterOptions filter;
  LatencyOptions latency;
  double max_saccade_deg_per_s = 200.0;  ///< copied into every GazeState
};

class GazeTracker {
 public:
  /// `display` is the render display: its size in pixels turns normalized
  /// gaze into pixels and its geometry turns motion into degrees.
  GazeTracker(std::unique_ptr<GazeSource> source, const Display& display,
              TrackerOptions options = {});
  /// A source from a spec (see make_gaze_source); empty = the screen centre.
  GazeTracker(const std::string& spec, const GazeContext& context, TrackerOptions options = {});
  ~GazeTracker();
  GazeTracker(GazeTracker&&) noexcept;
  GazeTracker& operator=(GazeTracker&&) noexcept;

  /// The filtered gaze for the frame rendered at `time_s` (render clock), with
  /// the estimated latency of the samples behind it. Frames are taken to be
  /// shown at `shown_s` (default: their render time). Call once per frame.
  GazeState at(double time_s, std::optional<double> shown_s = std::nullopt);
  /// The filter's output for the last frame (holding, fallback, saccade).
  [[nodiscard]] const FilteredGaze& last() const;
  /// Whether the last frame's gaze lay off the image (outside [0, 1]
  /// normalized): the source looked off the screen, within what the filter
  /// accepts (FilterOptions::off_screen_limit).
  [[nodiscard]] bool last_off_image() const;
  [[nodiscard]] const TrackerCounts& counts() const;
  [[nodiscard]] const GazeSource& source() const;
  [[nodiscard]] const GazeFilter& filter() const;
  [[nodiscard]] const LatencyEstimator& latency() const;
  [[nodiscard]] std::string describe() const;
  /// What the source and the filter did: dropped samples, holds, fallbacks,
  /// frames off the image, latency.
  [[nodiscard]] std::string report() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gaze
}  // namespace foveate
