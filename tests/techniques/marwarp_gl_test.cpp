// marwarp (issue 30): the native disc is native's pixels, the periphery keeps
// native's light, and the resolve shows no seam where the angle wraps and no
// ring where the disc, its blend band and the G-buffer levels meet.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "foveate/core/acuity_warp.hpp"
#include "foveate/gpu/object_counts.hpp"
#include "foveate/techniques/frame_runner.hpp"
#include "foveate/techniques/technique.hpp"
#include "gl_fixture.hpp"
#include "image_compare.hpp"
#include "srgb.hpp"
#include "supersampled.hpp"

using namespace foveate;

namespace {

class Marwarp : public test::GlTest {
 protected:
  TechniqueConfig config(int w, int h, std::map<std::string, double> params = {}) const {
    TechniqueConfig c;
    c.display = Display::load("desktop-1080p").resized(w, h);
    c.acuity = AcuityModel::preset("A");
    c.margin = 1.0;  // the paper's plan: the coarsest sampling, the most to see
    c.params = std::move(params);
    return c;
  }
  static Image run(Technique& t, Scene& s, Vec2d gaze, FrameStats* stats = nullptr) {
    FrameRunnerOptions o;
    o.width = t.display().width_px;
    o.height = t.display().height_px;
    o.start_time_s = 1.0;
    FrameRunner r(s, o);
    const FrameStats st = r.render(t, 0, GazeState{gaze});
    if (stats) *stats = st;
    return r.read_output();
  }
  Image native(Scene& s, int w, int h) {
    auto n = make_technique("native", config(w, h));
    return run(*n, s, {w / 2.0, h / 2.0});
  }
  static double fovea_px(const Technique& t, Vec2d gaze) {
    for (const OverlayShape& s : t.overlay(GazeState{gaze})) {
      if (s.kind == OverlayShape::Kind::Circle) return s.w;
    }
    return 0.0;
  }
  // Mean absolute error against `ref` (codes, three channels) over the
  // pixels whose centres lie from r0 to r1 from the gaze.
  static double ring_error(const Image& img, const Image& ref, Vec2d g, double r0, double r1) {
    double sum = 0;
    int n = 0;
    for (int y = 0; y < img.height; ++y) {
      for (int x = 0; x < img.width; ++x) {
        const double r = std::hypot(x + 0.5 - g.x, y + 0.5 - g.y);
        if (r < r0 || r >= r1) continue;
        for (int c = 0; c < 3; ++c) sum += std::abs(int(img.at(x, y)[c]) - int(ref.at(x, y)[c]));
        ++n;
      }
    }
    return n ? sum / (3.0 * n) : 0.0;
  }
};

}  // namespace

TEST_F(Marwarp, FoveaIsNativeAndThePeripheryKeepsItsLuminance) {
  const int W = 960, H = 540;
  for (const char* name : {"detail", "guenter"}) {
    auto scene = load_scene(name);
    const Image ref = native(*scene, W, H);
    auto t = make_technique("marwarp", config(W, H));
    for (const Vec2d gaze : {Vec2d{480, 270}, Vec2d{150, 450}}) {
      FrameStats s;
      const Image img = run(*t, *scene, gaze, &s);
      const double fovea = fovea_px(*t, gaze);
      // The disc reaches where the buffer's spacing is one pixel.
      const AcuityWarpMapping m = AcuityWarp(t->display(), AcuityModel::preset("A")).mapping(gaze);
      EXPECT_GE(fovea, m.start_px() - 1e-6);
      const test::Comparison c = test::compare_disc(ref, img, gaze, fovea);
      EXPECT_TRUE(c.within(test::Tolerance{}))
          << name << ": max " << c.max_error << ", mean " << c.mean_error;
      EXPECT_EQ(c.max_error, 0) << name;  // native's pixels exactly
      const double periphery = test::mean_linear_luminance(ref, gaze, fovea);
      EXPECT_NEAR(test::mean_linear_luminance(img, gaze, fovea) / periphery, 1.0, 0.02) << name;
      // (detail, the stress case, has edges everywhere: most of its texels
      // are reshaded.)
      EXPECT_LT(s.shaded_pixels, (name == std::string("detail") ? 0.6 : 0.25) * W * H) << name;
      ASSERT_EQ(s.parts.size(), 3u);
      EXPECT_GT(s.parts[0].pixels, 0.0);  // the buffer
      EXPECT_GT(s.parts[1].pixels, 0.0);  // the native disc
      EXPECT_GT(s.parts[2].pixels, 0.0);  // the reshaded texels' new samples
    }
  }
}

