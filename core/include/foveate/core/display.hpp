#pragma once
// Display geometry: a flat image plane viewed from a point on its central
// normal. A desktop monitor is described by its resolution, physical width and
// viewing distance (Guenter et al. eq. 6 and 7); a head-mounted display by its
// per-eye resolution and horizontal field of view. Both reduce to one number,
// the distance from the eye to the image plane in pixels (eye_distance_px), from which
// every angle follows exactly (no small-angle approximation). A head-mounted
// eye may instead be described by its four edge angles (asymmetric field of
// view, as OpenXR's XrFovf): then the eye's optical axis meets the image at the
// principal point, not at the centre, and every angle is taken from there.
#include <functional>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "foveate/core/lens.hpp"

namespace foveate {

struct Vec2d {
  double x = 0.0;
  double y = 0.0;
};

/// One eye's field of view as OpenXR's XrFovf gives it, in degrees: the angles
/// of the left, right, top and bottom image edges from the eye's optical axis
/// (left and down negative for an axis inside the image).
struct FovAngles {
  double left_deg = 0.0;
  double right_deg = 0.0;
  double up_deg = 0.0;
  double down_deg = 0.0;
  [[nodiscard]] bool set() const {
    return left_deg != 0.0 || right_deg != 0.0 || up_deg != 0.0 || down_deg != 0.0;
  }
  /// The other eye's field (left and right swapped and negated).
  [[nodiscard]] FovAngles mirrored() const { return {-right_deg, -left_deg, up_deg, down_deg}; }
};

/// How the display turns an 8-bit value into light: the gain-offset-gamma
/// model with the sRGB transfer function that FovVideoVDP (Mantiuk et al.
/// 2021) uses, L = (peak - black) srgb_to_linear(V) + black, where the black
/// level is the panel's own (peak / contrast) plus the ambient light it
/// reflects (ambient / pi * reflectivity), all in cd/m^2.
struct Photometry {
  double peak_cd_m2 = 200.0;     ///< luminance of white
  double contrast_ratio = 1000;  ///< the panel's peak / black, without ambient light
  double ambient_lux = 250.0;    ///< illuminance falling on the screen
  double reflectivity = 0.005;   ///< share of the ambient light the screen reflects
  [[nodiscard]] double black_cd_m2() const;
  /// Luminance for a linear (already decoded) value in [0, 1].
  [[nodiscard]] double luminance_cd_m2(double linear) const {
    return (peak_cd_m2 - black_cd_m2()) * linear + black_cd_m2();
  }
  /// Throws foveate::Error naming the field ("where.peak_cd_m2: ...").
  void validate(const std::string& where) const;
  /// The same with the names `name(key)` gives the fields (a command line's flags).
  void validate(const std::function<std::string(const char* key)>& name) const;
};

/// Photometry given field by field over a display's own (a command line's
/// flags, a library's options): each value set replaces the display's.
struct PhotometryOverrides {
  std::optional<double> peak_cd_m2;
  std::optional<double> contrast_ratio;
  std::optional<double> ambient_lux;
  std::optional<double> reflectivity;
  [[nodiscard]] bool any() const {
    return peak_cd_m2 || contrast_ratio || ambient_lux || reflectivity;
  }
  void apply_to(Photometry& p) const {
    if (peak_cd_m2) p.peak_cd_m2 = *peak_cd_m2;
    if (contrast_ratio) p.contrast_ratio = *contrast_ratio;
    if (ambient_lux) p.ambient_lux = *ambient_lux;
    if (reflectivity) p.reflectivity = *reflectivity;
  }
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
  /// Head-mounted, asymmetric: the (left) eye's four edge angles; when set
  /// they define the geometry and fov_h_deg is 0. The horizontal angles give
  /// the focal length and the principal point's x; the vertical ones the
  /// principal point's y (as the ratio up : down, pixels being square, so a
  /// resized display keeps the axis at the same relative height).
  FovAngles fov{};
  /// Inter-pupillary distance of a stereo head-mounted display (the eye
  /// positions for per-eye cameras); 0 = not a stereo display.
  double ipd_mm = 0.0;
  /// Head-mounted: the lens and panel behind the eye buffer (lens.hpp). When
  /// set, the planner and the shading rates sample no finer than the panel
  /// shows through the lens; eccentricities stay the buffer's pinhole angles
  /// (the lens shows each buffer pixel at its pinhole angle). Absent: the
  /// panel is taken to be as fine as the buffer everywhere.
  std::optional<Lens> lens = std::nullopt;
  /// The light it emits, for the perceptual metrics (FovVideoVDP). Head-mounted
  /// presets see no ambient light.
  Photometry photometry{};
  /// The file it was read from (Display::load), empty for a preset: errors
  /// about the display name it.
  std::string source{};

