// Mixed-radix Stockham FFT (decimation in frequency, self-sorting), written for
// this library. A stage of radix r splits each sub-transform of length L into r
// interleaved ones of length m = L / r:
//   y[s (r p + k) + q] = w_L^(p k) * sum_j x[s (p + j m) + q] * w_r^(j k),
// for p < m, k < r and the s sub-transforms q of the stage, with
// w_N = exp(-2 pi i / N). After all stages the result is in natural order.
// Every "element" is a vector of v complex numbers, so the innermost loop runs
// over s * v contiguous floats and vectorises; the column pass of a 2-D
// transform uses whole rows as elements, the row pass transposes blocks of
// rows.
#include "fft.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "foveate/core/error.hpp"

namespace foveate::metrics::detail {

int fft_size(int n) {
  n = std::max(n, 4);
  for (int c = n;; ++c) {
    if (c % 4 != 0) continue;
    int r = c;
    for (int f : {2, 3, 5}) {
      while (r % f == 0) r /= f;
    }
    if (r == 1) return c;
  }
}

FftPlan::FftPlan(int n) : n_(n) {
  if (n < 1) throw Error("fft: the size must be positive");
  std::vector<int> radices;
  int r = n;
  while (r % 4 == 0) radices.push_back(4), r /= 4;
  while (r % 2 == 0) radices.push_back(2), r /= 2;
  while (r % 3 == 0) radices.push_back(3), r /= 3;
  while (r % 5 == 0) radices.push_back(5), r /= 5;
  if (r != 1) throw Error("fft: the size " + std::to_string(n) + " has a prime factor above 5");
  int length = n, stride = 1;
  for (int radix : radices) {
    Stage st{radix, length, stride, tw_re_.size()};
    const int m = length / radix;
    for (int p = 0; p < m; ++p) {
      for (int k = 1; k < radix; ++k) {
        // Reduce the exponent first so that the angle stays accurate.
        const long e = static_cast<long>(p) * k % length;
        const double a = -2.0 * std::numbers::pi * static_cast<double>(e) / length;
        tw_re_.push_back(static_cast<float>(std::cos(a)));
        tw_im_.push_back(static_cast<float>(std::sin(a)));
      }
    }
    stages_.push_back(st);
    length = m;
    stride *= radix;
  }
}

namespace {

// Multiplies (re, im) by (wr, wi) in place for n values.
inline void twiddle(float* re, float* im, float wr, float wi, int n) {
  for (int t = 0; t < n; ++t) {
    const float a = re[t], b = im[t];
    re[t] = a * wr - b * wi;
    im[t] = a * wi + b * wr;
  }
}

}  // namespace

void FftPlan::transform(float* re, float* im, int v, bool inverse, std::vector<float>& work) const {
  const size_t total = static_cast<size_t>(n_) * v;
  if (stages_.empty()) return;
  work.resize(2 * total);
  float* xr = re;
  float* xi = im;
  float* yr = work.data();
  float* yi = work.data() + total;
  const float sign = inverse ? 1.0f : -1.0f;  // sign of the exponent
  for (const Stage& st : stages_) {
    const int r = st.radix;
    const int m = st.length / r;
    const int block = st.stride * v;  // contiguous floats per (p, j)
    const float* twr = tw_re_.data() + st.twiddles;
    const float* twi = tw_im_.data() + st.twiddles;
    for (int p = 0; p < m; ++p) {
      const float* ar[5];
      const float* ai[5];
      float* br[5];
      float* bi[5];
      for (int j = 0; j < r; ++j) {
        const size_t in = static_cast<size_t>(st.stride) * (p + j * m) * v;
        const size_t out = static_cast<size_t>(st.stride) * (r * p + j) * v;
        ar[j] = xr + in;
        ai[j] = xi + in;
        br[j] = yr + out;
        bi[j] = yi + out;
      }
      if (r == 2) {
        for (int t = 0; t < block; ++t) {
          const float a0r = ar[0][t], a0i = ai[0][t], a1r = ar[1][t], a1i = ai[1][t];
          br[0][t] = a0r + a1r;
          bi[0][t] = a0i + a1i;
          br[1][t] = a0r - a1r;
          bi[1][t] = a0i - a1i;
        }
      } else if (r == 4) {
        for (int t = 0; t < block; ++t) {
          const float t0r = ar[0][t] + ar[2][t], t0i = ai[0][t] + ai[2][t];
          const float t1r = ar[0][t] - ar[2][t], t1i = ai[0][t] - ai[2][t];
          const float t2r = ar[1][t] + ar[3][t], t2i = ai[1][t] + ai[3][t];
          // t3 = (a1 - a3) times the sign of the exponent times i.
          const float d3r = ar[1][t] - ar[3][t], d3i = ai[1][t] - ai[3][t];
          const float t3r = -sign * d3i, t3i = sign * d3r;
          br[0][t] = t0r + t2r;
          bi[0][t] = t0i + t2i;
          br[2][t] = t0r - t2r;
          bi[2][t] = t0i - t2i;
          br[1][t] = t1r + t3r;
          bi[1][t] = t1i + t3i;
          br[3][t] = t1r - t3r;
          bi[3][t] = t1i - t3i;
        }
      } else if (r == 3) {
        const float h = sign * static_cast<float>(std::sqrt(3.0) / 2.0);
        for (int t = 0; t < block; ++t) {
          const float sr = ar[1][t] + ar[2][t], si = ai[1][t] + ai[2][t];
          const float dr = ar[1][t] - ar[2][t], di = ai[1][t] - ai[2][t];
          const float mr = ar[0][t] - 0.5f * sr, mi = ai[0][t] - 0.5f * si;
          br[0][t] = ar[0][t] + sr;
          bi[0][t] = ai[0][t] + si;
          // w_3 = -1/2 + i h: b1 = m + i h d, b2 = m - i h d.
          br[1][t] = mr - h * di;
          bi[1][t] = mi + h * dr;
          br[2][t] = mr + h * di;
          bi[2][t] = mi - h * dr;
        }
      } else {  // r == 5
        const float c1 = static_cast<float>(std::cos(2 * std::numbers::pi / 5));
        const float c2 = static_cast<float>(std::cos(4 * std::numbers::pi / 5));
        const float s1 = sign * static_cast<float>(std::sin(2 * std::numbers::pi / 5));
        const float s2 = sign * static_cast<float>(std::sin(4 * std::numbers::pi / 5));
        for (int t = 0; t < block; ++t) {
          const float p1r = ar[1][t] + ar[4][t], p1i = ai[1][t] + ai[4][t];
          const float q1r = ar[1][t] - ar[4][t], q1i = ai[1][t] - ai[4][t];
          const float p2r = ar[2][t] + ar[3][t], p2i = ai[2][t] + ai[3][t];
          const float q2r = ar[2][t] - ar[3][t], q2i = ai[2][t] - ai[3][t];
          const float a0r = ar[0][t], a0i = ai[0][t];
          br[0][t] = a0r + p1r + p2r;
          bi[0][t] = a0i + p1i + p2i;
          const float m1r = a0r + c1 * p1r + c2 * p2r, m1i = a0i + c1 * p1i + c2 * p2i;
          const float m2r = a0r + c2 * p1r + c1 * p2r, m2i = a0i + c2 * p1i + c1 * p2i;
          // i * (s1 q1 + s2 q2) and i * (s2 q1 - s1 q2), with the exponent's sign.
          const float n1r = s1 * q1r + s2 * q2r, n1i = s1 * q1i + s2 * q2i;
          const float n2r = s2 * q1r - s1 * q2r, n2i = s2 * q1i - s1 * q2i;
          br[1][t] = m1r - n1i;
          bi[1][t] = m1i + n1r;
          br[4][t] = m1r + n1i;
          bi[4][t] = m1i - n1r;
          br[2][t] = m2r - n2i;
          bi[2][t] = m2i + n2r;
          br[3][t] = m2r + n2i;
          bi[3][t] = m2i - n2r;
        }
      }
      if (p > 0) {
        for (int k = 1; k < r; ++k) {
          const size_t w = static_cast<size_t>(p) * (r - 1) + (k - 1);
          twiddle(br[k], bi[k], twr[w], inverse ? -twi[w] : twi[w], block);
        }
      }
    }
    std::swap(xr, yr);
    std::swap(xi, yi);
  }
  if (xr != re) {
    std::copy(xr, xr + total, re);
    std::copy(xi, xi + total, im);
  }
}

const FftPlan& fft_plan(int n) {
  thread_local std::map<int, FftPlan> plans;
  auto it = plans.find(n);
  if (it == plans.end()) it = plans.emplace(n, FftPlan(n)).first;
  return it->second;
}

namespace {

constexpr int kRowBlock = 16;  // row pairs transformed together

}  // namespace

HalfSpectrum rfft2(const float* data, int w, int h) {
  if (w < 2 || h < 2 || w % 2 != 0 || h % 2 != 0) {
    throw Error("rfft2: the size must be even in both directions");
  }
  HalfSpectrum s;
  s.w = w;
  s.h = h;
  const int hw = s.stride();
  s.re.assign(static_cast<size_t>(hw) * h, 0.0f);
  s.im.assign(static_cast<size_t>(hw) * h, 0.0f);
  const FftPlan& rows = fft_plan(w);
  std::vector<float> tr, ti, work;
  // Rows in pairs: z = row a + i row b; then X_a[k] = (Z[k] + conj Z[-k]) / 2
  // and X_b[k] = (Z[k] - conj Z[-k]) / (2 i).
  for (int y0 = 0; y0 < h; y0 += 2 * kRowBlock) {
    const int pairs = std::min(kRowBlock, (h - y0) / 2);
    tr.assign(static_cast<size_t>(w) * pairs, 0.0f);
    ti.assign(static_cast<size_t>(w) * pairs, 0.0f);
    for (int b = 0; b < pairs; ++b) {
      const float* ra = data + static_cast<size_t>(y0 + 2 * b) * w;
      const float* rb = ra + w;
      for (int x = 0; x < w; ++x) {
        tr[static_cast<size_t>(x) * pairs + b] = ra[x];
        ti[static_cast<size_t>(x) * pairs + b] = rb[x];
      }
    }
    rows.transform(tr.data(), ti.data(), pairs, false, work);
    for (int b = 0; b < pairs; ++b) {
      float* oar = &s.re[static_cast<size_t>(y0 + 2 * b) * hw];
      float* oai = &s.im[static_cast<size_t>(y0 + 2 * b) * hw];
      float* obr = oar + hw;
      float* obi = oai + hw;
      for (int k = 0; k < hw; ++k) {
        const int nk = k == 0 ? 0 : w - k;
        const float zr = tr[static_cast<size_t>(k) * pairs + b];
        const float zi = ti[static_cast<size_t>(k) * pairs + b];
        const float cr = tr[static_cast<size_t>(nk) * pairs + b];
        const float ci = -ti[static_cast<size_t>(nk) * pairs + b];
        oar[k] = 0.5f * (zr + cr);
        oai[k] = 0.5f * (zi + ci);
        // (z - c) / (2 i) = -i (z - c) / 2
        obr[k] = 0.5f * (zi - ci);
        obi[k] = -0.5f * (zr - cr);
      }
    }
  }
  fft_plan(h).transform(s.re.data(), s.im.data(), hw, false, work);
  return s;
}

void irfft2(HalfSpectrum s, float* out) {
  const int w = s.w, h = s.h;
  const int hw = s.stride();
  std::vector<float> tr, ti, work;
  fft_plan(h).transform(s.re.data(), s.im.data(), hw, true, work);
  const FftPlan& rows = fft_plan(w);
  for (int y0 = 0; y0 < h; y0 += 2 * kRowBlock) {
    const int pairs = std::min(kRowBlock, (h - y0) / 2);
    tr.assign(static_cast<size_t>(w) * pairs, 0.0f);
    ti.assign(static_cast<size_t>(w) * pairs, 0.0f);
    for (int b = 0; b < pairs; ++b) {
      const float* ar = &s.re[static_cast<size_t>(y0 + 2 * b) * hw];
      const float* ai = &s.im[static_cast<size_t>(y0 + 2 * b) * hw];
      const float* br = ar + hw;
      const float* bi = ai + hw;
      // Z[k] = X_a[k] + i X_b[k]; Z[w - k] = conj X_a[k] + i conj X_b[k]. The
      // bins 0 and w/2 of a real row are real.
      for (int k = 0; k < hw; ++k) {
        const bool edge = k == 0 || k == w / 2;
        const float xar = ar[k], xai = edge ? 0.0f : ai[k];
        const float xbr = br[k], xbi = edge ? 0.0f : bi[k];
        tr[static_cast<size_t>(k) * pairs + b] = xar - xbi;
        ti[static_cast<size_t>(k) * pairs + b] = xai + xbr;
        if (!edge) {
          tr[static_cast<size_t>(w - k) * pairs + b] = xar + xbi;
          ti[static_cast<size_t>(w - k) * pairs + b] = -xai + xbr;
        }
      }
    }
    rows.transform(tr.data(), ti.data(), pairs, true, work);
    for (int b = 0; b < pairs; ++b) {
      float* oa = out + static_cast<size_t>(y0 + 2 * b) * w;
      float* ob = oa + w;
      for (int x = 0; x < w; ++x) {
        oa[x] = tr[static_cast<size_t>(x) * pairs + b];
        ob[x] = ti[static_cast<size_t>(x) * pairs + b];
      }
    }
  }
}

}  // namespace foveate::metrics::detail
