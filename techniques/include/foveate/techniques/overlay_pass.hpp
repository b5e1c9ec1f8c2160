#pragma once
// The inspection overlay (Figure 1 of Guenter et al.): a technique's layer
// or region borders and the gaze, drawn over a frame.
#include <memory>
#include <vector>

#include "foveate/gpu/pass.hpp"
#include "foveate/techniques/technique.hpp"

namespace foveate {

/// Draws overlay shapes over a display-sized framebuffer. Owns GL objects:
/// create and destroy it while the context is current.
class OverlayPass {
 public:
  OverlayPass();
  ~OverlayPass();
  void draw(const std::vector<OverlayShape>& shapes, const gpu::RenderTarget& target);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace foveate
