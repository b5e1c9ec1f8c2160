#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <memory>
#include <span>
#include <vector>

#include "foveate/core/error.hpp"
#include "foveate/gpu/frame.hpp"
#include "foveate/gpu/pass.hpp"
#include "foveate/gpu/readback.hpp"
#include "foveate/gpu/shader.hpp"
#include "foveate_embedded/gpu_test_shaders.hpp"
#include "gl_fixture.hpp"

using namespace foveate;
using foveate::test::GlTest;

class Gpu : public GlTest {};

TEST_F(Gpu, HeadlessCoreContext) {
  EXPECT_NE(context().backend().find("egl"), std::string::npos);
  GLint major = 0, minor = 0, mask = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
  EXPECT_GE(major * 10 + minor, 45);
  EXPECT_TRUE(mask & GL_CONTEXT_CORE_PROFILE_BIT);
}

TEST_F(Gpu, DrawAndReadBackWithIncludes) {
  gpu::ShaderCompiler c({embedded::gpu_test_shaders()});
  gpu::Program p = c.build("fullscreen.vert", "uses_include.frag");
  gpu::Texture t = gpu::Texture::create_2d(GL_RGBA8, 8, 4);
  gpu::Framebuffer fb = gpu::Framebuffer::create();
  fb.attach(GL_COLOR_ATTACHMENT0, t);
  fb.check("test");
  gpu::VertexArray vao = gpu::VertexArray::create();
  fb.bind();
  glViewport(0, 0, 8, 4);
  p.use();
  glBindVertexArray(vao.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  const Image img = gpu::read_texture(t);
  ASSERT_EQ(img.width, 8);
  // GL lets a float-to-unorm conversion round either way at a code's midpoint
  // (llvmpipe gives 128 for 0.5, NVIDIA's driver 127): within one code.
  EXPECT_NEAR(img.at(7, 3)[0], 64, 1);
  EXPECT_NEAR(img.at(0, 0)[1], 128, 1);
  EXPECT_NEAR(img.at(3, 2)[2], 191, 1);
}

TEST_F(Gpu, CompileErrorNamesOriginalFileAndLine) {
  gpu::ShaderCompiler c({embedded::gpu_test_shaders()});
  try {
    c.build("fullscreen.vert", "broken.frag");
    FAIL() << "expected a compile error";
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("broken.frag:5:"), std::string::npos) << m;
    EXPECT_NE(m.find("undefined_thing"), std::string::npos) << m;
  }
}

TEST_F(Gpu, MapsDriverLogs) {
  const std::vector<std::string> names = {"a.frag", "b.glsl"};
  EXPECT_EQ(gpu::map_info_log("1:7(3): error: bad\n", names), "b.glsl:7:3: error: bad\n");
  EXPECT_EQ(gpu::map_info_log("0(12) : error C1008: undefined\n", names),
            "a.frag:12: error C1008: undefined\n");
}

TEST_F(Gpu, MapsDriverLogsByLineWhateverTheSourceNumber) {
  // a.frag lines 1-3 at 2-4, b.glsl lines 1-5 at 6-10, a.frag from line 4 at 12.
  gpu::SourceMap map;
  map.names = {"a.frag", "b.glsl"};
  map.segments = {{0, 2, 1, 3}, {1, 6, 1, 5}, {0, 12, 4, 10}};
  // Mesa reports source 0 for semantic errors: the line decides.
  EXPECT_EQ(gpu::map_info_log("0:8(11): error: `x' undeclared\n", map),
            "b.glsl:3:11: error: `x' undeclared\n");
  EXPECT_EQ(gpu::map_info_log("0:13(1): error: y\n", map), "a.frag:5:1: error: y\n");
  EXPECT_EQ(gpu::map_info_log("1(7) : error C0000: z\n", map), "b.glsl:2: error C0000: z\n");
  // Lines outside every segment fall back to the source number; other
  // lines pass through, however long.
  EXPECT_EQ(gpu::map_info_log("1:99(2): w\n", map), "b.glsl:99:2: w\n");
  const std::string long_line = "0:8(1): `" + std::string(300000, 'q') + "' undeclared";
  EXPECT_EQ(gpu::map_info_log(long_line, map).substr(0, 12), "b.glsl:3:1: ");
  EXPECT_EQ(gpu::map_info_log("warning: something\n", map), "warning: something\n");
}

