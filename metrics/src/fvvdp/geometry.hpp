#pragma once
// Where FovVideoVDP's samples lie and what the eye sees there: for every level
// of the pyramid, the angle of each column and row from the display's
// principal point, the eccentricity of each sample from the gaze, and the
// local pixels per degree relative to the centre's.
#include <cstdint>
#include <vector>

#include "foveate/core/display.hpp"
#include "fvvdp/csf.hpp"

namespace foveate::metrics::fvvdp {

/// One pyramid level's samples: level sample (i, j) of a w x h level stands
/// for the image point (0.5 + i (W - 1) / (w - 1), 0.5 + j (H - 1) / (h - 1))
/// of the W x H frame (the reference's convention).
struct LevelGeometry {
  int width = 0;
  int height = 0;
  std::vector<double> column_px;   ///< image x of each column
  std::vector<double> row_px;      ///< image y of each row
  std::vector<double> column_deg;  ///< horizontal angle of each column from the principal point
  std::vector<double> row_deg;     ///< vertical angle of each row
  /// Local pixels per degree over the centre's, at every sample (row-major).
  std::vector<float> magnification;
};

/// The display as the metric sees it.
class ViewGeometry {
 public:
  ViewGeometry(const Display& display, int levels);
  [[nodiscard]] double pixels_per_degree() const { return ppd_; }
  [[nodiscard]] const LevelGeometry& level(int l) const { return levels_[static_cast<size_t>(l)]; }
  /// Angles of a gaze point (pixels, centres at +0.5) from the principal point.
  [[nodiscard]] std::pair<double, double> gaze_deg(Vec2d gaze_px) const;
  /// Eccentricity in degrees of every sample of level `l` from the gaze: the
  /// distance of the horizontal and vertical angles (the reference's measure).
  void eccentricity(int l, Vec2d gaze_px, std::vector<float>& out) const;
  /// The eccentricity band of every sample of level `l` by the exact angle
  /// between the rays to the sample and to the gaze (Display::eccentricity_deg,
  /// as the other metrics band pixels): the index of the last edge not above
  /// it, -1 below the first. Adds each band's sample count to `counts`.
  void bands(int l, Vec2d gaze_px, const std::vector<double>& edges_deg,
             std::vector<std::int8_t>& out, std::vector<double>& counts) const;

 private:
  Display display_;
  double eye_distance_px_ = 1;
  Vec2d principal_{};
  double ppd_ = 1;
  std::vector<LevelGeometry> levels_;
};

}  // namespace foveate::metrics::fvvdp
