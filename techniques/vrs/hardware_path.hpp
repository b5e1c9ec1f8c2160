#pragma once
// vrs's hardware path: the driver shades at the rates itself
// (GL_NV_shading_rate_image). The class of each tile indexes a palette of the
// extension's rates (gl_nv_palette), bound as the shading-rate image while the
// frame is shaded once at native resolution; coverage and depth stay per
// pixel. A tile next to a finer one is shaded at the finest rate around it
// (the component-wise least, which is again a rate of the set), as the
// emulation shades each class over the coarser tiles beside it. The driver
// copies a fragment's colour to all its pixels, a visible mosaic, so the frame
// is then put together as the emulation does (vrs/hardware_reconstruct.frag):
// the 1x1 tiles copied, the others interpolated between fragment centres and
// faded into their finer neighbours over one tile. Never runs on llvmpipe
// but simulated there (`simulate_driver`); scripts/gpu-bench.sh benches it
// beside the emulation (vrs.hardware=0).
#include <array>

#include "rate_classes.hpp"

namespace foveate::tech::vrs {

/// Whether the driver shades at the rates itself (GL_NV_shading_rate_image)
/// with tiles of this size: then no emulation is needed.
bool hardware_available(int tile);

class HardwarePath {
 public:
  /// `simulate`: no shading-rate image in the driver; what it would leave is
  /// made from a full-resolution frame (vrs/simulate_driver.frag), so that
  /// the rest of this path runs, and is tested, on any renderer.
  HardwarePath(int tile, bool simulate) : tile_(tile), simulate_(simulate) {}
  FrameStats render(PassKit& kit, Scene& scene, const ShadingRateImage& m,
                    const std::vector<std::uint8_t>& classes, const gpu::RenderTarget& target);

 private:
  /// Each tile's shaded class (the finest around it) and the fragments shaded.
  std::vector<std::uint8_t> shaded_classes(const ShadingRateImage& m,
                                           const std::vector<std::uint8_t>& classes, int width,
                                           int height, FrameStats& stats,
                                           std::vector<PixelRect>& fine,
                                           std::vector<PixelRect>& coarse) const;
  /// Shades `frame` at the rates of `shaded_` (or simulates the driver).
  void shade(PassKit& kit, Scene& scene, const View& view, gpu::RenderTarget& frame,
             float sample_offset);

  int tile_;
  bool simulate_;
  gpu::Texture shaded_;  ///< the shaded class per tile
  gpu::Texture own_;     ///< the model's class per tile
  std::array<int, 2> shaded_grid_{}, own_grid_{};
  gpu::RenderTarget frame_;  ///< the frame the driver shaded
  gpu::RenderTarget full_;   ///< simulated: the full-resolution frame
};

}  // namespace foveate::tech::vrs
