#include "foveate/gpu/gl.hpp"

#include <atomic>
#include <cstdio>

#include "foveate/core/error.hpp"
#include "foveate/gpu/object_counts.hpp"

namespace foveate::gpu {

namespace {
// Live objects per type, in the order of GlObjectCounts.
enum Kind {
  kBuffer,
  kTexture,
  kFramebuffer,
  kRenderbuffer,
  kVertexArray,
  kProgram,
  kShader,
  kQuery
};
std::atomic<long> g_live[kQuery + 1];
// Every object made since the process started (object_counts.hpp).
std::atomic<long> g_created[kQuery + 1];

void freed(Kind k) { g_live[k].fetch_sub(1, std::memory_order_relaxed); }
}  // namespace

namespace detail {
void delete_buffer(GLuint id) {
  glDeleteBuffers(1, &id);
  freed(kBuffer);
}
void delete_texture(GLuint id) {
  glDeleteTextures(1, &id);
  freed(kTexture);
}
void delete_framebuffer(GLuint id) {
  glDeleteFramebuffers(1, &id);
  freed(kFramebuffer);
}
void delete_renderbuffer(GLuint id) {
  glDeleteRenderbuffers(1, &id);
  freed(kRenderbuffer);
}
void delete_vertex_array(GLuint id) {
  glDeleteVertexArrays(1, &id);
  freed(kVertexArray);
}
void delete_program(GLuint id) {
  glDeleteProgram(id);
  freed(kProgram);
}
void delete_shader(GLuint id) {
  glDeleteShader(id);
  freed(kShader);
}
void delete_query(GLuint id) {
  glDeleteQueries(1, &id);
  freed(kQuery);
}

void count_created(void (*deleter)(GLuint)) {
  static void (*const kDeleters[])(GLuint) = {
      delete_buffer,       delete_texture, delete_framebuffer, delete_renderbuffer,
      delete_vertex_array, delete_program, delete_shader,      delete_query};
  for (int k = 0; k <= kQuery; ++k) {
    if (kDeleters[k] != deleter) continue;
    g_live[k].fetch_add(1, std::memory_order_relaxed);
    g_created[k].fetch_add(1, std::memory_order_relaxed);
  }
}
}  // namespace detail

namespace {
GlObjectCounts counts(const std::atomic<long> (&of)[kQuery + 1]) {
  auto n = [&](Kind k) { return of[k].load(std::memory_order_relaxed); };
  GlObjectCounts c;
  c.buffers = n(kBuffer);
  c.textures = n(kTexture);
  c.framebuffers = n(kFramebuffer);
  c.renderbuffers = n(kRenderbuffer);
  c.vertex_arrays = n(kVertexArray);
  c.programs = n(kProgram);
  c.shaders = n(kShader);
  c.queries = n(kQuery);
  return c;
}
}  // namespace

GlObjectCounts live_gl_objects() { return counts(g_live); }

GlObjectCounts gl_objects_created() { return counts(g_created); }

Buffer Buffer::create(GLsizeiptr size, const void* data, GLbitfield flags) {
  GLuint id = 0;
  glCreateBuffers(1, &id);
  Buffer b(id);
  glNamedBufferStorage(id, size, data, flags);
  b.size_ = size;
  return b;
}

Buffer Buffer::create_streamed() {
  GLuint id = 0;
  glCreateBuffers(1, &id);
  return Buffer(id);
}

void Buffer::stream(GLsizeiptr size, const void* data) {
  glNamedBufferData(id(), size, data, GL_STREAM_DRAW);
  size_ = size;
}

Texture Texture::create_2d_array(GLenum internal_format, int width, int height, int layers) {
  GLint max = 0, max_layers = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max);
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &max_layers);
  if (width < 1 || height < 1 || width > max || height > max || layers < 1 || layers > max_layers) {
    throw Error("array texture " + std::to_string(width) + "x" + std::to_string(height) + "x" +
                std::to_string(layers) + " is outside what this GL supports");
  }
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
  Texture t(id);
  glTextureStorage3D(id, 1, internal_format, width, height, layers);
  t.width_ = width;
  t.height_ = height;
  t.layers_ = layers;
  t.format_ = internal_format;
  t.set_filter(GL_NEAREST, GL_NEAREST);
  t.set_wrap(GL_CLAMP_TO_EDGE);
  return t;
}

