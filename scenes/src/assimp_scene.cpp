// Mesh files through assimp: OBJ, glTF/GLB, PLY, FBX, 3DS and the rest,
// framed automatically, with base colours and textures, deferred lighting and
// three LODs per mesh.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wshadow"
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#pragma GCC diagnostic pop

#include <stb/stb_image.h>

#include <cstring>
#include <filesystem>
#include <glm/gtc/type_ptr.hpp>
#include <map>

#include "factories.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"
#include "foveate/core/image.hpp"
#include "mesh_common.hpp"

namespace foveate::detail {

namespace {

namespace fs = std::filesystem;

Image decode_embedded(const aiTexture* t, const std::string& where) {
  if (t->mHeight == 0) {  // compressed (PNG, JPEG) bytes
    int w = 0, h = 0, n = 0;
    unsigned char* px = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(t->pcData),
                                              static_cast<int>(t->mWidth), &w, &h, &n, 4);
    if (!px)
      throw Error(where + ": an embedded texture cannot be decoded (" + stbi_failure_reason() +
                  ")");
    Image img(w, h);
    std::memcpy(img.rgba.data(), px, img.rgba.size());
    stbi_image_free(px);
    return img;
  }
  Image img(static_cast<int>(t->mWidth), static_cast<int>(t->mHeight));
  for (size_t i = 0; i < static_cast<size_t>(t->mWidth) * t->mHeight; ++i) {
    img.rgba[i * 4 + 0] = t->pcData[i].r;
    img.rgba[i * 4 + 1] = t->pcData[i].g;
    img.rgba[i * 4 + 2] = t->pcData[i].b;
    img.rgba[i * 4 + 3] = t->pcData[i].a;
  }
  return img;
}

class AssimpScene final : public MeshSceneBase {
 public:
  AssimpScene(const std::string& path, const SceneOptions& o)
      : MeshSceneBase(fs::path(path).filename().string(), "mesh file " + path, CameraPath{}) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw Error(path + ": is a directory, not a model file");
    if (fs::file_size(path, ec) == 0) throw Error(path + ": the model file is empty");
    Assimp::Importer importer;
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                                aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    const aiScene* s = importer.ReadFile(
        path, aiProcess_Triangulate | aiProcess_GenSmoothNormals | aiProcess_JoinIdenticalVertices |
                  aiProcess_PreTransformVertices | aiProcess_SortByPType |
                  aiProcess_ValidateDataStructure);
    if (!s || (s->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !s->mRootNode) {
      const std::string why = importer.GetErrorString();
      if (why.find("No meshes") != std::string::npos || why.find("no faces") != std::string::npos) {
        throw Error(path + ": the model has no triangles to render (" + why + ")");
      }
      throw Error(path + ": cannot read the model: " + why);
    }
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (unsigned mi = 0; mi < s->mNumMeshes; ++mi) {
      const aiMesh* am = s->mMeshes[mi];
      if (!(am->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) || am->mNumFaces == 0) continue;
      MeshData d;
      d.vertices.resize(am->mNumVertices);
      for (unsigned v = 0; v < am->mNumVertices; ++v) {
        Vertex& x = d.vertices[v];
        x.px = am->mVertices[v].x, x.py = am->mVertices[v].y, x.pz = am->mVertices[v].z;
        if (am->mNormals)
          x.nx = am->mNormals[v].x, x.ny = am->mNormals[v].y, x.nz = am->mNormals[v].z;
        else
          x.nx = 0, x.ny = 1, x.nz = 0;
        if (am->mTextureCoords[0])
          x.u = am->mTextureCoords[0][v].x, x.v = am->mTextureCoords[0][v].y;
        else
          x.u = x.v = 0;
        lo = glm::min(lo, glm::vec3(x.px, x.py, x.pz));
        hi = glm::max(hi, glm::vec3(x.px, x.py, x.pz));
      }
      for (unsigned f = 0; f < am->mNumFaces; ++f) {
        if (am->mFaces[f].mNumIndices != 3) continue;
        for (int k = 0; k < 3; ++k) d.indices.push_back(am->mFaces[f].mIndices[k]);
      }
      if (d.indices.empty()) continue;
      meshes_.push_back(upload_mesh(d, 3));
      materials_.push_back(material(s, am->mMaterialIndex, path));
      full_triangles_ += d.indices.size() / 3;
    }
    if (meshes_.empty()) throw Error(path + ": the model has no triangles");
    const glm::vec3 centre = 0.5f * (lo + hi);
    scene_radius_ = std::max(1e-4f, 0.5f * glm::length(hi - lo));
    // Framed automatically: an orbit that keeps the bounding sphere in view.
    const double fov = 45.0;
    const double dist = scene_radius_ / std::sin(0.5 * fov * 3.14159265358979 / 180.0) * 1.1;
    camera_ = o.camera_path.empty()
                  ? CameraPath::orbit(glm::dvec3(centre), dist, 0.35 * dist, 24.0, fov)
                  : CameraPath::load(o.camera_path);
    for (int i = 0; i < 6; ++i) {
      const float a = static_cast<float>(i) * 1.0472f;
      lights_[i] =
          glm::vec4(centre + scene_radius_ * glm::vec3(1.6f * std::cos(a),
                                                       0.8f + 0.4f * static_cast<float>(i % 2),
                                                       1.6f * std::sin(a)),
                    scene_radius_ * 2.0f);
      light_colors_[i] = 0.35f * glm::vec3(i % 3 == 0 ? 1.0f : 0.5f, i % 3 == 1 ? 1.0f : 0.5f,
                                           i % 3 == 2 ? 1.0f : 0.5f);
    }
    centre_ = centre;
  }

