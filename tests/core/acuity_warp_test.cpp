// The marwarp technique's mapping (core/acuity_warp.hpp): its sample spacing
// against the acuity model, worked by hand, and its pixel count against the
// ideal.
#include "foveate/core/acuity_warp.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace foveate;

namespace {

constexpr double kPi = std::numbers::pi;

Display desktop() { return Display::load("desktop-1080p"); }

// f(p, r, dir) at the centre p of every step_x-th pixel of every step_y-th
// row of the 1920x1080 screen, from pixel (x0, y0), that lies farther than
// `from` from the gaze g (r the distance, dir the unit vector from g).
template <class F>
void for_pixels_beyond(Vec2d g, double from, int x0, int y0, int step_x, int step_y, F&& f) {
  for (int y = y0; y < 1080; y += step_y) {
    for (int x = x0; x < 1920; x += step_x) {
      const Vec2d p{x + 0.5, y + 0.5};
      const double r = std::hypot(p.x - g.x, p.y - g.y);
      if (r <= from) continue;
      f(p, r, Vec2d{(p.x - g.x) / r, (p.y - g.y) / r});
    }
  }
}

}  // namespace

TEST(AcuityWarp, RadialSpacingIsHalfTheMarTimesTheMargin) {
  // desktop-1080p: 1920 px over 510 mm at 590 mm, so the eye is
  // f = 590 * 1920 / 510 = 2221.18 px from the screen. Quality A planned
  // with a margin of 1.5: m = 0.0275 / 1.5, w0 = (1/48) / 1.5.
  const AcuityWarp warp(desktop(), AcuityModel::preset("A").finer(1.5));
  const AcuityWarpMapping m = warp.mapping({960, 540});
  EXPECT_DOUBLE_EQ(m.kappa, 1.0);
  EXPECT_NEAR(m.focal_px, 2221.1765, 1e-3);
  // At e = 10 deg: w = (0.0275 * 10 + 1/48) / 1.5 = 0.197222 deg per cycle,
  // half of it 0.0986111 deg; a pixel there subtends cos^2(10) / f radians
  // radially, so the spacing is 0.0986111 * (pi / 180) * 2221.18 /
  // cos^2(10 deg) = 3.9417 px, at r = f tan(10 deg) = 391.653 px.
  EXPECT_NEAR(m.radial_spacing_px(391.6533), 3.9417, 1e-3);
  // At 5 deg (r = 194.328 px): 0.0527778 deg, 2.0617 px; at 20 deg
  // (r = 808.442 px): 0.190278 deg, 8.3537 px.
  EXPECT_NEAR(m.radial_spacing_px(194.3278), 2.0617, 1e-3);
  EXPECT_NEAR(m.radial_spacing_px(808.4421), 8.3537, 1e-3);
  // The columns' own spacing: neighbouring column centres at 10 deg lie
  // 0.0986 deg apart as the eye sees them.
  const Display d = desktop();
  for (double e : {5.0, 10.0, 20.0}) {
    const double u = m.column(m.radius_px(e));
    const double r0 = m.radius_at_column(u - 0.5), r1 = m.radius_at_column(u + 0.5);
    const double seen = d.eccentricity_deg({960 + r0, 540}, {960 + r1, 540});
    EXPECT_NEAR(seen, 0.5 * (0.0275 * e + 1 / 48.0) / 1.5, 1e-4) << e;
  }
  // The buffer begins where that spacing is one pixel: (0.0275 E0 + 1/48) /
  // 1.5 / 2 * (pi / 180) * f / cos^2 E0 = 1 at E0 = 2.05 deg (r = 79.6 px).
  EXPECT_NEAR(m.start_deg, 2.05, 0.01);
  EXPECT_NEAR(m.radial_spacing_px(m.start_px()), 1.0, 1e-6);
  EXPECT_NEAR(m.column(m.start_px()), 0.0, 1e-9);
}

TEST(AcuityWarp, ColumnAndRadiusAreInverses) {
  const AcuityWarp warp(desktop(), AcuityModel::preset("B"));
  const AcuityWarpMapping m = warp.mapping({300, 200});
  for (double u : {0.0, 1.5, 17.0, 120.0, 240.0}) {
    EXPECT_NEAR(m.column(m.radius_at_column(u)), u, 1e-6) << u;
  }
}

TEST(AcuityWarp, RowsKeepTheSpacingAcrossTheRaysWithinHalfTheMar) {
  // Across the rays a pixel subtends cos E / f: at the centre the rows must
  // reach 2 pi f tan E / (w(E) / 2 (pi / 180) f / cos E) = 720 sin E / w(E),
  // largest near 20 deg at quality A: 720 sin 20 / 0.5708 = 431.4 (margin 1).
  const AcuityWarp warp(desktop(), AcuityModel::preset("A"));
  const int rows = warp.rows_for({960, 540});
  EXPECT_GE(rows, 432);
  EXPECT_LE(rows, 440);
  EXPECT_EQ(rows % 4, 0);
}

