#include "fvvdp/csf.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace foveate::metrics::fvvdp {

namespace {

constexpr double kPi = std::numbers::pi;

// Laird, Rosen, Pelz, Montag and Daly 2006, "Spatio-velocity CSF as a function
// of retinal velocity using unstabilized stimuli": sensitivity to frequency
// rho (cpd) moving at vel (deg/s). The model vanishes for a pattern at rest on
// the retina, so velocities are taken to be at least 0.1 deg/s, the drift of
// the eye during a fixation.
double spatio_velocity_csf(double rho, double vel) {
  constexpr double s1 = 6.1, s2 = 7.3, p1 = 45.9;
  constexpr double c0 = 0.6329, c1 = 0.8404, c2 = 0.7986;
  vel = std::max(vel, 0.1);
  const double k = s1 + s2 * std::pow(std::abs(std::log10(c2 * vel / 3.0)), 3.0);
  const double rho_max = p1 / (c2 * vel + 2.0);
  const double u = c1 * 2.0 * kPi * rho;
  return k * c0 * c1 * c2 * vel * u * u * std::exp(-(c1 * 4.0 * kPi * rho) / rho_max);
}

// A temporal frequency omega of a pattern of frequency rho is the velocity omega / rho.
double spatio_temporal_csf(double rho, double omega) {
  return spatio_velocity_csf(rho, omega / rho);
}

// The luminance dependence of a parameter of Mantiuk et al. 2020: a constant,
// one hyperbola or the product of two.
double luminance_dependent(const std::vector<double>& p, double lum) {
  switch (p.size()) {
    case 1:
      return p[0];
    case 3:
      return p[0] * std::pow(1.0 + p[1] / lum, -p[2]);
    default:  // 5
      return p[0] * std::pow(1.0 + p[1] / lum, -p[2]) * (1.0 - std::pow(1.0 + p[3] / lum, -p[4]));
  }
}

// One colour mechanism of Mantiuk et al. 2020: a log-parabola in frequency
// whose peak, peak frequency, bandwidth and area exponent depend on luminance,
// with the stimulus-area model of Rovamo, Luntinen and Nasanen 1993.
struct Mechanism {
  std::vector<double> s_max, f_max, bandwidth, gamma;
  double ac_prime;
  bool low_pass;  // chromatic mechanisms keep their peak below it
};

const std::array<Mechanism, 3>& mechanisms() {
  // The fitted parameters of the model (achromatic, red-green, yellow-violet).
  static const std::array<Mechanism, 3> m{{
      {{356404, 6.2726, 0.320031, 895943, 7.77919e-05},
       {2.3021, 3317.45, 0.186215},
       {1.07516},
       {1.1107},
       52.9768,
       false},
      {{423.978, 15.4032, 0.50343}, {0.122699}, {2.70669}, {1.72903}, 1.38437, true},
      {{11811.9, 196.342, 0.339396}, {7.1099e-08}, {5.3416}, {1.47263}, 0.282573, true},
  }};
  return m;
}

double mechanism_sensitivity(const Mechanism& m, double freq, double area, double lum) {
  const double s_max = luminance_dependent(m.s_max, lum);
  const double f_max = luminance_dependent(m.f_max, lum);
  const double bw = luminance_dependent(m.bandwidth, lum);
  const double gamma = luminance_dependent(m.gamma, lum);
  const double d = std::log10(freq) - std::log10(f_max);
  double s_peak = s_max / std::pow(10.0, d * d / (0.5 * std::pow(2.0, bw)));
  if (m.low_pass && freq < f_max) s_peak = s_max;
  const double k = m.ac_prime + area * 0.65;
  const double a = std::pow(area, gamma) * freq * freq;
  return s_peak * std::sqrt(a / (k + a));
}

// Sensitivity to an achromatic Gabor of frequency `freq` and area `area`
// (deg^2) on a D65 background of luminance `lum`: the three mechanisms'
// responses to its cone contrast, pooled with exponent 2, give the
// detection contrast; its inverse as the RMS cone contrast is the sensitivity.
double achromatic_sensitivity(double freq, double area, double lum) {
  // CIE 2006 LMS of CIE 1931 XYZ on an LED LCD (Mantiuk et al. 2020) and the D65 white.
  constexpr double xyz_to_lms[3][3] = {{0.187596268556126, 0.585168649077728, -0.026384263306304},
                                       {-0.133397430663221, 0.405505777260049, 0.034502127690364},
                                       {0.000244379021663, -0.000542995890619, 0.019406849066323}};
  constexpr double d65[3] = {0.95047, 1.0, 1.08883};
  // Cone contrast to the mechanisms' responses (achromatic, red-green, yellow-violet).
  constexpr double lms_to_mechanism[3][3] = {
      {1.0, 0.256197, 6.42477e-07}, {1.0, -0.933541, 0.00373304}, {-0.00130319, -1.1504, 1.0}};
  // An achromatic modulation's direction in LMS.
  constexpr double delta[3] = {0.698, 0.302, 0.019613};
  double mean[3], cc[3];
  for (int i = 0; i < 3; ++i) {
    mean[i] =
        lum * (xyz_to_lms[i][0] * d65[0] + xyz_to_lms[i][1] * d65[1] + xyz_to_lms[i][2] * d65[2]);
    cc[i] = delta[i] / mean[i];
  }
  const double lm_luminance = mean[0] + mean[1];
  double pooled = 0.0;
  for (int c = 0; c < 3; ++c) {
    const double response =
        std::abs(lms_to_mechanism[c][0] * cc[0] + lms_to_mechanism[c][1] * cc[1] +
                 lms_to_mechanism[c][2] * cc[2]);
    const double r = response * mechanism_sensitivity(mechanisms()[static_cast<size_t>(c)], freq,
                                                      area, lm_luminance);
    pooled += r * r;
  }
  const double detection = std::sqrt(pooled);
  const double rms_cone_contrast = std::sqrt(cc[0] * cc[0] + cc[1] * cc[1] + cc[2] * cc[2]);
  return detection * std::sqrt(3.0) / rms_cone_contrast;
}

std::array<float, SensitivityTable::kSize> log_spaced(double from, double to) {
  std::array<float, SensitivityTable::kSize> v{};
  const double a = std::log10(from), b = std::log10(to);
  for (int i = 0; i < SensitivityTable::kSize; ++i) {
    v[static_cast<size_t>(i)] =
        static_cast<float>(std::pow(10.0, a + (b - a) * i / (SensitivityTable::kSize - 1)));
  }
  return v;
}

}  // namespace

