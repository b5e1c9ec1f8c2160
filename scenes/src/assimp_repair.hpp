#pragma once
// Repairs of an imported scene before assimp's post-processing, which
// validates it and would otherwise refuse (or misuse) what importers leave
// behind: faces without indices or with indices out of range, meshes
// without faces or vertices, a node naming the same mesh twice, and
// vertices at inf or NaN (vertex joining would merge them with real ones).
#include <cstddef>

struct aiScene;

namespace foveate::detail {

struct SceneRepair {
  size_t non_finite_vertices = 0;  ///< distinct positions with inf or NaN
  size_t bad_faces = 0;            ///< faces without indices or out of range
  size_t empty_meshes = 0;         ///< meshes removed: no vertices or no faces left
  size_t faces_left = 0;
  size_t meshes_left = 0;
};

/// Removes the faces that use a non-finite vertex or that have no indices or
/// indices out of range, then the meshes left without faces, fixing the
/// nodes' references (duplicates dropped). The removed vertices are moved onto
/// a finite one (they are unused from then on).
SceneRepair repair_scene(aiScene* scene);

}  // namespace foveate::detail
