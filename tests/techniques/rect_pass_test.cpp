// The covers of passes drawn over rectangles (foveate/techniques/rect_pass.hpp),
// without GL: discs, annuli, merged and coarsened runs, pixel by pixel.
#include "foveate/techniques/rect_pass.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "pixel_rects.hpp"

namespace foveate::tech {
namespace {

using test::covered;

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

TEST(Rects, AnnulusCoverHoldsEveryPixelOfTheRingAndLeavesTheHole) {
  const int W = 200, H = 120;
  const double inf = std::numeric_limits<double>::infinity();
  for (const auto& [cx, cy, r_in, r_out] : {std::array<double, 4>{100.3, 60.7, 20.0, 50.5},
                                            std::array<double, 4>{5.0, 110.0, 12.0, 30.0},
                                            std::array<double, 4>{100.0, 60.0, 40.0, inf},
                                            std::array<double, 4>{90.0, 50.0, 0.0, 30.0}}) {
    const auto rects = annulus_rects(cx, cy, r_in, r_out, W, H);
    double ring = 0, hole_covered = 0, hole = 0;
    for (int y = 0; y < H; ++y) {
      for (int x = 0; x < W; ++x) {
        const double d = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
        if (d < r_in - 3.0) {  // well inside the hole: should be left out
          ++hole;
          hole_covered += covered(rects, x, y) ? 1 : 0;
        }
        if (d > r_out || d < r_in) continue;
        ++ring;
        ASSERT_TRUE(covered(rects, x, y)) << x << "," << y << " of the ring at " << cx << "," << cy;
      }
    }
    for (const PixelRect& q : rects) {
      EXPECT_GE(q[0], 0);
      EXPECT_GE(q[1], 0);
      EXPECT_LE(q[2], W);
      EXPECT_LE(q[3], H);
      EXPECT_LT(q[0], q[2]);
    }
    EXPECT_GT(ring, 0);
    // Bands of 4 rows cut the hole by their farthest row: most of it is left out.
    if (hole > 0) {
      EXPECT_LT(hole_covered, 0.35 * hole) << r_in;
    }
  }
  EXPECT_TRUE(annulus_rects(50, 50, 0.0, 0.0, W, H).empty());
}

TEST(Rects, CoarsenedRunsCoverEveryPixelOnceWithLittleWaste) {
  // A disc and a ring (two rectangles per band across the hole): fewer
  // rectangles, every pixel of the input covered, none twice, and no more
  // than the allowed waste.
  const int W = 400, H = 300;
  for (const auto& rects :
       {disc_rects(200.5, 150.2, 120.0, W, H), annulus_rects(180.0, 140.0, 60.0, 130.0, W, H),
        annulus_rects(200.0, 150.0, 80.0, std::numeric_limits<double>::infinity(), W, H)}) {
    const auto coarse = coarsen_runs(rects, 0.08);
    EXPECT_LT(coarse.size() * 3, rects.size());
    double in = 0, out = 0;
    for (int y = 0; y < H; ++y) {
      for (int x = 0; x < W; ++x) {
        int n = 0;
        for (const PixelRect& q : coarse) n += x >= q[0] && x < q[2] && y >= q[1] && y < q[3];
        ASSERT_LE(n, 1) << x << "," << y;
        if (covered(rects, x, y)) {
          ASSERT_EQ(n, 1) << x << "," << y;
          ++in;
        }
        out += n;
      }
    }
    EXPECT_LE(out, in / (1.0 - 0.08));  // each box at most 8 % more than it covers
  }
}

TEST(Rects, MergedRunsCoverTheSamePixels) {
  const std::vector<PixelRect> tiles = {{0, 0, 4, 4},   {4, 0, 8, 4}, {8, 0, 12, 4},
                                        {16, 0, 20, 4}, {0, 4, 4, 8}, {3, 4, 9, 8}};
  const auto merged = merge_runs(tiles);
  EXPECT_EQ(merged.size(), 3u);  // 0-12 and 16-20 in the first row, 0-9 in the second
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 24; ++x) EXPECT_EQ(covered(tiles, x, y), covered(merged, x, y));
}

TEST(Rects, BoundingBoxHoldsEveryRectangleGrownOnEachSide) {
  const std::vector<PixelRect> rects = {{4, 6, 8, 9}, {-2, 10, 3, 12}, {5, 1, 6, 2}};
  EXPECT_EQ(bounding_box(rects), (PixelRect{-2, 1, 8, 12}));
  EXPECT_EQ(bounding_box(rects, 1), (PixelRect{-3, 0, 9, 13}));
  // None: an empty box, not grown (a clear or a copy over it does nothing).
  EXPECT_EQ(bounding_box({}, 1), (PixelRect{0, 0, 0, 0}));
}

}  // namespace
}  // namespace foveate::tech
