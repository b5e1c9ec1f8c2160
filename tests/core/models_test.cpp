#include "foveate/core/models.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "foveate/core/error.hpp"

using namespace foveate;

TEST(Swafford, ZeroLatencyIsThePlainFovea) {
  const Display d = Display::load("desktop-1080p");
  LatencyAwareFovea f;
  f.blend_border_px = 20;
  // 2 * f * tan(2.5 deg) + 2 * 20, with f = 590 mm * (1920 / 510) px/mm.
  const double expect = 2 * 590.0 * (1920.0 / 510.0) * std::tan(2.5 * M_PI / 180) + 40;
  EXPECT_NEAR(f.diameter_px(d), expect, 1e-9);
  EXPECT_NEAR(f.diameter_deg(d), 2 * std::atan((expect / 2) / d.eye_distance_px()) * 180 / M_PI,
              1e-9);
}

TEST(Swafford, PaperSetup4K28Inch) {
  // Section "Latency Aware...": a 28" 4K monitor viewed from 20". With near-zero
  // latency the fovea is about a third of the 1000 px they found sufficient.
  Display d;
  d.width_px = 3840;
  d.height_px = 2160;
  d.width_mm = 28 * 25.4 * 16 / std::hypot(16, 9);
  d.distance_mm = 20 * 25.4;
  LatencyAwareFovea f;
  f.blend_border_px = 30;
  const double zero = f.diameter_px(d);
  EXPECT_NEAR(zero, 1000.0 / 3.0, 15.0);
  // rho * d_u * tan(L S + a/2): 30 ms at 200 deg/s adds 6 degrees on each side.
  f.latency_ms = 30;
  const double expect = 2 * d.pixels_per_mm() * d.distance_mm * std::tan(8.5 * M_PI / 180) + 60;
  EXPECT_NEAR(f.diameter_px(d), expect, 1e-6);
  EXPECT_NEAR(f.diameter_px(d), 1000.0, 60.0);
}

TEST(Swafford, RejectsBadInput) {
  LatencyAwareFovea f;
  f.latency_ms = -1;
  EXPECT_THROW(f.validate(), Error);
  f.latency_ms = NAN;
  EXPECT_THROW(f.validate(), Error);
}

TEST(KernelLogPolar, RoundTrip) {
  for (double alpha : {1.0, 2.0, 4.0}) {
    for (double sigma : {1.2, 1.8, 2.4}) {
      KernelLogPolar k{1920, 1080, sigma, alpha};
      const Vec2d gaze{700, 400};
      for (double x = 0; x < 1920; x += 97.3) {
        for (double y = 0; y < 1080; y += 61.7) {
          if (std::hypot(x - gaze.x, y - gaze.y) < 1.0) continue;
          const Vec2d b = k.to_buffer({x, y}, gaze);
          EXPECT_GE(b.x, 0.0);
          EXPECT_LE(b.x, k.buffer_w() + 1e-9);
          const Vec2d s = k.to_screen(b, gaze);
          EXPECT_NEAR(s.x, x, 1e-3);
          EXPECT_NEAR(s.y, y, 1e-3);
        }
      }
    }
  }
}

TEST(KernelLogPolar, MatchesTheMapping) {
  KernelLogPolar k{1920, 1080, 2.0, 2.0};
  const double L = std::log(std::hypot(1920, 1080));
  EXPECT_DOUBLE_EQ(k.log_extent(), L);
  EXPECT_DOUBLE_EQ(k.buffer_w(), 960);
  // A point 100 px below-right of the gaze: u = sqrt(log(r) / L) * w; v from the angle.
  const Vec2d b = k.to_buffer({100, 100}, {0, 0});
  EXPECT_NEAR(b.x, std::sqrt(std::log(std::hypot(100, 100)) / L) * 960, 1e-9);
  EXPECT_NEAR(b.y, 0.125 * 540, 1e-9);
  // Negative y: the angle is moved into [0, 2 pi).
  EXPECT_NEAR(k.to_buffer({100, -100}, {0, 0}).y, 0.875 * 540, 1e-9);
  // The far corner maps to the end of the buffer only when the gaze is in the opposite corner.
  EXPECT_NEAR(k.to_buffer({1920, 1080}, {0, 0}).x, 960, 1e-9);
  // With alpha > 1 the fovea gets more of the buffer than with alpha = 1.
  KernelLogPolar k1{1920, 1080, 2.0, 1.0};
  EXPECT_GT(k.to_buffer({50, 0}, {0, 0}).x, k1.to_buffer({50, 0}, {0, 0}).x);
  k.sigma = 0.5;
  EXPECT_THROW(k.validate(), Error);
}

