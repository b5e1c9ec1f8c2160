#pragma once
// A radial warp whose sampling follows the acuity model (the `marwarp`
// technique's mapping; docs/continuous.md derives it). A buffer of
// `columns` x `rows` texels is laid around the gaze: a row is an angle
// (row j covers [j, j + 1) / rows of a turn), a column a distance from the
// gaze. Column u (texel centres at i + 0.5) lies at the screen distance r
// whose model eccentricity E(r) = atan(r / F) satisfies
//
//   u(r) = (2 / m) ln((m E(r) + w0) / (m E0 + w0)),   E in degrees,
//
// the integral of 2 / w(E) dE from E0: the radial spacing dr/du is half the
// MAR (m E + w0, degrees per cycle) over the angle a pixel subtends radially
// at E, one sample per half cycle (Guenter et al.'s display sharpness of two
// pixels). For a gaze at the principal point F is the eye distance and
// (m, w0) the planned acuity itself, which makes that spacing exact on a
// flat display: the radial pixel angle cos^2 E / F is what E'(r) is. For
// any other gaze F is chosen per gaze and (m, w0) made finer by a factor
// kappa <= 1, the largest at which the spacing stays within half the MAR at
// every point on the screen (checked against the exact angles), so that no
// gaze is sampled coarser than the model allows. E0 is where the spacing
// reaches one pixel: inside it the screen is shown at native pixels. The
// rows are enough that 2 pi r / rows stays within half the MAR across the
// rays everywhere on the screen. No GL here.
#include <array>
#include <vector>

#include "foveate/core/acuity.hpp"
#include "foveate/core/display.hpp"

namespace foveate {

/// The warp for one gaze: screen distance from the gaze <-> buffer column,
/// angle <-> row. Distances are pixels, angles of the model degrees.
struct AcuityWarpMapping {
  Vec2d gaze{};              ///< pixels, in the caller's orientation
  double focal_px = 1.0;     ///< F: the model eccentricity is atan(r / F)
  double slope = 0.0275;     ///< m of the mapping (the planned slope times kappa)
  double w0_deg = 1 / 48.0;  ///< w0 of the mapping (the planned w0 times kappa)
  double kappa = 1.0;        ///< how much finer than planned this gaze is sampled (<= 1)
  double start_deg = 0.0;    ///< E0: column 0 begins here, where the spacing is one pixel
  int rows = 1;              ///< texels around the gaze

  /// E(r), degrees.
  [[nodiscard]] double eccentricity_deg(double r_px) const;
  /// r(E), pixels.
  [[nodiscard]] double radius_px(double e_deg) const;
  /// Where column 0 begins (pixels from the gaze).
  [[nodiscard]] double start_px() const { return radius_px(start_deg); }
  /// u(r): the column at distance r (negative inside start_px()).
  [[nodiscard]] double column(double r_px) const;
  /// r(u), the inverse of column().
  [[nodiscard]] double radius_at_column(double u) const;
  /// dr/du at distance r: the radial spacing of the samples, pixels.
  [[nodiscard]] double radial_spacing_px(double r_px) const;
  /// 2 pi r / rows: the spacing across the rays at distance r, pixels.
  [[nodiscard]] double tangential_spacing_px(double r_px) const;
};

/// The allowed spacing (pixels) between samples at `pixel` along the unit
/// direction `dir` for a gaze at `gaze` (both pixels, origin top-left):
/// half the MAR at the pixel's eccentricity over the exact angle a one-pixel
/// step along `dir` subtends there.
double mar_half_spacing_px(const Display& display, const AcuityModel& acuity, Vec2d pixel,
                           Vec2d dir, Vec2d gaze);

class AcuityWarp {
 public:
  /// `planned`: the acuity the technique plans for (the model made finer by
  /// its planning margin). Throws foveate::Error for a display it cannot map.
  AcuityWarp(const Display& display, const AcuityModel& planned);
  /// The mapping for a gaze (pixels, origin top-left; a gaze off the screen
  /// is moved to its nearest point).
  [[nodiscard]] AcuityWarpMapping mapping(Vec2d gaze) const;
  /// The closed form for a gaze at the principal point (kappa 1, F the eye
  /// distance) with `rows` rows: what mapping() gives there.
  [[nodiscard]] AcuityWarpMapping centred(int rows) const;
  /// The least rows for which 2 pi r / rows stays within half the MAR across
  /// the rays at every screen point for this gaze.
  [[nodiscard]] int rows_for(Vec2d gaze) const;
  [[nodiscard]] const Display& display() const { return display_; }
  [[nodiscard]] const AcuityModel& acuity() const { return acuity_; }

 private:
  Display display_;
  AcuityModel acuity_;
};

/// E0 for a mapping with focal length F and acuity (m, w0): where the radial
/// spacing (m E + w0) / 2 / E'(r) reaches one pixel.
double acuity_warp_start_deg(double focal_px, double slope, double w0_deg);

/// Texels of the buffer (`columns` x m.rows) that a filter reaching `pad`
/// texels may read for points at least `inner` pixels from the gaze and
/// inside `keep` = (x0, y0, x1, y1) (in the mapping's orientation; the gaze
/// inside it), limited to the columns [first, last): per band of `band`
/// rows, the columns outside which no such texel lies (a row covers its
/// whole angular range, and each band reaches as far as its neighbours, so
/// that reads across rows find shaded texels), as (x0, y0, x1, y1) texel
/// rectangles. Empty bands are left out.
std::vector<std::array<int, 4>> acuity_warp_cover(const AcuityWarpMapping& m, int columns,
                                                  double inner, const std::array<double, 4>& keep,
                                                  int pad = 2, int first = 0, int last = 1 << 30,
                                                  int band = 4);

/// Texels in a cover (the sum of its rectangles' areas).
double cover_texels(const std::vector<std::array<int, 4>>& cover);

/// The fewest samples that sample the screen at half the MAR everywhere, no
/// finer than its pixels: the integral over the screen of
/// min(1, 1 / (s_r s_t)), s_r and s_t the allowed spacings (pixels, at least
/// 1) along and across the direction from the gaze (mar_half_spacing_px),
/// summed over blocks of `step` x `step` pixels.
double ideal_mar_samples(const Display& display, const AcuityModel& acuity, Vec2d gaze,
                         int step = 4);

}  // namespace foveate
