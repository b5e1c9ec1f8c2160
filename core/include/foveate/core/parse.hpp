#pragma once
// Parsing of the small values users type: numbers, screen points and sizes.
// Errors name the option they came from.
#include <string>

#include "foveate/core/display.hpp"

namespace foveate {

/// A number as people read it: no exponent in the everyday range, at most
/// `max_decimals` decimals, trailing zeros dropped (9 -> "9", 2073600 ->
/// "2073600", 0.0275 -> "0.0275", 1.0 / 3 -> "0.333333"); "nan", "inf", "-inf".
std::string format_number(double value, int max_decimals = 6);

/// A number with exactly `digits` decimals ("%.*f"): table cells and reports.
std::string format_fixed(double value, int digits);

/// The whole string as a finite number; false otherwise.
bool parse_number(const std::string& text, double& out);

/// "X,Y" in pixels, or normalized when both values are written with a decimal
/// point and lie in [0, 1] (e.g. "0.5,0.5"); returned in pixels of a
/// width x height screen, origin top-left. Points off the screen are allowed;
/// throws foveate::Error naming `option` for anything else.
Vec2d parse_point(const std::string& text, int width, int height, const std::string& option);

/// A render size in pixels.
struct PixelSize {
  int width = 0;
  int height = 0;
};
/// The largest side of a render target foveate makes.
inline constexpr int kMaxSizePx = 16384;
/// Why `size` cannot be rendered ("each side must be 1..16384 pixels, got
/// WxH"), or empty when it can.
std::string size_problem(PixelSize size);
/// "WxH" in pixels, each side 1..16384; throws foveate::Error naming `option`.
PixelSize parse_size(const std::string& text, const std::string& option);

}  // namespace foveate
