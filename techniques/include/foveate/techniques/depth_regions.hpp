#pragma once
// Full-screen passes split into regions, so that each pixel runs only the
// shader its region needs. On llvmpipe a shader pays for every texture fetch
// and both sides of every branch, on every pixel it runs; drawing a disc's
// polygon first and the rest of the screen after, with an early depth test,
// makes each pixel run one region's shader, and whole 4x4 blocks already
// written are skipped. The programs are built from pass_kit/region.vert and a
// fragment shader that declares layout(early_fragment_tests).
#include "foveate/core/display.hpp"
#include "foveate/gpu/gl.hpp"
#include "foveate/gpu/pass.hpp"
#include "foveate/gpu/shader.hpp"

namespace foveate::tech {

class DepthRegions {
 public:
  /// Draws into `target`'s colour texture with a depth buffer of its own
  /// (cleared), regions in the order drawn: earlier regions win. `target`
  /// must have a colour texture (see usable()).
  void begin(const gpu::RenderTarget& target, int regions);
  /// Whether `target` can be split (it has a colour texture; a window's
  /// default framebuffer has none: use one full-screen pass there).
  static bool usable(const gpu::RenderTarget& target) { return static_cast<bool>(target.color()); }
  /// The next region: the polygon around the disc (GL pixels), covering all of
  /// it (circumscribed) or only pixels inside it (inscribed).
  void disc(const gpu::Program& program, Vec2d centre, double radius_px, bool inscribed);
  /// The next region: every pixel not yet drawn.
  void rest(const gpu::Program& program);

 private:
  void prepare(const gpu::Program& program);
  gpu::Framebuffer fbo_;
  gpu::Renderbuffer depth_;
  gpu::RenderTarget target_;
  gpu::VertexArray vao_;
  int regions_ = 1, next_ = 0;
};

}  // namespace foveate::tech
