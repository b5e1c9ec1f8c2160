#pragma once
// Display geometry: a flat image plane viewed from a point on its central
// normal. A desktop monitor is described by its resolution, physical width and
// viewing distance (Guenter et al. eq. 6 and 7); a head-mounted display by its
// per-eye resolution and horizontal field of view. Both reduce to one number,
// the distance from the eye to the image plane in pixels (eye_distance_px), from which
// every angle follows exactly (no small-angle approximation).
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

namespace foveate {

struct Vec2d {
  double x = 0.0;
  double y = 0.0;
};

struct Display {
  std::string name = "desktop-1080p";
  int width_px = 1920;
  int height_px = 1080;
  // Flat panel: physical width of the active area and viewing distance.
  double width_mm = 510.0;
  double distance_mm = 590.0;
  // Head-mounted: horizontal field of view per eye; when > 0 it defines the
  // geometry and width_mm / distance_mm are ignored.
  double fov_h_deg = 0.0;

  [[nodiscard]] bool head_mounted() const { return fov_h_deg > 0.0; }
  /// Eye-to-image-plane distance measured in pixels (V* D* / W*).
  [[nodiscard]] double eye_distance_px() const;
  /// Pixel density in pixels per millimetre (flat panels only; 0 for HMDs).
  [[nodiscard]] double pixels_per_mm() const;
  /// Longer axis in pixels (D* of the paper) and aspect (shorter / longer, alpha*).
  [[nodiscard]] int long_axis_px() const;
  [[nodiscard]] double aspect() const;
  /// e*: half the field of view along the longer axis (eq. 6), degrees.
  [[nodiscard]] double half_fov_deg() const;
  /// w*: sharpness angle, one cycle (two pixels) at the display centre (eq. 7), degrees.
  [[nodiscard]] double sharpness_deg() const;

  /// Exact angle in degrees between the rays to `pixel` and to `gaze` (pixel units,
  /// origin top-left, pixel centres at +0.5).
  [[nodiscard]] double eccentricity_deg(Vec2d pixel, Vec2d gaze) const;
  /// Pixels per degree at `pixel`, measured along the direction away from the gaze.
  [[nodiscard]] double pixels_per_degree(Vec2d pixel, Vec2d gaze) const;
  /// Screen distance in pixels from the gaze point that subtends `eccentricity_deg`
  /// (along the ray from the gaze through the display centre's side, exact for a
  /// gaze at the centre).
  [[nodiscard]] double radius_px_at(double eccentricity_deg) const;

  /// The same physical display rendered at another resolution (same field of
  /// view): used to run at small test sizes with the real angular geometry.
  [[nodiscard]] Display resized(int width, int height) const;

  /// Throws foveate::Error naming the field when a value is out of range.
  void validate() const;

  /// Built-in displays: desktop-1080p (the paper's), desktop-27-4k, hmd-quest3.
  static const std::vector<Display>& presets();
  /// A preset name or a path to a JSON file.
  static Display load(const std::string& name_or_path);
  static Display from_json(const nlohmann::json& j, const std::string& where = "display");
};

void to_json(nlohmann::json& j, const Display& d);

}  // namespace foveate
