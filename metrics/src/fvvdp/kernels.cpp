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

SamplePosition sample_position(const AxisPosition& rho, const AxisPosition& ecc) {
  constexpr int n = SensitivityTable::kSize;
  SamplePosition p;
  p.offset = rho.lo * n + ecc.lo;
  p.rho_step = static_cast<std::int16_t>((rho.hi - rho.lo) * n);
  p.ecc_step = static_cast<std::int16_t>(ecc.hi - ecc.lo);
  p.rho_frac = rho.frac;
  p.ecc_frac = ecc.frac;
  return p;
}

void sensitivity_per_sample(const std::int32_t* lo, const float* frac,
                            const SamplePosition* positions, std::size_t n,
                            const SensitivityTable* const* table, float* const* log_s, int tables) {
  constexpr std::size_t slice = SensitivityTable::kSize * SensitivityTable::kSize;
  const float* values0 = table[0]->values.data();
  const float* values1 = tables > 1 ? table[1]->values.data() : nullptr;
  for (std::size_t i = 0; i < n; ++i) {
    const SamplePosition& p = positions[i];
    const std::size_t base = static_cast<std::size_t>(lo[i]) * slice + p.offset;
    const int dr = p.rho_step, de = p.ecc_step;
    const float fr = p.rho_frac, fe = p.ecc_frac, fy = frac[i];
    const auto bilinear = [&](const float* v) {
      const float e0 = v[0] + (v[dr] - v[0]) * fr;
      const float e1 = v[de] + (v[de + dr] - v[de]) * fr;
      return e0 + (e1 - e0) * fe;
    };
    const auto trilinear = [&](const float* values) {
      const float a = bilinear(values + base), b = bilinear(values + base + slice);
      return a + (b - a) * fy;
    };
    log_s[0][i] = trilinear(values0);
    if (values1) log_s[1][i] = trilinear(values1);
  }
}

FOVEATE_CLONES
void masked_difference(const float* test, const float* test_low, const float* reference,
                       const float* reference_low, const float* background, const float* log_s,
                       std::size_t n, const MaskingConstants& k, float* d_beta) {
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

}  // namespace foveate::metrics::fvvdp
