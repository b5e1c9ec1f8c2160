// The acuity-aware comparison: both images low-passed at every pixel to the
// finest detail the eye resolves at that pixel's eccentricity, w(e) = m e + w0
// degrees per cycle (Guenter et al. 2012, eq. 1), then compared.
//
// The spatially varying Gaussian is built from a pyramid of Gaussian blurs in
// half-octave steps of sigma. Level k (k >= 1) has sigma_k = 0.5 sqrt(2)^(k-1)
// full-resolution pixels and is stored on a grid of step d_k, the largest power
// of two not above sigma_k (so the level is sampled with at most ~1.7 %
// aliasing). Reading a coarse level back with bilinear interpolation adds on
// average d^2 / 6 of variance, which is subtracted from what the level itself
// gets. Each level is made from the previous one with the missing variance (a
// cascade: variances of Gaussians add), decimating by two when the grid step
// doubles. A pixel whose sigma lies between sigma_k and sigma_k+1 blends the two
// levels with weights chosen so that the blended variance equals sigma^2.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "foveate/core/error.hpp"
#include "internal.hpp"

namespace foveate::metrics {

namespace {

constexpr double kSigma1 = 0.5;  // sigma of level 1; level 0 is the image itself
constexpr int kMaxLevels = 48;

double level_sigma(int k) {
  static const std::array<double, kMaxLevels + 2> table = [] {
    std::array<double, kMaxLevels + 2> t{};
    for (int i = 1; i < kMaxLevels + 2; ++i) t[i] = kSigma1 * std::pow(std::sqrt(2.0), i - 1);
    return t;
  }();
  return table[k];
}

int level_step(int k) {
  const double s = level_sigma(k);
  int d = 1;
  while (2.0 * d <= s + 1e-9) d *= 2;
  return d;
}

double level_stored_variance(int k) {
  const double s = level_sigma(k);
  const int d = level_step(k);
  return s * s - (d > 1 ? d * d / 6.0 : 0.0);
}

void check_display(const Display& display, int width, int height, const char* what) {
  if (display.width_px != width || display.height_px != height) {
    throw Error(std::string(what) + ": display '" + display.name + "' is " +
                std::to_string(display.width_px) + "x" + std::to_string(display.height_px) +
                " but the images are " + std::to_string(width) + "x" + std::to_string(height) +
                " (use Display::resized)");
  }
}

// For every pixel: the lower bracketing level and the weight of the upper one.
struct LevelChoice {
  std::vector<std::uint8_t> lo;
  std::vector<float> t;
  int top = 0;  // highest level any pixel needs
};

LevelChoice choose_levels(const Map& sigma) {
  LevelChoice c;
  const size_t n = sigma.values.size();
  c.lo.resize(n);
  c.t.resize(n);
  const int max_side = std::max(sigma.width, sigma.height);
  int top = 0;
  float smax = 0.0f;
  for (float s : sigma.values) smax = std::max(smax, s);
  while (top < kMaxLevels && level_sigma(top) < smax && level_step(top + 1) <= max_side) ++top;
  c.top = top;
  const double top_sigma = level_sigma(top);
  for (size_t i = 0; i < n; ++i) {
    const double s = sigma.values[i];
    if (s >= top_sigma) {
      c.lo[i] = static_cast<std::uint8_t>(top);
      c.t[i] = 0.0f;
      continue;
    }
    int k = 0;
    if (s >= kSigma1) {
      // floor(2 log2(s / sigma_1)) = floor(log2((s / sigma_1)^2)), the binary exponent.
      k = 1 + std::ilogb((s / kSigma1) * (s / kSigma1));
      k = std::clamp(k, 1, top - 1);
      // Guard against rounding in log2 at exact level sigmas.
      while (k > 1 && level_sigma(k) > s) --k;
      while (k + 1 < top && level_sigma(k + 1) <= s) ++k;
    }
    const double a = level_sigma(k), b = level_sigma(k + 1);
    c.lo[i] = static_cast<std::uint8_t>(k);
    c.t[i] = static_cast<float>((s * s - a * a) / (b * b - a * a));
  }
  return c;
}

// Bilinear read-back of a level stored on a grid of step `step`: level sample j
// sits at full-resolution coordinate (j + 0.5) * step.
struct ReadBack {
  std::vector<int> x0, y0;
  std::vector<float> fx, fy;
};

void taps(int step, int n, int size, std::vector<int>& i0, std::vector<float>& f) {
  i0.resize(n);
  f.resize(n);
  for (int x = 0; x < n; ++x) {
    const double u = (x + 0.5) / step - 0.5;
    const double fu = std::floor(u);
    int a = static_cast<int>(fu);
    double fr = u - fu;
    if (a < 0) a = 0, fr = 0.0;
    if (a >= size - 1) a = size - 1, fr = 0.0;
    i0[x] = a;
    f[x] = static_cast<float>(fr);
  }
}

// Filters several linear-luminance maps with the same per-pixel sigma.
std::vector<Map> filter_varying(const std::vector<const Map*>& inputs, const Map& sigma) {
  const LevelChoice c = choose_levels(sigma);
  const int w = sigma.width, h = sigma.height;
  std::vector<int> steps(c.top + 1, 1);
  for (int k = 1; k <= c.top; ++k) steps[k] = level_step(k);
  std::vector<Map> outs;
  for (const Map* in : inputs) {
    // The whole pyramid (levels above 0); level 0 is the input.
    std::vector<Map> levels(c.top + 1);
    std::vector<ReadBack> rb(c.top + 1);
    const Map* cur = in;
    double var = 0.0;
    int step = 1;
    for (int k = 1; k <= c.top; ++k) {
      const double target = level_stored_variance(k);
      const double sigma_grid = std::sqrt(std::max(0.0, target - var)) / step;
      const detail::Kernel kern = detail::gaussian_kernel(sigma_grid, steps[k] > step);
      levels[k] = detail::filter2d(*cur, kern, kern);
      cur = &levels[k];
      var = target;
      step = steps[k];
      if (step > 1) {
        taps(step, w, levels[k].width, rb[k].x0, rb[k].fx);
        taps(step, h, levels[k].height, rb[k].y0, rb[k].fy);
      }
    }
    auto sample = [&](int k, int x, int y) -> float {
      const Map& m = k == 0 ? *in : levels[k];
      if (steps[k] == 1) return m.values[static_cast<size_t>(y) * w + x];
      const ReadBack& r = rb[k];
      const int lw = m.width;
      const float* r0 = &m.values[static_cast<size_t>(r.y0[y]) * lw];
      const float* r1 = r.y0[y] + 1 < m.height ? r0 + lw : r0;
      const int a = r.x0[x];
      const int a1 = a + 1 < lw ? a + 1 : a;
      const float fx = r.fx[x];
      const float t0 = r0[a] + fx * (r0[a1] - r0[a]);
      const float t1 = r1[a] + fx * (r1[a1] - r1[a]);
      return t0 + r.fy[y] * (t1 - t0);
    };
    Map out(w, h);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const size_t i = static_cast<size_t>(y) * w + x;
        const int lo = c.lo[i];
        const float t = c.t[i];
        float v = sample(lo, x, y);
        if (t != 0.0f) v += t * (sample(lo + 1, x, y) - v);
        out.values[i] = v;
      }
    }
    outs.push_back(std::move(out));
  }
  return outs;
}

}  // namespace

