// LDR-FLIP, written from Andersson, Nilsson, Akenine-Moeller, Oskarsson,
// Astrom, Fairchild, "FLIP: A Difference Evaluator for Alternating Images",
// Proc. ACM Comput. Graph. Interact. Tech. 3(2), 2020 (section 3).
//
// Colour pipeline: sRGB -> linear RGB -> XYZ (D65) -> YCxCz (a linearised
// CIELAB opponent space), each channel filtered with its contrast sensitivity
// function (achromatic, red-green, blue-yellow; sums of Gaussians in degrees,
// sampled at the viewing distance's pixels per degree), back to linear RGB
// clamped to [0, 1], then CIELAB with the Hunt adjustment (a, b scaled by
// 0.01 L), and the HyAB distance. The distance, raised to q_c = 0.7, is mapped
// to [0, 1] relative to the largest distance (green vs blue) with p_c = 0.4,
// p_t = 0.95. Feature pipeline: edges (first derivative of a Gaussian) and
// points (second derivative) of the normalised luminance, with the Gaussian's
// peak-to-trough width 0.082 degrees; the feature difference, raised to
// q_f = 0.5, sharpens the colour error: FLIP = dE_c ^ (1 - dE_f).
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "foveate/core/error.hpp"
#include "internal.hpp"

