// layered's temporal passes: each update's jittered samples resolved with
// the layer's history (temporal.frag, or temporal_reproject.frag through the
// scene's camera and depth), and the world points of a layer that will be
// shown stale, to warp it by.
#include <algorithm>

#include "foveate/gpu/profiler.hpp"
#include "layered.hpp"

namespace foveate::tech::layered {

void Layered::accumulate(Scene& scene, LayerState& st, const View& jv,
                         const std::array<double, 4>& rect, int slots_i, int phase,
                         bool same_image) {
  const int next = 1 - st.latest;
  gpu::RenderTarget& out = st.display[static_cast<size_t>(next)];
  out.ensure(jv.target_width, jv.target_height, kDisplayFormat);
  if (!st.ring || st.ring.width() != jv.target_width || st.ring.height() != jv.target_height ||
      st.ring.layers() != slots_i) {
    st.ring =
        gpu::Texture::create_2d_array(GL_SRGB8_ALPHA8, jv.target_width, jv.target_height, slots_i);
  }
  const bool have_history = st.valid && st.temporal;
  const auto vp = scene.view_projection();
  const bool reproject = have_history && reproject_ && vp && st.has_view_proj;
  const auto& prev = have_history ? st.rect : rect;
  const auto set = [&](const gpu::Program& p, gpu::Samplers& samplers) {
    samplers.bind(p, "u_sample", st.spare.color());
    samplers.bind(
        p, "u_prev",
        have_history ? st.display[static_cast<size_t>(st.latest)].color() : st.spare.color());
    samplers.bind(p, "u_ring", st.ring);
    p.set("u_slot_count", slots_i);
    p.set("u_phase", phase);
    p.set("u_have_history", have_history ? 1 : 0);
    p.set("u_same_image", same_image ? 1 : 0);
    p.set("u_rect", float(rect[0]), float(rect[1]), float(rect[2]), float(rect[3]));
    p.set("u_prev_rect", float(prev[0]), float(prev[1]), float(prev[2]), float(prev[3]));
    // Without the scene's camera and depth the history is found at the
    // same screen position and trails the motion: it gets less weight.
    p.set("u_blend", float(1.0 - (reproject ? history_ : history_screen_)));
    if (reproject) {
      p.set_mat4("u_view_proj", vp->data());
      p.set_mat4("u_prev_view_proj", st.view_proj.data());
      p.set("u_frame_size", float(display_.width_px), float(display_.height_px));
    }
  };
  if (reproject) {
    kit_.scene_pass(scene, jv,
                    kit_.scene_program(scene, "layered/temporal_reproject.frag", jv.samples), out,
                    {}, set);
  } else {
    kit_.pass(kit_.fullscreen("layered/temporal.frag"), out, {}, set);
  }
  st.has_view_proj = vp.has_value();
  if (vp) st.view_proj = *vp;
  st.latest = next;
  const gpu::ProfileScope timed("copy");
  glCopyImageSubData(st.spare.color().id(), GL_TEXTURE_2D, 0, 0, 0, 0, st.ring.id(),
                     GL_TEXTURE_2D_ARRAY, 0, 0, 0, phase, jv.target_width, jv.target_height, 1);
}

void Layered::keep_positions(Scene& scene, LayerState& st, const View& jv,
                             const std::array<double, 4>& rect, bool will_be_stale) {
  const auto vp = scene.view_projection();
  st.has_positions = will_be_stale && reproject_ && vp.has_value();
  if (!st.has_positions) return;
  st.view_proj = *vp;
  st.has_view_proj = true;
  st.positions.ensure(jv.target_width, jv.target_height, GL_RGBA32F);
  kit_.scene_pass(scene, jv, kit_.scene_program(scene, "layered/positions.frag", jv.samples),
                  st.positions, {}, [&](const gpu::Program& p, gpu::Samplers& samplers) {
                    samplers.bind(p, "u_sample", st.positions.color());
                    p.set("u_rect", float(rect[0]), float(rect[1]), float(rect[2]), float(rect[3]));
                  });
}

}  // namespace foveate::tech::layered
