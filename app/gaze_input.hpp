#pragma once
// The gaze that render, bench and view follow: a gaze source (foveate::gaze)
// through the tracker filter, with the latency estimate fed to the techniques.
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "foveate/techniques/technique.hpp"

namespace foveate::app {

class Session;

class GazeInput {
 public:
  /// Spec: X,Y | fixed:X,Y | trace:FILE | synthetic[:SEED] | pupil[:HOST:PORT] | mouse | nearest.
  /// Empty = the screen centre. `mouse` needs `mouse` (normalized, top-left).
  GazeInput(const std::string& spec, Session& session,
            std::function<std::optional<Vec2d>()> mouse = {});
  ~GazeInput();
  /// The filtered gaze for the frame rendered at `time_s` (render clock), with
  /// the estimated latency of the samples behind it. Frames are taken to be
  /// shown at `shown_s` (default: their render time).
  GazeState at(double time_s, std::optional<double> shown_s = std::nullopt);
  [[nodiscard]] std::string describe() const;
  /// What the source and the filter did: dropped samples, holds, fallbacks, latency.
  [[nodiscard]] std::string report() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace foveate::app
