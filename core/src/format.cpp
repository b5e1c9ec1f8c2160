// Numbers written for people (format.hpp).
#include "foveate/core/format.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace foveate {

namespace {

// "×10⁻⁵": the power of ten in superscript digits, as typeset.
std::string power_of_ten(int exponent) {
  static const char* const kDigits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string digits;
  for (int e = std::abs(exponent);; e /= 10) {
    digits.insert(0, kDigits[e % 10]);
    if (e < 10) break;
  }
  return std::string("×10") + (exponent < 0 ? "⁻" : "") + digits;
}

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals < 0 ? 0 : decimals, v);
  std::string s = buf;
  if (s.find_first_not_of("-0.") == std::string::npos) s = "0";  // no "-0.00"
  return s;
}

// m × 10^e with `decimals` decimals in m, 1 <= |m| < 10 after rounding.
std::string scientific(double v, int decimals) {
  int e = static_cast<int>(std::floor(std::log10(std::fabs(v))));
  double m = v / std::pow(10.0, e);
  const double scale = std::pow(10.0, decimals);
  if (std::fabs(std::round(m * scale) / scale) >= 10.0) m /= 10.0, ++e;
  return fixed(m, decimals) + power_of_ten(e);
}

}  // namespace

std::string format_significant(double v, int digits) {
  if (std::isnan(v)) return "–";
  if (std::isinf(v)) return v > 0 ? "∞" : "−∞";
  if (v == 0.0) return "0";
  if (digits < 1) digits = 1;
  const double a = std::fabs(v);
  if (a < 1e-3) return scientific(v, digits - 1);
  const int e = static_cast<int>(std::floor(std::log10(a)));
  int decimals = digits - 1 - e;
  if (decimals <= 0) return fixed(v, 0);
  // Rounding may carry into the next power (9.996 -> 10.00): one decimal less.
  const double scale = std::pow(10.0, decimals);
  if (std::fabs(std::round(v * scale) / scale) >= std::pow(10.0, e + 1)) --decimals;
  return fixed(v, decimals);
}

std::string format_quantity(double value, const std::string& unit, int digits) {
  const std::string n = format_significant(value, digits);
  return std::isnan(value) || unit.empty() ? n : n + " " + unit;
}

std::string format_percent(double share, int digits) {
  return format_quantity(100.0 * share, "%", digits);
}

std::string format_tick(double value, double step) {
  if (!(step > 0) || !std::isfinite(step) || !std::isfinite(value))
    return format_significant(value, 3);
  if (std::fabs(value) < 1e-9 * step) return "0";
  if (step < 1e-3) {
    // A shared power of ten: the step's, so that 2×10⁻⁵ and 4×10⁻⁵ line up.
    const int e = static_cast<int>(std::floor(std::log10(step) + 1e-9));
    const double m = value / std::pow(10.0, e);
    return fixed(m, std::fabs(m - std::round(m)) < 1e-6 ? 0 : 1) + power_of_ten(e);
  }
  // As many decimals as the step itself has (0.25 -> 2, 0.2 -> 1, 5 -> 0).
  int decimals = 0;
  for (double s = step; decimals < 12; ++decimals, s *= 10) {
    if (std::fabs(s - std::round(s)) <= 1e-6 * s) break;
  }
  return fixed(value, decimals);
}

std::string format_power_of_ten(int exponent) {
  if (exponent >= -2 && exponent <= 3)
    return fixed(std::pow(10.0, exponent), std::max(0, -exponent));
  return power_of_ten(exponent).substr(std::string("×").size());
}

}  // namespace foveate
