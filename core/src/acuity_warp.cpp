#include "foveate/core/acuity_warp.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "foveate/core/error.hpp"

namespace foveate {

namespace {

constexpr double kRad = std::numbers::pi / 180.0;
constexpr double kDeg = 180.0 / std::numbers::pi;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
// The model eccentricity stays below this (tan grows without bound at 90).
constexpr double kMaxDeg = 89.0;

// The radial spacing (pixels) of a mapping with focal length F and acuity
// (m, w0) at model eccentricity E: half the MAR over E'(r) = cos^2 E / F.
double model_spacing_px(double focal, double slope, double w0, double e_deg) {
  const double c = std::cos(e_deg * kRad);
  return 0.5 * (slope * e_deg + w0) * focal / (kDeg * c * c);
}

// Screen points at which a gaze's sampling is checked: rays every 1/64 of a
// turn (their directions computed once), on the screen only.
constexpr int kRays = 64;
// Check rings grow by this factor out to past the farthest corner.
constexpr double kRingStep = 1.06;

const std::array<Vec2d, kRays>& ray_directions() {
  static const std::array<Vec2d, kRays> dirs = [] {
    std::array<Vec2d, kRays> d{};
    for (int i = 0; i < kRays; ++i) {
      const double th = kTwoPi * (i + 0.5) / kRays;
      d[static_cast<size_t>(i)] = {std::cos(th), std::sin(th)};
    }
    return d;
  }();
  return dirs;
}

double farthest_corner(const Display& d, Vec2d gaze) {
  double far = 0.0;
  for (double cx : {0.0, double(d.width_px)}) {
    for (double cy : {0.0, double(d.height_px)})
      far = std::max(far, std::hypot(cx - gaze.x, cy - gaze.y));
  }
  return far;
}

// `f(p, dir)` for the on-screen points of the ring of radius r.
template <class F>
void for_ring(const Display& d, Vec2d gaze, double r, F&& f) {
  const double W = d.width_px, H = d.height_px;
  for (const Vec2d& dir : ray_directions()) {
    const Vec2d p{gaze.x + r * dir.x, gaze.y + r * dir.y};
    if (p.x < 0.0 || p.x > W || p.y < 0.0 || p.y > H) continue;
    f(p, dir);
  }
}

// The radii of the rings from `from` (at least half a pixel) out to past the
// farthest corner.
std::vector<double> rings_from(double from, double far) {
  std::vector<double> out;
  for (double r = std::max(from, 0.5); r <= far * kRingStep; r *= kRingStep) out.push_back(r);
  return out;
}

Vec2d clamp_to_screen(const Display& d, Vec2d g) {
  return {std::clamp(g.x, 0.0, double(d.width_px)), std::clamp(g.y, 0.0, double(d.height_px))};
}

}  // namespace

double AcuityWarpMapping::eccentricity_deg(double r_px) const {
  return std::atan(std::max(r_px, 0.0) / focal_px) * kDeg;
}

double AcuityWarpMapping::radius_px(double e_deg) const {
  return focal_px * std::tan(std::clamp(e_deg, 0.0, kMaxDeg) * kRad);
}

double AcuityWarpMapping::column(double r_px) const {
  const double e = eccentricity_deg(r_px);
  return 2.0 / slope * std::log((slope * e + w0_deg) / (slope * start_deg + w0_deg));
}

double AcuityWarpMapping::radius_at_column(double u) const {
  const double e = ((slope * start_deg + w0_deg) * std::exp(0.5 * slope * u) - w0_deg) / slope;
  return radius_px(e);
}

double AcuityWarpMapping::radial_spacing_px(double r_px) const {
  return model_spacing_px(focal_px, slope, w0_deg, eccentricity_deg(r_px));
}

double AcuityWarpMapping::tangential_spacing_px(double r_px) const { return kTwoPi * r_px / rows; }

double mar_half_spacing_px(const Display& display, const AcuityModel& acuity, Vec2d pixel,
                           Vec2d dir, Vec2d gaze) {
  const double e = display.eccentricity_deg(pixel, gaze);
  // The angle between the rays half a pixel either side of the point.
  const double step = display.eccentricity_deg({pixel.x - 0.5 * dir.x, pixel.y - 0.5 * dir.y},
                                               {pixel.x + 0.5 * dir.x, pixel.y + 0.5 * dir.y});
  return 0.5 * acuity.mar_deg(e) / step;
}

double acuity_warp_start_deg(double focal_px, double slope, double w0_deg) {
  if (model_spacing_px(focal_px, slope, w0_deg, 0.0) >= 1.0) return 0.0;
  double lo = 0.0, hi = kMaxDeg;
  if (model_spacing_px(focal_px, slope, w0_deg, hi) < 1.0) return hi;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (model_spacing_px(focal_px, slope, w0_deg, mid) < 1.0 ? lo : hi) = mid;
  }
  return hi;
}

