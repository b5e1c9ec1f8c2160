// The guenter scene's objects are drawn with their back faces culled (the
// prepass skips what a closed mesh hides from outside): each closed shape must
// be closed, and wound the way it declares, or the viewer would look into it.
#include "guenter_shapes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/glm.hpp>
#include <map>
#include <tuple>
#include <utility>

namespace foveate::detail {
namespace {

glm::vec3 position(const Vertex& v) { return {v.px, v.py, v.pz}; }
glm::vec3 normal(const Vertex& v) { return {v.nx, v.ny, v.nz}; }

// Edges used by exactly one triangle, vertices welded by position (the
// parameter grid repeats its seam and pole vertices); zero-area triangles
// (at the poles) left out.
int open_edges(const MeshData& m) {
  std::map<std::tuple<long, long, long>, int> ids;
  auto id = [&](unsigned i) {
    const glm::vec3 p = position(m.vertices[i]) * 1e4f;
    const auto key = std::make_tuple(std::lround(p.x), std::lround(p.y), std::lround(p.z));
    return ids.try_emplace(key, static_cast<int>(ids.size())).first->second;
  };
  std::map<std::pair<int, int>, int> uses;
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const int a = id(m.indices[t]), b = id(m.indices[t + 1]), c = id(m.indices[t + 2]);
    if (a == b || b == c || c == a) continue;
    for (auto [p, q] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
      ++uses[{std::min(p, q), std::max(p, q)}];
    }
  }
  int open = 0;
  for (const auto& [edge, n] : uses) open += n == 1 ? 1 : 0;
  return open;
}

TEST(GuenterShapes, ClosedShapesAreClosedAndWoundAsTheyDeclare) {
  for (int shape = 0; shape < kGuenterShapes; ++shape) {
    const GpuMesh::Winding declared = guenter_shape_outside(shape);
    for (int seg : {4, 12, 32}) {
      SCOPED_TRACE("shape " + std::to_string(shape) + ", " + std::to_string(seg) + " segments");
      const MeshData m = guenter_shape(shape, seg);
      if (declared == GpuMesh::Winding::unknown) {
        // Only an open shape may leave its back faces drawn: the vase.
        EXPECT_GT(open_edges(m), 0);
        continue;
      }
      EXPECT_EQ(open_edges(m), 0);
      // Seen from outside (along the outward normal), a triangle whose
      // vertices run counter-clockwise has its face normal, by the right-hand
      // rule, towards the viewer.
      int ccw = 0, cw = 0;
      for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
        const Vertex &a = m.vertices[m.indices[t]], &b = m.vertices[m.indices[t + 1]],
                     &c = m.vertices[m.indices[t + 2]];
        const glm::vec3 face = glm::cross(position(b) - position(a), position(c) - position(a));
        if (glm::length(face) < 1e-7f) continue;
        const float facing = glm::dot(face, normal(a) + normal(b) + normal(c));
        (facing > 0.0f ? ccw : cw) += 1;
      }
      if (declared == GpuMesh::Winding::ccw) {
        EXPECT_GT(ccw, 0);
        EXPECT_EQ(cw, 0);
      } else {
        EXPECT_GT(cw, 0);
        EXPECT_EQ(ccw, 0);
      }
    }
  }
}

}  // namespace
}  // namespace foveate::detail