TEST(AcuityWarp, NoGazeIsSampledCoarserThanHalfTheMar) {
  // For gazes at the centre, off it and in corners, at every screen pixel
  // beyond the native disc: the spacing along the ray (dr/du) and across it
  // (2 pi r / rows) is at most half the MAR there, from the exact angles.
  const Display d = desktop();
  const AcuityModel a = AcuityModel::preset("A").finer(1.25);
  const AcuityWarp warp(d, a);
  for (const Vec2d g :
       {Vec2d{960, 540}, Vec2d{400, 700}, Vec2d{0, 0}, Vec2d{1900, 60}, Vec2d{1500, 300}}) {
    const AcuityWarpMapping m = warp.mapping(g);
    EXPECT_LE(m.kappa, 1.0);
    EXPECT_GT(m.kappa, 0.7) << g.x << "," << g.y;
    double worst_r = 0, worst_t = 0;
    for_pixels_beyond(g, m.start_px() + 1.0, 5, 3, 41, 37, [&](Vec2d p, double r, Vec2d dir) {
      worst_r = std::max(worst_r, m.radial_spacing_px(r) / mar_half_spacing_px(d, a, p, dir, g));
      worst_t = std::max(
          worst_t, m.tangential_spacing_px(r) / mar_half_spacing_px(d, a, p, {-dir.y, dir.x}, g));
    });
    EXPECT_LE(worst_r, 1.002) << g.x << "," << g.y;
    EXPECT_LE(worst_t, 1.0) << g.x << "," << g.y;
    // And not much finer than it along the ray (the closed form is exact at
    // the centre).
    EXPECT_GT(worst_r, g.x == 960 ? 0.999 : 0.85) << g.x << "," << g.y;
    // mapping() checks the acuity on rings of 64 rays; worked here over
    // every 7th pixel instead: for the focal length it chose, the largest
    // kappa for which the model's radial spacing stays within half the MAR
    // beyond where the unscaled model's native disc ends. The rings may miss
    // the tightest pixel by a little (never coarser than 0.3 %) and must not
    // be needlessly fine (within 0.2 %; both are within 0.02 % here).
    AcuityWarpMapping unscaled = m;
    unscaled.slope = a.slope;
    unscaled.w0_deg = a.w0_deg;
    unscaled.kappa = 1.0;
    unscaled.start_deg = acuity_warp_start_deg(m.focal_px, a.slope, a.w0_deg);
    double kappa = 1.0;
    for_pixels_beyond(g, unscaled.start_px(), 0, 0, 7, 7, [&](Vec2d p, double r, Vec2d dir) {
      kappa = std::min(kappa, mar_half_spacing_px(d, a, p, dir, g) / unscaled.radial_spacing_px(r));
    });
    EXPECT_LE(m.kappa, kappa * 1.003) << g.x << "," << g.y;
    EXPECT_GE(m.kappa, kappa * 0.998) << g.x << "," << g.y;
  }
}

TEST(AcuityWarp, ShadesNearTheIdealAndATwentiethOfNativeAtThePapersPlan) {
  // Quality A, margin 1, gaze at the centre: the ideal (half the MAR in both
  // directions everywhere, at most a sample per pixel) is about 72,000
  // samples; the buffer's texels on the screen and the native disc are
  // 81,000, 13 % more (the rows are as many at every radius as the widest
  // ring needs), a 25th of native's 2,073,600 pixels.
  const Display d = desktop();
  const AcuityModel a = AcuityModel::preset("A");
  const double ideal = ideal_mar_samples(d, a, {960, 540});
  EXPECT_NEAR(ideal, 72000, 1500);
  const AcuityWarp warp(d, a);
  const AcuityWarpMapping m = warp.mapping({960, 540});
  const double texels = cover_texels(
      acuity_warp_cover(m, 1 << 20, m.start_px(), {0, 0, 1920, 1080}, 0, 0, 1 << 30, 1));
  const double disc = kPi * m.start_px() * m.start_px();
  EXPECT_LT((texels + disc) / ideal, 1.14);
  EXPECT_LT(texels + disc, 1920 * 1080 / 20.0);
}

TEST(AcuityWarp, CoverReachesTheScreenEdgeInEveryRow) {
  const AcuityWarp warp(desktop(), AcuityModel::preset("A"));
  const AcuityWarpMapping m = warp.mapping({500, 300});
  const auto cover = acuity_warp_cover(m, 1000, 50.0, {0, 0, 1920, 1080}, 2);
  int rows = 0;
  for (const auto& q : cover) {
    rows += q[3] - q[1];
    // Every row's texels reach past where its rays leave the screen.
    for (int j = q[1]; j < q[3]; ++j) {
      for (double t : {0.0, 0.5, 1.0}) {
        const double th = 2 * kPi * (j + t) / m.rows;
        const double c = std::cos(th), s = std::sin(th);
        double reach = 1e9;
        if (c > 1e-9) reach = std::min(reach, (1920 - 500) / c);
        if (c < -1e-9) reach = std::min(reach, -500 / c);
        if (s > 1e-9) reach = std::min(reach, (1080 - 300) / s);
        if (s < -1e-9) reach = std::min(reach, -300 / s);
        EXPECT_GE(q[2], m.column(reach) + 1.0);
      }
    }
    EXPECT_LE(q[0], m.column(50.0));
  }
  EXPECT_EQ(rows, m.rows);
}
