// vrs with a GL context (the fixture fails a test on any GL debug error).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "../../techniques/vrs/busy_tiles.hpp"
#include "../../techniques/vrs/content_adapt.hpp"
#include "foveate/core/shading_rate.hpp"
#include "foveate/gpu/frame.hpp"
#include "foveate/techniques/pass_kit.hpp"
#include "gl_fixture.hpp"

namespace foveate::tech {
namespace {

class Vrs : public test::GlTest {};

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

TEST_F(Vrs, HardwareReconstructionInterpolatesFragmentCentres) {
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

TEST_F(Vrs, HardwareReconstructionFadesIntoTheFinerTile) {
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

// A class target's sRGB bytes for class `k` of a w x h frame in tiles of
// `tile` pixels: `fill(i, j, tx, ty, p)` sets texel (i, j) of tile (tx, ty),
// `p` its four bytes.
struct ClassTarget {
  int tw, th;
  std::vector<std::uint8_t> rgba;
  template <typename F>
  ClassTarget(int k, int w, int h, int tile, F fill)
      : tw((w + kShadingRates[size_t(k)].width - 1) / kShadingRates[size_t(k)].width),
        th((h + kShadingRates[size_t(k)].height - 1) / kShadingRates[size_t(k)].height),
        rgba(size_t(tw * th * 4)) {
    const ShadingRate r = kShadingRates[size_t(k)];
    for (int j = 0; j < th; ++j)
      for (int i = 0; i < tw; ++i)
        fill(i, j, i * r.width / tile, j * r.height / tile, &rgba[size_t((j * tw + i) * 4)]);
  }
  // The target as the emulation keeps it (sRGB: fetched linear).
  [[nodiscard]] gpu::Texture texture() const {
    gpu::Texture t = gpu::Texture::create_2d(GL_SRGB8_ALPHA8, tw, th);
    t.upload(tw, th, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    return t;
  }
};

TEST_F(Vrs, BusyTilesOnTheGpuAreTheCpuMeasuresBusyTiles) {
  // vrs adapt measures on the GPU (busy_tiles.comp); ContentAdapt::measure
  // is its reference. Tiles of 16 px on a 192 x 90 frame (the top row 10 px
  // high), of every class, their targets grey at levels far apart in
  // luminance (so no pair lies near the threshold): a tile flat, or changing
  // level at some of its texels, with some texels left unshaded (alpha 0).
  constexpr int kTile = 16, W = 192, H = 90, gx = 12, gy = 6;
  constexpr double kContrast = 0.25, kShare = 0.5;
  const std::uint8_t levels[4] = {30, 90, 160, 250};
  std::vector<std::uint8_t> classes(size_t(gx * gy));
  for (size_t t = 0; t < classes.size(); ++t) classes[t] = std::uint8_t(t % 7);
  gpu::Texture classes_t = gpu::Texture::create_2d(GL_R8UI, gx, gy);
  classes_t.set_filter(GL_NEAREST, GL_NEAREST);
  classes_t.upload(gx, gy, GL_RED_INTEGER, GL_UNSIGNED_BYTE, classes.data());
  PassKit kit;
  vrs::BusyTiles gpu_busy(kContrast, kShare);
  gpu_busy.begin(kit, gx, gy);
  std::vector<int> cpu_busy(classes.size(), 0);
  std::vector<gpu::Texture> targets;
  for (int k = 1; k < 7; ++k) {
    const ShadingRate r = kShadingRates[size_t(k)];
    const ClassTarget c(k, W, H, kTile, [&](int i, int j, int tx, int ty, std::uint8_t* p) {
      const unsigned h =
          unsigned(i) * 73856093u ^ unsigned(j) * 19349663u ^ unsigned(k) * 83492791u;
      // Per tile, how often a texel leaves the tile's level: never, a
      // third, or two thirds of the time.
      const unsigned busyness = unsigned(tx * 7 + ty * 3 + k) % 3;
      const bool changes = (h >> 4) % 3 < busyness;
      p[0] = p[1] = p[2] = levels[changes ? (h >> 8) % 4 : unsigned(tx + ty) % 4];
      p[3] = (h >> 12) % 11 == 0 ? 0 : 255;
    });
    const int tw = c.tw, th = c.th;
    const std::vector<std::uint8_t>& rgba = c.rgba;
    targets.push_back(c.texture());
    gpu_busy.measure(classes_t, targets.back(), k, kTile, W, H);
    // The CPU's verdict on this class's tiles: a fresh object holds exactly
    // the tiles it found busy.
    vrs::ContentAdapt cpu(kContrast, kShare, 8);
    cpu.reset(gx, gy);
    cpu.measure(rgba, tw, th, r, classes, k, false, kTile, W, H);
    cpu.settle();
    for (size_t t2 = 0; t2 < classes.size(); ++t2)
      if (classes[t2] == k) cpu_busy[t2] = cpu.held(t2) ? 1 : 0;
  }
  gpu_busy.queue();
  ASSERT_TRUE(gpu_busy.pending());
  std::vector<int> found;
  gpu_busy.read([&](std::span<const std::uint8_t> b) { found.assign(b.begin(), b.end()); });
  EXPECT_FALSE(gpu_busy.pending());
  ASSERT_EQ(found.size(), classes.size());
  int busy = 0, mismatched = 0;
  for (size_t t = 0; t < classes.size(); ++t) {
    busy += cpu_busy[t];
    if (found[t] != cpu_busy[t]) ++mismatched;
    EXPECT_EQ(found[t], cpu_busy[t])
        << "tile " << t % gx << "," << t / gx << " class " << int(classes[t]);
  }
  // Both verdicts occur among the measured tiles (class 0 is never busy).
  const int measured = gx * gy - (gx * gy + 6) / 7;
  EXPECT_GT(busy, measured / 5);
  EXPECT_LT(busy, measured * 4 / 5);
  EXPECT_EQ(mismatched, 0);
}

TEST_F(Vrs, SmoothTilesOnTheGpuAreTheCpuReferencesSmoothTiles) {
  // vrs smooth judges on the GPU (busy_tiles.comp, bit 1) what
  // vrs::smooth_texels judges on the CPU, at the bound for a tile at 1x1 or
  // 2x2 not refined and at four times it for a coarsened tile (bit 6 of its
  // class byte); a 4x4 tile not coarsened and a refined tile are not judged.
  // Tiles of 16 px on a 192 x 90 frame, of classes 1x1, 2x2 and 4x4, each a
  // flat grey with, by tile, no bump, a middling one (+6 codes: 0.095 of
  // its luminance, between the bound 0.05 and four times it) or a large one
  // (+20: 0.27, over four times it), and here and there a texel unshaded; the grey is the same in
  // every tile (code 128), so that the tiles' borders are flat.
  constexpr int kTile = 16, W = 192, H = 90, gx = 12, gy = 6;
  constexpr double kSmooth = 0.05;
  const std::array<int, 3> cls = {0, 3, 6};
  std::vector<std::uint8_t> bytes(size_t(gx * gy));
  for (int t = 0; t < gx * gy; ++t) {
    const int own = cls[size_t(t % 3)];
    const bool refined = own == 3 && t % 4 == 1, coarsened = own != 0 && t % 5 == 2;
    bytes[size_t(t)] =
        std::uint8_t(own | (refined ? 6 : own) << 3 | (coarsened && !refined ? 64 : 0));
  }
  gpu::Texture classes_t = gpu::Texture::create_2d(GL_R8UI, gx, gy);
  classes_t.set_filter(GL_NEAREST, GL_NEAREST);
  classes_t.upload(gx, gy, GL_RED_INTEGER, GL_UNSIGNED_BYTE, bytes.data());
  PassKit kit;
  vrs::BusyTiles gpu(0.25, 0.0, kSmooth);
  gpu.begin(kit, gx, gy);
  std::vector<int> expected(bytes.size(), 0);
  std::vector<gpu::Texture> targets;
  for (const int k : cls) {
    const ShadingRate r = kShadingRates[size_t(k)];
    const ClassTarget c(k, W, H, kTile, [](int i, int j, int tx, int ty, std::uint8_t* p) {
      const int bump = (tx * 5 + ty * 3) % 3;  // none, middling, large
      const bool at_bump = i % 4 == 1 && j % 4 == 2;
      p[0] = p[1] = p[2] = std::uint8_t(128 + (at_bump ? (bump == 1 ? 6 : bump * 10) : 0));
      p[3] = (i * 7 + j * 13) % 29 == 3 ? 0 : 255;
    });
    const int tw = c.tw, th = c.th;
    const std::vector<std::uint8_t>& rgba = c.rgba;
    targets.push_back(c.texture());
    gpu.measure(classes_t, targets.back(), k, kTile, W, H);
    for (int ty = 0; ty < gy; ++ty) {
      for (int tx = 0; tx < gx; ++tx) {
        const size_t i = size_t(ty * gx + tx);
        if ((bytes[i] & 7) != k) continue;
        const bool coarsened = (bytes[i] & 64) != 0, refined = (bytes[i] >> 3 & 7) != k;
        if (!coarsened && (refined || k == 6)) continue;
        const PixelRect texels = {tx * kTile / r.width, ty * kTile / r.height,
                                  (std::min((tx + 1) * kTile, W) - 1) / r.width + 1,
                                  (std::min((ty + 1) * kTile, H) - 1) / r.height + 1};
        expected[i] =
            vrs::smooth_texels(rgba, tw, th, texels, (coarsened ? 4.0 : 1.0) * kSmooth) ? 1 : 0;
      }
    }
  }
  gpu.queue();
  std::vector<int> found;
  gpu.read([&](std::span<const std::uint8_t> b) {
    for (const std::uint8_t v : b) found.push_back(v);
  });
  ASSERT_EQ(found.size(), expected.size());
  int smooth = 0, judged_rough = 0, middling_coarse = 0, middling_fine = 0;
  for (size_t t = 0; t < expected.size(); ++t) {
    EXPECT_EQ(found[t] & 1, 0) << "tile " << t << ": busy, with adapt off";
    EXPECT_EQ(found[t] >> 1 & 1, expected[t])
        << "tile " << t % gx << "," << t / gx << " byte " << int(bytes[t]);
    smooth += expected[t];
    judged_rough += (bytes[t] & 7) != 6 && !expected[t];
    if ((int(t % gx) * 5 + int(t / gx) * 3) % 3 == 1 && expected[t])
      ++((bytes[t] & 64) ? middling_coarse : middling_fine);
  }
  // Both verdicts occur, and coarsened tiles are held smooth by the
  // middling bump that tiles at the model's rate are not.
  EXPECT_GT(smooth, 8);
  EXPECT_GT(judged_rough, 8);
  EXPECT_GT(middling_coarse, 0);
  EXPECT_EQ(middling_fine, 0);
}

}  // namespace
}  // namespace foveate::tech
