// The acuity-aware comparison: both images' linear luminance is split into
// half-octave frequency bands, every pixel keeps the bands the eye resolves at
// its eccentricity and drops the others, and the reconstructions are compared.
//
// The eye resolves at eccentricity e detail down to w(e) = m e + w0 degrees per
// cycle (Guenter et al. 2012, eq. 1, w in degrees per cycle as in the paper:
// w0 = 1/48 deg is 48 cycles per degree), so the cutoff at a pixel is
// f_c = 1 / (w(e) ppd) cycles per pixel, ppd the pixels per degree there.
//
// The ladder. Entry j (j >= 0) is the isotropic low-pass L_j with cutoff
// c_j = c_0 2^(-j/2), c_0 = 0.5 * 2^(-1/4) cycles per pixel: 1 up to
// c_j 2^(-1/4), 0 from c_j 2^(1/4), 0.5 - 0.5 sin(2 pi log2(f / c_j)) between
// (a raised cosine over half an octave). Entry -1 is the image itself. A pixel
// at ladder position lambda = 2 log2(c_0 / f_c) = m + s (m integer, s in
// [0, 1)) takes (1 - s) E_m + s E_(m+1). As bands D_j = E_j - E_(j+1) this is:
// weight 1 for the bands below the cutoff, 0 above it, 1 - s for the band D_m
// that straddles it. The response to frequency f is 1 below 0.595 f_c, >= 0.965
// at 0.7 f_c, <= 0.049 at 1.4 f_c and 0 from 1.68 f_c (acuity_response).
//
// The pyramid. Level n >= 1 is a grid of step 2^n pixels holding A_n = E_(2n+1)
// and B_n = E_(2n+2), whose low-passes end at 0.354 and 0.25 cycles per sample:
// level n's samples X_n come from level n-1 by a separable half-band filter and
// decimation (24 taps, Kaiser-windowed sinc: flat to 0.15 % up to 0.177 cycles
// per input sample, below 0.15 % from 0.323, so nothing aliases onto what A_n
// keeps), and A_n, B_n are the exact radial filters applied with an FFT over a
// mirror-padded domain. Level 0 (full resolution) holds E_0, E_1 and E_2, only
// around the gaze where some pixel needs them (lambda < 3). Reconstruction runs
// coarse to fine: R_N blends A_N and B_N; R_n blends A_n, B_n and
// C_n = up(R_(n+1)) (the half-band filter as an interpolator); R_0 blends the
// image, E_0, E_1, E_2 and C_0.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "fft.hpp"
#include "foveate/core/error.hpp"
#include "internal.hpp"

