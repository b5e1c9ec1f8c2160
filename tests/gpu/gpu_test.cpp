#include <gtest/gtest.h>

#include "foveate/core/error.hpp"
#include "foveate/gpu/frame.hpp"
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
  EXPECT_EQ(img.at(7, 3)[0], 64);
  EXPECT_EQ(img.at(0, 0)[1], 128);
  EXPECT_EQ(img.at(3, 2)[2], 191);
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
