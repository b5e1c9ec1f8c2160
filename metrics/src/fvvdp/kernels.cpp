#include "fvvdp/kernels.hpp"

#include <algorithm>
#include <cmath>

#include "fvvdp/fast_math.hpp"

// Build the hot loops for AVX2 too where GCC can dispatch at run time.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define FOVEATE_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define FOVEATE_CLONES
#endif

namespace foveate::metrics::fvvdp {

FOVEATE_CLONES
void temporal_filter(const float* const* frames, std::size_t count, const float* sustained_weights,
                     const float* transient_weights, std::size_t pixels, float* sustained,
                     float* transient) {
  // Blocks small enough for the two accumulators to stay in the L1 cache,
  // so that every frame is read once.
  constexpr std::size_t kBlock = 2048;
  for (std::size_t begin = 0; begin < pixels; begin += kBlock) {
    const std::size_t end = std::min(begin + kBlock, pixels);
    {
      const float ws = sustained_weights[count - 1], wt = transient_weights[count - 1];
      const float* f = frames[0];
      for (std::size_t i = begin; i < end; ++i) {
        sustained[i] = ws * f[i];
        transient[i] = wt * f[i];
      }
    }
    for (std::size_t k = 1; k < count; ++k) {
      const std::size_t age = count - 1 - k;
      const float ws = sustained_weights[age], wt = transient_weights[age];
      const float* f = frames[k];
      for (std::size_t i = begin; i < end; ++i) {
        sustained[i] += ws * f[i];
        transient[i] += wt * f[i];
      }
    }
  }
}

FOVEATE_CLONES
void luminance_positions(const float* background, std::size_t n, const SensitivityTable& table,
                         std::int32_t* lo, float* frac) {
  constexpr int last = SensitivityTable::kSize - 1;
  const float y_min = table.luminance[0], y_max = table.luminance[last];
  const float g0 = table.luminance_log2[0];
  const float inv_step = static_cast<float>(last) / (table.luminance_log2[last] - g0);
  for (std::size_t i = 0; i < n; ++i) {
    const float l = std::clamp(std::max(background[i], 0.1f), y_min, y_max);
    const float t = std::clamp((fast_log2(l) - g0) * inv_step, 0.0f, static_cast<float>(last));
    const auto j = std::min(static_cast<std::int32_t>(t), last - 1);
    lo[i] = j;
    frac[i] = t - static_cast<float>(j);
  }
}

void sensitivity_from_column(const std::int32_t* lo, const float* frac, std::size_t n,
                             const float* column, float* log_s) {
  for (std::size_t i = 0; i < n; ++i) {
    const float a = column[lo[i]], b = column[lo[i] + 1];
    log_s[i] = a + (b - a) * frac[i];
  }
}

void SamplePositions::resize(std::size_t n) {
  offset.resize(n);
  rho_step.resize(n);
  ecc_step.resize(n);
  rho_frac.resize(n);
  ecc_frac.resize(n);
}

void SamplePositions::set(std::size_t i, const AxisPosition& rho, const AxisPosition& ecc) {
  constexpr int n = SensitivityTable::kSize;
  offset[i] = rho.lo * n + ecc.lo;
  rho_step[i] = (rho.hi - rho.lo) * n;
  ecc_step[i] = ecc.hi - ecc.lo;
  rho_frac[i] = rho.frac;
  ecc_frac[i] = ecc.frac;
}

void sensitivity_per_sample(const std::int32_t* lo, const float* frac,
                            const SamplePositions& positions, std::size_t n, const float* values0,
                            const float* values1, float* log_s0, float* log_s1) {
  constexpr std::int32_t slice = SensitivityTable::kSize * SensitivityTable::kSize;
  const std::int32_t* offset = positions.offset.data();
  const std::int32_t* rho_step = positions.rho_step.data();
  const std::int32_t* ecc_step = positions.ecc_step.data();
  const float* rho_frac = positions.rho_frac.data();
  const float* ecc_frac = positions.ecc_frac.data();
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t b0 = lo[i] * slice + offset[i], b1 = b0 + slice;
    const std::int32_t dr = rho_step[i], de = ecc_step[i];
    const float fr = rho_frac[i], fe = ecc_frac[i], fy = frac[i];
    const auto trilinear = [&](const float* v) {
      const float a0 = v[b0] + (v[b0 + dr] - v[b0]) * fr;
      const float a1 = v[b0 + de] + (v[b0 + de + dr] - v[b0 + de]) * fr;
      const float c0 = v[b1] + (v[b1 + dr] - v[b1]) * fr;
      const float c1 = v[b1 + de] + (v[b1 + de + dr] - v[b1 + de]) * fr;
      const float a = a0 + (a1 - a0) * fe, c = c0 + (c1 - c0) * fe;
      return a + (c - a) * fy;
    };
    log_s0[i] = trilinear(values0);
    if (values1) log_s1[i] = trilinear(values1);
  }
}

namespace {

FOVEATE_CLONES
void masked_difference_block(const float* test, const float* test_low, const float* reference,
                             const float* reference_low, const float* background,
                             const float* log_s, std::size_t n, const MaskingConstants& k,
                             float* d_beta) {
  const float gain = k.band_gain, log2_k = k.log2_k, p = k.p, q = k.q, beta = k.beta;
  const float d_max = k.log2_d_max;
  for (std::size_t i = 0; i < n; ++i) {
    const float l = std::max(background[i], 0.1f);
    const float ct = std::min((test[i] - test_low[i]) / l, 1000.0f) * gain;
    const float cr = std::min((reference[i] - reference_low[i]) / l, 1000.0f) * gain;
    // In log2: D = (S |T - R|)^p / (1 + (k S min(|T|, |R|))^q).
    const float l_diff = log_s[i] + fast_log2(std::abs(ct - cr));
    const float l_mask = log_s[i] + log2_k + fast_log2(std::min(std::abs(ct), std::abs(cr)));
    const float l_d = std::min(p * l_diff - fast_log2(1.0f + fast_exp2(q * l_mask)), d_max);
    d_beta[i] = fast_exp2(beta * l_d);
  }
}

}  // namespace

void masked_difference(const float* test, const float* test_low, const float* reference,
                       const float* reference_low, const float* background, const float* log_s,
                       const std::int8_t* ecc_band, std::size_t n, const MaskingConstants& k,
                       PooledDifference& pooled, float* d_beta) {
  // Blocks that stay in the L1 cache between computing and pooling.
  constexpr std::size_t kBlock = 1024;
  float block[kBlock];
  for (std::size_t begin = 0; begin < n; begin += kBlock) {
    const std::size_t count = std::min(kBlock, n - begin);
    float* out = d_beta ? d_beta + begin : block;
    masked_difference_block(test + begin, test_low + begin, reference + begin,
                            reference_low + begin, background + begin, log_s + begin, count, k,
                            out);
    double all = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
      all += out[i];
      const int e = ecc_band[begin + i];
      if (e >= 0) pooled.by_ecc_band[static_cast<std::size_t>(e)] += out[i];
    }
    pooled.all += all;
  }
}

}  // namespace foveate::metrics::fvvdp
