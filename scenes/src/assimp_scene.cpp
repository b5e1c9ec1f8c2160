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

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <glm/gtc/type_ptr.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>

#include "assimp_repair.hpp"
#include "factories.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"
#include "foveate/core/image.hpp"
#include "mesh_scene_base.hpp"
#include "model_files.hpp"
#include "model_geometry.hpp"
#include "scene_warnings.hpp"

namespace foveate::detail {

namespace {

namespace fs = std::filesystem;

Image decode_embedded(const aiTexture* t, const std::string& where) {
  if (t->mHeight == 0) {  // compressed (PNG, JPEG) bytes
    int w = 0, h = 0, n = 0;
    unsigned char* px = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(t->pcData),
                                              static_cast<int>(t->mWidth), &w, &h, &n, 4);
    if (!px)
      throw Error("the embedded image in " + where + " cannot be decoded (" +
                  stbi_failure_reason() + ")");
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

void warn(const std::string& text) { warn_once(text); }

std::string lower_ext(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// What is wrong with a glTF file that assimp gave up on ("No suitable
// reader found" for a .gltf cut short): glTF's own structure says whether the
// file is truncated or corrupt. Empty when it looks whole.
std::string gltf_problem(const std::string& path, const std::string& ext) {
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  if (ec) return {};
  if (size == 0) return "the file is empty";
  if (ext == ".gltf") {
    try {
      const nlohmann::json whole = nlohmann::json::parse(read_file(path));
      if (!whole.is_object()) return "not a glTF JSON object: the file is corrupt";
    } catch (const nlohmann::json::parse_error& e) {
      return "not valid glTF JSON (" + std::to_string(size) + " bytes; " + e.what() +
             "): the file is truncated or corrupt";
    } catch (const Error&) {
      return {};
    }
    return {};
  }
  if (ext != ".glb") return {};
  // GLB: "glTF", version, total length (little-endian uint32s).
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return {};
  unsigned char h[12] = {};
  const size_t got = std::fread(h, 1, sizeof h, f);
  std::fclose(f);
  if (got < sizeof h) return "the GLB header is cut short (" + std::to_string(got) + " bytes)";
  if (std::memcmp(h, "glTF", 4) != 0) return "no GLB header (the file does not start with 'glTF')";
  const std::uint64_t length = std::uint64_t(h[8]) | std::uint64_t(h[9]) << 8 |
                               std::uint64_t(h[10]) << 16 | std::uint64_t(h[11]) << 24;
  if (size < length) {
    return "truncated: the GLB header gives " + std::to_string(length) + " bytes, the file has " +
           std::to_string(size);
  }
  return {};
}

// Why the import failed, in words, even when assimp gives no reason.
[[noreturn]] void import_failed(const std::string& path, const Assimp::Importer& importer) {
  const std::string ext = lower_ext(path);
  if (const std::string problem = gltf_problem(path, ext); !problem.empty())
    throw Error(path + ": cannot read the model: " + problem);
  const std::string why = importer.GetErrorString();
  if (why.find("No meshes") != std::string::npos || why.find("no faces") != std::string::npos ||
      why.find("mNumMeshes is 0") != std::string::npos) {
    throw Error(path + ": the model has no triangles to render (" + why + ")");
  }
  if (!why.empty()) throw Error(path + ": cannot read the model: " + why);
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  const bool known = !ext.empty() && importer.IsExtensionSupported(ext);
  throw Error(path + ": cannot read the model (the importer gave no reason; tried " +
              (known ? "the importer for '" + ext + "' files"
                     : std::string("every importer by content, as '") + ext +
                           "' is not an extension assimp knows") +
              " on " + std::to_string(size) + " bytes)");
}

// Whether the material's colour texture is box-projected (assimp's UV
// generation leaves that mapping out).
bool box_mapped(const aiMaterial* material) {
  int mapping = aiTextureMapping_UV;
  for (aiTextureType t : {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE}) {
    if (material->Get(AI_MATKEY_MAPPING(t, 0), mapping) == AI_SUCCESS) {
      return mapping == aiTextureMapping_BOX;
    }
  }
  return false;
}

// The file's up axis from its metadata (FBX and others set "UpAxis"), or
// `override` ("y" or "z") when given.
UpAxis up_axis_of(const aiScene* s, const std::string& override_up) {
  if (override_up == "y") return {1, 1};
  if (override_up == "z") return {2, 1};
  UpAxis up;
  if (!s->mMetaData) return up;
  int axis = 1, sign = 1;
  if (s->mMetaData->Get("UpAxis", axis) && axis >= 0 && axis <= 2) up.axis = axis;
  if (s->mMetaData->Get("UpAxisSign", sign)) up.sign = sign < 0 ? -1 : 1;
  return up;
}

// One turn around `centre` every 24 s at `distance`, from `start`.
CameraPath orbit(glm::dvec3 centre, double distance, OrbitStart start, double fov) {
  CameraPath p;
  p.loop = true;
  const int n = 8;
  const double r = distance * std::cos(start.elevation), h = distance * std::sin(start.elevation);
  for (int i = 0; i <= n; ++i) {
    const double a = start.azimuth + 2.0 * 3.14159265358979 * i / n;
    p.keys.push_back(
        {24.0 * i / n, centre + glm::dvec3(r * std::sin(a), h, r * std::cos(a)), centre, fov});
  }
  return p;
}

// The file read and repaired (assimp's validation refuses what some
// importers leave behind), then post-processed; `box` says which materials
// are box-projected (seen before UV generation rewrites the mappings), and
// `dropped` counts the vertices dropped as inf or NaN.
const aiScene* read_model(Assimp::Importer& importer, const std::string& path,
                          std::vector<char>& box, size_t& dropped) {
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* s = importer.ReadFile(path, 0);
  if (!s || !s->mRootNode) import_failed(path, importer);
  const SceneRepair repair = repair_scene(const_cast<aiScene*>(s));
  dropped = repair.non_finite_vertices;
  if (dropped > 0 && repair.faces_left == 0) {
    throw Error(path + ": the model has no finite vertices to render (all " +
                std::to_string(dropped) + " vertices of its faces are inf or NaN)");
  }
  if (repair.meshes_left == 0) {
    throw Error(path + ": the model has no triangles to render (" +
                (repair.empty_meshes == 0 ? std::string("the file holds no meshes")
                 : repair.bad_faces == 0
                     ? "its meshes have no faces: points only"
                     : "none of its faces has valid vertex indices (" +
                           std::to_string(repair.bad_faces) + " out of range or missing)") +
                ")");
  }
  if (repair.bad_faces > 0) {
    warn(path + ": " + std::to_string(repair.bad_faces) +
         " faces without vertex indices or with indices out of range dropped");
  }
  box.assign(s->mNumMaterials, 0);
  for (unsigned i = 0; i < s->mNumMaterials; ++i) box[i] = box_mapped(s->mMaterials[i]);
  s = importer.ApplyPostProcessing(
      aiProcess_Triangulate | aiProcess_GenSmoothNormals | aiProcess_JoinIdenticalVertices |
      aiProcess_PreTransformVertices | aiProcess_SortByPType | aiProcess_GenUVCoords |
      aiProcess_TransformUVCoords | aiProcess_ValidateDataStructure);
  if (!s || (s->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !s->mRootNode) {
    import_failed(path, importer);
  }
  return s;
}

// One assimp mesh's triangles as MeshData (empty when none is left).
MeshData mesh_data(const aiMesh* am, const std::vector<char>& box, UpAxis up, size_t& dropped) {
  MeshData d;
  d.vertices.resize(am->mNumVertices);
  for (unsigned v = 0; v < am->mNumVertices; ++v) {
    Vertex& x = d.vertices[v];
    x.px = am->mVertices[v].x, x.py = am->mVertices[v].y, x.pz = am->mVertices[v].z;
    if (am->mNormals)
      x.nx = am->mNormals[v].x, x.ny = am->mNormals[v].y, x.nz = am->mNormals[v].z;
    else
      x.nx = x.ny = x.nz = 0;  // repaired below
    if (am->mTextureCoords[0])
      x.u = am->mTextureCoords[0][v].x, x.v = am->mTextureCoords[0][v].y;
    else
      x.u = x.v = 0;
    if (!std::isfinite(x.u) || !std::isfinite(x.v)) x.u = x.v = 0;
  }
  for (unsigned f = 0; f < am->mNumFaces; ++f) {
    if (am->mFaces[f].mNumIndices != 3) continue;
    for (int k = 0; k < 3; ++k) d.indices.push_back(am->mFaces[f].mIndices[k]);
  }
  dropped += drop_non_finite(d);  // e.g. from a node transform with inf
  if (d.indices.empty()) return d;
  repair_normals(d);  // a file without normals is ordinary: no warning
  if (am->mMaterialIndex < box.size() && box[am->mMaterialIndex] &&
      std::all_of(d.vertices.begin(), d.vertices.end(),
                  [](const Vertex& x) { return x.u == 0.0f && x.v == 0.0f; })) {
    box_uvs(d);  // assimp leaves them zero
  }
  make_y_up(d, up);
  return d;
}

// Every mesh's triangles with its material index; refuses a model with
// nothing left to render.
std::vector<std::pair<MeshData, unsigned>> mesh_parts(const aiScene* s, const std::string& path,
                                                      const std::vector<char>& box, UpAxis up,
                                                      size_t& dropped, ShapeStats& shape) {
  std::vector<std::pair<MeshData, unsigned>> parts;
  for (unsigned mi = 0; mi < s->mNumMeshes; ++mi) {
    const aiMesh* am = s->mMeshes[mi];
    if (!(am->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) || am->mNumFaces == 0) continue;
    MeshData d = mesh_data(am, box, up, dropped);
    if (d.indices.empty()) continue;
    shape.add(d);
    parts.emplace_back(std::move(d), am->mMaterialIndex);
  }
  if (parts.empty()) {
    throw Error(path + (dropped > 0 ? ": the model has no triangles left without its " +
                                          std::to_string(dropped) + " inf or NaN vertices"
                                    : ": the model has no triangles"));
  }
  double area = 0.0;
  size_t triangles = 0;
  for (const auto& part : parts) {
    area += surface_area(part.first);
    triangles += part.first.indices.size() / 3;
  }
  if (!(area > 0.0)) {
    throw Error(path + ": every one of its " + std::to_string(triangles) +
                " triangles has zero area (collinear or coincident vertices): nothing to render");
  }
  if (dropped > 0) {
    warn(path + ": " + std::to_string(dropped) +
         " vertices with an inf or NaN coordinate dropped, with the triangles that use them");
  }
  return parts;
}

class AssimpScene final : public MeshSceneBase {
 public:
  AssimpScene(const std::string& path, const SceneOptions& o)
      : MeshSceneBase(fs::path(path).filename().string(), "mesh file " + path, CameraPath{}) {
    if (!o.up.empty() && o.up != "y" && o.up != "z") {
      throw Error("up axis '" + o.up + "': expected y or z");
    }
    check_model_file(path);
    check_model_memory(path, o.model_memory_limit);
    Assimp::Importer importer;
    std::vector<char> box;
    size_t dropped = 0;
    const aiScene* s = read_model(importer, path, box, dropped);
    ShapeStats shape;
    auto parts = mesh_parts(s, path, box, up_axis_of(s, o.up), dropped, shape);
    for (auto& [d, material_index] : parts) {
      meshes_.push_back(upload_mesh(d, 3));
      materials_.push_back(material(s, material_index, path));
      full_triangles_ += d.indices.size() / 3;
    }
    frame_and_light(shape, o.camera_path);
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
  // Framed automatically: an orbit that keeps the bounding sphere in view,
  // starting from above the model's dominant plane when it is flat (or
  // `camera_path`); six lights around it.
  void frame_and_light(const ShapeStats& shape, const std::string& camera_path) {
    const glm::vec3 lo = shape.lo(), hi = shape.hi();
    const glm::vec3 centre = 0.5f * (lo + hi);
    scene_radius_ = std::max(1e-4f, 0.5f * glm::length(hi - lo));
    const double fov = 45.0;
    const double dist = scene_radius_ / std::sin(0.5 * fov * 3.14159265358979 / 180.0) * 1.1;
    camera_ = camera_path.empty()
                  ? orbit(glm::dvec3(centre), dist, default_orbit_start(shape.plane_normal()), fov)
                  : CameraPath::load(camera_path);
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
    if (am->GetTexture(aiTextureType_BASE_COLOR, 0, &tex) != AI_SUCCESS &&
        am->GetTexture(aiTextureType_DIFFUSE, 0, &tex) != AI_SUCCESS) {
      return m;
    }
    const std::string name = tex.C_Str();
    if (trim_texture_name(name).empty()) return m;  // an empty name: no texture
    auto it = textures_.find(name);
    if (it == textures_.end()) {
      std::optional<gpu::Texture> t;
      try {
        t = texture_from_image(load_texture(s, name, path));
      } catch (const Error& e) {
        aiString material_name;
        am->Get(AI_MATKEY_NAME, material_name);
        warn(path + ": material '" + material_name.C_Str() + "': texture '" + name +
             "' cannot be used (" + e.what() + "); the material's base colour is used instead");
      }
      it = textures_.emplace(name, std::move(t)).first;
    }
    if (it->second) m.texture = &*it->second;
    return m;
  }

  // The image of texture `name`: embedded ("*0" in glTF/GLB, or by file name)
  // or a file found as find_texture() describes.
  static Image load_texture(const aiScene* s, const std::string& name, const std::string& path) {
    if (const aiTexture* emb = s->GetEmbeddedTexture(name.c_str())) {
      return decode_embedded(emb, path);
    }
    if (!name.empty() && name[0] == '*') {
      throw Error("the embedded texture " + name + " is not in the file");
    }
    std::string tried;
    const auto file = find_texture(fs::path(path).parent_path(), name, tried);
    if (!file) throw Error("not found; looked for " + tried);
    return read_image(file->string());
  }

  std::vector<GpuMesh> meshes_;
  std::vector<Material> materials_;
  std::map<std::string, std::optional<gpu::Texture>> textures_;  // empty: unusable
  glm::vec4 lights_[6];
  glm::vec3 light_colors_[6];
  glm::vec3 centre_{0.0f};
};

}  // namespace

std::unique_ptr<Scene> make_mesh_file(const std::string& path, const SceneOptions& options) {
  return std::make_unique<AssimpScene>(path, options);
}

}  // namespace foveate::detail
