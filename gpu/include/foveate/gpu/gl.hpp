#pragma once
// Move-only RAII wrappers over OpenGL 4.5 objects, created and edited with
// direct state access (glCreate*, glNamed*, glTexture*). The GL loader is
// libepoxy, so the same code runs on EGL (headless) and GLFW (window).
#include <epoxy/gl.h>

#include <string>
#include <utility>
#include <vector>

namespace foveate::gpu {

namespace detail {
/// Counts one more live object of the type `deleter` frees (see live_gl_objects).
void count_created(void (*deleter)(GLuint));
}  // namespace detail

/// Owns one GL object name; `Deleter` frees it.
template <void (*Deleter)(GLuint)>
class Handle {
 public:
  Handle() = default;
  explicit Handle(GLuint id) : id_(id) {
    if (id_) detail::count_created(Deleter);
  }
  ~Handle() { reset(); }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  Handle& operator=(Handle&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  [[nodiscard]] GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_) Deleter(id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
};

namespace detail {
void delete_buffer(GLuint id);
void delete_texture(GLuint id);
void delete_framebuffer(GLuint id);
void delete_renderbuffer(GLuint id);
void delete_vertex_array(GLuint id);
void delete_program(GLuint id);
void delete_shader(GLuint id);
void delete_query(GLuint id);
}  // namespace detail

class Buffer : public Handle<detail::delete_buffer> {
 public:
  Buffer() = default;
  /// Immutable storage of `size` bytes (glNamedBufferStorage).
  static Buffer create(GLsizeiptr size, const void* data, GLbitfield flags = 0);
  /// A buffer for data that each draw replaces (stream()).
  static Buffer create_streamed();
  /// Replaces the whole store (glNamedBufferData, GL_STREAM_DRAW): a store
  /// that draws queued earlier may still read is orphaned and they keep it,
  /// so each draw reads the data given just before it. (A store rewritten in
  /// place between draws would need a wait: without one NVIDIA's driver draws
  /// earlier passes from later data.)
  void stream(GLsizeiptr size, const void* data);
  [[nodiscard]] GLsizeiptr size() const { return size_; }

 private:
  using Handle::Handle;
  GLsizeiptr size_ = 0;
};

class Texture : public Handle<detail::delete_texture> {
 public:
  Texture() = default;
  /// 2D texture with immutable storage; linear filtering, clamp to edge.
  static Texture create_2d(GLenum internal_format, int width, int height, int levels = 1);
  static Texture create_2d_multisample(GLenum internal_format, int width, int height, int samples);
  /// 2D array texture of `layers` layers (nearest filtering, clamp to edge).
  static Texture create_2d_array(GLenum internal_format, int width, int height, int layers);
  /// A view of a 2D texture's first level as `internal_format`, of the same
  /// view class (GL_SRGB8_ALPHA8 as GL_RGBA8: image stores, which do not
  /// encode, into an sRGB texture's bytes). It shares `of`'s storage.
  static Texture view(const Texture& of, GLenum internal_format);
  void set_filter(GLenum min, GLenum mag) const;
  void set_wrap(GLenum wrap) const;
  void upload(int width, int height, GLenum format, GLenum type, const void* pixels) const;
  void bind(GLuint unit) const { glBindTextureUnit(unit, id()); }
  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  [[nodiscard]] GLenum format() const { return format_; }
  [[nodiscard]] int layers() const { return layers_; }

 private:
  using Handle::Handle;
  int width_ = 0, height_ = 0, layers_ = 1;
  GLenum format_ = 0;
};

class Renderbuffer : public Handle<detail::delete_renderbuffer> {
 public:
  Renderbuffer() = default;
  static Renderbuffer create(GLenum internal_format, int width, int height, int samples = 0);

 private:
  using Handle::Handle;
};

class Framebuffer : public Handle<detail::delete_framebuffer> {
 public:
  Framebuffer() = default;
  static Framebuffer create();
  void attach(GLenum attachment, const Texture& texture, int level = 0) const;
  void attach(GLenum attachment, const Renderbuffer& rb) const;
  /// Sets the draw buffers to COLOR_ATTACHMENT0..n-1.
  void set_draw_buffers(int count) const;
  /// Throws foveate::Error when incomplete.
  void check(const char* what) const;
  void bind() const { glBindFramebuffer(GL_FRAMEBUFFER, id()); }

 private:
  using Handle::Handle;
};

class VertexArray : public Handle<detail::delete_vertex_array> {
 public:
  VertexArray() = default;
  static VertexArray create();

 private:
  using Handle::Handle;
};

class Query : public Handle<detail::delete_query> {
 public:
  Query() = default;
  static Query create(GLenum target);

 private:
  using Handle::Handle;
};

/// GL objects alive now, per type, as counted by the wrappers above (objects
/// made with raw GL calls are not seen): a debug aid for leak hunting
/// (`foveate render --stats`, scripts/soak.sh).
struct GlObjectCounts {
  long buffers = 0, textures = 0, framebuffers = 0, renderbuffers = 0, vertex_arrays = 0,
       programs = 0, shaders = 0, queries = 0;
  [[nodiscard]] long total() const {
    return buffers + textures + framebuffers + renderbuffers + vertex_arrays + programs + shaders +
           queries;
  }
};
GlObjectCounts live_gl_objects();

/// Human-readable name of a GL error or enum, for messages.
std::string gl_enum_name(GLenum e);

/// The sample counts above 1 the implementation supports for `internal_format`
/// as `target` (GL_TEXTURE_2D_MULTISAMPLE or GL_RENDERBUFFER), highest first
/// (glGetInternalformativ GL_SAMPLES). Needs a current context.
std::vector<int> supported_sample_counts(GLenum target, GLenum internal_format);

}  // namespace foveate::gpu
