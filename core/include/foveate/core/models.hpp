#pragma once
// The other papers' models as plain functions.
#include <array>
#include <vector>

#include "foveate/core/acuity.hpp"
#include "foveate/core/display.hpp"

namespace foveate {

// --- Swafford, Cosker, Mitchell: "Latency Aware Foveated Rendering in UE4" (2015), eq. 1.
//   F' = 2 * rho_pixel * d_u * tan(L_tot * S_max + alpha / 2) + 2 * b_w + c
struct LatencyAwareFovea {
  double latency_ms = 0.0;               ///< L_tot, worst-case total latency
  double max_saccade_deg_per_s = 200.0;  ///< S_max
  double fovea_deg = 5.0;                ///< alpha, angle the fovea subtends
  double blend_border_px = 0.0;          ///< b_w
  double error_px = 0.0;                 ///< c

  /// Foveal diameter F' in pixels on `display` (rho * d_u = eye_distance_px).
  [[nodiscard]] double diameter_px(const Display& display) const;
  /// The same diameter as a visual angle (degrees) at the display centre.
  [[nodiscard]] double diameter_deg(const Display& display) const;
  void validate() const;
};

// --- Meng, Du, Zwicker, Varshney: "Kernel Foveated Rendering" (2018).
// Screen (W x H) <-> kernel log-polar buffer (w x h) = (W / sigma) x (H / sigma),
// with L = log(sqrt(W^2 + H^2)) and the kernel K(x) = x^alpha.
struct KernelLogPolar {
  double screen_w = 1920.0;
  double screen_h = 1080.0;
  double sigma = 1.8;  ///< buffer parameter, W / w
  double alpha = 4.0;  ///< kernel exponent

  [[nodiscard]] double buffer_w() const { return screen_w / sigma; }
  [[nodiscard]] double buffer_h() const { return screen_h / sigma; }
  [[nodiscard]] double log_extent() const;  ///< L
  /// Screen position (pixels) -> buffer position (u, v), relative to the gaze.
  [[nodiscard]] Vec2d to_buffer(Vec2d screen, Vec2d gaze) const;
  /// Buffer position (u, v) -> screen position (pixels).
  [[nodiscard]] Vec2d to_screen(Vec2d buffer, Vec2d gaze) const;
  void validate() const;
};

/// The texels of a w x h log-polar buffer, mapped to the screen around `gaze`
/// with extent L and exponent alpha (buffer -> screen as in KernelLogPolar,
/// texel centres displaced by up to half a texel of jitter), that can land at
/// least `inner` pixels from the gaze and inside `keep` = (x0, y0, x1, y1):
/// per band of `band` rows, the columns [x0, x1) outside which none does, as
/// (x0, y0, x1, y1) texel rectangles. A shading pass drawn over these alone
/// shades what a full-buffer pass would, without running the shader for the
/// texels it would discard (the disc at the gaze, the corners beyond the
/// screen). Empty bands are left out.
std::vector<std::array<int, 4>> log_polar_cover(Vec2d gaze, double L, double alpha, int w, int h,
                                                double inner, const std::array<double, 4>& keep,
                                                int band = 4);

// --- Silvera: "OpenGL Foveated Rendering" (2022), mask-based checkerboard.
// Pixels are grouped in n x n quads, quads in 2 x 2 tiles. Region k (0..3)
// drops k of the 4 quads of each tile. Regions are chosen per tile (Silvera's
// block-aligned distance): by the distance from the gaze to the nearest point
// of the pixel's tile, so that region 0 holds every pixel within
// thresholds_px[0] of the gaze and a tile is never split between regions.
struct CheckerboardPattern {
  int block = 16;                         ///< n
  std::array<double, 3> thresholds_px{};  ///< region k+1 begins beyond thresholds_px[k]

  /// Silvera's fixed thresholds: 10 %, 25 %, 40 % of the framebuffer diagonal.
  static CheckerboardPattern from_fractions(int block, int width, int height,
                                            std::array<double, 3> fractions = {0.10, 0.25, 0.40});
  /// Thresholds from the acuity model and the block size: region k starts
  /// where the MAR in pixels, w(e) * ppd(e), reaches twice the largest gap its
  /// pattern leaves between kept pixels (checkerboard_gap_px: n + 1 for the
  /// n x n holes of regions 1 and 2, (n + 1) sqrt 2 across the dropped corner
  /// quad of region 3), i.e. two samples per resolvable cycle even across a
  /// hole. The average density of a region (sqrt(4 / (4 - k)) per axis) is
  /// never the limit: a hole of n pixels is wider than that for any n.
  /// ppd is the tangential density D / cos e (the smaller of the two at a
  /// flat display), for a gaze at the display centre like radius_px_at.
  static CheckerboardPattern from_acuity(int block, const Display& display,
                                         const AcuityModel& acuity);

  /// Block-aligned distance (pixels) from the gaze to the nearest point of
  /// the tile of `pixel`.
  [[nodiscard]] double tile_distance(Vec2d pixel, Vec2d gaze) const;
  /// Region 0..3 of a pixel.
  [[nodiscard]] int region(Vec2d pixel, Vec2d gaze) const;
  /// Quad index within the tile, 0..3: (0,0)=0, (x0,y1)=1, (x1,y0)=2, (x1,y1)=3,
  /// with x, y the quad column and row; region k drops quads 1..k.
  [[nodiscard]] int quad(Vec2d pixel) const;
  /// Whether the pixel is shaded (not dropped).
  [[nodiscard]] bool kept(Vec2d pixel, Vec2d gaze) const;
  /// How many pixels of a width x height screen each region keeps (pixel
  /// centres, as kept()): what one shading pass over the kept pixels shades,
  /// split by region. Counted per row of tiles, in the run of tiles each
  /// threshold holds (found by bisection): checkerboard counts every frame,
  /// and with 1-pixel quads a count tile by tile costs milliseconds.
  [[nodiscard]] std::array<double, 4> kept_by_region(int width, int height, Vec2d gaze) const;
  void validate() const;
};

/// Sampling factor of a checkerboard region that keeps (4 - k) of 4 quads, by
/// average density: sqrt(4 / (4 - k)).
double checkerboard_sampling_factor(int region);
/// The largest gap (pixels) that region k's pattern leaves between kept pixel
/// centres with quads of n = `block` pixels: 1 in region 0 (native spacing);
/// n + 1 across the n x n holes of regions 1 and 2 (kept centres on either
/// side of a hole along its rows and columns); (n + 1) sqrt 2 across the
/// dropped corner quad of region 3, whose rows and columns hold no kept pixel,
/// between the kept quads at its corners.
double checkerboard_gap_px(int region, int block);
/// The MAR in pixels at eccentricity e (degrees) for a gaze at the display
/// centre: w(e) times the tangential pixel density there (D / cos e per radian).
double mar_px_at(const Display& display, const AcuityModel& acuity, double eccentricity_deg);

}  // namespace foveate