TEST_F(Marwarp, NoSeamWhereTheAngleWraps) {
  // The angle wraps on the ray to the right of the gaze (row 0 meets the
  // last row). The error against native in the rows just above and below
  // that ray is no worse than a little further up or down, where nothing
  // wraps.
  const int W = 640, H = 360;
  auto scene = load_scene("cheap");
  const Image ref = native(*scene, W, H);
  auto t = make_technique("marwarp", config(W, H));
  const Image img = run(*t, *scene, {320, 180});
  auto band = [&](int y0) {
    double sum = 0;
    int n = 0;
    for (int y = y0; y <= y0 + 3; ++y) {
      for (int x = 400; x < 630; ++x) {
        for (int c = 0; c < 3; ++c) sum += std::abs(int(img.at(x, y)[c]) - int(ref.at(x, y)[c]));
        ++n;
      }
    }
    return sum / n;
  };
  EXPECT_LT(band(178), std::max(band(168), band(188)) + 1.0);
}

TEST_F(Marwarp, KeepsItsStorageAsTheGazeMoves) {
  // The rows follow the gaze (more off the centre, most in a corner). Once
  // the buffers have grown to the gazes' most rows, moving among them
  // allocates nothing, and a frame drawn into the taller buffer is the frame
  // a fresh technique draws at that gaze.
  const int W = 320, H = 180;
  const std::vector<Vec2d> gazes{{160, 90}, {10, 10}, {250, 60}, {100, 150}};
  const AcuityWarp warp(config(W, H).display, AcuityModel::preset("A"));
  int most = 0;
  for (const Vec2d& g : gazes) most = std::max(most, warp.mapping(g).rows);
  ASSERT_GT(most, warp.mapping(gazes[0]).rows);  // the gazes do move the rows
  auto scene = load_scene("cheap");
  auto t = make_technique("marwarp", config(W, H));
  for (const Vec2d& g : gazes) run(*t, *scene, g);
  // What a run costs besides the technique (run() makes a frame runner,
  // whose output target is its own): a second frame at the same gaze.
  const gpu::GlObjectCounts c0 = gpu::gl_objects_created();
  run(*t, *scene, gazes.back());
  const gpu::GlObjectCounts c1 = gpu::gl_objects_created();
  Image centre;
  for (const Vec2d& g : gazes) {
    Image img = run(*t, *scene, g);
    if (g.x == gazes[0].x && g.y == gazes[0].y) centre = std::move(img);
  }
  const gpu::GlObjectCounts c2 = gpu::gl_objects_created();
  const long n = static_cast<long>(gazes.size());
  EXPECT_EQ(c2.textures - c1.textures, n * (c1.textures - c0.textures));
  EXPECT_EQ(c2.framebuffers - c1.framebuffers, n * (c1.framebuffers - c0.framebuffers));
  EXPECT_EQ(c2.renderbuffers - c1.renderbuffers, n * (c1.renderbuffers - c0.renderbuffers));
  auto fresh = make_technique("marwarp", config(W, H));
  const Image expected = run(*fresh, *scene, gazes[0]);
  const test::Comparison c = test::compare_images(expected, centre, 0);
  EXPECT_TRUE(c.size_matches);
  // The taller buffer puts the same rows at other texture coordinates: on
  // llvmpipe the frames are bit-identical; NVIDIA's driver rounds the
  // filter's weights there by one code at most (an H100). Rows read from
  // the taller buffer's unused part would differ by far more.
  EXPECT_LE(c.max_error, test::on_llvmpipe() ? 0 : 1);
}

TEST_F(Marwarp, NoRingInTheResolve) {
  // Going out from the gaze, the error against native grows without a
  // ring: no ring of 3 pixels is more than 1.36 times as far from native as
  // the farther of the rings either side of it (4 pixels away), across the
  // native disc's edge, its blend band, and the borders between G-buffer
  // levels (guenter) where the buffer is shaded from coarser geometry; with
  // the buffer's prefilter and without. The scenes' own detail varies that
  // much from ring to ring: 1.33 at worst on cheap; on guenter 1.28 without
  // the prefilter and 1.31 with it, at 17 pixels beyond the disc, where the
  // error of the rings 15-30 pixels out runs 2.8, 3.1, 2.5, 2.4, 3.1 (an
  // object's edge, not the resolve's: it comes and goes with the scene). A
  // seam in the resolve stands out by far more.
  const int W = 960, H = 540;
  for (const auto& [name, sharpen] : {std::pair{"cheap", 0.0}, std::pair{"guenter", 0.0},
                                      std::pair{"cheap", 0.12}, std::pair{"guenter", 0.12}}) {
    auto scene = load_scene(name);
    const Image ref = native(*scene, W, H);
    auto t = make_technique("marwarp", config(W, H, {{"sharpen", sharpen}}));
    const Vec2d g{480, 270};
    const Image img = run(*t, *scene, g);
    const double fovea = fovea_px(*t, g);
    double worst = 0, at = 0;
    for (double r = fovea + 4.0; r < 260.0; r += 1.0) {
      const double here = ring_error(img, ref, g, r, r + 3.0);
      const double beside = std::max(ring_error(img, ref, g, r - 7.0, r - 4.0),
                                     ring_error(img, ref, g, r + 4.0, r + 7.0));
      const double ratio = (here + 0.25) / (beside + 0.25);
      if (ratio > worst) worst = ratio, at = r;
    }
    EXPECT_LT(worst, 1.36) << name << ", sharpen " << sharpen << ": at " << at << " px (disc "
                           << fovea << " px)";
  }
}

