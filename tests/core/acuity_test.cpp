#include "foveate/core/acuity.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "foveate/core/display.hpp"
#include "foveate/core/error.hpp"

using namespace foveate;

TEST(Acuity, LinearMarModel) {
  const AcuityModel a = AcuityModel::preset("A");
  EXPECT_DOUBLE_EQ(a.slope, 0.0275);
  EXPECT_DOUBLE_EQ(a.mar_deg(0.0), 1.0 / 48.0);
  EXPECT_DOUBLE_EQ(a.mar_deg(10.0), 0.275 + 1.0 / 48.0);
  EXPECT_NEAR(a.eccentricity_for_mar(a.mar_deg(7.3)), 7.3, 1e-12);
  EXPECT_DOUBLE_EQ(AcuityModel::preset("b").slope, 0.0220);
  // 1.65 and 1.32 arc minutes per degree (section 5).
  EXPECT_NEAR(kSlopePresetA * 60.0, 1.65, 1e-12);
  EXPECT_NEAR(kSlopePresetB * 60.0, 1.32, 1e-12);
}

TEST(Acuity, RejectsBadQualityAndSlope) {
  EXPECT_THROW(AcuityModel::preset("C"), Error);
  EXPECT_THROW(AcuityModel::with_slope(0.0), Error);
  EXPECT_THROW(AcuityModel::with_slope(-0.01), Error);
  EXPECT_THROW(AcuityModel::with_slope(NAN), Error);
  EXPECT_NO_THROW(AcuityModel::with_slope(0.01));
}

TEST(Acuity, FinerDividesTheWholeModel) {
  // A margin k: the MAR is k times smaller at every eccentricity, so the
  // eccentricity where it reaches a given MAR lies further out.
  const AcuityModel a = AcuityModel::preset("A");
  const AcuityModel f = a.finer(2.0);
  EXPECT_DOUBLE_EQ(f.slope, 0.0275 / 2.0);
  EXPECT_DOUBLE_EQ(f.w0_deg, 1.0 / 96.0);
  for (double e : {0.0, 5.0, 20.0}) EXPECT_DOUBLE_EQ(f.mar_deg(e), a.mar_deg(e) / 2.0);
  EXPECT_GT(f.eccentricity_for_mar(0.2), a.eccentricity_for_mar(0.2));
  EXPECT_DOUBLE_EQ(a.finer(1.0).slope, a.slope);
  EXPECT_THROW((void)a.finer(0.9), Error);
  EXPECT_THROW((void)a.finer(4.5), Error);
  EXPECT_THROW((void)a.finer(NAN), Error);
}

TEST(Display, PaperDesktopGeometry) {
  const Display d = Display::load("desktop-1080p");
  // Section 5: e* = 23.4 deg (eq. 6), w* = 0.0516 deg (eq. 7), w0 / w* about 40 %.
  EXPECT_NEAR(d.half_fov_deg(), 23.4, 0.05);
  EXPECT_NEAR(d.sharpness_deg(), 0.0516, 0.00005);
  EXPECT_NEAR(kFovealMarDeg / d.sharpness_deg(), 0.40, 0.01);
  EXPECT_DOUBLE_EQ(d.aspect(), 9.0 / 16.0);
  // Hand-computed: focal length = 590 * 1920 / 510 px.
  EXPECT_NEAR(d.eye_distance_px(), 2221.176, 1e-3);
}

TEST(Display, ExactEccentricity) {
  const Display d = Display::load("desktop-1080p");
  const Vec2d c{960, 540};
  EXPECT_NEAR(d.eccentricity_deg(c, c), 0.0, 1e-9);
  // The screen edge seen from the centre is e*.
  EXPECT_NEAR(d.eccentricity_deg({1920, 540}, c), d.half_fov_deg(), 1e-9);
  // Gaze at the left edge, pixel at the right edge: the full field of view.
  EXPECT_NEAR(d.eccentricity_deg({1920, 540}, {0, 540}), 2 * d.half_fov_deg(), 1e-9);
  // Off-centre: not the small-angle value. Gaze at the right edge, pixel 200 px
  // further in: atan(960/f) - atan(760/f).
  const double f = d.eye_distance_px();
  const double expect = (std::atan(960 / f) - std::atan(760 / f)) * 180 / M_PI;
  EXPECT_NEAR(d.eccentricity_deg({1720, 540}, {1920, 540}), expect, 1e-9);
  EXPECT_GT(std::fabs(expect - 200 / d.pixels_per_degree(c, c)), 0.1);
}

TEST(Display, PixelsPerDegree) {
  const Display d = Display::load("desktop-1080p");
  const Vec2d c{960, 540};
  // At the centre: f * pi / 180 pixels per degree.
  EXPECT_NEAR(d.pixels_per_degree(c, c), d.eye_distance_px() * M_PI / 180.0, 0.01);
  // Towards the edge the screen is seen obliquely: more pixels per degree.
  EXPECT_GT(d.pixels_per_degree({1900, 540}, c), d.pixels_per_degree({1000, 540}, c));
}