TEST_F(Gpu, SemanticErrorInAUserPieceNamesItsLine) {
  gpu::ShaderCompiler c;
  try {
    c.build(
        {gpu::StageSource{GL_VERTEX_SHADER, {{"fullscreen.vert", {}}}},
         gpu::StageSource{GL_FRAGMENT_SHADER,
                          {{"first.glsl", "// one\n// two\nfloat f() { return 1.0; }\n"},
                           {"user.glsl", "out vec4 o;\nvoid main() {\n  o = vec4(nope);\n}\n"}}}},
        "test");
    FAIL() << "expected a compile error";
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("user.glsl:3:"), std::string::npos) << m;
    EXPECT_EQ(m.find("first.glsl"), std::string::npos) << m;
  }
}

TEST_F(Gpu, UnknownShaderAndBadTextureSize) {
  gpu::ShaderCompiler c;
  EXPECT_THROW((void)c.file("nope.frag"), Error);
  EXPECT_THROW(gpu::Texture::create_2d(GL_RGBA8, 0, 4), Error);
  EXPECT_THROW(gpu::Texture::create_2d(GL_RGBA8, 1 << 20, 4), Error);
}

TEST_F(Gpu, RaiiMovesOwnership) {
  gpu::Buffer a = gpu::Buffer::create(64, nullptr, GL_DYNAMIC_STORAGE_BIT);
  const GLuint id = a.id();
  gpu::Buffer b = std::move(a);
  EXPECT_EQ(a.id(), 0u);
  EXPECT_EQ(b.id(), id);
  EXPECT_TRUE(glIsBuffer(id));
  b.reset();
  EXPECT_FALSE(glIsBuffer(id));
}

TEST_F(Gpu, DebugContextReportsErrors) {
  glEnable(0x1234);  // GL_INVALID_ENUM
  const auto errors = context().take_debug_errors();
  ASSERT_FALSE(errors.empty());
}

TEST_F(Gpu, AMisspelledUniformIsReportedUnderTheDebugContext) {
  gpu::ShaderCompiler c({embedded::gpu_test_shaders()});
  gpu::Program p = c.build("fullscreen.vert", "uses_include.frag");
  p.set("u_no_such_uniform", 1.0f);
  auto errors = context().take_debug_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].text.find("has no active uniform 'u_no_such_uniform'"), std::string::npos)
      << errors[0].text;
  EXPECT_NE(errors[0].text.find("uses_include.frag"), std::string::npos) << errors[0].text;
  // Reported once per name, and not at all for names declared optional.
  p.set("u_no_such_uniform", 2.0f);
  p.allow_missing({"u_optional"});
  p.set("u_optional", 1.0f);
  EXPECT_TRUE(context().take_debug_errors().empty());
}

