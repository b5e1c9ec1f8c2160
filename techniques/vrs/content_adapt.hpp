#pragma once
// vrs's content-adaptive rates (`adapt`). The acuity model gives each tile
// the coarsest rate the eye cannot tell from native on average content; on
// busy content (many small objects, fine texture, silhouettes) FovVideoVDP
// sees a 4-pixel spacing blur where the same rate on smooth content is
// invisible. So a tile the model gives a rate of 4 in either axis is shaded
// at 2x2 while its last frame's samples, taken 4 pixels apart, show enough
// contrast between neighbours. The measure reads what the frame before
// shaded (its class targets), so nothing is shaded for it (on the GPU it is
// a dispatch per class over the tiles: BusyTiles); a tile refined stays
// refined for `hold` frames after it was last found busy, so that its rate
// does not flip back and forth. Pure CPU: no GL here (measure() is the
// GPU's reference).
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "rate_classes.hpp"

namespace foveate::tech::vrs {

class ContentAdapt {
 public:
  /// `contrast`: a sample pair differs when its linear luminances differ by
  /// more than this share of the brighter; `share`: a tile is busy when at
  /// least this share of its pairs differ; `hold`: frames a refined tile
  /// stays refined without being found busy again.
  /// `smooth` (0: off): a tile the model gives 1x1 or 2x2 is shaded a step
  /// coarser (2x2 or 4x4) while its last frame's texels stay within this
  /// share of their luminance of the mean of their neighbours along each
  /// axis (busy_tiles.comp); `share` 0: no tile is busy.
  ContentAdapt(double contrast, double share, int hold, double smooth = 0.0)
      : contrast_(contrast), share_(share), smooth_(smooth), hold_frames_(hold) {}

  /// Starts over on a gx x gy grid (a new size or tile grid): nothing is busy.
  void reset(int gx, int gy);
  [[nodiscard]] int grid_x() const { return gx_; }
  [[nodiscard]] int grid_y() const { return gy_; }

  /// Measures the tiles of class `cls` (per `classes`, the last frame's) in
  /// that class's target: `rgba` its sRGB bytes, `tw` x `th` texels, rows
  /// from the bottom, alpha 0 where nothing was shaded; `rate` the class's
  /// rate; `width` x `height` the frame in tiles of `tile` pixels. With
  /// `refined_only`, only tiles this object refined are measured (a class
  /// the model also gives: its own tiles stay as they are). With `smooth`,
  /// its tiles at 1x1 or 2x2 not held refined, and those it coarsened, are
  /// judged smooth or not as mark() takes them (smooth_texels).
  void measure(std::span<const std::uint8_t> rgba, int tw, int th, ShadingRate rate,
               const std::vector<std::uint8_t>& classes, int cls, bool refined_only, int tile,
               int width, int height);
  /// Takes a frame's busy tiles as measured elsewhere (on the GPU:
  /// BusyTiles, which judges as measure() does): `busy` a byte per tile,
  /// row-major, bit 0 set where busy and bit 1 where smooth, for the tiles
  /// of `classes` (the frame's) whose class is `measured`. As measure()
  /// would, it counts the tiles of a class adapt refines, and those of
  /// another class only where held refined; with `smooth`, smooth tiles of
  /// 1x1 and 2x2 not refined, and those coarsened this frame, are coarsened
  /// in the next.
  void mark(std::span<const std::uint8_t> busy, const std::vector<std::uint8_t>& classes,
            const std::array<bool, kClasses>& measured);
  /// Ends a frame's measurements: busy tiles hold for `hold` frames from
  /// now, the others count down.
  void settle();
  /// Shades every held tile whose class has a rate of 4 in either axis at
  /// 2x2 instead (and counts the classes again). Returns 1 per tile it
  /// refined, 0 for the others (empty when `classes` is of another grid).
  std::vector<std::uint8_t> refine(TileClasses& classes) const;
  /// With `smooth`: shades every tile found smooth in the last frame's
  /// measurements (mark) and not refined a step coarser, 1x1 at 2x2 and 2x2
  /// at 4x4 (and counts the classes again); call after refine(). Returns 1
  /// per tile it coarsened, 0 for the others (empty when `classes` is of
  /// another grid or nothing is coarsened).
  std::vector<std::uint8_t> coarsen(TileClasses& classes);
  /// Whether tile `i` (row-major) is held refined.
  [[nodiscard]] bool held(size_t i) const { return i < hold_.size() && hold_[i] > 0; }
  /// Whether any tile is.
  [[nodiscard]] bool any_held() const;

 private:
  /// Whether `smooth` judges tile `t`: one this frame coarsened, or one the
  /// model gives 1x1 or 2x2 (`fine`) not held refined.
  [[nodiscard]] bool judged_smooth(size_t t, bool fine) const;

  double contrast_, share_, smooth_;
  int hold_frames_;
  int gx_ = 0, gy_ = 0;
  std::vector<int> hold_;                   ///< frames left, per tile
  std::vector<std::uint8_t> busy_;          ///< found busy in this frame's measurements
  std::vector<std::uint8_t> smooth_found_;  ///< found smooth in them
  std::vector<std::uint8_t> coarse_;        ///< to be coarsened (settled)
  std::vector<std::uint8_t> coarsened_;     ///< coarsened this frame (coarsen)
};

/// Each tile's class as its neighbours see it, given the frame's `classes`
/// and the tiles adapt `refined` (1 per tile; empty: none): a refined tile
/// still at kRefinedClass is seen as the coarsest class, so no neighbour
/// fades into it and no class is shaded over its neighbours for it. The
/// fade hides a border the model draws between rates; a refined tile lies
/// in busy content, where its border does not show, and fading around
/// scattered refined tiles shaded and reconstructed their neighbours twice
/// (docs/fidelity.md, "vrs: no fade into a refined tile").
std::vector<std::uint8_t> seen_by_neighbours(const std::vector<std::uint8_t>& classes,
                                             const std::vector<std::uint8_t>& refined);

/// Linear luminance under which `smooth`'s threshold stops shrinking: about
/// a desktop display's black level with its reflections (0.5 % of peak).
inline constexpr double kSmoothDark = 0.005;

/// `smooth`'s verdict on the texels `texels` ([x0, x1) x [y0, y1)) of a
/// class target (`rgba` its sRGB bytes, `tw` x `th`, rows from the bottom,
/// alpha 0 where unshaded; beyond it unshaded): the first texel is shaded,
/// and at every texel shaded whose two neighbours along an axis are shaded,
/// no colour channel (linear) leaves their mean by more than `bound` of the
/// texel's luminance (at least kSmoothDark). The GPU judges the same
/// (busy_tiles.comp).
bool smooth_texels(std::span<const std::uint8_t> rgba, int tw, int th, PixelRect texels,
                   double bound);

/// Whether class `k` is one that `adapt` refines (a rate of 4 in either axis).
bool adapt_refines(int k);
/// The class a refined tile is shaded at: 2x2 (kShadingRates[3]).
inline constexpr int kRefinedClass = 3;

}  // namespace foveate::tech::vrs
