#include "foveate/core/display.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "display_units.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/parse.hpp"

namespace foveate {

using display_units::kDeg;
using display_units::kMaxEdgeDeg;
using display_units::kMaxPixels;
using display_units::kRad;
using display_units::tan_deg;

double Photometry::black_cd_m2() const {
  return ambient_lux / std::numbers::pi * reflectivity + peak_cd_m2 / contrast_ratio;
}

void Photometry::validate(const std::string& where) const {
  validate([&](const char* key) { return where + "." + key; });
}

void Photometry::validate(const std::function<std::string(const char* key)>& name) const {
  const auto check = [&](const char* key, double v, double min, double max, bool open_min) {
    if (!std::isfinite(v) || v > max || (open_min ? v <= min : v < min)) {
      throw Error(name(key) + ": must be in " + (open_min ? "(" : "[") + format_number(min) + ", " +
                  format_number(max) + "], got " + format_number(v));
    }
  };
  check("peak_cd_m2", peak_cd_m2, 0.0, 1e5, true);
  check("contrast_ratio", contrast_ratio, 1.0, 1e9, true);
  check("ambient_lux", ambient_lux, 0.0, 1e6, false);
  check("reflectivity", reflectivity, 0.0, 1.0, false);
  if (black_cd_m2() >= peak_cd_m2) {
    throw Error(name("peak_cd_m2") +
                ": must exceed the black level with reflected ambient light (" +
                format_number(black_cd_m2()) + " cd/m^2), got " + format_number(peak_cd_m2));
  }
}

double Display::eye_distance_px() const {
  if (fov.set()) return width_px / (tan_deg(fov.right_deg) - tan_deg(fov.left_deg));
  if (head_mounted()) return 0.5 * width_px / std::tan(0.5 * fov_h_deg * kRad);
  return distance_mm * width_px / width_mm;
}

Vec2d Display::principal_point() const {
  if (!fov.set()) return {0.5 * width_px, 0.5 * height_px};
  const double l = tan_deg(fov.left_deg), r = tan_deg(fov.right_deg);
  const double u = tan_deg(fov.up_deg), d = tan_deg(fov.down_deg);
  // The left edge is -l focal lengths left of the axis; the top edge u above it.
  return {width_px * -l / (r - l), height_px * u / (u - d)};
}

double Display::horizontal_fov_deg() const {
  if (fov.set()) return fov.right_deg - fov.left_deg;
  return head_mounted() ? fov_h_deg : 0.0;
}

Display Display::mirrored() const {
  Display d = *this;
  d.fov = fov.mirrored();
  if (lens) d.lens = lens->mirrored();
  return d;
}

double Display::max_view_tan() const {
  const auto [cx, cy] = principal_point();
  const double dx = std::max(cx, width_px - cx), dy = std::max(cy, height_px - cy);
  return std::hypot(dx, dy) / eye_distance_px();
}

std::optional<OversamplingTable> Display::lens_oversampling_table() const {
  if (!lens) return std::nullopt;
  return OversamplingTable(*lens, eye_distance_px(), std::atan(max_view_tan()) * kDeg);
}

namespace {
// The view tangent of buffer `pixel` from the principal point.
double view_tan(const Display& d, Vec2d pixel) {
  const auto [cx, cy] = d.principal_point();
  return std::hypot(pixel.x - cx, pixel.y - cy) / d.eye_distance_px();
}
}  // namespace

PanelDensity Display::panel_pixels_per_degree(Vec2d pixel) const {
  if (!lens) throw Error("display '" + name + "': has no lens (panel_pixels_per_degree)");
  return lens->density_at_tan(view_tan(*this, pixel));
}

Oversampling Display::lens_oversampling(Vec2d pixel) const {
  if (!lens) return {};
  return lens->oversampling_at_tan(view_tan(*this, pixel), eye_distance_px());
}

double Display::displayed_pixel_angle_deg(Vec2d pixel) const {
  // The buffer's pixel angles at view tangent t: cos^2 / f radially, cos / f
  // tangentially (radians).
  const double t = view_tan(*this, pixel), f = eye_distance_px();
  const double c2 = 1.0 / (1.0 + t * t);
  double radial = c2 / f * kDeg, tangential = std::sqrt(c2) / f * kDeg;
  if (lens) {
    const PanelDensity p = lens->density_at_tan(t);
    radial = std::max(radial, 1.0 / p.radial);
    tangential = std::max(tangential, 1.0 / p.tangential);
  }
  return std::min(radial, tangential);
}

double Display::pixels_per_mm() const { return head_mounted() ? 0.0 : width_px / width_mm; }

int Display::long_axis_px() const { return std::max(width_px, height_px); }

double Display::aspect() const {
  return static_cast<double>(std::min(width_px, height_px)) / long_axis_px();
}

double Display::half_fov_deg() const {
  return std::atan(0.5 * long_axis_px() / eye_distance_px()) * kDeg;
}

double Display::sharpness_deg() const { return std::atan(2.0 / eye_distance_px()) * kDeg; }

double Display::eccentricity_deg(Vec2d pixel, Vec2d gaze) const {
  const double f = eye_distance_px();
  const auto [cx, cy] = principal_point();
  const double ax = pixel.x - cx, ay = pixel.y - cy, az = f;
  const double bx = gaze.x - cx, by = gaze.y - cy, bz = f;
  const double crx = ay * bz - az * by, cry = az * bx - ax * bz, crz = ax * by - ay * bx;
  const double cross = std::sqrt(crx * crx + cry * cry + crz * crz);
  const double dot = ax * bx + ay * by + az * bz;
  return std::atan2(cross, dot) * kDeg;
}

double Display::pixels_per_degree(Vec2d pixel, Vec2d gaze) const {
  double dx = pixel.x - gaze.x, dy = pixel.y - gaze.y;
  const double len = std::hypot(dx, dy);
  const double h = 0.5;
  if (len < h) {
    // At (or next to) the gaze point the angle grows like |t|: step away from the gaze.
    const Vec2d out{gaze.x + h, gaze.y};
    return h / eccentricity_deg(out, gaze);
  }
  dx /= len;
  dy /= len;
  const double e1 = eccentricity_deg({pixel.x + dx * h, pixel.y + dy * h}, gaze);
  const double e0 = eccentricity_deg({pixel.x - dx * h, pixel.y - dy * h}, gaze);
  return 2.0 * h / (e1 - e0);
}

double Display::radius_px_at(double eccentricity) const {
  return eye_distance_px() * std::tan(std::min(eccentricity, 89.9) * kRad);
}

Display Display::resized(int width, int height) const {
  Display d = *this;
  d.width_px = width;
  d.height_px = height;
  d.validate();
  return d;
}

void Display::validate() const {
  const std::string w = name.empty() ? "display" : "display '" + name + "'";
  validate_geometry();
  photometry.validate(w + ": photometry");
  if (!lens) return;
  if (!head_mounted()) {
    throw Error(w + ": lens needs a head-mounted display (fov_deg or fov_h_deg)");
  }
  lens->validate(w, max_view_tan());
}

void Display::validate_geometry() const {
  const std::string w = name.empty() ? "display" : "display '" + name + "'";
  if (width_px < 1 || width_px > kMaxPixels) {
    throw Error(w + ": width_px must be in [1, 65536], got " + std::to_string(width_px));
  }
  if (height_px < 1 || height_px > kMaxPixels) {
    throw Error(w + ": height_px must be in [1, 65536], got " + std::to_string(height_px));
  }
  if (!std::isfinite(ipd_mm) || ipd_mm < 0.0 || ipd_mm > 200.0) {
    throw Error(w + ": ipd_mm must be in (0, 200] (or 0 for a display without stereo), got " +
                format_number(ipd_mm));
  }
  if (fov.set()) {
    const std::pair<const char*, double> edges[] = {{"left", fov.left_deg},
                                                    {"right", fov.right_deg},
                                                    {"up", fov.up_deg},
                                                    {"down", fov.down_deg}};
    for (const auto& [key, a] : edges) {
      if (!std::isfinite(a) || std::abs(a) >= kMaxEdgeDeg) {
        throw Error(w + ": fov_deg." + key + " must be in (-85, 85) degrees, got " +
                    format_number(a));
      }
    }
    if (!(fov.right_deg > fov.left_deg)) {
      throw Error(w + ": fov_deg.right (" + format_number(fov.right_deg) +
                  ") must be greater than fov_deg.left (" + format_number(fov.left_deg) + ")");
    }
    if (!(fov.up_deg > fov.down_deg)) {
      throw Error(w + ": fov_deg.up (" + format_number(fov.up_deg) +
                  ") must be greater than fov_deg.down (" + format_number(fov.down_deg) + ")");
    }
    if (fov_h_deg != 0.0) throw Error(w + ": give either fov_h_deg or fov_deg, not both");
    return;
  }
  if (ipd_mm > 0.0) {
    throw Error(w + ": ipd_mm needs the per-eye angles fov_deg (a stereo head-mounted display)");
  }
  if (head_mounted()) {
    if (!std::isfinite(fov_h_deg) || fov_h_deg >= 179.0) {
      throw Error(w + ": fov_h_deg must be in (0, 179), got " + format_number(fov_h_deg));
    }
    return;
  }
  if (!std::isfinite(fov_h_deg) || fov_h_deg < 0.0) {
    throw Error(w + ": fov_h_deg must be in (0, 179) or 0 for a flat display, got " +
                format_number(fov_h_deg));
  }
  if (!std::isfinite(width_mm) || width_mm <= 0.0) {
    throw Error(w + ": width_mm must be > 0, got " + std::to_string(width_mm));
  }
  if (!std::isfinite(distance_mm) || distance_mm <= 0.0) {
    throw Error(w + ": distance_mm must be > 0, got " + format_number(distance_mm));
  }
}

}  // namespace foveate
