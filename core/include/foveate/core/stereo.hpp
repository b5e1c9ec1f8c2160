#pragma once
// Stereo head-mounted displays: two eyes, each a Display of its own (the
// right eye's four field-of-view angles mirror the left's), the eyes
// inter-pupillary distance apart. The gaze of both eyes follows from one
// combined gaze: the direction of the cyclopean eye (midway between the eyes)
// and the vergence distance of the point both eyes fixate. Pure geometry, no
// GL: the renderer and the app build on it.
#include <array>

#include "foveate/core/display.hpp"

namespace foveate {

enum class Eye { Left = 0, Right = 1 };
inline constexpr std::array<Eye, 2> kEyes{Eye::Left, Eye::Right};
inline const char* eye_name(Eye e) { return e == Eye::Left ? "left" : "right"; }

/// The image-plane tangents of one eye's rendered image: the frustum an
/// off-axis projection needs (left and down negative), exact for the image's
/// size (the vertical extent follows from the height, pixels being square).
struct FrustumTangents {
  double left = 0, right = 0, down = 0, up = 0;
};

struct StereoDisplay {
  Display left;
  Display right;
  double ipd_mm = 0.0;

  /// Both eyes of a stereo display (Display::stereo()); throws foveate::Error
  /// naming the display and what it lacks otherwise.
  static StereoDisplay from(const Display& left_eye);
  [[nodiscard]] const Display& eye(Eye e) const { return e == Eye::Left ? left : right; }
  /// The eye's offset from the midpoint between the eyes along the head's
  /// right axis, in metres (-ipd/2 for the left eye).
  [[nodiscard]] double eye_offset_m(Eye e) const {
    return (e == Eye::Left ? -0.5 : 0.5) * ipd_mm * 1e-3;
  }
  /// The cyclopean view: one eye's size and focal length with the optical
  /// axis at the image centre. Combined gazes are positions in it.
  [[nodiscard]] Display cyclopean() const;
};

FrustumTangents frustum_tangents(const Display& eye);

/// Each eye's gaze in its own image (pixels, origin top-left).
struct StereoGaze {
  std::array<Vec2d, 2> px{};
  [[nodiscard]] const Vec2d& eye(Eye e) const { return px[static_cast<size_t>(e)]; }
};

/// Both eyes' gaze for a combined gaze: `cyclopean_px` is the gaze direction
/// as a position in StereoDisplay::cyclopean() (its centre = straight ahead)
/// and `vergence_m` the distance of the fixated point from the cyclopean eye
/// (infinity: parallel gaze, each eye at the same angle from its own axis).
/// Throws foveate::Error for a vergence distance that is not > 0.
StereoGaze stereo_gaze(const StereoDisplay& stereo, Vec2d cyclopean_px, double vergence_m);

}  // namespace foveate