namespace foveate::metrics {

namespace detail {

namespace {

constexpr double kC0 = 0.42044820762685725;  // 0.5 * 2^(-1/4)
constexpr int kMargin = 16;      // FFT domain: mirror padding around a level, in samples
constexpr int kTileMargin = 24;  // level-0 tile: real neighbours kept around it, in pixels

std::vector<Map> lowpass_bank(const float* src, int stride, int w, int h,
                              const std::vector<double>& cutoffs) {
  const int pw = fft_size(w + 2 * kMargin), ph = fft_size(h + 2 * kMargin);
  std::vector<float> dom(static_cast<size_t>(pw) * ph);
  std::vector<int> mx(pw);
  for (int p = 0; p < pw; ++p) mx[p] = mirror(p - kMargin, w);
  for (int q = 0; q < ph; ++q) {
    const float* row = src + static_cast<size_t>(mirror(q - kMargin, h)) * stride;
    float* d = &dom[static_cast<size_t>(q) * pw];
    for (int p = 0; p < pw; ++p) d[p] = row[mx[p]];
  }
  const HalfSpectrum spectrum = rfft2(dom.data(), pw, ph);
  const int hw = spectrum.stride();
  // Radial frequency of every bin, in cycles per sample.
  std::vector<float> rho(static_cast<size_t>(hw) * ph);
  for (int ky = 0; ky < ph; ++ky) {
    const double fy = static_cast<double>(ky <= ph / 2 ? ky : ky - ph) / ph;
    for (int kx = 0; kx < hw; ++kx) {
      const double fx = static_cast<double>(kx) / pw;
      rho[static_cast<size_t>(ky) * hw + kx] = static_cast<float>(std::sqrt(fx * fx + fy * fy));
    }
  }
  const float scale = 1.0f / (static_cast<float>(pw) * static_cast<float>(ph));
  std::vector<Map> out;
  for (double c : cutoffs) {
    HalfSpectrum s = spectrum;
    const float pass = static_cast<float>(c * std::exp2(-0.25));
    const float stop = static_cast<float>(c * std::exp2(0.25));
    for (size_t i = 0; i < rho.size(); ++i) {
      const float r = rho[i];
      float g = scale;
      if (r >= stop) {
        g = 0.0f;
      } else if (r > pass) {
        g *= static_cast<float>(ladder_lowpass(r, c));
      }
      s.re[i] *= g;
      s.im[i] *= g;
    }
    irfft2(std::move(s), dom.data());
    Map m(w, h);
    for (int y = 0; y < h; ++y) {
      std::copy_n(&dom[static_cast<size_t>(y + kMargin) * pw + kMargin], w,
                  &m.values[static_cast<size_t>(y) * w]);
    }
    out.push_back(std::move(m));
  }
  return out;
}

// Pixels per degree on a 16-pixel grid, interpolated bilinearly (it changes
// slowly across the screen).
class PpdGrid {
 public:
  PpdGrid(const Display& d, Vec2d gaze) {
    nx_ = (d.width_px - 1) / kStep + 2;
    ny_ = (d.height_px - 1) / kStep + 2;
    v_.resize(static_cast<size_t>(nx_) * ny_);
    for (int j = 0; j < ny_; ++j) {
      for (int i = 0; i < nx_; ++i) {
        v_[static_cast<size_t>(j) * nx_ + i] =
            d.pixels_per_degree({i * kStep + 0.5, j * kStep + 0.5}, gaze);
      }
    }
  }
  // At image coordinates (u, v) (pixel centres at + 0.5).
  [[nodiscard]] double at(double u, double v) const {
    const double gx = std::clamp((u - 0.5) / kStep, 0.0, nx_ - 1.0);
    const double gy = std::clamp((v - 0.5) / kStep, 0.0, ny_ - 1.0);
    const int i = std::min(static_cast<int>(gx), nx_ - 2);
    const int j = std::min(static_cast<int>(gy), ny_ - 2);
    const double fx = gx - i, fy = gy - j;
    const double* p0 = &v_[static_cast<size_t>(j) * nx_ + i];
    const double* p1 = p0 + nx_;
    const double top = p0[0] + fx * (p0[1] - p0[0]);
    const double bot = p1[0] + fx * (p1[1] - p1[0]);
    return top + fy * (bot - top);
  }

