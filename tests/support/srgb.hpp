#pragma once
// The sRGB transfer functions written out independently of the library, for
// tests that check it, and the mean linear luminance of part of an image.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "foveate/core/image.hpp"

namespace foveate::test {

inline double to_linear(double code) {
  const double c = code / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
inline double to_code(double lin) {
  lin = std::clamp(lin, 0.0, 1.0);
  return 255.0 * (lin <= 0.0031308 ? 12.92 * lin : 1.055 * std::pow(lin, 1.0 / 2.4) - 0.055);
}
inline std::uint8_t q8(double code) {
  return static_cast<std::uint8_t>(std::clamp(std::lround(code), 0L, 255L));
}

/// Mean linear luminance (sRGB decoded, Rec. 709 weights) of the pixels at
/// least `min_radius` from `centre` (pixels, origin top-left).
inline double mean_linear_luminance(const Image& img, Vec2d centre, double min_radius) {
  double sum = 0;
  int n = 0;
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      if (std::hypot(x + 0.5 - centre.x, y + 0.5 - centre.y) < min_radius) continue;
      const std::uint8_t* p = img.at(x, y);
      sum += 0.2126 * to_linear(p[0]) + 0.7152 * to_linear(p[1]) + 0.0722 * to_linear(p[2]);
      ++n;
    }
  }
  return n ? sum / n : 0.0;
}

}  // namespace foveate::test
