#include "model_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace foveate::detail {

namespace {

bool finite(float a, float b, float c) {
  return std::isfinite(a) && std::isfinite(b) && std::isfinite(c);
}

// Eigenvalues (ascending) and eigenvectors (columns) of a symmetric 3x3
// matrix by cyclic Jacobi rotations.
void symmetric_eigen(glm::dmat3 a, glm::dvec3& values, glm::dmat3& vectors) {
  glm::dmat3 v(1.0);
  for (int sweep = 0; sweep < 50; ++sweep) {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    if (off < 1e-30) break;
    for (int p = 0; p < 2; ++p) {
      for (int q = p + 1; q < 3; ++q) {
        if (std::abs(a[p][q]) < 1e-300) continue;
        const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
        const double t =
            (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1.0 / std::sqrt(t * t + 1), s = t * c;
        glm::dmat3 r(1.0);
        r[p][p] = c, r[q][q] = c, r[q][p] = s, r[p][q] = -s;  // column-major: r[col][row]
        a = glm::transpose(r) * a * r;
        v = v * r;
      }
    }
  }
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int x, int y) { return a[x][x] < a[y][y]; });
  for (int i = 0; i < 3; ++i) {
    values[i] = a[order[i]][order[i]];
    vectors[i] = v[order[i]];
  }
}

}  // namespace

size_t drop_non_finite(MeshData& m) {
  std::vector<unsigned> remap(m.vertices.size(), ~0u);
  std::vector<Vertex> kept;
  kept.reserve(m.vertices.size());
  for (size_t i = 0; i < m.vertices.size(); ++i) {
    const Vertex& v = m.vertices[i];
    if (!finite(v.px, v.py, v.pz)) continue;
    remap[i] = static_cast<unsigned>(kept.size());
    kept.push_back(v);
  }
  const size_t dropped = m.vertices.size() - kept.size();
  if (dropped == 0) return 0;
  std::vector<unsigned> indices;
  indices.reserve(m.indices.size());
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const unsigned a = remap[m.indices[t]], b = remap[m.indices[t + 1]],
                   c = remap[m.indices[t + 2]];
    if (a == ~0u || b == ~0u || c == ~0u) continue;
    indices.insert(indices.end(), {a, b, c});
  }
  m.vertices = std::move(kept);
  m.indices = std::move(indices);
  return dropped;
}

size_t repair_normals(MeshData& m) {
  std::vector<char> bad(m.vertices.size(), 0);
  size_t count = 0;
  for (size_t i = 0; i < m.vertices.size(); ++i) {
    const Vertex& v = m.vertices[i];
    const float len2 = v.nx * v.nx + v.ny * v.ny + v.nz * v.nz;
    if (!std::isfinite(len2) || len2 < 1e-12f) bad[i] = 1, ++count;
  }
  if (count == 0) return 0;
  std::vector<glm::vec3> acc(m.vertices.size(), glm::vec3(0.0f));
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const unsigned i[3] = {m.indices[t], m.indices[t + 1], m.indices[t + 2]};
    if (!bad[i[0]] && !bad[i[1]] && !bad[i[2]]) continue;
    glm::vec3 p[3];
    for (int k = 0; k < 3; ++k) {
      const Vertex& v = m.vertices[i[k]];
      p[k] = glm::vec3(v.px, v.py, v.pz);
    }
    const glm::vec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);  // length = 2 * area
    if (!std::isfinite(glm::dot(n, n))) continue;
    for (unsigned k : i) acc[k] += n;
  }
  for (size_t i = 0; i < m.vertices.size(); ++i) {
    if (!bad[i]) continue;
    const float len = glm::length(acc[i]);
    const glm::vec3 n = len > 1e-20f && std::isfinite(len) ? acc[i] / len : glm::vec3(0, 1, 0);
    m.vertices[i].nx = n.x, m.vertices[i].ny = n.y, m.vertices[i].nz = n.z;
  }
  return count;
}

double surface_area(const MeshData& m) {
  double area = 0.0;
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    glm::dvec3 p[3];
    for (int k = 0; k < 3; ++k) {
      const Vertex& v = m.vertices[m.indices[t + static_cast<size_t>(k)]];
      p[k] = glm::dvec3(v.px, v.py, v.pz);
    }
    area += 0.5 * glm::length(glm::cross(p[1] - p[0], p[2] - p[0]));
  }
  return area;
}

