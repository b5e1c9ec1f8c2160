#include "foveate/core/parse.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "foveate/core/error.hpp"

namespace foveate {

std::string format_number(double v, int max_decimals) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  const double a = std::fabs(v);
  if (a >= 1e15 || (a > 0 && a < std::pow(10.0, -max_decimals))) {
    std::snprintf(buf, sizeof buf, "%.6g", v);  // beyond the everyday range
    return buf;
  }
  std::snprintf(buf, sizeof buf, "%.*f", max_decimals < 0 ? 0 : max_decimals, v);
  std::string s = buf;
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  return s;
}

std::string format_fixed(double value, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, value);
  return buf;
}

bool parse_number(const std::string& s, double& out) {
  if (s.empty()) return false;
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && std::isfinite(out);
}

Vec2d parse_point(const std::string& text, int width, int height, const std::string& option) {
  const auto c = text.find(',');
  double x = 0, y = 0;
  if (c == std::string::npos || !parse_number(text.substr(0, c), x) ||
      !parse_number(text.substr(c + 1), y)) {
    throw Error(option + ": expected X,Y in pixels or normalized (e.g. 960,540 or 0.5,0.5), got '" +
                text + "'");
  }
  const std::string sx = text.substr(0, c), sy = text.substr(c + 1);
  const bool normalized = sx.find('.') != std::string::npos && sy.find('.') != std::string::npos &&
                          x >= 0.0 && x <= 1.0 && y >= 0.0 && y <= 1.0;
  if (normalized) return {x * width, y * height};
  if (std::fabs(x) > 1e6 || std::fabs(y) > 1e6) {
    throw Error(option + ": point '" + text + "' is absurdly far off screen");
  }
  return {x, y};
}

std::string size_problem(PixelSize size) {
  if (size.width >= 1 && size.height >= 1 && size.width <= kMaxSizePx && size.height <= kMaxSizePx)
    return {};
  return "each side must be 1.." + std::to_string(kMaxSizePx) + " pixels, got " +
         std::to_string(size.width) + "x" + std::to_string(size.height);
}

PixelSize parse_size(const std::string& text, const std::string& option) {
  const auto x = text.find_first_of("xX");
  double w = 0, h = 0;
  if (x == std::string::npos || !parse_number(text.substr(0, x), w) ||
      !parse_number(text.substr(x + 1), h) || w != std::floor(w) || h != std::floor(h)) {
    throw Error(option + ": expected WIDTHxHEIGHT in pixels (e.g. 640x360), got '" + text + "'");
  }
  if (w < 1 || h < 1 || w > kMaxSizePx || h > kMaxSizePx) {
    throw Error(option + ": each side must be 1.." + std::to_string(kMaxSizePx) + " pixels, got '" +
                text + "'");
  }
  return {static_cast<int>(w), static_cast<int>(h)};
}

}  // namespace foveate
