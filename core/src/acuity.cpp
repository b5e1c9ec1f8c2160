#include "foveate/core/acuity.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "foveate/core/error.hpp"
#include "foveate/core/parse.hpp"

namespace foveate {

double AcuityModel::mar_deg(double eccentricity_deg) const {
  return slope * eccentricity_deg + w0_deg;
}

double AcuityModel::eccentricity_for_mar(double mar) const {
  return std::max(0.0, (mar - w0_deg) / slope);
}

AcuityModel AcuityModel::preset(const std::string& name) {
  std::string n = name;
  std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return std::toupper(c); });
  if (n == "A") return AcuityModel{kSlopePresetA, kFovealMarDeg};
  if (n == "B") return AcuityModel{kSlopePresetB, kFovealMarDeg};
  throw Error("acuity preset: expected A or B, got '" + name + "'");
}

AcuityModel AcuityModel::with_slope(double m) {
  if (!std::isfinite(m) || m <= 0.0 || m > 1.0) {
    throw Error("slope: expected a number in (0, 1] (degrees of MAR per degree), got " +
                format_number(m));
  }
  return AcuityModel{m, kFovealMarDeg};
}

AcuityModel AcuityModel::finer(double margin) const {
  if (!std::isfinite(margin) || margin < 1.0 || margin > 4.0) {
    throw Error("margin: expected a factor from 1 to 4, got " + format_number(margin));
  }
  return AcuityModel{slope / margin, w0_deg / margin};
}

}  // namespace foveate
