#include "foveate/core/planner.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "foveate/core/error.hpp"

using namespace foveate;

namespace {
const Display kDesk = Display::load("desktop-1080p");
}

TEST(Planner, SamplingFactorsFollowEq2) {
  const LayerPlan p = plan_layers(kDesk, AcuityModel::preset("A"));
  ASSERT_EQ(p.layers.size(), 3u);
  EXPECT_DOUBLE_EQ(p.layers[0].sampling_factor, 1.0);
  for (size_t i = 1; i < 3; ++i) {
    const double e = p.layers[i - 1].radius_deg;
    EXPECT_NEAR(p.layers[i].sampling_factor, (0.0275 * e + 1.0 / 48) / kDesk.sharpness_deg(),
                1e-12);
  }
  // Eq. 3: inner layer diameter 2 f tan(e1), outer layer the screen divided by s3.
  EXPECT_EQ(p.layers[0].width_px, std::lround(2 * kDesk.eye_distance_px() *
                                              std::tan(p.layers[0].radius_deg * M_PI / 180)));
  EXPECT_EQ(p.layers[2].width_px, std::lround(1920 / p.layers[2].sampling_factor));
  EXPECT_EQ(p.layers[2].height_px, std::lround(1080 / p.layers[2].sampling_factor));
}

TEST(Planner, ReproducesMeasuredPixelSavings) {
  // Section 6: 13.3x (quality A) and 9.8x (quality B) fewer pixels, counting the
  // middle and outer layers at half rate.
  const LayerPlan a = plan_layers(kDesk, AcuityModel::preset("A"));
  const LayerPlan b = plan_layers(kDesk, AcuityModel::preset("B"));
  EXPECT_NEAR(a.pixel_ratio_half_rate(), 13.3, 13.3 * 0.05);
  EXPECT_NEAR(b.pixel_ratio_half_rate(), 9.8, 9.8 * 0.05);
  // Unweighted, quality A saves more than B, and both less than with half rate.
  EXPECT_GT(a.pixel_ratio(), b.pixel_ratio());
  EXPECT_LT(a.pixel_ratio(), a.pixel_ratio_half_rate());
}

TEST(Planner, OptimumIsAMinimum) {
  // Brute force over a coarse grid never beats the planner on the same grid.
  PlannerOptions o;
  o.grid_step_deg = 0.5;
  const AcuityModel acu = AcuityModel::preset("A");
  const LayerPlan p = plan_layers(kDesk, acu, o);
  const double f = kDesk.eye_distance_px();
  double best = 1e300;
  for (double e1 = 0.5; e1 < kDesk.half_fov_deg(); e1 += 0.5) {
    for (double e2 = e1 + 0.5; e2 < kDesk.half_fov_deg(); e2 += 0.5) {
      const double s2 = std::max(1.0, acu.mar_deg(e1) / kDesk.sharpness_deg());
      const double s3 = std::max(1.0, acu.mar_deg(e2) / kDesk.sharpness_deg());
      const double d1 = 2 * f * std::tan(e1 * M_PI / 180),
                   d2 = 2 * f * std::tan(e2 * M_PI / 180) / s2;
      const double P = d1 * d1 + d2 * d2 + 0.5625 * std::pow(1920 / s3, 2);
      best = std::min(best, P);
    }
  }
  double planned = 0;
  {
    const double e1 = p.layers[0].radius_deg, e2 = p.layers[1].radius_deg;
    const double d1 = 2 * f * std::tan(e1 * M_PI / 180);
    const double d2 = 2 * f * std::tan(e2 * M_PI / 180) / p.layers[1].sampling_factor;
    planned = d1 * d1 + d2 * d2 + 0.5625 * std::pow(1920 / p.layers[2].sampling_factor, 2);
  }
  EXPECT_NEAR(planned, best, best * 1e-9);
}

TEST(Planner, MoreLayersNeverCostMore) {
  double last = 1e300;
  for (int n = 2; n <= 6; ++n) {
    PlannerOptions o;
    o.layers = n;
    o.grid_step_deg = 0.1;
    const LayerPlan p = plan_layers(kDesk, AcuityModel::preset("A"), o);
    ASSERT_EQ(static_cast<int>(p.layers.size()), n);
    for (int i = 1; i < n - 1; ++i) EXPECT_GT(p.layers[i].radius_deg, p.layers[i - 1].radius_deg);
    EXPECT_LE(p.total_pixels, last * 1.001);  // integer rounding of target sizes
    last = p.total_pixels;
  }
}

TEST(Planner, OneLayerIsNative) {
  PlannerOptions o;
  o.layers = 1;
  const LayerPlan p = plan_layers(kDesk, AcuityModel::preset("A"), o);
  ASSERT_EQ(p.layers.size(), 1u);
  EXPECT_EQ(p.layers[0].width_px, 1920);
  EXPECT_DOUBLE_EQ(p.pixel_ratio(), 1.0);
}

