#pragma once
// vrs's rate classes: the index of each of kShadingRates (0 = 1x1, the
// finest), per tile of a shading-rate image, and what both of vrs's paths
// read from them: the classes around a tile, a tile's pixels, the classes'
// extents as uniforms.
#include <array>
#include <cstdint>
#include <vector>

#include "foveate/core/shading_rate.hpp"
#include "foveate/gpu/shader.hpp"
#include "foveate/techniques/pass_kit.hpp"

namespace foveate::tech::vrs {

inline constexpr int kClasses = static_cast<int>(kShadingRates.size());

/// The class of a rate of kShadingRates (kClasses for any other).
int class_of(ShadingRate r);

/// The class of every tile of `m` (row-major, as m.rates), and how many
/// tiles each class has.
struct TileClasses {
  std::vector<std::uint8_t> of_tile;
  std::array<size_t, kClasses> count{};
};
TileClasses tile_classes(const ShadingRateImage& m);

/// Per tile, the classes found in its 3x3 neighbourhood (itself included),
/// bit k for class k, over a gx x gy grid of classes in row-major order.
std::vector<std::uint8_t> neighbourhood_classes(const std::vector<std::uint8_t>& classes, int gx,
                                                int gy);

/// The lowest class in a neighbourhood's bits: the finest class nearby.
int finest_of(unsigned bits);

/// Every class costs the emulation passes of its own (on mesh scenes the
/// geometry once more), so a class with fewer than `min_fraction` of the
/// tiles is shaded at the coarsest class that is as fine in both axes and
/// large enough (1x1 at worst): finer than the model asks, never coarser.
void merge_small_classes(TileClasses& classes, double min_fraction);

/// Tile (tx, ty)'s pixels (GL: rows from the bottom) in a width x height
/// target with tiles of `tile` pixels.
PixelRect tile_pixels(int tx, int ty, int tile, int width, int height);

/// u_rates[k]: the width and height of kShadingRates[k].
void set_rates(const gpu::Program& p);

/// Radius (pixels) of the disc around `c` that only 1x1 tiles cover.
double native_radius(const ShadingRateImage& m, Vec2d c);

/// A gx x gy grid of classes as an R8UI texture, (re)created when the grid's
/// size changed (`grid` holds the size the texture was made for).
void upload_classes(gpu::Texture& texture, std::array<int, 2>& grid, int gx, int gy,
                    const std::vector<std::uint8_t>& classes);

/// Copies `rects` (GL pixels) of a full-resolution `src` of the target's size
/// into `target`: a copy of the bytes where the target has a texture of the
/// same format (far cheaper than a pass), else a pass that reads each pixel
/// at its centre (vrs/reconstruct_copy.frag).
void copy_native_tiles(PassKit& kit, const std::vector<PixelRect>& rects,
                       const gpu::RenderTarget& src, const gpu::RenderTarget& target);

}  // namespace foveate::tech::vrs
