// Multipass Shadertoy projects under a debug GL context (any GL error fails
// the test): feedback buffers counted frame by frame through the FrameRunner,
// with a foveated technique on the Image pass and the buffers advancing once
// per distinct frame.
#include <gtest/gtest.h>

#include <string>

#include "foveate/core/display.hpp"
#include "foveate/core/error.hpp"
#include "foveate/techniques/frame_runner.hpp"
#include "foveate/techniques/technique.hpp"
#include "gl_fixture.hpp"

namespace foveate {
namespace {

constexpr int kW = 64, kH = 36;
const std::string kData = FOVEATE_TEST_DATA;

class Multipass : public test::GlTest {
 protected:
  static std::unique_ptr<Technique> technique(const std::string& name) {
    TechniqueConfig c;
    c.display = Display::load("desktop-1080p").resized(kW, kH);
    return make_technique(name, c);
  }
  static FrameRunnerOptions options() {
    FrameRunnerOptions o;
    o.width = kW;
    o.height = kH;
    return o;
  }
};

TEST_F(Multipass, FeedbackCountsFramesAndRepeatsNothing) {
  auto scene = load_scene(kData + "/shadertoy/multipass/counter.json");
  FrameRunner r(*scene, options());
  auto native = technique("native");
  auto inset = technique("inset");
  for (int k = 0; k < 4; ++k) {
    // Two techniques per frame, as bench interleaves them: the buffers must
    // advance once per frame, not once per render.
    for (Technique* t : {native.get(), inset.get()}) {
      r.render(*t, k, GazeState{});
      const Image img = r.read_output();
      const std::uint8_t* px = img.at(kW / 2, kH / 2);
      // Buffer A holds k + 1 (red = A / 10), Buffer B the sum 1..k+1 (green =
      // B / 100), blue = iFrame / 10; sRGB-encoded PNG codes = value * 255.
      EXPECT_NEAR(px[0], (k + 1) / 10.0 * 255.0, 1.5) << t->name() << " frame " << k;
      EXPECT_NEAR(px[1], (k + 1) * (k + 2) / 2 / 100.0 * 255.0, 1.5) << t->name() << " frame " << k;
      EXPECT_NEAR(px[2], k / 10.0 * 255.0, 1.5) << t->name() << " frame " << k;
    }
  }
  // Starting over from frame 0 clears the buffers: the same image as before.
  r.render(*native, 0, GazeState{});
  EXPECT_NEAR(r.read_output().at(kW / 2, kH / 2)[0], 25.5, 1.5);
}

TEST_F(Multipass, EveryImageChannelAndBufferIsBound) {
  auto scene = load_scene(kData + "/shadertoy/multipass/counter.json");
  FrameRunner r(*scene, options());
  auto native = technique("native");
  r.render(*native, 0, GazeState{});
  // The left eighth shows quadrants.png (top-left red).
  const Image img = r.read_output();
  const std::uint8_t* px = img.at(2, 2);
  EXPECT_EQ(px[0], 255);
  EXPECT_EQ(px[1], 0);
  EXPECT_EQ(px[2], 0);
}

}  // namespace
}  // namespace foveate
