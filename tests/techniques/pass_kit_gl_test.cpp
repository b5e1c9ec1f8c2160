// PassKit with a GL context: the fragments a shading pass counts, read
// after later passes; and supersample_edges: which texels it reshades, what
// it writes there, and what it leaves alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "foveate/core/error.hpp"
#include "foveate/gpu/object_counts.hpp"
#include "foveate/scenes/scene.hpp"
#include "foveate/techniques/pass_kit.hpp"
#include "gl_fixture.hpp"

namespace foveate::tech {
namespace {

constexpr int kW = 40, kH = 24;
// The pass covers columns [0, 36) only: marks in two words of 32 per row.
constexpr int kLast = 36;

using Texels = std::vector<std::array<float, 4>>;

std::unique_ptr<Scene> shadertoy_scene(const char* name, const std::string& source) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << source;
  auto scene = load_scene(path.string());
  FrameInput f;
  f.width = kW;
  f.height = kH;
  scene->update(f);
  return scene;
}

double linear(double s) { return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4); }
double encode(double l) {
  return l <= 0.0031308 ? l * 12.92 : 1.055 * std::pow(l, 1 / 2.4) - 0.055;
}

// A scene's colour at a screen position, in linear light.
using Colour = std::array<double, 3>;
using SceneAt = std::function<Colour(double, double)>;

// A scene whose colour at screen position p is (p.x / 64, p.y / 64, 0.25),
// sRGB-encoded as Shadertoy's output is.
std::unique_ptr<Scene> gradient_scene() {
  return shadertoy_scene("foveate_edges_gradient.glsl",
                         "void mainImage(out vec4 c, in vec2 p) {\n"
                         "  c = vec4(p.x / 64.0, p.y / 64.0, 0.25, 1.0);\n}\n");
}
Colour gradient_at(double x, double y) { return {linear(x / 64), linear(y / 64), linear(0.25)}; }

// A step to the right of x = 10.2 in red, above y = 6.8 in green, and where
// both hold in blue: samples a third of a texel from (10.5, 6.5) fall on
// either side of both, and diagonal from each other only one way.
std::unique_ptr<Scene> step_scene() {
  return shadertoy_scene("foveate_edges_step.glsl",
                         "void mainImage(out vec4 c, in vec2 p) {\n"
                         "  bool x = p.x > 10.2, y = p.y > 6.8;\n"
                         "  c = vec4(x ? 0.9 : 0.1, y ? 0.9 : 0.1, x && y ? 0.9 : 0.1, 1.0);\n}\n");
}
Colour step_at(double x, double y) {
  const double lo = linear(0.1), hi = linear(0.9);
  return {x > 10.2 ? hi : lo, y > 6.8 ? hi : lo, x > 10.2 && y > 6.8 ? hi : lo};
}

// What a reshaded texel (x, y) holds, in linear light: the mean of the four
// rotated-grid samples; or with 2, of the two on its diagonal a third of a
// texel from its centre and the centre's `before`.
Colour edge_mean(const SceneAt& at, int x, int y, int samples, double before) {
  const double grid[4][2] = {{0.125, 0.375}, {0.375, -0.125}, {-0.125, -0.375}, {-0.375, 0.125}};
  const double diagonal[2][2] = {{-1.0 / 3, 1.0 / 3}, {1.0 / 3, -1.0 / 3}};
  Colour m{0, 0, 0};
  const auto add = [&](const double(*offsets)[2], int n, double weight) {
    for (int i = 0; i < n; ++i) {
      const Colour c = at(x + 0.5 + offsets[i][0], y + 0.5 + offsets[i][1]);
      for (int k = 0; k < 3; ++k) m[size_t(k)] += weight * c[size_t(k)];
    }
  };
  if (samples == 4) {
    add(grid, 4, 0.25);
  } else {
    add(diagonal, 2, 1.0 / 3);
    for (double& v : m) v += before / 3;
  }
  return m;
}