Map eccentricity_map(const Display& display, Vec2d gaze) {
  Map m(display.width_px, display.height_px);
  for (int y = 0; y < m.height; ++y) {
    for (int x = 0; x < m.width; ++x) {
      m.at(x, y) = static_cast<float>(display.eccentricity_deg({x + 0.5, y + 0.5}, gaze));
    }
  }
  return m;
}

Map acuity_sigma_map(const Display& display, Vec2d gaze, const AcuityModel& acuity) {
  return detail::acuity_sigma_from_eccentricity(eccentricity_map(display, gaze), display, gaze,
                                                acuity);
}

Map detail::acuity_sigma_from_eccentricity(const Map& ecc, const Display& display, Vec2d gaze,
                                           const AcuityModel& acuity) {
  // Pixels per degree changes slowly across the screen: evaluate it exactly on
  // a 16-pixel grid and interpolate bilinearly.
  constexpr int kStep = 16;
  const int w = display.width_px, h = display.height_px;
  const int nx = (w - 1) / kStep + 2, ny = (h - 1) / kStep + 2;
  std::vector<double> ppd(static_cast<size_t>(nx) * ny);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      ppd[static_cast<size_t>(j) * nx + i] =
          display.pixels_per_degree({i * kStep + 0.5, j * kStep + 0.5}, gaze);
    }
  }
  Map out(w, h);
  for (int y = 0; y < h; ++y) {
    const int j = y / kStep;
    const double fy = double(y % kStep) / kStep;
    for (int x = 0; x < w; ++x) {
      const int i = x / kStep;
      const double fx = double(x % kStep) / kStep;
      const double* p0 = &ppd[static_cast<size_t>(j) * nx + i];
      const double* p1 = p0 + nx;
      const double top = p0[0] + fx * (p0[1] - p0[0]);
      const double bot = p1[0] + fx * (p1[1] - p1[0]);
      const double px_per_deg = top + fy * (bot - top);
      const double period_px = acuity.mar_deg(double(ecc.at(x, y))) * px_per_deg;
      out.at(x, y) = static_cast<float>(period_px / std::numbers::pi);
    }
  }
  return out;
}

Map acuity_filtered(const Image& image, const Display& display, Vec2d gaze,
                    const AcuityModel& acuity) {
  if (image.empty()) throw Error("acuity_filtered: the image is empty");
  check_display(display, image.width, image.height, "acuity_filtered");
  const Map lin = detail::luminance_linear(image);
  const Map sigma = acuity_sigma_map(display, gaze, acuity);
  Map out = std::move(filter_varying({&lin}, sigma)[0]);
  for (float& v : out.values) v = detail::luminance_to_code(v);
  return out;
}

Map acuity_difference(const Image& reference, const Image& test, const Display& display, Vec2d gaze,
                      const AcuityModel& acuity) {
  detail::check_same_size(reference, test, "acuity_difference");
  check_display(display, reference.width, reference.height, "acuity_difference");
  return detail::acuity_difference_with_sigma(reference, test,
                                              acuity_sigma_map(display, gaze, acuity));
}

Map detail::acuity_difference_with_sigma(const Image& reference, const Image& test,
                                         const Map& sigma) {
  const Map a = detail::luminance_linear(reference);
  const Map b = detail::luminance_linear(test);
  std::vector<Map> f = filter_varying({&a, &b}, sigma);
  Map out(reference.width, reference.height);
  for (size_t i = 0; i < out.values.size(); ++i) {
    out.values[i] =
        detail::luminance_to_code(f[0].values[i]) - detail::luminance_to_code(f[1].values[i]);
  }
  return out;
}

}  // namespace foveate::metrics