TEST_F(Marwarp, ShadesTheMappingsTexelsOnly) {
  // At 1920x1080 and the paper's plan, the texels on the screen and the
  // native disc, without reshading edges: about a 24th of native's pixels
  // (docs/continuous.md).
  const int W = 1920, H = 1080;
  auto scene = load_scene("cheap");
  auto t = make_technique("marwarp", config(W, H, {{"edge_contrast", 0.0}}));
  FrameStats s;
  run(*t, *scene, {960, 540}, &s);
  EXPECT_LT(s.shaded_pixels, W * H / 20.0);
  EXPECT_GT(s.shaded_pixels, W * H / 30.0);
}

TEST_F(Marwarp, ReshadedEdgesComeCloserToTheSupersampledScene) {
  // One sample per texel aliases silhouettes and small objects; the texels
  // that differ from a neighbour, reshaded with more samples, bring the
  // periphery's edges (where the supersampled frame changes by more than 24
  // codes to a neighbouring pixel) closer to a 4x4 supersampled frame
  // (11.8 codes against 13.2 when this was written).
  const int W = 640, H = 360;
  auto scene = load_scene("guenter");
  const Image truth = test::supersampled_frame("guenter", config(W, H).display);
  // (With the buffer's prefilter, which the reshaded texels' samples
  // feed; without it the reshaded edges are no closer.)
  auto with = make_technique("marwarp", config(W, H, {{"sharpen", 0.12}}));
  auto without =
      make_technique("marwarp", config(W, H, {{"edge_contrast", 0.0}, {"sharpen", 0.12}}));
  const Vec2d g{320, 180};
  const double disc = fovea_px(*with, g);
  const auto edge_error = [&](const Image& img) {
    double sum = 0;
    int n = 0;
    for (int y = 1; y + 1 < H; ++y) {
      for (int x = 1; x + 1 < W; ++x) {
        if (std::hypot(x + 0.5 - g.x, y + 0.5 - g.y) < disc) continue;
        int step = 0;
        for (const auto& [dx, dy] :
             {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
          for (int c = 0; c < 3; ++c)
            step =
                std::max(step, std::abs(int(truth.at(x, y)[c]) - int(truth.at(x + dx, y + dy)[c])));
        }
        if (step <= 24) continue;
        for (int c = 0; c < 3; ++c) sum += std::abs(int(img.at(x, y)[c]) - int(truth.at(x, y)[c]));
        n += 3;
      }
    }
    return sum / n;
  };
  const double e_with = edge_error(run(*with, *scene, g));
  const double e_without = edge_error(run(*without, *scene, g));
  EXPECT_LT(e_with, 0.93 * e_without) << e_with << " against " << e_without;
}

TEST_F(Marwarp, SixteenSamplesAverageTheTexel) {
  // samples=16 (a 4x4 grid in every texel) is the texel's area average. On a
  // grating far finer than the periphery's texels (mean linear luminance
  // 0.5), one sample per texel aliases into bands of black and white; the
  // average leaves the periphery near 0.5. Each sample is counted.
  const int W = 640, H = 360;
  auto scene = load_scene(std::string(FOVEATE_TEST_DATA) + "/shadertoy/grating.glsl");
  const Vec2d g{320, 180};
  std::map<int, double> deviation, buffer;
  for (const int n : {1, 4, 9, 16}) {
    auto t =
        make_technique("marwarp", config(W, H, {{"edge_contrast", 0.0}, {"samples", double(n)}}));
    FrameStats s;
    const Image img = run(*t, *scene, g, &s);
    buffer[n] = s.parts[0].pixels;
    // Mean |L - 0.5| beyond twice the native disc, where texels span pixels.
    const double r0 = 2.0 * fovea_px(*t, g);
    double sum = 0;
    int count = 0;
    for (int y = 0; y < H; ++y) {
      for (int x = 0; x < W; ++x) {
        if (std::hypot(x + 0.5 - g.x, y + 0.5 - g.y) < r0) continue;
        sum += std::abs(test::to_linear(img.at(x, y)[1]) - 0.5);
        ++count;
      }
    }
    deviation[n] = sum / count;
  }
  for (const int n : {4, 9, 16}) EXPECT_EQ(buffer[n], n * buffer[1]) << n;
  // (0.285, 0.130, 0.071 and 0.044 for 1, 4, 9 and 16 when this was written.)
  EXPECT_LT(deviation[16], 0.25 * deviation[1]) << deviation[16] << " against " << deviation[1];
  EXPECT_LT(deviation[16], 0.5 * deviation[4]) << deviation[16] << " against " << deviation[4];
  EXPECT_LT(deviation[9], deviation[4]) << deviation[9] << " against " << deviation[4];
}
