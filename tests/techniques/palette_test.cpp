// One colour per technique in every figure, and the overlay legend's
// entries (techniques/palette.hpp), without GL.
#include "foveate/techniques/palette.hpp"

#include <gtest/gtest.h>

#include <set>

using namespace foveate;

TEST(Palette, EachBuiltinItsOwnFixedColour) {
  std::set<std::string> seen;
  for (const std::string& name : technique_names()) {
    const std::string hex = technique_colour_hex(name);
    EXPECT_EQ(hex.size(), 7u) << name;
    EXPECT_TRUE(seen.insert(hex).second) << name << " shares " << hex;
  }
  // Fixed, not by position in a report: layered is blue in every report.
  EXPECT_EQ(technique_colour_hex("layered"), "#0072b2");
  EXPECT_EQ(technique_colour_hex("native"), "#555555");
  EXPECT_EQ(technique_colour_hex("vrs"), "#56b4e9");
}

TEST(Palette, OtherNamesByTheirNameAlone) {
  const std::string a = technique_colour_hex("my-own-technique");
  EXPECT_EQ(a, technique_colour_hex("my-own-technique"));
  for (const std::string& name : technique_names())
    EXPECT_NE(a, technique_colour_hex(name)) << name;
  // Registering it does not change its colour (the name decides, not the order).
  TechniqueInfo t;
  t.name = "my-own-technique";
  t.make = [](const TechniqueConfig& c, const ParamValues&) { return make_technique("native", c); };
  register_technique(t);
  EXPECT_EQ(technique_colour_hex("my-own-technique"), a);
}

TEST(Palette, VariantsShadeTheBaseAndDifferFromEachOther) {
  const Rgb8 base = technique_colour("logpolar");
  std::set<std::string> seen{hex_colour(base)};
  for (int v = 1; v <= 4; ++v) {
    const Rgb8 c = technique_colour("logpolar", v);
    EXPECT_TRUE(seen.insert(hex_colour(c)).second) << v;
    // Darker for odd variants, lighter for even ones.
    const int sum = c.r + c.g + c.b, base_sum = base.r + base.g + base.b;
    if (v % 2 == 1) {
      EXPECT_LT(sum, base_sum) << v;
    } else {
      EXPECT_GT(sum, base_sum) << v;
    }
  }
  EXPECT_EQ(technique_colour("logpolar", 0), base);
}

TEST(OverlayLegend, OneEntryPerLabelColourAndShape) {
  using K = OverlayShape::Kind;
  const std::vector<OverlayShape> shapes = {
      {K::Rect, 0, 0, 10, 10, 1, 0, 0, "layer 1"}, {K::Circle, 5, 5, 4, 0, 1, 0, 0, "layer 1"},
      {K::Rect, 1, 1, 10, 10, 1, 0, 0, "layer 1"}, {K::Circle, 5, 5, 8, 0, 0, 1, 0, "layer 2"},
      {K::Dot, 5, 5, 2, 0, 1, 0.3f, 0.8f, "gaze"}, {K::Dot, 6, 5, 2, 0, 1, 0.3f, 0.8f, "gaze"}};
  const std::vector<OverlayShape> legend = overlay_legend(shapes);
  ASSERT_EQ(legend.size(), 4u);
  // The rectangle and the ring of one colour stay two entries, told apart by kind.
  EXPECT_EQ(legend[0].kind, K::Rect);
  EXPECT_EQ(legend[1].kind, K::Circle);
  EXPECT_EQ(legend[1].label, "layer 1");
  EXPECT_EQ(legend[2].label, "layer 2");
  EXPECT_EQ(legend[3].label, "gaze");
}
