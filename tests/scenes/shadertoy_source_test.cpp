#include "foveate/scenes/shadertoy_source.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "foveate/core/error.hpp"
#include "foveate/scenes/scene.hpp"

namespace foveate {
namespace {

const char* kShader =
    "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
    "  fragColor = texture(iChannel0, fragCoord);\n"
    "}\n";

TEST(ShadertoySource, FindsMainImageAndChannels) {
  const ShadertoySource s = analyse_shadertoy_source(kShader);
  EXPECT_TRUE(s.has_main_image);
  EXPECT_TRUE(s.main_image_params_ok);
  EXPECT_EQ(s.main_image_line, 1);
  EXPECT_FALSE(s.has_main);
  EXPECT_TRUE(s.channels[0]);
  EXPECT_FALSE(s.channels[1] || s.channels[2] || s.channels[3]);
  EXPECT_FALSE(s.animated);
  EXPECT_FALSE(s.bom);
}

TEST(ShadertoySource, SkipsCommentsAndStrings) {
  const ShadertoySource s = analyse_shadertoy_source(
      "// void main() { iChannel1 }\n"
      "/* void mainImage(out vec4 a, in vec2 b)\n iChannel2 iTime */\n"
      "#include \"iChannel3.glsl\"\n"
      "void main() { }\n");
  EXPECT_FALSE(s.has_main_image);
  EXPECT_FALSE(s.mentions_main_image);
  EXPECT_TRUE(s.has_main);
  EXPECT_EQ(s.main_line, 5);
  EXPECT_FALSE(s.channels[1] || s.channels[2] || s.channels[3]);
  EXPECT_FALSE(s.animated);
}

TEST(ShadertoySource, MainImageSignatureVariants) {
  EXPECT_TRUE(
      analyse_shadertoy_source("void mainImage( out vec4 O, vec2 U ) {}").main_image_params_ok);
  EXPECT_TRUE(analyse_shadertoy_source("void\nmainImage(\nout highp vec4 O,\nin mediump vec2 U) {}")
                  .main_image_params_ok);
  const ShadertoySource bad = analyse_shadertoy_source("void mainImage(out vec3 c, vec2 p) {}");
  EXPECT_TRUE(bad.has_main_image);
  EXPECT_FALSE(bad.main_image_params_ok);
  EXPECT_EQ(bad.main_image_params, "out vec3 c, vec2 p");
  // Inside a function body it is not a definition; a macro is only mentioned.
  EXPECT_FALSE(analyse_shadertoy_source("void f() { void mainImage(); }").has_main_image);
  const ShadertoySource macro =
      analyse_shadertoy_source("#define M mainImage\nvoid M(out vec4 a, vec2 b) {}");
  EXPECT_FALSE(macro.has_main_image);
  EXPECT_TRUE(macro.mentions_main_image);
}

TEST(ShadertoySource, ByteOrderMark) {
  const std::string text = std::string("\xEF\xBB\xBF") + kShader;
  const ShadertoySource s = analyse_shadertoy_source(text);
  EXPECT_TRUE(s.bom);
  EXPECT_TRUE(s.has_main_image);
}

TEST(ShadertoySource, LegacyNamesUsedAndDefined) {
  const ShadertoySource s = analyse_shadertoy_source(
      "#define texture2D texture\n"
      "vec4 textureCube(sampler2D s, vec3 d) { return vec4(0.0); }\n"
      "void mainImage(out vec4 c, vec2 p) {\n"
      "  c = texture2D(iChannel0, p) + textureCube(iChannel1, vec3(iGlobalTime));\n"
      "  return texture2DLod(iChannel2, p, 0.0);\n"
      "}\n");
  EXPECT_TRUE(s.uses_legacy("texture2D"));
  EXPECT_TRUE(s.uses_legacy("textureCube"));
  EXPECT_TRUE(s.uses_legacy("iGlobalTime"));
  EXPECT_TRUE(s.uses_legacy("texture2DLod"));
  EXPECT_FALSE(s.uses_legacy("iChannelTime"));
  EXPECT_TRUE(s.defines("texture2D"));
  EXPECT_TRUE(s.defines("textureCube"));
  EXPECT_FALSE(s.defines("iGlobalTime"));   // used, not declared
  EXPECT_FALSE(s.defines("texture2DLod"));  // after `return`: a use
  EXPECT_TRUE(s.animated);
}

TEST(ShadertoySource, TopLevelUniforms) {
  const ShadertoySource s = analyse_shadertoy_source(
      "uniform vec3 iResolution;\nuniform highp float iTime, iTimeDelta;\n"
      "uniform vec3 iChannelResolution[4];\nvoid f() { }\n");
  ASSERT_EQ(s.uniforms.size(), 4u);
  EXPECT_EQ(s.uniforms[0].type, "vec3");
  EXPECT_EQ(s.uniforms[0].name, "iResolution");
  EXPECT_EQ(s.uniforms[1].type, "float");
  EXPECT_EQ(s.uniforms[1].name, "iTime");
  EXPECT_EQ(s.uniforms[2].name, "iTimeDelta");
  EXPECT_EQ(s.uniforms[3].name, "iChannelResolution");
}

TEST(ShadertoySource, LinearOnHostileInputs) {
  // The inputs that overflowed std::regex's recursion: 50,000 newlines in a
  // declaration, a 300,000-character name, and deep nesting; each must be
  // scanned quickly and without recursion.
  const auto t0 = std::chrono::steady_clock::now();
  std::string a = std::string(kShader) + "void" + std::string(50000, '\n') + "helper() {}";
  EXPECT_TRUE(analyse_shadertoy_source(a).has_main_image);
  std::string b = "void mainImage(out vec4 c, in vec2 " + std::string(300000, 'x') + ") {}";
  EXPECT_TRUE(analyse_shadertoy_source(b).main_image_params_ok);
  std::string c = "void mainImage(" + std::string(200000, '(') + std::string(200000, '{');
  EXPECT_FALSE(analyse_shadertoy_source(c).has_main_image);
  std::string d = "/*" + std::string(500000, '*');
  EXPECT_FALSE(analyse_shadertoy_source(d).mentions_main_image);
  std::string e(1 << 20, '\0');
  (void)analyse_shadertoy_source(e);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LT(s, 5.0);
}

TEST(ShadertoyDate, ParsesAndAdvances) {
  const ShadertoyDate d = parse_shadertoy_date("2024-02-29T23:59:30");
  EXPECT_EQ(d.year, 2024);
  EXPECT_EQ(d.month, 2);
  EXPECT_EQ(d.day, 29);
  EXPECT_DOUBLE_EQ(d.seconds, 86370.0);
  // 45 s later: 2024-03-01 00:00:15; iDate.y counts months from 0.
  const auto v = shadertoy_idate(d, 45.0);
  EXPECT_EQ(v[0], 2024.0f);
  EXPECT_EQ(v[1], 2.0f);
  EXPECT_EQ(v[2], 1.0f);
  EXPECT_NEAR(v[3], 15.0f, 1e-3);
  const auto dflt = shadertoy_idate(ShadertoyDate{}, 0.0);
  EXPECT_EQ(dflt[0], 2026.0f);
  EXPECT_EQ(dflt[1], 0.0f);
  EXPECT_EQ(dflt[2], 1.0f);
  EXPECT_EQ(dflt[3], 0.0f);
  EXPECT_TRUE(parse_shadertoy_date("now").real_clock);
  EXPECT_EQ(parse_shadertoy_date("2025-12-31 08:05").seconds, 8 * 3600.0 + 300.0);
  for (const char* bad : {"2023-02-29", "2025-13-01", "2025-1-1x", "yesterday", "2025-01-01T24:00",
                          "", "2025-01-01T10:00:00Z"}) {
    EXPECT_THROW(parse_shadertoy_date(bad), Error) << bad;
  }
}

}  // namespace
}  // namespace foveate
