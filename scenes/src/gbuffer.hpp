#pragma once
// The mesh scenes' G-buffer.
#include "foveate/gpu/gl.hpp"

namespace foveate::detail {

/// The scene's G-buffer: one integer attachment of 16 bytes a sample that
/// gbuffer.frag packs and deferred_common.glsl unpacks (the layout is written
/// there), and a depth-stencil attachment the technique may write its masks
/// into. Packed because a software rasterizer pays a prepass by the bytes it
/// writes a pixel, and every technique pays a full-resolution prepass or
/// several smaller ones (docs/performance.md).
struct GBuffer {
  static constexpr GLenum kFormat = GL_RGBA32UI;
  gpu::Texture surface;
  gpu::Renderbuffer depth_stencil;
  gpu::Framebuffer fbo;
  int width = 0, height = 0;
  int samples = 1;
  void ensure(int w, int h, int samples);
};

}  // namespace foveate::detail
