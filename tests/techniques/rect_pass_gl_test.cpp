// Passes drawn over rectangles (foveate/techniques/rect_pass.hpp) with a GL
// context (the fixture fails a test on any GL debug error): the pixels they
// reach.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "foveate/gpu/frame.hpp"
#include "foveate/techniques/pass_kit.hpp"
#include "foveate/techniques/rect_pass.hpp"
#include "gl_fixture.hpp"
#include "pixel_rects.hpp"

namespace foveate::tech {
namespace {

using test::covered;

class RectPassTest : public test::GlTest {};

TEST_F(RectPassTest, DrawsExactlyTheRectangles) {
  PassKit kit;
  gpu::RenderTarget t;
  t.ensure(64, 48, GL_RGBA8);
  t.clear(1, 1, 1, 1);
  const std::vector<PixelRect> rects = {{2, 3, 10, 7}, {20, 0, 64, 5}, {0, 40, 1, 48}};
  // vrs/mask.frag writes black.
  kit.rect_pass(kit.over_rects("vrs/mask.frag"), rects, t);
  const Image img = gpu::read_framebuffer(t.framebuffer(), 64, 48);
  int black = 0;
  for (int y = 0; y < 48; ++y) {
    for (int x = 0; x < 64; ++x) {
      const bool b = img.at(x, 47 - y)[0] == 0;  // read back top row first
      black += b ? 1 : 0;
      EXPECT_EQ(b, covered(rects, x, y)) << x << "," << y;
    }
  }
  EXPECT_EQ(black, 8 * 4 + 44 * 5 + 8);
  // Nothing to draw: nothing drawn, no error.
  kit.rect_pass(kit.over_rects("vrs/mask.frag"), {}, t);
}

TEST_F(RectPassTest, BackToBackPassesEachDrawTheirOwnRectangles) {
  // Passes queued with no wait between them, each with its own rectangles
  // (more each time, so the store grows): every pass draws its own. A driver
  // that runs a draw's vertex work after later commands (NVIDIA's) would
  // draw the earlier passes from the last pass's rectangles if one store were
  // rewritten in place (gpu::Buffer::stream). llvmpipe runs each draw's
  // vertex work when it is issued, so there this test could not fail.
  if (test::on_llvmpipe()) {
    GTEST_SKIP() << "llvmpipe runs vertex work at draw time: a rewritten store cannot show";
  }
  PassKit kit;
  gpu::RenderTarget t;
  t.ensure(64, 48, GL_RGBA8);
  t.clear(1, 1, 1, 1);
  const std::vector<std::vector<PixelRect>> passes = {
      {{0, 0, 8, 8}},
      {{16, 0, 24, 8}, {32, 0, 40, 8}},
      {{0, 16, 8, 24}, {16, 16, 24, 24}, {32, 16, 40, 24}, {48, 16, 56, 24}}};
  for (const auto& rects : passes) kit.rect_pass(kit.over_rects("vrs/mask.frag"), rects, t);
  const Image img = gpu::read_framebuffer(t.framebuffer(), 64, 48);
  for (const auto& rects : passes) {
    for (int y = 0; y < 48; ++y) {
      for (int x = 0; x < 64; ++x) {
        if (covered(rects, x, y)) {
          ASSERT_EQ(img.at(x, 47 - y)[0], 0) << x << "," << y;
        }
      }
    }
  }
}

}  // namespace
}  // namespace foveate::tech
