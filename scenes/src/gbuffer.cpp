#include "gbuffer.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include "foveate/gpu/frame.hpp"
#include "foveate/scenes/scene.hpp"

namespace foveate::detail {

void GBuffer::ensure(int w, int h, int n) {
  if (fbo && width == w && height == h && samples == n) return;
  width = w;
  height = h;
  samples = n;
  if (n > 1) {
    albedo = gpu::Texture::create_2d_multisample(GL_RGBA8, w, h, n);
    normal = gpu::Texture::create_2d_multisample(GL_RGBA16F, w, h, n);
    position = gpu::Texture::create_2d_multisample(GL_RGBA32F, w, h, n);
  } else {
    albedo = gpu::Texture::create_2d(GL_RGBA8, w, h);
    normal = gpu::Texture::create_2d(GL_RGBA16F, w, h);
    position = gpu::Texture::create_2d(GL_RGBA32F, w, h);
    for (gpu::Texture* t : {&albedo, &normal, &position}) t->set_filter(GL_NEAREST, GL_NEAREST);
  }
  depth_stencil = gpu::Renderbuffer::create(GL_DEPTH24_STENCIL8, w, h, n > 1 ? n : 0);
  fbo = gpu::Framebuffer::create();
  fbo.attach(GL_COLOR_ATTACHMENT0, albedo);
  fbo.attach(GL_COLOR_ATTACHMENT1, normal);
  fbo.attach(GL_COLOR_ATTACHMENT2, position);
  fbo.attach(GL_DEPTH_STENCIL_ATTACHMENT, depth_stencil);
  fbo.set_draw_buffers(3);
  fbo.check("G-buffer");
}

}  // namespace foveate::detail

namespace foveate {

std::vector<int> gbuffer_sample_counts() {
  std::vector<int> out = gpu::supported_sample_counts(GL_TEXTURE_2D_MULTISAMPLE, GL_RGBA8);
  const std::pair<GLenum, GLenum> others[] = {{GL_TEXTURE_2D_MULTISAMPLE, GL_RGBA16F},
                                              {GL_TEXTURE_2D_MULTISAMPLE, GL_RGBA32F},
                                              {GL_RENDERBUFFER, GL_DEPTH24_STENCIL8}};
  for (const auto& [target, format] : others) {
    const std::vector<int> ok = gpu::supported_sample_counts(target, format);
    std::erase_if(out, [&](int n) { return std::find(ok.begin(), ok.end(), n) == ok.end(); });
  }
  return out;
}

}  // namespace foveate