TEST_F(Gpu, PassStateSetsEverythingItNames) {
  // (the stencil reference reads back clamped to the bound buffer's bits)
  gpu::RenderTarget t = gpu::RenderTarget::create(4, 4, GL_RGBA8, true);
  t.bind();
  gpu::PassState s;
  s.depth_func = GL_LESS;
  s.depth_write = true;
  s.stencil_func = GL_EQUAL;
  s.stencil_ref = 3;
  s.stencil_pass_op = GL_REPLACE;
  s.stencil_write = true;
  s.alpha_blend = true;
  s.color_off = true;
  s.scissor = {1, 2, 3, 1};
  gpu::apply(s);
  GLint v = 0;
  GLint box[4] = {};
  EXPECT_TRUE(glIsEnabled(GL_SCISSOR_TEST));
  glGetIntegerv(GL_SCISSOR_BOX, box);
  EXPECT_EQ(box[0], 1);
  EXPECT_EQ(box[1], 2);
  EXPECT_EQ(box[2], 3);
  EXPECT_EQ(box[3], 1);
  glGetIntegerv(GL_BLEND_DST_ALPHA, &v);
  EXPECT_EQ(v, GL_ONE);  // the target's alpha is kept
  GLboolean mask[4] = {};
  EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
  EXPECT_TRUE(glIsEnabled(GL_STENCIL_TEST));
  EXPECT_TRUE(glIsEnabled(GL_BLEND));
  glGetIntegerv(GL_STENCIL_REF, &v);
  EXPECT_EQ(v, 3);
  glGetIntegerv(GL_STENCIL_PASS_DEPTH_PASS, &v);
  EXPECT_EQ(v, GL_REPLACE);
  glGetBooleanv(GL_COLOR_WRITEMASK, mask);
  EXPECT_FALSE(mask[0]);
  // The default state turns every one of them off again: nothing leaks.
  gpu::apply({});
  EXPECT_FALSE(glIsEnabled(GL_SCISSOR_TEST));
  EXPECT_FALSE(glIsEnabled(GL_DEPTH_TEST));
  EXPECT_FALSE(glIsEnabled(GL_STENCIL_TEST));
  EXPECT_FALSE(glIsEnabled(GL_BLEND));
  glGetBooleanv(GL_COLOR_WRITEMASK, mask);
  EXPECT_TRUE(mask[0] && mask[1] && mask[2] && mask[3]);
  glGetBooleanv(GL_DEPTH_WRITEMASK, mask);
  EXPECT_FALSE(mask[0]);
  glGetIntegerv(GL_STENCIL_WRITEMASK, &v);
  EXPECT_EQ(v, 0);
}

TEST_F(Gpu, RenderTargetsOwnTheirViewportAndClearThroughMasks) {
  gpu::RenderTarget a = gpu::RenderTarget::create(8, 4, GL_RGBA8, true);
  gpu::RenderTarget b = gpu::RenderTarget::create(3, 5);
  b.bind();
  a.bind();
  GLint vp[4] = {}, fb = 0;
  glGetIntegerv(GL_VIEWPORT, vp);
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fb);
  EXPECT_EQ(vp[2], 8);
  EXPECT_EQ(vp[3], 4);
  EXPECT_EQ(static_cast<GLuint>(fb), a.framebuffer());
  // A clear reaches the target even after a pass that closed colour writes.
  gpu::PassState closed;
  closed.color_off = true;
  gpu::apply(closed);
  a.clear(1, 0, 0, 1);
  EXPECT_EQ(gpu::read_texture(a.color()).at(7, 3)[0], 255);
  // A region's clear reaches its pixels alone, clamped to the target, and
  // leaves the scissor test as it found it (off: clears honour it). Regions
  // are in GL's pixels, origin bottom-left; the image read back is top-down.
  a.clear(0, 1, 0, 1, {5, 1, 20, 3});
  a.clear(0, 0, 1, 1, {-4, -4, 1, 1});
  a.clear(1, 1, 1, 1, {6, 2, 6, 4});  // empty: nothing
  const Image cleared = gpu::read_texture(a.color());
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 8; ++x) {
      const bool green = x >= 5 && y >= 1 && y < 3, blue = x < 1 && y == 3;
      const auto px = cleared.at(x, y);
      EXPECT_EQ(px[0], green || blue ? 0 : 255) << x << "," << y;
      EXPECT_EQ(px[1], green ? 255 : 0) << x << "," << y;
      EXPECT_EQ(px[2], blue ? 255 : 0) << x << "," << y;
    }
  }
  EXPECT_FALSE(glIsEnabled(GL_SCISSOR_TEST));
  // A wrapped framebuffer is bound with its own size.
  gpu::RenderTarget w = gpu::RenderTarget::wrap(b.framebuffer(), 3, 5);
  w.bind();
  glGetIntegerv(GL_VIEWPORT, vp);
  EXPECT_EQ(vp[2], 3);
  EXPECT_EQ(vp[3], 5);
  // What a prepass captures it restores.
  const gpu::FramebufferBinding saved = gpu::FramebufferBinding::current();
  a.bind();
  saved.restore();
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fb);
  glGetIntegerv(GL_VIEWPORT, vp);
  EXPECT_EQ(static_cast<GLuint>(fb), b.framebuffer());
  EXPECT_EQ(vp[2], 3);
}

