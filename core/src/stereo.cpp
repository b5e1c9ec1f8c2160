#include "foveate/core/stereo.hpp"

#include <cmath>
#include <numbers>

#include "foveate/core/error.hpp"
#include "foveate/core/parse.hpp"

namespace foveate {

StereoDisplay StereoDisplay::from(const Display& left_eye) {
  const std::string w = "display '" + left_eye.name + "'";
  if (!left_eye.fov.set()) {
    throw Error(w +
                ": not a stereo head-mounted display (it has no per-eye angles fov_deg; stereo "
                "presets: " +
                Display::preset_names(true) + ")");
  }
  if (!(left_eye.ipd_mm > 0.0)) {
    throw Error(w + ": a stereo display needs an inter-pupillary distance ipd_mm > 0, got " +
                format_number(left_eye.ipd_mm));
  }
  left_eye.validate();
  return StereoDisplay{left_eye, left_eye.mirrored(), left_eye.ipd_mm};
}

Display StereoDisplay::cyclopean() const {
  Display d;
  d.name = left.name + " (cyclopean)";
  d.width_px = left.width_px;
  d.height_px = left.height_px;
  d.fov_h_deg =
      2.0 * std::atan(0.5 * left.width_px / left.eye_distance_px()) * 180.0 / std::numbers::pi;
  return d;
}

FrustumTangents frustum_tangents(const Display& eye) {
  const double f = eye.eye_distance_px();
  const Vec2d p = eye.principal_point();
  return {-p.x / f, (eye.width_px - p.x) / f, -(eye.height_px - p.y) / f, p.y / f};
}

StereoGaze stereo_gaze(const StereoDisplay& s, Vec2d c, double vergence_m) {
  if (!(vergence_m > 0.0) || std::isnan(vergence_m)) {
    throw Error("vergence distance: must be > 0 metres (or inf for a parallel gaze), got " +
                format_number(vergence_m));
  }
  // Directions as image-plane tangents (x right, y down, z forward).
  const double f = s.left.eye_distance_px();
  const double dx = (c.x - 0.5 * s.left.width_px) / f, dy = (c.y - 0.5 * s.left.height_px) / f;
  StereoGaze g;
  for (Eye e : kEyes) {
    const Display& d = s.eye(e);
    const Vec2d p = d.principal_point();
    double tx = dx, ty = dy;
    if (std::isfinite(vergence_m)) {
      // The fixated point, vergence_m from the cyclopean eye along the gaze,
      // seen from this eye (offset along x).
      const double n = std::sqrt(dx * dx + dy * dy + 1.0);
      const double px = vergence_m * dx / n, py = vergence_m * dy / n, pz = vergence_m / n;
      tx = (px - s.eye_offset_m(e)) / pz;
      ty = py / pz;
    }
    g.px[static_cast<size_t>(e)] = {p.x + f * tx, p.y + f * ty};
  }
  return g;
}

}  // namespace foveate
