#pragma once
// logpolar's plan from the acuity model, without GL: how far apart the
// buffer's samples lie at each distance from the gaze, the native disc, and
// the kernel exponent and buffer size that keep the samples within half the
// MAR outside it while shading the fewest pixels.
#include "foveate/core/acuity.hpp"
#include "foveate/core/display.hpp"

namespace foveate::tech::logpolar {

inline constexpr double kBandFraction = 0.15;  ///< blend band beyond the disc, of its radius
inline constexpr double kSkipFraction =
    0.85;  ///< texels within this much of the radius are not shaded

/// The largest gap (screen pixels) between the samples of a W x H screen's
/// log-polar buffer (w x h texels, L = log of the extent) at distance r from
/// the gaze: the diagonal of its cell, which spans r L alpha t^(1 - 1/alpha)
/// / w radially (t = log r / L) and 2 pi r / h around; the diameter of the
/// largest disc holding no sample, as for the checkerboard's holes
/// (checkerboard_gap_px).
double buffer_gap_px(double r, double L, double alpha, double w, double h);

/// What a kernel exponent gives on a display, for a gaze at the centre.
struct KernelPlan {
  double accepted_sigma = 0;  ///< the largest sigma within the MAR outside the disc (unclamped)
  double sigma = 1;           ///< accepted_sigma clamped into [1, 16]
  double native_px = 0;       ///< radius of the native disc
  double shaded = 0;          ///< pixels shaded per frame: buffer texels and the disc's square
};

/// The plan for exponent `alpha` and a native disc of at least `fovea_deg`;
/// `sigma` > 0 fixes the buffer's size instead of taking the largest accepted.
KernelPlan plan_kernel(const Display& d, const AcuityModel& a, double fovea_deg, double alpha,
                       double sigma = 0.0);

/// The kernel exponent in the user study's range [1, 4] (steps of 1/8) whose
/// buffer, at the largest sigma the acuity model accepts outside the native
/// disc, shades the fewest pixels. Where no buffer is fine enough (sigma
/// would be below 1), the most compliant exponents are compared.
double acuity_kernel(const Display& d, const AcuityModel& a, double fovea_deg);

}  // namespace foveate::tech::logpolar
