#include "foveate/scenes/camera_path.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "foveate/core/error.hpp"
#include "foveate/core/json_read.hpp"

using namespace foveate;

namespace {
std::string load_error(const std::string& text) {
  try {
    (void)CameraPath::from_json(parse_json(text, "cam.json"), "cam.json");
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}
}  // namespace

TEST(CameraPath, InterpolatesThroughKeyframes) {
  const CameraPath p = CameraPath::from_json(parse_json(R"({"loop": false, "keyframes": [
        {"t": 0, "position": [0, 0, 5], "target": [0, 0, 0], "fov_deg": 40},
        {"t": 2, "position": [4, 0, 5], "target": [0, 0, 0], "fov_deg": 60}]})",
                                                        "cam.json"),
                                             "cam.json");
  const CameraPose mid = p.at(1.0);
  EXPECT_NEAR(mid.position.x, 2.0, 1e-12);  // two keys: the spline is the straight line
  EXPECT_NEAR(mid.fov_deg, 50.0, 1e-12);
  EXPECT_NEAR(p.at(5.0).position.x, 4.0, 1e-12);  // held after the end
}

// Found by camera_path_fuzz: finite but huge coordinates (1e308) made the
// spline overflow, and a render would have used an infinite camera position.
TEST(CameraPath, HugeCoordinatesAreRefused) {
  EXPECT_EQ(load_error(R"({"keyframes": [{"t": 0, "position": [1e308, 0, 0]}, {"t": 1}]})"),
            "cam.json.keyframes[0].position: coordinates must be finite and within +-1e12, got "
            "1e+308");
  EXPECT_EQ(load_error(R"({"keyframes": [{"t": 0, "target": [0, -2e12, 0]}]})"),
            "cam.json.keyframes[0].target: coordinates must be finite and within +-1e12, got "
            "-2000000000000.0");
  // At the limit the pose stays finite everywhere on a looping path.
  const CameraPath p =
      CameraPath::from_json(parse_json(R"({"keyframes": [{"t": 0, "position": [1e12, 0, 0]},
                                   {"t": 1, "position": [-1e12, 0, 0]},
                                   {"t": 2, "position": [1e12, 1e12, -1e12]}]})",
                                       "cam.json"),
                            "cam.json");
  for (double t : {0.1, 0.5, 1.3, 1.9, 7.7}) {
    const CameraPose pose = p.at(t);
    EXPECT_TRUE(std::isfinite(pose.position.x) && std::isfinite(pose.position.y) &&
                std::isfinite(pose.position.z))
        << t;
  }
}
