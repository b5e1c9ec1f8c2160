#pragma once
// Meshes on the GPU: the vertex layout, a mesh's CPU geometry, its upload
// with three discrete LODs, and image textures.
#include <glm/glm.hpp>
#include <vector>

#include "foveate/core/image.hpp"
#include "foveate/gpu/gl.hpp"

namespace foveate::detail {

struct Vertex {
  float px, py, pz;
  float nx, ny, nz;
  float u, v;
};

/// CPU geometry of one mesh.
struct MeshData {
  std::vector<Vertex> vertices;
  std::vector<unsigned> indices;
};

/// One mesh on the GPU: a vertex buffer and the index ranges of its LODs
/// (0 = full detail; 1 and 2 about 10 % and 1 % of the triangles).
struct GpuMesh {
  gpu::VertexArray vao;
  gpu::Buffer vertices;
  gpu::Buffer indices;
  struct Lod {
    GLsizei first = 0;   ///< first index
    GLsizei count = 0;   ///< index count
    float error = 0.0f;  ///< geometric error in the mesh's units
  };
  std::vector<Lod> lods;
  glm::vec3 centre{0.0f};
  float radius = 0.0f;
  /// The winding on the screen of the faces a viewer sees, for a closed mesh
  /// wound consistently: its other faces never show from outside it, so the
  /// prepass culls them (a fifth of guenter's G-buffer pass). Unknown (the
  /// default): both sides are drawn, as files disagree on winding and an
  /// open surface shows its inside.
  enum class Winding { unknown, ccw, cw };
  Winding outside = Winding::unknown;
  [[nodiscard]] size_t triangles(size_t lod = 0) const {
    return lods.empty() ? 0 : static_cast<size_t>(lods[std::min(lod, lods.size() - 1)].count) / 3;
  }
};

/// Uploads `data` with `lod_count` LODs made by meshoptimizer's simplifier,
/// each about a tenth of the previous (Knapik and McGowen).
GpuMesh upload_mesh(const MeshData& data, int lod_count = 3);
/// Uploads several already-made LOD levels of one mesh (e.g. tessellations),
/// finest first.
GpuMesh upload_levels(const std::vector<MeshData>& levels);

/// Linear-ish colour of an image texture upload (mipmapped, repeat).
gpu::Texture texture_from_image(const Image& image);

}  // namespace foveate::detail
