#include "foveate/core/parse.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "foveate/core/error.hpp"

namespace foveate {

std::string format_alternatives(const std::vector<std::string>& items) {
  std::string out;
  for (size_t i = 0; i < items.size(); ++i) {
    if (i > 0) out += i + 1 == items.size() ? " or " : ", ";
    out += items[i];
  }
  return out;
}

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

namespace {

std::string coordinate_text(double v) { return format_number(v, 3); }

}  // namespace

Vec2d parse_point(const std::string& text, int width, int height, const std::string& option) {
  const auto c = text.find(',');
  double x = 0, y = 0;
  if (c == std::string::npos || !parse_number(text.substr(0, c), x) ||
      !parse_number(text.substr(c + 1), y)) {
    throw Error(option + ": expected X,Y in pixels or normalized (e.g. 960,540 or 0.5,0.5), got '" +
                text + "'");
  }
  const std::string sx = text.substr(0, c), sy = text.substr(c + 1);
  const bool nx = sx.find('.') != std::string::npos, ny = sy.find('.') != std::string::npos;
  if (nx != ny) {
    throw Error(option + ": '" + text + "' mixes a normalized coordinate (" + (nx ? sx : sy) +
                ", written with a decimal point) and one in pixels (" + (nx ? sy : sx) +
                "); write both normalized (0.0..1.0, e.g. 0.5,0.5) or both in pixels (whole "
                "numbers, e.g. 960,540)");
  }
  if (nx) {
    for (const double v : {x, y}) {
      if (v >= 0.0 && v <= 1.0) continue;
      throw Error(option + ": '" + text + "': " + coordinate_text(v) +
                  " is outside 0.0..1.0; a coordinate written with a decimal point is "
                  "normalized (0.0 the left or top edge, 1.0 the right or bottom one); give "
                  "pixels as whole numbers (e.g. 960,540)");
    }
    return {x * width, y * height};
  }
  if (std::fabs(x) > 1e6 || std::fabs(y) > 1e6) {
    throw Error(option + ": point '" + text + "' is absurdly far off screen");
  }
  return {x, y};
}

Vec2d parse_point_on_image(const std::string& text, int width, int height,
                           const std::string& option) {
  const Vec2d p = parse_point(text, width, height, option);
  if (p.x >= 0.0 && p.x <= width && p.y >= 0.0 && p.y <= height) return p;
  const std::string w = std::to_string(width), h = std::to_string(height);
  throw Error(option + ": '" + text + "' is (" + coordinate_text(p.x) + ", " +
              coordinate_text(p.y) + ") px, outside the " + w + "x" + h + " image (x 0.." + w +
              " and y 0.." + h + " in pixels, or 0.0..1.0 normalized)");
}

namespace {

// Edit distance with adjacent transpositions (optimal string alignment),
// case ignored.
size_t edit_distance(const std::string& a, const std::string& b) {
  const auto lower = [](char ch) { return std::tolower(static_cast<unsigned char>(ch)); };
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1, 0));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t cost = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) &&
          lower(a[i - 2]) == lower(b[j - 1]))
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[a.size()][b.size()];
}

}  // namespace

std::string closest_name(const std::string& input, const std::vector<std::string>& candidates) {
  // Leading dashes are not part of an option's name: "--sise" is 4 letters.
  const size_t letters = input.size() - std::min(input.find_first_not_of('-'), input.size());
  const size_t allowed = std::max<size_t>(1, letters / 3);
  std::string best;
  size_t best_distance = allowed + 1;
  for (const std::string& c : candidates) {
    const size_t d = edit_distance(input, c);
    if (d < best_distance && c != input) {
      best = c;
      best_distance = d;
    }
  }
  return best;
}

std::string did_you_mean(const std::string& input, const std::vector<std::string>& candidates) {
  const std::string best = closest_name(input, candidates);
  return best.empty() ? std::string() : "; did you mean '" + best + "'?";
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
