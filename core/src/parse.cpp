#include "foveate/core/parse.hpp"

#include <cmath>
#include <cstdlib>

#include "foveate/core/error.hpp"

namespace foveate {

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

}  // namespace foveate
