// The registry: techniques declared once, registered at run time from outside
// the library, parameters resolved and checked from their declarations.
#include <gtest/gtest.h>

#include <cmath>

#include "bars_technique.hpp"
#include "errors.hpp"
#include "foveate/techniques/reference.hpp"
#include "foveate/techniques/renderer.hpp"
#include "gl_fixture.hpp"

using namespace foveate;
using foveate::test::error_of;

namespace {

// marwarp's own planning margin (docs/continuous.md).
constexpr double kMarwarpMargin = 2.0;

TechniqueConfig config(int w, int h, std::map<std::string, double> params = {}) {
  TechniqueConfig c;
  c.display = Display::load("desktop-1080p").resized(w, h);
  c.acuity = AcuityModel::quality("A");
  c.params = std::move(params);
  return c;
}

TechniqueInfo minimal(const std::string& name) {
  TechniqueInfo t;
  t.name = name;
  t.make = [](const TechniqueConfig& c, const ParamValues&) { return make_technique("native", c); };
  return t;
}

}  // namespace

TEST(Registry, BuiltinsInTheirOrder) {
  const std::vector<std::string> names = technique_names();
  ASSERT_GE(names.size(), 7u);
  EXPECT_EQ(std::vector<std::string>(names.begin(), names.begin() + 7),
            (std::vector<std::string>{"native", "layered", "logpolar", "checkerboard", "lodmask",
                                      "inset", "vrs"}));
  // Every technique but native resolves what it shaded into the output in
  // passes it declares (reports sum them as the resolve share).
  for (const TechniqueInfo& t : techniques())
    EXPECT_EQ(t.resolve_passes.empty(), t.name == "native" || t.name == "lodmask") << t.name;
  EXPECT_TRUE(technique_info("lodmask").needs.mesh_lods);
  EXPECT_FALSE(technique_info("layered").needs.meshes);
}

TEST(Registry, ParametersResolveFromTheirDeclarations) {
  const TechniqueInfo& layered = technique_info("layered");
  const ParamValues v = resolve_parameters(layered, config(640, 360));
  EXPECT_EQ(v.integer("layers"), 3);
  EXPECT_TRUE(v.boolean("half_rate"));
  EXPECT_DOUBLE_EQ(v.real("transition"), 0.2);
  // Overrides, typed.
  const ParamValues o =
      resolve_parameters(layered, config(640, 360, {{"layers", 2}, {"jitter", 0}}));
  EXPECT_EQ(o.integer("layers"), 2);
  EXPECT_FALSE(o.boolean("jitter"));
  // Errors name the technique, the key and the reason; none names a flag.
  const std::string range = error_of([&] {
    resolve_parameters(layered, config(640, 360, {{"layers", 9}}));
  });
  EXPECT_EQ(range, "layered parameter layers=9: out of range [1, 6]");
  const std::string whole = error_of([&] {
    resolve_parameters(layered, config(640, 360, {{"layers", 2.5}}));
  });
  EXPECT_EQ(whole, "layered parameter layers=2.5: must be a whole number");
  const std::string boolean = error_of([&] {
    resolve_parameters(layered, config(640, 360, {{"jitter", 0.5}}));
  });
  EXPECT_NE(boolean.find("0 or 1"), std::string::npos) << boolean;
  const std::string unknown = error_of([&] {
    resolve_parameters(layered, config(640, 360, {{"sigma", 2}}));
  });
  EXPECT_NE(unknown.find("layered has no parameter 'sigma' (it has: margin, layers, transition"),
            std::string::npos)
      << unknown;
  const std::string cross = error_of([&] {
    resolve_parameters(technique_info("lodmask"),
                       config(640, 360, {{"inner_deg", 10}, {"outer_deg", 5}}));
  });
  EXPECT_NE(cross.find("outer_deg must be >= inner_deg"), std::string::npos) << cross;
}