 private:
  static constexpr int kStep = 16;
  int nx_ = 0, ny_ = 0;
  std::vector<double> v_;
};

float ladder_position(double mar_deg, double ppd) {
  // lambda = 2 log2(c_0 / f_c) with f_c = 1 / (mar ppd) cycles per pixel.
  return 2.0f * std::log2(static_cast<float>(kC0 * mar_deg * ppd));
}

// Bilinear read of a full-resolution map at image coordinates (u, v).
float sample_at(const Map& m, double u, double v) {
  const double gx = std::clamp(u - 0.5, 0.0, m.width - 1.0);
  const double gy = std::clamp(v - 0.5, 0.0, m.height - 1.0);
  const int i = std::min(static_cast<int>(gx), std::max(0, m.width - 2));
  const int j = std::min(static_cast<int>(gy), std::max(0, m.height - 2));
  const int i1 = std::min(i + 1, m.width - 1), j1 = std::min(j + 1, m.height - 1);
  const float fx = static_cast<float>(gx - i), fy = static_cast<float>(gy - j);
  const float top = m.at(i, j) + fx * (m.at(i1, j) - m.at(i, j));
  const float bot = m.at(i, j1) + fx * (m.at(i1, j1) - m.at(i, j1));
  return top + fy * (bot - top);
}

// Blend of a level's entries at position l (0 = first entry, 1 = second, ...).
inline float blend(float l, const float* e, int count) {
  if (!(l > 0.0f)) return e[0];
  if (l >= static_cast<float>(count - 1)) return e[count - 1];
  const int k = static_cast<int>(l);
  const float s = l - static_cast<float>(k);
  return e[k] + s * (e[k + 1] - e[k]);
}

}  // namespace

double ladder_cutoff(int j) { return kC0 * std::exp2(-0.5 * j); }

double ladder_lowpass(double rho, double c) {
  if (!(rho > 0.0)) return 1.0;
  const double t = std::log2(rho / c);
  if (t <= -0.25) return 1.0;
  if (t >= 0.25) return 0.0;
  return 0.5 - 0.5 * std::sin(2.0 * std::numbers::pi * t);
}

void check_display(const Display& display, int width, int height, const char* what) {
  if (display.width_px != width || display.height_px != height) {
    throw Error(std::string(what) + ": display '" + display.name + "' is " +
                std::to_string(display.width_px) + "x" + std::to_string(display.height_px) +
                " but the images are " + std::to_string(width) + "x" + std::to_string(height) +
                " (use Display::resized)");
  }
}

PyramidGeometry pyramid_geometry(const Display& display, Vec2d gaze, const AcuityModel& acuity,
                                 const Map* eccentricity) {
  PyramidGeometry g;
  const int w = display.width_px, h = display.height_px;
  const PpdGrid ppd(display, gaze);
  Map own;
  if (!eccentricity) {
    own = eccentricity_map(display, gaze);
    eccentricity = &own;
  }
  LevelGeometry l0;
  l0.w = w;
  l0.h = h;
  l0.lambda.resize(static_cast<size_t>(w) * h);
  l0.ppd.resize(l0.lambda.size());
  float lambda_max = -1e30f;
  int bx0 = w, by0 = h, bx1 = 0, by1 = 0;  // bounding box of lambda < 3
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y) * w + x;
      const double e = eccentricity->values[i];
      const double p = ppd.at(x + 0.5, y + 0.5);
      const float lam = ladder_position(acuity.mar_deg(e), p);
      l0.lambda[i] = lam;
      l0.ppd[i] = static_cast<float>(p);
      lambda_max = std::max(lambda_max, lam);
      if (lam < 3.0f) {
        bx0 = std::min(bx0, x), by0 = std::min(by0, y);
        bx1 = std::max(bx1, x + 1), by1 = std::max(by1, y + 1);
      }
    }
  }
  if (bx1 > bx0) {
    g.tx0 = std::max(0, bx0 - kTileMargin);
    g.ty0 = std::max(0, by0 - kTileMargin);
    g.tx1 = std::min(w, bx1 + kTileMargin);
    g.ty1 = std::min(h, by1 + kTileMargin);
  }
  // Levels up to N with 2N + 2 >= lambda_max (B_N's cutoff below every
  // pixel's), while the grid keeps at least 2 x 2 samples.
  int levels = std::max(1, static_cast<int>(std::ceil((lambda_max - 2.0f) / 2.0f)));
  g.levels.push_back(std::move(l0));
  for (int n = 1; n <= levels; ++n) {
    const LevelGeometry& prev = g.levels.back();
    if (n > 1 && (prev.w < 4 || prev.h < 4)) break;
    LevelGeometry l;
    l.w = (prev.w + 1) / 2;
    l.h = (prev.h + 1) / 2;
    l.lambda.resize(static_cast<size_t>(l.w) * l.h);
    l.ppd.resize(l.lambda.size());
    const double step = std::exp2(n);
    for (int j = 0; j < l.h; ++j) {
      for (int i = 0; i < l.w; ++i) {
        const Vec2d p{(i + 0.5) * step, (j + 0.5) * step};
        const double pp = ppd.at(p.x, p.y);
        const size_t k = static_cast<size_t>(j) * l.w + i;
        // Eccentricity is smooth at this scale: interpolated from the pixels'.
        l.lambda[k] = ladder_position(acuity.mar_deg(sample_at(*eccentricity, p.x, p.y)), pp);
        l.ppd[k] = static_cast<float>(pp);
      }
    }
    g.levels.push_back(std::move(l));
  }
  return g;
}

