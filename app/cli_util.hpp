#pragma once
// Parsing helpers shared by the subcommands: every bad value becomes a
// foveate::Error that names the option.
#include <cstdint>
#include <optional>
#include <string>

#include "foveate/core/acuity.hpp"
#include "foveate/core/display.hpp"
#include "foveate/core/parse.hpp"

namespace foveate::app {

struct Size {
  int width = 0;
  int height = 0;
};

/// "WxH", each 1..16384.
Size parse_size(const std::string& text, const std::string& option);
/// --quality A|B or --slope M (at most one); defaults to quality A.
AcuityModel acuity_from_options(const std::string& quality, std::optional<double> slope);
/// A byte count: a number with an optional K, M, G or T suffix (powers of
/// 1024, "B" and "iB" allowed: 512M, 1.5GiB, 4096), more than 0.
std::uint64_t parse_byte_size(const std::string& text, const std::string& option);
/// Formats a number with `digits` decimals.
std::string fmt(double value, int digits);

}  // namespace foveate::app