TEST(Registry, ThePlanningMarginIsEachTechniquesOwnUnlessGiven) {
  // Declared first by every built-in technique but native, with the least
  // margin at which the technique meets the fidelity target (docs/fidelity.md).
  const std::map<std::string, double> own = {
      {"layered", 2.0}, {"logpolar", 1.75}, {"checkerboard", 1.5},      {"vrs", 1.5},
      {"inset", 1.0},   {"lodmask", 1.0},   {"marwarp", kMarwarpMargin}};
  for (const auto& [name, margin] : own) {
    const TechniqueInfo& t = technique_info(name);
    ASSERT_FALSE(t.params.empty()) << name;
    EXPECT_EQ(t.params[0].key, kPlanMarginKey) << name;
    EXPECT_EQ(resolve_parameters(t, config(1920, 1080)).real(kPlanMarginKey), margin) << name;
  }
  EXPECT_FALSE(resolve_parameters(technique_info("native"), config(1920, 1080)).has("margin"));
  // TechniqueConfig::margin (--margin) sets every technique's; a parameter
  // of the technique's own wins over it.
  const TechniqueInfo& layered = technique_info("layered");
  TechniqueConfig c = config(1920, 1080);
  c.margin = 1.25;
  EXPECT_EQ(resolve_parameters(layered, c).real("margin"), 1.25);
  EXPECT_EQ(resolve_parameters(technique_info("native"), c).items().size(), 0u);
  c.params = {{"margin", 3.0}};
  EXPECT_EQ(resolve_parameters(layered, c).real("margin"), 3.0);
  c.params.clear();
  c.margin = 0.5;
  EXPECT_EQ(error_of([&] { resolve_parameters(layered, c); }),
            "layered parameter margin=0.5: out of range [1, 4]");
  // The plan is for the acuity made finer by the margin, and so are the
  // defaults derived from the acuity model: checkerboard at its own 1.5 has
  // the regions of the paper's plan (margin 1) for the model made 1.5 times finer.
  const TechniqueInfo& cb = technique_info("checkerboard");
  TechniqueConfig paper = config(1920, 1080);
  paper.margin = 1.0;
  paper.acuity = paper.acuity.finer(1.5);
  const ParamValues own_values = resolve_parameters(cb, config(1920, 1080));
  for (const char* key : {"r1", "r2", "r3"}) {
    EXPECT_EQ(own_values.real(key), resolve_parameters(cb, paper).real(key)) << key;
    EXPECT_GT(own_values.real(key), resolve_parameters(cb,
                                                       [] {
                                                         TechniqueConfig p = config(1920, 1080);
                                                         p.margin = 1.0;
                                                         return p;
                                                       }())
                                        .real(key))
        << key;
  }
  const TechniqueConfig planned = planning_config(config(1920, 1080), own_values);
  EXPECT_DOUBLE_EQ(planned.acuity.slope, AcuityModel::quality("A").slope / 1.5);
  EXPECT_DOUBLE_EQ(planned.acuity.w0_deg, AcuityModel::quality("A").w0_deg / 1.5);
}

TEST(Registry, BadRegistrationsAreRefused) {
  EXPECT_NE(error_of([] { register_technique(minimal("layered")); }).find("already registered"),
            std::string::npos);
  EXPECT_NE(error_of([] { register_technique(minimal("")); }).find("no name"), std::string::npos);
  TechniqueInfo twice = minimal("test-twice");
  twice.params = {param("k", "", "", ParamType::Real, 0, 1, 0.5),
                  param("k", "", "", ParamType::Real, 0, 1, 0.5)};
  EXPECT_NE(error_of([&] { register_technique(twice); }).find("declared twice"), std::string::npos);
  TechniqueInfo outside = minimal("test-outside");
  outside.params = {param("k", "", "", ParamType::Real, 0, 1, 2)};
  EXPECT_NE(error_of([&] { register_technique(outside); }).find("outside its range"),
            std::string::npos);
  TechniqueInfo flag = minimal("test-flag");
  flag.params = {param("on", "", "", ParamType::Boolean, 0, 2, 1)};
  EXPECT_NE(error_of([&] { register_technique(flag); }).find("boolean"), std::string::npos);
  TechniqueInfo dotted = minimal("test-dotted");
  dotted.params = {param("a.b", "", "", ParamType::Real, 0, 1, 0)};
  EXPECT_NE(error_of([&] { register_technique(dotted); }).find("must be non-empty"),
            std::string::npos);
  TechniqueInfo late = minimal("test-late-margin");
  late.params = {param("k", "", "", ParamType::Real, 0, 1, 0), plan_margin_param(1.5)};
  EXPECT_NE(error_of([&] { register_technique(late); }).find("planning margin is declared first"),
            std::string::npos);
  // Nothing refused was added.
  for (const char* name :
       {"test-twice", "test-outside", "test-flag", "test-dotted", "test-late-margin"}) {
    EXPECT_NE(error_of([&] { technique_info(name); }).find("unknown technique"), std::string::npos);
  }
}

