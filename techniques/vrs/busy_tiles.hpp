#pragma once
// vrs adapt's measure on the GPU (busy_tiles.comp): which tiles show busy
// content in what a frame shaded, judged as ContentAdapt::measure judges
// them on the CPU, one byte per tile, read back at the start of the next
// frame without a stall. Reading the class targets back and measuring them
// on the CPU cost an H100 1.5 ms a frame at 1920x1080 and 7 ms at 3840x2160
// (docs/gpu/README.md); this costs a dispatch per class and a few kB.
#include <cstdint>
#include <span>

#include "foveate/gpu/readback.hpp"
#include "foveate/gpu/shader.hpp"
#include "foveate/techniques/pass_kit.hpp"

namespace foveate::tech::vrs {

class BusyTiles {
 public:
  /// `contrast`, `share` and `smooth` as ContentAdapt's.
  BusyTiles(double contrast, double share, double smooth = 0.0)
      : contrast_(contrast), share_(share), smooth_(smooth) {}

  /// Starts a frame's measurements over a gx x gy grid: no tile busy.
  void begin(const PassKit& kit, int gx, int gy);
  /// Measures the tiles of class `cls` per `classes` (the frame's class per
  /// tile in bits 0-2, bit 6 set where coarsened; R8UI, gx x gy) in `target`, that class's target,
  /// for a `width` x `height` frame in tiles of `tile` pixels.
  void measure(const gpu::Texture& classes, const gpu::Texture& target, int cls, int tile,
               int width, int height);
  /// Queues the read-back of the frame's busy tiles.
  void queue();
  [[nodiscard]] bool pending() const { return readback_.pending(); }
  /// Waits for the queued read-back and calls `use(busy)`: a byte per tile,
  /// row-major from the bottom row (as the classes), bit 0 set where busy,
  /// bit 1 where smooth.
  template <typename F>
  void read(F&& use) {
    readback_.read(std::forward<F>(use));
  }
  void discard() { readback_.discard(); }

 private:
  double contrast_, share_, smooth_;
  gpu::Program program_;
  gpu::Texture busy_;
  gpu::TextureReadback readback_;
};

}  // namespace foveate::tech::vrs
