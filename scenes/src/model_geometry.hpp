#pragma once
// The geometry side of model loading, on the CPU: dropping non-finite
// vertices, repairing normals, turning a Z-up file upright, and choosing a
// default view that sees a flat model from its face.
#include <glm/glm.hpp>
#include <optional>
#include <string>

#include "gpu_mesh.hpp"

namespace foveate::detail {

/// Removes vertices with a non-finite position and every triangle that
/// uses one (indices remapped). Returns how many vertices were removed.
size_t drop_non_finite(MeshData& mesh);

/// Gives every vertex whose normal is zero, degenerate or non-finite the
/// area-weighted normal of the triangles around it (or +Y when those are
/// degenerate too). Returns how many normals were replaced.
size_t repair_normals(MeshData& mesh);

/// The summed area of the mesh's triangles (0 when every one is degenerate).
double surface_area(const MeshData& mesh);

/// Box-projected UVs (assimp leaves aiTextureMapping_BOX unimplemented):
/// each vertex is projected along the axis its normal is closest to, onto
/// the mesh's bounding box faces scaled to [0, 1].
void box_uvs(MeshData& mesh);

/// Up axis of a file: 0 = X, 1 = Y, 2 = Z, with sign +1 or -1.
struct UpAxis {
  int axis = 1;
  int sign = 1;
};
/// Rotates positions and normals so that `up` becomes +Y.
void make_y_up(MeshData& mesh, UpAxis up);

/// Accumulates the vertices of several meshes for the default view.
class ShapeStats {
 public:
  void add(const MeshData& mesh);
  [[nodiscard]] bool empty() const { return count_ == 0; }
  [[nodiscard]] glm::vec3 lo() const { return lo_; }
  [[nodiscard]] glm::vec3 hi() const { return hi_; }
  /// The unit normal of the model's dominant plane, when it is flat
  /// enough to have one (the smallest principal axis clearly smaller than
  /// the others), oriented toward the side its normals face.
  [[nodiscard]] std::optional<glm::vec3> plane_normal() const;

 private:
  double count_ = 0;
  glm::dvec3 sum_{0.0};
  glm::dmat3 sum_sq_{0.0};
  glm::dvec3 normal_sum_{0.0};
  glm::vec3 lo_{1e30f}, hi_{-1e30f};
};

/// Azimuth (radians, about +Y, 0 = the +Z side) and elevation (radians) of
/// the default orbit's start, so that a flat model is seen from its face.
struct OrbitStart {
  double azimuth = 0.0;
  double elevation = 0.0;
};
OrbitStart default_orbit_start(const std::optional<glm::vec3>& plane_normal);

}  // namespace foveate::detail
