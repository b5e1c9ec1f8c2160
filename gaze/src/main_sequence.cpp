#include "foveate/gaze/main_sequence.hpp"

#include <algorithm>
#include <cmath>

namespace foveate::gaze {

double MainSequence::duration_s(double amplitude_deg) const {
  return (d0_ms + k_ms_per_deg * std::max(0.0, amplitude_deg)) * 1e-3;
}

double MainSequence::peak_velocity_deg_per_s(double amplitude_deg) const {
  return vmax_deg_per_s * (1.0 - std::exp(-std::max(0.0, amplitude_deg) / c_deg));
}

double MainSequence::amplitude_for_peak_deg(double peak) const {
  const double f = std::clamp(peak / vmax_deg_per_s, 0.0, 0.999);
  return -c_deg * std::log1p(-f);
}

namespace {

/// Peak / mean of u^a (1-u)^a on [0, 1]: 0.25^a / B(a+1, a+1).
double profile_ratio(double a) {
  return std::exp(a * std::log(0.25) + std::lgamma(2 * a + 2) - 2 * std::lgamma(a + 1));
}

double inv_beta(double a) { return std::exp(std::lgamma(2 * a + 2) - 2 * std::lgamma(a + 1)); }

}  // namespace

double profile_exponent_for_ratio(double ratio) {
  const double r = std::clamp(ratio, 1.0001, 3.5);
  double lo = 0.0, hi = 12.0;
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (lo + hi);
    (profile_ratio(mid) < r ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double profile_velocity(double u, double a) {
  if (u <= 0.0 || u >= 1.0) return 0.0;
  return std::pow(u * (1.0 - u), a) * inv_beta(a);
}

namespace {

/// Continued fraction of the incomplete beta function (modified Lentz).
double beta_cf(double a, double b, double x) {
  constexpr double tiny = 1e-300, eps = 1e-15;
  const double qab = a + b, qap = a + 1.0, qam = a - 1.0;
  double c = 1.0, d = 1.0 - qab * x / qap;
  if (std::fabs(d) < tiny) d = tiny;
  d = 1.0 / d;
  double h = d;
  for (int m = 1; m <= 300; ++m) {
    const double m2 = 2.0 * m;
    double aa = m * (b - m) * x / ((qam + m2) * (a + m2));
    d = 1.0 + aa * d;
    if (std::fabs(d) < tiny) d = tiny;
    c = 1.0 + aa / c;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1.0 / d;
    h *= d * c;
    aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2));
    d = 1.0 + aa * d;
    if (std::fabs(d) < tiny) d = tiny;
    c = 1.0 + aa / c;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double del = d * c;
    h *= del;
    if (std::fabs(del - 1.0) < eps) break;
  }
  return h;
}

}  // namespace

double profile_position(double u, double a) {
  if (u <= 0.0) return 0.0;
  if (u >= 1.0) return 1.0;
  if (u == 0.5) return 0.5;
  // I_u(p, p) with p = a + 1; the profile is symmetric, so use the side where
  // the continued fraction converges fast.
  const double p = a + 1.0;
  if (u > 0.5) return 1.0 - profile_position(1.0 - u, a);
  const double front =
      std::exp(std::lgamma(2 * p) - 2 * std::lgamma(p) + p * std::log(u) + p * std::log1p(-u));
  return front * beta_cf(p, p, u) / p;
}

}  // namespace foveate::gaze
