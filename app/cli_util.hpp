#pragma once
// Parsing helpers shared by the subcommands: every bad value becomes a
// foveate::Error that names the option.
#include <optional>
#include <string>

#include "foveate/core/acuity.hpp"
#include "foveate/core/display.hpp"

namespace foveate::app {

struct Size {
  int width = 0;
  int height = 0;
};

/// "WxH", each 1..16384.
Size parse_size(const std::string& text, const std::string& option);
/// "X,Y" in pixels, or normalized when both values are written with a decimal
/// point and lie in [0, 1] (e.g. "0.5,0.5"). Points outside the screen are allowed.
Vec2d parse_point(const std::string& text, int width, int height, const std::string& option);
/// --quality A|B or --slope M (at most one); defaults to quality A.
AcuityModel acuity_from_options(const std::string& quality, std::optional<double> slope);
/// Formats a number with `digits` decimals.
std::string fmt(double value, int digits);

}  // namespace foveate::app
