// Shading-rate images: hand-worked tiles on the paper's display and on the
// headset preset, monotonicity, supported sets, encodings against the API
// specifications, the latency travel, the grid origin and bad input.
#include "foveate/core/shading_rate.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "foveate/core/error.hpp"

namespace foveate {
namespace {

const Display& preset(const std::string& name) {
  static const Display d1 = Display::load("desktop-1080p");
  static const Display d2 = Display::load("hmd-quest3");
  return name == "hmd-quest3" ? d2 : d1;
}

ShadingRate tile(const Display& d, Vec2d gaze, int tx, int ty, ShadingRateOptions o = {}) {
  return shading_rate_image(d, AcuityModel::preset("A"), gaze, o).at(tx, ty);
}

// Guenter et al.'s display: 1920 px over 510 mm viewed from 590 mm, so the eye
// is f = 590 * 1920 / 510 = 2221.18 px from the screen; a pixel at the centre
// subtends atan(1 / f) = 0.02580 deg (38.8 px per degree). Quality A:
// w(e) = 0.0275 e + 1/48 deg. Gaze at the centre (960, 540); 16-px tiles, so
// tile row 33 spans y 528..544 and contains the gaze's row.
TEST(ShadingRate, DesktopHandWorkedTiles) {
  const Display& d = preset("desktop-1080p");
  const Vec2d g{960, 540};
  // The tile at the gaze: e = 0, w = 0.02083 deg, half a cycle 0.0104 deg is
  // less than one pixel (0.0258 deg): 1x1.
  EXPECT_EQ(tile(d, g, 60, 33), (ShadingRate{1, 1}));
  // Tile 65 (x 1040..1056): nearest point (1040, 540), 80 px from the gaze,
  // e = atan(80 / 2221.18) = 2.063 deg, w = 0.0776 deg, half 0.0388 deg; one
  // pixel step subtends 0.02576 deg: at most 1.50 pixels per sample: 1x1.
  EXPECT_EQ(tile(d, g, 65, 33), (ShadingRate{1, 1}));
  // Tile 70 (x 1120..1136): 160 px, e = 4.120 deg, w = 0.1341 deg, half
  // 0.0671 deg over 0.02566 (x) and 0.02573 (y) deg per pixel: 2.61 and 2.61
  // pixels per sample: 2x2 (not 4).
  EXPECT_EQ(tile(d, g, 70, 33), (ShadingRate{2, 2}));
  // The tile at 20 degrees: f tan 20 = 808 px right of the gaze, x = 1768, in
  // tile 110 (x 1760..1776). Its nearest point is 800 px away,
  // e = atan(800 / 2221.18) = 19.81 deg, w = 0.0275 * 19.81 + 0.02083 =
  // 0.5655 deg, half a cycle 0.2828 deg. There a step along x subtends
  // f / (800^2 + f^2) = 0.02283 deg and along y 1 / sqrt(800^2 + f^2) =
  // 0.02427 deg: 12.4 and 11.7 pixels per sample are allowed, so the
  // coarsest rate, 4x4.
  EXPECT_EQ(tile(d, g, 110, 33), (ShadingRate{4, 4}));
  // With only 1x1 and 2x2 supported the same tile gets 2x2.
  ShadingRateOptions o;
  o.supported = {{1, 1}, {2, 2}};
  EXPECT_EQ(tile(d, g, 110, 33, o), (ShadingRate{2, 2}));
  // The same tile with a 16-degree latency travel: e = 3.81 deg, w = 0.1255,
  // half 0.0628 deg: 2.75 (x) and 2.59 (y) pixels per sample: 2x2.
  o = {};
  o.latency_travel_deg = 16.0;
  EXPECT_EQ(tile(d, g, 110, 33, o), (ShadingRate{2, 2}));
}

// hmd-quest3: 2064 x 2208 per eye, 104 degrees horizontally, so
// f = 1032 / tan 52 = 806.29 px (14.07 px per degree at the centre). Gaze at
// the centre (1032, 1104); tile row 69 spans y 1104..1120.
TEST(ShadingRate, HeadsetHandWorkedTiles) {
  const Display& d = preset("hmd-quest3");
  const Vec2d g{1032, 1104};
  EXPECT_EQ(tile(d, g, 64, 69), (ShadingRate{1, 1}));  // at the gaze
  // Tile 72 (x 1152..1168): 120 px, e = 8.465 deg, w = 0.2536, half 0.1268 deg
  // over 0.06952 deg per pixel: 1.82: 1x1.
  EXPECT_EQ(tile(d, g, 72, 69), (ShadingRate{1, 1}));
  // Tile 73 (x 1168..1184): 136 px, e = 9.574 deg, w = 0.2841, half 0.1421 deg
  // over 0.06910 (x) and 0.07007 (y) deg per pixel: 2.06 and 2.03: 2x2.
  EXPECT_EQ(tile(d, g, 73, 69), (ShadingRate{2, 2}));
  // Tile 81 (x 1296..1312): 264 px, e = 18.13 deg, w = 0.5194, half 0.2597 deg;
  // a step along x subtends f / (264^2 + f^2) = 0.06418 deg, along y
  // 1 / sqrt(264^2 + f^2) = 0.06753 deg: 4.05 and 3.85 pixels per sample. 4x4
  // would undersample vertically; 4x2 fits: an anisotropic rate.
  EXPECT_EQ(tile(d, g, 81, 69), (ShadingRate{4, 2}));
  // Tile 93 (x 1488..1504): 456 px, e = 29.49 deg, w = 0.8318: 7.7 and 6.7: 4x4.
  EXPECT_EQ(tile(d, g, 93, 69), (ShadingRate{4, 4}));
}

// Moving a tile away from the gaze along its row or column never makes its
// rate finer (fewer pixels per invocation), as long as the step does not also
// move towards the display centre, where pixels subtend more (a tile nearer
// the centre may rightly need a finer rate than one nearer the gaze). Checked
// with the gaze at the centre on both presets and off-centre on the desktop.
// Not off-centre on the headset's 104-degree pinhole: there, along a column
// far from the gaze, the angle from the gaze is smallest well above or below
// the gaze's row (the column is an arc of a great circle), so stepping away
// in pixels can lower the eccentricity itself.
TEST(ShadingRate, MonotoneInEccentricity) {
  for (const char* name : {"desktop-1080p", "hmd-quest3"}) {
    const Display& d = preset(name);
    std::vector<Vec2d> gazes = {{0.5 * d.width_px, 0.5 * d.height_px}};
    if (!d.head_mounted()) gazes.insert(gazes.end(), {{300, 200}, {d.width_px - 100.0, 540}});
    for (Vec2d g : gazes) {
      const ShadingRateImage img = shading_rate_image(d, AcuityModel::preset("A"), g);
      const auto gt = img.tile_of(int(g.x), int(g.y));
      const auto ct = img.tile_of(d.width_px / 2, d.height_px / 2);
      int checked = 0;
      for (int ty = 0; ty < img.tiles_y; ++ty) {
        for (int tx = 0; tx < img.tiles_x; ++tx) {
          const int sx = tx > gt[0] ? 1 : -1, sy = ty > gt[1] ? 1 : -1;
          // Not towards the centre: already on the far side of it, or level with it.
          const bool x_out = (tx - ct[0]) * sx >= 0, y_out = (ty - ct[1]) * sy >= 0;
          if (tx != gt[0] && x_out && tx + sx >= 0 && tx + sx < img.tiles_x) {
            EXPECT_LE(img.at(tx, ty).pixels(), img.at(tx + sx, ty).pixels())
                << name << " tile " << tx << "," << ty;
            ++checked;
          }
          if (ty != gt[1] && y_out && ty + sy >= 0 && ty + sy < img.tiles_y) {
            EXPECT_LE(img.at(tx, ty).pixels(), img.at(tx, ty + sy).pixels())
                << name << " tile " << tx << "," << ty;
            ++checked;
          }
        }
      }
      EXPECT_GT(checked, 2000);
      EXPECT_EQ(img.at(gt[0], gt[1]), (ShadingRate{1, 1}));
      EXPECT_GT(img.fraction({4, 4}), 0.3) << name;  // the periphery is coarse
    }
  }
}

TEST(ShadingRate, OnlySupportedRatesAndFractions) {
  const Display& d = preset("desktop-1080p");
  ShadingRateOptions o;
  o.tile_px = 8;
  o.supported = {{1, 1}, {2, 1}, {4, 2}};
  const ShadingRateImage img = shading_rate_image(d, AcuityModel::preset("B"), {960, 540}, o);
  EXPECT_EQ(img.tiles_x, 240);
  EXPECT_EQ(img.tiles_y, 135);
  double sum = 0.0;
  for (ShadingRate r : kShadingRates) {
    const bool supported =
        std::find(o.supported.begin(), o.supported.end(), r) != o.supported.end();
    if (!supported) {
      EXPECT_EQ(img.fraction(r), 0.0) << r.name();
    }
    sum += img.fraction(r);
  }
  EXPECT_NEAR(sum, 1.0, 1e-12);
  EXPECT_GT(img.fraction({4, 2}), 0.5);
  EXPECT_GT(img.fraction({2, 1}), 0.0);
  // Invocations: per tile 8*8 / (rw*rh) (8 is a multiple of every rate).
  double expect = 0.0;
  for (ShadingRate r : kShadingRates) expect += img.fraction(r) * 1920.0 * 1080.0 / r.pixels();
  EXPECT_NEAR(img.shaded_samples(), expect, 1e-6);
  EXPECT_NEAR(img.pixel_ratio(), expect / (1920.0 * 1080.0), 1e-12);

  // Only 1x1: native, ratio exactly 1.
  o.supported = {{1, 1}};
  EXPECT_DOUBLE_EQ(shading_rate_image(d, AcuityModel{}, {960, 540}, o).pixel_ratio(), 1.0);
}

TEST(ShadingRate, PartialTilesAtTheEdgesCountWholeFragments) {
  // 20 x 10 screen, 16-px tiles: 2 x 1 tiles, the right one 4 x 10 pixels.
  Display d = preset("desktop-1080p").resized(20, 10);
  ShadingRateImage img;
  img.width_px = 20;
  img.height_px = 10;
  img.tile_px = 16;
  img.tiles_x = 2;
  img.tiles_y = 1;
  img.rates = {{4, 4}, {4, 4}};
  // ceil(16/4) * ceil(10/4) + ceil(4/4) * ceil(10/4) = 4*3 + 1*3 = 15.
  EXPECT_DOUBLE_EQ(img.shaded_samples(), 15.0);
  EXPECT_NEAR(img.fraction({4, 4}), 1.0, 1e-12);
  EXPECT_EQ(shading_rate_image(d, AcuityModel{}, {10, 5}).rates.size(), 2u);
}

// Vulkan: attachment texel = log2(width) << 2 | log2(height) (Vulkan spec,
// "Attachment Fragment Shading Rate"). D3D12: the D3D12_SHADING_RATE values of
// d3d12.h. GL_NV_shading_rate_image: the index into our palette, whose entries
// are the extension's GL_SHADING_RATE_1_INVOCATION_PER_* tokens.
TEST(ShadingRate, EncodingsMatchTheSpecifications) {
  struct Row {
    ShadingRate r;
    int vulkan, d3d12, gl_index;
    unsigned gl_enum;
  };
  const Row rows[] = {{{1, 1}, 0, 0x0, 0, 0x9565}, {{1, 2}, 1, 0x1, 1, 0x9566},
                      {{2, 1}, 4, 0x4, 2, 0x9567}, {{2, 2}, 5, 0x5, 3, 0x9568},
                      {{2, 4}, 6, 0x6, 4, 0x9569}, {{4, 2}, 9, 0x9, 5, 0x956A},
                      {{4, 4}, 10, 0xa, 6, 0x956B}};
  for (const Row& row : rows) {
    EXPECT_EQ(encode_shading_rate(row.r, RateApi::Vulkan), row.vulkan) << row.r.name();
    EXPECT_EQ(encode_shading_rate(row.r, RateApi::D3D12), row.d3d12) << row.r.name();
    const int idx = encode_shading_rate(row.r, RateApi::GlNv);
    EXPECT_EQ(idx, row.gl_index) << row.r.name();
    EXPECT_EQ(gl_nv_palette()[static_cast<size_t>(idx)], row.gl_enum) << row.r.name();
  }
  EXPECT_THROW(encode_shading_rate({3, 3}, RateApi::Vulkan), Error);
  // The list is ordered by pixels per fragment (the vrs technique's shaders
  // rely on it: a higher index is coarser).
  for (size_t i = 1; i < kShadingRates.size(); ++i) {
    EXPECT_LE(kShadingRates[i - 1].pixels(), kShadingRates[i].pixels());
  }
}

TEST(ShadingRate, LatencyMarginShrinksTheCoarseArea) {
  const Display& d = preset("desktop-1080p");
  ShadingRateOptions o;
  const auto a = shading_rate_image(d, AcuityModel::preset("A"), {960, 540}, o);
  o.latency_travel_deg = 5.0;  // e.g. 25 ms at 200 deg/s
  const auto b = shading_rate_image(d, AcuityModel::preset("A"), {960, 540}, o);
  EXPECT_LT(b.fraction({4, 4}), a.fraction({4, 4}) - 0.05);
  EXPECT_GT(b.fraction({1, 1}), a.fraction({1, 1}));
  EXPECT_GT(b.pixel_ratio(), a.pixel_ratio());
  for (size_t i = 0; i < a.rates.size(); ++i) EXPECT_LE(b.rates[i].pixels(), a.rates[i].pixels());
}

TEST(ShadingRate, FoveaScaleWidensTheFinerRates) {
  // A tracker's fallback divides eccentricities by its scale: the 20-degree
  // tile of the desktop at scale 4 is at 4.95 deg (w = 0.157 deg, 3.4 and 3.2
  // pixels per sample): 2x2 instead of 4x4.
  ShadingRateOptions o;
  o.fovea_scale = 4.0;
  EXPECT_EQ(tile(preset("desktop-1080p"), {960, 540}, 110, 33, o), (ShadingRate{2, 2}));
}

TEST(ShadingRate, BottomLeftOriginFlipsTheRows) {
  // 320 x 160 (10 tile rows of 16): the OpenGL grid is the Vulkan one upside down.
  const Display d = preset("desktop-1080p").resized(320, 160);
  ShadingRateOptions o;
  const auto top = shading_rate_image(d, AcuityModel::preset("A"), {100, 30}, o);
  o.origin_bottom_left = true;
  const auto bottom = shading_rate_image(d, AcuityModel::preset("A"), {100, 30}, o);
  ASSERT_EQ(top.tiles_y, 10);
  bool differs = false;
  for (int ty = 0; ty < 10; ++ty) {
    for (int tx = 0; tx < top.tiles_x; ++tx) {
      EXPECT_EQ(top.at(tx, ty), bottom.at(tx, 9 - ty));
      differs |= !(top.at(tx, ty) == bottom.at(tx, ty));
    }
  }
  EXPECT_TRUE(differs);  // the gaze is off the middle row, so the flip shows
  // 1080 is not a multiple of 16: the partial row is the last one in both orders.
  ShadingRateImage g;
  g.width_px = 1920;
  g.height_px = 1080;
  g.tile_px = 16;
  g.origin_bottom_left = true;
  EXPECT_EQ(g.tile_rect(0, 0), (std::array<int, 4>{0, 1064, 16, 1080}));
  EXPECT_EQ(g.tile_rect(0, 67), (std::array<int, 4>{0, 0, 16, 8}));
  EXPECT_EQ(g.tile_of(0, 1079), (std::array<int, 2>{0, 0}));
}

TEST(ShadingRate, PlannerReusedAcrossGazesMatchesEachTileWorkedAlone) {
  // One planner, many gazes, latency travels and scales: every tile's rate is the one
  // tile_shading_rate works out for that tile from scratch (a planner that
  // kept anything of an earlier gaze would differ), on a desktop, a headset
  // and a headset seen through its lens; and shading_rate_image agrees.
  const AcuityModel a = AcuityModel::preset("A");
  for (const char* name : {"desktop-1080p", "hmd-quest3", "hmd-quest2-lens"}) {
    SCOPED_TRACE(name);
    const Display d = Display::load(name).resized(480, 270);
    ShadingRateOptions o;
    o.origin_bottom_left = true;
    const ShadingRatePlanner p(d, a, o);
    int coarse = 0;
    for (const Vec2d g : {Vec2d{240, 135}, Vec2d{10, 260}, Vec2d{479, 0}, Vec2d{-200, 135}}) {
      for (const auto& [travel, scale] :
           {std::pair{0.0, 1.0}, std::pair{3.0, 1.0}, std::pair{0.0, 2.5}}) {
        ShadingRateOptions q = o;
        q.latency_travel_deg = travel;
        q.fovea_scale = scale;
        const ShadingRateImage img = p.image(g, travel, scale);
        ASSERT_EQ(img.rates.size(), size_t(img.tiles_x * img.tiles_y));
        for (int ty = 0; ty < img.tiles_y; ++ty) {
          for (int tx = 0; tx < img.tiles_x; ++tx) {
            const ShadingRate r = img.at(tx, ty);
            ASSERT_EQ(r, tile_shading_rate(d, a, g, img.tile_rect(tx, ty), q)) << tx << "," << ty;
            coarse += r.pixels() > 1 ? 1 : 0;
          }
        }
        EXPECT_EQ(img.rates, shading_rate_image(d, a, g, q).rates);
      }
    }
    EXPECT_GT(coarse, 0);  // not all 1x1: the comparison sees rates change
  }
  const ShadingRatePlanner p(preset("desktop-1080p"), a);
  EXPECT_THROW((void)p.image({std::nan(""), 0}), Error);
  EXPECT_THROW((void)p.image({960, 540}, -1.0), Error);
  EXPECT_THROW((void)p.image({960, 540}, 0.0, 0.5), Error);
}

TEST(ShadingRate, BadInputIsRefused) {
  const Display& d = preset("desktop-1080p");
  auto fails = [&](ShadingRateOptions o, const std::string& what) {
    try {
      (void)shading_rate_image(d, AcuityModel{}, {960, 540}, o);
      ADD_FAILURE() << "accepted " << what;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  ShadingRateOptions o;
  o.tile_px = 12;
  fails(o, "tile: expected 8, 16 or 32 pixels, got 12");
  EXPECT_TRUE(is_shading_rate_tile(32));
  EXPECT_FALSE(is_shading_rate_tile(4));
  o = {};
  o.latency_travel_deg = -1.0;
  fails(o, "latency travel");
  o.latency_travel_deg = std::nan("");
  fails(o, "latency travel");
  o = {};
  o.fovea_scale = 0.5;
  fails(o, "fovea scale");
  o = {};
  o.supported = {{2, 2}};
  fails(o, "1x1");
  o.supported = {{1, 1}, {3, 1}};
  fails(o, "3x1");
  EXPECT_THROW((void)shading_rate_image(d, AcuityModel{}, {std::nan(""), 0}), Error);
  EXPECT_EQ(parse_shading_rates("1x1,4x4").size(), 2u);
  EXPECT_THROW(parse_shading_rates("2x2,4x4"), Error);  // no 1x1
  EXPECT_THROW(parse_shading_rates("1x1,1x1"), Error);
  EXPECT_THROW(parse_shading_rates("1x1,"), Error);
  EXPECT_THROW(parse_shading_rate("8x8"), Error);
  EXPECT_THROW(parse_rate_api("metal"), Error);
  EXPECT_EQ(parse_rate_api("gl-nv"), RateApi::GlNv);
}

}  // namespace
}  // namespace foveate
