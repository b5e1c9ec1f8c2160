#pragma once
// FovVideoVDP's per-sample loops, over raw arrays so that they vectorise (and
// are built for AVX2 besides the baseline where the compiler can: the CPU
// picks at run time).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "fvvdp/csf.hpp"

namespace foveate::metrics::fvvdp {

/// The sustained and transient channels of one stream (test or reference)
/// at its newest frame: frames[0] is the oldest of `count`, frames[count - 1]
/// the newest, to which weights[0] applies.
void temporal_filter(const float* const* frames, std::size_t count, const float* sustained_weights,
                     const float* transient_weights, std::size_t pixels, float* sustained,
                     float* transient);

/// Where each sample's adapting luminance (max(background, 0.1), clamped to
/// the table) lies on the table's luminance axis, taken as uniform in log2.
void luminance_positions(const float* background, std::size_t n, const SensitivityTable& table,
                         std::int32_t* lo, float* frac);

/// log2 sensitivity where frequency and eccentricity are the same for every
/// sample: `column` holds the table interpolated along them at each of the
/// 32 luminance nodes.
void sensitivity_from_column(const std::int32_t* lo, const float* frac, std::size_t n,
                             const float* column, float* log_s);

/// Every sample's place in the table along frequency and eccentricity (one
/// array per field, so that the lookup vectorises): the offset of its lower
/// corner within a luminance slice, the strides to the upper nodes (0 where a
/// query sits on the table's edge) and the fractions.
struct SamplePositions {
  std::vector<std::int32_t> offset, rho_step, ecc_step;
  std::vector<float> rho_frac, ecc_frac;
  void resize(std::size_t n);
  void set(std::size_t i, const AxisPosition& rho, const AxisPosition& ecc);
};

/// log2 sensitivity with each sample's own frequency and eccentricity
/// (trilinear interpolation of the tables' values), for one or two tables
/// (the temporal channels share the positions); `values1` may be null.
void sensitivity_per_sample(const std::int32_t* lo, const float* frac,
                            const SamplePositions& positions, std::size_t n, const float* values0,
                            const float* values1, float* log_s0, float* log_s1);

struct MaskingConstants {
  float band_gain;   ///< 1 for the finest band, 2 for the others (the reference's scaling)
  float log2_k;      ///< log2 of the masking signal's coefficient
  float p, q;        ///< excitation and inhibition exponents
  float beta;        ///< spatial pooling exponent
  float log2_d_max;  ///< differences are clamped at 1e4
};

/// Sums of D^beta over a band's samples: all of them and per eccentricity band.
struct PooledDifference {
  double all = 0.0;
  std::vector<double> by_ecc_band;  ///< sized by the caller
};

/// D^beta per sample, pooled: Weber contrasts of test and reference against
/// the adapting luminance, normalised by the sensitivity, through the masking
/// model D = |T - R|^p / (1 + (k min(|T|, |R|))^q), summed over all samples and
/// per eccentricity band (ecc_band[i]: the band's index, or -1 for none).
/// `d_beta`, when not null, receives every sample's value.
void masked_difference(const float* test, const float* test_low, const float* reference,
                       const float* reference_low, const float* background, const float* log_s,
                       const std::int8_t* ecc_band, std::size_t n, const MaskingConstants& k,
                       PooledDifference& pooled, float* d_beta);

}  // namespace foveate::metrics::fvvdp
