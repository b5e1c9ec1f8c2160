#pragma once
// A texture read back to the CPU without stalling the pipeline: queue()
// copies the texture into a buffer on the GPU (glGetTextureImage into a
// pixel-pack buffer), behind the passes already sent, and marks the copy
// with a fence; read() waits on that fence and maps the buffer. Queued at
// the end of one frame and read at the start of the next, the wait is over
// by then and the CPU touches memory the copy already filled. A plain
// glGetTextureImage into client memory instead waits for the GPU to drain
// and converts on the CPU: on an H100 that cost 3.5 ms a frame at
// 1920x1080 for vrs's class targets (docs/gpu/README.md).
#include <cstdint>
#include <span>

#include "foveate/gpu/gl.hpp"

namespace foveate::gpu {

class TextureReadback {
 public:
  TextureReadback() = default;
  ~TextureReadback();
  TextureReadback(const TextureReadback&) = delete;
  TextureReadback& operator=(const TextureReadback&) = delete;
  TextureReadback(TextureReadback&& o) noexcept;
  TextureReadback& operator=(TextureReadback&& o) noexcept;

  /// Queues a copy of level 0 of `texture` in `format` and `type`,
  /// `texel_bytes` a texel, rows tightly packed from the bottom (as
  /// glGetTextureImage gives them), replacing any copy not read.
  void queue(const Texture& texture, GLenum format = GL_RGBA, GLenum type = GL_UNSIGNED_BYTE,
             int texel_bytes = 4);
  /// Whether a copy is queued and not read yet.
  [[nodiscard]] bool pending() const { return fence_ != nullptr; }
  /// The queued copy's width and height in texels.
  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  /// Waits for the queued copy, maps it and calls `use(bytes)` with its
  /// width x height x texel_bytes bytes, then unmaps; the copy is read. Throws
  /// foveate::Error when none is queued or the wait fails.
  template <typename F>
  void read(F&& use) {
    const std::span<const std::uint8_t> bytes = map();
    struct Unmap {
      TextureReadback* r;
      ~Unmap() { r->unmap(); }
    } unmap_on_exit{this};
    use(bytes);
  }
  /// Drops a queued copy unread.
  void discard();

 private:
  std::span<const std::uint8_t> map();
  void unmap();

  Buffer buffer_;  ///< grows to the largest copy queued
  GLsync fence_ = nullptr;
  int width_ = 0, height_ = 0;
  GLsizeiptr bytes_ = 0;  ///< the queued copy's
};

}  // namespace foveate::gpu
