// One colour per technique (palette.hpp).
#include "foveate/techniques/palette.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "registry.hpp"

namespace foveate {

namespace {

// The built-ins, in registry order (registry.hpp). Colour-blind-safe hues
// after Okabe and Ito (2008), readable on white and under white text; native,
// the reference, a neutral grey.
constexpr std::array<Rgb8, 8> kBuiltin = {{
    {0x55, 0x55, 0x55},  // native
    {0x00, 0x72, 0xb2},  // layered: blue
    {0xe6, 0x9f, 0x00},  // logpolar: orange
    {0x00, 0x9e, 0x73},  // checkerboard: bluish green
    {0xcc, 0x79, 0xa7},  // lodmask: reddish purple
    {0xd5, 0x5e, 0x00},  // inset: vermillion
    {0x56, 0xb4, 0xe9},  // vrs: sky blue
    {0x7b, 0x32, 0x94},  // marwarp: purple
}};
#define FOVEATE_COUNT_ONE(name) +1
static_assert(kBuiltin.size() == 0 FOVEATE_BUILTIN_TECHNIQUES(FOVEATE_COUNT_ONE),
              "one colour per built-in technique");
#undef FOVEATE_COUNT_ONE

// Any other name: chosen by the name itself (FNV-1a), not by when it was
// registered, so that the same name has the same colour in every report.
constexpr std::array<Rgb8, 6> kOthers = {{{0x88, 0x22, 0x55},
                                          {0x44, 0xaa, 0x99},
                                          {0x99, 0x99, 0x33},
                                          {0x33, 0x22, 0x88},
                                          {0xaa, 0x44, 0x99},
                                          {0x11, 0x77, 0x33}}};

Rgb8 base_colour(const std::string& name) {
  const auto& all = techniques();
  const size_t builtin = std::min(all.size(), kBuiltin.size());
  for (size_t i = 0; i < builtin; ++i) {
    if (all[i].name == name) return kBuiltin[i];
  }
  std::uint32_t h = 2166136261u;
  for (unsigned char c : name) h = (h ^ c) * 16777619u;
  return kOthers[h % kOthers.size()];
}

std::uint8_t mix(std::uint8_t c, double target, double t) {
  return static_cast<std::uint8_t>(std::lround((1.0 - t) * c + t * target));
}

}  // namespace

Rgb8 technique_colour(const std::string& technique, int variant) {
  const Rgb8 c = base_colour(technique);
  if (variant <= 0) return c;
  // 1: darker, 2: lighter, 3: darker still, ...; at most 70 % of the way.
  const double t = std::min(0.7, 0.3 * ((variant + 1) / 2));
  const double target = variant % 2 == 1 ? 0.0 : 255.0;
  return {mix(c.r, target, t), mix(c.g, target, t), mix(c.b, target, t)};
}

std::string hex_colour(Rgb8 c) {
  char s[8];
  std::snprintf(s, sizeof s, "#%02x%02x%02x", c.r, c.g, c.b);
  return s;
}

std::string technique_colour_hex(const std::string& technique, int variant) {
  return hex_colour(technique_colour(technique, variant));
}

std::vector<OverlayShape> overlay_legend(const std::vector<OverlayShape>& shapes) {
  std::vector<OverlayShape> out;
  for (const OverlayShape& s : shapes) {
    const bool seen = std::any_of(out.begin(), out.end(), [&](const OverlayShape& e) {
      return e.label == s.label && e.kind == s.kind && e.r == s.r && e.g == s.g && e.b == s.b;
    });
    if (!seen) out.push_back(s);
  }
  return out;
}

}  // namespace foveate