// Every texel whose jittered centre maps outside the disc and inside the kept
// rectangle lies in the cover, and the cover leaves out most of what a
// full-buffer pass would run at a 1080p plan (the disc and the corners).
TEST(KernelLogPolar, CoverHoldsEveryTexelThatIsShaded) {
  struct Case {
    int W, H, w, h;
    double alpha, inner;
    Vec2d gaze;
  };
  const Case cases[] = {{1920, 1080, 1752, 985, 1.25, 255, {960, 540}},
                        {1920, 1080, 960, 540, 2.0, 40, {20, 1000}},
                        {640, 360, 355, 200, 1.0, 0, {640, 0}},
                        {320, 180, 300, 170, 4.0, 60, {100, 90}},
                        {16, 2, 9, 1, 1.0, 0, {8, 1}}};
  for (const Case& c : cases) {
    const double far = std::max(
        {std::hypot(c.gaze.x, c.gaze.y), std::hypot(c.W - c.gaze.x, c.gaze.y),
         std::hypot(c.gaze.x, c.H - c.gaze.y), std::hypot(c.W - c.gaze.x, c.H - c.gaze.y)});
    const double L = std::log(far), m = 0.02 * std::hypot(c.W, c.H);
    const std::array<double, 4> keep{-m, -m, c.W + m, c.H + m};
    const auto cover = log_polar_cover(c.gaze, L, c.alpha, c.w, c.h, c.inner, keep);
    std::vector<char> in(static_cast<size_t>(c.w) * c.h, 0);
    double covered = 0;
    for (const auto& r : cover) {
      ASSERT_LE(0, r[0]);
      ASSERT_LT(r[0], r[2]);
      ASSERT_LE(r[2], c.w);
      ASSERT_LE(0, r[1]);
      ASSERT_LE(r[3], c.h);
      for (int y = r[1]; y < r[3]; ++y)
        for (int x = r[0]; x < r[2]; ++x) in[static_cast<size_t>(y) * c.w + x] = 1;
      covered += double(r[2] - r[0]) * (r[3] - r[1]);
    }
    double needed = 0;
    for (int y = 0; y < c.h; ++y) {
      for (int x = 0; x < c.w; ++x) {
        bool shaded = false;
        for (double jx : {-0.5, -0.2, 0.0, 0.3, 0.5}) {
          for (double jy : {-0.5, 0.0, 0.5}) {
            const double u = x + 0.5 + jx, v = y + 0.5 + jy;
            const double r = std::exp(L * std::pow(std::max(u / c.w, 0.0), c.alpha));
            const double a = v * 2.0 * std::numbers::pi / c.h;
            const Vec2d p{c.gaze.x + r * std::cos(a), c.gaze.y + r * std::sin(a)};
            shaded = shaded || (r >= c.inner && p.x >= keep[0] && p.y >= keep[1] &&
                                p.x <= keep[2] && p.y <= keep[3]);
          }
        }
        if (!shaded) continue;
        ++needed;
        ASSERT_TRUE(in[static_cast<size_t>(y) * c.w + x])
            << c.W << "x" << c.H << " texel " << x << "," << y;
      }
    }
    EXPECT_GT(needed, 0);
    EXPECT_LE(covered, 1.25 * needed + 8.0 * c.h) << c.W << "x" << c.H;
    if (c.W == 1920 && c.gaze.x == 960) {
      EXPECT_LT(covered, 0.3 * c.w * c.h);
    }
  }
  EXPECT_THROW(log_polar_cover({0, 0}, 0.0, 1.0, 10, 10, 0, {0, 0, 1, 1}), Error);
}

TEST(Checkerboard, PatternAndRegions) {
  CheckerboardPattern p;
  p.block = 2;
  p.thresholds_px = {10, 20, 30};
  const Vec2d g{0.5, 0.5};
  // Quads in a 4x4 tile: (0,0) kept always.
  EXPECT_EQ(p.quad({0.5, 0.5}), 0);
  EXPECT_EQ(p.quad({0.5, 2.5}), 1);
  EXPECT_EQ(p.quad({2.5, 0.5}), 2);
  EXPECT_EQ(p.quad({3.5, 3.5}), 3);
  EXPECT_EQ(p.quad({4.5, 4.5}), 0);
  // Block-aligned distance: every pixel of a tile has the tile's distance,
  // from the gaze to the tile's nearest point.
  EXPECT_DOUBLE_EQ(p.tile_distance({12.5, 0.5}, g), 11.5);
  EXPECT_DOUBLE_EQ(p.tile_distance({15.9, 3.9}, g), 11.5);
  EXPECT_DOUBLE_EQ(p.tile_distance({1.5, 2.5}, g), 0.0);  // the gaze's own tile
  EXPECT_DOUBLE_EQ(p.tile_distance({12.5, 12.5}, g), std::hypot(11.5, 11.5));
  EXPECT_EQ(p.region({8.5, 0.5}, g), 0);
  EXPECT_EQ(p.region({12.5, 0.5}, g), 1);
  EXPECT_EQ(p.region({24.5, 0.5}, g), 2);
  EXPECT_EQ(p.region({100.5, 0.5}, g), 3);
  // Region k keeps 4 - k of 4 quads: count over a large area.
  for (int k = 0; k < 4; ++k) {
    CheckerboardPattern q;
    q.block = 4;
    const double t = k == 0 ? 1e9 : -1;
    q.thresholds_px = {k >= 1 ? -1 : t, k >= 2 ? -1 : 1e9, k >= 3 ? -1 : 1e9};
    int kept = 0, total = 0;
    for (int y = 0; y < 64; ++y) {
      for (int x = 0; x < 64; ++x) {
        kept += q.kept({x + 0.5, y + 0.5}, {1000, 1000});
        ++total;
      }
    }
    EXPECT_EQ(kept * 4, total * (4 - k)) << "region " << k;
  }
}

