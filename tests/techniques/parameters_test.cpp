// Technique parameters, without GL: resolved from their declarations (typed,
// ranged, derived from the acuity model and the display), the planning
// margin, and bad values refused with messages that name the technique and
// the key.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "errors.hpp"
#include "foveate/core/error.hpp"
#include "foveate/techniques/technique.hpp"

using namespace foveate;
using foveate::test::error_of;

namespace {

// The configuration of a 640x360 render of the paper's display, by default
// planned with the papers' own plans (margin 1).
TechniqueConfig config(std::map<std::string, double> params = {}) {
  TechniqueConfig c;
  c.display = Display::load("desktop-1080p").resized(640, 360);
  c.acuity = AcuityModel::preset("A");
  c.margin = 1.0;
  c.params = std::move(params);
  return c;
}

// At another size, with each technique's own planning margin.
TechniqueConfig config(int w, int h, std::map<std::string, double> params = {}) {
  TechniqueConfig c;
  c.display = Display::load("desktop-1080p").resized(w, h);
  c.acuity = AcuityModel::preset("A");
  c.params = std::move(params);
  return c;
}

struct Size {
  int w, h;
};

}  // namespace

TEST(Parameters, ParametersResolveFromTheirDeclarations) {
  const TechniqueInfo& layered = technique_info("layered");
  const ParamValues v = resolve_parameters(layered, config(640, 360));
  EXPECT_EQ(v.integer("layers"), 2);
  EXPECT_FALSE(v.boolean("half_rate"));
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
  EXPECT_NE(
      unknown.find("layered has no parameter 'sigma' (it has: margin, layers, s2, transition"),
      std::string::npos)
      << unknown;
  const std::string cross = error_of([&] {
    resolve_parameters(technique_info("lodmask"),
                       config(640, 360, {{"inner_deg", 10}, {"outer_deg", 5}}));
  });
  EXPECT_NE(cross.find("outer_deg must be >= inner_deg"), std::string::npos) << cross;
}

TEST(Parameters, LayeredSecondLayersFactorIsTheOptimisersOrAtLeastOne) {
  const TechniqueInfo& layered = technique_info("layered");
  EXPECT_EQ(resolve_parameters(layered, config(1920, 1080)).real("s2"), 0.0);
  EXPECT_EQ(resolve_parameters(layered, config(640, 360, {{"s2", 2}})).real("s2"), 2.0);
  const std::string below = error_of([&] {
    resolve_parameters(layered, config(640, 360, {{"s2", 0.5}}));
  });
  EXPECT_EQ(below, "layered parameter s2 must be 0 (the optimiser's) or at least 1, got 0.5");
  const std::string one = error_of([&] {
    resolve_parameters(layered, config(640, 360, {{"s2", 2}, {"layers", 1}}));
  });
  EXPECT_EQ(one, "layered parameter s2 needs layers >= 2 (one layer is native)");
}

TEST(Parameters, ThePlanningMarginIsEachTechniquesOwnUnlessGiven) {
  // Declared first by every built-in technique but native, with the margin
  // `foveate tune` chose at 1920x1080 (docs/fidelity.md).
  const std::map<std::string, double> own = {
      {"layered", 1.5}, {"logpolar", 1.5}, {"checkerboard", 1.0}, {"vrs", 1.0},
      {"inset", 1.0},   {"lodmask", 2.0},  {"marwarp", 2.0}};
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
  // defaults derived from the acuity model: checkerboard at margin 2 has
  // the regions of the paper's plan (margin 1) for the model made 2 times finer.
  const TechniqueInfo& cb = technique_info("checkerboard");
  TechniqueConfig paper = config(1920, 1080);
  paper.margin = 1.0;
  paper.acuity = paper.acuity.finer(2.0);
  TechniqueConfig two = config(1920, 1080);
  two.margin = 2.0;
  const ParamValues own_values = resolve_parameters(cb, two);
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
  EXPECT_DOUBLE_EQ(planned.acuity.slope, AcuityModel::preset("A").slope / 2.0);
  EXPECT_DOUBLE_EQ(planned.acuity.w0_deg, AcuityModel::preset("A").w0_deg / 2.0);
}

