// layered's composite: stale layers warped to this frame's camera, then
// every layer put together into the target, each pixel reading only the
// layers that can show there.
#include <algorithm>

#include "foveate/gpu/profiler.hpp"
#include "layered.hpp"

namespace foveate::tech::layered {

std::array<const gpu::Texture*, kMaxLayers> Layered::warp_stale_layers(Scene& scene) {
  const int n = static_cast<int>(plan_.layers.size());
  const auto vp = scene.view_projection();
  // Layers shown stale (half rate) move with the camera: each is warped to
  // this frame at its own resolution before the composite reads it.
  std::array<const gpu::Texture*, kMaxLayers> source{};
  for (int i = 0; i < n; ++i) {
    LayerState& st = state_[static_cast<size_t>(i)];
    // A layer without temporal resolve (the native-rate inner one) is its
    // last render; the others their resolved display.
    const gpu::RenderTarget& shown =
        st.temporal ? st.display[static_cast<size_t>(st.latest)] : st.spare;
    source[static_cast<size_t>(i)] = &shown.color();
    if (st.updated || !st.has_positions || !vp) continue;
    st.warped.ensure(shown.width(), shown.height(), kDisplayFormat);
    kit_.pass(kit_.fullscreen("layered/warp.frag"), st.warped, {},
              [&](const gpu::Program& p, gpu::Samplers& samplers) {
                samplers.bind(p, "u_layer", shown.color());
                samplers.bind(p, "u_positions", st.positions.color());
                p.set("u_rect", float(st.rect[0]), float(st.rect[1]), float(st.rect[2]),
                      float(st.rect[3]));
                p.set_mat4("u_layer_view_proj", st.view_proj.data());
                p.set_mat4("u_view_proj", vp->data());
                p.set("u_frame_size", float(display_.width_px), float(display_.height_px));
              });
    source[static_cast<size_t>(i)] = &st.warped.color();
  }
  return source;
}

void Layered::composite(Scene& scene, const gpu::RenderTarget& target) {
  const int n = static_cast<int>(plan_.layers.size());
  const std::array<const gpu::Texture*, kMaxLayers> source = warp_stale_layers(scene);
  auto set = [&](const gpu::Program& prog, gpu::Samplers& samplers) {
    float rects[kMaxLayers * 4] = {}, centres[kMaxLayers * 2] = {}, radii[kMaxLayers] = {};
    static const char* names[kMaxLayers] = {"u_layers[0]", "u_layers[1]", "u_layers[2]",
                                            "u_layers[3]", "u_layers[4]", "u_layers[5]"};
    for (int i = 0; i < n; ++i) {
      const LayerState& st = state_[static_cast<size_t>(i)];
      samplers.bind(prog, names[i], *source[static_cast<size_t>(i)]);
      for (int k = 0; k < 4; ++k) rects[i * 4 + k] = float(st.rect[static_cast<size_t>(k)]);
      centres[i * 2] = float(st.centre.x);
      centres[i * 2 + 1] = float(st.centre.y);
      radii[i] = float(st.radius_px);
    }
    glProgramUniform4fv(prog.id(), prog.uniform("u_rects[0]"), n, rects);
    glProgramUniform2fv(prog.id(), prog.uniform("u_centres[0]"), n, centres);
    glProgramUniform1fv(prog.id(), prog.uniform("u_radii[0]"), n, radii);
    prog.set("u_count", n);
    prog.set("u_first", 0);
    prog.set("u_band", float(transition_));
  };
  if (!DepthRegions::usable(target)) {
    // A target without a colour texture (a window's framebuffer): one pass
    // over every pixel, reading every layer.
    kit_.pass(kit_.fullscreen("layered/composite.frag"), target, {}, set);
    return;
  }
  // The regions, innermost first: within the inner layer's radius only that
  // layer shows; the disc of layer k's blend band reads layers k..n-1;
  // outside every disc only the outer layer shows. Where one layer alone
  // shows, composite_one.frag reads it. A depth test keeps each pixel to the
  // first region that covers it (early, so llvmpipe skips the 4x4 blocks
  // already written).
  const gpu::ProfileScope timed("composite");
  const gpu::Program& blend = kit_.over_regions("layered/composite.frag");
  const gpu::Program& one = kit_.over_regions("layered/composite_one.frag");
  const auto only = [&](int k) -> const gpu::Program& {
    const LayerState& st = state_[static_cast<size_t>(k)];
    gpu::Samplers own;
    own.bind(one, "u_layer", *source[static_cast<size_t>(k)]);
    one.set("u_layer_rect", float(st.rect[0]), float(st.rect[1]), float(st.rect[2]),
            float(st.rect[3]));
    return one;
  };
  regions_.begin(target, n > 1 ? n + 1 : n);
  if (n > 1) regions_.disc(only(0), state_[0].centre, state_[0].radius_px - 1.0, true);
  gpu::Samplers samplers;
  set(blend, samplers);
  for (int k = 0; k + 1 < n; ++k) {
    blend.set("u_first", k);
    const LayerState& st = state_[static_cast<size_t>(k)];
    regions_.disc(blend, st.centre, st.radius_px * (1.0 + std::max(0.0, transition_)) + 1.0, false);
  }
  regions_.rest(only(n - 1));
}

}  // namespace foveate::tech::layered
