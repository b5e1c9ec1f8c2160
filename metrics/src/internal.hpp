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

// ---- The acuity-aware band-pass pyramid (acuity.cpp, contrast.cpp) ----------

/// Cutoff of ladder entry j in cycles per pixel: c_j = c_0 2^(-j/2) with
/// c_0 = 0.5 * 2^(-1/4), so that the entry's low-pass ends at 0.5 cycles per
/// sample on the grid that stores it.
double ladder_cutoff(int j);
/// The ladder's low-pass at radial frequency rho for cutoff c (same units): 1
/// up to c 2^(-1/4), 0 from c 2^(1/4), a raised cosine in log2(rho) between.
double ladder_lowpass(double rho, double c);

/// Where every sample of every pyramid level lies on the ladder. Level n has
/// (w, h) samples; sample (i, j) is the centre of pixels [i 2^n, (i+1) 2^n) x
/// [j 2^n, (j+1) 2^n), at image coordinates ((i + 0.5) 2^n, (j + 0.5) 2^n).
struct LevelGeometry {
  int w = 0, h = 0;
  std::vector<float> lambda;  ///< ladder position 2 log2(c_0 / f_c) of the sample
  std::vector<float> ppd;     ///< pixels per degree there
};

struct PyramidGeometry {
  std::vector<LevelGeometry> levels;  ///< 0 (the image's pixels) .. N
  /// Level-0 region holding every pixel with lambda < 3 (plus a margin): only
  /// there are the full-resolution ladder entries computed.
  int tx0 = 0, ty0 = 0, tx1 = 0, ty1 = 0;
  [[nodiscard]] int top() const { return static_cast<int>(levels.size()) - 1; }
  [[nodiscard]] bool has_tile() const { return tx1 > tx0 && ty1 > ty0; }
};

/// The geometry for a display and gaze; `eccentricity` (optional) is the
/// display's eccentricity_map, reused for level 0.
PyramidGeometry pyramid_geometry(const Display& display, Vec2d gaze, const AcuityModel& acuity,
                                 const Map* eccentricity = nullptr);

/// One image's ladder entries and its acuity-filtered reconstruction (linear).
struct AcuityPyramid {
  Map x0;                    ///< the image's linear luminance (entry -1, the identity)
  std::vector<Map> tile;     ///< entries 0, 1, 2 over the tile (full resolution)
  Map c0_tile;               ///< C_0 over the tile
  std::vector<Map> a, b, c;  ///< per level n >= 1: A_n, B_n and C_n = up(R_(n+1)) (n < N)
  Map filtered;              ///< the reconstruction: linear luminance low-passed per pixel
};

/// Decomposes linear luminance and reconstructs it with every pixel's weights.
AcuityPyramid acuity_pyramid(Map linear, const PyramidGeometry& geometry);

/// Pooled JND per pixel (Barten's CSF on Peli's band-limited contrast, see
/// contrast.cpp) from the two images' pyramids.
Map jnd_from_pyramids(const AcuityPyramid& reference, const AcuityPyramid& test,
                      const PyramidGeometry& geometry, const ContrastModel& contrast);

/// Throws foveate::Error unless the display has the size w x h.
void check_display(const Display& display, int width, int height, const char* what);

/// Throws foveate::Error unless both images are non-empty and have the same size.
void check_same_size(const Image& a, const Image& b, const std::string& what);
/// Throws foveate::Error unless the options are valid for compare().
void check_options(const QualityOptions& options);

/// Index i mirrored into 0..n-1 (resample.cpp).
int mirror(int i, int n);
/// A level halved in each direction by the half-band filter.
Map down(const Map& in);
/// A level doubled back to w x h by the same filter.
Map up(const Map& in, int w, int h);

}  // namespace foveate::metrics::detail
