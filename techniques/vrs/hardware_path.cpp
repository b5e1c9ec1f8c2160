#include "hardware_path.hpp"

#include <algorithm>

namespace foveate::tech::vrs {

bool hardware_available(int tile) {
  if (!epoxy_has_gl_extension("GL_NV_shading_rate_image")) return false;
  GLint w = 0, h = 0;
  glGetIntegerv(GL_SHADING_RATE_IMAGE_TEXEL_WIDTH_NV, &w);
  glGetIntegerv(GL_SHADING_RATE_IMAGE_TEXEL_HEIGHT_NV, &h);
  return w == tile && h == tile;
}

std::vector<std::uint8_t> HardwarePath::shaded_classes(const ShadingRateImage& m,
                                                       const std::vector<std::uint8_t>& classes,
                                                       int W, int H, FrameStats& s,
                                                       std::vector<PixelRect>& fine,
                                                       std::vector<PixelRect>& coarse) const {
  const int gx = m.tiles_x, gy = m.tiles_y;
  std::vector<std::uint8_t> shade(classes.size());
  for (int ty = 0; ty < gy; ++ty) {
    for (int tx = 0; tx < gx; ++tx) {
      const size_t i = static_cast<size_t>(ty) * size_t(gx) + size_t(tx);
      const PixelRect p = tile_pixels(tx, ty, tile_, W, H);
      (classes[i] == 0 ? fine : coarse).push_back(p);
      ShadingRate r = kShadingRates[classes[i]];
      for (int y = std::max(0, ty - 1); y <= std::min(gy - 1, ty + 1); ++y) {
        for (int x = std::max(0, tx - 1); x <= std::min(gx - 1, tx + 1); ++x) {
          const ShadingRate n =
              kShadingRates[classes[static_cast<size_t>(y) * size_t(gx) + size_t(x)]];
          r = {std::min(r.width, n.width), std::min(r.height, n.height)};
        }
      }
      const int k = class_of(r);  // the rates are closed under the component-wise least
      shade[i] = static_cast<std::uint8_t>(k < kClasses ? k : 0);
      const int w = p[2] - p[0], h = p[3] - p[1];
      s.shaded_pixels += double((w + r.width - 1) / r.width) * ((h + r.height - 1) / r.height);
    }
  }
  return shade;
}

void HardwarePath::shade(PassKit& kit, Scene& scene, const View& view, gpu::RenderTarget& frame,
                         float sample_offset) {
  const int W = frame.width(), H = frame.height();
  if (simulate_) {
    full_.ensure(W, H, GL_SRGB8_ALPHA8, true);
    full_.color().set_filter(GL_LINEAR, GL_LINEAR);
    kit.shade(scene, view, kMapRect, full_,
              [&](const gpu::Program& p, gpu::Samplers&) { set_rect_mapping(p, view); });
    kit.rect_pass(kit.over_rects("vrs/simulate_driver.frag"), {{0, 0, W, H}}, frame, {},
                  [&](const gpu::Program& p, gpu::Samplers& smp) {
                    smp.bind(p, "u_full", full_.color());
                    smp.bind(p, "u_shade", shaded_);
                    set_rates(p);
                    p.set("u_tile", tile_);
                    p.set("u_sample_offset", sample_offset);
                  });
    return;
  }
  const auto& palette = gl_nv_palette();
  const std::vector<GLenum> rates(palette.begin(), palette.end());
  glShadingRateImagePaletteNV(0, 0, static_cast<GLsizei>(rates.size()), rates.data());
  glBindShadingRateImageNV(shaded_.id());
  glEnable(GL_SHADING_RATE_IMAGE_NV);
  kit.shade(scene, view, kMapRect, frame,
            [&](const gpu::Program& p, gpu::Samplers&) { set_rect_mapping(p, view); });
  glDisable(GL_SHADING_RATE_IMAGE_NV);
  glBindShadingRateImageNV(0);
}

FrameStats HardwarePath::render(PassKit& kit, Scene& scene, const ShadingRateImage& m,
                                const std::vector<std::uint8_t>& classes,
                                const gpu::RenderTarget& target) {
  const int W = target.width(), H = target.height();
  FrameStats s;
  s.native_pixels = double(W) * H;
  std::vector<PixelRect> fine, coarse;  // the 1x1 tiles, the others
  const std::vector<std::uint8_t> shaded = shaded_classes(m, classes, W, H, s, fine, coarse);
  upload_classes(shaded_, shaded_grid_, m.tiles_x, m.tiles_y, shaded);
  upload_classes(own_, own_grid_, m.tiles_x, m.tiles_y, classes);
  frame_.ensure(W, H, GL_SRGB8_ALPHA8, true);
  frame_.color().set_filter(GL_LINEAR, GL_LINEAR);
  frame_.color().set_wrap(GL_CLAMP_TO_EDGE);
  const View view = View::full(W, H);
  scene.prepass(view);
  // Mesh scenes shade a coarse fragment from the G-buffer pixel at its
  // centre (deferred_common.glsl); procedural scenes at the centre itself.
  const float sample_offset = scene.info().has_meshes ? 0.5f : 0.0f;
  shade(kit, scene, view, frame_, sample_offset);
  copy_native_tiles(kit, merge_runs(fine), frame_, target);
  kit.rect_pass(kit.over_rects("vrs/hardware_reconstruct.frag"), merge_runs(coarse), target, {},
                [&](const gpu::Program& p, gpu::Samplers& smp) {
                  smp.bind(p, "u_frame", frame_.color());
                  smp.bind(p, "u_shade", shaded_);
                  smp.bind(p, "u_own", own_);
                  set_rates(p);
                  p.set("u_tile", tile_);
                  p.set("u_sample_offset", sample_offset);
                });
  s.parts.push_back({"hardware rates", s.shaded_pixels});
  return s;
}

}  // namespace foveate::tech::vrs
