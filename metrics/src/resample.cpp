// Halving and doubling a level of the acuity pyramid: a Kaiser-windowed
// half-band filter (2 * kHalfTaps taps) with mirrored borders.
#include <array>
#include <cmath>
#include <numbers>

#include "internal.hpp"

namespace foveate::metrics::detail {

namespace {

constexpr int kHalfTaps = 12;  // half-band filter: 2 * kHalfTaps taps
constexpr double kKaiserBeta = 5.5;

double bessel_i0(double x) {
  double sum = 1.0, term = 1.0;
  for (int k = 1; k < 100; ++k) {
    term *= (0.5 * x / k) * (0.5 * x / k);
    sum += term;
    if (term < 1e-14 * sum) break;
  }
  return sum;
}

// The half-band kernel at distance d in fine samples: sinc(d / 2) under a Kaiser
// window reaching zero at |d| = kHalfTaps (unnormalised).
double half_band(double d) {
  const double x = 0.5 * d;
  const double sinc = x == 0.0 ? 1.0 : std::sin(std::numbers::pi * x) / (std::numbers::pi * x);
  const double r = d / kHalfTaps;
  if (std::fabs(r) >= 1.0) return 0.0;
  return sinc * bessel_i0(kKaiserBeta * std::sqrt(1.0 - r * r)) / bessel_i0(kKaiserBeta);
}

struct HalfBandTaps {
  // Decimation: out[j] = sum_t down[t] in[2 j + t + 1 - kHalfTaps], t < 2 kHalfTaps
  // (output sample j lies half-way between inputs 2j and 2j + 1).
  std::array<float, 2 * kHalfTaps> down{};
  // Interpolation: fine 2j reads coarse j - kHalfTaps/2 .. j + kHalfTaps/2 - 1
  // (it lies at coarse coordinate j - 1/4), fine 2j + 1 reads
  // j - kHalfTaps/2 + 1 .. j + kHalfTaps/2 (coordinate j + 1/4).
  std::array<float, kHalfTaps> up_even{}, up_odd{};
};

const HalfBandTaps& half_band_taps() {
  static const HalfBandTaps taps = [] {
    HalfBandTaps t;
    double s = 0;
    for (int i = 0; i < 2 * kHalfTaps; ++i) s += half_band(i + 1 - kHalfTaps - 0.5);
    for (int i = 0; i < 2 * kHalfTaps; ++i) {
      t.down[i] = static_cast<float>(half_band(i + 1 - kHalfTaps - 0.5) / s);
    }
    // Fine sample 2j at coarse coordinate j - 1/4 reads coarse j + u,
    // u = -kHalfTaps/2 .. kHalfTaps/2 - 1, at fine distance 2 (u + 1/4).
    double se = 0, so = 0;
    for (int i = 0; i < kHalfTaps; ++i) {
      se += half_band(2.0 * (i - kHalfTaps / 2 + 0.25));
      so += half_band(2.0 * (i - kHalfTaps / 2 + 1 - 0.25));
    }
    for (int i = 0; i < kHalfTaps; ++i) {
      t.up_even[i] = static_cast<float>(half_band(2.0 * (i - kHalfTaps / 2 + 0.25)) / se);
      t.up_odd[i] = static_cast<float>(half_band(2.0 * (i - kHalfTaps / 2 + 1 - 0.25)) / so);
    }
    return t;
  }();
  return taps;
}

// Index into [0, n) by repeated whole-sample-symmetric reflection (x[-i] =
// x[i]), which keeps a pixel checkerboard a checkerboard across the border.
}  // namespace

int mirror(int i, int n) {
  if (n == 1) return 0;
  const int p = 2 * (n - 1);
  i %= p;
  if (i < 0) i += p;
  return i < n ? i : p - i;
}

// Halves a map in both directions (sizes rounded up) with the half-band filter.
Map down(const Map& in) {
  const HalfBandTaps& hb = half_band_taps();
  const int w = in.width, h = in.height;
  const int ow = (w + 1) / 2, oh = (h + 1) / 2;
  constexpr int n = 2 * kHalfTaps;
  const int lo = 1 - kHalfTaps;  // first input index read for output 0
  Map rows(ow, h);
  std::vector<float> pad(static_cast<size_t>(2 * ow + n));
  for (int y = 0; y < h; ++y) {
    const float* src = &in.values[static_cast<size_t>(y) * w];
    for (int i = 0; i < static_cast<int>(pad.size()); ++i) pad[i] = src[mirror(i + lo, w)];
    float* o = &rows.values[static_cast<size_t>(y) * ow];
    for (int t = 0; t < n; ++t) {
      const float c = hb.down[t];
      const float* q = pad.data() + t;
      for (int j = 0; j < ow; ++j) o[j] += c * q[2 * j];
    }
  }
  Map out(ow, oh);
  for (int j = 0; j < oh; ++j) {
    float* o = &out.values[static_cast<size_t>(j) * ow];
    for (int t = 0; t < n; ++t) {
      const float c = hb.down[t];
      const float* r = &rows.values[static_cast<size_t>(mirror(2 * j + t + lo, h)) * ow];
      for (int x = 0; x < ow; ++x) o[x] += c * r[x];
    }
  }
  return out;
}

// Doubles a map to (w, h) (each w, h at most twice the input's) with the
// half-band interpolator.
Map up(const Map& in, int w, int h) {
  const HalfBandTaps& hb = half_band_taps();
  const int cw = in.width, ch = in.height;
  constexpr int half = kHalfTaps / 2;
  // Columns first: (cw, ch) -> (cw, h).
  Map cols(cw, h);
  for (int y = 0; y < h; ++y) {
    const int j = y / 2;
    const bool odd = (y & 1) != 0;
    const float* taps = odd ? hb.up_odd.data() : hb.up_even.data();
    const int first = j - half + (odd ? 1 : 0);
    float* o = &cols.values[static_cast<size_t>(y) * cw];
    for (int t = 0; t < kHalfTaps; ++t) {
      const float c = taps[t];
      const float* r = &in.values[static_cast<size_t>(mirror(first + t, ch)) * cw];
      for (int x = 0; x < cw; ++x) o[x] += c * r[x];
    }
  }
  // Rows: (cw, h) -> (w, h), even and odd outputs separately.
  Map out(w, h);
  const int ne = (w + 1) / 2, no = w / 2;
  std::vector<float> pad(static_cast<size_t>(ne + kHalfTaps + 1)), even(ne), oddv(no);
  for (int y = 0; y < h; ++y) {
    const float* src = &cols.values[static_cast<size_t>(y) * cw];
    // pad[k] = coarse (k - half)
    for (int k = 0; k < static_cast<int>(pad.size()); ++k) pad[k] = src[mirror(k - half, cw)];
    std::fill(even.begin(), even.end(), 0.0f);
    std::fill(oddv.begin(), oddv.end(), 0.0f);
    for (int t = 0; t < kHalfTaps; ++t) {
      const float ce = hb.up_even[t], co = hb.up_odd[t];
      const float* qe = pad.data() + t;
      const float* qo = pad.data() + t + 1;
      for (int j = 0; j < ne; ++j) even[j] += ce * qe[j];
      for (int j = 0; j < no; ++j) oddv[j] += co * qo[j];
    }
    float* o = &out.values[static_cast<size_t>(y) * w];
    for (int j = 0; j < ne; ++j) o[2 * j] = even[j];
    for (int j = 0; j < no; ++j) o[2 * j + 1] = oddv[j];
  }
  return out;
}

// The ladder low-passes of the given cutoffs (cycles per sample) of a w x h
// region (row stride `stride`), by FFT over a mirror-padded domain.
}  // namespace foveate::metrics::detail
