#include "mesh_scene_base.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include "foveate/core/error.hpp"
#include "foveate/gpu/profiler.hpp"
#include "foveate_embedded/scenes_shaders.hpp"

namespace foveate::detail {

MeshSceneBase::MeshSceneBase(std::string name, std::string description, CameraPath camera)
    : name_(std::move(name)), description_(std::move(description)), camera_(std::move(camera)) {
  gpu::ShaderCompiler c({embedded::scenes_shaders()});
  prepass_program_ = c.build("gbuffer.vert", "gbuffer.frag");
  prepass_textured_ =
      c.build({{GL_VERTEX_SHADER, {{"gbuffer.vert", {}}}},
               {GL_FRAGMENT_SHADER,
                {{"textured", "#define FOVEATE_ALBEDO_TEXTURE 1\n"}, {"gbuffer.frag", {}}}}},
              "gbuffer.frag (textured)");
}

SceneInfo MeshSceneBase::info() const {
  return {name_, description_, true, has_lods_, full_triangles_};
}

void MeshSceneBase::update(const FrameInput& frame) {
  frame_ = frame;
  pose_ = camera_.at(frame.time_s);
}

std::optional<std::uint64_t> MeshSceneBase::image_key() const {
  const double v[] = {pose_.position.x, pose_.position.y,     pose_.position.z,
                      pose_.target.x,   pose_.target.y,       pose_.target.z,
                      pose_.fov_deg,    double(frame_.width), double(frame_.height)};
  const std::uint64_t h = hash_bytes(1469598103934665603ull, v, sizeof v);
  if (!frame_.eye) return h;
  const EyeView& e = *frame_.eye;
  const double w[] = {e.offset_m, e.frustum.left, e.frustum.right, e.frustum.down, e.frustum.up};
  return hash_bytes(h, w, sizeof w);
}

double MeshSceneBase::camera_focal_px() const {
  if (frame_.eye) return frame_.height / (frame_.eye->frustum.up - frame_.eye->frustum.down);
  return 0.5 * frame_.height / std::tan(0.5 * pose_.fov_deg * std::numbers::pi / 180.0);
}

CameraPose MeshSceneBase::eye_pose() const {
  if (!frame_.eye || frame_.eye->offset_m == 0.0) return pose_;
  const glm::dvec3 forward = pose_.target - pose_.position;
  const glm::dvec3 right = glm::normalize(glm::cross(forward, camera_up(forward)));
  CameraPose p = pose_;
  p.position += right * frame_.eye->offset_m;
  p.target += right * frame_.eye->offset_m;  // parallel eyes, as a headset's views
  return p;
}

namespace {

// An item's bounding sphere in world space and the eye's distance to its
// centre, computed once per draw: the order, the culling, the LOD and the
// back faces all ask for them.
struct WorldBounds {
  glm::vec3 centre;
  float scale;     // the model matrix's (uniform) scale
  float radius;    // the mesh's bounding radius times it
  float distance;  // from the eye to the centre
};

WorldBounds world_bounds(const DrawItem& item, glm::vec3 eye) {
  const GpuMesh& m = *item.mesh;
  WorldBounds b;
  b.centre = glm::vec3(item.model * glm::vec4(m.centre, 1.0f));
  b.scale = glm::length(glm::vec3(item.model[0]));
  b.radius = m.radius * b.scale;
  b.distance = glm::length(b.centre - eye);
  return b;
}

// The order to draw items with `bounds` in: nearest first, so that the depth
// test rejects what later draws would cover before it is shaded (llvmpipe
// tests depth before the fragment shader, a GPU in its early-Z hardware); a
// mesh whose bounds hold the eye (terrain, a room) last, as it lies mostly
// behind the rest. The order changes no visible fragment: the depth test
// keeps the nearest either way (ties aside).
std::vector<size_t> draw_order(const std::vector<WorldBounds>& bounds) {
  std::vector<std::pair<float, size_t>> keyed;
  keyed.reserve(bounds.size());
  for (size_t i = 0; i < bounds.size(); ++i) {
    const WorldBounds& b = bounds[i];
    keyed.emplace_back(
        b.distance <= b.radius ? std::numeric_limits<float>::max() : b.distance - b.radius, i);
  }
  std::stable_sort(keyed.begin(), keyed.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<size_t> out;
  out.reserve(keyed.size());
  for (const auto& k : keyed) out.push_back(k.second);
  return out;
}

// Culls the back faces of a closed mesh seen from outside it (GpuMesh::outside);
// a mirroring model matrix turns its winding over. Anything else is drawn
// two-sided.
void cull_back_faces(const GpuMesh& m, const glm::mat4& model, bool seen_from_outside) {
  if (m.outside == GpuMesh::Winding::unknown || !seen_from_outside) {
    glDisable(GL_CULL_FACE);
    return;
  }
  const bool ccw =
      (m.outside == GpuMesh::Winding::ccw) == (glm::determinant(glm::mat3(model)) > 0.0f);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glFrontFace(ccw ? GL_CCW : GL_CW);
}

}  // namespace

double MeshSceneBase::near_plane() const { return std::max(0.01, scene_radius_ * 0.002); }

glm::mat4 MeshSceneBase::view_projection(const View& v) const {
  const double n = near_plane(), f = scene_radius_ * 20.0;
  if (frame_.eye) {
    // The eye's off-axis frustum: x in [0, width] spans tangents left..right,
    // y (origin bottom) down..up.
    const FrustumTangents& t = frame_.eye->frustum;
    auto sx = [&](double x) { return n * (t.left + (t.right - t.left) * x / frame_.width); };
    auto sy = [&](double y) { return n * (t.down + (t.up - t.down) * y / frame_.height); };
    return glm::mat4(glm::frustum(sx(v.x0), sx(v.x1), sy(v.y0), sy(v.y1), n, f) *
                     view_matrix(eye_pose()));
  }
  return glm::mat4(
      projection_for_rect(pose_, frame_.width, frame_.height, v.x0, v.y0, v.x1, v.y1, n, f) *
      view_matrix(pose_));
}

bool MeshSceneBase::visible(const glm::mat4& m, glm::vec3 c, float r) const {
  // Gribb-Hartmann planes of the view-projection matrix. With a negative r:
  // whether the sphere of radius -r lies wholly inside the frustum.
  const glm::mat4 t = glm::transpose(m);
  const glm::vec4 planes[6] = {t[3] + t[0], t[3] - t[0], t[3] + t[1],
                               t[3] - t[1], t[3] + t[2], t[3] - t[2]};
  for (const glm::vec4& p : planes) {
    const float len = glm::length(glm::vec3(p));
    if (glm::dot(glm::vec3(p), c) + p.w < -r * len) return false;
  }
  return true;
}

GBuffer& MeshSceneBase::gbuffer_for(int width, int height, int samples) {
  // At most this many sizes are kept (layered's layers, inset's two sizes,
  // native: a bench of every technique stays well under it).
  constexpr size_t kKept = 12;
  for (auto it = gbuffers_.begin(); it != gbuffers_.end(); ++it) {
    GBuffer& g = **it;
    if (g.width == width && g.height == height && g.samples == samples) {
      std::rotate(it, it + 1, gbuffers_.end());  // most recently used last
      return *gbuffers_.back();
    }
  }
  if (gbuffers_.size() >= kKept) gbuffers_.erase(gbuffers_.begin());
  gbuffers_.push_back(std::make_unique<GBuffer>());
  gbuffers_.back()->ensure(width, height, samples);
  return *gbuffers_.back();
}

void MeshSceneBase::prepass_begin(const View& view) {
  // Timed as one pass up to prepass_end (lodmask's masks included).
  if (gpu::PassProfiler* prof = gpu::PassProfiler::current()) prof->begin("gbuffer");
  last_view_ = view;
  outer_ = gpu::FramebufferBinding::current();
  view_proj_ = view_projection(view);
  gbuffer_ = &gbuffer_for(view.target_width, view.target_height, std::max(1, view.samples));
  gbuffer_->fbo.bind();
  glViewport(0, 0, view.target_width, view.target_height);
  // No scissor, stencil or blending left by the technique's last pass: the
  // clears and the draws honour them (a scissored pass before a prepass
  // left the G-buffer uncleared outside it). A caller that masks geometry
  // (lodmask) sets its stencil after this.
  gpu::apply(gpu::PassState{});
  gpu::open_write_masks();              // clears honour them
  const GLuint zero[4] = {0, 0, 0, 0};  // coverage 0: no surface
  glClearNamedFramebufferuiv(gbuffer_->fbo.id(), GL_COLOR, 0, zero);
  glClearNamedFramebufferfi(gbuffer_->fbo.id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
}

void MeshSceneBase::prepass_draw(const View& view, int lod) {
  // Depth test and writes, colour on; the stencil test is the caller's
  // (lodmask draws under stencil masks). Back faces are culled only for
  // meshes that declare themselves closed (cull_back_faces): files disagree
  // on winding.
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_BLEND);
  const double focal = camera_focal_px();
  const glm::vec3 eye(eye_pose().position);
  for (const gpu::Program* q : {&prepass_textured_, &prepass_program_}) {
    q->use();
    q->set_mat4("u_view_proj", glm::value_ptr(view_proj_));
    q->set("u_eye", eye.x, eye.y, eye.z);
  }
  prepass_textured_.use();
  prepass_textured_.set("u_albedo_tex", 0);
  const gpu::Program* in_use = &prepass_textured_;
  // A sub-rectangle of the prepass's view culls to its own frustum (the
  // geometry is still drawn with the prepass's projection).
  const bool same = view.x0 == last_view_.x0 && view.y0 == last_view_.y0 &&
                    view.x1 == last_view_.x1 && view.y1 == last_view_.y1;
  const glm::mat4 cull = same ? view_proj_ : view_projection(view);
  // The frustum of the skip rectangle: objects wholly inside it are left out.
  const bool skips = view.skip_x1 > view.skip_x0 && view.skip_y1 > view.skip_y0;
  glm::mat4 skip_frustum(1.0f);
  if (skips) {
    View s = view;
    s.x0 = view.skip_x0;
    s.y0 = view.skip_y0;
    s.x1 = view.skip_x1;
    s.y1 = view.skip_y1;
    skip_frustum = view_projection(s);
  }
  // The items the view shows (culled before they are ordered), nearest first.
  std::vector<DrawItem> drawn;
  std::vector<WorldBounds> bounds;
  for (DrawItem& item : items(view, lod)) {
    const WorldBounds b = world_bounds(item, eye);
    if (!visible(cull, b.centre, b.radius)) continue;
    if (skips && visible(skip_frustum, b.centre, -b.radius)) continue;
    drawn.push_back(std::move(item));
    bounds.push_back(b);
  }
  for (size_t index : draw_order(bounds)) {
    DrawItem& item = drawn[index];
    const GpuMesh& m = *item.mesh;
    const WorldBounds& b = bounds[index];
    int l = item.lod;
    if (item.automatic) {
      // The coarsest LOD whose geometric error projects below one target
      // pixel; the requested level only ever makes it coarser.
      const double dist = std::max(1e-3, double(b.distance) - b.radius);
      int a = 0;
      for (int k = static_cast<int>(m.lods.size()) - 1; k > 0; --k) {
        if (m.lods[static_cast<size_t>(k)].error * b.scale * focal / dist <= view.pixel_scale) {
          a = k;
          break;
        }
      }
      l = std::max(a, item.lod);
    }
    const GpuMesh::Lod& lv =
        m.lods[static_cast<size_t>(std::min<int>(l, static_cast<int>(m.lods.size()) - 1))];
    const glm::mat3 nm = glm::transpose(glm::inverse(glm::mat3(item.model)));
    // Seen from within its bounds (as near its surface as the near plane's
    // corners, within twice its distance of the eye), a mesh shows both sides.
    cull_back_faces(m, item.model, b.distance > b.radius + 2.0f * float(near_plane()));
    const gpu::Program& p = item.material.texture ? prepass_textured_ : prepass_program_;
    if (in_use != &p) {
      p.use();
      in_use = &p;
    }
    p.set_mat4("u_model", glm::value_ptr(item.model));
    p.set_mat3("u_normal_matrix", glm::value_ptr(nm));
    p.set("u_base_color", item.material.base_color.r, item.material.base_color.g,
          item.material.base_color.b, 1.0f);
    p.set("u_gloss", item.material.gloss);
    p.set("u_material", item.material.id);
    if (item.material.texture) item.material.texture->bind(0);
    glBindVertexArray(m.vao.id());
    glDrawElements(
        GL_TRIANGLES, lv.count, GL_UNSIGNED_INT,
        reinterpret_cast<const void*>(static_cast<uintptr_t>(lv.first) * sizeof(unsigned)));
  }
}

void MeshSceneBase::prepass_end() {
  glDisable(GL_CULL_FACE);
  glFrontFace(GL_CCW);
  glDisable(GL_DEPTH_TEST);
  outer_.restore();
  if (gpu::PassProfiler* prof = gpu::PassProfiler::current()) prof->end();
}

void MeshSceneBase::bind(const gpu::Program& p, const View& v, gpu::Samplers& samplers) {
  if (v.x0 != last_view_.x0 || v.y0 != last_view_.y0 || v.x1 != last_view_.x1 ||
      v.y1 != last_view_.y1 || v.target_width != last_view_.target_width ||
      v.target_height != last_view_.target_height || gbuffer_ == nullptr) {
    throw Error("scene '" + name_ +
                "': shading bound for a view other than the last prepass's (a technique must run "
                "the prepass for the view it shades)");
  }
  // Each program uses the part of the scene's shading it calls (temporal
  // reprojection only the world position): the rest may be optimised away.
  p.allow_missing(
      {"u_g_surface", "u_g_rect", "u_screen", "u_inv_view_proj", "u_cam_pos", "u_time"});
  samplers.bind(p, "u_g_surface", gbuffer_->surface);
  p.set("u_g_rect", float(v.x0), float(v.y0), float(v.x1 - v.x0), float(v.y1 - v.y0));
  p.set("u_screen", float(frame_.width), float(frame_.height));
  const glm::mat4 full = view_projection(View::full(frame_.width, frame_.height));
  const glm::mat4 inv = glm::inverse(full);
  p.set_mat4("u_inv_view_proj", glm::value_ptr(inv));
  const CameraPose cam = eye_pose();
  p.set("u_cam_pos", float(cam.position.x), float(cam.position.y), float(cam.position.z));
  p.set("u_time", float(frame_.time_s));
  bind_extra(p);
}

std::optional<std::array<float, 16>> MeshSceneBase::view_projection() const {
  const glm::mat4 m = view_projection(View::full(frame_.width, frame_.height));
  std::array<float, 16> out{};
  std::copy_n(glm::value_ptr(m), 16, out.begin());
  return out;
}

std::vector<Vec2d> MeshSceneBase::object_positions() const {
  glm::mat4 full = glm::mat4(projection_for_rect(pose_, frame_.width, frame_.height, 0, 0,
                                                 frame_.width, frame_.height, 0.1, 1000.0) *
                             view_matrix(pose_));
  if (frame_.eye) {
    // A stereo pair: as seen from midway between the eyes (the camera's own
    // position), the axis at the image centre, with the eye's focal length.
    const double hx = 0.5 * frame_.width / camera_focal_px() * 0.1;
    const double hy = 0.5 * frame_.height / camera_focal_px() * 0.1;
    full = glm::mat4(glm::frustum(-hx, hx, -hy, hy, 0.1, 1000.0) * view_matrix(pose_));
  }
  std::vector<std::pair<float, Vec2d>> found;
  for (const glm::vec3& c : object_centres()) {
    const glm::vec4 clip = full * glm::vec4(c, 1.0f);
    if (clip.w <= 0.0f) continue;
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    if (std::abs(ndc.x) > 1.0f || std::abs(ndc.y) > 1.0f) continue;
    found.push_back(
        {clip.w, {(ndc.x * 0.5 + 0.5) * frame_.width, (0.5 - ndc.y * 0.5) * frame_.height}});
  }
  std::sort(found.begin(), found.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Vec2d> out;
  for (const auto& f : found) out.push_back(f.second);
  return out;
}

}  // namespace foveate::detail
