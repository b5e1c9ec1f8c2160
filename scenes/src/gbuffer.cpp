#include "gbuffer.hpp"

#include <algorithm>
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
    surface = gpu::Texture::create_2d_multisample(kFormat, w, h, n);
  } else {
    surface = gpu::Texture::create_2d(kFormat, w, h);
    surface.set_filter(GL_NEAREST, GL_NEAREST);
  }
  depth_stencil = gpu::Renderbuffer::create(GL_DEPTH24_STENCIL8, w, h, n > 1 ? n : 0);
  fbo = gpu::Framebuffer::create();
  fbo.attach(GL_COLOR_ATTACHMENT0, surface);
  fbo.attach(GL_DEPTH_STENCIL_ATTACHMENT, depth_stencil);
  fbo.set_draw_buffers(1);
  fbo.check("G-buffer");
}

}  // namespace foveate::detail

namespace foveate {

std::vector<int> gbuffer_sample_counts() {
  // The counts both attachments support.
  std::vector<int> out =
      gpu::supported_sample_counts(GL_TEXTURE_2D_MULTISAMPLE, detail::GBuffer::kFormat);
  const std::vector<int> depth = gpu::supported_sample_counts(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8);
  std::erase_if(out,
                [&](int n) { return std::find(depth.begin(), depth.end(), n) == depth.end(); });
  return out;
}

}  // namespace foveate
