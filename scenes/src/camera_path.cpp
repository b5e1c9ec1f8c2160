#include "foveate/scenes/camera_path.hpp"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>
#include <numbers>

#include "foveate/core/error.hpp"
#include "foveate/core/json_read.hpp"

namespace foveate {

namespace {
constexpr double kMaxCoordinate = 1e12;

glm::dvec3 catmull_rom(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2,
                       const glm::dvec3& p3, double u) {
  const double u2 = u * u, u3 = u2 * u;
  return 0.5 * ((2.0 * p1) + (-p0 + p2) * u + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * u2 +
                (-p0 + 3.0 * p1 - 3.0 * p2 + p3) * u3);
}

glm::dvec3 read_vec3(JsonReader& r, const char* key, glm::dvec3 fallback) {
  const nlohmann::json* v = r.get(key);
  if (!v) return fallback;
  if (!v->is_array() || v->size() != 3) throw Error(r.path(key) + ": expected [x, y, z]");
  glm::dvec3 out;
  for (int i = 0; i < 3; ++i) {
    if (!(*v)[i].is_number()) throw Error(r.path(key) + ": expected numbers");
    out[i] = (*v)[i].get<double>();
    // Bounded so that the spline through the keyframes stays finite.
    if (!std::isfinite(out[i]) || std::fabs(out[i]) > kMaxCoordinate) {
      throw Error(r.path(key) + ": coordinates must be finite and within +-1e12, got " +
                  (*v)[i].dump());
    }
  }
  return out;
}
}  // namespace

CameraPose CameraPath::at(double time_s) const {
  double t = time_s;
  if (keys.empty()) return {{0, 0, 5}, {0, 0, 0}, 50.0};
  if (keys.size() == 1) return {keys[0].position, keys[0].target, keys[0].fov_deg};
  const double T = duration_s();
  if (loop && T > 0) {
    t = std::fmod(t, T);
    if (t < 0) t += T;
  }
  t = std::clamp(t, keys.front().time_s, keys.back().time_s);
  size_t i = 0;
  while (i + 2 < keys.size() && keys[i + 1].time_s <= t) ++i;
  const CameraKey& a = keys[i];
  const CameraKey& b = keys[i + 1];
  const double span = b.time_s - a.time_s;
  const double u = span > 0 ? (t - a.time_s) / span : 0.0;
  const CameraKey& p = i > 0 ? keys[i - 1] : (loop ? keys[keys.size() - 2] : a);
  const CameraKey& q = i + 2 < keys.size() ? keys[i + 2] : (loop ? keys[1] : b);
  return {catmull_rom(p.position, a.position, b.position, q.position, u),
          catmull_rom(p.target, a.target, b.target, q.target, u),
          a.fov_deg + (b.fov_deg - a.fov_deg) * u};
}

CameraPath CameraPath::from_json(const nlohmann::json& j, const std::string& where) {
  JsonReader r(j, where);
  CameraPath path;
  r.boolean("loop", path.loop);
  const nlohmann::json* keys = r.get("keyframes");
  r.finish();
  if (!keys || !keys->is_array() || keys->empty()) {
    throw Error(where + ".keyframes: expected a non-empty array of keyframes");
  }
  for (size_t i = 0; i < keys->size(); ++i) {
    const std::string w = where + ".keyframes[" + std::to_string(i) + "]";
    JsonReader k((*keys)[i], w);
    CameraKey key;
    if (!k.number("t", key.time_s, 0.0, 1e6)) throw Error(w + ".t: required");
    key.position = read_vec3(k, "position", key.position);
    key.target = read_vec3(k, "target", key.target);
    k.number("fov_deg", key.fov_deg, 1.0, 170.0);
    k.finish();
    if (glm::length(key.position - key.target) < 1e-9) throw Error(w + ": position equals target");
    if (!path.keys.empty() && key.time_s <= path.keys.back().time_s) {
      throw Error(w + ".t: keyframe times must increase");
    }
    path.keys.push_back(key);
  }
  return path;
}

CameraPath CameraPath::load(const std::string& file) {
  return from_json(read_json_file(file, "camera path"), file);
}

CameraPath CameraPath::orbit(glm::dvec3 c, double radius, double height, double period_s,
                             double fov) {
  CameraPath p;
  p.loop = true;
  const int n = 8;
  for (int i = 0; i <= n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    p.keys.push_back({period_s * i / n,
                      c + glm::dvec3(radius * std::sin(a), height, radius * std::cos(a)), c, fov});
  }
  return p;
}

glm::dvec3 camera_up(const glm::dvec3& forward) {
  const glm::dvec3 f = glm::normalize(forward);
  // World up is +y; looking (almost) straight down or up it is parallel to
  // the view, so the screen's top points along -z (down) or +z (up): the
  // camera of the default view (looking along -z) tilted down or up.
  if (glm::length(glm::cross(f, glm::dvec3(0, 1, 0))) < 1e-6) {
    return glm::dvec3(0, 0, f.y < 0 ? -1 : 1);
  }
  return glm::dvec3(0, 1, 0);
}

glm::dmat4 view_matrix(const CameraPose& pose) {
  return glm::lookAt(pose.position, pose.target, camera_up(pose.target - pose.position));
}

glm::dmat4 projection_for_rect(const CameraPose& pose, int width, int height, double x0, double y0,
                               double x1, double y1, double n, double f) {
  // The full frame spans [-top*aspect, top*aspect] x [-top, top] at the near plane.
  const double top = n * std::tan(0.5 * pose.fov_deg * std::numbers::pi / 180.0);
  const double right = top * width / height;
  auto sx = [&](double x) { return -right + 2.0 * right * x / width; };
  auto sy = [&](double y) { return -top + 2.0 * top * y / height; };
  return glm::frustum(sx(x0), sx(x1), sy(y0), sy(y1), n, f);
}

}  // namespace foveate
