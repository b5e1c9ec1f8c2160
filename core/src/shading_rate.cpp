#include "foveate/core/shading_rate.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "foveate/core/error.hpp"
#include "foveate/core/parse.hpp"

namespace foveate {

namespace {
constexpr double kRad = std::numbers::pi / 180.0;

bool known_rate(ShadingRate r) {
  return std::find(kShadingRates.begin(), kShadingRates.end(), r) != kShadingRates.end();
}

int log2_of(int v) { return v == 4 ? 2 : v == 2 ? 1 : 0; }

// The value in [lo, hi] nearest to v.
double nearest_in(double v, double lo, double hi) { return std::clamp(v, lo, hi); }

// Largest angle (radians) one pixel step along the first axis subtends over the
// rectangle [a0, a1] x [b0, b1] (coordinates relative to the display centre,
// the first axis being the step's). At (a, b) the step subtends
// sqrt(b^2 + f^2) / (a^2 + b^2 + f^2): decreasing in |a|, and in |b| it rises
// to a peak at b^2 = a^2 - f^2 (0 when |a| <= f) and falls after it.
double max_step_angle(double a0, double a1, double b0, double b1, double f) {
  const double a = nearest_in(0.0, a0, a1);
  const double peak = std::sqrt(std::max(0.0, a * a - f * f));
  // |b| over [b0, b1] spans [lo, hi]; the function of |b| is unimodal.
  const double lo = (b0 <= 0.0 && b1 >= 0.0) ? 0.0 : std::min(std::abs(b0), std::abs(b1));
  const double hi = std::max(std::abs(b0), std::abs(b1));
  const double b = nearest_in(peak, lo, hi);
  const double q = b * b + f * f;
  return std::sqrt(q) / (a * a + q);
}

// The smallest eccentricity (degrees) of any point of the rectangle
// [x0, x1] x [y0, y1] (top-left pixels). The angle from the gaze has no
// minimum inside the rectangle but at the gaze itself, so it lies on an edge;
// each edge is an arc of a great circle, along which the angle falls to one
// minimum and rises again: at x* = gx (y^2 + f^2) / (y gy + f^2) along a row y
// (centre-relative coordinates), likewise along a column. On a flat panel this
// is the point nearest the gaze in pixels to within a hundredth of a degree;
// on a wide head-mounted pinhole far from the centre it is not.
double min_eccentricity(const Display& d, Vec2d gaze, double x0, double y0, double x1, double y1) {
  if (gaze.x >= x0 && gaze.x <= x1 && gaze.y >= y0 && gaze.y <= y1) return 0.0;
  const double f = d.eye_distance_px(), f2 = f * f;
  const Vec2d centre = d.principal_point();  // (no structured binding: the lambda uses it)
  const double cx = centre.x, cy = centre.y;
  const double gx = gaze.x - cx, gy = gaze.y - cy;
  // The candidates are compared by the cosine of their angle to the gaze
  // (times the gaze ray's constant length), which falls as the angle grows:
  // one square root each, and the angle of the nearest alone.
  double best_cos = -1e300;
  Vec2d best{x0, y0};
  auto consider = [&](double x, double y) {
    const double ax = x - cx, ay = y - cy;
    const double c = (ax * gx + ay * gy + f2) / std::sqrt(ax * ax + ay * ay + f2);
    if (c > best_cos) {
      best_cos = c;
      best = {x, y};
    }
  };
  for (double y : {y0, y1}) {  // rows: the along-edge coordinate is x
    const double yr = y - cy, den = yr * gy + f2;
    consider(x0, y);
    consider(x1, y);
    if (den > 0.0) consider(nearest_in(cx + gx * (yr * yr + f2) / den, x0, x1), y);
  }
  for (double x : {x0, x1}) {  // columns
    const double xr = x - cx, den = xr * gx + f2;
    if (den > 0.0) consider(x, nearest_in(cy + gy * (xr * xr + f2) / den, y0, y1));
  }
  return d.eccentricity_deg(best, gaze);
}
}  // namespace

std::string ShadingRate::name() const {
  return std::to_string(width) + "x" + std::to_string(height);
}

ShadingRate parse_shading_rate(const std::string& text) {
  for (ShadingRate r : kShadingRates) {
    if (r.name() == text) return r;
  }
  throw Error("shading rate '" + text + "': expected one of 1x1, 1x2, 2x1, 2x2, 2x4, 4x2, 4x4");
}

std::vector<ShadingRate> parse_shading_rates(const std::string& text) {
  std::vector<ShadingRate> out;
  size_t start = 0;
  while (true) {
    const size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? comma : comma - start);
    const ShadingRate r = parse_shading_rate(item);
    if (std::find(out.begin(), out.end(), r) != out.end()) {
      throw Error("shading rates: " + r.name() + " is listed twice");
    }
    out.push_back(r);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (std::find(out.begin(), out.end(), ShadingRate{1, 1}) == out.end()) {
    throw Error("shading rates: must include 1x1 (native shading, which every GPU supports)");
  }
  return out;
}

RateApi parse_rate_api(const std::string& text) {
  if (text == "vulkan") return RateApi::Vulkan;
  if (text == "d3d12") return RateApi::D3D12;
  if (text == "gl-nv") return RateApi::GlNv;
  throw Error("api '" + text + "': expected vulkan, d3d12 or gl-nv");
}

const char* rate_api_name(RateApi api) {
  switch (api) {
    case RateApi::Vulkan:
      return "vulkan";
    case RateApi::D3D12:
      return "d3d12";
    case RateApi::GlNv:
      return "gl-nv";
  }
  return "?";
}

std::uint8_t encode_shading_rate(ShadingRate rate, RateApi api) {
  if (!known_rate(rate)) throw Error("shading rate " + rate.name() + ": not a VRS rate");
  if (api == RateApi::GlNv) {
    const auto it = std::find(kShadingRates.begin(), kShadingRates.end(), rate);
    return static_cast<std::uint8_t>(it - kShadingRates.begin());
  }
  // Vulkan's attachment texel and D3D12_SHADING_RATE share this encoding.
  return static_cast<std::uint8_t>(log2_of(rate.width) << 2 | log2_of(rate.height));
}

const std::array<unsigned, 7>& gl_nv_palette() {
  static const std::array<unsigned, 7> palette = {0x9565, 0x9566, 0x9567, 0x9568,
                                                  0x9569, 0x956A, 0x956B};
  return palette;
}

bool is_shading_rate_tile(int px) {
  return std::find(kShadingRateTiles.begin(), kShadingRateTiles.end(), px) !=
         kShadingRateTiles.end();
}

std::string shading_rate_tiles_text() {
  std::vector<std::string> tiles;
  for (int t : kShadingRateTiles) tiles.push_back(std::to_string(t));
  return format_alternatives(tiles);
}

void ShadingRateOptions::validate() const {
  if (!is_shading_rate_tile(tile_px)) {
    throw Error("tile: expected " + shading_rate_tiles_text() + " pixels, got " +
                std::to_string(tile_px));
  }
  if (!std::isfinite(latency_travel_deg) || latency_travel_deg < 0.0) {
    throw Error("latency travel: expected a finite number of degrees >= 0, got " +
                std::to_string(latency_travel_deg));
  }
  if (!std::isfinite(fovea_scale) || fovea_scale < 1.0 || fovea_scale > 100.0) {
    throw Error("fovea scale: expected 1..100, got " + std::to_string(fovea_scale));
  }
  if (std::find(supported.begin(), supported.end(), ShadingRate{1, 1}) == supported.end()) {
    throw Error("shading rates: must include 1x1 (native shading, which every GPU supports)");
  }
  for (ShadingRate r : supported) {
    if (!known_rate(r)) throw Error("shading rates: " + r.name() + " is not a VRS rate");
  }
}

std::array<int, 4> ShadingRateImage::tile_rect(int tx, int ty) const {
  const int x0 = tx * tile_px, x1 = std::min(width_px, x0 + tile_px);
  if (!origin_bottom_left) {
    const int y0 = ty * tile_px;
    return {x0, y0, x1, std::min(height_px, y0 + tile_px)};
  }
  const int b0 = ty * tile_px, b1 = std::min(height_px, b0 + tile_px);
  return {x0, height_px - b1, x1, height_px - b0};
}

std::array<int, 2> ShadingRateImage::tile_of(int x, int y) const {
  const int row = origin_bottom_left ? height_px - 1 - y : y;
  return {x / tile_px, row / tile_px};
}

double ShadingRateImage::fraction(ShadingRate rate) const {
  double n = 0.0;
  for (int ty = 0; ty < tiles_y; ++ty) {
    for (int tx = 0; tx < tiles_x; ++tx) {
      if (!(at(tx, ty) == rate)) continue;
      const auto r = tile_rect(tx, ty);
      n += double(r[2] - r[0]) * (r[3] - r[1]);
    }
  }
  return n / (double(width_px) * height_px);
}

double ShadingRateImage::shaded_samples() const {
  double n = 0.0;
  for (int ty = 0; ty < tiles_y; ++ty) {
    for (int tx = 0; tx < tiles_x; ++tx) {
      const ShadingRate s = at(tx, ty);
      const auto r = tile_rect(tx, ty);
      // A fragment partly outside the screen is still shaded once.
      n +=
          double((r[2] - r[0] + s.width - 1) / s.width) * ((r[3] - r[1] + s.height - 1) / s.height);
    }
  }
  return n;
}

double ShadingRateImage::pixel_ratio() const {
  return shaded_samples() / (double(width_px) * height_px);
}

std::vector<std::uint8_t> ShadingRateImage::encode(RateApi api) const {
  std::vector<std::uint8_t> out;
  out.reserve(rates.size());
  for (ShadingRate r : rates) out.push_back(encode_shading_rate(r, api));
  return out;
}

namespace {
// Through the lens: the largest sample spacing along x and along y, in buffer
// pixels, that is still no coarser than the panel's pixels anywhere in the
// tile [x0, x1] x [y0, y1]. At a point whose direction from the lens axis makes
// angle phi with x, a spacing k along x spans k sqrt(cos^2 / m_r^2 + sin^2 /
// m_t^2) panel pixels (m_r, m_t: buffer pixels per panel pixel radially and
// tangentially), so k may be 1 / sqrt(...). Bounded over the tile by the
// least m_r and m_t at any view angle of the tile (from the table) and the
// largest |cos phi| and |sin phi| of its points.
std::array<double, 2> panel_spacing(const Display& d, const OversamplingTable& table, double x0,
                                    double y0, double x1, double y1) {
  const Vec2d p = d.principal_point();
  const Oversampling m = table.least_beyond(min_eccentricity(d, p, x0, y0, x1, y1));
  const double ax0 = x0 - p.x, ax1 = x1 - p.x, ay0 = y0 - p.y, ay1 = y1 - p.y;
  const double big_x = std::max(std::abs(ax0), std::abs(ax1));
  const double big_y = std::max(std::abs(ay0), std::abs(ay1));
  const double small_x = (ax0 <= 0.0 && ax1 >= 0.0) ? 0.0 : std::min(std::abs(ax0), std::abs(ax1));
  const double small_y = (ay0 <= 0.0 && ay1 >= 0.0) ? 0.0 : std::min(std::abs(ay0), std::abs(ay1));
  auto most = [](double a, double b) {  // the largest a / hypot(a, b): 1 where both are 0
    const double h = std::hypot(a, b);
    return h > 0.0 ? a / h : 1.0;
  };
  const double cos_max = most(big_x, small_y), sin_max = most(big_y, small_x);
  auto spacing = [&](double c, double s) {
    return 1.0 / std::sqrt(c * c / (m.radial * m.radial) + s * s / (m.tangential * m.tangential));
  };
  return {spacing(cos_max, sin_max), spacing(sin_max, cos_max)};
}

using detail::TileBounds;

TileBounds tile_bounds(const Display& display, const std::array<int, 4>& rect,
                       const OversamplingTable* lens) {
  const double x0 = rect[0], y0 = rect[1], x1 = rect[2], y1 = rect[3];
  const double f = display.eye_distance_px();
  const Vec2d c = display.principal_point();
  TileBounds b;
  b.ax = max_step_angle(x0 - c.x, x1 - c.x, y0 - c.y, y1 - c.y, f);
  b.ay = max_step_angle(y0 - c.y, y1 - c.y, x0 - c.x, x1 - c.x, f);
  if (lens) {
    const auto [px, py] = panel_spacing(display, *lens, x0, y0, x1, y1);
    b.px = px;
    b.py = py;
  }
  return b;
}

// The coarsest supported rate for a tile whose point nearest the gaze is at
// `e` degrees (latency travel and fovea scale applied).
ShadingRate rate_within(const TileBounds& b, double e, const AcuityModel& acuity,
                        const std::vector<ShadingRate>& supported) {
  const double half_cycle = 0.5 * acuity.mar_deg(e) * kRad;
  // The largest allowed spacings; through a lens no finer than the panel
  // shows there (lens.hpp): two samples per cycle the eye resolves or the
  // panel shows, whichever is coarser.
  const double kx = std::max(half_cycle / b.ax, b.px), ky = std::max(half_cycle / b.ay, b.py);
  ShadingRate best{1, 1};
  double best_headroom = std::min(kx, ky);
  for (ShadingRate r : supported) {
    if (r.width > kx || r.height > ky) continue;
    const double headroom = std::min(kx / r.width, ky / r.height);
    if (r.pixels() > best.pixels() || (r.pixels() == best.pixels() && headroom > best_headroom)) {
      best = r;
      best_headroom = headroom;
    }
  }
  return best;
}

// Eccentricity of the tile's point nearest the gaze, divided by the fovea
// scale, less the latency travel.
double tile_eccentricity(const Display& display, Vec2d gaze, const std::array<int, 4>& rect,
                         double latency_travel_deg, double fovea_scale) {
  return std::max(
      0.0, min_eccentricity(display, gaze, rect[0], rect[1], rect[2], rect[3]) / fovea_scale -
               latency_travel_deg);
}

}  // namespace

ShadingRate tile_shading_rate(const Display& display, const AcuityModel& acuity, Vec2d gaze,
                              const std::array<int, 4>& rect, const ShadingRateOptions& options) {
  const auto table = display.lens_oversampling_table();
  return rate_within(
      tile_bounds(display, rect, table ? &*table : nullptr),
      tile_eccentricity(display, gaze, rect, options.latency_travel_deg, options.fovea_scale),
      acuity, options.supported);
}

ShadingRatePlanner::ShadingRatePlanner(const Display& display, const AcuityModel& acuity,
                                       const ShadingRateOptions& options)
    : display_(display), acuity_(acuity), options_(options) {
  display.validate();
  options.validate();
  if (!(acuity.slope > 0.0) || !std::isfinite(acuity.slope) || !(acuity.w0_deg > 0.0)) {
    throw Error("acuity: slope and w0 must be positive");
  }
  blank_.width_px = display.width_px;
  blank_.height_px = display.height_px;
  blank_.tile_px = options.tile_px;
  blank_.origin_bottom_left = options.origin_bottom_left;
  blank_.tiles_x = (display.width_px + options.tile_px - 1) / options.tile_px;
  blank_.tiles_y = (display.height_px + options.tile_px - 1) / options.tile_px;
  const auto table = display.lens_oversampling_table();
  for (int ty = 0; ty < blank_.tiles_y; ++ty) {
    for (int tx = 0; tx < blank_.tiles_x; ++tx) {
      const std::array<int, 4> rect = blank_.tile_rect(tx, ty);
      tiles_.push_back({rect, tile_bounds(display, rect, table ? &*table : nullptr)});
    }
  }
}

ShadingRateImage ShadingRatePlanner::image(Vec2d gaze, double latency_travel_deg,
                                           double fovea_scale) const {
  if (!std::isfinite(gaze.x) || !std::isfinite(gaze.y)) throw Error("gaze: must be finite");
  ShadingRateOptions o = options_;
  o.latency_travel_deg = latency_travel_deg;
  o.fovea_scale = fovea_scale;
  o.validate();
  ShadingRateImage img = blank_;
  img.rates.reserve(tiles_.size());
  for (const Tile& t : tiles_) {
    img.rates.push_back(rate_within(
        t.bounds, tile_eccentricity(display_, gaze, t.rect, latency_travel_deg, fovea_scale),
        acuity_, options_.supported));
  }
  return img;
}

ShadingRateImage shading_rate_image(const Display& display, const AcuityModel& acuity, Vec2d gaze,
                                    const ShadingRateOptions& options) {
  return ShadingRatePlanner(display, acuity, options)
      .image(gaze, options.latency_travel_deg, options.fovea_scale);
}

}  // namespace foveate
