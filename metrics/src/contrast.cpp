// Visibility of the band differences in JND units: Peli's local band-limited
// contrast (E. Peli, "Contrast in complex images", JOSA A 7(10), 1990) of the
// difference between the two images in every band of the acuity pyramid,
// weighted by Barten's contrast sensitivity at the band's centre frequency,
// and pooled over the bands with a Minkowski sum.
//
// For band D_j = E_j - E_(j+1) (acuity.cpp) at a sample:
//   contrast  c_j = (D_j(ref) - D_j(test)) / (l + Lb / (Lp - Lb)),
//             l = (E_(j+1)(ref) + E_(j+1)(test)) / 2, the local mean linear
//             luminance below the band, Lp, Lb the display's white and black;
//   JND       J_j = w_j * sqrt(2 G * (c_j S(u_j, L))^2),
//             S Barten's CSF at the band's centre u_j (cycles per degree) and
//             the adapting luminance L = Lb + (Lp - Lb) l, G a Gaussian of
//             0.4 periods of the band's centre (so that a grating's J_j is its
//             peak contrast times S, whatever its phase), w_j the acuity weight
//             of the band at the sample;
//   pooled    J = (sum_j J_j^beta)^(1/beta), beta = ContrastModel::pooling_beta.
// The bands of coarser levels reach full resolution by bilinear interpolation
// of their sum of J_j^beta. The residual below the last band (B_N) is one more
// term, its contrast taken at half of B_N's cutoff.
#include <algorithm>
#include <cmath>

#include "foveate/core/error.hpp"
#include "internal.hpp"