// edges.frag's rule, on the CPU: luminance against the four neighbours
// (columns clamped to the covered ones, rows wrapping at `rows`).
bool marked(const Texels& t, int x, int y, double contrast, int rows = kH) {
  const auto luma = [&](int px, int py) {
    const auto& v = t[size_t(py * kW + px)];
    return 0.2126 * v[0] + 0.7152 * v[1] + 0.0722 * v[2];
  };
  const double c = luma(x, y);
  const double n[4] = {luma(std::max(x - 1, 0), y), luma(std::min(x + 1, kLast - 1), y),
                       luma(x, (y + 1) % rows), luma(x, (y + rows - 1) % rows)};
  const double lo = std::min({c, n[0], n[1], n[2], n[3]});
  const double hi = std::max({c, n[0], n[1], n[2], n[3]});
  return hi - lo > contrast * (hi + 0.02);
}

Texels read(const gpu::RenderTarget& t) {
  Texels out(size_t(kW * kH));
  glGetTextureImage(t.color().id(), 0, GL_RGBA, GL_FLOAT,
                    static_cast<GLsizei>(out.size() * sizeof(out[0])), out.data());
  return out;
}

// Each test runs both ways: with the total read back and the packed pass
// scissored (software renderers), and with the GPU sizing the packed pass
// and the store from the total it listed (hardware ones).
class SupersampleEdgesTest : public test::GlTest, public ::testing::WithParamInterface<bool> {
 protected:
  // Runs the pass over `grey` (a linear luminance per texel, row 0 at the
  // bottom) in a buffer of `format` (RGBA16F, or GL_SRGB8_ALPHA8, which
  // stores sRGB-encoded bytes) and checks every texel: the marked ones hold
  // the scene's edge_mean with `samples`, the rest what they held. With
  // `rows`, the buffer's first rows only, wrapping there (a polar buffer
  // taller than its mapping's rows). Returns the count the pass reported.
  double run(const std::vector<float>& grey, Texels* after = nullptr, GLenum format = GL_RGBA16F,
             int rows = 0, int samples = 4) {
    const bool srgb = format == GL_SRGB8_ALPHA8;
    // An 8-bit code's worth in linear light at the brightest, else fp16's.
    const double tolerance = srgb ? 6e-3 : 2e-3;
    Texels before(size_t(kW * kH)), stored(size_t(kW * kH));
    for (size_t i = 0; i < before.size(); ++i) {
      before[i] = {grey[i], grey[i], grey[i], 1.0f};
      const float v = srgb ? float(encode(grey[i])) : grey[i];
      stored[i] = {v, v, v, 1.0f};
    }
    gpu::RenderTarget buffer;
    buffer.ensure(kW, kH, format);
    glTextureSubImage2D(buffer.color().id(), 0, 0, 0, kW, kH, GL_RGBA, GL_FLOAT, stored.data());
    gpu::RenderTarget scratch;
    scratch.ensure(kW, kH, format);
    const View view = View::full(kW, kH);
    kit_.set_indirect_edges(GetParam());
    const double n =
        kit_.supersample_edges(
                *scene_, view, kMapRect, buffer, scratch.color(), {{0, 0, kLast, kH}}, 0, kLast,
                0.25, [&](const gpu::Program& p, gpu::Samplers&) { set_rect_mapping(p, view); },
                true, rows, samples)
            .read();
    Texels got = read(buffer);  // as stored: decoded here
    if (srgb)
      for (auto& t : got)
        for (int c = 0; c < 3; ++c) t[size_t(c)] = float(linear(t[size_t(c)]));
    int expected = 0;
    for (int y = 0; y < kH; ++y) {
      for (int x = 0; x < kW; ++x) {
        const auto& g = got[size_t(y * kW + x)];
        const int wrap = rows > 0 ? rows : kH;
        if (x < kLast && y < wrap && marked(before, x, y, 0.25, wrap)) {
          ++expected;
          const Colour m = edge_mean(scene_at_, x, y, samples, grey[size_t(y * kW + x)]);
          for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(g[size_t(c)], m[size_t(c)], tolerance) << x << "," << y;
        } else {
          for (int c = 0; c < 4; ++c)
            EXPECT_NEAR(g[size_t(c)], before[size_t(y * kW + x)][size_t(c)], tolerance)
                << x << "," << y;
        }
      }
    }
    EXPECT_EQ(n, double(expected));
    if (after) *after = got;
    return n;
  }

