// Fidelity of the foveated techniques against native ("a viewer cannot tell
// their periphery from native"): every technique's foveal disc, out to its
// innermost radius and at least 2.5 degrees, equals native within the golden
// tolerance; the periphery keeps native's mean linear luminance; and each
// technique's own artefacts are checked where they used to show (checkerboard's
// lattice of sharp kept quads, lodmask's stale coarse surfaces and popping
// borders, logpolar's dark rim and blurred fovea).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "foveate/core/models.hpp"
#include "foveate/techniques/renderer.hpp"
#include "foveate/techniques/technique.hpp"
#include "gl_fixture.hpp"
#include "image_compare.hpp"

using namespace foveate;

namespace {

const std::string kModels = std::string(FOVEATE_TEST_DATA) + "/models";

// The golden tolerance (max channel error 48, mean 0.5, at most 0.5 % of
// pixels off by more than 16) over the pixels within `radius` of `centre`.
test::Comparison compare_disc(const Image& a, const Image& b, Vec2d centre, double radius) {
  test::Comparison c;
  c.size_matches = a.width == b.width && a.height == b.height;
  if (!c.size_matches) return c;
  const int threshold = test::Tolerance{}.pixel_threshold;
  double sum = 0;
  size_t n = 0, off = 0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      if (std::hypot(x + 0.5 - centre.x, y + 0.5 - centre.y) > radius) continue;
      int worst = 0;
      for (int ch = 0; ch < 3; ++ch) {
        const int e = std::abs(int(a.at(x, y)[ch]) - int(b.at(x, y)[ch]));
        worst = std::max(worst, e);
        sum += e;
      }
      c.max_error = std::max(c.max_error, worst);
      off += worst > threshold ? 1 : 0;
      ++n;
    }
  }
  c.mean_error = n ? sum / (3.0 * double(n)) : 0.0;
  c.fraction = n ? double(off) / double(n) : 0.0;
  return c;
}

// Whether a comparison is within the golden tolerance, with its numbers.
::testing::AssertionResult within_golden(const test::Comparison& c) {
  const std::string numbers = "max " + std::to_string(c.max_error) + ", mean " +
                              std::to_string(c.mean_error) + ", " +
                              std::to_string(100 * c.fraction) + " % off by more than 16";
  if (c.within(test::Tolerance{})) return ::testing::AssertionSuccess() << numbers;
  return ::testing::AssertionFailure() << numbers;
}

// Mean linear luminance (sRGB decoded, Rec. 709 weights) of the pixels at
// least `min_radius` from `centre` (as in technique_test.cpp).
double mean_linear_luminance(const Image& img, Vec2d centre, double min_radius) {
  auto lin = [](uint8_t c) {
    const double v = c / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
  };
  double sum = 0;
  int n = 0;
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      if (std::hypot(x + 0.5 - centre.x, y + 0.5 - centre.y) < min_radius) continue;
      const uint8_t* p = img.at(x, y);
      sum += 0.2126 * lin(p[0]) + 0.7152 * lin(p[1]) + 0.0722 * lin(p[2]);
      ++n;
    }
  }
  return n ? sum / n : 0.0;
}

class Fidelity : public test::GlTest {
 protected:
  TechniqueConfig config(int w, int h, std::map<std::string, double> params = {}) const {
    TechniqueConfig c;
    c.display = Display::load("desktop-1080p").resized(w, h);
    c.acuity = AcuityModel::quality("A");
    c.params = std::move(params);
    return c;
  }
  // Frame k (at 1 s + k / 60) of `scene` with `technique` for `gaze`.
  static Image run(Technique& t, Scene& s, Vec2d gaze, int k = 0, FrameStats* stats = nullptr) {
    RendererOptions o;
    o.width = t.display().width_px;
    o.height = t.display().height_px;
    o.start_time_s = 1.0;
    Renderer r(s, o);
    const FrameStats st = r.render(t, k, GazeState{gaze});
    if (stats) *stats = st;
    return r.read_output();
  }
  Image native(Scene& s, int w, int h, int k = 0) {
    auto n = make_technique("native", config(w, h));
    return run(*n, s, {w / 2.0, h / 2.0}, k);
  }
  // The radius of the first circle of a technique's overlay: its fovea.
  static double fovea_px(const Technique& t, Vec2d gaze) {
    for (const OverlayShape& s : t.overlay(GazeState{gaze})) {
      if (s.kind == OverlayShape::Kind::Circle) return s.w;
    }
    return 0.0;
  }
};

}  // namespace

// ---------------------------------------------------------------- checkerboard

TEST_F(Fidelity, CheckerboardFoveaIsNativeAndThePeripheryKeepsItsLuminance) {
  const int W = 1920, H = 1080;
  for (const char* name : {"detail", "cheap"}) {
    auto scene = load_scene(name);
    const Image ref = native(*scene, W, H);
    auto t = make_technique("checkerboard", config(W, H));
    for (const Vec2d gaze : {Vec2d{960, 540}, Vec2d{400, 300}}) {
      FrameStats s;
      const Image img = run(*t, *scene, gaze, 0, &s);
      EXPECT_LT(s.shaded_pixels, 0.6 * W * H) << name;
      const double fovea = fovea_px(*t, gaze);
      EXPECT_GE(fovea, t->display().radius_px_at(2.5));
      EXPECT_TRUE(within_golden(compare_disc(ref, img, gaze, fovea))) << name;
      const double periphery = mean_linear_luminance(ref, gaze, fovea);
      EXPECT_NEAR(mean_linear_luminance(img, gaze, fovea) / periphery, 1.0, 0.02) << name;
    }
  }
}

