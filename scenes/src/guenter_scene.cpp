// The test scene of Guenter et al., "Foveated 3D Graphics" (2012), sections 5
// and 6: a terrain of about 20k triangles with procedural shading, a 20 x 20
// grid of parametric objects with procedural materials from diffuse to
// glossy, an environment map, and continuous LOD by camera distance.
#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "factories.hpp"
#include "guenter_shapes.hpp"
#include "mesh_scene_base.hpp"

namespace foveate::detail {

namespace {

constexpr int kGrid = 20;         // objects per side
constexpr float kSpacing = 4.5f;  // world units between objects
constexpr float kTerrainHalf = 70.0f;
// Continuous LOD (section 6): tessellation goes from MaxTriCount to
// MinTriCount as the squared distance goes from MinDistSq to MaxDistSq. The
// paper used 20,000 triangles per object on a GTX 580; a software rasterizer
// pays per pixel more than per triangle, so 2,048 keeps the same curve at a
// workable cost.
constexpr float kMaxTriCount = 2048.0f, kMinTriCount = 32.0f;
constexpr float kMinDistSq = 16.0f, kMaxDistSq = 3600.0f;
// Tessellations available, finest first (n x n parameter grid, 2 n^2
// triangles); the discrete LODs 0, 1, 2 are 32, 10 and 4 (2048, 200 and 32
// triangles: about 10 % and 1.6 %).
constexpr int kLevels[] = {32, 24, 20, 16, 12, 10, 8, 6, 4};
constexpr int kDiscrete[3] = {0, 5, 8};  // indices into kLevels

float terrain_height(float x, float z) {
  return 2.2f * std::sin(0.045f * x) * std::cos(0.06f * z) +
         1.2f * std::sin(0.11f * x + 0.7f) * std::sin(0.09f * z) +
         0.35f * std::sin(0.31f * x + 0.2f * z);
}

MeshData terrain(int cells) {
  MeshData m;
  const float step = 2.0f * kTerrainHalf / float(cells);
  for (int j = 0; j <= cells; ++j) {
    for (int i = 0; i <= cells; ++i) {
      const float x = -kTerrainHalf + float(i) * step, z = -kTerrainHalf + float(j) * step;
      const float e = 0.05f;
      const float hx = (terrain_height(x + e, z) - terrain_height(x - e, z)) / (2 * e);
      const float hz = (terrain_height(x, z + e) - terrain_height(x, z - e)) / (2 * e);
      const glm::vec3 n = glm::normalize(glm::vec3(-hx, 1.0f, -hz));
      m.vertices.push_back({x, terrain_height(x, z), z, n.x, n.y, n.z, x * 0.1f, z * 0.1f});
    }
  }
  grid_triangles(m, cells);
  return m;
}

CameraPath fly_through() {
  CameraPath p;
  p.loop = true;
  const float e = 0.5f * kSpacing * (kGrid - 1);
  p.keys = {{0.0, {-e - 6, 7.0, -e - 6}, {0, 2.0, 0}, 55.0},
            {10.0, {e + 6, 6.0, -e - 2}, {0, 2.5, -4}, 55.0},
            {20.0, {e + 4, 8.0, e + 4}, {-4, 2.0, 0}, 55.0},
            {30.0, {-e, 5.0, e + 6}, {2, 2.5, -2}, 55.0},
            {40.0, {-e - 6, 7.0, -e - 6}, {0, 2.0, 0}, 55.0}};
  return p;
}

class GuenterScene final : public MeshSceneBase {
 public:
  GuenterScene(const SceneOptions& o)
      : MeshSceneBase(
            "guenter",
            "the test scene of Guenter et al.: 20k-triangle terrain, 20x20 parametric objects, "
            "procedural materials, environment map, continuous LOD",
            o.camera_path.empty() ? fly_through() : CameraPath::load(o.camera_path)) {
    terrain_ = upload_levels({terrain(99), terrain(31), terrain(9)});
    for (int shape = 0; shape < kGuenterShapes; ++shape) {
      std::vector<MeshData> levels;
      for (int n : kLevels) levels.push_back(guenter_shape(shape, n));
      shapes_[shape] = upload_levels(levels);
      shapes_[shape].outside = guenter_shape_outside(shape);
    }
    const float e = 0.5f * kSpacing * (kGrid - 1);
    for (int j = 0; j < kGrid; ++j) {
      for (int i = 0; i < kGrid; ++i) {
        Object obj;
        const float x = -e + float(i) * kSpacing, z = -e + float(j) * kSpacing;
        obj.centre = glm::vec3(x, terrain_height(x, z) + 2.2f, z);
        obj.shape = (i + 3 * j) % 4;
        obj.material = 2.0f + float((i * 7 + j * 3) % 7);
        obj.gloss = std::fmod(0.15f * float(i + j), 1.0f);
        obj.colour = glm::vec3(0.5f + 0.5f * std::sin(0.7f * float(i)),
                               0.5f + 0.5f * std::sin(0.9f * float(j) + 1.0f),
                               0.5f + 0.5f * std::sin(0.5f * float(i + j) + 2.0f));
        obj.spin = 0.3f + 0.05f * float((i * j) % 7);
        objects_.push_back(obj);
      }
    }
    scene_radius_ = kTerrainHalf;
    full_triangles_ = terrain_.triangles(0) + objects_.size() * 2 * 32 * 32;
  }