  PassKit kit_;
  std::unique_ptr<Scene> scene_ = gradient_scene();
  SceneAt scene_at_ = gradient_at;
};

TEST_P(SupersampleEdgesTest, ReshadesTheContrastyTexelsOfTheCoverOnly) {
  // A step from 0.2 to 0.8 between columns 23 and 24, one bright texel at
  // (6, 8), and one at (38, 4), outside the covered columns.
  std::vector<float> grey(size_t(kW * kH), 0.2f);
  for (int y = 0; y < kH; ++y)
    for (int x = 24; x < kW; ++x) grey[size_t(y * kW + x)] = 0.8f;
  grey[size_t(8 * kW + 6)] = 0.9f;
  grey[size_t(4 * kW + 38)] = 0.1f;
  Texels first, second;
  // Both sides of the step in every row, the bright texel and its four
  // neighbours.
  EXPECT_EQ(run(grey, &first), 2 * kH + 5);
  // The same again, texel for texel (the list's order does not depend on
  // the threads').
  run(grey, &second);
  EXPECT_EQ(first, second);
}

TEST_P(SupersampleEdgesTest, EveryTexelOfACheckerboardIsReshaded) {
  // Rows of many marks each: the list spans many of its own rows.
  std::vector<float> grey(size_t(kW * kH));
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) grey[size_t(y * kW + x)] = (x + y) % 2 ? 0.9f : 0.1f;
  EXPECT_EQ(run(grey), kLast * kH);
}

TEST_P(SupersampleEdgesTest, AnSrgbBufferGetsItsReshadedTexelsEncoded) {
  // logpolar's and vrs's buffers store sRGB-encoded bytes, which image
  // stores do not encode by themselves.
  std::vector<float> grey(size_t(kW * kH), 0.2f);
  for (int y = 0; y < kH; ++y)
    for (int x = 24; x < kW; ++x) grey[size_t(y * kW + x)] = 0.8f;
  EXPECT_EQ(run(grey, nullptr, GL_SRGB8_ALPHA8), 2 * kH);
}

TEST_P(SupersampleEdgesTest, RowsWrapAtTheMappingsRowsNotTheBuffersHeight) {
  // marwarp's buffer keeps the most rows it has needed: with 18 rows in use,
  // row 17 neighbours row 0 (bright), not row 18 (as dark as it), and rows
  // 18-23 are left alone. Wrapping at the height would mark row 23 instead.
  constexpr int kRows = 18;
  std::vector<float> grey(size_t(kW * kH), 0.3f);
  for (int x = 0; x < kW; ++x) grey[size_t(x)] = 0.9f;
  EXPECT_EQ(run(grey, nullptr, GL_RGBA16F, kRows), 3 * kLast);
}

TEST_P(SupersampleEdgesTest, TwoSamplesOnTheDiagonalAreAveragedWithTheCentre) {
  // One bright texel at (10, 6) and its neighbours are reshaded over the
  // step scene. With 2 samples texel (10, 6) holds (0.9 + the samples at
  // (10.17, 6.83) and (10.83, 6.17)) / 3: red and green a third bright
  // besides the centre, blue dark (neither sample is past both steps; on
  // the other diagonal one would be). Four on the rotated grid give other
  // means: red 3/4 bright, green and blue 1/4.
  scene_ = step_scene();
  scene_at_ = step_at;
  std::vector<float> grey(size_t(kW * kH), 0.2f);
  grey[size_t(6 * kW + 10)] = 0.9f;
  EXPECT_EQ(run(grey, nullptr, GL_RGBA16F, 0, 2), 5);
  EXPECT_EQ(run(grey, nullptr, GL_RGBA16F, 0, 4), 5);
  // An sRGB buffer's centre is read decoded, as the samples are averaged.
  EXPECT_EQ(run(grey, nullptr, GL_SRGB8_ALPHA8, 0, 2), 5);
  gpu::RenderTarget buffer, scratch;
  buffer.ensure(kW, kH, GL_RGBA16F);
  scratch.ensure(kW, kH, GL_RGBA16F);
  const View view = View::full(kW, kH);
  EXPECT_THROW(kit_.supersample_edges(*scene_, view, kMapRect, buffer, scratch.color(),
                                      {{0, 0, kW, kH}}, 0, kW, 0.25, {}, true, 0, 3),
               Error);
}

