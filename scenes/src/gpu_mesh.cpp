#include "gpu_mesh.hpp"

#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>

#include "foveate/core/error.hpp"
#include "foveate/gpu/frame.hpp"

namespace foveate::detail {

namespace {

void bounds_of(const std::vector<Vertex>& v, glm::vec3& centre, float& radius) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const Vertex& x : v) {
    lo = glm::min(lo, glm::vec3(x.px, x.py, x.pz));
    hi = glm::max(hi, glm::vec3(x.px, x.py, x.pz));
  }
  centre = 0.5f * (lo + hi);
  radius = 0.5f * glm::length(hi - lo);
}

GpuMesh make_gpu(const std::vector<Vertex>& vertices, const std::vector<unsigned>& indices,
                 std::vector<GpuMesh::Lod> lods) {
  GpuMesh m;
  m.vertices = gpu::Buffer::create(static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
                                   vertices.data());
  m.indices = gpu::Buffer::create(static_cast<GLsizeiptr>(indices.size() * sizeof(unsigned)),
                                  indices.data());
  m.vao = gpu::VertexArray::create();
  const GLuint vao = m.vao.id();
  glVertexArrayVertexBuffer(vao, 0, m.vertices.id(), 0, sizeof(Vertex));
  glVertexArrayElementBuffer(vao, m.indices.id());
  for (GLuint a = 0; a < 3; ++a) glEnableVertexArrayAttrib(vao, a);
  glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, px));
  glVertexArrayAttribFormat(vao, 1, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, nx));
  glVertexArrayAttribFormat(vao, 2, 2, GL_FLOAT, GL_FALSE, offsetof(Vertex, u));
  for (GLuint a = 0; a < 3; ++a) glVertexArrayAttribBinding(vao, a, 0);
  m.lods = std::move(lods);
  bounds_of(vertices, m.centre, m.radius);
  return m;
}

}  // namespace

GpuMesh upload_mesh(const MeshData& data, int lod_count) {
  if (data.indices.size() < 3) throw Error("mesh has no triangles");
  std::vector<unsigned> all = data.indices;
  std::vector<GpuMesh::Lod> lods{{0, static_cast<GLsizei>(data.indices.size()), 0.0f}};
  const float scale =
      meshopt_simplifyScale(&data.vertices[0].px, data.vertices.size(), sizeof(Vertex));
  std::vector<unsigned> source = data.indices;
  for (int l = 1; l < lod_count; ++l) {
    // About a tenth of the previous level's triangles.
    const size_t target = std::max<size_t>(3, (source.size() / 3 / 10) * 3);
    std::vector<unsigned> out(source.size());
    float error = 0.0f;
    size_t n = meshopt_simplify(out.data(), source.data(), source.size(), &data.vertices[0].px,
                                data.vertices.size(), sizeof(Vertex), target, 1.0f, 0, &error);
    if (n > target * 2) {
      // Topology kept the simplifier from getting there: drop connectivity.
      n = meshopt_simplifySloppy(out.data(), source.data(), source.size(), &data.vertices[0].px,
                                 data.vertices.size(), sizeof(Vertex), target, 1.0f, &error);
    }
    if (n < 3) {  // nothing left: keep the previous level
      lods.push_back(lods.back());
      continue;
    }
    out.resize(n);
    lods.push_back({static_cast<GLsizei>(all.size()), static_cast<GLsizei>(n),
                    std::max(lods.back().error, error * scale)});
    all.insert(all.end(), out.begin(), out.end());
    source = std::move(out);
  }
  return make_gpu(data.vertices, all, std::move(lods));
}

GpuMesh upload_levels(const std::vector<MeshData>& levels) {
  std::vector<Vertex> vertices;
  std::vector<unsigned> indices;
  std::vector<GpuMesh::Lod> lods;
  for (const MeshData& m : levels) {
    const auto base = static_cast<unsigned>(vertices.size());
    lods.push_back(
        {static_cast<GLsizei>(indices.size()), static_cast<GLsizei>(m.indices.size()), 0.0f});
    vertices.insert(vertices.end(), m.vertices.begin(), m.vertices.end());
    for (unsigned i : m.indices) indices.push_back(base + i);
  }
  return make_gpu(vertices, indices, std::move(lods));
}

gpu::Texture texture_from_image(const Image& image) { return gpu::upload_image(image, true); }

}  // namespace foveate::detail
