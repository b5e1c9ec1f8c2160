#pragma once
// The gaze a frame is rendered for: what every technique foveates around.
// The gaze library (foveate::gaze) produces it from an eye tracker; a
// renderer with a gaze of its own fills it in directly.
#include "foveate/core/display.hpp"

namespace foveate {

/// The gaze for one frame, after filtering.
struct GazeState {
  Vec2d gaze_px{0.0, 0.0};   ///< pixels, origin top-left
  double fovea_scale = 1.0;  ///< > 1 widens every foveal region (tracker fallback)
  double latency_ms = 0.0;   ///< end-to-end gaze latency: regions grow by the saccade reach
  double max_saccade_deg_per_s = 200.0;  ///< the fastest the eye moves (S_max of Swafford eq. 1)
};

}  // namespace foveate
