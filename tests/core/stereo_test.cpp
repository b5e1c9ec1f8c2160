// Asymmetric per-eye fields of view and stereo gaze: eccentricities at the
// principal point and at the image edges worked by hand against the four
// angles, the mirrored right eye, the headset presets' published figures,
// the combined gaze with vergence, and bad input.
#include "foveate/core/stereo.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>

#include "foveate/core/error.hpp"
#include "foveate/core/shading_rate.hpp"

namespace foveate {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;
double atan_deg(double t) { return std::atan(t) * kDeg; }

// A 200x100 eye whose edges lie at tangents -1 (left), 0.6 (right), 0.2 (up)
// and -0.6 (down): the focal length is 200 / 1.6 = 125 px and the optical
// axis meets the image at (125, 25), not at the centre (100, 50).
Display test_eye() {
  Display d;
  d.name = "test-eye";
  d.width_px = 200;
  d.height_px = 100;
  d.fov = FovAngles{-45.0, atan_deg(0.6), atan_deg(0.2), atan_deg(-0.6)};
  d.ipd_mm = 64.0;
  d.validate();
  return d;
}

TEST(Stereo, PrincipalPointAndFocalFromTheFourAngles) {
  const Display d = test_eye();
  EXPECT_TRUE(d.head_mounted());
  EXPECT_TRUE(d.stereo());
  EXPECT_NEAR(d.eye_distance_px(), 125.0, 1e-9);
  EXPECT_NEAR(d.principal_point().x, 125.0, 1e-9);
  EXPECT_NEAR(d.principal_point().y, 25.0, 1e-9);
  EXPECT_NEAR(d.horizontal_fov_deg(), 45.0 + atan_deg(0.6), 1e-9);
}

TEST(Stereo, EccentricityAtThePrincipalPointAndTheEdgesIsTheFourAngles) {
  const Display d = test_eye();
  const Vec2d axis = d.principal_point();
  EXPECT_NEAR(d.eccentricity_deg(axis, axis), 0.0, 1e-9);
  // The edge points level with the axis subtend exactly the edge angles.
  EXPECT_NEAR(d.eccentricity_deg({0.0, 25.0}, axis), 45.0, 1e-9);
  EXPECT_NEAR(d.eccentricity_deg({200.0, 25.0}, axis), atan_deg(0.6), 1e-9);  // 30.96
  EXPECT_NEAR(d.eccentricity_deg({125.0, 0.0}, axis), atan_deg(0.2), 1e-9);   // 11.31
  EXPECT_NEAR(d.eccentricity_deg({125.0, 100.0}, axis), atan_deg(0.6), 1e-9);
  // The image centre is off the axis: (-25, 25) px at f = 125 is
  // atan(sqrt(2) * 25 / 125) = 15.79 deg away (0 on a centred display).
  EXPECT_NEAR(d.eccentricity_deg({100.0, 50.0}, axis), atan_deg(std::sqrt(2.0) * 0.2), 1e-9);
  EXPECT_NEAR(d.eccentricity_deg({100.0, 50.0}, axis), 15.7932, 1e-4);
  // Pixels per degree at the axis: f * pi / 180 = 2.1817 (one pixel's angle).
  EXPECT_NEAR(d.pixels_per_degree(axis, axis), 125.0 / kDeg, 1e-4);
  // Far off the axis a pixel subtends less: d(theta)/dx = f / (f^2 + x^2), so
  // 124.5 px left of the axis (f^2 + x^2) / f / (180 / pi) = 4.3460 px/deg.
  EXPECT_NEAR(d.pixels_per_degree({0.5, 25.0}, axis),
              (125.0 * 125.0 + 124.5 * 124.5) / 125.0 / kDeg, 1e-3);
  EXPECT_NEAR(d.radius_px_at(45.0), 125.0, 1e-9);
}

TEST(Stereo, RightEyeMirrorsTheLeft) {
  const StereoDisplay s = StereoDisplay::from(test_eye());
  EXPECT_NEAR(s.right.principal_point().x, 75.0, 1e-9);
  EXPECT_NEAR(s.right.principal_point().y, 25.0, 1e-9);
  EXPECT_NEAR(s.right.eye_distance_px(), 125.0, 1e-9);
  const Vec2d axis = s.right.principal_point();
  EXPECT_NEAR(s.right.eccentricity_deg({0.0, 25.0}, axis), atan_deg(0.6), 1e-9);
  EXPECT_NEAR(s.right.eccentricity_deg({200.0, 25.0}, axis), 45.0, 1e-9);
  EXPECT_NEAR(s.eye_offset_m(Eye::Left), -0.032, 1e-12);
  EXPECT_NEAR(s.eye_offset_m(Eye::Right), 0.032, 1e-12);
  const FrustumTangents l = frustum_tangents(s.left), r = frustum_tangents(s.right);
  EXPECT_NEAR(l.left, -1.0, 1e-12);
  EXPECT_NEAR(l.right, 0.6, 1e-12);
  EXPECT_NEAR(l.up, 0.2, 1e-12);
  EXPECT_NEAR(l.down, -0.6, 1e-12);
  EXPECT_NEAR(r.left, -0.6, 1e-12);
  EXPECT_NEAR(r.right, 1.0, 1e-12);
  // Resized, the axis stays at the same relative position.
  const Display half = s.left.resized(100, 50);
  EXPECT_NEAR(half.principal_point().x, 62.5, 1e-9);
  EXPECT_NEAR(half.principal_point().y, 12.5, 1e-9);
  EXPECT_NEAR(half.eccentricity_deg({0.0, 12.5}, half.principal_point()), 45.0, 1e-9);
}

TEST(Stereo, Quest2PresetHasTheRuntimesFigures) {
  // hmdq's record of the Oculus runtime: tangents -1.279942, 1.0 (52 and 45
  // deg), 1.110613 up, -1.191754 down (48 and 50 deg), 2352x2368 per eye.
  const Display d = Display::load("hmd-quest2");
  ASSERT_TRUE(d.stereo());
  EXPECT_EQ(d.width_px, 2352);
  EXPECT_EQ(d.height_px, 2368);
  EXPECT_NEAR(d.ipd_mm, 63.5, 1e-12);
  const double f = 2352.0 / 2.279942;  // 1031.6 px
  EXPECT_NEAR(d.eye_distance_px(), f, 1e-9);
  const Vec2d p = d.principal_point();
  EXPECT_NEAR(p.x, 1.279942 * f, 1e-6);  // 1320.4 px from the left edge
  EXPECT_NEAR(d.eccentricity_deg({0.0, p.y}, p), 52.0, 0.01);
  EXPECT_NEAR(d.eccentricity_deg({2352.0, p.y}, p), 45.0, 1e-9);
  EXPECT_NEAR(d.eccentricity_deg({p.x, 0.0}, p), 48.0, 0.2);  // square pixels: within 0.2 deg
  EXPECT_NEAR(d.eccentricity_deg({p.x, 2368.0}, p), 50.0, 0.2);
  const StereoDisplay s = StereoDisplay::from(d);
  EXPECT_NEAR(s.right.eccentricity_deg({0.0, p.y}, s.right.principal_point()), 45.0, 1e-9);
  const Display pimax = Display::load("hmd-pimax-crystal");
  EXPECT_TRUE(pimax.stereo());
  EXPECT_NEAR(pimax.fov.left_deg, -51.65, 0.01);
  EXPECT_NEAR(pimax.fov.right_deg, 41.65, 0.01);
  EXPECT_NEAR(pimax.fov.up_deg, 51.88, 0.01);
  // The monocular presets are unchanged: centred, no stereo.
  const Display q3 = Display::load("hmd-quest3");
  EXPECT_FALSE(q3.stereo());
  EXPECT_NEAR(q3.principal_point().x, 1032.0, 1e-12);
}

TEST(Stereo, CombinedGazeWithVergence) {
  const StereoDisplay s = StereoDisplay::from(test_eye());
  const Vec2d ahead{100.0, 50.0};  // the cyclopean image's centre
  // Parallel gaze straight ahead: each eye looks along its own axis.
  StereoGaze g = stereo_gaze(s, ahead, std::numeric_limits<double>::infinity());
  EXPECT_NEAR(g.eye(Eye::Left).x, 125.0, 1e-9);
  EXPECT_NEAR(g.eye(Eye::Left).y, 25.0, 1e-9);
  EXPECT_NEAR(g.eye(Eye::Right).x, 75.0, 1e-9);
  // A point 1 m ahead: the left eye (32 mm left) turns right by 0.032 in
  // tangent, 125 * 0.032 = 4 px; the right eye as much to the left.
  g = stereo_gaze(s, ahead, 1.0);
  EXPECT_NEAR(g.eye(Eye::Left).x, 129.0, 1e-9);
  EXPECT_NEAR(g.eye(Eye::Right).x, 71.0, 1e-9);
  EXPECT_NEAR(g.eye(Eye::Left).y, 25.0, 1e-9);
  // 25 px right of centre (tangent 0.2), parallel: 25 px right of each axis.
  g = stereo_gaze(s, {125.0, 50.0}, std::numeric_limits<double>::infinity());
  EXPECT_NEAR(g.eye(Eye::Left).x, 150.0, 1e-9);
  EXPECT_NEAR(g.eye(Eye::Right).x, 100.0, 1e-9);
  const Display c = s.cyclopean();
  EXPECT_NEAR(c.eye_distance_px(), 125.0, 1e-9);
  EXPECT_NEAR(c.principal_point().x, 100.0, 1e-9);
}

TEST(Stereo, ShadingRatesFollowEachEyesAxis) {
  // The right eye's rates for a mirrored gaze are the left eye's mirrored:
  // the tile rates take their angles from each eye's own principal point.
  const StereoDisplay s = StereoDisplay::from(Display::load("hmd-quest2").resized(512, 512));
  const AcuityModel a = AcuityModel::preset("A");
  const Vec2d gl{300.0, 200.0}, gr{512.0 - 300.0, 200.0};
  const ShadingRateImage l = shading_rate_image(s.left, a, gl, {});
  const ShadingRateImage r = shading_rate_image(s.right, a, gr, {});
  ASSERT_EQ(l.tiles_x, r.tiles_x);
  int coarse = 0;
  for (int ty = 0; ty < l.tiles_y; ++ty) {
    for (int tx = 0; tx < l.tiles_x; ++tx) {
      const ShadingRate a1 = l.at(tx, ty), b1 = r.at(l.tiles_x - 1 - tx, ty);
      EXPECT_EQ(a1.width, b1.width) << tx << "," << ty;
      EXPECT_EQ(a1.height, b1.height) << tx << "," << ty;
      coarse += a1.pixels() > 1 ? 1 : 0;
    }
  }
  EXPECT_GT(coarse, 0);  // not trivially all 1x1
  // Gaze on the left eye's axis (off the image centre): angles are symmetric
  // about the axis, so tiles the same distance left and right of it get the
  // same rate (taken from the centre they would not: 287 px from the left
  // edge, the axis is 31 px right of it).
  const Vec2d axis = s.left.principal_point();
  ASSERT_GT(axis.x - 256.0, 30.0);
  int coarse_pairs = 0;
  for (double d : {40.0, 80.0, 120.0, 160.0, 200.0}) {
    const std::array<int, 4> lt{int(axis.x - d) - 8, int(axis.y) - 8, int(axis.x - d) + 8,
                                int(axis.y) + 8};
    const std::array<int, 4> rt{int(axis.x + d) - 8, int(axis.y) - 8, int(axis.x + d) + 8,
                                int(axis.y) + 8};
    const ShadingRate rl = tile_shading_rate(s.left, a, axis, lt, {});
    const ShadingRate rr = tile_shading_rate(s.left, a, axis, rt, {});
    EXPECT_EQ(rl.pixels(), rr.pixels())
        << "at " << d << " px: " << rl.name() << " vs " << rr.name();
    coarse_pairs += rl.pixels() > 1 ? 1 : 0;
  }
  EXPECT_GE(coarse_pairs, 2);
  // The same gaze pixel in both eyes is not the same direction: the maps differ.
  const ShadingRateImage same = shading_rate_image(s.right, a, gl, {});
  int differ = 0;
  for (size_t i = 0; i < l.rates.size(); ++i)
    differ += l.rates[i].pixels() != same.rates[i].pixels();
  EXPECT_GT(differ, 0);
}

void expect_error(const std::function<void()>& fn, const std::string& part) {
  try {
    fn();
    FAIL() << "no error; expected one containing '" << part << "'";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(Stereo, BadInputIsNamed) {
  const StereoDisplay s = StereoDisplay::from(test_eye());
  expect_error([&] { (void)stereo_gaze(s, {100, 50}, 0.0); }, "vergence distance: must be > 0");
  expect_error([&] { (void)stereo_gaze(s, {100, 50}, -1.0); }, "got -1");
  expect_error([] { (void)StereoDisplay::from(Display::load("hmd-quest3")); },
               "display 'hmd-quest3': not a stereo head-mounted display");
  // The error lists the stereo presets, from the preset table itself.
  expect_error([] { (void)StereoDisplay::from(Display::load("hmd-quest3")); },
               "stereo presets: hmd-quest2, hmd-pimax-crystal, hmd-rift-dk1, hmd-quest2-lens)");
  EXPECT_EQ(Display::preset_names().find("desktop-1080p, "), 0u);
  EXPECT_EQ(Display::preset_names(true).find("desktop"), std::string::npos);
  Display d = test_eye();
  d.ipd_mm = 0.0;
  expect_error([&] { (void)StereoDisplay::from(d); }, "ipd_mm > 0");
  d = test_eye();
  d.fov.right_deg = -50.0;
  expect_error([&] { d.validate(); }, "fov_deg.right (-50) must be greater than fov_deg.left");
  d = test_eye();
  d.fov.up_deg = 89.0;
  expect_error([&] { d.validate(); }, "fov_deg.up must be in (-85, 85)");
  d = test_eye();
  d.ipd_mm = -3.0;
  expect_error([&] { d.validate(); }, "ipd_mm must be in (0, 200]");
}

TEST(Stereo, JsonRoundTripAndErrors) {
  const Display d = test_eye();
  nlohmann::json j = d;
  EXPECT_EQ(j["ipd_mm"], 64.0);
  EXPECT_EQ(j["fov_deg"]["left"], -45.0);
  EXPECT_FALSE(j.contains("fov_h_deg"));
  const Display back = Display::from_json(j);
  EXPECT_NEAR(back.principal_point().x, 125.0, 1e-9);
  EXPECT_NEAR(back.ipd_mm, 64.0, 1e-12);
  nlohmann::json bad = j;
  bad["ipd_mm"] = -1.0;
  expect_error([&] { (void)Display::from_json(bad); }, "display.ipd_mm");
  bad = j;
  bad["fov_deg"].erase("down");
  expect_error([&] { (void)Display::from_json(bad); }, "display.fov_deg.down: required");
  bad = j;
  bad.erase("fov_deg");
  bad["fov_h_deg"] = 90.0;
  expect_error([&] { (void)Display::from_json(bad); }, "ipd_mm: needs the per-eye angles");
  bad = j;
  bad["fov_h_deg"] = 90.0;
  expect_error([&] { (void)Display::from_json(bad); }, "either fov_h_deg or fov_deg");
}

}  // namespace
}  // namespace foveate