TEST(Checkerboard, RegionZeroHoldsTheDiscOfItsRadius) {
  // Every pixel within thresholds_px[0] of the gaze is kept (region 0), for
  // any gaze inside a tile: no tile straddling the circle drops a quad.
  CheckerboardPattern p;
  p.block = 4;
  p.thresholds_px = {37.3, 50, 80};
  for (const Vec2d g : {Vec2d{100, 100}, Vec2d{103.7, 98.2}, Vec2d{7.9, 0.1}}) {
    for (int y = 0; y < 200; ++y) {
      for (int x = 0; x < 200; ++x) {
        const Vec2d px{x + 0.5, y + 0.5};
        if (std::hypot(px.x - g.x, px.y - g.y) <= p.thresholds_px[0]) {
          EXPECT_EQ(p.region(px, g), 0) << x << "," << y;
        }
      }
    }
  }
}

TEST(Checkerboard, KeptByRegionCountsEveryKeptPixel) {
  // Against kept() and region() pixel by pixel: screens that end inside a
  // tile and inside a quad, gazes inside, at the edge of and off the screen;
  // thresholds that tiles' distances meet exactly (a gaze on tile corners),
  // thresholds that do not nest (unvalidated), and a gaze that is no point.
  struct Case {
    int block, width, height;
    Vec2d gaze;
    std::array<double, 3> thresholds = {6.0, 13.0, 21.5};
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const Case c :
       {Case{2, 37, 23, {11.2, 9.7}}, Case{4, 101, 57, {0.0, 0.0}}, Case{3, 64, 48, {70.5, -8.0}},
        Case{1, 9, 5, {4.5, 2.5}}, Case{4, 3, 2, {1.0, 1.0}},
        Case{1, 301, 173, {150.0, 86.0}, {4.0, 4.0, 10.0}},
        Case{1, 300, 170, {1e9, 80.0}, {4.0, 9.0, 1e9 - 200.0}},
        Case{2, 41, 29, {20.0, 12.0}, {13.0, 6.0, 21.5}}, Case{1, 20, 10, {nan, 3.0}}}) {
    CheckerboardPattern p;
    p.block = c.block;
    p.thresholds_px = c.thresholds;
    std::array<double, 4> expected{};
    for (int y = 0; y < c.height; ++y) {
      for (int x = 0; x < c.width; ++x) {
        const Vec2d px{x + 0.5, y + 0.5};
        if (p.kept(px, c.gaze)) expected[static_cast<size_t>(p.region(px, c.gaze))] += 1.0;
      }
    }
    const auto got = p.kept_by_region(c.width, c.height, c.gaze);
    for (size_t k = 0; k < 4; ++k) {
      EXPECT_EQ(got[k], expected[k])
          << c.width << "x" << c.height << " block " << c.block << " region " << k;
    }
  }
  EXPECT_EQ(CheckerboardPattern{}.kept_by_region(0, 0, {0, 0}), (std::array<double, 4>{}));
}