TEST_P(SupersampleEdgesTest, AFlatBufferIsLeftAlone) {
  EXPECT_EQ(run(std::vector<float>(size_t(kW * kH), 0.5f)), 0);
}

TEST_P(SupersampleEdgesTest, CallsOfOneSizeEachCountTheirOwnTexels) {
  // marwarp reshades each G-buffer level's columns of one buffer: the calls
  // share their storage, and the counts are read after the last of them.
  gpu::RenderTarget a, b, scratch;
  for (gpu::RenderTarget* t : {&a, &b, &scratch}) t->ensure(kW, kH, GL_RGBA16F);
  std::vector<std::array<float, 4>> flat(size_t(kW * kH), {0.5f, 0.5f, 0.5f, 1.0f});
  glTextureSubImage2D(a.color().id(), 0, 0, 0, kW, kH, GL_RGBA, GL_FLOAT, flat.data());
  flat[size_t(8 * kW + 6)] = {0.9f, 0.9f, 0.9f, 1.0f};  // itself and its 4 neighbours
  glTextureSubImage2D(b.color().id(), 0, 0, 0, kW, kH, GL_RGBA, GL_FLOAT, flat.data());
  const View view = View::full(kW, kH);
  const SetUniforms set = [&](const gpu::Program& p, gpu::Samplers&) { set_rect_mapping(p, view); };
  kit_.set_indirect_edges(GetParam());
  const PixelCount first = kit_.supersample_edges(*scene_, view, kMapRect, b, scratch.color(),
                                                  {{0, 0, kW, kH}}, 0, kW, 0.25, set);
  const PixelCount second = kit_.supersample_edges(*scene_, view, kMapRect, a, scratch.color(),
                                                   {{0, 0, kW, kH}}, 0, kW, 0.25, set);
  EXPECT_EQ(first.read(), 5.0);
  EXPECT_EQ(second.read(), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Paths, SupersampleEdgesTest, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& i) {
                           return i.param ? "Indirect" : "ReadBack";
                         });

// A frame's shading passes, read only after the last of them: each count
// is its own pass's, sums add up (a count twice counts twice), and the queries are
// reused once the counts are dropped.
class PixelCountTest : public test::GlTest {};

TEST_F(PixelCountTest, CountsReadAfterLaterPassesAreEachPasssOwn) {
  PassKit kit;
  const std::unique_ptr<Scene> scene = gradient_scene();
  gpu::RenderTarget target;
  target.ensure(kW, kH, GL_RGBA16F);
  const View view = View::full(kW, kH);
  const SetUniforms set = [&](const gpu::Program& p, gpu::Samplers&) { set_rect_mapping(p, view); };
  const auto frame = [&] {
    const std::vector<PixelRect> a{{0, 0, 10, 4}}, b{{5, 6, 25, 12}};
    const PixelCount ca = kit.shade(*scene, view, kMapRect, target, set, {}, false, &a);
    const PixelCount cb = kit.shade(*scene, view, kMapRect, target, set, {}, false, &b);
    const PixelCount all = kit.shade(*scene, view, kMapRect, target, set);
    EXPECT_EQ(ca.read(), 40.0);
    EXPECT_EQ(cb.read(), 120.0);
    EXPECT_EQ(all.read(), double(kW * kH));
    EXPECT_EQ((ca + cb).read(), 160.0);
    EXPECT_EQ((ca + ca + PixelCount(5.0)).read(), 85.0);
    EXPECT_EQ(ca.read(), 40.0);  // read twice, the same
  };
  frame();
  const long queries = gpu::gl_objects_created().queries;
  frame();
  frame();
  EXPECT_EQ(gpu::gl_objects_created().queries, queries);
  EXPECT_EQ(PixelCount().read(), 0.0);
}

