#include "foveate/core/models.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "foveate/core/error.hpp"
#include "foveate/core/parse.hpp"

namespace foveate {

namespace {
constexpr double kRad = std::numbers::pi / 180.0;
constexpr double kDeg = 180.0 / std::numbers::pi;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

void require(bool ok, const std::string& what) {
  if (!ok) throw Error(what);
}
}  // namespace

// ---------------------------------------------------------------- Swafford et al.

void LatencyAwareFovea::validate() const {
  require(std::isfinite(latency_ms) && latency_ms >= 0.0 && latency_ms <= 1000.0,
          "latency_ms: expected 0..1000 ms, got " + format_number(latency_ms));
  require(std::isfinite(max_saccade_deg_per_s) && max_saccade_deg_per_s >= 0.0 &&
              max_saccade_deg_per_s <= 1000.0,
          "max_saccade_deg_per_s: expected 0..1000, got " + format_number(max_saccade_deg_per_s));
  require(std::isfinite(fovea_deg) && fovea_deg > 0.0 && fovea_deg < 179.0,
          "fovea_deg: expected (0, 179), got " + format_number(fovea_deg));
  require(std::isfinite(blend_border_px) && blend_border_px >= 0.0,
          "blend_border_px: must be >= 0, got " + format_number(blend_border_px));
  require(std::isfinite(error_px), "error_px: must be finite");
}

double LatencyAwareFovea::diameter_px(const Display& display) const {
  validate();
  // L_tot * S_max in degrees: ms * (deg/s) / 1000. The half-angle cannot reach 90 degrees.
  const double half = std::min(latency_ms * max_saccade_deg_per_s / 1000.0 + 0.5 * fovea_deg, 89.0);
  return 2.0 * display.eye_distance_px() * std::tan(half * kRad) + 2.0 * blend_border_px + error_px;
}

double LatencyAwareFovea::diameter_deg(const Display& display) const {
  return 2.0 * std::atan(0.5 * diameter_px(display) / display.eye_distance_px()) * kDeg;
}

// ---------------------------------------------------------------- Meng et al.

void KernelLogPolar::validate() const {
  require(std::isfinite(screen_w) && screen_w >= 1.0 && std::isfinite(screen_h) && screen_h >= 1.0,
          "logpolar: screen size must be >= 1 pixel");
  require(std::isfinite(sigma) && sigma >= 1.0 && sigma <= 16.0,
          "sigma: expected 1..16, got " + format_number(sigma));
  require(std::isfinite(alpha) && alpha >= 0.1 && alpha <= 16.0,
          "alpha: expected 0.1..16, got " + format_number(alpha));
}

double KernelLogPolar::log_extent() const { return std::log(std::hypot(screen_w, screen_h)); }

Vec2d KernelLogPolar::to_buffer(Vec2d p, Vec2d gaze) const {
  const double x = p.x - gaze.x, y = p.y - gaze.y;
  // Inside one pixel of the gaze the logarithm is clamped (log r >= 0).
  const double r = std::max(std::hypot(x, y), 1.0);
  const double t = std::clamp(std::log(r) / log_extent(), 0.0, 1.0);
  double angle = std::atan2(y, x);
  if (angle < 0.0) angle += kTwoPi;
  return {std::pow(t, 1.0 / alpha) * buffer_w(), angle / kTwoPi * buffer_h()};
}

Vec2d KernelLogPolar::to_screen(Vec2d b, Vec2d gaze) const {
  const double r = std::exp(log_extent() * std::pow(std::max(b.x / buffer_w(), 0.0), alpha));
  const double angle = b.y * kTwoPi / buffer_h();
  return {gaze.x + r * std::cos(angle), gaze.y + r * std::sin(angle)};
}

namespace {
// Distance from `g` (inside `keep`) to the border of `keep` along angle `a`.
double exit_distance(Vec2d g, const std::array<double, 4>& keep, double a) {
  const double dx = std::cos(a), dy = std::sin(a);
  double t = std::numeric_limits<double>::infinity();
  if (dx > 1e-12) t = std::min(t, (keep[2] - g.x) / dx);
  if (dx < -1e-12) t = std::min(t, (keep[0] - g.x) / dx);
  if (dy > 1e-12) t = std::min(t, (keep[3] - g.y) / dy);
  if (dy < -1e-12) t = std::min(t, (keep[1] - g.y) / dy);
  return std::max(t, 0.0);
}
}  // namespace

std::vector<std::array<int, 4>> log_polar_cover(Vec2d gaze, double L, double alpha, int w, int h,
                                                double inner, const std::array<double, 4>& keep,
                                                int band) {
  require(w >= 1 && h >= 1 && band >= 1, "log_polar_cover: empty buffer or band");
  require(std::isfinite(L) && L > 0.0 && std::isfinite(alpha) && alpha > 0.0,
          "log_polar_cover: L and alpha must be positive");
  // Column (texel units) at which the mapping reaches radius r: u = w (log r / L)^(1/alpha).
  const auto column = [&](double r) {
    return r <= 1.0 ? 0.0 : std::pow(std::log(r) / L, 1.0 / alpha) * w;
  };
  // A texel c has u in [c, c + 1] whatever its jitter: it can reach `inner`
  // only if c + 1 >= column(inner).
  const int first =
      std::max(0, static_cast<int>(std::floor(std::min(column(inner), double(w)))) - 1);
  // The exit distance along an angle is least at a side's normal and grows
  // towards the corners: over an interval of angles it is largest at the
  // interval's ends or at a corner's direction inside it.
  std::array<double, 4> corners{};
  for (int k = 0; k < 4; ++k) {
    const double cx = keep[k == 0 || k == 3 ? 0 : 2], cy = keep[k < 2 ? 1 : 3];
    corners[static_cast<size_t>(k)] = std::atan2(cy - gaze.y, cx - gaze.x);
  }
  const bool inside =
      gaze.x >= keep[0] && gaze.x <= keep[2] && gaze.y >= keep[1] && gaze.y <= keep[3];
  std::vector<std::array<int, 4>> out;
  for (int y0 = 0; y0 < h; y0 += band) {
    const int y1 = std::min(h, y0 + band);
    // Rows y0..y1-1 have v in [y0, y1] (centre +- half a texel of jitter).
    const double a0 = y0 * kTwoPi / h, a1 = y1 * kTwoPi / h;
    double reach = std::max(exit_distance(gaze, keep, a0), exit_distance(gaze, keep, a1));
    for (double c : corners) {
      for (int turn = -1; turn <= 2; ++turn) {
        const double a = c + turn * kTwoPi;
        if (a > a0 && a < a1) reach = std::max(reach, exit_distance(gaze, keep, a));
      }
    }
    if (!inside) reach = std::numeric_limits<double>::infinity();  // no shortcut off the rectangle
    if (reach < inner) continue;
    const double u = std::isfinite(reach) ? column(reach) : double(w);
    const int last = std::min(w, static_cast<int>(std::floor(std::min(u, double(w)))) + 2);
    if (last > first) out.push_back({first, y0, last, y1});
  }
  return out;
}

// ---------------------------------------------------------------- Silvera

double checkerboard_sampling_factor(int region) {
  if (region < 0 || region > 3) throw Error("checkerboard region must be 0..3");
  return std::sqrt(4.0 / (4.0 - region));
}

double checkerboard_gap_px(int region, int block) {
  if (region < 0 || region > 3) throw Error("checkerboard region must be 0..3");
  if (block < 1) throw Error("checkerboard block must be >= 1");
  if (region == 0) return 1.0;
  // A hole of n pixels between kept pixels: their centres are n + 1 apart.
  // In region 3 only the top-left quad of each 2n tile is kept: the centre of
  // the dropped bottom-right quad is (n + 1) / sqrt 2 from the nearest kept
  // centres, the corners of four kept quads.
  const double n = block;
  return region < 3 ? n + 1.0 : (n + 1.0) * std::sqrt(2.0);
}

double mar_px_at(const Display& display, const AcuityModel& acuity, double e) {
  return acuity.mar_deg(e) * kRad * display.eye_distance_px() / std::cos(e * kRad);
}

void CheckerboardPattern::validate() const {
  require(block >= 1 && block <= 256, "block: expected 1..256, got " + std::to_string(block));
  for (int k = 0; k < 3; ++k) {
    require(std::isfinite(thresholds_px[k]) && thresholds_px[k] >= 0.0,
            "thresholds: must be finite and >= 0");
    if (k > 0 && thresholds_px[k] < thresholds_px[k - 1]) {
      // The three rings nest: the values say which one is out of order.
      require(false, "thresholds (r1, r2, r3): must not decrease, got " +
                         format_number(thresholds_px[0]) + ", " + format_number(thresholds_px[1]) +
                         ", " + format_number(thresholds_px[2]) + " px (r" + std::to_string(k + 1) +
                         " = " + format_number(thresholds_px[k]) + " is below r" +
                         std::to_string(k) + " = " + format_number(thresholds_px[k - 1]) + ")");
    }
  }
}

CheckerboardPattern CheckerboardPattern::from_fractions(int block, int width, int height,
                                                        std::array<double, 3> f) {
  CheckerboardPattern p;
  p.block = block;
  const double diag = std::hypot(width, height);
  for (int k = 0; k < 3; ++k) p.thresholds_px[k] = f[k] * diag;
  p.validate();
  return p;
}

CheckerboardPattern CheckerboardPattern::from_acuity(int block, const Display& display,
                                                     const AcuityModel& acuity) {
  CheckerboardPattern p;
  p.block = block;
  require(block >= 1 && block <= 256, "block: expected 1..256, got " + std::to_string(block));
  for (int k = 0; k < 3; ++k) {
    // Two samples per MAR cycle across the region's largest gap: the first
    // eccentricity where w(e) * ppd(e) >= 2 gap (increasing in e; bisection).
    const double need = 2.0 * checkerboard_gap_px(k + 1, block);
    double lo = 0.0, hi = 89.0;
    if (mar_px_at(display, acuity, lo) >= need) {
      hi = lo;
    } else {
      for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (mar_px_at(display, acuity, mid) >= need ? hi : lo) = mid;
      }
    }
    p.thresholds_px[k] = display.radius_px_at(hi);
  }
  p.validate();
  return p;
}

