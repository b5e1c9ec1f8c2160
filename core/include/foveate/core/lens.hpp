#pragma once
// The lens of a head-mounted display: how much detail its panel can show at
// each view angle.
//
// An HMD application renders a rectilinear (pinhole) eye buffer; the runtime's
// compositor pre-distorts it onto the panel, and the lens maps each panel
// position back to the view angle the buffer had there. So a buffer pixel is
// seen at its pinhole angle (eccentricities stay the pinhole's, Display's), and
// what the lens changes is the panel's resolution at that angle: the panel's
// pixels per degree fall away from the lens axis (a pincushion lens), while
// the rectilinear buffer's rise (1/cos^2 radially, 1/cos tangentially). Where
// the buffer has more pixels per degree than the panel, sampling it finer than
// the panel's pixels is waste.
//
// The model is the Oculus SDK 0.2's radial distortion (Oculus SDK Overview
// 0.2.3, "Distortion correction"; OVR::Util::Render::DistortionConfig): a
// panel point r pixels from the lens centre is seen in the direction whose
// tangent from the lens axis is
//     tan(theta) = (r / px_per_tan) * (1 + k1 rho^2 + k2 rho^4 + k3 rho^6),
//     rho = r / radius_unit_px,
// the SDK's DistortionK = {1, k1, k2, k3} with its radius unit (a quarter of
// the DK1's panel width) in panel pixels and px_per_tan = the panel's pixels per
// unit tangent at the lens centre (the SDK's unit over its EyeToScreenDistance;
// LibOVR's later PixelsPerTanAngleAtCenter). The lens axis is the eye buffer's
// optical axis (the display's principal point).
#include <array>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

namespace foveate {

/// Buffer pixels per panel pixel, along the direction away from the lens axis
/// (radial) and across it (tangential); > 1 where the buffer is finer than
/// the panel shows.
struct Oversampling {
  double radial = 1.0;
  double tangential = 1.0;
  [[nodiscard]] double least() const { return radial < tangential ? radial : tangential; }
};

/// Panel pixels per degree of view angle, radially and tangentially.
struct PanelDensity {
  double radial = 0.0;
  double tangential = 0.0;
};

struct Lens {
  int panel_width_px = 0;  ///< one eye's panel (or its part behind this lens)
  int panel_height_px = 0;
  double center_x_px = 0.0;  ///< where the lens axis meets the panel (panel pixels, top-left)
  double center_y_px = 0.0;
  double px_per_tan = 0.0;      ///< panel pixels per unit tangent at the lens centre
  double radius_unit_px = 0.0;  ///< the polynomial's radius unit in panel pixels
  std::array<double, 3> k{};    ///< k1, k2, k3 (the SDK's K1..K3; its K0 is 1)

  /// tan(theta) of the panel point `r_px` from the lens centre.
  [[nodiscard]] double tan_at_radius(double r_px) const;
  /// d tan(theta) / d r (per panel pixel).
  [[nodiscard]] double dtan_dr(double r_px) const;
  /// The panel radius seen at view tangent `t` >= 0 (the inverse of
  /// tan_at_radius; valid for a validated lens out to the view's corners).
  [[nodiscard]] double radius_at_tan(double t) const;
  /// Panel pixels per degree at view tangent `t` from the axis.
  [[nodiscard]] PanelDensity density_at_tan(double t) const;
  /// Buffer pixels per panel pixel at view tangent `t`, for a rectilinear
  /// buffer with `buffer_px_per_tan` pixels per unit tangent (its focal length
  /// in pixels): radially f * dtan/dr, tangentially f * tan / r.
  [[nodiscard]] Oversampling oversampling_at_tan(double t, double buffer_px_per_tan) const;
  /// The other eye's lens (the centre mirrored across the panel).
  [[nodiscard]] Lens mirrored() const;
  /// Throws foveate::Error naming `where`.field when a value is out of range
  /// or the mapping stops growing before the panel's farthest corner or the
  /// view tangent `max_tan` (the eye buffer's farthest corner).
  void validate(const std::string& where, double max_tan) const;

  /// {"panel_px": [w, h], "center_px": [x, y], "px_per_tan": ..,
  ///  "radius_unit_px": .. (default px_per_tan), "k": [k1, k2, k3] (1 to 3)}.
  static Lens from_json(const nlohmann::json& j, const std::string& where);
};

void to_json(nlohmann::json& j, const Lens& lens);

/// The least oversampling at any view angle at or beyond a given one, from a
/// table over [0, max_angle_deg] sampled every step_deg (each entry holds the
/// least of the samples from its own angle up, and a query rounds its angle
/// down to an entry, so it errs on the finer side but for what the
/// oversampling does between two samples 0.05 deg apart).
class OversamplingTable {
 public:
  OversamplingTable(const Lens& lens, double buffer_px_per_tan, double max_angle_deg,
                    double step_deg = 0.05);
  /// The least radial and the least tangential oversampling over view angles
  /// >= angle_deg (each minimised on its own).
  [[nodiscard]] Oversampling least_beyond(double angle_deg) const;

 private:
  double step_deg_;
  std::vector<Oversampling> suffix_;
};

}  // namespace foveate
