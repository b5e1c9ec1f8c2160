// Camera-path JSON (--camera FILE): a path that loads gives a finite pose at
// any time.
#include <cmath>

#include "foveate/core/json_read.hpp"
#include "foveate/scenes/camera_path.hpp"
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  foveate::fuzz::expect_clean([&] {
    const foveate::CameraPath p = foveate::CameraPath::from_json(
        foveate::parse_json(foveate::fuzz::text(data, size), "fuzz"), "fuzz.json");
    for (double t : {-3.5, 0.0, 0.25 * p.duration_s(), p.duration_s(), 1e6 + 7.0}) {
      const foveate::CameraPose pose = p.at(t);
      for (int i = 0; i < 3; ++i) {
        foveate::fuzz::check(std::isfinite(pose.position[i]) && std::isfinite(pose.target[i]));
      }
      foveate::fuzz::check(pose.fov_deg >= 1.0 && pose.fov_deg <= 170.0);
    }
  });
  return 0;
}