// A scene that filters by the samples' spacing (FOVEATE_FOOTPRINT) is told
// it by every shading pass: 1 at native sampling, the mapping's spacing in a
// subsampled buffer, half of it for an edge texel's four samples (and
// 1/sqrt(3) for the three of two beside its centre). The scene
// shows the spacing in green (an eighth of it) beside a step in red.
class ShadingPassTest : public test::GlTest {};

TEST_F(ShadingPassTest, TellsTheSceneTheSpacingOfItsSamples) {
  const auto path = std::filesystem::temp_directory_path() / "foveate_footprint_scene.glsl";
  std::ofstream(path)
      << "#define FOVEATE_FOOTPRINT 1\n"
         "float foveate_footprint_px = 1.0;\n"
         "void mainImage(out vec4 c, in vec2 p) {\n"
         "  c = vec4(p.x < 20.0 ? 0.1 : 0.9, foveate_footprint_px / 8.0, 0.0, 1.0);\n"
         "}\n";
  auto scene = load_scene(path.string());
  FrameInput f;
  f.width = 2 * kW;
  f.height = 2 * kH;
  scene->update(f);
  PassKit kit;
  const auto spacing = [](const std::array<float, 4>& t) { return 8.0 * encode(t[1]); };
  // Native sampling: a view the target's size.
  gpu::RenderTarget native;
  native.ensure(2 * kW, 2 * kH, GL_RGBA16F);
  const View full = View::full(2 * kW, 2 * kH);
  (void)kit.shade(*scene, full, kMapRect, native,
                  [&](const gpu::Program& p, gpu::Samplers&) { set_rect_mapping(p, full); });
  std::vector<std::array<float, 4>> n(size_t(4 * kW * kH));
  glGetTextureImage(native.color().id(), 0, GL_RGBA, GL_FLOAT,
                    static_cast<GLsizei>(n.size() * sizeof(n[0])), n.data());
  EXPECT_NEAR(spacing(n[size_t(5 * 2 * kW + 33)]), 1.0, 0.01);
  // Half resolution: the same screen in a kW x kH buffer, then its edges.
  gpu::RenderTarget half, scratch;
  half.ensure(kW, kH, GL_RGBA16F);
  scratch.ensure(kW, kH, GL_RGBA16F);
  View v = full;
  v.target_width = kW;
  v.target_height = kH;
  const SetUniforms set = [&](const gpu::Program& p, gpu::Samplers&) { set_rect_mapping(p, v); };
  (void)kit.shade(*scene, v, kMapRect, half, set);
  EXPECT_NEAR(spacing(read(half)[size_t(5 * kW + 30)]), 2.0, 0.01);
  EXPECT_GT(kit.supersample_edges(*scene, v, kMapRect, half, scratch.color(), {{0, 0, kW, kH}}, 0,
                                  kW, 0.25, set, false)
                .read(),
            0.0);
  const Texels after = read(half);
  int reshaded = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const auto& t = after[size_t(y * kW + x)];
      const bool edge = x == 9 || x == 10;  // either side of the step at screen x = 20
      EXPECT_NEAR(spacing(t), edge ? 1.0 : 2.0, 0.01) << x << "," << y;
      reshaded += edge;
    }
  }
  EXPECT_EQ(reshaded, 2 * kH);
  // Two samples on the diagonal: three in the texel with the centre, each
  // told 2 / sqrt(3); the centre keeps the 2 it was shaded with.
  (void)kit.shade(*scene, v, kMapRect, half, set);
  EXPECT_GT(kit.supersample_edges(*scene, v, kMapRect, half, scratch.color(), {{0, 0, kW, kH}}, 0,
                                  kW, 0.25, set, false, 0, 2)
                .read(),
            0.0);
  const double mean = (linear(2.0 / 8) + 2 * linear(2.0 / std::sqrt(3.0) / 8)) / 3;
  EXPECT_NEAR(spacing(read(half)[size_t(5 * kW + 10)]), 8 * encode(mean), 0.01);
}

}  // namespace
}  // namespace foveate::tech
