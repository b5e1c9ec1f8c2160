// Passes drawn over rectangles (techniques/common/rects.hpp): the covers they
// compute and the pixels they reach.
#include "rects.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "foveate/gpu/frame.hpp"
#include "gl_fixture.hpp"
#include "kit.hpp"

namespace foveate::tech {
namespace {

bool covered(const std::vector<PixelRect>& rects, int x, int y) {
  for (const PixelRect& r : rects)
    if (x >= r[0] && x < r[2] && y >= r[1] && y < r[3]) return true;
  return false;
}

double area(const std::vector<PixelRect>& rects) {
  double a = 0;
  for (const PixelRect& r : rects) a += double(r[2] - r[0]) * (r[3] - r[1]);
  return a;
}

TEST(Rects, DiscCoverHoldsEveryPixelOfTheDiscAndLittleElse) {
  const int W = 200, H = 120;
  for (const auto& [cx, cy, r] :
       {std::array<double, 3>{100.3, 60.7, 37.2}, std::array<double, 3>{5.0, 110.0, 30.0},
        std::array<double, 3>{100.0, 60.0, 500.0}}) {
    const auto rects = disc_rects(cx, cy, r, W, H);
    double inside = 0;
    for (int y = 0; y < H; ++y) {
      for (int x = 0; x < W; ++x) {
        if (std::hypot(x + 0.5 - cx, y + 0.5 - cy) > r) continue;
        ++inside;
        ASSERT_TRUE(covered(rects, x, y))
            << x << "," << y << " of the disc at " << cx << "," << cy << " r " << r;
      }
    }
    for (const PixelRect& q : rects) {
      EXPECT_GE(q[0], 0);
      EXPECT_GE(q[1], 0);
      EXPECT_LE(q[2], W);
      EXPECT_LE(q[3], H);
    }
    // Bands of 4 rows over the disc and a pixel's margin: close to the disc,
    // far below its bounding box where the disc fits on screen.
    if (r < 100) {
      EXPECT_LT(area(rects), inside * 1.25 + 4.0 * 2 * r);
    }
  }
  EXPECT_TRUE(disc_rects(50, 50, 0.0, W, H).empty());
}

TEST(Rects, MergedRunsCoverTheSamePixels) {
  const std::vector<PixelRect> tiles = {{0, 0, 4, 4},   {4, 0, 8, 4}, {8, 0, 12, 4},
                                        {16, 0, 20, 4}, {0, 4, 4, 8}, {3, 4, 9, 8}};
  const auto merged = merge_runs(tiles);
  EXPECT_EQ(merged.size(), 3u);  // 0-12 and 16-20 in the first row, 0-9 in the second
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 24; ++x) EXPECT_EQ(covered(tiles, x, y), covered(merged, x, y));
}

class RectPassTest : public test::GlTest {};

TEST_F(RectPassTest, DrawsExactlyTheRectangles) {
  Kit kit;
  gpu::RenderTarget t;
  t.ensure(64, 48, GL_RGBA8);
  t.clear(1, 1, 1, 1);
  const std::vector<PixelRect> rects = {{2, 3, 10, 7}, {20, 0, 64, 5}, {0, 40, 1, 48}};
  // vrs/mask.frag writes black.
  kit.rect_pass(kit.over_rects("vrs/mask.frag"), rects, t);
  const Image img = gpu::read_framebuffer(t.framebuffer(), 64, 48);
  int black = 0;
  for (int y = 0; y < 48; ++y) {
    for (int x = 0; x < 64; ++x) {
      const bool b = img.at(x, 47 - y)[0] == 0;  // read back top row first
      black += b ? 1 : 0;
      EXPECT_EQ(b, covered(rects, x, y)) << x << "," << y;
    }
  }
  EXPECT_EQ(black, 8 * 4 + 44 * 5 + 8);
  // Nothing to draw: nothing drawn, no error.
  kit.rect_pass(kit.over_rects("vrs/mask.frag"), {}, t);
}

}  // namespace
}  // namespace foveate::tech
