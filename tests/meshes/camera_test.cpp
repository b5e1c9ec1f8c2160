// The camera's look-at for any viewing direction (issue 13): looking straight
// down or up, where the world's up vector is parallel to the view, the view
// matrix is still a rotation that puts the target in front of the camera
// (not NaN, which renders an empty frame).
#include <gtest/gtest.h>

#include <cmath>
#include <glm/glm.hpp>

#include "foveate/scenes/camera_path.hpp"

using namespace foveate;

namespace {

void expect_looks_at(const CameraPose& pose) {
  const glm::dmat4 v = view_matrix(pose);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) ASSERT_TRUE(std::isfinite(v[c][r])) << c << "," << r;
  // The target lands on the view axis (-z), at its distance.
  const glm::dvec4 t = v * glm::dvec4(pose.target, 1.0);
  const double dist = glm::length(pose.target - pose.position);
  EXPECT_NEAR(t.x, 0.0, 1e-9);
  EXPECT_NEAR(t.y, 0.0, 1e-9);
  EXPECT_NEAR(t.z, -dist, 1e-9);
  // A rotation: orthonormal axes.
  const glm::dmat3 r(v);
  const glm::dmat3 i = glm::transpose(r) * r;
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(i[c][k], c == k ? 1.0 : 0.0, 1e-9);
}

}  // namespace

TEST(Camera, LooksStraightDownAndUp) {
  expect_looks_at({{0, 6, 0}, {0, 0, 0}, 50});   // straight down
  expect_looks_at({{1, -4, 2}, {1, 3, 2}, 50});  // straight up
  expect_looks_at({{0, 1, 5}, {0, 0, 0}, 50});   // an ordinary view
  // Looking down, the top of the image points along -z (the default view,
  // along -z, tilted down); looking up, along +z.
  EXPECT_EQ(camera_up({0, -1, 0}), glm::dvec3(0, 0, -1));
  EXPECT_EQ(camera_up({0, 2, 0}), glm::dvec3(0, 0, 1));
  EXPECT_EQ(camera_up({1, -1, 0}), glm::dvec3(0, 1, 0));
}