namespace foveate::metrics {

namespace {

using detail::Kernel;

constexpr double kPi = std::numbers::pi;

// Linear sRGB (D65) to CIE XYZ.
constexpr double kM[3][3] = {{0.4124564, 0.3575761, 0.1804375},
                             {0.2126729, 0.7151522, 0.0721750},
                             {0.0193339, 0.1191920, 0.9503041}};
// Its inverse.
constexpr double kMinv[3][3] = {{3.2404542, -1.5371385, -0.4985314},
                                {-0.9692660, 1.8760108, 0.0415560},
                                {0.0556434, -0.2040259, 1.0572252}};
// XYZ of linear RGB (1, 1, 1): the reference white.
constexpr double kWhite[3] = {kM[0][0] + kM[0][1] + kM[0][2], kM[1][0] + kM[1][1] + kM[1][2],
                              kM[2][0] + kM[2][1] + kM[2][2]};

struct Opponent {
  Map y, cx, cz;
};

Opponent to_ycxcz(const Image& img) {
  const auto& lin = detail::srgb_to_linear_table();
  Opponent o{Map(img.width, img.height), Map(img.width, img.height), Map(img.width, img.height)};
  const std::uint8_t* p = img.rgba.data();
  for (size_t i = 0; i < o.y.values.size(); ++i, p += 4) {
    const double r = lin[p[0]], g = lin[p[1]], b = lin[p[2]];
    const double x = (kM[0][0] * r + kM[0][1] * g + kM[0][2] * b) / kWhite[0];
    const double y = (kM[1][0] * r + kM[1][1] * g + kM[1][2] * b) / kWhite[1];
    const double z = (kM[2][0] * r + kM[2][1] * g + kM[2][2] * b) / kWhite[2];
    o.y.values[i] = static_cast<float>(116.0 * y - 16.0);
    o.cx.values[i] = static_cast<float>(500.0 * (x - y));
    o.cz.values[i] = static_cast<float>(200.0 * (y - z));
  }
  return o;
}

double lab_f_exact(double t) {
  constexpr double d = 6.0 / 29.0;
  return t > d * d * d ? std::cbrt(t) : t / (3.0 * d * d) + 4.0 / 29.0;
}

// The CIELAB f() on [0, 1] (where clamped linear RGB lands once divided by the
// white) from a table with linear interpolation: at most 2e-6 from the exact
// value, i.e. below 3e-4 in L*. Outside [0, 1] it falls back to the formula.
constexpr int kLabTable = 16384;

double lab_f(double t) {
  static const std::vector<double> table = [] {
    std::vector<double> v(kLabTable + 2);
    for (int i = 0; i <= kLabTable + 1; ++i) v[i] = lab_f_exact(double(i) / kLabTable);
    return v;
  }();
  if (!(t >= 0.0 && t <= 1.0)) return lab_f_exact(t);
  const double s = t * kLabTable;
  const int i = static_cast<int>(s);
  return table[i] + (s - i) * (table[i + 1] - table[i]);
}

// Hunt-adjusted CIELAB of a linear RGB colour.
std::array<double, 3> hunt_lab(double r, double g, double b) {
  const double fx = lab_f((kM[0][0] * r + kM[0][1] * g + kM[0][2] * b) / kWhite[0]);
  const double fy = lab_f((kM[1][0] * r + kM[1][1] * g + kM[1][2] * b) / kWhite[1]);
  const double fz = lab_f((kM[2][0] * r + kM[2][1] * g + kM[2][2] * b) / kWhite[2]);
  const double l = 116.0 * fy - 16.0;
  return {l, 0.01 * l * 500.0 * (fx - fy), 0.01 * l * 200.0 * (fy - fz)};
}

double hyab(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  const double da = a[1] - b[1], db = a[2] - b[2];
  return std::fabs(a[0] - b[0]) + std::sqrt(da * da + db * db);
}

// One contrast sensitivity function: a1 sqrt(pi/b1) exp(-pi^2 x^2 / b1) + (same
// with a2, b2), x in degrees, sampled on the pixel grid over a common radius
// and normalised to sum 1. Each Gaussian is separable; the sum is applied as a
// weighted sum of two separable filters.
struct Csf {
  double a1, b1, a2, b2;
};
constexpr Csf kCsfA{1.0, 0.0047, 0.0, 1e-5};
constexpr Csf kCsfRG{1.0, 0.0053, 0.0, 1e-5};
constexpr Csf kCsfBY{34.1, 0.04, 13.5, 0.025};

Map apply_csf(const Map& in, const Csf& csf, double ppd) {
  const double bmax = 0.04;  // the widest of all six Gaussians sets the radius
  const int r = static_cast<int>(std::ceil(3.0 * std::sqrt(bmax / (2.0 * kPi * kPi)) * ppd));
  auto gauss = [&](double b, double& total) {
    Kernel k;
    k.offset = -r;
    k.w.resize(2 * r + 1);
    double sum = 0;
    for (int i = -r; i <= r; ++i) {
      const double x = i / ppd;
      const double v = std::exp(-kPi * kPi * x * x / b);
      k.w[i + r] = static_cast<float>(v);
      sum += v;
    }
    for (float& v : k.w) v = static_cast<float>(v / sum);
    total = sum * sum;  // 2-D sum of the unnormalised separable Gaussian
    return k;
  };
  double s1 = 0, s2 = 0;
  const Kernel k1 = gauss(csf.b1, s1);
  Map out = detail::filter2d(in, k1, k1);
  if (csf.a2 == 0.0) return out;
  const Kernel k2 = gauss(csf.b2, s2);
  const Map out2 = detail::filter2d(in, k2, k2);
  const double w1 = csf.a1 * std::sqrt(kPi / csf.b1) * s1;
  const double w2 = csf.a2 * std::sqrt(kPi / csf.b2) * s2;
  const float f1 = static_cast<float>(w1 / (w1 + w2)), f2 = static_cast<float>(w2 / (w1 + w2));
  for (size_t i = 0; i < out.values.size(); ++i) {
    out.values[i] = f1 * out.values[i] + f2 * out2.values[i];
  }
  return out;
}

// Edge and point detector kernels (1-D factors): the derivative factor has its
// positive weights normalised to sum 1 and its negative weights to sum -1; the
// Gaussian factor sums to 1.
struct FeatureKernels {
  Kernel gauss, edge, point;
};

FeatureKernels feature_kernels(double ppd) {
  constexpr double w = 0.082;  // degrees, peak to trough of the edge detector
  const double sd = 0.5 * w * ppd;
  const int r = static_cast<int>(std::ceil(3.0 * sd));
  FeatureKernels f;
  for (Kernel* k : {&f.gauss, &f.edge, &f.point}) {
    k->offset = -r;
    k->w.resize(2 * r + 1);
  }
  std::vector<double> g(2 * r + 1), e(2 * r + 1), p(2 * r + 1);
  for (int i = -r; i <= r; ++i) {
    const double gi = std::exp(-0.5 * i * i / (sd * sd));
    g[i + r] = gi;
    e[i + r] = -i * gi;
    p[i + r] = (i * i / (sd * sd) - 1.0) * gi;
  }
  auto normalise = [](const std::vector<double>& v, Kernel& k) {
    double pos = 0, neg = 0;
    for (double x : v) (x > 0 ? pos : neg) += x;
    for (size_t i = 0; i < v.size(); ++i) {
      const double x = v[i];
      k.w[i] = static_cast<float>(x > 0 ? x / pos : (x < 0 ? x / -neg : 0.0));
    }
  };
  normalise(g, f.gauss);
  normalise(e, f.edge);
  normalise(p, f.point);
  return f;
}

// |gradient| and |second derivatives| of the normalised luminance.
void features(const Map& y, const FeatureKernels& k, Map& edges, Map& points) {
  const Map rg = detail::filter_rows(y, k.gauss);
  const Map re = detail::filter_rows(y, k.edge);
  const Map rp = detail::filter_rows(y, k.point);
  const Map ex = detail::filter_cols(re, k.gauss), ey = detail::filter_cols(rg, k.edge);
  const Map px = detail::filter_cols(rp, k.gauss), py = detail::filter_cols(rg, k.point);
  edges = Map(y.width, y.height);
  points = Map(y.width, y.height);
  for (size_t i = 0; i < y.values.size(); ++i) {
    edges.values[i] = std::sqrt(ex.values[i] * ex.values[i] + ey.values[i] * ey.values[i]);
    points.values[i] = std::sqrt(px.values[i] * px.values[i] + py.values[i] * py.values[i]);
  }
}

}  // namespace

Map flip_map(const Image& reference, const Image& test, double ppd) {
  detail::check_same_size(reference, test, "flip");
  if (!(ppd > 0.0) || !std::isfinite(ppd)) throw Error("flip: pixels per degree must be > 0");
  constexpr double qc = 0.7, pc = 0.4, pt = 0.95;

  const Opponent ref = to_ycxcz(reference), tst = to_ycxcz(test);

  // Feature pipeline on the normalised luminance (Y / Y_white = (Y' + 16) / 116).
  const FeatureKernels fk = feature_kernels(ppd);
  auto norm_y = [](const Map& yy) {
    Map m = yy;
    for (float& v : m.values) v = (v + 16.0f) / 116.0f;
    return m;
  };
  Map edges_r, points_r, edges_t, points_t;
  features(norm_y(ref.y), fk, edges_r, points_r);
  features(norm_y(tst.y), fk, edges_t, points_t);

  // Colour pipeline.
  const Map ry = apply_csf(ref.y, kCsfA, ppd), rx = apply_csf(ref.cx, kCsfRG, ppd),
            rz = apply_csf(ref.cz, kCsfBY, ppd);
  const Map ty = apply_csf(tst.y, kCsfA, ppd), tx = apply_csf(tst.cx, kCsfRG, ppd),
            tz = apply_csf(tst.cz, kCsfBY, ppd);

  auto filtered_lab = [](float yy, float cx, float cz) {
    const double y = (yy + 16.0) / 116.0;
    const double x = (y + cx / 500.0) * kWhite[0];
    const double z = (y - cz / 200.0) * kWhite[2];
    const double yw = y * kWhite[1];
    double rgb[3];
    for (int c = 0; c < 3; ++c) {
      rgb[c] = std::clamp(kMinv[c][0] * x + kMinv[c][1] * yw + kMinv[c][2] * z, 0.0, 1.0);
    }
    return hunt_lab(rgb[0], rgb[1], rgb[2]);
  };

  const double cmax = std::pow(hyab(hunt_lab(0, 1, 0), hunt_lab(0, 0, 1)), qc);
  const double pccmax = pc * cmax;
  Map out(reference.width, reference.height);
  for (size_t i = 0; i < out.values.size(); ++i) {
    const auto a = filtered_lab(ry.values[i], rx.values[i], rz.values[i]);
    const auto b = filtered_lab(ty.values[i], tx.values[i], tz.values[i]);
    const double dc = std::pow(static_cast<float>(hyab(a, b)), static_cast<float>(qc));
    const double ec =
        dc < pccmax ? (pt / pccmax) * dc : pt + (dc - pccmax) / (cmax - pccmax) * (1.0 - pt);
    const double df = std::max(std::fabs(edges_r.values[i] - edges_t.values[i]),
                               std::fabs(points_r.values[i] - points_t.values[i]));
    const double ef = std::sqrt(df / std::sqrt(2.0));  // q_f = 0.5
    // dE_c ^ (1 - dE_f), with the exponent 1 (no feature difference) exact.
    out.values[i] = ef == 0.0 ? static_cast<float>(ec)
                              : std::pow(static_cast<float>(ec), static_cast<float>(1.0 - ef));
  }
  return out;
}

}  // namespace foveate::metrics
