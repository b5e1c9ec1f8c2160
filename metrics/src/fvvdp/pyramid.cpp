#include "fvvdp/pyramid.hpp"

#include <algorithm>
#include <cmath>

namespace foveate::metrics::fvvdp {

namespace {

// The (source index, weight) pairs of output sample i of a reduction along an
// axis of n samples: kKernel centred on 2i over the samples that exist, plus
// the reference's corrections for the missing ones at both ends. At the end
// the correction is the one for an axis of `parity_n` samples' parity.
struct Taps {
  int index[7];
  float weight[7];
  int count = 0;
  void add(int i, float w) {
    index[count] = i;
    weight[count] = w;
    ++count;
  }
};

Taps reduce_taps(int i, int n, int parity_n) {
  Taps t;
  const int m = (n + 1) / 2;
  const int c = 2 * i;
  for (int j = 0; j < 5; ++j) {
    const int s = c + j - 2;
    if (s >= 0 && s < n) t.add(s, kKernel[j]);
  }
  const auto at = [n](int s) { return std::clamp(s, 0, n - 1); };
  if (i == 0) {
    t.add(at(0), kKernel[1]);
    t.add(at(1), kKernel[0]);
  }
  if (i == m - 1) {
    if (parity_n % 2 == 1) {
      t.add(at(n - 1), kKernel[3]);
      t.add(at(n - 2), kKernel[4]);
    } else {
      t.add(at(n - 1), kKernel[4]);
    }
  }
  return t;
}

}  // namespace

Map reduce(const Map& in) {
  Map out, rows;
  reduce(in, out, rows);
  return out;
}

void reduce(const Map& in, Map& out, Map& rows) {
  const int w = in.width, h = in.height;
  const int ow = (w + 1) / 2, oh = (h + 1) / 2;
  // Vertical pass: each output row is a weighted sum of input rows.
  resize(rows, w, oh);
  for (int i = 0; i < oh; ++i) {
    float* dst = &rows.values[static_cast<size_t>(i) * w];
    if (i > 0 && 2 * i + 2 < h) {
      // Interior rows: the five taps in one pass.
      const float* r0 = &in.values[static_cast<size_t>(2 * i - 2) * w];
      const float *r1 = r0 + w, *r2 = r1 + w, *r3 = r2 + w, *r4 = r3 + w;
      for (int x = 0; x < w; ++x) {
        dst[x] = kKernel[0] * r0[x] + kKernel[1] * r1[x] + kKernel[2] * r2[x] + kKernel[3] * r3[x] +
                 kKernel[4] * r4[x];
      }
      continue;
    }
    const Taps t = reduce_taps(i, h, h);
    {
      const float* src = &in.values[static_cast<size_t>(t.index[0]) * w];
      const float w0 = t.weight[0];
      for (int x = 0; x < w; ++x) dst[x] = w0 * src[x];
    }
    for (int k = 1; k < t.count; ++k) {
      const float* src = &in.values[static_cast<size_t>(t.index[k]) * w];
      const float wk = t.weight[k];
      for (int x = 0; x < w; ++x) dst[x] += wk * src[x];
    }
  }
  // Horizontal pass: interior samples directly, the two ends through their taps.
  resize(out, ow, oh);
  const Taps first = reduce_taps(0, w, h);
  const Taps last = reduce_taps(ow - 1, w, h);
  for (int y = 0; y < oh; ++y) {
    const float* src = &rows.values[static_cast<size_t>(y) * w];
    float* dst = &out.values[static_cast<size_t>(y) * ow];
    for (int x = 1; x < ow - 1; ++x) {
      const float* s = src + 2 * x - 2;
      dst[x] = kKernel[0] * s[0] + kKernel[1] * s[1] + kKernel[2] * s[2] + kKernel[3] * s[3] +
               kKernel[4] * s[4];
    }
    const auto apply = [&](const Taps& t, int x) {
      float v = 0.0f;
      for (int k = 0; k < t.count; ++k) v += t.weight[k] * src[t.index[k]];
      dst[x] = v;
    };
    apply(first, 0);
    if (ow > 1) apply(last, ow - 1);
  }
}

void expand(const Map& in, int width, int height, Map& out) {
  Map rows;
  expand(in, width, height, out, rows);
}

void expand(const Map& in, int width, int height, Map& out, Map& rows) {
  const int m = in.width, mh = in.height;
  // Vertical pass to (m x height): even rows 0.1, 0.8, 0.1 of rows s-1, s,
  // s+1; odd rows the mean of rows s and s+1; indices clamped to the input.
  resize(rows, m, height);
  const auto row = [&](int s) {
    return &in.values[static_cast<size_t>(std::clamp(s, 0, mh - 1)) * m];
  };
  constexpr float a = 2.0f * kKernel[0], b = 2.0f * kKernel[2], c = 2.0f * kKernel[1];
  for (int y = 0; y < height; ++y) {
    const int s = y / 2;
    float* dst = &rows.values[static_cast<size_t>(y) * m];
    if (y % 2 == 0) {
      const float *r0 = row(s - 1), *r1 = row(s), *r2 = row(s + 1);
      for (int x = 0; x < m; ++x) dst[x] = a * r0[x] + b * r1[x] + a * r2[x];
    } else {
      const float *r1 = row(s), *r2 = row(s + 1);
      for (int x = 0; x < m; ++x) dst[x] = c * r1[x] + c * r2[x];
    }
  }
  resize(out, width, height);
  for (int y = 0; y < height; ++y) {
    const float* src = &rows.values[static_cast<size_t>(y) * m];
    float* dst = &out.values[static_cast<size_t>(y) * width];
    const auto at = [&](int s) { return src[std::clamp(s, 0, m - 1)]; };
    // Interior without clamping, ends with it.
    const int interior_end = std::min(width / 2, m - 1);
    int s = 0;
    if (width > 0) dst[0] = a * at(-1) + b * at(0) + a * at(1);
    if (width > 1) dst[1] = c * at(0) + c * at(1);
    for (s = 1; s < interior_end; ++s) {
      dst[2 * s] = a * src[s - 1] + b * src[s] + a * src[s + 1];
      if (2 * s + 1 < width) dst[2 * s + 1] = c * src[s] + c * src[s + 1];
    }
    for (; 2 * s < width; ++s) {
      dst[2 * s] = a * at(s - 1) + b * at(s) + a * at(s + 1);
      if (2 * s + 1 < width) dst[2 * s + 1] = c * at(s) + c * at(s + 1);
    }
  }
}

int band_count(int width, int height, double ppd) {
  const int max_levels = static_cast<int>(std::floor(std::log2(std::min(width, height)))) - 1;
  int first_low = -1;
  for (int b = 0; b < 15; ++b) {
    if (band_frequency(b, ppd) <= 0.5) {
      first_low = b;
      break;
    }
  }
  const int wanted = first_low < 0 ? max_levels : first_low + 1;
  return std::clamp(wanted, 0, std::max(max_levels, 0));
}

double band_frequency(int band, double ppd) {
  return (band == 0 ? 1.0 : 0.3228 * std::pow(2.0, -(band - 1))) * ppd / 2.0;
}

}  // namespace foveate::metrics::fvvdp
