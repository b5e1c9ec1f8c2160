// Passes drawn over rectangles (foveate/techniques/rect_pass.hpp): the covers they
// compute and the pixels they reach.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "foveate/core/shading_rate.hpp"
#include "foveate/gpu/frame.hpp"
#include "foveate/techniques/pass_kit.hpp"
#include "foveate/techniques/rect_pass.hpp"
#include "gl_fixture.hpp"

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

class RectPassTest : public test::GlTest {};

TEST_F(RectPassTest, DrawsExactlyTheRectangles) {
  PassKit kit;
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

TEST_F(RectPassTest, BackToBackPassesEachDrawTheirOwnRectangles) {
  // Passes queued with no wait between them, each with its own rectangles
  // (more each time, so the store grows): every pass draws its own. NVIDIA's
  // driver 580 drew the earlier passes from the last pass's rectangles while
  // one buffer was rewritten in place (llvmpipe never did: it cannot fail
  // here, but it does on such a driver).
  PassKit kit;
  gpu::RenderTarget t;
  t.ensure(64, 48, GL_RGBA8);
  t.clear(1, 1, 1, 1);
  const std::vector<std::vector<PixelRect>> passes = {
      {{0, 0, 8, 8}},
      {{16, 0, 24, 8}, {32, 0, 40, 8}},
      {{0, 16, 8, 24}, {16, 16, 24, 24}, {32, 16, 40, 24}, {48, 16, 56, 24}}};
  for (const auto& rects : passes) kit.rect_pass(kit.over_rects("vrs/mask.frag"), rects, t);
  const Image img = gpu::read_framebuffer(t.framebuffer(), 64, 48);
  for (const auto& rects : passes) {
    for (int y = 0; y < 48; ++y) {
      for (int x = 0; x < 64; ++x) {
        if (covered(rects, x, y)) {
          ASSERT_EQ(img.at(x, 47 - y)[0], 0) << x << "," << y;
        }
      }
    }
  }
}

// vrs's hardware path (GL_NV_shading_rate_image) put together by
// vrs/hardware_reconstruct.frag from a frame made here by hand as the driver
// shades it (no VRS on llvmpipe): each rw x rh fragment one colour, that of
// its centre. Tiles of 16 px, 6 x 3: column 0 is 1x1, the rest 4x4 by the
// model; column 1 borders the 1x1 tiles, so it is shaded 1x1 and fades.
struct HardwareVrsFrame {
  static constexpr int kTile = 16, kGx = 6, kGy = 3, W = kGx * kTile, H = kGy * kTile;
  std::vector<std::uint8_t> own, shade;
  std::vector<float> rgba = std::vector<float>(size_t(W * H * 4), 1.0f);
  HardwareVrsFrame() {
    for (int ty = 0; ty < kGy; ++ty) {
      for (int tx = 0; tx < kGx; ++tx) {
        own.push_back(tx == 0 ? 0 : 6);    // kShadingRates: 1x1 ... 4x4
        shade.push_back(tx <= 1 ? 0 : 6);  // the finest rate around each tile
      }
    }
  }
  [[nodiscard]] ShadingRate shaded_at(int x, int y) const {
    return kShadingRates[shade[size_t((y / kTile) * kGx + x / kTile)]];
  }
  // Past the centre along each axis a fragment spans: 0.5 as a deferred
  // scene shades (the G-buffer pixel at the centre), 0 as a procedural one.
  float sample_offset = 0.0f;
  // Every pixel the value of `f` where its fragment was shaded.
  template <typename F>
  void shade_with(F f) {
    for (int y = 0; y < H; ++y) {
      for (int x = 0; x < W; ++x) {
        const ShadingRate r = shaded_at(x, y);
        const double ox = r.width > 1 ? sample_offset : 0.0,
                     oy = r.height > 1 ? sample_offset : 0.0;
        const float v =
            float(f((x / r.width + 0.5) * r.width + ox, (y / r.height + 0.5) * r.height + oy));
        for (int c = 0; c < 3; ++c) rgba[size_t((y * W + x) * 4 + c)] = v;
      }
    }
  }
  // The frame put together, read back (rows from the top).
  Image reconstruct() const {
    gpu::Texture src = gpu::Texture::create_2d(GL_RGBA32F, W, H);
    src.set_filter(GL_LINEAR, GL_LINEAR);  // as vrs.cpp sets its frame
    src.upload(W, H, GL_RGBA, GL_FLOAT, rgba.data());
    const auto classes = [](const std::vector<std::uint8_t>& c) {
      gpu::Texture t = gpu::Texture::create_2d(GL_R8UI, kGx, kGy);
      t.set_filter(GL_NEAREST, GL_NEAREST);
      t.upload(kGx, kGy, GL_RED_INTEGER, GL_UNSIGNED_BYTE, c.data());
      return t;
    };
    const gpu::Texture shade_t = classes(shade), own_t = classes(own);
    gpu::RenderTarget t;
    t.ensure(W, H, GL_RGBA8);
    t.clear(0, 0, 0, 1);
    PassKit kit;
    kit.rect_pass(kit.over_rects("vrs/hardware_reconstruct.frag"), {{kTile, 0, W, H}}, t, {},
                  [&](const gpu::Program& p, gpu::Samplers& smp) {
                    smp.bind(p, "u_frame", src);
                    smp.bind(p, "u_shade", shade_t);
                    smp.bind(p, "u_own", own_t);
                    for (int k = 0; k < 7; ++k) {
                      const std::string e = "u_rates[" + std::to_string(k) + "]";
                      p.set(e.c_str(), float(kShadingRates[size_t(k)].width),
                            float(kShadingRates[size_t(k)].height));
                    }
                    p.set("u_tile", kTile);
                    p.set("u_sample_offset", sample_offset);
                  });
    return gpu::read_framebuffer(t.framebuffer(), W, H);
  }
};

TEST_F(RectPassTest, VrsHardwareReconstructionInterpolatesFragmentCentres) {
  // On a linear ramp, interpolating between the points where fragments were
  // shaded (and, in the fading column, between the means of 4x4 blocks)
  // gives the ramp back within a code away from the screen's edge, where the
  // driver's blocks are off by up to 5 codes; the 1x1 tiles are not drawn.
  // Both for a procedural scene (shaded at the centre) and a deferred one.
  for (const float offset : {0.0f, 0.5f}) {
    SCOPED_TRACE(offset);
    HardwareVrsFrame f;
    using F = HardwareVrsFrame;
    f.sample_offset = offset;
    const auto ramp = [](double x, double y) { return 0.05 + 0.0075 * x + 0.003 * y; };
    f.shade_with(ramp);
    const Image img = f.reconstruct();
    int checked = 0;
    double worst_block = 0;
    for (int y = 0; y < F::H; ++y) {
      for (int x = 0; x < F::W; ++x) {
        const int got = img.at(x, F::H - 1 - y)[0];
        if (x < F::kTile) {
          EXPECT_EQ(got, 0) << x << "," << y;  // not drawn
          continue;
        }
        if (y < 2 || y >= F::H - 2 || x >= F::W - 2) continue;  // centres clamped at the edge
        ++checked;
        const double want = 255.0 * ramp(x + 0.5, y + 0.5);
        EXPECT_NEAR(got, want, 1.0) << x << "," << y;
        worst_block =
            std::max(worst_block, std::abs(255.0 * f.rgba[size_t((y * F::W + x) * 4)] - want));
      }
    }
    EXPECT_GT(checked, 3000);
    EXPECT_GT(worst_block, 4.0);  // the blocks alone would fail
  }
}

TEST_F(RectPassTest, VrsHardwareReconstructionFadesIntoTheFinerTile) {
  // A one-pixel checkerboard shaded 1x1 next to the 1x1 tiles, and flat
  // beyond (4x4 fragments of it, prefiltered): across the fading column the
  // contrast falls from the checkerboard's at the 1x1 border to nothing one
  // tile away, where the flat 4x4 tiles begin, and the mean stays.
  HardwareVrsFrame f;
  using F = HardwareVrsFrame;
  f.shade_with([](double x, double y) {
    return x >= 2 * F::kTile ? 0.5 : (int(x) + int(y)) % 2 ? 0.8 : 0.2;
  });
  const Image img = f.reconstruct();
  const auto contrast =
      [&](int x) {  // mean |step| to the right neighbour over the middle row of tiles
        double c = 0;
        for (int y = F::kTile; y < 2 * F::kTile; ++y)
          c += std::abs(int(img.at(x + 1, y)[0]) - int(img.at(x, y)[0])) / 255.0;
        return c / F::kTile;
      };
  EXPECT_GT(contrast(F::kTile), 0.5);           // 0.6 for the checkerboard itself
  EXPECT_LT(contrast(2 * F::kTile - 3), 0.08);  // nearly flat by the far side
  EXPECT_GT(contrast(F::kTile), contrast(F::kTile + 6));
  EXPECT_GT(contrast(F::kTile + 6), contrast(F::kTile + 11));
  double mean = 0;
  for (int y = F::kTile; y < 2 * F::kTile; ++y)
    for (int x = F::kTile; x < 2 * F::kTile; ++x) mean += img.at(x, y)[0];
  EXPECT_NEAR(mean / (F::kTile * F::kTile), 127.5, 3.0);
}

}  // namespace
}  // namespace foveate::tech
