#pragma once
// What the mesh scenes share: per-view culling and LOD choice, and the
// deferred prepass into the G-buffer (gbuffer.hpp) of the meshes a subclass
// uploaded (gpu_mesh.hpp). A MeshSceneBase subclass supplies its draw items
// each frame and its shading function.
#include <array>
#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <vector>

#include "foveate/gpu/shader.hpp"
#include "foveate/scenes/camera_path.hpp"
#include "foveate/scenes/scene.hpp"
#include "gbuffer.hpp"
#include "gpu_mesh.hpp"

namespace foveate::detail {

struct Material {
  glm::vec3 base_color{0.8f};
  float gloss = 0.2f;  ///< 0 diffuse .. 1 mirror-like
  float id = 0.0f;     ///< material id the shading function understands
  const gpu::Texture* texture = nullptr;
};

struct DrawItem {
  const GpuMesh* mesh = nullptr;
  glm::mat4 model{1.0f};
  Material material;
  int lod = 0;  ///< index into mesh->lods (0 = full detail)
  /// When set, the LOD is chosen by projected geometric error and `lod` is
  /// only a floor (the result is never finer than `lod`).
  bool automatic = true;
};

class MeshSceneBase : public Scene {
 public:
  MeshSceneBase(std::string name, std::string description, CameraPath camera);

  [[nodiscard]] SceneInfo info() const override;
  void update(const FrameInput& frame) override;
  void prepass_begin(const View& view) override;
  void prepass_draw(const View& view, int lod) override;
  void prepass_end() override;
  void bind(const gpu::Program& program, const View& view, gpu::Samplers& samplers) override;
  [[nodiscard]] std::vector<Vec2d> object_positions() const override;
  [[nodiscard]] std::optional<std::array<float, 16>> view_projection() const override;
  /// The camera and the frame size (the sky's slow drift is left to the
  /// techniques' per-pixel change detection).
  [[nodiscard]] std::optional<std::uint64_t> image_key() const override;

 protected:
  /// The items to draw for `view` with `lod` (0..2, or -1 = automatic).
  virtual std::vector<DrawItem> items(const View& view, int lod) = 0;
  /// Binds the subclass's own uniforms for shading.
  virtual void bind_extra(const gpu::Program&) {}
  /// Object centres (world) for object_positions(), any order.
  [[nodiscard]] virtual std::vector<glm::vec3> object_centres() const { return {}; }

  /// Focal length of the full frame in pixels (for screen-space LOD).
  [[nodiscard]] double camera_focal_px() const;
  /// The camera the frame is rendered from: pose_, or moved to the eye of a
  /// stereo view (FrameInput::eye) along the camera's right vector.
  [[nodiscard]] CameraPose eye_pose() const;
  /// Whether a sphere is inside the view's sub-frustum.
  [[nodiscard]] bool visible(const glm::mat4& view_proj, glm::vec3 centre, float radius) const;

  std::string name_, description_;
  CameraPath camera_;
  CameraPose pose_{};
  FrameInput frame_;
  float scene_radius_ = 10.0f;
  size_t full_triangles_ = 0;
  bool has_lods_ = true;
  glm::mat4 view_proj_{1.0f};  ///< of the last prepass view

 private:
  [[nodiscard]] glm::mat4 view_projection(const View& view) const;
  /// Distance from the eye to the near clipping plane (world units).
  [[nodiscard]] double near_plane() const;
  /// The G-buffer for a target size and sample count: one per size kept for
  /// the scene's life (techniques render at several sizes; recreating 66 MB
  /// at 1080p whenever the size changes would be charged to the frame).
  GBuffer& gbuffer_for(int width, int height, int samples);
  std::vector<std::unique_ptr<GBuffer>> gbuffers_;  ///< most recently used last
  GBuffer* gbuffer_ = nullptr;                      ///< of the last prepass
  gpu::Program prepass_program_;                    ///< materials without a texture
  gpu::Program prepass_textured_;                   ///< with an albedo texture
  View last_view_;
  gpu::FramebufferBinding outer_;  ///< what prepass_begin found
};

}  // namespace foveate::detail