AcuityWarp::AcuityWarp(const Display& display, const AcuityModel& planned)
    : display_(display), acuity_(planned) {
  display_.validate();
  if (!(planned.slope > 0.0) || !(planned.w0_deg > 0.0)) {
    throw Error("acuity warp: the acuity's slope and foveal MAR must be positive");
  }
}

AcuityWarpMapping AcuityWarp::centred(int rows) const {
  AcuityWarpMapping m;
  m.gaze = display_.principal_point();
  m.focal_px = display_.eye_distance_px();
  m.slope = acuity_.slope;
  m.w0_deg = acuity_.w0_deg;
  m.kappa = 1.0;
  m.start_deg = acuity_warp_start_deg(m.focal_px, m.slope, m.w0_deg);
  m.rows = std::max(rows, 1);
  return m;
}

int AcuityWarp::rows_for(Vec2d gaze) const {
  gaze = clamp_to_screen(display_, gaze);
  // From where the closed form's native disc ends (a gaze elsewhere, whose
  // mapping is finer, has a wider one): the disc shows the pixels inside.
  const double f = display_.eye_distance_px();
  const double from = f * std::tan(acuity_warp_start_deg(f, acuity_.slope, acuity_.w0_deg) * kRad);
  double need = 4.0;
  for (double r : rings_from(from, farthest_corner(display_, gaze))) {
    for_ring(display_, gaze, r, [&](Vec2d p, Vec2d dir) {
      const double across = mar_half_spacing_px(display_, acuity_, p, {-dir.y, dir.x}, gaze);
      need = std::max(need, kTwoPi * r / across);
    });
  }
  // Whole bands of 4 rows (the cover's), rounded up.
  // (0.5 % over what the samples found: the largest need may lie between them.)
  return 4 * static_cast<int>(std::ceil(1.005 * need / 4.0));
}

AcuityWarpMapping AcuityWarp::mapping(Vec2d gaze) const {
  gaze = clamp_to_screen(display_, gaze);
  const int rows = rows_for(gaze);
  const Vec2d pp = display_.principal_point();
  const double f = display_.eye_distance_px();
  // Exact at the principal point (kappa 1 there, up to the rounding of the
  // checks): the closed form.
  if (std::hypot(gaze.x - pp.x, gaze.y - pp.y) < 0.5) {
    AcuityWarpMapping m = centred(rows);
    m.gaze = gaze;
    return m;
  }
  // Elsewhere the focal length whose mapping shades the fewest texels on
  // the screen, each made finer by its kappa: the largest (at most 1) for
  // which the radial spacing stays within half the MAR on every ring from
  // where its native disc ends. The allowed spacing does not depend on the
  // candidate, so each ring's tightest is found once (a ring at each
  // candidate's start, then rings growing by 6 % from the nearest start),
  // and a candidate costs one comparison per ring.
  constexpr std::array<double, 6> kScales{1.0, 1.1, 1.2, 1.35, 1.5, 1.7};
  std::array<double, kScales.size()> starts{};
  for (size_t i = 0; i < kScales.size(); ++i) {
    const double F = f * kScales[i];
    starts[i] = F * std::tan(acuity_warp_start_deg(F, acuity_.slope, acuity_.w0_deg) * kRad);
  }
  std::vector<double> radii =
      rings_from(*std::min_element(starts.begin(), starts.end()), farthest_corner(display_, gaze));
  radii.insert(radii.end(), starts.begin(), starts.end());
  struct Ring {
    double r, along;
  };
  std::vector<Ring> rings;
  rings.reserve(radii.size());
  for (double r : radii) {
    double along = std::numeric_limits<double>::infinity();
    for_ring(display_, gaze, r, [&](Vec2d p, Vec2d dir) {
      along = std::min(along, mar_half_spacing_px(display_, acuity_, p, dir, gaze));
    });
    if (std::isfinite(along)) rings.push_back({r, along});
  }
  AcuityWarpMapping best;
  double best_texels = 0.0;
  const std::array<double, 4> screen{0.0, 0.0, double(display_.width_px),
                                     double(display_.height_px)};
  for (size_t i = 0; i < kScales.size(); ++i) {
    AcuityWarpMapping m;
    m.gaze = gaze;
    m.focal_px = f * kScales[i];
    double kappa = 1.0;
    for (const Ring& ring : rings) {
      if (ring.r < starts[i]) continue;
      const double model = model_spacing_px(m.focal_px, acuity_.slope, acuity_.w0_deg,
                                            std::atan(ring.r / m.focal_px) * kDeg);
      kappa = std::min(kappa, ring.along / model);
    }
    m.kappa = std::max(kappa, 0.02);
    m.slope = acuity_.slope * m.kappa;
    m.w0_deg = acuity_.w0_deg * m.kappa;
    m.start_deg = acuity_warp_start_deg(m.focal_px, m.slope, m.w0_deg);
    m.rows = rows;
    const double texels = cover_texels(acuity_warp_cover(m, 1 << 20, 0.0, screen, 0));
    if (best_texels == 0.0 || texels < best_texels) best = m, best_texels = texels;
  }
  return best;
}

