// The registry, without GL: the built-in techniques in their order and what
// they declare, and registrations that are refused.
#include <gtest/gtest.h>

#include "errors.hpp"
#include "foveate/techniques/technique.hpp"

using namespace foveate;
using foveate::test::error_of;

namespace {

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
  TechniqueInfo badtune = minimal("test-bad-tune");
  badtune.params = {tuned(param("n", "", "", ParamType::Integer, 1, 4, 2), {1, 2.5})};
  EXPECT_NE(error_of([&] { register_technique(badtune); }).find("tune value 2.5"),
            std::string::npos);
  TechniqueInfo listed = minimal("test-bad-allowed");
  ParamDecl n = tuned(param("n", "", "", ParamType::Integer, 1, 4, 2), {2, 3});
  n.allowed = {2, 4};
  listed.params = {n};
  EXPECT_NE(error_of([&] { register_technique(listed); }).find("tune value 3 not among"),
            std::string::npos);
  listed.params[0].value = 1;
  EXPECT_NE(error_of([&] { register_technique(listed); }).find("default 1 not among"),
            std::string::npos);
  // Nothing refused was added.
  for (const char* name : {"test-twice", "test-outside", "test-flag", "test-dotted",
                           "test-late-margin", "test-bad-tune", "test-bad-allowed"}) {
    EXPECT_NE(error_of([&] { technique_info(name); }).find("unknown technique"), std::string::npos);
  }
}

// tune searches what each technique declares: every built-in technique with
// a planning margin tunes it over the same values, and some other parameter
// that trades quality for time besides (lodmask has none).
TEST(Registry, EveryPlanningTechniqueDeclaresWhatTuneSearches) {
  for (const std::string& name : technique_names()) {
    const TechniqueInfo& info = technique_info(name);
    if (info.params.empty() || info.params[0].key != kPlanMarginKey) continue;
    EXPECT_EQ(info.params[0].tune, (std::vector<double>{1.0, 1.25, 1.5, 2.0, 2.5, 3.0})) << name;
    int others = 0;
    for (const ParamDecl& p : info.params) others += p.key != kPlanMarginKey && !p.tune.empty();
    if (name != "lodmask") {
      EXPECT_GT(others, 0) << name;
    }
  }
}