void box_uvs(MeshData& m) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const Vertex& v : m.vertices) {
    lo = glm::min(lo, glm::vec3(v.px, v.py, v.pz));
    hi = glm::max(hi, glm::vec3(v.px, v.py, v.pz));
  }
  const glm::vec3 size = glm::max(hi - lo, glm::vec3(1e-20f));
  for (Vertex& v : m.vertices) {
    const glm::vec3 p = (glm::vec3(v.px, v.py, v.pz) - lo) / size;
    const glm::vec3 n = glm::abs(glm::vec3(v.nx, v.ny, v.nz));
    if (n.x >= n.y && n.x >= n.z)
      v.u = p.z, v.v = p.y;
    else if (n.y >= n.z)
      v.u = p.x, v.v = p.z;
    else
      v.u = p.x, v.v = p.y;
  }
}

void make_y_up(MeshData& m, UpAxis up) {
  if (up.axis == 1 && up.sign > 0) return;
  // A rotation taking the file's up direction to +Y (a right-handed turn,
  // so that nothing is mirrored).
  auto turn = [&](float& x, float& y, float& z) {
    const float a = x, b = y, c = z;
    if (up.axis == 2 && up.sign > 0)
      x = a, y = c, z = -b;  // +Z up: -90 deg about X
    else if (up.axis == 2)
      x = a, y = -c, z = b;  // -Z up: +90 deg about X
    else if (up.axis == 0 && up.sign > 0)
      x = -b, y = a, z = c;  // +X up: +90 deg about Z
    else if (up.axis == 0)
      x = b, y = -a, z = c;  // -X up: -90 deg about Z
    else
      x = -a, y = -b, z = c;  // -Y up: 180 deg about Z
  };
  for (Vertex& v : m.vertices) {
    turn(v.px, v.py, v.pz);
    turn(v.nx, v.ny, v.nz);
  }
}

void ShapeStats::add(const MeshData& m) {
  for (const Vertex& v : m.vertices) {
    const glm::dvec3 p(v.px, v.py, v.pz);
    count_ += 1.0;
    sum_ += p;
    sum_sq_ += glm::outerProduct(p, p);
    normal_sum_ += glm::dvec3(v.nx, v.ny, v.nz);
    lo_ = glm::min(lo_, glm::vec3(p));
    hi_ = glm::max(hi_, glm::vec3(p));
  }
}

std::optional<glm::vec3> ShapeStats::plane_normal() const {
  if (count_ < 3) return std::nullopt;
  const glm::dvec3 mean = sum_ / count_;
  const glm::dmat3 cov = sum_sq_ / count_ - glm::outerProduct(mean, mean);
  glm::dvec3 values;
  glm::dmat3 vectors;
  symmetric_eigen(cov, values, vectors);
  // Flat when the thinnest spread is under a third of the middle one.
  if (!(values[1] > 0.0) || values[0] > values[1] / 9.0) return std::nullopt;
  glm::dvec3 n = glm::normalize(vectors[0]);
  const double facing = glm::dot(n, normal_sum_);
  if (facing < 0.0 || (facing == 0.0 && n.y < 0.0)) n = -n;
  return glm::vec3(n);
}

OrbitStart default_orbit_start(const std::optional<glm::vec3>& plane_normal) {
  const double base = std::atan(0.35);  // the orbit's usual look down
  if (!plane_normal) return {0.0, base};
  const glm::vec3 n = *plane_normal;
  const double limit = 60.0 * std::numbers::pi / 180.0;  // never straight down
  double elevation = std::asin(std::clamp(double(n.y), -1.0, 1.0));
  elevation = std::clamp(elevation, -limit, limit);
  if (std::abs(elevation) < base) elevation = base;  // a wall: face it, slightly from above
  const double horizontal = std::hypot(double(n.x), double(n.z));
  const double azimuth = horizontal > 1e-3 ? std::atan2(double(n.x), double(n.z)) : 0.0;
  return {azimuth, elevation};
}

}  // namespace foveate::detail
