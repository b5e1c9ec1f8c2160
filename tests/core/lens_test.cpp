// The lens model (lens.hpp): hand-worked panel densities and oversampling on
// the Rift DK1's published lens, the rates and the plan that coarsen through
// the lens at an off-axis gaze and stay as they were on the axis, the JSON
// form and its errors.
#include "foveate/core/lens.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <nlohmann/json.hpp>
#include <numbers>

#include "foveate/core/display.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/planner.hpp"
#include "foveate/core/shading_rate.hpp"

namespace foveate {
namespace {

constexpr double kPi = std::numbers::pi;

void expect_error(const std::function<void()>& fn, const std::string& part) {
  try {
    fn();
    ADD_FAILURE() << "no error; expected one containing: " << part;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

Display without_lens(Display d) {
  d.lens.reset();
  return d;
}

// A display 1:1 with its panel at the centre: a 700 px buffer over 90 deg
// has f = 350 px per tangent, and the lens 350 panel px per tangent.
nlohmann::json one_to_one_json() {
  return nlohmann::json::parse(R"({"name": "t", "width_px": 700, "height_px": 700,
    "fov_h_deg": 90,
    "lens": {"panel_px": [600, 600], "center_px": [300, 300], "px_per_tan": 350,
             "radius_unit_px": 300, "k": [0.22, 0.24]}})");
}

// The SDK's DK1 figures: px_per_tan = 320 * 41 / (149.76 / 4) = 350.42735;
// the lens centre 320 + (37.44 - 31.75) * 1280 / 149.76 = 368.632 px from the
// eye panel's left edge; DistortionScale at rho = 368.632 / 320 = 1.151976:
// 1 + 0.22 rho^2 + 0.24 rho^4 = 1.714606, so the buffer is 640 * 1.714606 =
// 1097.35 -> 1097 by 800 * 1.714606 = 1371.68 -> 1372, and its focal length
// 1097 * 350.42735 / 1097.35 = 350.3163 px.
TEST(Lens, Dk1PresetHasTheSdkFigures) {
  const Display d = Display::load("hmd-rift-dk1");
  ASSERT_TRUE(d.lens.has_value());
  EXPECT_EQ(d.width_px, 1097);
  EXPECT_EQ(d.height_px, 1372);
  EXPECT_NEAR(d.lens->px_per_tan, 350.42735, 1e-4);
  EXPECT_NEAR(d.lens->center_x_px, 368.6325, 1e-3);
  EXPECT_NEAR(d.eye_distance_px(), 350.3163, 1e-3);
  // The principal point is the lens centre scaled by the DistortionScale.
  EXPECT_NEAR(d.principal_point().x, 368.6325 * 1.714606 * 1097.0 / 1097.3476, 1e-2);
  EXPECT_NEAR(d.principal_point().y, 686.0, 1e-6);
  // The SDK's vertical field: 2 atan(46.8 mm * 1.714606 / 41 mm) = 125.87 deg.
  EXPECT_NEAR(d.fov.up_deg - d.fov.down_deg, 125.871, 1e-3);
}

// At the lens axis a 1:1 buffer and its panel have the same pixels per
// degree: 350 px per tangent = 350 * pi / 180 = 6.10865 per degree.
TEST(Lens, PanelDensityAtTheAxisEqualsTheBuffersWhenSizedOneToOne) {
  const Display d = Display::from_json(one_to_one_json());
  const Vec2d c = d.principal_point();
  const PanelDensity p = d.panel_pixels_per_degree(c);
  EXPECT_NEAR(p.radial, 350.0 * kPi / 180.0, 1e-9);
  EXPECT_NEAR(p.tangential, 350.0 * kPi / 180.0, 1e-9);
  EXPECT_NEAR(d.pixels_per_degree(c, c), p.radial, 1e-4);
  EXPECT_NEAR(d.lens_oversampling(c).radial, 1.0, 1e-12);
  EXPECT_NEAR(d.lens_oversampling(c).tangential, 1.0, 1e-12);
  EXPECT_NEAR(d.displayed_pixel_angle_deg(c), std::atan(1.0 / 350.0) * 180.0 / kPi, 1e-6);
}

// The DK1 lens one radius unit (320 panel px) from its centre, rho = 1:
//   tan = 320 / 350.42735 * (1 + 0.22 + 0.24) = 1.3332293 (53.128 deg),
//   dtan/dr = (1 + 3 * 0.22 + 5 * 0.24) / 350.42735 = 2.86 / 350.42735,
//   radial: (1 + tan^2) / (dtan/dr) = 340.32 px per radian = 5.93969 per deg,
//   tangential: r / sin = 320 * sqrt(1 + tan^2) / tan = 400.02 per radian
//   = 6.98151 per degree;
// the buffer (f = 350.3163) has there f * dtan/dr = 2.85909 pixels per
// panel pixel radially and f * tan / r = 1.45954 tangentially.
TEST(Lens, DensityAtAnAngleFromThePolynomialsDerivative) {
  const Display d = Display::load("hmd-rift-dk1");
  const Lens& l = *d.lens;
  EXPECT_NEAR(l.tan_at_radius(320.0), 1.3332293, 1e-6);
  EXPECT_NEAR(l.dtan_dr(320.0), 2.86 / 350.42735, 1e-8);
  EXPECT_NEAR(l.radius_at_tan(1.3332293), 320.0, 1e-3);
  const PanelDensity p = l.density_at_tan(1.3332293);
  EXPECT_NEAR(p.radial, 5.939685, 1e-5);
  EXPECT_NEAR(p.tangential, 6.981513, 1e-5);
  // The same through the display, at a buffer pixel straight right of the axis.
  const Vec2d c = d.principal_point();
  const Vec2d px{c.x + 1.3332293 * d.eye_distance_px(), c.y};
  EXPECT_NEAR(d.panel_pixels_per_degree(px).radial, 5.939685, 1e-5);
  const Oversampling m = d.lens_oversampling(px);
  EXPECT_NEAR(m.radial, 2.859094, 1e-5);
  EXPECT_NEAR(m.tangential, 1.459537, 1e-5);
  // The displayed pixel: radially the panel's (1 / 5.93969 deg) is coarser
  // than the buffer's (cos^2 / f); tangentially the panel's (1 / 6.98151) too;
  // the finer of the two is the tangential one.
  EXPECT_NEAR(d.displayed_pixel_angle_deg(px), 1.0 / 6.981513, 1e-6);
  // Without the lens: the buffer's radial pixel, cos^2(53.128 deg) / f rad.
  const double c2 = 1.0 / (1.0 + 1.3332293 * 1.3332293);
  EXPECT_NEAR(without_lens(d).displayed_pixel_angle_deg(px), c2 / d.eye_distance_px() * 180.0 / kPi,
              1e-9);
}

TEST(Lens, RightEyeMirrorsTheLensCentre) {
  const Display d = Display::load("hmd-rift-dk1");
  const Display r = d.mirrored();
  EXPECT_NEAR(r.lens->center_x_px, 640.0 - d.lens->center_x_px, 1e-9);
  // The same view angle on the other side has the same density.
  const Vec2d cl = d.principal_point(), cr = r.principal_point();
  EXPECT_NEAR(d.lens_oversampling({cl.x + 300, cl.y}).radial,
              r.lens_oversampling({cr.x - 300, cr.y}).radial, 1e-12);
}

ShadingRateImage rates(const Display& d, Vec2d gaze) {
  return shading_rate_image(d, AcuityModel::preset("A"), gaze);
}

// Gaze 0.95 across the DK1's buffer: x = 1042, 410 px right of the axis,
// tan 1.17 (49.5 deg), where the buffer has about 2.5 pixels per panel pixel
// radially (along x) and 1.4 tangentially. The MAR alone needs 1x1 at the gaze
// (half of w0 = 0.0104 deg against a 0.069 deg step); through the lens a
// spacing of 2 along x is no coarser than the panel: 2x1.
TEST(Lens, RatesCoarsenNearAnOffAxisGaze) {
  const Display d = Display::load("hmd-rift-dk1");
  const Vec2d g{0.95 * d.width_px, 0.5 * d.height_px};
  const ShadingRateImage with = rates(d, g), without = rates(without_lens(d), g);
  const auto at_gaze = with.tile_of(static_cast<int>(g.x), static_cast<int>(g.y));
  EXPECT_EQ(without.at(at_gaze[0], at_gaze[1]), (ShadingRate{1, 1}));
  EXPECT_EQ(with.at(at_gaze[0], at_gaze[1]), (ShadingRate{2, 1}));
  EXPECT_LT(with.pixel_ratio(), without.pixel_ratio());
  int coarser = 0;
  for (size_t i = 0; i < with.rates.size(); ++i) {
    EXPECT_GE(with.rates[i].pixels(), without.rates[i].pixels()) << "tile " << i;
    coarser += with.rates[i].pixels() > without.rates[i].pixels();
  }
  EXPECT_GT(coarser, 0);
}

// On the axis, out to 30 deg, the buffer has fewer than 2 pixels per panel
// pixel in either direction (checked), so no rate can change there.
TEST(Lens, RatesOnAxisUnchangedWhereTheBufferIsNotOversampled) {
  const Display d = Display::load("hmd-rift-dk1");
  const Vec2d c = d.principal_point();
  const double r30 = std::tan(30.0 * kPi / 180.0) * d.eye_distance_px();
  EXPECT_LT(d.lens_oversampling({c.x + r30, c.y}).radial, 2.0);
  const ShadingRateImage with = rates(d, c), without = rates(without_lens(d), c);
  int compared = 0;
  for (int ty = 0; ty < with.tiles_y; ++ty) {
    for (int tx = 0; tx < with.tiles_x; ++tx) {
      const auto r = with.tile_rect(tx, ty);
      bool inside = true;
      for (int x : {r[0], r[2]}) {
        for (int y : {r[1], r[3]}) {
          inside = inside && d.eccentricity_deg({double(x), double(y)}, c) < 30.0;
        }
      }
      if (!inside) continue;
      ++compared;
      EXPECT_EQ(with.at(tx, ty), without.at(tx, ty)) << tx << "," << ty;
    }
  }
  EXPECT_GT(compared, 100);
}

// The plan through the lens: with the gaze on the axis the buffer is never
// finer than the panel near it (f / px_per_tan = 0.9997), so the plan is the
// lens-free one; at the off-axis gaze (49.5 deg out) the fovea's ring lies
// where the panel is coarser than the buffer in both directions, so its layer
// is sampled coarser than native and the plan is smaller.
TEST(Lens, PlanCoarserOffAxisIdenticalOnAxis) {
  const Display d = Display::load("hmd-rift-dk1");
  const AcuityModel a = AcuityModel::preset("A");
  PlannerOptions o;
  o.gaze = d.principal_point();
  const LayerPlan on = plan_layers(d, a, o), free = plan_layers(without_lens(d), a, o);
  ASSERT_EQ(on.layers.size(), free.layers.size());
  for (size_t i = 0; i < on.layers.size(); ++i) {
    EXPECT_EQ(on.layers[i].sampling_factor, free.layers[i].sampling_factor);
    EXPECT_EQ(on.layers[i].radius_deg, free.layers[i].radius_deg);
  }
  EXPECT_EQ(on.total_pixels, free.total_pixels);
  // No gaze (any gaze): the least oversampling anywhere, at the axis: the same.
  EXPECT_EQ(plan_layers(d, a).total_pixels, free.total_pixels);

  o.gaze = Vec2d{0.95 * d.width_px, 0.5 * d.height_px};
  const LayerPlan off = plan_layers(d, a, o), off_free = plan_layers(without_lens(d), a, o);
  EXPECT_EQ(off_free.layers[0].sampling_factor, 1.0);
  EXPECT_GT(off.layers[0].sampling_factor, 1.05);
  EXPECT_LT(off.total_pixels, off_free.total_pixels);
  // The factor is the least oversampling over the fovea ring's view angles:
  // from the gaze's angle less the ring's radius outwards.
  const double gamma = d.eccentricity_deg(d.principal_point(), *o.gaze);
  const OversamplingTable t(*d.lens, d.eye_distance_px(), 80.0);
  EXPECT_NEAR(off.layers[0].sampling_factor,
              t.least_beyond(gamma - off.layers[0].radius_deg).least(), 1e-12);
}

TEST(Lens, OversamplingUnderFivePercentKeepsTheFoveaNative) {
  // hmd-quest2-lens: at its full size the buffer is 0.25 % finer than the
  // panel at the axis; a fovea layer resampled by 1.0025 would save nothing
  // worth its lost exactness, so the plan keeps it native.
  const Display d = Display::load("hmd-quest2-lens");
  const OversamplingTable t(*d.lens, d.eye_distance_px(), 80.0);
  ASSERT_GT(t.least_beyond(0.0).least(), 1.0);
  ASSERT_LT(t.least_beyond(0.0).least(), 1.05);
  PlannerOptions o;
  o.gaze = d.principal_point();
  EXPECT_EQ(plan_layers(d, AcuityModel::preset("A"), o).layers[0].sampling_factor, 1.0);
}

TEST(Lens, JsonRoundTrip) {
  const Display d = Display::load("hmd-quest2-lens");
  const nlohmann::json j = d;
  ASSERT_TRUE(j.contains("lens"));
  EXPECT_EQ(j["lens"]["panel_px"], nlohmann::json::parse("[1592, 1664]"));
  const Display back = Display::from_json(j);
  ASSERT_TRUE(back.lens.has_value());
  EXPECT_EQ(back.lens->k, d.lens->k);
  EXPECT_EQ(back.lens->center_x_px, d.lens->center_x_px);
  // Displays without a lens write none.
  EXPECT_FALSE(nlohmann::json(Display::load("hmd-quest2")).contains("lens"));
  // radius_unit_px defaults to px_per_tan.
  nlohmann::json k = one_to_one_json();
  k["lens"].erase("radius_unit_px");
  EXPECT_EQ(Display::from_json(k).lens->radius_unit_px, 350.0);
}

TEST(Lens, JsonErrorsNameTheField) {
  auto with = [](const std::function<void(nlohmann::json&)>& edit) {
    nlohmann::json j = one_to_one_json();
    edit(j);
    return j;
  };
  auto load = [](const nlohmann::json& j) { return [j] { (void)Display::from_json(j); }; };
  expect_error(load(with([](auto& j) { j["lens"].erase("panel_px"); })),
               "display.lens.panel_px: required");
  expect_error(load(with([](auto& j) { j["lens"]["panel_px"] = {600}; })),
               "display.lens.panel_px: expected an array of 2 numbers");
  expect_error(load(with([](auto& j) {
                 j["lens"]["panel_px"] = {600.5, 600};
               })),
               "two whole numbers");
  expect_error(load(with([](auto& j) { j["lens"].erase("px_per_tan"); })),
               "display.lens.px_per_tan: required");
  expect_error(load(with([](auto& j) {
                 j["lens"]["k"] = {0.1, 0.2, 0.3, 0.4};
               })),
               "display.lens.k: expected an array of 1 to 3 numbers");
  expect_error(load(with([](auto& j) { j["lens"]["k"] = {"a"}; })),
               "display.lens.k: expected numbers");
  expect_error(load(with([](auto& j) {
                 j["lens"]["center_px"] = {700, 300};
               })),
               "lens.center_px: must lie on the panel");
  expect_error(load(with([](auto& j) { j["lens"]["colour"] = 1; })), "colour");
  // A k that folds the lens back: tan = r (1 - rho^2) / 350 stops growing
  // at rho = 1 / sqrt(3), 173.2 px from the centre, inside the panel.
  expect_error(load(with([](auto& j) { j["lens"]["k"] = {-1.0}; })),
               "lens.k: the view angle stops growing 173.");
  // A lens on a flat display.
  expect_error(load(nlohmann::json::parse(R"({"width_px": 100, "height_px": 100,
    "width_mm": 500, "distance_mm": 600,
    "lens": {"panel_px": [10, 10], "center_px": [5, 5], "px_per_tan": 10, "k": [0.1]}})")),
               "lens needs a head-mounted display");
}

}  // namespace
}  // namespace foveate
