#pragma once
// Camera fly-through paths: keyframes on a fixed clock, interpolated with a
// Catmull-Rom spline (positions and targets), looping when `loop` is set.
// JSON form:
//   {"loop": true, "keyframes": [{"t": 0, "position": [x,y,z], "target": [x,y,z],
//                                 "fov_deg": 50}, ...]}
#include <glm/glm.hpp>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

namespace foveate {

struct CameraKey {
  double time_s = 0.0;  ///< the path's time of this key ("t" in the JSON)
  glm::dvec3 position{0.0, 0.0, 5.0};
  glm::dvec3 target{0.0, 0.0, 0.0};
  double fov_deg = 50.0;  ///< vertical field of view of the rendered image
};

struct CameraPose {
  glm::dvec3 position;
  glm::dvec3 target;
  double fov_deg;
};

struct CameraPath {
  std::vector<CameraKey> keys;
  bool loop = true;

  [[nodiscard]] CameraPose at(double time_s) const;
  [[nodiscard]] double duration_s() const { return keys.empty() ? 0.0 : keys.back().time_s; }
  /// Throws foveate::Error naming the field (`where`.keyframes[i].t ...).
  static CameraPath from_json(const nlohmann::json& j, const std::string& where);
  static CameraPath load(const std::string& path);
  /// An orbit around `centre` at `radius`, `height` above it, one turn per `period_s`.
  static CameraPath orbit(glm::dvec3 centre, double radius, double height, double period_s,
                          double fov_deg = 50.0);
};

/// Column-major view and projection matrices for a pose. The projection is the
/// off-centre sub-frustum of the screen rectangle [x0,x1]x[y0,y1] of a full
/// frame width x height (pixels, origin bottom-left).
glm::dmat4 view_matrix(const CameraPose& pose);
/// The up vector the view uses for a viewing direction: +y, or -z / +z when
/// looking straight down / up (where +y would be parallel to the view).
glm::dvec3 camera_up(const glm::dvec3& forward);
glm::dmat4 projection_for_rect(const CameraPose& pose, int width, int height, double x0, double y0,
                               double x1, double y1, double z_near, double z_far);

}  // namespace foveate
