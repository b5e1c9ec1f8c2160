#pragma once
// Parsing of the small values users type: numbers, screen points and sizes.
// Errors name the option they came from.
#include <string>
#include <vector>

#include "foveate/core/display.hpp"

namespace foveate {

/// A number as people read it: no exponent in the everyday range, at most
/// `max_decimals` decimals, trailing zeros dropped (9 -> "9", 2073600 ->
/// "2073600", 0.0275 -> "0.0275", 1.0 / 3 -> "0.333333"); "nan", "inf", "-inf".
std::string format_number(double value, int max_decimals = 6);

/// Alternatives as a sentence lists them: "a", "a or b", "a, b or c".
std::string format_alternatives(const std::vector<std::string>& items);

/// A number with exactly `digits` decimals ("%.*f"): table cells and reports.
std::string format_fixed(double value, int digits);

/// The whole string as a finite number; false otherwise.
bool parse_number(const std::string& text, double& out);

/// "X,Y" on a width x height screen, returned in pixels, origin top-left. A
/// coordinate written with a decimal point is normalized (0.0 = the left or
/// top edge, 1.0 = the right or bottom one) and must lie in [0, 1]; one
/// without is in pixels. Both must be of one kind ("0.5,540" is refused).
/// Pixel points off the screen are allowed (within 1e6 px); throws
/// foveate::Error naming `option` and the reason for anything else.
Vec2d parse_point(const std::string& text, int width, int height, const std::string& option);
/// parse_point, and the point must lie on the image: 0 <= x <= width and
/// 0 <= y <= height (a gaze off the image leaves a foveated technique
/// nothing to follow). The error names `option`, the point and the size.
Vec2d parse_point_on_image(const std::string& text, int width, int height,
                           const std::string& option);

/// The candidate closest to `input` in edit distance (letters swapped,
/// missing or wrong; case ignored), when it is close enough to be a typo
/// (at most a third of its length, and 1 for short names), else empty.
std::string closest_name(const std::string& input, const std::vector<std::string>& candidates);
/// "; did you mean 'NAME'?" for closest_name, or empty.
std::string did_you_mean(const std::string& input, const std::vector<std::string>& candidates);

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
