#include "foveate/core/lens.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "foveate/core/error.hpp"
#include "foveate/core/json_read.hpp"
#include "foveate/core/parse.hpp"

namespace foveate {

namespace {
constexpr double kDeg = 180.0 / std::numbers::pi;
constexpr double kRad = std::numbers::pi / 180.0;
constexpr int kMaxPanel = 65536;

// A JSON array of `n` numbers at `key` (each finite), or an error naming it.
std::vector<double> numbers_at(JsonReader& r, const char* key, size_t min_n, size_t max_n,
                               const char* what) {
  const nlohmann::json* v = r.get(key);
  if (!v) throw Error(r.path(key) + ": required (" + what + ")");
  if (!v->is_array() || v->size() < min_n || v->size() > max_n) {
    const std::string count = min_n == max_n
                                  ? std::to_string(min_n)
                                  : std::to_string(min_n) + " to " + std::to_string(max_n);
    throw Error(r.path(key) + ": expected an array of " + count + " numbers (" + what + ")");
  }
  std::vector<double> out;
  for (const nlohmann::json& x : *v) {
    if (!x.is_number() || !std::isfinite(x.get<double>())) {
      throw Error(r.path(key) + ": expected numbers, got " + x.dump());
    }
    out.push_back(x.get<double>());
  }
  return out;
}
}  // namespace

double Lens::tan_at_radius(double r) const {
  const double q = (r / radius_unit_px) * (r / radius_unit_px);
  return r / px_per_tan * (1.0 + q * (k[0] + q * (k[1] + q * k[2])));
}

double Lens::dtan_dr(double r) const {
  const double q = (r / radius_unit_px) * (r / radius_unit_px);
  return (1.0 + q * (3.0 * k[0] + q * (5.0 * k[1] + q * 7.0 * k[2]))) / px_per_tan;
}

double Lens::radius_at_tan(double t) const {
  if (!(t > 0.0)) return 0.0;
  // Bracket, then bisect: the mapping increases out to where validate() looked.
  double lo = 0.0, hi = t * px_per_tan;
  for (int i = 0; i < 200 && tan_at_radius(hi) < t; ++i) {
    lo = hi;
    hi *= 2.0;
  }
  for (int i = 0; i < 100 && hi - lo > 1e-9 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (tan_at_radius(mid) < t ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

PanelDensity Lens::density_at_tan(double t) const {
  // Per radian: radially dr/dtheta = (1 + t^2) / (dtan/dr); tangentially a
  // circle of panel radius r is seen as one of angular radius theta, so
  // r / sin(theta) (px_per_tan at the centre).
  const double r = radius_at_tan(t);
  const double radial = (1.0 + t * t) / dtan_dr(r);
  const double tangential = t > 1e-12 ? r * std::sqrt(1.0 + t * t) / t : px_per_tan;
  return {radial * kRad, tangential * kRad};
}

Oversampling Lens::oversampling_at_tan(double t, double f) const {
  // The buffer's pixels per radian are f (1 + t^2) radially and f sqrt(1 + t^2)
  // tangentially; divided by the panel's (above) they reduce to these.
  const double r = radius_at_tan(t);
  const double tangential = t > 1e-12 ? f * t / r : f / px_per_tan;
  return {f * dtan_dr(r), tangential};
}

Lens Lens::mirrored() const {
  Lens l = *this;
  l.center_x_px = panel_width_px - center_x_px;
  return l;
}

void Lens::validate(const std::string& where, double max_tan) const {
  const std::string w = where + ": lens";
  if (panel_width_px < 1 || panel_width_px > kMaxPanel || panel_height_px < 1 ||
      panel_height_px > kMaxPanel) {
    throw Error(w + ".panel_px: each must be in [1, 65536], got " + std::to_string(panel_width_px) +
                "x" + std::to_string(panel_height_px));
  }
  if (!std::isfinite(center_x_px) || !std::isfinite(center_y_px) || center_x_px < 0.0 ||
      center_x_px > panel_width_px || center_y_px < 0.0 || center_y_px > panel_height_px) {
    throw Error(w + ".center_px: must lie on the panel [0, " + std::to_string(panel_width_px) +
                "] x [0, " + std::to_string(panel_height_px) + "], got " +
                format_number(center_x_px) + ", " + format_number(center_y_px));
  }
  if (!std::isfinite(px_per_tan) || !(px_per_tan > 0.0) || px_per_tan > 1e6) {
    throw Error(w + ".px_per_tan: must be in (0, 1e6] panel pixels per unit tangent, got " +
                format_number(px_per_tan));
  }
  if (!std::isfinite(radius_unit_px) || !(radius_unit_px > 0.0) || radius_unit_px > 1e6) {
    throw Error(w + ".radius_unit_px: must be in (0, 1e6] panel pixels, got " +
                format_number(radius_unit_px));
  }
  for (size_t i = 0; i < k.size(); ++i) {
    if (!std::isfinite(k[i]) || std::abs(k[i]) > 1e3) {
      throw Error(w + ".k: k" + std::to_string(i + 1) + " must be finite, |k| <= 1000, got " +
                  format_number(k[i]));
    }
  }
  // The mapping must grow (one panel radius per view angle) out to the
  // panel's farthest corner and to the view's farthest corner.
  const double cx = std::max(center_x_px, panel_width_px - center_x_px);
  const double cy = std::max(center_y_px, panel_height_px - center_y_px);
  const double corner = std::hypot(cx, cy);
  const double step = std::max(0.25, corner / 4000.0);
  for (double r = 0.0;; r += step) {
    if (!(dtan_dr(r) > 0.0)) {
      throw Error(w + ".k: the view angle stops growing " + format_number(r, 1) +
                  " panel pixels from the lens centre (at " +
                  format_number(std::atan(tan_at_radius(r)) * kDeg, 2) +
                  " deg), inside the panel or the view; a lens must map each panel radius to "
                  "one view angle (k1 = " +
                  format_number(k[0]) + ", k2 = " + format_number(k[1]) +
                  ", k3 = " + format_number(k[2]) + ")");
    }
    if (r >= corner && tan_at_radius(r) >= max_tan) break;
    if (r > 1e3 * corner) {
      throw Error(w + ": the lens never reaches the view's corner (tangent " +
                  format_number(max_tan) + ")");
    }
  }
}

Lens Lens::from_json(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object()) throw Error(where + ": expected an object");
  JsonReader r(j, where);
  Lens l;
  const auto panel = numbers_at(r, "panel_px", 2, 2, "the panel's pixels per eye, [width, height]");
  for (double v : panel) {
    if (v != std::floor(v) || v < 1 || v > kMaxPanel) {
      throw Error(r.path("panel_px") + ": expected two whole numbers in [1, 65536], got " +
                  format_number(v));
    }
  }
  l.panel_width_px = static_cast<int>(panel[0]);
  l.panel_height_px = static_cast<int>(panel[1]);
  const auto c = numbers_at(r, "center_px", 2, 2, "the lens axis on the panel, [x, y] pixels");
  l.center_x_px = c[0];
  l.center_y_px = c[1];
  if (!r.number("px_per_tan", l.px_per_tan, 1e-9, 1e6)) {
    throw Error(r.path("px_per_tan") +
                ": required (panel pixels per unit tangent at the lens centre)");
  }
  l.radius_unit_px = l.px_per_tan;
  r.number("radius_unit_px", l.radius_unit_px, 1e-9, 1e6);
  const auto k =
      numbers_at(r, "k", 1, 3, "[k1, k2, k3] of tan = r / px_per_tan * (1 + k1 rho^2 + ...)");
  for (size_t i = 0; i < k.size(); ++i) l.k[i] = k[i];
  r.finish();
  return l;
}

void to_json(nlohmann::json& j, const Lens& l) {
  j = nlohmann::json{{"panel_px", {l.panel_width_px, l.panel_height_px}},
                     {"center_px", {l.center_x_px, l.center_y_px}},
                     {"px_per_tan", l.px_per_tan},
                     {"radius_unit_px", l.radius_unit_px},
                     {"k", {l.k[0], l.k[1], l.k[2]}}};
}

OversamplingTable::OversamplingTable(const Lens& lens, double f, double max_angle_deg,
                                     double step_deg)
    : step_deg_(step_deg) {
  const int n = std::max(1, static_cast<int>(std::ceil(max_angle_deg / step_deg))) + 1;
  suffix_.resize(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    const double a = std::min(i * step_deg, 89.9);
    suffix_[static_cast<size_t>(i)] = lens.oversampling_at_tan(std::tan(a * kRad), f);
  }
  for (int i = n - 2; i >= 0; --i) {
    Oversampling& o = suffix_[static_cast<size_t>(i)];
    const Oversampling& next = suffix_[static_cast<size_t>(i) + 1];
    o.radial = std::min(o.radial, next.radial);
    o.tangential = std::min(o.tangential, next.tangential);
  }
}

Oversampling OversamplingTable::least_beyond(double angle_deg) const {
  const double i = std::floor(std::max(0.0, angle_deg) / step_deg_);
  const size_t idx = std::min(suffix_.size() - 1, static_cast<size_t>(i));
  return suffix_[idx];
}

}  // namespace foveate