TEST(Display, HeadMountedFromFov) {
  const Display d = Display::load("hmd-quest3");
  EXPECT_TRUE(d.head_mounted());
  EXPECT_NEAR(d.eccentricity_deg({0, 1104}, {1032, 1104}), 52.0, 1e-9);
  // Portrait panel: the longer axis is vertical.
  EXPECT_EQ(d.long_axis_px(), 2208);
  EXPECT_GT(d.half_fov_deg(), 52.0);
}

TEST(Display, ResizedKeepsFieldOfView) {
  const Display d = Display::load("desktop-1080p");
  const Display s = d.resized(480, 270);
  EXPECT_NEAR(s.half_fov_deg(), d.half_fov_deg(), 1e-9);
  EXPECT_NEAR(s.sharpness_deg(), 4 * d.sharpness_deg(), 0.001);
}

TEST(Display, JsonRoundTripAndErrors) {
  const Display d = Display::load("desktop-27-4k");
  const nlohmann::json j = d;
  const Display back = Display::from_json(j);
  EXPECT_EQ(back.width_px, 3840);
  EXPECT_DOUBLE_EQ(back.width_mm, d.width_mm);

  auto message = [](const nlohmann::json& bad) {
    try {
      Display::from_json(bad);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const nlohmann::json base = {
      {"width_px", 1920}, {"height_px", 1080}, {"width_mm", 510}, {"distance_mm", 590}};
  auto with = [&](const char* k, nlohmann::json v) {
    nlohmann::json b = base;
    b[k] = v;
    return b;
  };
  EXPECT_NE(message(with("distance_mm", 0)).find("display.distance_mm"), std::string::npos);
  EXPECT_NE(message(with("distance_mm", -5)).find("distance_mm"), std::string::npos);
  EXPECT_NE(message(with("width_mm", 0.0)).find("display.width_mm"), std::string::npos);
  EXPECT_NE(message(with("width_px", 0)).find("display.width_px"), std::string::npos);
  EXPECT_NE(message(with("height_px", 0)).find("display.height_px"), std::string::npos);
  EXPECT_NE(message(with("width_px", "1920")).find("expected an integer"), std::string::npos);
  EXPECT_NE(message(with("width_px", 19.5)).find("display.width_px"), std::string::npos);
  EXPECT_NE(message(with("width_mm", "wide")).find("expected a number"), std::string::npos);
  EXPECT_NE(message(with("colour", "red")).find("unknown key 'colour'"), std::string::npos);
  nlohmann::json nan = base;
  nan["width_mm"] = std::nan("");  // serialises as null: a wrong type
  EXPECT_NE(message(nan).find("display.width_mm"), std::string::npos);
  nlohmann::json missing = base;
  missing.erase("distance_mm");
  EXPECT_NE(message(missing).find("distance_mm: required"), std::string::npos);
  EXPECT_NE(message(nlohmann::json::array()).find("expected a JSON object"), std::string::npos);
  EXPECT_THROW(Display::load("no-such-display"), Error);
}

TEST(Display, PhotometryDefaultsJsonAndErrors) {
  // FovVideoVDP's standard office display: 200 cd/m^2, 1000:1, 250 lux, 0.5 %.
  const Display d;
  EXPECT_DOUBLE_EQ(d.photometry.peak_cd_m2, 200.0);
  EXPECT_NEAR(d.photometry.black_cd_m2(), 250.0 / 3.14159265358979 * 0.005 + 0.2, 1e-9);
  EXPECT_DOUBLE_EQ(d.photometry.luminance_cd_m2(1.0), 200.0);
  EXPECT_DOUBLE_EQ(d.photometry.luminance_cd_m2(0.0), d.photometry.black_cd_m2());
  // Head-mounted presets see no ambient light.
  EXPECT_EQ(Display::load("hmd-quest3").photometry.ambient_lux, 0.0);
  EXPECT_EQ(Display::load("desktop-1080p").photometry.ambient_lux, 250.0);

  nlohmann::json j = {
      {"width_px", 640},
      {"height_px", 360},
      {"width_mm", 400},
      {"distance_mm", 1000},
      {"photometry", {{"peak_cd_m2", 100}, {"contrast_ratio", 500}, {"ambient_lux", 50}}}};
  const Display p = Display::from_json(j);
  EXPECT_DOUBLE_EQ(p.photometry.peak_cd_m2, 100.0);
  EXPECT_DOUBLE_EQ(p.photometry.contrast_ratio, 500.0);
  EXPECT_DOUBLE_EQ(p.photometry.ambient_lux, 50.0);
  EXPECT_DOUBLE_EQ(p.photometry.reflectivity, 0.005);  // default kept
  nlohmann::json back;
  to_json(back, p);
  EXPECT_DOUBLE_EQ(Display::from_json(back).photometry.contrast_ratio, 500.0);

  const auto message = [&](const char* key, nlohmann::json v) {
    nlohmann::json b = j;
    b["photometry"][key] = v;
    try {
      Display::from_json(b);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("peak_cd_m2", -1).find("display.photometry.peak_cd_m2"), std::string::npos);
  EXPECT_NE(message("contrast_ratio", 1).find("display.photometry.contrast_ratio"),
            std::string::npos);
  EXPECT_NE(message("reflectivity", 2).find("display.photometry.reflectivity"), std::string::npos);
  EXPECT_NE(message("gamma", 2.2).find("unknown key 'gamma'"), std::string::npos);
}