  [[nodiscard]] bool head_mounted() const { return fov_h_deg > 0.0 || fov.set(); }
  /// Whether it can be rendered in stereo (four angles and an IPD).
  [[nodiscard]] bool stereo() const { return fov.set() && ipd_mm > 0.0; }
  /// Where the eye's optical axis meets the image (pixels, origin top-left):
  /// the centre unless the four angles say otherwise.
  [[nodiscard]] Vec2d principal_point() const;
  /// The full horizontal field of view in degrees (HMDs; 0 for flat panels).
  [[nodiscard]] double horizontal_fov_deg() const;
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
  /// origin top-left, pixel centres at +0.5), both from the eye at the
  /// principal point's normal.
  [[nodiscard]] double eccentricity_deg(Vec2d pixel, Vec2d gaze) const;
  /// Pixels per degree at `pixel`, measured along the direction away from the gaze.
  [[nodiscard]] double pixels_per_degree(Vec2d pixel, Vec2d gaze) const;
  /// Screen distance in pixels from the gaze point that subtends `eccentricity_deg`
  /// (along the ray from the gaze through the display centre's side, exact for a
  /// gaze at the principal point).
  [[nodiscard]] double radius_px_at(double eccentricity_deg) const;

  /// Through the lens: the panel's pixels per degree at the view direction of
  /// buffer `pixel` (radially from the lens axis and across). Throws
  /// foveate::Error for a display without a lens.
  [[nodiscard]] PanelDensity panel_pixels_per_degree(Vec2d pixel) const;
  /// Buffer pixels per panel pixel at `pixel` (1 and 1 without a lens).
  [[nodiscard]] Oversampling lens_oversampling(Vec2d pixel) const;
  /// The finest detail displayed at buffer `pixel`, as the angle of one
  /// displayed pixel in degrees: along the radial and the tangential
  /// direction the larger of the buffer's and the panel's pixel angle, and of
  /// those two the smaller. Without a lens the buffer's (radial) pixel angle.
  [[nodiscard]] double displayed_pixel_angle_deg(Vec2d pixel) const;
  /// The view tangent of the buffer's corner farthest from the principal point.
  [[nodiscard]] double max_view_tan() const;
  /// The lens's least oversampling beyond each view angle, out to the
  /// buffer's farthest corner (lens.hpp); none without a lens.
  [[nodiscard]] std::optional<OversamplingTable> lens_oversampling_table() const;

  /// The same physical display rendered at another resolution (same field of
  /// view): used to run at small test sizes with the real angular geometry.
  /// A lens (its panel) stays as it is: a smaller buffer has fewer pixels per
  /// panel pixel, so the lens relaxes less.
  [[nodiscard]] Display resized(int width, int height) const;

  /// Throws foveate::Error naming the field when a value is out of range.
  void validate() const;

  /// The other eye of a stereo display: the four angles (and the lens centre) mirrored.
  [[nodiscard]] Display mirrored() const;

  /// Built-in displays: desktop-1080p (the paper's), desktop-27-4k, hmd-quest3,
  /// the stereo headsets hmd-quest2 and hmd-pimax-crystal (left eye), and
  /// with a lens hmd-rift-dk1 (the Oculus SDK's published lens) and
  /// hmd-quest2-lens (hmd-quest2 with an example lens, see the README).
  static const std::vector<Display>& presets();
  /// The presets' names, comma-separated, in order (only the stereo ones
  /// when `stereo_only`): for help texts and error messages.
  static std::string preset_names(bool stereo_only = false);
  /// A preset name or a path to a JSON file.
  static Display load(const std::string& name_or_path);
  static Display from_json(const nlohmann::json& j, const std::string& where = "display");

 private:
  void validate_geometry() const;  // everything but the lens
};

void to_json(nlohmann::json& j, const Display& d);

}  // namespace foveate
