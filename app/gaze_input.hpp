#pragma once
// The gaze that render, bench and view follow, from a --gaze spec.
#include <memory>
#include <string>

#include "foveate/techniques/technique.hpp"

namespace foveate::app {

class Session;

class GazeInput {
 public:
  virtual ~GazeInput() = default;
  /// The filtered gaze for the frame shown at `time_s`.
  virtual GazeState at(double time_s) = 0;
  [[nodiscard]] virtual std::string describe() const = 0;
  /// Summary of what the filter did (dropped samples, holds, fallbacks); may be empty.
  [[nodiscard]] virtual std::string report() const { return {}; }

  /// Spec: X,Y | fixed:X,Y | trace:FILE | synthetic[:SEED] | pupil[:HOST:PORT] | nearest.
  /// Empty = the screen centre.
  static std::unique_ptr<GazeInput> create(const std::string& spec, Session& session);
};

}  // namespace foveate::app