// The EGL device platform (the only one NVIDIA's driver offers) makes a
// working context: Mesa exposes its software renderer as a device too, so the
// path is exercised here without a GPU. FOVEATE_EGL picks the platform.
TEST_F(Gpu, AReadBackHoldsTheTextureAsItWasWhenQueued) {
  // The copy is queued behind the work sent before it: what the texture
  // holds later does not reach it. Rows come tightly packed from the bottom,
  // also one byte wide on a width that is no multiple of 4.
  gpu::Texture t = gpu::Texture::create_2d(GL_R8UI, 5, 3);
  std::vector<std::uint8_t> first(15), second(15, 200);
  for (size_t i = 0; i < first.size(); ++i) first[i] = static_cast<std::uint8_t>(i);
  t.upload(5, 3, GL_RED_INTEGER, GL_UNSIGNED_BYTE, first.data());
  gpu::TextureReadback r;
  EXPECT_FALSE(r.pending());
  EXPECT_THROW(r.read([](std::span<const std::uint8_t>) {}), Error);
  r.queue(t, GL_RED_INTEGER, GL_UNSIGNED_BYTE, 1);
  t.upload(5, 3, GL_RED_INTEGER, GL_UNSIGNED_BYTE, second.data());
  EXPECT_TRUE(r.pending());
  EXPECT_EQ(r.width(), 5);
  EXPECT_EQ(r.height(), 3);
  std::vector<std::uint8_t> got;
  r.read([&](std::span<const std::uint8_t> b) { got.assign(b.begin(), b.end()); });
  EXPECT_EQ(got, first);
  EXPECT_FALSE(r.pending());
  // Queued again (RGBA bytes of a colour texture), moved, and discarded.
  gpu::Texture c = gpu::Texture::create_2d(GL_RGBA8, 2, 2);
  const std::vector<std::uint8_t> rgba = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
  c.upload(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  r.queue(c);
  gpu::TextureReadback moved = std::move(r);
  EXPECT_TRUE(moved.pending());
  moved.read([&](std::span<const std::uint8_t> b) { got.assign(b.begin(), b.end()); });
  EXPECT_EQ(got, rgba);
  moved.queue(c);
  moved.discard();
  EXPECT_FALSE(moved.pending());
}

TEST(EglPlatform, DevicePlatformRendersAndBadChoiceIsNamed) {
  struct EnvGuard {
    ~EnvGuard() { unsetenv("FOVEATE_EGL"); }
  } guard;
  setenv("FOVEATE_EGL", "device", 1);
  std::unique_ptr<gpu::Context> c = gpu::create_headless_context({});
  EXPECT_EQ(c->backend(), "egl-device");
  {
    gpu::Texture t = gpu::Texture::create_2d(GL_RGBA8, 4, 4);
    gpu::Framebuffer fb = gpu::Framebuffer::create();
    fb.attach(GL_COLOR_ATTACHMENT0, t);
    fb.check("device test");
    const float colour[4] = {0.0f, 1.0f, 0.0f, 1.0f};
    glClearNamedFramebufferfv(fb.id(), GL_COLOR, 0, colour);
    const Image img = gpu::read_texture(t);
    EXPECT_EQ(img.at(3, 3)[1], 255);
    EXPECT_EQ(img.at(3, 3)[0], 0);
  }
  c.reset();
  setenv("FOVEATE_EGL", "surfaceless", 1);
  EXPECT_EQ(gpu::create_headless_context({})->backend(), "egl-surfaceless");
  setenv("FOVEATE_EGL", "vulkan", 1);
  try {
    (void)gpu::create_headless_context({});
    ADD_FAILURE() << "FOVEATE_EGL=vulkan accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("FOVEATE_EGL='vulkan'"), std::string::npos) << e.what();
  }
}