std::vector<std::array<int, 4>> acuity_warp_cover(const AcuityWarpMapping& m, int columns,
                                                  double inner, const std::array<double, 4>& keep,
                                                  int pad, int first, int last, int band) {
  std::vector<std::array<int, 4>> out;
  const int rows = std::max(m.rows, 1);
  band = std::max(band, 1);
  const int bands = (rows + band - 1) / band;
  const Vec2d g = m.gaze;
  const bool inside = g.x >= keep[0] && g.x <= keep[2] && g.y >= keep[1] && g.y <= keep[3];
  double far = 0.0;
  for (double cx : {keep[0], keep[2]}) {
    for (double cy : {keep[1], keep[3]}) far = std::max(far, std::hypot(cx - g.x, cy - g.y));
  }
  // The ray's length from the gaze to the rectangle's edge.
  const auto reach = [&](double th) {
    if (!inside) return far;
    const double c = std::cos(th), s = std::sin(th);
    double t = 1e30;
    if (c > 1e-12) t = std::min(t, (keep[2] - g.x) / c);
    if (c < -1e-12) t = std::min(t, (keep[0] - g.x) / c);
    if (s > 1e-12) t = std::min(t, (keep[3] - g.y) / s);
    if (s < -1e-12) t = std::min(t, (keep[1] - g.y) / s);
    return t;
  };
  // Corner directions, where the reach is largest between two angles.
  std::vector<double> corners;
  for (double cx : {keep[0], keep[2]}) {
    for (double cy : {keep[1], keep[3]}) {
      double a = std::atan2(cy - g.y, cx - g.x);
      if (a < 0.0) a += kTwoPi;
      corners.push_back(a);
    }
  }
  const int lo = std::max({0, first, static_cast<int>(std::floor(m.column(inner))) - pad});
  const int hi_limit = std::min(columns, last);
  std::vector<int> hi(static_cast<size_t>(bands), 0);
  for (int b = 0; b < bands; ++b) {
    const double a0 = kTwoPi * (b * band) / rows;
    const double a1 = kTwoPi * std::min(rows, (b + 1) * band) / rows;
    double r = std::max(reach(a0), reach(a1));
    for (double a : corners) {
      if (a >= a0 && a <= a1) r = std::max(r, reach(a));
    }
    hi[static_cast<size_t>(b)] = static_cast<int>(std::ceil(m.column(r))) + pad;
  }
  for (int b = 0; b < bands; ++b) {
    const auto at = [&](int k) { return hi[static_cast<size_t>((k + bands) % bands)]; };
    const int h = std::min(hi_limit, std::max({at(b - 1), at(b), at(b + 1)}));
    if (h > lo) out.push_back({lo, b * band, h, std::min(rows, (b + 1) * band)});
  }
  return out;
}

double cover_texels(const std::vector<std::array<int, 4>>& cover) {
  double n = 0.0;
  for (const auto& r : cover) n += double(r[2] - r[0]) * double(r[3] - r[1]);
  return n;
}

double ideal_mar_samples(const Display& display, const AcuityModel& acuity, Vec2d gaze, int step) {
  step = std::max(step, 1);
  double total = 0.0;
  for (int y = 0; y < display.height_px; y += step) {
    for (int x = 0; x < display.width_px; x += step) {
      const double w = std::min(step, display.width_px - x),
                   h = std::min(step, display.height_px - y);
      const Vec2d p{x + 0.5 * w, y + 0.5 * h};
      double dx = p.x - gaze.x, dy = p.y - gaze.y;
      const double len = std::hypot(dx, dy);
      if (len < 1e-9)
        dx = 1.0, dy = 0.0;
      else
        dx /= len, dy /= len;
      const double sr = std::max(1.0, mar_half_spacing_px(display, acuity, p, {dx, dy}, gaze));
      const double st = std::max(1.0, mar_half_spacing_px(display, acuity, p, {-dy, dx}, gaze));
      total += w * h / (sr * st);
    }
  }
  return total;
}

}  // namespace foveate
