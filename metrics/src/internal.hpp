#pragma once
// Shared building blocks of the metrics: sRGB conversions and separable
// filtering with clamp-to-edge borders and optional decimation by two.
#include <array>
#include <string>
#include <vector>

#include "foveate/core/image.hpp"
#include "foveate/metrics/metrics.hpp"

namespace foveate::metrics::detail {

/// sRGB 8-bit code -> linear value in [0, 1] (IEC 61966-2-1).
const std::array<float, 256>& srgb_to_linear_table();
/// Linear value -> sRGB-encoded value in [0, 1], exact (std::pow).
double linear_to_srgb(double linear);
/// Linear luminance in [0, 1] -> luminance code in [0, 255] (table with linear
/// interpolation; error below 0.002 codes).
float luminance_to_code(float linear);

/// Linear luminance Y of every pixel (Rec. 709 / sRGB primaries).
Map luminance_linear(const Image& image);

/// A 1-D kernel applied as out[i] = sum_n w[n] * in[clamp(stride * i + offset + n)].
/// stride 1 keeps the size; stride 2 halves it (rounding up).
struct Kernel {
  std::vector<float> w;
  int offset = 0;
  int stride = 1;
};

/// Sampled Gaussian normalised to sum 1 with radius ceil(3.5 sigma). With
/// `decimate`, the taps are centred half-way between two input samples, which
/// is where the output sample of the half-resolution grid lies. Below sigma
/// 0.8 (without decimation) a 3-tap kernel [a, 1-2a, a] with a = sigma^2 / 2
/// is used so that the variance is exactly sigma^2.
Kernel gaussian_kernel(double sigma, bool decimate = false);
/// Sampled Gaussian normalised to sum 1 with a given radius (no variance fix).
Kernel gaussian_kernel_radius(double sigma, int radius);

Map filter_rows(const Map& in, const Kernel& k);
Map filter_cols(const Map& in, const Kernel& k);
inline Map filter2d(const Map& in, const Kernel& kx, const Kernel& ky) {
  return filter_cols(filter_rows(in, kx), ky);
}

/// acuity_sigma_map from a precomputed eccentricity_map.
Map acuity_sigma_from_eccentricity(const Map& eccentricity, const Display& display, Vec2d gaze,
                                   const AcuityModel& acuity);
/// acuity_difference with a precomputed acuity_sigma_map (sizes already checked).
Map acuity_difference_with_sigma(const Image& reference, const Image& test, const Map& sigma);

/// Throws foveate::Error unless both images are non-empty and have the same size.
void check_same_size(const Image& a, const Image& b, const std::string& what);
/// Throws foveate::Error unless the options are valid for compare().
void check_options(const QualityOptions& options);

}  // namespace foveate::metrics::detail