  std::string shade_key() const override { return "builtin:guenter"; }
  std::vector<gpu::StageSource::Piece> shade_source() const override {
    return {{"guenter_shade.glsl", {}}};
  }

 protected:
  std::vector<DrawItem> items(const View& view, int lod) override {
    std::vector<DrawItem> out;
    Material tm;
    tm.base_color = glm::vec3(1.0f);
    tm.id = 1.0f;
    tm.gloss = 0.05f;
    out.push_back({&terrain_, glm::mat4(1.0f), tm, std::clamp(lod, 0, 2), false});
    const glm::vec3 eye(eye_pose().position);
    const float t = static_cast<float>(frame_.time_s);
    for (const Object& o : objects_) {
      glm::mat4 m = glm::translate(glm::mat4(1.0f), o.centre);
      m = glm::rotate(m, o.spin * t, glm::vec3(0.0f, 1.0f, 0.0f));
      // Continuous LOD by squared distance, coarsened by the view's pixel size:
      // an object seen at s times coarser sampling is tessellated as if it
      // were s times farther away. A requested discrete level (lodmask) only
      // ever makes it coarser.
      const float s = static_cast<float>(view.pixel_scale);
      const glm::vec3 d = o.centre - eye;
      const float dsq = glm::dot(d, d) * s * s;
      const float f = std::clamp((dsq - kMinDistSq) / (kMaxDistSq - kMinDistSq), 0.0f, 1.0f);
      const float tris = kMaxTriCount + (kMinTriCount - kMaxTriCount) * f;
      // The finest level that does not exceed the triangle budget.
      int level = 0;
      while (level + 1 < int(std::size(kLevels)) &&
             2.0f * float(kLevels[level] * kLevels[level]) > tris)
        ++level;
      if (lod > 0) level = std::max(level, kDiscrete[std::min(lod, 2)]);
      Material mat;
      mat.base_color = o.colour;
      mat.id = o.material;
      mat.gloss = o.gloss;
      out.push_back({&shapes_[o.shape], m, mat, level, false});
    }
    return out;
  }
  std::vector<glm::vec3> object_centres() const override {
    std::vector<glm::vec3> out;
    for (const Object& o : objects_) out.push_back(o.centre);
    return out;
  }

 private:
  struct Object {
    glm::vec3 centre{0.0f};
    int shape = 0;
    float material = 2.0f;
    float gloss = 0.2f;
    glm::vec3 colour{0.8f};
    float spin = 0.3f;
  };
  GpuMesh terrain_;
  GpuMesh shapes_[4];
  std::vector<Object> objects_;
};

}  // namespace

std::unique_ptr<Scene> make_guenter_scene(const SceneOptions& options) {
  return std::make_unique<GuenterScene>(options);
}

}  // namespace foveate::detail
