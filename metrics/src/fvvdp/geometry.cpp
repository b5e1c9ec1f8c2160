#include "fvvdp/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace foveate::metrics::fvvdp {

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;
constexpr double kRad = std::numbers::pi / 180.0;

// Sample positions of a level of n samples over a frame of size full.
double sample_position(int i, int n, int full) {
  return n > 1 ? 0.5 + i * (full - 1.0) / (n - 1) : 0.5;
}

}  // namespace

ViewGeometry::ViewGeometry(const Display& display, int levels)
    : display_(display),
      eye_distance_px_(display.eye_distance_px()),
      principal_(display.principal_point()) {
  // One pixel at the principal point subtends 2 atan(1 / (2 D)).
  const double pix_deg = 2.0 * std::atan(0.5 / eye_distance_px_) * kDeg;
  ppd_ = 1.0 / pix_deg;
  const double delta = pix_deg / 2.0, tan_delta = std::tan(delta * kRad);
  int w = display.width_px, h = display.height_px;
  for (int l = 0; l < levels; ++l) {
    LevelGeometry g;
    g.width = w;
    g.height = h;
    for (int i = 0; i < w; ++i) {
      const double x = sample_position(i, w, display.width_px);
      g.column_px.push_back(x);
      g.column_deg.push_back(std::atan((x - principal_.x) / eye_distance_px_) * kDeg);
    }
    for (int j = 0; j < h; ++j) {
      const double y = sample_position(j, h, display.height_px);
      g.row_px.push_back(y);
      g.row_deg.push_back(std::atan((y - principal_.y) / eye_distance_px_) * kDeg);
    }
    // A flat image seen from its normal has more pixels per degree away from
    // the principal point: (tan(e + delta) - tan(e)) / tan(delta) at angle e
    // from it. Through a lens, the displayed pixel's angle says it.
    g.magnification.resize(static_cast<size_t>(w) * h);
    for (int j = 0; j < h; ++j) {
      for (int i = 0; i < w; ++i) {
        double m;
        if (display.lens) {
          const Vec2d p{sample_position(i, w, display.width_px),
                        sample_position(j, h, display.height_px)};
          m = pix_deg / display.displayed_pixel_angle_deg(p);
        } else {
          const double e = std::min(
              std::hypot(g.column_deg[static_cast<size_t>(i)], g.row_deg[static_cast<size_t>(j)]),
              89.9);
          m = (std::tan((e + delta) * kRad) - std::tan(e * kRad)) / tan_delta;
        }
        g.magnification[static_cast<size_t>(j) * w + i] = static_cast<float>(m);
      }
    }
    levels_.push_back(std::move(g));
    w = (w + 1) / 2;
    h = (h + 1) / 2;
  }
}

std::pair<double, double> ViewGeometry::gaze_deg(Vec2d gaze_px) const {
  return {std::atan((gaze_px.x - principal_.x) / eye_distance_px_) * kDeg,
          std::atan((gaze_px.y - principal_.y) / eye_distance_px_) * kDeg};
}

void ViewGeometry::eccentricity(int l, Vec2d gaze_px, std::vector<float>& out) const {
  const LevelGeometry& g = level(l);
  const auto [gx, gy] = gaze_deg(gaze_px);
  out.resize(static_cast<size_t>(g.width) * g.height);
  for (int j = 0; j < g.height; ++j) {
    const double dy = g.row_deg[static_cast<size_t>(j)] - gy;
    float* row = &out[static_cast<size_t>(j) * g.width];
    for (int i = 0; i < g.width; ++i) {
      const double dx = g.column_deg[static_cast<size_t>(i)] - gx;
      row[i] = static_cast<float>(std::sqrt(dx * dx + dy * dy));
    }
  }
}

void ViewGeometry::bands(int l, Vec2d gaze_px, const std::vector<double>& edges_deg,
                         std::vector<std::int8_t>& out, std::vector<double>& counts) const {
  const LevelGeometry& g = level(l);
  const double d = eye_distance_px_;
  const double gx = gaze_px.x - principal_.x, gy = gaze_px.y - principal_.y;
  const double g_norm = std::sqrt(gx * gx + gy * gy + d * d);
  // The angle exceeds an edge where its cosine is below the edge's cosine.
  std::vector<double> cos_edges;
  for (double e : edges_deg) cos_edges.push_back(std::cos(e * kRad));
  out.resize(static_cast<size_t>(g.width) * g.height);
  for (int j = 0; j < g.height; ++j) {
    const double py = g.row_px[static_cast<size_t>(j)] - principal_.y;
    for (int i = 0; i < g.width; ++i) {
      const double px = g.column_px[static_cast<size_t>(i)] - principal_.x;
      const double c =
          (px * gx + py * gy + d * d) / (std::sqrt(px * px + py * py + d * d) * g_norm);
      int band = -1;
      for (size_t e = 0; e < cos_edges.size() && c <= cos_edges[e]; ++e) band = static_cast<int>(e);
      out[static_cast<size_t>(j) * g.width + i] = static_cast<std::int8_t>(band);
      if (band >= 0) counts[static_cast<size_t>(band)] += 1.0;
    }
  }
}

}  // namespace foveate::metrics::fvvdp
