#pragma once
// The 4x4 supersampled frame of a built-in scene, as the GL tests that judge
// antialiasing compare against: frame 0 of the scene's clock from 1 s, on
// `display` at its size. Needs a current GL context.
#include <string>

#include "foveate/scenes/scene.hpp"
#include "foveate/techniques/frame_runner.hpp"
#include "foveate/techniques/supersampled_native.hpp"

namespace foveate::test {

inline Image supersampled_frame(const std::string& scene_name, const Display& display) {
  auto scene = load_scene(scene_name), reference_scene = load_scene(scene_name);
  FrameRunnerOptions o;
  o.width = display.width_px;
  o.height = display.height_px;
  o.start_time_s = 1.0;
  SupersampledNative reference(display, 4);
  reference.render(*reference_scene, FrameRunner(*scene, o).frame_input(0));
  return reference.read();
}

}  // namespace foveate::test
