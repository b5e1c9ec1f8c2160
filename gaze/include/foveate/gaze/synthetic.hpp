#pragma once
// A synthetic viewer, seeded and deterministic: fixations with drift and
// microsaccades, saccades on the main sequence (main_sequence.hpp), smooth
// pursuit of a moving target, and blinks.
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "foveate/gaze/gaze.hpp"
#include "foveate/gaze/main_sequence.hpp"

namespace foveate::gaze {

struct SyntheticOptions {
  std::uint64_t seed = 1;
  MainSequence main_sequence;
  double fixation_mean_s = 0.28;  ///< mean fixation duration (gamma distributed)
  double fixation_min_s = 0.1;
  double drift_deg_per_sqrt_s = 0.15;  ///< fixational drift as a random walk
  double microsaccade_rate_hz = 1.2;   ///< Poisson rate inside fixations
  double microsaccade_max_deg = 0.5;
  double saccade_min_deg = 2.0;
  double saccade_max_deg = 25.0;
  double pursuit_probability = 0.15;  ///< after a fixation: pursuit instead of a saccade
  double pursuit_min_deg_per_s = 4.0;
  double pursuit_max_deg_per_s = 20.0;
  double pursuit_min_s = 0.5;
  double pursuit_max_s = 1.5;
  double blink_rate_hz = 0.25;  ///< blinks start inside fixations at this rate
  double blink_min_s = 0.1;
  double blink_max_s = 0.3;
  double edge_inset = 0.05;  ///< targets stay this far inside the screen (normalized)
  double noise_deg = 0.0;    ///< Gaussian tracker noise per sample (0: none)
  double rate_hz = 0.0;      ///< tracker rate; 0 = continuous (sample at t)
  double latency_ms = 0.0;   ///< the tracker reports the eye as it was this long ago
};

/// One piece of the viewer's behaviour, for tests and `gaze synth`.
struct Movement {
  enum class Kind { kFixation, kSaccade, kPursuit, kBlink, kMicrosaccade };
  Kind kind = Kind::kFixation;
  double start_s = 0.0;
  double end_s = 0.0;
  Vec2d from{0.5, 0.5};  ///< normalized
  Vec2d to{0.5, 0.5};
  double amplitude_deg = 0.0;   ///< saccades and microsaccades
  double peak_deg_per_s = 0.0;  ///< saccades and microsaccades (main sequence)
};
const char* to_string(Movement::Kind kind);

class SyntheticViewer final : public GazeSource {
 public:
  SyntheticViewer(const Display& display, SyntheticOptions options = {});
  ~SyntheticViewer() override;
  SyntheticViewer(const SyntheticViewer&) = delete;
  SyntheticViewer& operator=(const SyntheticViewer&) = delete;

  GazeSample sample(double t_s) override;
  [[nodiscard]] std::string describe() const override;
  /// The eye itself at time t (no tracker rate, latency or noise). Any t >= 0,
  /// in any order: the behaviour is generated ahead deterministically.
  GazeSample eye(double t_s);
  /// Every movement that starts before t (generating as needed).
  std::vector<Movement> movements_until(double t_s);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace foveate::gaze
