#include "kernel_plan.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "foveate/core/models.hpp"

namespace foveate::tech::logpolar {

double buffer_gap_px(double r, double L, double alpha, double w, double h) {
  const double t = std::clamp(std::log(std::max(r, 1.0)) / L, 1e-9, 1.0);
  return std::hypot(r * L * alpha * std::pow(t, 1.0 - 1.0 / alpha) / w,
                    2.0 * std::numbers::pi * r / h);
}

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

// Native pixels' own largest gap, the diagonal of a pixel.
const double kNativeGap = std::sqrt(2.0);

// The gap the acuity model allows at distance r from a gaze at the display
// centre: half the MAR in pixels (two samples per cycle), and never less than
// native's.
double allowed_gap_px(const Display& d, const AcuityModel& a, double r) {
  return std::max(kNativeGap, 0.5 * mar_px_at(d, a, std::atan(r / d.eye_distance_px()) * kDeg));
}

// Radius (pixels) of the native disc: at least `min_px`, and out to where the
// buffer's samples are no longer closer together than native pixels.
double native_radius_px(double min_px, double L, double alpha, double w, double h) {
  double r = 2.0;
  while (r < 1e5 && buffer_gap_px(r, L, alpha, w, h) < kNativeGap) r *= 1.005;
  return std::max(min_px, r);
}

}  // namespace

KernelPlan plan_kernel(const Display& d, const AcuityModel& a, double fovea_deg, double alpha,
                       double sigma) {
  const double W = d.width_px, H = d.height_px;
  const double L = std::log(std::hypot(W, H));
  const double min_px = d.radius_px_at(fovea_deg);
  KernelPlan p;
  // The MAR criterion outside the disc, for every distance a gaze anywhere can give.
  double best = 1e9;
  for (double r = min_px; r <= std::hypot(W, H); r *= 1.01) {
    best = std::min(best, allowed_gap_px(d, a, r) / buffer_gap_px(r, L, alpha, W, H));
  }
  p.accepted_sigma = best;
  p.sigma = sigma > 0.0 ? sigma : std::clamp(best, 1.0, 16.0);
  const double w = std::max(1.0, std::round(W / p.sigma)),
               h = std::max(1.0, std::round(H / p.sigma));
  p.native_px = native_radius_px(min_px, L, alpha, w, h);
  // Shaded texels for a gaze at the centre: per row (angle), the columns from
  // the skipped disc out to the screen's edge plus the filter's reach past it.
  const double skip = kSkipFraction * p.native_px, past_edge_px = 0.02 * std::hypot(W, H);
  const auto u = [&](double r) {
    return std::pow(std::clamp(std::log(std::max(r, 1.0)) / L, 0.0, 1.0), 1.0 / alpha) * w;
  };
  for (int j = 0; j < static_cast<int>(h); ++j) {
    const double th = (j + 0.5) / h * 2.0 * std::numbers::pi;
    const double c = std::abs(std::cos(th)), s = std::abs(std::sin(th));
    const double edge = std::min(c > 1e-9 ? 0.5 * W / c : 1e9, s > 1e-9 ? 0.5 * H / s : 1e9);
    p.shaded += std::max(0.0, u(edge + past_edge_px) - u(skip));
  }
  const double side = 2.0 * p.native_px * (1.0 + kBandFraction);
  p.shaded += side * side;
  return p;
}

double acuity_kernel(const Display& d, const AcuityModel& a, double fovea_deg) {
  double best_alpha = 1.0, best_compliance = -1.0, best_shaded = 0.0;
  for (int i = 0; i <= 24; ++i) {
    const double alpha = 1.0 + i / 8.0;
    const KernelPlan p = plan_kernel(d, a, fovea_deg, alpha);
    const double compliance = std::min(p.accepted_sigma, 1.0);
    if (compliance > best_compliance + 1e-9 ||
        (compliance > best_compliance - 1e-9 && p.shaded < best_shaded)) {
      best_alpha = alpha, best_compliance = compliance, best_shaded = p.shaded;
    }
  }
  return best_alpha;
}

}  // namespace foveate::tech::logpolar
