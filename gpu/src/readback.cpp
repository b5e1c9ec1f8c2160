#include "foveate/gpu/readback.hpp"

#include <utility>

#include "foveate/core/error.hpp"

namespace foveate::gpu {

TextureReadback::~TextureReadback() { discard(); }

TextureReadback::TextureReadback(TextureReadback&& o) noexcept
    : buffer_(std::move(o.buffer_)),
      fence_(std::exchange(o.fence_, nullptr)),
      width_(o.width_),
      height_(o.height_),
      bytes_(o.bytes_) {}

TextureReadback& TextureReadback::operator=(TextureReadback&& o) noexcept {
  if (this != &o) {
    discard();
    buffer_ = std::move(o.buffer_);
    fence_ = std::exchange(o.fence_, nullptr);
    width_ = o.width_;
    height_ = o.height_;
    bytes_ = o.bytes_;
  }
  return *this;
}

void TextureReadback::discard() {
  if (fence_) glDeleteSync(fence_);
  fence_ = nullptr;
}

void TextureReadback::queue(const Texture& texture, GLenum format, GLenum type, int texel_bytes) {
  discard();
  width_ = texture.width();
  height_ = texture.height();
  bytes_ = static_cast<GLsizeiptr>(width_) * height_ * texel_bytes;
  // Client storage: the driver keeps the copy where the CPU reads it fast.
  if (!buffer_ || buffer_.size() < bytes_)
    buffer_ = Buffer::create(bytes_, nullptr, GL_MAP_READ_BIT | GL_CLIENT_STORAGE_BIT);
  // Explicit pack state for this copy: rows tightly packed (a row of bytes
  // of any width), into offset 0; the alignment found is put back.
  GLint alignment = 4;
  glGetIntegerv(GL_PACK_ALIGNMENT, &alignment);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, buffer_.id());
  glGetTextureImage(texture.id(), 0, format, type, static_cast<GLsizei>(bytes_), nullptr);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, alignment);
  fence_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
}

std::span<const std::uint8_t> TextureReadback::map() {
  if (!fence_) throw Error("texture read-back: no copy queued");
  // The first wait flushes the copy to the GPU; a hung GPU is the watchdog's
  // to report, so this waits as long as it takes, a second at a time.
  GLbitfield flags = GL_SYNC_FLUSH_COMMANDS_BIT;
  for (;;) {
    const GLenum r = glClientWaitSync(fence_, flags, 1'000'000'000);
    if (r == GL_ALREADY_SIGNALED || r == GL_CONDITION_SATISFIED) break;
    if (r == GL_WAIT_FAILED) throw Error("texture read-back: waiting for the copy failed");
    flags = 0;
  }
  discard();
  const void* p = glMapNamedBufferRange(buffer_.id(), 0, bytes_, GL_MAP_READ_BIT);
  if (!p) throw Error("texture read-back: the copy could not be mapped");
  return {static_cast<const std::uint8_t*>(p), static_cast<size_t>(bytes_)};
}

void TextureReadback::unmap() { glUnmapNamedBuffer(buffer_.id()); }

}  // namespace foveate::gpu
