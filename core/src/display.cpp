#include "foveate/core/display.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numbers>

#include "foveate/core/error.hpp"
#include "foveate/core/json_read.hpp"
#include "foveate/core/parse.hpp"

namespace foveate {

namespace {
constexpr double kDeg = 180.0 / std::numbers::pi;
constexpr double kRad = std::numbers::pi / 180.0;
constexpr int kMaxPixels = 65536;
}  // namespace

double Display::eye_distance_px() const {
  if (head_mounted()) return 0.5 * width_px / std::tan(0.5 * fov_h_deg * kRad);
  return distance_mm * width_px / width_mm;
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
  const double cx = 0.5 * width_px, cy = 0.5 * height_px;
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
  if (width_px < 1 || width_px > kMaxPixels) {
    throw Error(w + ": width_px must be in [1, 65536], got " + std::to_string(width_px));
  }
  if (height_px < 1 || height_px > kMaxPixels) {
    throw Error(w + ": height_px must be in [1, 65536], got " + std::to_string(height_px));
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

const std::vector<Display>& Display::presets() {
  static const std::vector<Display> all = [] {
    std::vector<Display> v;
    // Guenter et al. section 5: LG W2363D, 1920x1080, W* = 51 cm, V* = 59 cm.
    v.push_back(Display{"desktop-1080p", 1920, 1080, 510.0, 590.0, 0.0});
    // A 27-inch 16:9 UHD monitor (597.7 mm wide) viewed from 60 cm.
    v.push_back(Display{"desktop-27-4k", 3840, 2160, 27.0 * 25.4 * 16.0 / std::hypot(16.0, 9.0),
                        600.0, 0.0});
    // Meta Quest 3, one eye: 2064x2208 panel, about 104 degrees horizontally
    // (modelled as a pinhole; real lenses distort).
    v.push_back(Display{"hmd-quest3", 2064, 2208, 0.0, 0.0, 104.0});
    return v;
  }();
  return all;
}

Display Display::from_json(const nlohmann::json& j, const std::string& where) {
  JsonReader r(j, where);
  Display d;
  d.name.clear();
  r.string("name", d.name);
  r.integer("width_px", d.width_px, 1, kMaxPixels);
  r.integer("height_px", d.height_px, 1, kMaxPixels);
  const bool has_fov = r.number("fov_h_deg", d.fov_h_deg, 1e-6, 178.999);
  const bool has_w = r.number("width_mm", d.width_mm, 1e-6, 1e7);
  const bool has_v = r.number("distance_mm", d.distance_mm, 1e-6, 1e7);
  r.finish();
  if (!j.contains("width_px")) throw Error(r.path("width_px") + ": required");
  if (!j.contains("height_px")) throw Error(r.path("height_px") + ": required");
  if (has_fov && (has_w || has_v)) {
    throw Error(
        where +
        ": give either fov_h_deg (head-mounted) or width_mm and distance_mm (flat), not both");
  }
  if (!has_fov) {
    if (!has_w) throw Error(r.path("width_mm") + ": required for a flat display");
    if (!has_v) throw Error(r.path("distance_mm") + ": required for a flat display");
  }
  d.validate();
  return d;
}

Display Display::load(const std::string& name_or_path) {
  for (const Display& d : presets()) {
    if (d.name == name_or_path) return d;
  }
  std::error_code ec;
  if (!std::filesystem::exists(name_or_path, ec)) {
    std::string names;
    for (const Display& d : presets()) names += (names.empty() ? "" : ", ") + d.name;
    throw Error("display '" + name_or_path + "': not a preset (" + names +
                ") nor an existing file");
  }
  Display d = from_json(read_json_file(name_or_path, "display JSON"), name_or_path);
  if (d.name.empty()) d.name = std::filesystem::path(name_or_path).stem().string();
  return d;
}

void to_json(nlohmann::json& j, const Display& d) {
  j = nlohmann::json{{"name", d.name}, {"width_px", d.width_px}, {"height_px", d.height_px}};
  if (d.head_mounted()) {
    j["fov_h_deg"] = d.fov_h_deg;
  } else {
    j["width_mm"] = d.width_mm;
    j["distance_mm"] = d.distance_mm;
  }
}

}  // namespace foveate