AcuityPyramid acuity_pyramid(Map linear, const PyramidGeometry& g) {
  AcuityPyramid p;
  p.x0 = std::move(linear);
  const int top = g.top();
  p.a.resize(top + 1);
  p.b.resize(top + 1);
  p.c.resize(top + 1);
  // Analysis: X_n by halving, A_n and B_n by the exact radial low-passes.
  {
    Map x = down(p.x0);
    for (int n = 1; n <= top; ++n) {
      std::vector<Map> bank = lowpass_bank(x.values.data(), x.width, x.width, x.height,
                                           {ladder_cutoff(1), ladder_cutoff(2)});
      p.a[n] = std::move(bank[0]);
      p.b[n] = std::move(bank[1]);
      if (n < top) x = down(x);
    }
  }
  if (g.has_tile()) {
    const int W = p.x0.width;
    p.tile = lowpass_bank(&p.x0.values[static_cast<size_t>(g.ty0) * W + g.tx0], W, g.tx1 - g.tx0,
                          g.ty1 - g.ty0, {ladder_cutoff(0), ladder_cutoff(1), ladder_cutoff(2)});
  }
  // Synthesis, coarse to fine.
  Map r;
  {
    const LevelGeometry& lg = g.levels[top];
    r = Map(lg.w, lg.h);
    const float first = static_cast<float>(2 * top + 1);
    for (size_t i = 0; i < r.values.size(); ++i) {
      const float e[2] = {p.a[top].values[i], p.b[top].values[i]};
      r.values[i] = blend(lg.lambda[i] - first, e, 2);
    }
  }
  for (int n = top - 1; n >= 1; --n) {
    const LevelGeometry& lg = g.levels[n];
    p.c[n] = up(r, lg.w, lg.h);
    r = Map(lg.w, lg.h);
    const float first = static_cast<float>(2 * n + 1);
    for (size_t i = 0; i < r.values.size(); ++i) {
      const float e[3] = {p.a[n].values[i], p.b[n].values[i], p.c[n].values[i]};
      r.values[i] = blend(lg.lambda[i] - first, e, 3);
    }
  }
  const LevelGeometry& l0 = g.levels[0];
  p.filtered = up(r, l0.w, l0.h);
  if (g.has_tile()) {
    const int tw = g.tx1 - g.tx0, th = g.ty1 - g.ty0;
    p.c0_tile = Map(tw, th);
    for (int y = 0; y < th; ++y) {
      for (int x = 0; x < tw; ++x) {
        const size_t i = static_cast<size_t>(g.ty0 + y) * l0.w + (g.tx0 + x);
        const size_t t = static_cast<size_t>(y) * tw + x;
        const float c0 = p.filtered.values[i];
        p.c0_tile.values[t] = c0;
        const float e[5] = {p.x0.values[i], p.tile[0].values[t], p.tile[1].values[t],
                            p.tile[2].values[t], c0};
        p.filtered.values[i] = blend(l0.lambda[i] + 1.0f, e, 5);
      }
    }
  }
  return p;
}

}  // namespace detail

double acuity_response(double frequency, double cutoff) {
  if (!(cutoff > 0.0)) throw Error("acuity_response: the cutoff must be > 0");
  const double lambda = std::max(-1.0, 2.0 * std::log2(detail::ladder_cutoff(0) / cutoff));
  const int m = static_cast<int>(std::floor(lambda));
  const double s = lambda - m;
  auto entry = [&](int j) {
    return j < 0 ? 1.0 : detail::ladder_lowpass(frequency, detail::ladder_cutoff(j));
  };
  return (1.0 - s) * entry(m) + s * entry(m + 1);
}

Map eccentricity_map(const Display& display, Vec2d gaze) {
  Map m(display.width_px, display.height_px);
  for (int y = 0; y < m.height; ++y) {
    for (int x = 0; x < m.width; ++x) {
      m.at(x, y) = static_cast<float>(display.eccentricity_deg({x + 0.5, y + 0.5}, gaze));
    }
  }
  return m;
}

Map acuity_cutoff_map(const Display& display, Vec2d gaze, const AcuityModel& acuity) {
  const detail::PyramidGeometry g = detail::pyramid_geometry(display, gaze, acuity);
  Map out(display.width_px, display.height_px);
  const auto& l0 = g.levels[0];
  for (size_t i = 0; i < out.values.size(); ++i) {
    out.values[i] = static_cast<float>(detail::ladder_cutoff(0) * std::exp2(-0.5 * l0.lambda[i]));
  }
  return out;
}

Map acuity_filtered(const Image& image, const Display& display, Vec2d gaze,
                    const AcuityModel& acuity) {
  if (image.empty()) throw Error("acuity_filtered: the image is empty");
  detail::check_display(display, image.width, image.height, "acuity_filtered");
  const detail::PyramidGeometry g = detail::pyramid_geometry(display, gaze, acuity);
  Map out = detail::acuity_pyramid(detail::luminance_linear(image), g).filtered;
  for (float& v : out.values) v = detail::luminance_to_code(v);
  return out;
}

Map acuity_difference(const Image& reference, const Image& test, const Display& display, Vec2d gaze,
                      const AcuityModel& acuity) {
  detail::check_same_size(reference, test, "acuity_difference");
  detail::check_display(display, reference.width, reference.height, "acuity_difference");
  const detail::PyramidGeometry g = detail::pyramid_geometry(display, gaze, acuity);
  const Map a = detail::acuity_pyramid(detail::luminance_linear(reference), g).filtered;
  const Map b = detail::acuity_pyramid(detail::luminance_linear(test), g).filtered;
  Map out(reference.width, reference.height);
  for (size_t i = 0; i < out.values.size(); ++i) {
    out.values[i] = detail::luminance_to_code(a.values[i]) - detail::luminance_to_code(b.values[i]);
  }
  return out;
}

}  // namespace foveate::metrics
