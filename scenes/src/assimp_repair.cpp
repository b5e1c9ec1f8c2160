#include "assimp_repair.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wshadow"
#include <assimp/scene.h>
#pragma GCC diagnostic pop

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <set>
#include <vector>

namespace foveate::detail {

namespace {

bool finite(const aiVector3D& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// Filters one mesh's faces; returns false when the mesh has nothing left.
bool repair_mesh(aiMesh* m, SceneRepair& r) {
  if (!m->mVertices || m->mNumVertices == 0 || !m->mFaces) return false;
  std::vector<char> bad(m->mNumVertices, 0);
  std::set<std::array<std::uint32_t, 3>> distinct;  // importers copy vertices per face
  unsigned anchor = m->mNumVertices;
  for (unsigned v = 0; v < m->mNumVertices; ++v) {
    const aiVector3D& p = m->mVertices[v];
    if (finite(p)) {
      if (anchor == m->mNumVertices) anchor = v;
      continue;
    }
    bad[v] = 1;
    static_assert(sizeof(p.x) == sizeof(std::uint32_t));
    std::array<std::uint32_t, 3> bits{};
    std::memcpy(&bits[0], &p.x, 4);
    std::memcpy(&bits[1], &p.y, 4);
    std::memcpy(&bits[2], &p.z, 4);
    distinct.insert(bits);
  }
  r.non_finite_vertices += distinct.size();
  std::vector<unsigned> keep;
  for (unsigned f = 0; f < m->mNumFaces; ++f) {
    const aiFace& face = m->mFaces[f];
    bool in_range = face.mNumIndices > 0 && face.mIndices;
    bool uses_bad = false;
    for (unsigned k = 0; in_range && k < face.mNumIndices; ++k) {
      in_range = face.mIndices[k] < m->mNumVertices;
      uses_bad = uses_bad || (in_range && bad[face.mIndices[k]]);
    }
    if (!in_range) ++r.bad_faces;
    if (in_range && !uses_bad) keep.push_back(f);
  }
  if (keep.empty()) return false;
  if (anchor < m->mNumVertices) {
    for (unsigned v = 0; v < m->mNumVertices; ++v) {
      if (bad[v]) m->mVertices[v] = m->mVertices[anchor];
    }
  }
  r.faces_left += keep.size();
  if (keep.size() == m->mNumFaces) return true;
  auto* faces = new aiFace[keep.size()];
  for (size_t i = 0; i < keep.size(); ++i) {
    std::swap(faces[i].mNumIndices, m->mFaces[keep[i]].mNumIndices);
    std::swap(faces[i].mIndices, m->mFaces[keep[i]].mIndices);
  }
  delete[] m->mFaces;
  m->mFaces = faces;
  m->mNumFaces = static_cast<unsigned>(keep.size());
  return true;
}

void fix_node(aiNode* node, const std::vector<unsigned>& remap) {
  if (!node) return;
  std::vector<unsigned> meshes;
  for (unsigned i = 0; i < node->mNumMeshes; ++i) {
    const unsigned old = node->mMeshes[i];
    if (old >= remap.size() || remap[old] == ~0u) continue;
    if (std::find(meshes.begin(), meshes.end(), remap[old]) == meshes.end()) {
      meshes.push_back(remap[old]);
    }
  }
  if (meshes.size() != node->mNumMeshes ||
      !std::equal(meshes.begin(), meshes.end(), node->mMeshes)) {
    delete[] node->mMeshes;
    node->mMeshes = nullptr;
    node->mNumMeshes = static_cast<unsigned>(meshes.size());
    if (!meshes.empty()) {
      node->mMeshes = new unsigned[meshes.size()];
      std::copy(meshes.begin(), meshes.end(), node->mMeshes);
    }
  }
  for (unsigned c = 0; c < node->mNumChildren; ++c) fix_node(node->mChildren[c], remap);
}

}  // namespace

SceneRepair repair_scene(aiScene* s) {
  SceneRepair r;
  std::vector<unsigned> remap(s->mNumMeshes, ~0u);
  std::vector<aiMesh*> kept;
  for (unsigned i = 0; i < s->mNumMeshes; ++i) {
    aiMesh* m = s->mMeshes[i];
    if (m && repair_mesh(m, r)) {
      remap[i] = static_cast<unsigned>(kept.size());
      kept.push_back(m);
    } else {
      ++r.empty_meshes;
      delete m;
    }
  }
  r.meshes_left = kept.size();
  if (kept.size() != s->mNumMeshes) {
    std::copy(kept.begin(), kept.end(), s->mMeshes);
    s->mNumMeshes = static_cast<unsigned>(kept.size());
  }
  fix_node(s->mRootNode, remap);
  return r;
}

}  // namespace foveate::detail