Texture Texture::view(const Texture& of, GLenum internal_format) {
  GLuint id = 0;
  glGenTextures(1, &id);  // a view needs a name never bound (not glCreateTextures')
  Texture t(id);
  glTextureView(id, GL_TEXTURE_2D, of.id(), internal_format, 0, 1, 0, 1);
  t.width_ = of.width_;
  t.height_ = of.height_;
  t.format_ = internal_format;
  return t;
}

Texture Texture::create_2d(GLenum internal_format, int width, int height, int levels) {
  GLint max = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max);
  if (width < 1 || height < 1 || width > max || height > max) {
    throw Error("texture size " + std::to_string(width) + "x" + std::to_string(height) +
                " is outside what this GL supports (1.." + std::to_string(max) + ")");
  }
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &id);
  Texture t(id);
  glTextureStorage2D(id, levels, internal_format, width, height);
  t.width_ = width;
  t.height_ = height;
  t.format_ = internal_format;
  t.set_filter(levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR, GL_LINEAR);
  t.set_wrap(GL_CLAMP_TO_EDGE);
  return t;
}

Texture Texture::create_2d_multisample(GLenum internal_format, int width, int height, int samples) {
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D_MULTISAMPLE, 1, &id);
  Texture t(id);
  glTextureStorage2DMultisample(id, samples, internal_format, width, height, GL_TRUE);
  t.width_ = width;
  t.height_ = height;
  t.format_ = internal_format;
  return t;
}

void Texture::set_filter(GLenum min, GLenum mag) const {
  glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, static_cast<GLint>(min));
  glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, static_cast<GLint>(mag));
}

void Texture::set_wrap(GLenum wrap) const {
  glTextureParameteri(id(), GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap));
  glTextureParameteri(id(), GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap));
}

void Texture::upload(int width, int height, GLenum format, GLenum type, const void* pixels) const {
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(id(), 0, 0, 0, width, height, format, type, pixels);
}

Renderbuffer Renderbuffer::create(GLenum internal_format, int width, int height, int samples) {
  GLuint id = 0;
  glCreateRenderbuffers(1, &id);
  Renderbuffer r(id);
  if (samples > 0) {
    glNamedRenderbufferStorageMultisample(id, samples, internal_format, width, height);
  } else {
    glNamedRenderbufferStorage(id, internal_format, width, height);
  }
  return r;
}

Framebuffer Framebuffer::create() {
  GLuint id = 0;
  glCreateFramebuffers(1, &id);
  return Framebuffer(id);
}

void Framebuffer::attach(GLenum attachment, const Texture& texture, int level) const {
  glNamedFramebufferTexture(id(), attachment, texture.id(), level);
}

void Framebuffer::attach(GLenum attachment, const Renderbuffer& rb) const {
  glNamedFramebufferRenderbuffer(id(), attachment, GL_RENDERBUFFER, rb.id());
}

void Framebuffer::set_draw_buffers(int count) const {
  GLenum bufs[8];
  for (int i = 0; i < count && i < 8; ++i) bufs[i] = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i);
  glNamedFramebufferDrawBuffers(id(), count, bufs);
}

void Framebuffer::check(const char* what) const {
  const GLenum s = glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER);
  if (s != GL_FRAMEBUFFER_COMPLETE) {
    throw Error(std::string(what) + ": framebuffer incomplete (" + gl_enum_name(s) + ")");
  }
}

VertexArray VertexArray::create() {
  GLuint id = 0;
  glCreateVertexArrays(1, &id);
  return VertexArray(id);
}

Query Query::create(GLenum target) {
  GLuint id = 0;
  glCreateQueries(target, 1, &id);
  return Query(id);
}

std::string gl_enum_name(GLenum e) {
  switch (e) {
    case GL_INVALID_ENUM:
      return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
      return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
      return "GL_INVALID_OPERATION";
    case GL_OUT_OF_MEMORY:
      return "GL_OUT_OF_MEMORY";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
      return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_FRAMEBUFFER_UNSUPPORTED:
      return "GL_FRAMEBUFFER_UNSUPPORTED";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT:
      return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
      return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE:
      return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
    default: {
      char buf[32];
      std::snprintf(buf, sizeof buf, "0x%04X", e);
      return buf;
    }
  }
}

std::vector<int> supported_sample_counts(GLenum target, GLenum internal_format) {
  GLint n = 0;
  glGetInternalformativ(target, internal_format, GL_NUM_SAMPLE_COUNTS, 1, &n);
  if (n <= 0) return {};
  std::vector<GLint> counts(static_cast<size_t>(n));
  glGetInternalformativ(target, internal_format, GL_SAMPLES, n, counts.data());
  return {counts.begin(), counts.end()};
}

}  // namespace foveate::gpu