TEST(Parameters, BadParametersAreErrorsBeforeAnythingIsMade) {
  // Each is refused while the parameters resolve, before the technique (and
  // its GL objects) is made: no GL context is needed here.
  EXPECT_THROW(make_technique("layered", config({{"layers", 9}})), Error);
  EXPECT_THROW(make_technique("layered", config({{"layers", 2.5}})), Error);
  EXPECT_THROW(make_technique("layered", config({{"sigma", 2}})), Error);
  EXPECT_THROW(make_technique("logpolar", config({{"sigma", 0.5}})), Error);
  EXPECT_THROW(make_technique("nope", config()), Error);
  // The message lists the keys the technique has.
  const std::string unknown = error_of([&] {
    make_technique("checkerboard", config({{"colour", 1}}));
  });
  EXPECT_NE(unknown.find("checkerboard has no parameter 'colour'"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("block"), std::string::npos) << "lists known keys: " << unknown;
  // marwarp's samples fill a grid: a count that does not would weight some
  // positions twice, and is refused by name.
  for (const double n : {3.0, 5.0, 8.0, 12.0}) {
    const std::string bad = error_of([&] { make_technique("marwarp", config({{"samples", n}})); });
    EXPECT_NE(bad.find("marwarp parameter samples=" + std::to_string(int(n)) + ": must be"),
              std::string::npos)
        << bad;
  }
  EXPECT_THROW(make_technique("marwarp", config({{"samples", 25}})), Error);  // over the range
  // edge_samples is a pattern, 2 or 4 (ParamDecl::allowed): 3 is in its
  // range but fills neither, and is refused with the values it takes.
  for (const char* t : {"marwarp", "logpolar", "vrs"}) {
    EXPECT_NO_THROW(check_parameter(technique_info(t), "edge_samples", 2)) << t;
    EXPECT_NO_THROW(check_parameter(technique_info(t), "edge_samples", 4)) << t;
    const std::string bad = error_of([&] { make_technique(t, config({{"edge_samples", 3}})); });
    EXPECT_NE(bad.find(std::string(t) + " parameter edge_samples=3: must be 2 or 4"),
              std::string::npos)
        << bad;
  }
  // vrs's tile is one of the sizes the shading-rate APIs offer.
  for (const double n : {8.0, 16.0, 32.0})
    EXPECT_NO_THROW(check_parameter(technique_info("vrs"), "tile", n)) << n;
  const std::string tile = error_of([&] { make_technique("vrs", config({{"tile", 12}})); });
  EXPECT_NE(tile.find("vrs parameter tile=12: must be 8, 16 or 32"), std::string::npos) << tile;
}

TEST(Parameters, DefaultsComeFromTheAcuityModel) {
  // A steeper MAR slope (more aggressive) shrinks every foveal region.
  TechniqueConfig a = config(), b = config();
  b.acuity = AcuityModel::with_slope(0.05);
  auto get = [](const std::string& name, const TechniqueConfig& c, const std::string& key) {
    return resolve_parameters(technique_info(name), c).real(key);
  };
  EXPECT_GT(get("checkerboard", a, "r3"), get("checkerboard", b, "r3"));
  EXPECT_GT(get("inset", a, "fovea_deg"), get("inset", b, "fovea_deg"));
  EXPECT_LT(get("logpolar", a, "sigma"), get("logpolar", b, "sigma"));
  EXPECT_GT(get("lodmask", a, "inner_deg"), get("lodmask", b, "inner_deg"));
}

TEST(Parameters, LodmaskCirclesLieWhereHalfACycleCoversTheLodsSilhouetteError) {
  // LOD k errs by about 0.5 px * 10^k (a tenth of the triangles per level,
  // chord error ~ 1 / triangles); it may show where w(e) ppd >= 2 * error,
  // i.e. w(e) >= error * w*. Quality A: w(e) = 0.0275 e + 1/48.
  auto e_for = [](double w) { return (w - 1.0 / 48.0) / 0.0275; };
  for (const Size& sz : {Size{1920, 1080}, Size{640, 360}}) {
    TechniqueConfig c = config();
    c.display = Display::load("desktop-1080p").resized(sz.w, sz.h);
    const ParamValues v = resolve_parameters(technique_info("lodmask"), c);
    const double ws = c.display.sharpness_deg();
    EXPECT_NEAR(v.real("inner_deg"), e_for(5 * ws), 1e-9) << sz.w;
    EXPECT_EQ(v.real("outer_deg"), 90.0) << sz.w;  // 50 w*: beyond the screen
  }
  // 1920x1080: w* = 0.0516 deg, the mid LOD from 8.6 deg out.
  TechniqueConfig c = config();
  c.display = Display::load("desktop-1080p");
  EXPECT_NEAR(resolve_parameters(technique_info("lodmask"), c).real("inner_deg"), 8.63, 0.02);
}

TEST(Parameters, EveryDeclaredDefaultLiesInItsRange) {
  // At sizes where the derivations run off their scales (a tiny render of a
  // wide display, a steep or a flat slope) the defaults are clamped, and
  // whole-number and boolean parameters are whole.
  for (const Size& sz : {Size{64, 36}, Size{1920, 1080}, Size{7680, 4320}}) {
    for (double slope : {0.005, 0.0275, 0.2}) {
      TechniqueConfig c = config();
      c.display = Display::load("desktop-1080p").resized(sz.w, sz.h);
      c.acuity = AcuityModel::with_slope(slope);
      for (const TechniqueInfo& t : techniques()) {
        const ParamValues v = resolve_parameters(t, c);
        ASSERT_EQ(v.items().size(), t.params.size()) << t.name;
        for (const ParamDecl& p : t.params) {
          const double x = v.real(p.key);
          EXPECT_GE(x, p.min) << t.name << "." << p.key;
          EXPECT_LE(x, p.max) << t.name << "." << p.key;
          if (p.type != ParamType::Real) {
            EXPECT_EQ(x, std::round(x)) << t.name << "." << p.key;
          }
        }
      }
    }
  }
}