double sensitivity(double rho_cpd, double omega_hz, double luminance_cd_m2, double ecc_deg,
                   const FvvdpParameters& parameters) {
  const double sigma =
      parameters.csf_sigma < 0.0 ? -parameters.csf_sigma / rho_cpd : parameters.csf_sigma;
  constexpr double e2 = 3.67;  // Dougherty et al. 2003: M(e) = 29.2 / (e + 3.67) mm/deg
  const double m_rel = std::pow(e2 / (ecc_deg + e2), parameters.k_cm);
  const double area = kPi * (sigma * m_rel) * (sigma * m_rel);
  const double rho_cm = rho_cpd / m_rel;
  const double temporal =
      spatio_temporal_csf(rho_cm, omega_hz) / (spatio_temporal_csf(rho_cm, 0.0) + 1e-5);
  return achromatic_sensitivity(rho_cm, area, luminance_cd_m2) * temporal;
}

SensitivityTable make_sensitivity_table(double omega_hz, const FvvdpParameters& parameters) {
  constexpr int n = SensitivityTable::kSize;
  SensitivityTable t;
  t.luminance = log_spaced(0.001, 10000.0);
  t.rho = log_spaced(1.0 / 16.0, 64.0);
  const double ecc_max_sqrt = std::sqrt(120.0);
  for (int i = 0; i < n; ++i) {
    const double s = ecc_max_sqrt * i / (n - 1);
    t.ecc[static_cast<size_t>(i)] = static_cast<float>(s * s);
  }
  for (size_t i = 0; i < static_cast<size_t>(n); ++i) {
    t.luminance_log2[i] = std::log2(t.luminance[i]);
    t.rho_log2[i] = std::log2(t.rho[i]);
    t.ecc_sqrt[i] = std::sqrt(t.ecc[i]);
  }
  const double gain_log2 = parameters.sensitivity_correction_db / 20.0 * std::log2(10.0);
  t.values.resize(static_cast<size_t>(n) * n * n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      for (int k = 0; k < n; ++k) {
        const double s = sensitivity(t.rho[static_cast<size_t>(i)], omega_hz,
                                     t.luminance[static_cast<size_t>(j)],
                                     t.ecc[static_cast<size_t>(k)], parameters);
        t.values[(static_cast<size_t>(j) * n + i) * n + k] =
            static_cast<float>(std::log2(std::max(s, 1e-4)) + gain_log2);
      }
    }
  }
  return t;
}

AxisPosition locate(const std::array<float, SensitivityTable::kSize>& grid, float q) {
  constexpr int n = SensitivityTable::kSize;
  // The grids are (nearly) uniform: start from the uniform estimate and step
  // to the first node not below q.
  const float step = (grid[n - 1] - grid[0]) / static_cast<float>(n - 1);
  int hi = std::clamp(static_cast<int>(std::ceil((q - grid[0]) / step)), 0, n - 1);
  while (hi < n - 1 && grid[static_cast<size_t>(hi)] < q) ++hi;
  while (hi > 0 && grid[static_cast<size_t>(hi - 1)] >= q) --hi;
  const int lo = std::max(hi - 1, 0);
  AxisPosition p{lo, hi, 0.0f};
  if (hi != lo) {
    const float lo_v = grid[static_cast<size_t>(lo)];
    p.frac = std::max(0.0f, (q - lo_v) / (grid[static_cast<size_t>(hi)] - lo_v + 1e-6f));
  }
  return p;
}

AxisPosition SensitivityTable::locate_luminance(float cd_m2) const {
  return locate(luminance_log2, std::log2(std::clamp(cd_m2, luminance[0], luminance[kSize - 1])));
}

AxisPosition SensitivityTable::locate_rho(float cpd) const {
  return locate(rho_log2, std::log2(std::clamp(cpd, rho[0], rho[kSize - 1])));
}

AxisPosition SensitivityTable::locate_ecc(float deg) const {
  return locate(ecc_sqrt, std::sqrt(std::clamp(deg, ecc[0], ecc[kSize - 1])));
}

float SensitivityTable::lookup(const AxisPosition& y, const AxisPosition& r,
                               const AxisPosition& e) const {
  const auto lerp = [](float a, float b, float f) { return a * (1.0f - f) + b * f; };
  const auto plane = [&](int k) {
    return lerp(lerp(at(y.lo, r.lo, k), at(y.lo, r.hi, k), r.frac),
                lerp(at(y.hi, r.lo, k), at(y.hi, r.hi, k), r.frac), y.frac);
  };
  return lerp(plane(e.lo), plane(e.hi), e.frac);
}

}  // namespace foveate::metrics::fvvdp