class RegisteredAtRunTime : public test::GlTest {};

TEST_F(RegisteredAtRunTime, RendersThroughTheFrameRunner) {
  test::register_bars_technique();
  const TechniqueInfo& info = technique_info(test::kBarsTechnique);
  // The derived default: a 36th of the height.
  EXPECT_EQ(resolve_parameters(info, config(320, 180)).integer("bar_px"), 5);
  EXPECT_EQ(resolve_parameters(info, config(64, 36)).integer("bar_px"), 1);
  // Clamped into the declared range where the derivation runs past it.
  EXPECT_EQ(resolve_parameters(info, config(7680, 4320)).integer("bar_px"), 64);

  auto scene = load_scene("detail");
  RendererOptions o;
  o.width = 320;
  o.height = 180;
  Renderer renderer(*scene, o);
  auto bars = make_technique(test::kBarsTechnique, config(320, 180));
  EXPECT_EQ(bars->name(), test::kBarsTechnique);
  EXPECT_EQ(bars->parameters(), (std::vector<std::pair<std::string, double>>{{"bar_px", 5.0}}));
  const FrameStats s = renderer.render(*bars, 0, GazeState{{160, 90}});
  EXPECT_EQ(s.shaded_pixels, 320.0 * 180.0);
  const Image img = renderer.read_output();
  auto native = make_technique("native", config(320, 180));
  renderer.render(*native, 0, GazeState{{160, 90}});
  const Image ref = renderer.read_output();
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

TEST_F(RegisteredAtRunTime, TheRendererRefusesAMismatchedScene) {
  auto scene = load_scene("cheap");
  RendererOptions o;
  o.width = 64;
  o.height = 36;
  Renderer renderer(*scene, o);
  auto lodmask = make_technique("lodmask", config(64, 36));
  const std::string e = error_of([&] { renderer.render(*lodmask, 0, GazeState{{32, 18}}); });
  EXPECT_NE(e.find("needs a scene with mesh levels of detail"), std::string::npos) << e;
  // A target and a frame of different sizes are refused, not half-drawn.
  FrameInput f = renderer.frame_input(0);
  f.width = 65;
  auto native = make_technique("native", config(64, 36));
  EXPECT_NE(error_of([&] { renderer.render(*native, f, GazeState{}); }).find("65x36"),
            std::string::npos);
  // So is a technique planned for another display size.
  auto big = make_technique("native", config(128, 72));
  EXPECT_NE(error_of([&] { renderer.render(*big, 0, GazeState{}); }).find("128x72 display"),
            std::string::npos);
}

TEST_F(RegisteredAtRunTime, SupersampledReferenceIsTheBoxFilteredBigFrame) {
  // The reference of a fine grating is its mean in linear light, where native
  // at one sample per pixel aliases.
  auto scene = load_scene(std::string(FOVEATE_TEST_DATA) + "/shadertoy/grating.glsl");
  const Display d = Display::load("desktop-1080p").resized(64, 36);
  SupersampledReference ref(d, 4);
  RendererOptions o;
  o.width = 64;
  o.height = 36;
  Renderer renderer(*scene, o);
  ref.render(*scene, renderer.frame_input(0));
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
  EXPECT_EQ(parse_reference("native"), 1);
  EXPECT_EQ(parse_reference("ssaa"), 4);
  EXPECT_EQ(parse_reference("ssaa:2"), 2);
  EXPECT_NE(error_of([] { parse_reference("ssaa:9"); }).find("2 to 8"), std::string::npos);
  EXPECT_NE(error_of([] { parse_reference("msaa"); }).find("'msaa'"), std::string::npos);
}
