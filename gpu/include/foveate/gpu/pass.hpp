#pragma once
// Explicit per-pass GL state. A pass names where it draws (a RenderTarget,
// which carries its framebuffer and viewport), the fixed-function state it
// needs (a PassState: zero means off, and everything it does not name is set
// to off), and the textures it samples (Samplers: units handed out in order,
// so a scene's textures and a technique's never collide). Nothing a pass sets
// leaks into the next one.
#include <array>
#include <vector>

#include "foveate/gpu/gl.hpp"

namespace foveate::gpu {

class Program;

/// Where a pass draws: a framebuffer and the viewport that covers it.
/// Either owns its attachments (create) or refers to a framebuffer someone
/// else owns (wrap: a user's target, the window's framebuffer 0).
class RenderTarget {
 public:
  RenderTarget() = default;
  /// A colour texture of `format` (and a depth-stencil renderbuffer when
  /// asked). The default, GL_SRGB8_ALPHA8, stores sRGB-encoded bytes and
  /// reads and blends as linear light; GL_RGBA16F where precision matters
  /// (temporal history).
  static RenderTarget create(int width, int height, GLenum format = GL_SRGB8_ALPHA8,
                             bool depth_stencil = false);
  /// A framebuffer owned elsewhere, `width` x `height` pixels.
  static RenderTarget wrap(GLuint framebuffer, int width, int height);
  /// Recreates the attachments when the size, format or depth-stencil changes.
  void ensure(int width, int height, GLenum format = GL_SRGB8_ALPHA8, bool depth_stencil = false);
  /// Whether writes are sRGB-encoded (owned GL_SRGB8_ALPHA8 targets, or a
  /// wrapped framebuffer whose colour attachment says so).
  [[nodiscard]] bool srgb() const;
  /// Binds the framebuffer and sets the viewport to the whole target.
  void bind() const;
  /// Clears colour to `rgba`, and depth to 1 and stencil to 0 where the
  /// target has them. Write masks are opened first (GL clears honour them).
  void clear(float r, float g, float b, float a) const;
  /// The same within pixels [x0, x1) x [y0, y1) alone (clamped to the
  /// target): a clear costs per pixel, and a pass that writes and reads a
  /// known region of a large target need not pay for the rest.
  void clear(float r, float g, float b, float a, const std::array<int, 4>& region) const;
  [[nodiscard]] GLuint framebuffer() const { return owned_ ? fbo_.id() : wrapped_; }
  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  /// The colour texture (owning targets only).
  [[nodiscard]] const Texture& color() const { return color_; }
  [[nodiscard]] bool has_depth_stencil() const { return static_cast<bool>(depth_stencil_); }
  explicit operator bool() const { return framebuffer() != 0 || (width_ > 0 && !owned_); }

 private:
  /// Clears colour, depth and stencil under the current scissor state.
  void clear_attachments(float r, float g, float b, float a) const;
  bool owned_ = false;
  GLuint wrapped_ = 0;
  int width_ = 0, height_ = 0;
  Texture color_;
  Renderbuffer depth_stencil_;
  Framebuffer fbo_;
};

/// Fixed-function state of one pass. Zero (the default) means off: a
/// default PassState draws colour with no depth, stencil or blending.
/// Writes to sRGB-encoded targets are always encoded (GL_FRAMEBUFFER_SRGB):
/// shaders output linear light.
struct PassState {
  GLenum depth_func = 0;  ///< 0 = no depth test; otherwise GL_LESS, GL_ALWAYS, ...
  bool depth_write = false;
  GLenum stencil_func = 0;  ///< 0 = no stencil test; otherwise GL_EQUAL, GL_ALWAYS, ...
  GLint stencil_ref = 0;
  GLenum stencil_pass_op = 0;  ///< on depth pass: 0 = keep, GL_REPLACE, GL_INCR, ...
  bool stencil_write = false;  ///< stencil write mask 0xFF instead of 0
  bool alpha_blend = false;    ///< colour: src alpha, one minus src alpha; alpha kept
  bool color_off = false;      ///< colour writes off (depth/stencil-only passes)
  /// Only this rectangle is drawn (x, y, width, height; GL pixels, origin
  /// bottom-left); a zero width or height = the whole target.
  std::array<int, 4> scissor{};

  /// A stencil-only pass (colour off): where it draws and the stencil test
  /// `func` against `ref` passes, `op` is applied to the stencil (GL_REPLACE
  /// writes `ref`). The default marks every pixel drawn with 1.
  static PassState stencil_mark(GLint ref = 1, GLenum func = GL_ALWAYS, GLenum op = GL_REPLACE);
  /// A pass drawn only where the stencil equals `ref`.
  static PassState stencil_equal(GLint ref = 1);
};

/// Sets every piece of state PassState names, on or off.
void apply(const PassState& state);
/// Opens every write mask (colour, depth, stencil) so that clears reach
/// everything; the next apply() sets them as its pass needs.
void open_write_masks();

/// Texture units for one pass, handed out in order from unit 0.
class Samplers {
 public:
  /// Binds `texture` to the next unit and points sampler uniform `name` at it.
  void bind(const Program& program, const char* name, const Texture& texture);
  /// Binds a raw texture name (e.g. a scene's own) the same way.
  void bind(const Program& program, const char* name, GLuint texture);
  [[nodiscard]] int used() const { return next_; }

 private:
  int next_ = 0;
};

/// A framebuffer binding and viewport, captured and restored: for code that
/// draws somewhere of its own in the middle of someone else's work (a scene's
/// geometry prepass restores what it found).
struct FramebufferBinding {
  GLint framebuffer = 0;
  GLint viewport[4] = {};
  static FramebufferBinding current();
  void restore() const;
};

}  // namespace foveate::gpu
