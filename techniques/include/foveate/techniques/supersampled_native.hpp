#pragma once
// A true reference: native rendering with N x N supersampling, box-filtered
// in linear light down to the output size. Native at one sample per pixel is
// itself aliased; judged against it, aliasing that native and a technique
// share goes uncounted and a correctly antialiased periphery is penalised.
#include <memory>

#include "foveate/core/display.hpp"
#include "foveate/core/image.hpp"
#include "foveate/gpu/pass.hpp"
#include "foveate/scenes/scene.hpp"

namespace foveate {

class SupersampledNative {
 public:
  /// `display` at the output size; `factor` samples per pixel per axis (2..8).
  /// Throws foveate::Error when the supersampled size exceeds the GL's limits.
  /// Needs a current GL context.
  SupersampledNative(const Display& display, int factor = 4);
  ~SupersampledNative();
  SupersampledNative(const SupersampledNative&) = delete;
  SupersampledNative& operator=(const SupersampledNative&) = delete;

  /// Renders `input` (output-sized) of `scene` at factor x the resolution and
  /// resolves it. Give it a scene of its own (load the scene twice): a scene
  /// rendered at two sizes in turn reallocates its G-buffer every frame.
  const gpu::RenderTarget& render(Scene& scene, const FrameInput& input);
  [[nodiscard]] Image read() const;
  [[nodiscard]] int factor() const { return factor_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int factor_;
};

/// "native" -> 1 (the reference is native itself), "ssaa" -> 4, "ssaa:N" -> N
/// (2..8). Throws foveate::Error naming the text otherwise.
int parse_reference(const std::string& text);

}  // namespace foveate
