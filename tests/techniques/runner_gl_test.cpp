// The frame runners with a GL context (the fixture fails a test on any GL
// debug error): a technique registered from outside rendered like a built-in
// one, mismatched scenes, sizes and displays refused, and the supersampled
// native reference.
#include <gtest/gtest.h>

#include <cmath>

#include "bars_technique.hpp"
#include "errors.hpp"
#include "foveate/techniques/frame_runner.hpp"
#include "foveate/techniques/supersampled_native.hpp"
#include "gl_fixture.hpp"

using namespace foveate;
using foveate::test::error_of;

namespace {

TechniqueConfig config(int w, int h) {
  TechniqueConfig c;
  c.display = Display::load("desktop-1080p").resized(w, h);
  c.acuity = AcuityModel::preset("A");
  return c;
}

class FrameRunners : public test::GlTest {};

}  // namespace

TEST_F(FrameRunners, RenderATechniqueRegisteredAtRunTime) {
  test::register_bars_technique();
  const TechniqueInfo& info = technique_info(test::kBarsTechnique);
  // The derived default: a 36th of the height.
  EXPECT_EQ(resolve_parameters(info, config(320, 180)).integer("bar_px"), 5);
  EXPECT_EQ(resolve_parameters(info, config(64, 36)).integer("bar_px"), 1);
  // Clamped into the declared range where the derivation runs past it.
  EXPECT_EQ(resolve_parameters(info, config(7680, 4320)).integer("bar_px"), 64);

  auto scene = load_scene("detail");
  FrameRunnerOptions o;
  o.width = 320;
  o.height = 180;
  FrameRunner runner(*scene, o);
  auto bars = make_technique(test::kBarsTechnique, config(320, 180));
  EXPECT_EQ(bars->name(), test::kBarsTechnique);
  EXPECT_EQ(bars->parameters(), (std::vector<std::pair<std::string, double>>{{"bar_px", 5.0}}));
  const FrameStats s = runner.render(*bars, 0, GazeState{{160, 90}});
  EXPECT_EQ(s.shaded_pixels, 320.0 * 180.0);
  const Image img = runner.read_output();
  auto native = make_technique("native", config(320, 180));
  runner.render(*native, 0, GazeState{{160, 90}});
  const Image ref = runner.read_output();
  int bar = 0, same = 0;
  for (int y = 0; y < 180; ++y) {
    for (int x = 0; x < 320; ++x) {
      const bool in_bar = y < 5 || y >= 175;
      if (in_bar) bar += img.at(x, y)[0] == 0 && img.at(x, y)[1] == 0 && img.at(x, y)[2] == 0;
      if (!in_bar) same += std::equal(img.at(x, y), img.at(x, y) + 3, ref.at(x, y));
    }
  }
  EXPECT_EQ(bar, 2 * 5 * 320);
  EXPECT_EQ(same, 170 * 320);
}

TEST_F(FrameRunners, RefuseAMismatchedSceneSizeOrDisplay) {
  auto scene = load_scene("cheap");
  FrameRunnerOptions o;
  o.width = 64;
  o.height = 36;
  FrameRunner runner(*scene, o);
  auto lodmask = make_technique("lodmask", config(64, 36));
  const std::string e = error_of([&] { runner.render(*lodmask, 0, GazeState{{32, 18}}); });
  EXPECT_NE(e.find("needs a scene with mesh levels of detail"), std::string::npos) << e;
  // A target and a frame of different sizes are refused, not half-drawn.
  FrameInput f = runner.frame_input(0);
  f.width = 65;
  auto native = make_technique("native", config(64, 36));
  EXPECT_NE(error_of([&] { runner.render(*native, f, GazeState{}); }).find("65x36"),
            std::string::npos);
  // So is a technique planned for another display size.
  auto big = make_technique("native", config(128, 72));
  EXPECT_NE(error_of([&] { runner.render(*big, 0, GazeState{}); }).find("128x72 display"),
            std::string::npos);
}

TEST_F(FrameRunners, SupersampledNativeIsTheBoxFilteredBigFrame) {
  // The reference of a fine grating is its mean in linear light, where native
  // at one sample per pixel aliases.
  auto scene = load_scene(std::string(FOVEATE_TEST_DATA) + "/shadertoy/grating.glsl");
  const Display d = Display::load("desktop-1080p").resized(64, 36);
  SupersampledNative ref(d, 4);
  FrameRunnerOptions o;
  o.width = 64;
  o.height = 36;
  FrameRunner runner(*scene, o);
  ref.render(*scene, runner.frame_input(0));
  const Image img = ref.read();
  double sum = 0;
  for (int y = 0; y < 36; ++y) {
    for (int x = 0; x < 64; ++x) {
      const double v = img.at(x, y)[1] / 255.0;
      sum += v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
    }
  }
  EXPECT_NEAR(sum / (64 * 36), 0.5, 0.03);
  // Every pixel is a mix, none pure black or white (16 samples of a grating
  // with a 1.37 px period always see both).
  int pure = 0;
  for (int y = 0; y < 36; ++y)
    for (int x = 0; x < 64; ++x) pure += img.at(x, y)[1] == 0 || img.at(x, y)[1] == 255;
  EXPECT_EQ(pure, 0);
}
