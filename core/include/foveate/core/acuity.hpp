#pragma once
// The linear acuity model of Guenter et al., "Foveated 3D Graphics" (2012),
// eq. 1: the minimum angle of resolution grows linearly with eccentricity,
//   w(e) = m * e + w0   (degrees per cycle; e in degrees).
#include <string>

namespace foveate {

/// MAR slopes of the acuity presets A and B, from the user study of Guenter
/// et al. (section 5).
inline constexpr double kSlopePresetA = 0.0275;  ///< 1.65 arc minutes per degree
inline constexpr double kSlopePresetB = 0.0220;  ///< 1.32 arc minutes per degree
/// Average foveal acuity of adults: 48 cycles per degree.
inline constexpr double kFovealMarDeg = 1.0 / 48.0;

struct AcuityModel {
  double slope = kSlopePresetA;   ///< m
  double w0_deg = kFovealMarDeg;  ///< w0, MAR at the fovea

  /// MAR in degrees per cycle at eccentricity e (degrees).
  [[nodiscard]] double mar_deg(double eccentricity_deg) const;
  /// Inverse of mar_deg: the eccentricity at which the MAR reaches w (0 when w <= w0).
  [[nodiscard]] double eccentricity_for_mar(double mar_deg) const;

  /// Acuity preset by name: "A" or "B" (case-insensitive), the slopes of
  /// Guenter et al.'s user study. Throws foveate::Error otherwise.
  static AcuityModel preset(const std::string& name);
  /// A model with a custom slope; throws foveate::Error unless 0 < m <= 1.
  static AcuityModel with_slope(double m);
  /// The model `margin` times finer (slope and w0 divided by it): what a
  /// technique plans for to keep a margin over the acuity it is judged by.
  /// Throws foveate::Error unless 1 <= margin <= 4.
  [[nodiscard]] AcuityModel finer(double margin) const;
};

}  // namespace foveate
