#pragma once
// vrs's emulation, for drivers without variable-rate shading (llvmpipe):
// every rate class present is shaded into a target of its own reduced
// resolution (W / rw x H / rh), limited by a stencil mask to its tiles and the
// coarser tiles next to them; on mesh scenes every class shades from one
// native G-buffer. The masks are drawn over those tiles alone (RectPass), and
// llvmpipe rejects whole 4x4 blocks before shading, so the other tiles cost
// nothing. In the coarse classes, texels that differ from a neighbour by more
// than `edge_contrast` are reshaded with `edge_samples` more
// (PassKit::supersample_edges): one sample per coarse pixel aliases small
// objects, highlights and procedural texture, which is where FovVideoVDP
// finds vrs's error. Then the frame is put together in linear light: each pixel reads
// its class bilinearly, and a tile next to a finer one fades into it over one
// tile, so the 1x1 fovea is native and no tile edge shows (a tile refined by
// `adapt` pulls no fade: seen_by_neighbours; a tile coarsened by `smooth`
// fades into no finer neighbour). Every pass is
// drawn over the tiles that need it, so each output pixel runs one shader
// once.
#include <array>
#include <optional>

#include "busy_tiles.hpp"
#include "content_adapt.hpp"
#include "rate_classes.hpp"

namespace foveate::tech::vrs {

class EmulatedPath {
 public:
  /// `adapt` above 0: content-adaptive rates (ContentAdapt) with that share,
  /// judged by `edge_contrast` (0.25 when edges are off).
  /// `smooth` above 0: smooth tiles shaded a step coarser (ContentAdapt).
  EmulatedPath(int tile, double edge_contrast, int edge_samples, double adapt = 0.0,
               double smooth = 0.0)
      : tile_(tile), edge_(edge_contrast), edge_samples_(edge_samples) {
    if (adapt > 0.0 || smooth > 0.0) {
      const double contrast = edge_contrast > 0.0 ? edge_contrast : 0.25;
      adapt_.emplace(contrast, adapt, kAdaptHold, smooth);
      busy_.emplace(contrast, adapt, smooth);
    }
    smooth_ = smooth > 0.0;
  }
  /// Frames a tile refined by `adapt` stays so without being found busy again.
  static constexpr int kAdaptHold = 8;
  /// With `adapt`: takes the busy tiles of what the last frame shaded
  /// (measured on the GPU at its end and read back now, with no stall) and
  /// refines this frame's `classes` of a gx x gy grid for a width x height
  /// frame. A no-op without.
  void adapt(TileClasses& classes, int gx, int gy, int width, int height);
  /// Renders with `classes` (merged: merge_small_classes) of a gx x gy grid.
  FrameStats render(PassKit& kit, Scene& scene, const TileClasses& classes, int gx, int gy,
                    const gpu::RenderTarget& target);

 private:
  /// The tiles' classes and what each frame's passes read of them.
  struct Grid {
    const std::vector<std::uint8_t>& classes;
    std::vector<std::uint8_t> near;  ///< neighbourhood_classes
    int gx, gy;
    [[nodiscard]] int at(int tx, int ty) const {
      return classes[static_cast<size_t>(ty) * size_t(gx) + size_t(tx)];
    }
    [[nodiscard]] unsigned near_at(int tx, int ty) const {
      return near[static_cast<size_t>(ty) * size_t(gx) + size_t(tx)];
    }
  };
  /// What one class's shading cost: its texels, and those reshaded with
  /// edge_samples more.
  struct Shaded {
    PixelCount texels, edges;
  };
  /// Shades class `k` into its own target over the texels the
  /// reconstruction reads of it.
  Shaded shade_class(PassKit& kit, Scene& scene, const Grid& grid, int k, int width, int height);
  /// Puts the frame together from the class targets into `target`.
  void reconstruct(PassKit& kit, const Grid& grid, const std::array<bool, kClasses>& present,
                   const gpu::RenderTarget& target);
  /// With `adapt`: measures the busy tiles in this frame's class targets
  /// for the next frame's adapt(), and queues their read-back.
  void measure_busy_tiles(const PassKit& kit, const std::array<bool, kClasses>& present, int gx,
                          int gy, int width, int height);

  int tile_;
  double edge_;
  int edge_samples_;
  gpu::Texture classes_;
  std::array<int, 2> grid_{};
  std::array<gpu::RenderTarget, kClasses> targets_;
  std::array<gpu::RenderTarget, kClasses> scratch_;  ///< supersample_edges' copies
  std::optional<ContentAdapt> adapt_;
  /// The last frame's classes (merged) and its size, which its targets
  /// hold.
  std::vector<std::uint8_t> last_classes_;
  std::array<int, 2> last_size_{};
  /// adapt's measure on the GPU, and the classes it measured in the frame
  /// whose read-back is queued.
  std::optional<BusyTiles> busy_;
  std::array<bool, kClasses> measured_{};
  std::vector<std::uint8_t> refined_;  ///< per tile: refined by adapt this frame
  bool smooth_ = false;
  std::vector<std::uint8_t> coarsened_;  ///< per tile: coarsened by `smooth` this frame
};

}  // namespace foveate::tech::vrs