TEST(Planner, FixedS2) {
  PlannerOptions o;
  o.fixed_s2 = 2.0;
  const AcuityModel a = AcuityModel::preset("A");
  const LayerPlan p = plan_layers(kDesk, a, o);
  EXPECT_NEAR(p.layers[1].sampling_factor, 2.0, 1e-9);
  EXPECT_NEAR(p.layers[0].radius_deg, (2 * kDesk.sharpness_deg() - a.w0_deg) / a.slope, 1e-9);
  // Restricting a variable cannot beat the free optimum.
  EXPECT_GE(p.total_pixels, plan_layers(kDesk, a).total_pixels * 0.999);
  // Two layers: s2 places the only radius, where w(e) = 2.5 w* (1080p, preset
  // A: (2.5 x 0.0516 - 0.0208) / 0.0275 = 3.93 deg), and the outer layer
  // samples at 2.5 pixels there.
  o.layers = 2;
  o.fixed_s2 = 2.5;
  const LayerPlan two = plan_layers(kDesk, a, o);
  ASSERT_EQ(two.layers.size(), 2u);
  EXPECT_NEAR(two.layers[0].radius_deg, (2.5 * kDesk.sharpness_deg() - a.w0_deg) / a.slope, 1e-9);
  EXPECT_NEAR(two.layers[0].radius_deg, 3.93, 0.01);
  EXPECT_NEAR(two.layers[1].sampling_factor, 2.5, 1e-9);
}

TEST(Planner, WeightsShiftTheOptimum) {
  PlannerOptions o;
  o.weights = {1.0, 0.5, 0.5};
  const LayerPlan w = plan_layers(kDesk, AcuityModel::preset("A"), o);
  const LayerPlan u = plan_layers(kDesk, AcuityModel::preset("A"));
  EXPECT_GE(w.pixel_ratio_half_rate(), u.pixel_ratio_half_rate() - 1e-9);
}

TEST(Planner, RejectsBadOptions) {
  PlannerOptions o;
  o.layers = 7;
  EXPECT_THROW(plan_layers(kDesk, AcuityModel{}, o), Error);
  o.layers = 0;
  EXPECT_THROW(plan_layers(kDesk, AcuityModel{}, o), Error);
  o.layers = 3;
  o.grid_step_deg = 0;
  EXPECT_THROW(plan_layers(kDesk, AcuityModel{}, o), Error);
  o.grid_step_deg = 0.05;
  o.weights = {1, 1};
  EXPECT_THROW(plan_layers(kDesk, AcuityModel{}, o), Error);
  o.weights.clear();
  o.fixed_s2 = 100.0;
  EXPECT_THROW(plan_layers(kDesk, AcuityModel{}, o), Error);
}

TEST(Planner, JsonHasDocumentedFields) {
  const nlohmann::json j = plan_layers(kDesk, AcuityModel::preset("A"));
  EXPECT_NEAR(j["display"]["half_fov_deg"].get<double>(), 23.4, 0.05);
  EXPECT_NEAR(j["display"]["sharpness_deg"].get<double>(), 0.0516, 0.0001);
  ASSERT_EQ(j["layers"].size(), 3u);
  for (const char* k : {"radius_deg", "sampling_factor", "width_px", "height_px", "pixels"}) {
    EXPECT_TRUE(j["layers"][0].contains(k)) << k;
  }
  EXPECT_NEAR(j["pixel_ratio_half_rate"].get<double>(), 13.3, 0.7);
}

TEST(Sweep, Equation9Display) {
  const auto rows = fov_sweep(60.0, 60.0, 5.0, 0.1);
  ASSERT_EQ(rows.size(), 1u);
  // D*(60) = 4 tan(30 deg) / tan(1/48 deg).
  EXPECT_NEAR(rows[0].display_width_px, 4 * std::tan(M_PI / 6) / std::tan(M_PI / 180 / 48), 1e-6);
  EXPECT_EQ(rows[0].speedup_a.size(), sweep_variants().size());
}

TEST(Sweep, SpeedupGrowsWithFieldOfView) {
  // Figures 12 and 13: savings grow with the field of view, more layers save
  // more at wide fields of view, and A saves more than B.
  const auto rows = fov_sweep(20.0, 100.0, 40.0, 0.1);
  ASSERT_EQ(rows.size(), 3u);
  for (size_t v = 0; v < sweep_variants().size(); ++v) {
    EXPECT_LT(rows[0].speedup_a[v], rows[1].speedup_a[v]);
    EXPECT_LT(rows[1].speedup_a[v], rows[2].speedup_a[v]);
    EXPECT_GT(rows[2].speedup_a[v], rows[2].speedup_b[v]);
  }
  EXPECT_GT(rows[2].speedup_a[2], rows[2].speedup_a[0]);  // n=4 beats n=2
  // The abstract: about 100x at a 70 degree field of view (sharpness = acuity).
  const auto r70 = fov_sweep(70.0, 70.0, 5.0, 0.1);
  EXPECT_GT(r70[0].speedup_a[2], 50.0);
  EXPECT_LT(r70[0].speedup_a[2], 200.0);
}

// A display too small for the layers is named by the file it came from
// (what the user has to change), else by its name.
TEST(Planner, ADisplayTooSmallIsNamed) {
  Display d = Display::load("desktop-1080p").resized(64, 36);
  d.width_mm = 2;
  d.name = "tiny";
  const auto message = [&] {
    try {
      (void)plan_layers(d, AcuityModel::preset("A"), PlannerOptions{});
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message().find("layers: the display 'tiny' (64x36 px,"), std::string::npos)
      << message();
  d.source = "/data/tiny.json";
  EXPECT_NE(message().find("the display /data/tiny.json (64x36 px"), std::string::npos)
      << message();
  EXPECT_NE(message().find("too small for 3 layers at a grid step of"), std::string::npos)
      << message();
}
