#include "cli_util.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "foveate/core/error.hpp"
#include "foveate/core/parse.hpp"

namespace foveate::app {

Size parse_size(const std::string& text, const std::string& option) {
  const auto x = text.find_first_of("xX");
  double w = 0, h = 0;
  if (x == std::string::npos || !parse_number(text.substr(0, x), w) ||
      !parse_number(text.substr(x + 1), h) || w != std::floor(w) || h != std::floor(h)) {
    throw Error(option + ": expected WIDTHxHEIGHT in pixels (e.g. 640x360), got '" + text + "'");
  }
  if (w < 1 || h < 1 || w > 16384 || h > 16384) {
    throw Error(option + ": each side must be 1..16384 pixels, got '" + text + "'");
  }
  return {static_cast<int>(w), static_cast<int>(h)};
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
