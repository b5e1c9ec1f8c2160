#pragma once
// The mesh scenes' G-buffer.
#include "foveate/gpu/gl.hpp"

namespace foveate::detail {

/// The scene's G-buffer: albedo + material, normal + gloss, world position,
/// and a depth-stencil attachment the technique may write its masks into.
struct GBuffer {
  gpu::Texture albedo, normal, position;
  gpu::Renderbuffer depth_stencil;
  gpu::Framebuffer fbo;
  int width = 0, height = 0;
  int samples = 1;
  void ensure(int w, int h, int samples);
};

}  // namespace foveate::detail