  std::string shade_key() const override { return "builtin:mesh"; }
  std::vector<gpu::StageSource::Piece> shade_source() const override {
    return {{"mesh_shade.glsl", {}}};
  }

 protected:
  std::vector<DrawItem> items(const View&, int lod) override {
    std::vector<DrawItem> out;
    for (size_t i = 0; i < meshes_.size(); ++i) {
      out.push_back({&meshes_[i], glm::mat4(1.0f), materials_[i], std::max(lod, 0), true});
    }
    return out;
  }
  void bind_extra(const gpu::Program& p) override {
    p.allow_missing({"u_lights[0]", "u_light_colors[0]"});  // unused where only depth is read
    glProgramUniform4fv(p.id(), p.uniform("u_lights[0]"), 6, glm::value_ptr(lights_[0]));
    glProgramUniform3fv(p.id(), p.uniform("u_light_colors[0]"), 6,
                        glm::value_ptr(light_colors_[0]));
  }
  std::vector<glm::vec3> object_centres() const override {
    std::vector<glm::vec3> out;
    for (const GpuMesh& m : meshes_) out.push_back(m.centre);
    return out;
  }

 private:
  Material material(const aiScene* s, unsigned index, const std::string& path) {
    Material m;
    if (index >= s->mNumMaterials) return m;
    const aiMaterial* am = s->mMaterials[index];
    aiColor4D c;
    if (aiGetMaterialColor(am, AI_MATKEY_BASE_COLOR, &c) == AI_SUCCESS ||
        aiGetMaterialColor(am, AI_MATKEY_COLOR_DIFFUSE, &c) == AI_SUCCESS) {
      m.base_color = glm::vec3(c.r, c.g, c.b);
    }
    float shininess = 0.0f;
    if (aiGetMaterialFloat(am, AI_MATKEY_SHININESS, &shininess) == AI_SUCCESS) {
      m.gloss = std::clamp(shininess / 256.0f, 0.0f, 1.0f);
    }
    aiString tex;
    if (am->GetTexture(aiTextureType_BASE_COLOR, 0, &tex) == AI_SUCCESS ||
        am->GetTexture(aiTextureType_DIFFUSE, 0, &tex) == AI_SUCCESS) {
      const std::string name = tex.C_Str();
      auto it = textures_.find(name);
      if (it == textures_.end()) {
        Image img;
        if (const aiTexture* emb = s->GetEmbeddedTexture(tex.C_Str())) {
          img = decode_embedded(emb, path);
        } else {
          const fs::path file = fs::path(path).parent_path() / name;
          try {
            img = read_image(file.string());
          } catch (const Error& e) {
            throw Error(path + ": texture '" + name + "': " + e.what());
          }
        }
        it = textures_.emplace(name, texture_from_image(img)).first;
      }
      m.texture = &it->second;
      m.base_color = glm::max(m.base_color, glm::vec3(0.0f));
    }
    return m;
  }

  std::vector<GpuMesh> meshes_;
  std::vector<Material> materials_;
  std::map<std::string, gpu::Texture> textures_;
  glm::vec4 lights_[6];
  glm::vec3 light_colors_[6];
  glm::vec3 centre_{0.0f};
};

}  // namespace

std::unique_ptr<Scene> make_mesh_file(const std::string& path, const SceneOptions& options) {
  return std::make_unique<AssimpScene>(path, options);
}

}  // namespace foveate::detail
