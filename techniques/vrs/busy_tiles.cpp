#include "busy_tiles.hpp"

#include <algorithm>

#include "rate_classes.hpp"

namespace foveate::tech::vrs {

void BusyTiles::begin(const PassKit& kit, int gx, int gy) {
  if (!program_) {
    const char* file = "vrs/busy_tiles.comp";
    program_ = kit.compiler().build({gpu::StageSource{GL_COMPUTE_SHADER, {{file, {}}}}}, file);
  }
  if (!busy_ || busy_.width() != gx || busy_.height() != gy) {
    busy_ = gpu::Texture::create_2d(GL_R8UI, gx, gy);
    busy_.set_filter(GL_NEAREST, GL_NEAREST);
  }
  const GLubyte zero = 0;
  glClearTexImage(busy_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, &zero);
}

void BusyTiles::measure(const gpu::Texture& classes, const gpu::Texture& target, int cls, int tile,
                        int width, int height) {
  const ShadingRate r = kShadingRates[static_cast<size_t>(cls)];
  program_.use();
  gpu::Samplers samplers;
  samplers.bind(program_, "u_classes", classes);
  samplers.bind(program_, "u_target", target);
  program_.set("u_class", cls);
  program_.set("u_rate", r.width, r.height);
  program_.set("u_step", std::max(1, 4 / r.width), std::max(1, 4 / r.height));
  program_.set("u_tile", tile);
  program_.set("u_frame", width, height);
  program_.set("u_contrast", static_cast<float>(contrast_));
  program_.set("u_share", static_cast<float>(share_));
  program_.set("u_smooth", static_cast<float>(smooth_));
  glBindImageTexture(0, busy_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R8UI);
  glDispatchCompute(static_cast<GLuint>((busy_.width() + 7) / 8),
                    static_cast<GLuint>((busy_.height() + 7) / 8), 1);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R8UI);
}

void BusyTiles::queue() {
  glMemoryBarrier(GL_PIXEL_BUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  readback_.queue(busy_, GL_RED_INTEGER, GL_UNSIGNED_BYTE, 1);
}

}  // namespace foveate::tech::vrs
