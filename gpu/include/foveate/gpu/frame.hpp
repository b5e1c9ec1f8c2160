#pragma once
// Reading frames back and timing them. On llvmpipe GPU timer queries report
// meaningless numbers, so frames are timed with a steady clock around glFinish.
#include <chrono>
#include <string>

#include "foveate/core/image.hpp"
#include "foveate/gpu/gl.hpp"

namespace foveate::gpu {

/// Reads the RGBA8 colour of `texture` (or the bound read framebuffer when 0)
/// into an Image with the top-left origin.
Image read_texture(const Texture& texture);
Image read_framebuffer(GLuint framebuffer, int width, int height);
/// Uploads an Image as an RGBA8 (sRGB-encoded values, no conversion) texture.
Texture upload_image(const Image& image, bool mipmaps = true);

/// Wall-clock time of GPU work: start() and stop() both call glFinish. On a
/// real GPU a GL_TIME_ELAPSED query runs alongside (gpu_ms()); software
/// renderers (llvmpipe, softpipe, SwiftShader) report meaningless numbers
/// there, so no query is made on them.
class FrameTimer {
 public:
  FrameTimer();
  void start();
  /// Milliseconds since start().
  double stop();
  /// GPU time of the last start()/stop() in ms, or NaN where not meaningful.
  [[nodiscard]] double gpu_ms() const { return gpu_ms_; }
  /// Whether the current renderer reports meaningful GPU timer queries.
  static bool gpu_timer_meaningful();
  /// The same for a renderer named `renderer` (GL_RENDERER): false for the
  /// software rasterizers (llvmpipe, softpipe, SwiftShader) and for no name.
  static bool gpu_timer_meaningful(const std::string& renderer);

 private:
  std::chrono::steady_clock::time_point t0_;
  bool use_query_ = false;
  Query query_;
  double gpu_ms_;
};

}  // namespace foveate::gpu
