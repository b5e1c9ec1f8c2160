#pragma once
// A synthetic viewer, seeded and deterministic: fixations with drift and
// microsaccades, saccades on the main sequence, smooth pursuit of a moving
// target, and blinks. And a viewer that looks at the nearest scene object.
//
// Main sequence (amplitude A in degrees):
//   duration        D(A) = D0 + k * A            D0 = 21 ms, k = 2.2 ms/deg
//                   (the linear duration-amplitude law, Carpenter,
//                   "Movements of the Eyes", 1988)
//   peak velocity   Vp(A) = Vmax * (1 - exp(-A / C))
//                   (the exponential saturation form used for the main
//                   sequence since Baloh et al. 1975; Vmax = 600 deg/s and
//                   C = 10 deg are typical fitted values, kept as parameters)
// The velocity profile over the saccade is v(u) ~ u^a (1 - u)^a (u = t / D),
// with a chosen per saccade so that its peak equals Vp(A) and its integral
// equals A: both laws hold exactly (a = 2 is the minimum-jerk profile).
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "foveate/gaze/gaze.hpp"

namespace foveate::gaze {

struct MainSequence {
  double d0_ms = 21.0;
  double k_ms_per_deg = 2.2;
  double vmax_deg_per_s = 600.0;
  double c_deg = 10.0;

  [[nodiscard]] double duration_s(double amplitude_deg) const;
  [[nodiscard]] double peak_velocity_deg_per_s(double amplitude_deg) const;
  /// Inverse of peak_velocity: the amplitude whose peak velocity is v (for
  /// landing-point prediction); saturates just below Vmax.
  [[nodiscard]] double amplitude_for_peak_deg(double peak_deg_per_s) const;
};

/// The shape exponent a of v(u) ~ u^a (1-u)^a whose peak/mean ratio is `ratio`
/// (clamped to the family's range 1 < ratio <= 3).
double profile_exponent_for_ratio(double ratio);
/// Fraction of the amplitude covered at u in [0, 1] for exponent a (the
/// regularized incomplete beta function I_u(a+1, a+1)).
double profile_position(double u, double a);
/// Normalized velocity v(u) / (A / D) for exponent a (mean 1 over [0, 1]).
double profile_velocity(double u, double a);

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
  double screen_margin = 0.05;  ///< targets stay this far inside the screen
  double noise_deg = 0.0;       ///< Gaussian tracker noise per sample (0: none)
  double rate_hz = 0.0;         ///< tracker rate; 0 = continuous (sample at t)
  double latency_ms = 0.0;      ///< the tracker reports the eye as it was this long ago
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

/// Looks at the nearest scene object (ctx.objects()[0]): a main-sequence
/// saccade when it changes or escapes by more than `catch_up_deg`, smooth
/// pursuit otherwise; the screen centre while there is no object.
class NearestObjectViewer final : public GazeSource {
 public:
  NearestObjectViewer(const Display& display, std::function<std::vector<Vec2d>(double)> objects,
                      MainSequence main_sequence = {}, double catch_up_deg = 1.0);
  GazeSample sample(double t_s) override;
  [[nodiscard]] std::string describe() const override;

 private:
  Display display_;
  std::function<std::vector<Vec2d>(double)> objects_;
  MainSequence ms_;
  double catch_up_deg_;
  Vec2d pos_{0.5, 0.5};
  bool started_ = false;
  bool in_saccade_ = false;
  double sac_start_ = 0, sac_dur_ = 0, sac_a_ = 2;
  Vec2d sac_from_{}, sac_to_{};
};

}  // namespace foveate::gaze