double CheckerboardPattern::tile_distance(Vec2d pixel, Vec2d gaze) const {
  const double s = 2.0 * block;
  const double tx = std::floor(pixel.x / s) * s, ty = std::floor(pixel.y / s) * s;
  return std::hypot(gaze.x - std::clamp(gaze.x, tx, tx + s),
                    gaze.y - std::clamp(gaze.y, ty, ty + s));
}

int CheckerboardPattern::region(Vec2d pixel, Vec2d gaze) const {
  const double d = tile_distance(pixel, gaze);
  int r = 0;
  while (r < 3 && d > thresholds_px[r]) ++r;
  return r;
}

int CheckerboardPattern::quad(Vec2d pixel) const {
  const double s = 2.0 * block;
  const double xm = pixel.x - std::floor(pixel.x / s) * s;
  const double ym = pixel.y - std::floor(pixel.y / s) * s;
  const int qx = xm >= block ? 1 : 0, qy = ym >= block ? 1 : 0;
  return qx * 2 + qy;
}

bool CheckerboardPattern::kept(Vec2d pixel, Vec2d gaze) const {
  return quad(pixel) > region(pixel, gaze) || quad(pixel) == 0;
}

std::array<double, 4> CheckerboardPattern::kept_by_region(int width, int height, Vec2d gaze) const {
  std::array<double, 4> out{};
  const int n = block, s = 2 * block;
  if (width <= 0 || height <= 0 || n <= 0) return out;
  // The pixels tile (tx, ty) keeps in region r: quads 0 and r+1..3, each
  // clipped to the screen.
  const auto kept_in = [&](int tx, int ty, int r) {
    double sum = 0;
    for (int q = 0; q < 4; ++q) {
      if (q != 0 && q <= r) continue;  // region r drops quads 1..r
      const int x0 = tx + (q >= 2 ? n : 0), y0 = ty + (q & 1 ? n : 0);
      sum += double(std::clamp(width - x0, 0, n)) * std::clamp(height - y0, 0, n);
    }
    return sum;
  };
  // Rows are counted in runs where the thresholds nest (validate()) and the
  // gaze is a point; otherwise tile by tile.
  const bool runs = thresholds_px[0] <= thresholds_px[1] && thresholds_px[1] <= thresholds_px[2] &&
                    std::isfinite(gaze.x) && std::isfinite(gaze.y);
  const int cols = (width + s - 1) / s;
  for (int ty = 0; ty < height; ty += s) {
    const auto region_at = [&](int i) { return region({i * s + 0.5, ty + 0.5}, gaze); };
    if (!runs) {
      for (int i = 0; i < cols; ++i) {
        const int r = region_at(i);
        out[size_t(r)] += kept_in(i * s, ty, r);
      }
      continue;
    }
    // Along a row the tiles' distance to the gaze falls to the tile under
    // it (or the nearest one) and rises after: the tiles within each
    // threshold are one run around it, found by bisection with the same
    // distance as region(), so every tile counts where region() puts it.
    const int c = int(std::clamp(std::floor(gaze.x / s), 0.0, double(cols - 1)));
    std::array<int, 3> within{};
    for (size_t k = 0; k < 3; ++k) {
      const auto near = [&](int i) {
        return tile_distance({i * s + 0.5, ty + 0.5}, gaze) <= thresholds_px[k];
      };
      if (!near(c)) continue;
      int lo = 0, hi = c;  // the first near tile in [0, c]
      while (lo < hi) {
        const int mid = (lo + hi) / 2;
        if (near(mid))
          hi = mid;
        else
          lo = mid + 1;
      }
      const int first = lo;
      lo = c, hi = cols - 1;  // the last near tile in [c, cols - 1]
      while (lo < hi) {
        const int mid = (lo + hi + 1) / 2;
        if (near(mid))
          lo = mid;
        else
          hi = mid - 1;
      }
      within[k] = lo - first + 1;
    }
    const std::array<int, 4> tiles = {within[0], within[1] - within[0], within[2] - within[1],
                                      cols - within[2]};
    for (int r = 0; r < 4; ++r) out[size_t(r)] += tiles[size_t(r)] * kept_in(0, ty, r);
    // A last column cut by the screen's edge keeps less than a whole tile.
    if (width % s != 0) {
      const int r = region_at(cols - 1);
      out[size_t(r)] += kept_in((cols - 1) * s, ty, r) - kept_in(0, ty, r);
    }
  }
  return out;
}

}  // namespace foveate
