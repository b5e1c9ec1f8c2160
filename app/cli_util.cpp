#include "cli_util.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "foveate/core/error.hpp"

namespace foveate::app {

namespace {
bool parse_double(const std::string& s, double& out) {
  if (s.empty()) return false;
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && std::isfinite(out);
}
}  // namespace

Size parse_size(const std::string& text, const std::string& option) {
  const auto x = text.find_first_of("xX");
  double w = 0, h = 0;
  if (x == std::string::npos || !parse_double(text.substr(0, x), w) ||
      !parse_double(text.substr(x + 1), h) || w != std::floor(w) || h != std::floor(h)) {
    throw Error(option + ": expected WIDTHxHEIGHT in pixels (e.g. 640x360), got '" + text + "'");
  }
  if (w < 1 || h < 1 || w > 16384 || h > 16384) {
    throw Error(option + ": each side must be 1..16384 pixels, got '" + text + "'");
  }
  return {static_cast<int>(w), static_cast<int>(h)};
}

Vec2d parse_point(const std::string& text, int width, int height, const std::string& option) {
  const auto c = text.find(',');
  double x = 0, y = 0;
  if (c == std::string::npos || !parse_double(text.substr(0, c), x) ||
      !parse_double(text.substr(c + 1), y)) {
    throw Error(option + ": expected X,Y in pixels or normalized (e.g. 960,540 or 0.5,0.5), got '" +
                text + "'");
  }
  const std::string sx = text.substr(0, c), sy = text.substr(c + 1);
  const bool normalized = sx.find('.') != std::string::npos && sy.find('.') != std::string::npos &&
                          x >= 0.0 && x <= 1.0 && y >= 0.0 && y <= 1.0;
  if (normalized) return {x * width, y * height};
  if (std::fabs(x) > 1e6 || std::fabs(y) > 1e6)
    throw Error(option + ": point is absurdly far off screen");
  return {x, y};
}

AcuityModel acuity_from_options(const std::string& quality, std::optional<double> slope) {
  if (!quality.empty() && slope) throw Error("--quality and --slope: give one, not both");
  if (slope) return AcuityModel::with_slope(*slope);
  if (!quality.empty()) return AcuityModel::quality(quality);
  return AcuityModel::quality("A");
}

std::string fmt(double value, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, value);
  return buf;
}

}  // namespace foveate::app
