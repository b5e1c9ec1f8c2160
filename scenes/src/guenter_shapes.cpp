#include "guenter_shapes.hpp"

#include <cmath>
#include <glm/glm.hpp>
#include <numbers>

namespace foveate::detail {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// A parametric surface on (u, v) in [0,1]^2.
glm::vec3 surface(int shape, float u, float v, glm::vec3& n) {
  const float th = 2.0f * kPi * u, ph = kPi * v;
  switch (shape) {
    case 0: {  // sphere
      const glm::vec3 p(std::sin(ph) * std::cos(th), std::cos(ph), std::sin(ph) * std::sin(th));
      n = p;
      return p;
    }
    case 1: {  // torus
      const float R = 0.75f, r = 0.3f, a = 2.0f * kPi * v;
      const glm::vec3 c(R * std::cos(th), 0.0f, R * std::sin(th));
      n = glm::vec3(std::cos(a) * std::cos(th), std::sin(a), std::cos(a) * std::sin(th));
      return c + r * n;
    }
    case 2: {  // superquadric: a rounded cube
      // Signed power. sin(pi) and cos(pi / 2) are not quite 0 in floats, and
      // their 0.35th power is 0.003: the poles and the seam would open into
      // tiny holes, rimmed by inverted triangles. Rounding errors are 0.
      auto sp = [](float x, float e) {
        return std::abs(x) < 1e-6f ? 0.0f : std::copysign(std::pow(std::abs(x), e), x);
      };
      const float e = 0.35f;
      const glm::vec3 p(sp(std::sin(ph), e) * sp(std::cos(th), e), sp(std::cos(ph), e),
                        sp(std::sin(ph), e) * sp(std::sin(th), e));
      n = glm::vec3(sp(std::sin(ph), 2 - e) * sp(std::cos(th), 2 - e), sp(std::cos(ph), 2 - e),
                    sp(std::sin(ph), 2 - e) * sp(std::sin(th), 2 - e));
      return 0.85f * p;
    }
    default: {  // a vase: a surface of revolution, open at both ends
      const float y = 2.0f * v - 1.0f;
      const float r = 0.45f + 0.25f * std::sin(3.0f * y + 1.0f) + 0.1f * std::cos(7.0f * y);
      const float dr = 0.75f * std::cos(3.0f * y + 1.0f) - 0.7f * std::sin(7.0f * y);
      n = glm::vec3(std::cos(th), -dr * 0.5f, std::sin(th));
      return glm::vec3(r * std::cos(th), y, r * std::sin(th));
    }
  }
}

}  // namespace

MeshData guenter_shape(int shape, int seg) {
  MeshData m;
  for (int j = 0; j <= seg; ++j) {
    for (int i = 0; i <= seg; ++i) {
      const float u = float(i) / float(seg), v = float(j) / float(seg);
      glm::vec3 n;
      const glm::vec3 p = surface(shape, u, v, n);
      n = glm::length(n) > 1e-6f ? glm::normalize(n) : glm::vec3(0, 1, 0);
      m.vertices.push_back({p.x, p.y, p.z, n.x, n.y, n.z, u, v});
    }
  }
  grid_triangles(m, seg);
  return m;
}

void grid_triangles(MeshData& m, int cells) {
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      const unsigned a = unsigned(j * (cells + 1) + i), b = a + 1, c = a + unsigned(cells + 1),
                     d = c + 1;
      m.indices.insert(m.indices.end(), {a, c, b, b, c, d});
    }
  }
}

GpuMesh::Winding guenter_shape_outside(int shape) {
  switch (shape) {
    case 0:
    case 2:
      return GpuMesh::Winding::cw;
    case 1:
      return GpuMesh::Winding::ccw;
    default:
      return GpuMesh::Winding::unknown;
  }
}

}  // namespace foveate::detail
