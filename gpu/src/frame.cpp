#include "foveate/gpu/frame.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace foveate::gpu {

Image read_framebuffer(GLuint framebuffer, int width, int height) {
  Image img(width, height);
  std::vector<std::uint8_t> rows(img.rgba.size());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  const size_t stride = static_cast<size_t>(width) * 4;
  for (int y = 0; y < height; ++y) {
    std::memcpy(&img.rgba[static_cast<size_t>(y) * stride],
                &rows[static_cast<size_t>(height - 1 - y) * stride], stride);
  }
  return img;
}

Image read_texture(const Texture& texture) {
  Image img(texture.width(), texture.height());
  std::vector<std::uint8_t> rows(img.rgba.size());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(texture.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(rows.size()),
                    rows.data());
  const size_t stride = static_cast<size_t>(img.width) * 4;
  for (int y = 0; y < img.height; ++y) {
    std::memcpy(&img.rgba[static_cast<size_t>(y) * stride],
                &rows[static_cast<size_t>(img.height - 1 - y) * stride], stride);
  }
  return img;
}

Texture upload_image(const Image& image, bool mipmaps) {
  int levels = 1;
  if (mipmaps) {
    for (int s = std::max(image.width, image.height); s > 1; s >>= 1) ++levels;
  }
  Texture t = Texture::create_2d(GL_RGBA8, image.width, image.height, levels);
  // GL's origin is bottom-left: flip rows so that v = 0 is the image bottom.
  std::vector<std::uint8_t> rows(image.rgba.size());
  const size_t stride = static_cast<size_t>(image.width) * 4;
  for (int y = 0; y < image.height; ++y) {
    std::memcpy(&rows[static_cast<size_t>(y) * stride],
                &image.rgba[static_cast<size_t>(image.height - 1 - y) * stride], stride);
  }
  t.upload(image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  if (levels > 1) glGenerateTextureMipmap(t.id());
  t.set_wrap(GL_REPEAT);
  return t;
}

bool FrameTimer::gpu_timer_meaningful() {
  const auto* r = glGetString(GL_RENDERER);
  return gpu_timer_meaningful(r ? reinterpret_cast<const char*>(r) : "");
}

bool FrameTimer::gpu_timer_meaningful(const std::string& renderer) {
  for (const char* soft : {"llvmpipe", "softpipe", "SwiftShader", "Software"}) {
    if (renderer.find(soft) != std::string::npos) return false;
  }
  return !renderer.empty();
}

FrameTimer::FrameTimer() : use_query_(gpu_timer_meaningful()), gpu_ms_(std::nan("")) {
  if (use_query_) query_ = Query::create(GL_TIME_ELAPSED);
}

void FrameTimer::start() {
  glFinish();
  t0_ = std::chrono::steady_clock::now();
  if (use_query_) glBeginQuery(GL_TIME_ELAPSED, query_.id());
}

double FrameTimer::stop() {
  if (use_query_) glEndQuery(GL_TIME_ELAPSED);
  glFinish();
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0_).count();
  if (use_query_) {
    GLuint64 ns = 0;
    glGetQueryObjectui64v(query_.id(), GL_QUERY_RESULT, &ns);
    gpu_ms_ = static_cast<double>(ns) / 1e6;
  }
  return ms;
}

}  // namespace foveate::gpu