TEST(Checkerboard, GapsBetweenKeptPixels) {
  // Against brute force: the diameter of the largest disc free of kept pixel
  // centres, probed on a fine grid of candidate centres over one 2n tile. In
  // region 3 that is the gap exactly (the disc at the dropped corner quad
  // touches the corners of four kept quads); across an n x n hole it is n + 1,
  // or up to sqrt((n + 1)^2 + 1) when n is even and the disc passes between
  // two kept centres of the neighbouring row.
  for (int n : {1, 2, 4, 8}) {
    for (int k = 1; k < 4; ++k) {
      CheckerboardPattern p;
      p.block = n;
      p.thresholds_px = {k >= 1 ? -1.0 : 1e9, k >= 2 ? -1.0 : 1e9, k >= 3 ? -1.0 : 1e9};
      std::vector<Vec2d> kept;
      for (int y = -4 * n; y < 8 * n; ++y) {
        for (int x = -4 * n; x < 8 * n; ++x) {
          if (p.kept({x + 0.5, y + 0.5}, {1e6, 1e6})) kept.push_back({x + 0.5, y + 0.5});
        }
      }
      double largest = 0;
      const int steps = 8 * n;
      for (int j = 0; j <= steps; ++j) {
        for (int i = 0; i <= steps; ++i) {
          const Vec2d c{2.0 * n * i / steps, 2.0 * n * j / steps};
          double nearest = 1e9;
          for (const Vec2d& q : kept) nearest = std::min(nearest, std::hypot(q.x - c.x, q.y - c.y));
          largest = std::max(largest, 2 * nearest);
        }
      }
      const double gap = checkerboard_gap_px(k, n);
      if (k == 3) {
        EXPECT_NEAR(gap, largest, 1e-9) << "block " << n;
      } else {
        EXPECT_DOUBLE_EQ(gap, n + 1.0);
        EXPECT_GE(largest, gap - 1e-9) << "block " << n << " region " << k;
        EXPECT_LE(largest, std::hypot(gap, 1.0) + 1e-9) << "block " << n << " region " << k;
      }
    }
  }
  EXPECT_DOUBLE_EQ(checkerboard_gap_px(0, 4), 1.0);  // native spacing
  EXPECT_THROW(checkerboard_gap_px(4, 4), Error);
}

TEST(Checkerboard, ThresholdsFromFractionsAndAcuity) {
  const auto f = CheckerboardPattern::from_fractions(16, 1280, 720);
  const double diag = std::hypot(1280, 720);
  EXPECT_DOUBLE_EQ(f.thresholds_px[0], 0.10 * diag);
  EXPECT_DOUBLE_EQ(f.thresholds_px[2], 0.40 * diag);

  const Display d = Display::load("desktop-1080p");
  const AcuityModel a = AcuityModel::preset("A");
  // Region k starts where the MAR in pixels, w(e) f / cos e per radian (f the
  // eye distance in pixels), is twice the region's largest gap.
  const auto mar_px = [&](double e) {
    return a.mar_deg(e) * M_PI / 180 * d.eye_distance_px() / std::cos(e * M_PI / 180);
  };
  for (int n : {2, 4, 16}) {
    const auto p = CheckerboardPattern::from_acuity(n, d, a);
    for (int k = 0; k < 3; ++k) {
      const double e = std::atan(p.thresholds_px[k] / d.eye_distance_px()) * 180 / M_PI;
      EXPECT_NEAR(mar_px(e), 2 * checkerboard_gap_px(k + 1, n), 1e-6) << n << " " << k;
      EXPECT_NEAR(mar_px_at(d, a, e), mar_px(e), 1e-9);
    }
    // Regions 1 and 2 leave the same n x n holes: region 1 is empty.
    EXPECT_DOUBLE_EQ(p.thresholds_px[0], p.thresholds_px[1]);
    EXPECT_LT(p.thresholds_px[1], p.thresholds_px[2]);
  }
  // 4-pixel quads on the paper's display: two samples per MAR cycle across
  // 5-pixel gaps from 8.5 degrees, across 7.1-pixel gaps from 12.2.
  const auto p4 = CheckerboardPattern::from_acuity(4, d, a);
  EXPECT_NEAR(std::atan(p4.thresholds_px[0] / d.eye_distance_px()) * 180 / M_PI, 8.5, 0.05);
  EXPECT_NEAR(std::atan(p4.thresholds_px[2] / d.eye_distance_px()) * 180 / M_PI, 12.2, 0.05);
  // Bigger quads leave bigger holes: every region starts further out.
  const auto p8 = CheckerboardPattern::from_acuity(8, d, a);
  for (int k = 0; k < 3; ++k) EXPECT_GT(p8.thresholds_px[k], p4.thresholds_px[k]);
  EXPECT_NEAR(checkerboard_sampling_factor(1), std::sqrt(4.0 / 3.0), 1e-12);
  EXPECT_THROW(CheckerboardPattern::from_fractions(0, 10, 10), Error);
}

// Thresholds out of order are refused with their values, so that the user
// sees which of r1, r2, r3 to change.
TEST(Checkerboard, DecreasingThresholdsAreRefusedWithTheirValues) {
  CheckerboardPattern p;
  p.block = 4;
  p.thresholds_px = {30, 10, 50};
  try {
    p.validate();
    FAIL() << "decreasing thresholds accepted";
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("must not decrease, got 30, 10, 50 px (r2 = 10 is below r1 = 30)"),
              std::string::npos)
        << m;
  }
}
