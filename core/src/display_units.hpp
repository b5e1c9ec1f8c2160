#pragma once
// What the display's files share: degree conversions and the limits a
// display's numbers are checked against.
#include <cmath>
#include <numbers>

namespace foveate::display_units {

inline constexpr double kDeg = 180.0 / std::numbers::pi;
inline constexpr double kRad = std::numbers::pi / 180.0;
inline constexpr int kMaxPixels = 65536;
inline constexpr double kMaxEdgeDeg = 85.0;  ///< an edge angle's bound (tan stays finite and sane)
inline double tan_deg(double a) { return std::tan(a * kRad); }
/// An edge angle in degrees from a raw projection value (the tangent, as
/// OpenVR's GetProjectionRaw and hmdq report it).
inline double edge_deg(double tangent) { return std::atan(tangent) * kDeg; }

}  // namespace foveate::display_units
