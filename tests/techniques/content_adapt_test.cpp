// vrs's content-adaptive rates (vrs/content_adapt.hpp): which tiles a frame's
// coarse samples call busy, how long a refined tile holds, and what it
// refines to. Pure CPU.
#include "../../techniques/vrs/content_adapt.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

namespace foveate::tech::vrs {
namespace {

constexpr int kTile = 16;
constexpr int k4x4 = 6, k2x2 = 3;  // kShadingRates' classes

// A class target of `tw` x `th` texels, every one shaded (alpha 255) with
// the grey `value(i, j)` (sRGB code).
template <typename F>
std::vector<std::uint8_t> target(int tw, int th, F value) {
  std::vector<std::uint8_t> t(static_cast<size_t>(tw) * size_t(th) * 4);
  for (int j = 0; j < th; ++j)
    for (int i = 0; i < tw; ++i) {
      std::uint8_t* p = &t[(size_t(j) * size_t(tw) + size_t(i)) * 4];
      p[0] = p[1] = p[2] = static_cast<std::uint8_t>(value(i, j));
      p[3] = 255;
    }
  return t;
}

// Two 4x4 tiles side by side (a 32 x 16 frame): 8 x 4 texels at 4x4.
TileClasses two_coarse_tiles() {
  TileClasses c;
  c.of_tile = {k4x4, k4x4};
  c.count[k4x4] = 2;
  return c;
}

TEST(ContentAdapt, BusyTilesAreShadedAt2x2AndSmoothOnesAreNot) {
  ContentAdapt a(0.25, 0.5, 8);
  a.reset(2, 1);
  TileClasses c = two_coarse_tiles();
  // Left tile: a checker of black and white texels; right tile: flat grey.
  const auto t = target(8, 4, [](int i, int j) { return i < 4 ? ((i + j) % 2) * 255 : 128; });
  a.measure(t, 8, 4, kShadingRates[k4x4], c.of_tile, k4x4, false, kTile, 32, 16);
  a.settle();
  EXPECT_EQ(a.refine(c), (std::vector<std::uint8_t>{1, 0}));
  EXPECT_EQ(c.of_tile[0], k2x2);
  EXPECT_EQ(c.of_tile[1], k4x4);
  EXPECT_EQ(c.count[k2x2], 1u);
  EXPECT_EQ(c.count[k4x4], 1u);
}

TEST(ContentAdapt, ContrastBelowTheThresholdAndUnshadedTexelsAreNotBusy) {
  ContentAdapt a(0.25, 0.5, 8);
  a.reset(2, 1);
  TileClasses c = two_coarse_tiles();
  // Codes 200 and 188 are 0.58 and 0.50 in linear light: 14 % apart, under 25 %.
  auto t = target(8, 4, [](int i, int j) { return (i + j) % 2 ? 200 : 188; });
  // The right tile's checker is black and white, but nothing was shaded there.
  for (int j = 0; j < 4; ++j)
    for (int i = 4; i < 8; ++i) {
      std::uint8_t* p = &t[(size_t(j) * 8 + size_t(i)) * 4];
      p[0] = p[1] = p[2] = static_cast<std::uint8_t>(((i + j) % 2) * 255);
      p[3] = 0;
    }
  a.measure(t, 8, 4, kShadingRates[k4x4], c.of_tile, k4x4, false, kTile, 32, 16);
  a.settle();
  a.refine(c);
  EXPECT_EQ(c.of_tile[0], k4x4);
  EXPECT_EQ(c.of_tile[1], k4x4);
}

TEST(ContentAdapt, ARefinedTileHoldsForItsFramesAndIsJudgedAtFourPixels) {
  ContentAdapt a(0.25, 0.5, 3);
  a.reset(2, 1);
  // Busy on the left tile only.
  const auto busy = target(8, 4, [](int i, int j) { return i < 4 ? ((i + j) % 2) * 255 : 128; });
  TileClasses model = two_coarse_tiles();
  a.measure(busy, 8, 4, kShadingRates[k4x4], model.of_tile, k4x4, false, kTile, 32, 16);
  a.settle();
  TileClasses c = model;
  a.refine(c);
  ASSERT_EQ(c.of_tile[0], k2x2);
  // Shaded at 2x2 (16 x 8 texels), the tiles' content is judged 4 pixels
  // apart, every second texel: a checker of 2x2 texels (4-pixel cells) is
  // still busy there, although neighbouring 2x2 texels match in pairs.
  const auto checker4 =
      target(16, 8, [](int i, int j) { return i < 8 ? ((i / 2 + j / 2) % 2) * 255 : 128; });
  a.measure(checker4, 16, 8, kShadingRates[k2x2], c.of_tile, k2x2, true, kTile, 32, 16);
  a.settle();
  EXPECT_TRUE(a.held(0));
  EXPECT_FALSE(a.held(1));  // never busy
  // Smooth from now on: the tile holds 3 frames, then goes back to 4x4.
  const auto flat = target(16, 8, [](int, int) { return 128; });
  for (int frame = 0; frame < 3; ++frame) {
    EXPECT_TRUE(a.held(0)) << frame;
    a.measure(flat, 16, 8, kShadingRates[k2x2], c.of_tile, k2x2, true, kTile, 32, 16);
    a.settle();
  }
  EXPECT_FALSE(a.held(0));
  c = model;
  a.refine(c);
  EXPECT_EQ(c.of_tile[0], k4x4);
}

TEST(ContentAdapt, OnlyRatesOfFourAreRefined) {
  for (int k = 0; k < kClasses; ++k) {
    const ShadingRate r = kShadingRates[static_cast<size_t>(k)];
    EXPECT_EQ(adapt_refines(k), r.width == 4 || r.height == 4) << r.name();
  }
  // A model 2x2 tile that was never refined is not measured as a refined one.
  ContentAdapt a(0.25, 0.5, 8);
  a.reset(1, 1);
  const std::vector<std::uint8_t> classes = {k2x2};
  const auto busy = target(8, 8, [](int i, int j) { return ((i + j) % 2) * 255; });
  a.measure(busy, 8, 8, kShadingRates[k2x2], classes, k2x2, true, kTile, 16, 16);
  a.settle();
  EXPECT_FALSE(a.held(0));
}

TEST(ContentAdapt, BusyTilesMarkedFromTheGpuCountAsMeasuredOnes) {
  // mark() takes the GPU's verdicts (BusyTiles) as measure() would count
  // them: in a class measured that adapt refines, every busy tile; in the
  // 2x2 class, only tiles held refined; in a class not measured, none.
  ContentAdapt a(0.25, 0.5, 8);
  a.reset(4, 1);
  std::vector<std::uint8_t> classes = {k4x4, k4x4, k2x2, k4x4};
  const std::vector<std::uint8_t> busy = {1, 0, 1, 1};
  std::array<bool, kClasses> measured{};
  measured[k4x4] = measured[k2x2] = true;
  a.mark(busy, classes, measured);
  a.settle();
  EXPECT_TRUE(a.held(0));
  EXPECT_FALSE(a.held(1));
  EXPECT_FALSE(a.held(2));  // a model 2x2 tile, never refined
  EXPECT_TRUE(a.held(3));
  // Next frame tile 0 is shaded at 2x2 (refined); found busy again there it
  // holds anew, while tile 3, whose class was not measured, counts down.
  classes = {k2x2, k4x4, k2x2, k4x4};
  measured[k4x4] = false;
  for (int f = 0; f < 7; ++f) {
    a.mark(busy, classes, measured);
    a.settle();
  }
  EXPECT_TRUE(a.held(0));
  EXPECT_TRUE(a.held(3));  // 8 frames of hold, 7 passed
  a.mark(busy, classes, measured);
  a.settle();
  EXPECT_TRUE(a.held(0));
  EXPECT_FALSE(a.held(3));
  EXPECT_FALSE(a.held(2));
}

TEST(ContentAdapt, NoNeighbourFadesIntoARefinedTile) {
  // A row of four tiles: a model 2x2 tile, a 4x4 tile, a refined tile (4x4
  // by the model, shaded at 2x2) and a 4x4 tile. Neighbours see the refined
  // tile as the coarsest class, so the 4x4 tiles beside it do not fade into
  // it (their neighbourhood has no 2x2 bit from it); the model's 2x2 tile
  // still pulls the fade of the 4x4 tile beside it.
  const std::vector<std::uint8_t> classes = {k2x2, k4x4, k2x2, k4x4};
  const std::vector<std::uint8_t> refined = {0, 0, 1, 0};
  const std::vector<std::uint8_t> seen = seen_by_neighbours(classes, refined);
  EXPECT_EQ(seen, (std::vector<std::uint8_t>{k2x2, k4x4, k4x4, k4x4}));
  const std::vector<std::uint8_t> near = neighbourhood_classes(seen, 4, 1);
  EXPECT_EQ(finest_of(near[1]), k2x2);  // beside the model's 2x2 tile
  EXPECT_EQ(finest_of(near[3]), k4x4);  // beside the refined tile only
  // A refined tile merged into a finer class (merge_small_classes) is that
  // class to its neighbours; without refined tiles nothing changes.
  EXPECT_EQ(seen_by_neighbours({0, k4x4}, {1, 0}), (std::vector<std::uint8_t>{0, k4x4}));
  EXPECT_EQ(seen_by_neighbours(classes, {}), classes);
}

// `smooth`: a flat grey at sRGB code 128 (linear 0.2158) with one texel at
// code 136 (0.2462). The bump leaves the mean of its neighbours by
// (0.2462 - 0.2158) / 0.2462 = 0.1235 of its luminance, each neighbour the
// mean of the bump and the flat beyond by 0.0152 / 0.2158 = 0.0704: the
// tile's curvature is 0.1235.
std::vector<std::uint8_t> bumped(int tw, int th, int bi, int bj) {
  return target(tw, th, [&](int i, int j) { return i == bi && j == bj ? 136 : 128; });
}

TEST(ContentAdapt, SmoothTexelsAreJudgedByTheirLargestCurvature) {
  const auto t = bumped(16, 16, 5, 7);
  EXPECT_FALSE(smooth_texels(t, 16, 16, {0, 0, 16, 16}, 0.12));
  EXPECT_TRUE(smooth_texels(t, 16, 16, {0, 0, 16, 16}, 0.13));
  // The texels around the bump alone: 0.0704.
  EXPECT_FALSE(smooth_texels(t, 16, 16, {6, 7, 16, 16}, 0.07));
  EXPECT_TRUE(smooth_texels(t, 16, 16, {6, 7, 16, 16}, 0.071));
  // A texel whose neighbour along an axis is unshaded is not judged along
  // it; a first texel unshaded leaves the tile unjudged (not smooth).
  auto holed = t;
  holed[(size_t(7) * 16 + 4) * 4 + 3] = 0;  // left of the bump
  holed[(size_t(7) * 16 + 6) * 4 + 3] = 0;  // right of it
  holed[(size_t(6) * 16 + 5) * 4 + 3] = 0;  // below it
  EXPECT_TRUE(smooth_texels(holed, 16, 16, {0, 0, 16, 16}, 0.08));
  holed[3] = 0;
  EXPECT_FALSE(smooth_texels(holed, 16, 16, {0, 0, 16, 16}, 1.0));
  // Dark texels are judged against kSmoothDark, not their own luminance:
  // codes 1 and 2 (linear 0.0003 and 0.0006) on black read 0.0003 / 0.005.
  const auto dark = target(8, 1, [](int i, int) { return i == 3 ? 2 : 1; });
  EXPECT_TRUE(smooth_texels(dark, 8, 1, {0, 0, 8, 1}, 0.07));
  EXPECT_FALSE(smooth_texels(dark, 8, 1, {0, 0, 8, 1}, 0.05));
}

TEST(ContentAdapt, SmoothTilesAreShadedAStepCoarserUntilTheyAreNot) {
  // Two 1x1 tiles (a 32 x 16 frame), the left with the bump (0.1235), the
  // right a checker of codes 120 and 136; smooth = 0.15, then 0.05.
  const auto frame = target(32, 16, [](int i, int j) {
    if (i < 16) return i == 5 && j == 7 ? 136 : 128;
    return (i + j) % 2 ? 136 : 120;
  });
  ContentAdapt a(0.25, 0.0, 8, 0.15);
  a.reset(2, 1);
  TileClasses model;
  model.of_tile = {0, 0};
  model.count[0] = 2;
  a.measure(frame, 32, 16, kShadingRates[0], model.of_tile, 0, false, kTile, 32, 16);
  a.settle();
  TileClasses c = model;
  EXPECT_EQ(a.refine(c), (std::vector<std::uint8_t>{0, 0}));  // share 0: nothing is busy
  EXPECT_EQ(a.coarsen(c), (std::vector<std::uint8_t>{1, 0}));
  EXPECT_EQ(c.of_tile, (std::vector<std::uint8_t>{k2x2, 0}));
  EXPECT_EQ(c.count[0], 1u);
  EXPECT_EQ(c.count[k2x2], 1u);
  // Coarsened, the tile is judged at its 2x2 texels against 4 x 0.15: the
  // bump (now a texel of the 2x2 target, 16 x 8) holds it there.
  const auto half = bumped(16, 8, 2, 3);
  a.measure(half, 16, 8, kShadingRates[k2x2], c.of_tile, k2x2, false, kTile, 32, 16);
  a.settle();
  c = model;
  a.refine(c);
  EXPECT_EQ(a.coarsen(c), (std::vector<std::uint8_t>{1, 0}));
  // At 0.03 the same 2x2 texels exceed 4 x 0.03 = 0.12: back to 1x1.
  ContentAdapt strict(0.25, 0.0, 8, 0.03);
  strict.reset(2, 1);
  const auto flat = target(32, 16, [](int, int) { return 128; });
  strict.measure(flat, 32, 16, kShadingRates[0], model.of_tile, 0, false, kTile, 32, 16);
  strict.settle();
  c = model;
  EXPECT_EQ(strict.coarsen(c), (std::vector<std::uint8_t>{1, 1}));
  strict.measure(half, 16, 8, kShadingRates[k2x2], c.of_tile, k2x2, false, kTile, 32, 16);
  strict.settle();
  c = model;
  EXPECT_EQ(strict.coarsen(c), (std::vector<std::uint8_t>{0, 1}));
  EXPECT_EQ(c.of_tile, (std::vector<std::uint8_t>{0, k2x2}));
}

TEST(ContentAdapt, SmoothCoarsensOnlyUnrefinedTilesOfOneAndTwo) {
  // A model 2x2 tile goes to 4x4; a 4x4 tile, flat or not, stays (nothing
  // is coarser); a tile adapt refined (4x4 by the model, busy) is not
  // coarsened back while it holds; off (0), nothing is coarsened.
  ContentAdapt a(0.25, 0.5, 8, 0.05);
  a.reset(3, 1);
  std::vector<std::uint8_t> classes = {k2x2, k4x4, k4x4};
  std::vector<std::uint8_t> busy = {2, 2, 1};
  std::array<bool, kClasses> measured{};
  measured[k4x4] = measured[k2x2] = true;
  a.mark(busy, classes, measured);
  a.settle();
  TileClasses c;
  c.of_tile = classes;
  c.count[k2x2] = 1;
  c.count[k4x4] = 2;
  EXPECT_EQ(a.refine(c), (std::vector<std::uint8_t>{0, 0, 1}));
  EXPECT_EQ(a.coarsen(c), (std::vector<std::uint8_t>{1, 0, 0}));
  EXPECT_EQ(c.of_tile, (std::vector<std::uint8_t>{k4x4, k4x4, k2x2}));
  EXPECT_EQ(c.count[k4x4], 2u);
  // The refined tile found smooth at 2x2 is not coarsened while it holds.
  a.mark(std::vector<std::uint8_t>{2, 2, 2}, c.of_tile, measured);
  a.settle();
  TileClasses next;
  next.of_tile = classes;
  next.count[k2x2] = 1;
  next.count[k4x4] = 2;
  a.refine(next);
  a.coarsen(next);
  EXPECT_EQ(next.of_tile, (std::vector<std::uint8_t>{k4x4, k4x4, k2x2}));
  ContentAdapt off(0.25, 0.5, 8);
  off.reset(3, 1);
  off.mark(std::vector<std::uint8_t>{2, 2, 2}, classes, measured);
  off.settle();
  TileClasses same;
  same.of_tile = classes;
  EXPECT_TRUE(off.coarsen(same).empty());
  EXPECT_EQ(same.of_tile, classes);
}

}  // namespace
}  // namespace foveate::tech::vrs
