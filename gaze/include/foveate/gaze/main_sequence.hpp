#pragma once
// Saccades on the main sequence (amplitude A in degrees):
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

}  // namespace foveate::gaze
