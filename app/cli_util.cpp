#include "cli_util.hpp"

#include <cctype>
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

std::uint64_t parse_byte_size(const std::string& text, const std::string& option) {
  std::string t = text;
  for (const char* suffix : {"iB", "B", "ib", "b"}) {
    const std::string sfx(suffix);
    if (t.size() > sfx.size() && t.compare(t.size() - sfx.size(), sfx.size(), sfx) == 0) {
      t.resize(t.size() - sfx.size());
      break;
    }
  }
  double scale = 1.0;
  if (!t.empty()) {
    switch (std::toupper(static_cast<unsigned char>(t.back()))) {
      case 'K':
        scale = 1024.0;
        break;
      case 'M':
        scale = 1024.0 * 1024;
        break;
      case 'G':
        scale = 1024.0 * 1024 * 1024;
        break;
      case 'T':
        scale = 1024.0 * 1024 * 1024 * 1024;
        break;
      default:
        break;
    }
    if (scale > 1.0) t.pop_back();
  }
  double v = 0.0;
  if (!parse_number(t, v) || !(v * scale >= 1.0) || !(v * scale < 1.8e19)) {
    throw Error(option + ": expected a size in bytes such as 512M or 8G, got '" + text + "'");
  }
  return static_cast<std::uint64_t>(v * scale);
}

std::string fmt(double value, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, value);
  return buf;
}

}  // namespace foveate::app
