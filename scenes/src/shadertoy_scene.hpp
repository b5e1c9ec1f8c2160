#pragma once
// A Shadertoy scene: one Image pass (a user file or a built-in) and, for a
// multipass project, a Common part and up to four buffer passes rendered
// into float targets once per frame before the Image pass is shaded.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "foveate/scenes/camera_path.hpp"
#include "shadertoy_pass.hpp"

namespace foveate::detail {

/// Where an iChannel reads from: nothing (black), an image, or a buffer.
struct ChannelSource {
  int image = -1;   ///< index into ShadertoyProject::images
  int buffer = -1;  ///< 0..3 = Buffer A..D
};

struct ShadertoyPass {
  std::string name;  ///< "Image", "Buffer A", ...
  UserPass code;
  std::array<ChannelSource, 4> channels{};
};

struct ShadertoyProject {
  std::string scene_name;
  std::string description;
  std::string key;       ///< stable key for the program cache
  bool builtin = false;  ///< foveate's own scene: no channel warnings
  std::optional<UserPass> common;
  /// Buffer passes in Shadertoy's order (A before B ...), each with its id.
  std::vector<std::pair<int, ShadertoyPass>> buffers;
  ShadertoyPass image;
  std::vector<Image> images;
  CameraPath camera;
  ShadertoyDate date;
};

/// Builds the scene (uploads the images, compiles every pass to report
/// errors at load) and warns once for each channel a pass samples with
/// nothing bound to it. Needs a current GL context.
std::unique_ptr<Scene> make_shadertoy_scene(ShadertoyProject project);

/// Refuses a camera path (`camera_path`, empty: none given) for a project
/// none of whose passes reads the camera (foveate_cam_pos,
/// foveate_cam_target, foveate_cam_fov or foveate_ray): its frames would be
/// the same with or without it, and a run would say it followed the path.
void require_camera_read(const ShadertoyProject& project, const std::string& camera_path);

}  // namespace foveate::detail