TEST_F(Fidelity, CheckerboardKeptQuadsDoNotStandOut) {
  // Where quads are dropped, the kept pixels come out of the same filter as
  // the dropped ones: they are not native while their neighbours are
  // reconstructed (the lattice of sharp quads). On the detail scene's fine
  // rings, kept and dropped pixels of region 3 differ from native alike.
  const int W = 1920, H = 1080;
  auto scene = load_scene("detail");
  const Image ref = native(*scene, W, H);
  auto t = make_technique("checkerboard", config(W, H));
  const Vec2d gaze{960, 540};
  const Image img = run(*t, *scene, gaze);
  const auto rings = t->overlay(GazeState{gaze});
  CheckerboardPattern p;
  p.block = t->values().integer("block");
  p.thresholds_px = {rings[1].w, rings[2].w, rings[3].w};
  double err[2] = {0, 0};
  int n[2] = {0, 0};
  for (int y = 0; y < H; ++y) {
    for (int x = 0; x < W; ++x) {
      if (p.region({x + 0.5, y + 0.5}, gaze) != 3) continue;
      const int kept = p.kept({x + 0.5, y + 0.5}, gaze) ? 1 : 0;
      for (int c = 0; c < 3; ++c)
        err[kept] += std::abs(int(img.at(x, y)[c]) - int(ref.at(x, y)[c]));
      n[kept] += 3;
    }
  }
  ASSERT_GT(n[1], 10000);
  const double kept = err[1] / n[1], dropped = err[0] / n[0];
  EXPECT_GT(kept, 0.8 * dropped) << kept << " vs " << dropped;
}

// ---------------------------------------------------------------- lodmask

TEST_F(Fidelity, LodmaskFullDetailCircleIsNativeBackgroundIncluded) {
  // A torus seen face on: its coarse LODs cut the hole with chords and cover
  // background that the full-detail mesh leaves open. Inside the full-detail
  // circle the image is native's, the hole included, on the torus and on the
  // test scene of Guenter et al.
  const int W = 640, H = 360;
  struct Case {
    std::string scene;
    Vec2d gaze;
  };
  for (const Case& c : {Case{kModels + "/torus.obj", {320, 180}}, Case{"guenter", {320, 200}},
                        Case{"guenter", {150, 250}}}) {
    auto scene = load_scene(c.scene);
    const Image ref = native(*scene, W, H);
    auto t = make_technique("lodmask", config(W, H));
    const Image img = run(*t, *scene, c.gaze);
    const double inner = t->display().radius_px_at(t->values().real("inner_deg"));
    EXPECT_GE(inner, t->display().radius_px_at(2.5));
    EXPECT_TRUE(within_golden(compare_disc(ref, img, c.gaze, inner))) << c.scene;
    const double periphery = mean_linear_luminance(ref, c.gaze, inner);
    EXPECT_NEAR(mean_linear_luminance(img, c.gaze, inner) / periphery, 1.0, 0.02) << c.scene;
  }
}

TEST_F(Fidelity, LodmaskBordersHoldStillUnderSmallGazeMoves) {
  // Fixational drift and microsaccades (under hold_deg) move the gaze, not the
  // LOD borders: frames of the same scene time are identical. A larger move
  // (a saccade) moves them, and the fovea around the new gaze is native.
  const int W = 640, H = 360;
  auto scene = load_scene("guenter");
  auto t = make_technique("lodmask", config(W, H));
  const double hold = t->display().radius_px_at(t->values().real("hold_deg"));
  const Vec2d g0{300, 190};
  const Image first = run(*t, *scene, g0);
  for (const Vec2d d : {Vec2d{0.5, 0.3}, Vec2d{-0.6, 0.2}, Vec2d{0.1, -0.7}}) {
    const Vec2d g{g0.x + d.x * hold, g0.y + d.y * hold};
    const Image img = run(*t, *scene, g);
    EXPECT_EQ(test::compare_images(first, img, 0).max_error, 0) << d.x << "," << d.y;
    const auto shapes = t->overlay(GazeState{g});
    EXPECT_EQ(shapes[0].x, g0.x);
    EXPECT_EQ(shapes[0].y, g0.y);
  }
  const Vec2d far{g0.x + 3 * hold, g0.y};
  const Image moved = run(*t, *scene, far);
  EXPECT_EQ(t->overlay(GazeState{far})[0].x, far.x);
  const double inner = t->display().radius_px_at(t->values().real("inner_deg"));
  EXPECT_TRUE(within_golden(compare_disc(native(*scene, W, H), moved, far, inner)));
  // Without holding, the same small moves move the borders.
  auto follow = make_technique("lodmask", config(W, H, {{"hold_deg", 0}}));
  const Image a = run(*follow, *scene, g0);
  const Image b = run(*follow, *scene, {g0.x + 0.6 * hold, g0.y});
  EXPECT_GT(test::compare_images(a, b, 0).max_error, 0);
}
