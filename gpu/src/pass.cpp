#include "foveate/gpu/pass.hpp"

#include <algorithm>

#include "foveate/gpu/shader.hpp"

namespace foveate::gpu {

RenderTarget RenderTarget::create(int width, int height, GLenum format, bool depth_stencil) {
  RenderTarget t;
  t.ensure(width, height, format, depth_stencil);
  return t;
}

RenderTarget RenderTarget::wrap(GLuint framebuffer, int width, int height) {
  RenderTarget t;
  t.wrapped_ = framebuffer;
  t.width_ = width;
  t.height_ = height;
  return t;
}

void RenderTarget::ensure(int width, int height, GLenum format, bool depth_stencil) {
  if (owned_ && color_ && width_ == width && height_ == height && color_.format() == format &&
      has_depth_stencil() == depth_stencil) {
    return;
  }
  owned_ = true;
  wrapped_ = 0;
  width_ = width;
  height_ = height;
  color_ = Texture::create_2d(format, width, height);
  fbo_ = Framebuffer::create();
  fbo_.attach(GL_COLOR_ATTACHMENT0, color_);
  depth_stencil_.reset();
  if (depth_stencil) {
    depth_stencil_ = Renderbuffer::create(GL_DEPTH24_STENCIL8, width, height);
    fbo_.attach(GL_DEPTH_STENCIL_ATTACHMENT, depth_stencil_);
  }
  fbo_.check("render target");
}

bool RenderTarget::srgb() const {
  if (owned_) return color_.format() == GL_SRGB8_ALPHA8;
  const GLuint fb = framebuffer();
  GLint encoding = GL_LINEAR;
  glGetNamedFramebufferAttachmentParameteriv(fb, fb == 0 ? GL_BACK_LEFT : GL_COLOR_ATTACHMENT0,
                                             GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING, &encoding);
  return encoding == GL_SRGB;
}

void RenderTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer());
  glViewport(0, 0, width_, height_);
}

PassState PassState::stencil_mark(GLint ref, GLenum func, GLenum op) {
  PassState s;
  s.stencil_func = func;
  s.stencil_ref = ref;
  s.stencil_pass_op = op;
  s.stencil_write = true;
  s.color_off = true;
  return s;
}

PassState PassState::stencil_equal(GLint ref) {
  PassState s;
  s.stencil_func = GL_EQUAL;
  s.stencil_ref = ref;
  return s;
}

void RenderTarget::clear(float r, float g, float b, float a) const {
  open_write_masks();
  clear_attachments(r, g, b, a);
}

void RenderTarget::clear(float r, float g, float b, float a,
                         const std::array<int, 4>& region) const {
  const int x0 = std::clamp(region[0], 0, width_), y0 = std::clamp(region[1], 0, height_);
  const int x1 = std::clamp(region[2], x0, width_), y1 = std::clamp(region[3], y0, height_);
  if (x1 == x0 || y1 == y0) return;
  open_write_masks();  // (which turns the scissor test off)
  glEnable(GL_SCISSOR_TEST);
  glScissor(x0, y0, x1 - x0, y1 - y0);
  clear_attachments(r, g, b, a);
  glDisable(GL_SCISSOR_TEST);
}

void RenderTarget::clear_attachments(float r, float g, float b, float a) const {
  const float rgba[4] = {r, g, b, a};
  glClearNamedFramebufferfv(framebuffer(), GL_COLOR, 0, rgba);
  if (has_depth_stencil()) glClearNamedFramebufferfi(framebuffer(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
}

void open_write_masks() {
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  glStencilMask(0xFFu);
  glDisable(GL_SCISSOR_TEST);  // clears honour the scissor too
}

void apply(const PassState& s) {
  if (s.depth_func != 0) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(s.depth_func);
  } else {
    glDisable(GL_DEPTH_TEST);
  }
  glDepthMask(s.depth_write ? GL_TRUE : GL_FALSE);
  if (s.stencil_func != 0) {
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(s.stencil_func, s.stencil_ref, 0xFF);
    const GLenum pass = s.stencil_pass_op != 0 ? s.stencil_pass_op : GL_KEEP;
    glStencilOp(GL_KEEP, GL_KEEP, pass);
  } else {
    glDisable(GL_STENCIL_TEST);
  }
  glStencilMask(s.stencil_write ? 0xFFu : 0u);
  if (s.alpha_blend) {
    glEnable(GL_BLEND);
    // Colour over colour; the target keeps its own alpha (PNGs stay opaque).
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  } else {
    glDisable(GL_BLEND);
  }
  const GLboolean c = s.color_off ? GL_FALSE : GL_TRUE;
  glColorMask(c, c, c, c);
  if (s.scissor[2] > 0 && s.scissor[3] > 0) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(s.scissor[0], s.scissor[1], s.scissor[2], s.scissor[3]);
  } else {
    glDisable(GL_SCISSOR_TEST);
  }
  glEnable(GL_FRAMEBUFFER_SRGB);
}

void Samplers::bind(const Program& program, const char* name, const Texture& texture) {
  bind(program, name, texture.id());
}

void Samplers::bind(const Program& program, const char* name, GLuint texture) {
  const int unit = next_++;
  glBindTextureUnit(static_cast<GLuint>(unit), texture);
  program.set(name, unit);
}

FramebufferBinding FramebufferBinding::current() {
  FramebufferBinding b;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &b.framebuffer);
  glGetIntegerv(GL_VIEWPORT, b.viewport);
  return b;
}

void FramebufferBinding::restore() const {
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(framebuffer));
  glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
}

}  // namespace foveate::gpu