namespace foveate::metrics {

double barten_csf(double u, double luminance, double field_deg) {
  if (!(u > 0.0) || !(luminance > 0.0) || !(field_deg > 0.0)) return 0.0;
  const double a = 540.0 * std::pow(1.0 + 0.7 / luminance, -0.2) /
                   (1.0 + 12.0 / (field_deg * (1.0 + u / 3.0) * (1.0 + u / 3.0)));
  const double b = 0.3 * std::pow(1.0 + 100.0 / luminance, 0.15);
  constexpr double c = 0.06;
  const double bu = b * u;
  // a u e^(-bu) sqrt(1 + c e^(bu)) = a u sqrt(e^(-2bu) + c e^(-bu)), which
  // cannot overflow at high frequencies.
  return a * u * std::sqrt(std::exp(-2.0 * bu) + c * std::exp(-bu));
}

namespace detail {

namespace {

// Centre of band D_j in cycles per pixel: c_j 2^(-1/4) (the geometric mean of
// its cutoffs c_j and c_(j+1)).
double band_centre(int j) { return ladder_cutoff(j) * std::exp2(-0.25); }

struct Display2 {
  double peak, black, offset;  // offset = Lb / (Lp - Lb)
};

// The band's squared visibility per sample, before the envelope.
void band_energy(const Map& hi_r, const Map& lo_r, const Map& hi_t, const Map& lo_t,
                 const float* lambda, const float* ppd, int j, double centre_cpp,
                 const ContrastModel& cm, const Display2& d, Map& out) {
  const size_t n = out.values.size();
  const float active = static_cast<float>(j) + 1.25f;  // weights vanish from j + 1
  for (size_t i = 0; i < n; ++i) {
    if (!(lambda[i] < active)) {
      out.values[i] = 0.0f;
      continue;
    }
    // The sharp low-passes ring next to strong edges and may dip below 0;
    // the display never shows less than its black.
    const double l = std::max(0.0, 0.5 * (double(lo_r.values[i]) + double(lo_t.values[i])));
    const double dd = (double(hi_r.values[i]) - double(lo_r.values[i])) -
                      (double(hi_t.values[i]) - double(lo_t.values[i]));
    if (dd == 0.0) {
      out.values[i] = 0.0f;
      continue;
    }
    const double denom = l + d.offset;
    const double s =
        barten_csf(centre_cpp * ppd[i], d.black + (d.peak - d.black) * l, cm.field_deg);
    const double e = dd / denom * s;
    out.values[i] = static_cast<float>(e * e);
  }
}

// pool += (w_j * sqrt(2 blur(energy)))^beta over the samples.
void pool_band(Map energy, const float* lambda, int j, double sigma, double beta, Map& pool) {
  const Kernel k = gaussian_kernel_radius(sigma, static_cast<int>(std::ceil(3.0 * sigma)));
  const Map env = filter2d(energy, k, k);
  for (size_t i = 0; i < pool.values.size(); ++i) {
    const double w = std::clamp(static_cast<double>(j) + 1.0 - lambda[i], 0.0, 1.0);
    if (w == 0.0) continue;
    const double v = w * w * 2.0 * std::max(0.0, double(env.values[i]));  // (w J)^2
    if (v == 0.0) continue;
    pool.values[i] += static_cast<float>(beta == 4.0   ? v * v
                                         : beta == 2.0 ? v
                                                       : std::pow(v, 0.5 * beta));
  }
}

// Bilinear interpolation of a level to the next finer one (w, h): fine sample
// i lies at coarse coordinate (i - 0.5) / 2.
Map bilinear_up(const Map& in, int w, int h) {
  Map out(w, h);
  const int cw = in.width, ch = in.height;
  std::vector<int> x0(w), x1(w);
  std::vector<float> fx(w);
  for (int i = 0; i < w; ++i) {
    const double u = std::clamp((i - 0.5) / 2.0, 0.0, cw - 1.0);
    x0[i] = static_cast<int>(u);
    x1[i] = std::min(x0[i] + 1, cw - 1);
    fx[i] = static_cast<float>(u - x0[i]);
  }
  for (int y = 0; y < h; ++y) {
    const double v = std::clamp((y - 0.5) / 2.0, 0.0, ch - 1.0);
    const int y0 = static_cast<int>(v);
    const int y1 = std::min(y0 + 1, ch - 1);
    const float fy = static_cast<float>(v - y0);
    const float* r0 = &in.values[static_cast<size_t>(y0) * cw];
    const float* r1 = &in.values[static_cast<size_t>(y1) * cw];
    float* o = &out.values[static_cast<size_t>(y) * w];
    for (int i = 0; i < w; ++i) {
      const float a = r0[x0[i]] + fx[i] * (r0[x1[i]] - r0[x0[i]]);
      const float b = r1[x0[i]] + fx[i] * (r1[x1[i]] - r1[x0[i]]);
      o[i] = a + fy * (b - a);
    }
  }
  return out;
}

Map crop(const Map& m, int x0, int y0, int w, int h) {
  Map out(w, h);
  for (int y = 0; y < h; ++y) {
    std::copy_n(&m.values[static_cast<size_t>(y0 + y) * m.width + x0], w,
                &out.values[static_cast<size_t>(y) * w]);
  }
  return out;
}

std::vector<float> crop(const std::vector<float>& v, int stride, int x0, int y0, int w, int h) {
  std::vector<float> out(static_cast<size_t>(w) * h);
  for (int y = 0; y < h; ++y) {
    std::copy_n(&v[static_cast<size_t>(y0 + y) * stride + x0], w, &out[static_cast<size_t>(y) * w]);
  }
  return out;
}

}  // namespace

Map jnd_from_pyramids(const AcuityPyramid& r, const AcuityPyramid& t, const PyramidGeometry& g,
                      const ContrastModel& cm) {
  const Display2 d{cm.peak_cd_m2, cm.black_cd_m2,
                   cm.black_cd_m2 / (cm.peak_cd_m2 - cm.black_cd_m2)};
  const double beta = cm.pooling_beta;
  const int top = g.top();
  Map pool;
  for (int n = top; n >= 1; --n) {
    const LevelGeometry& lg = g.levels[n];
    pool = n == top ? Map(lg.w, lg.h) : bilinear_up(pool, lg.w, lg.h);
    const double step = std::exp2(n);
    // Bands at this level: A_n - B_n (j = 2n + 1) and B_n - C_n (j = 2n + 2).
    const int j1 = 2 * n + 1;
    Map energy(lg.w, lg.h);
    band_energy(r.a[n], r.b[n], t.a[n], t.b[n], lg.lambda.data(), lg.ppd.data(), j1,
                band_centre(j1), cm, d, energy);
    pool_band(std::move(energy), lg.lambda.data(), j1, 0.4 / (band_centre(j1) * step), beta, pool);
    if (n < top) {
      Map e2(lg.w, lg.h);
      band_energy(r.b[n], r.c[n], t.b[n], t.c[n], lg.lambda.data(), lg.ppd.data(), j1 + 1,
                  band_centre(j1 + 1), cm, d, e2);
      pool_band(std::move(e2), lg.lambda.data(), j1 + 1, 0.4 / (band_centre(j1 + 1) * step), beta,
                pool);
    } else {
      // The residual B_N: everything below the last cutoff, including the mean.
      const double u_cpp = 0.5 * ladder_cutoff(2 * n + 2);
      for (size_t i = 0; i < pool.values.size(); ++i) {
        const double l = std::max(0.0, 0.5 * (double(r.b[n].values[i]) + double(t.b[n].values[i])));
        const double dd = double(r.b[n].values[i]) - double(t.b[n].values[i]);
        if (dd == 0.0) continue;
        const double s =
            barten_csf(u_cpp * lg.ppd[i], d.black + (d.peak - d.black) * l, cm.field_deg);
        const double e = std::fabs(dd) / (l + d.offset) * s;
        pool.values[i] += static_cast<float>(std::pow(e, beta));
      }
    }
  }
  const LevelGeometry& l0 = g.levels[0];
  pool = bilinear_up(pool, l0.w, l0.h);
  if (g.has_tile()) {
    const int tw = g.tx1 - g.tx0, th = g.ty1 - g.ty0;
    const std::vector<float> lam = crop(l0.lambda, l0.w, g.tx0, g.ty0, tw, th);
    const std::vector<float> ppd = crop(l0.ppd, l0.w, g.tx0, g.ty0, tw, th);
    Map tile_pool = crop(pool, g.tx0, g.ty0, tw, th);
    const Map xr = crop(r.x0, g.tx0, g.ty0, tw, th), xt = crop(t.x0, g.tx0, g.ty0, tw, th);
    // Entries -1 .. 3 over the tile: the image, E_0, E_1, E_2 and C_0.
    const Map* er[5] = {&xr, &r.tile[0], &r.tile[1], &r.tile[2], &r.c0_tile};
    const Map* et[5] = {&xt, &t.tile[0], &t.tile[1], &t.tile[2], &t.c0_tile};
    for (int k = 0; k < 4; ++k) {
      const int j = k - 1;
      Map energy(tw, th);
      band_energy(*er[k], *er[k + 1], *et[k], *et[k + 1], lam.data(), ppd.data(), j, band_centre(j),
                  cm, d, energy);
      pool_band(std::move(energy), lam.data(), j, 0.4 / band_centre(j), beta, tile_pool);
    }
    for (int y = 0; y < th; ++y) {
      std::copy_n(&tile_pool.values[static_cast<size_t>(y) * tw], tw,
                  &pool.values[static_cast<size_t>(g.ty0 + y) * l0.w + g.tx0]);
    }
  }
  for (float& v : pool.values) {
    const double p = std::max(0.0, double(v));
    v = static_cast<float>(beta == 4.0   ? std::sqrt(std::sqrt(p))
                           : beta == 2.0 ? std::sqrt(p)
                                         : std::pow(p, 1.0 / beta));
  }
  return pool;
}

}  // namespace detail

Map jnd_map(const Image& reference, const Image& test, const Display& display, Vec2d gaze,
            const QualityOptions& options) {
  detail::check_same_size(reference, test, "jnd_map");
  detail::check_options(options);
  detail::check_display(display, reference.width, reference.height, "jnd_map");
  const detail::PyramidGeometry g = detail::pyramid_geometry(display, gaze, options.acuity);
  const detail::AcuityPyramid a = detail::acuity_pyramid(detail::luminance_linear(reference), g);
  const detail::AcuityPyramid b = detail::acuity_pyramid(detail::luminance_linear(test), g);
  return detail::jnd_from_pyramids(a, b, g, options.contrast);
}

}  // namespace foveate::metrics
