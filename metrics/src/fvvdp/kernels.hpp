#pragma once
// FovVideoVDP's per-sample loops, over raw arrays so that they vectorise (and
// are built for AVX2 besides the baseline where the compiler can: the CPU
// picks at run time).
#include <cstddef>
#include <cstdint>

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

/// A sample's place in the table along frequency and eccentricity: the
/// offset of its lower corner within a luminance slice, the strides to the
/// upper nodes (0 where a query sits on the table's edge) and the fractions.
struct SamplePosition {
  std::int32_t offset = 0;
  std::int16_t rho_step = 0;
  std::int16_t ecc_step = 0;
  float rho_frac = 0;
  float ecc_frac = 0;
};
SamplePosition sample_position(const AxisPosition& rho, const AxisPosition& ecc);

/// log2 sensitivity with each sample's own frequency and eccentricity
/// (trilinear interpolation of the table), for `tables` tables at once
/// (the temporal channels share the positions).
void sensitivity_per_sample(const std::int32_t* lo, const float* frac,
                            const SamplePosition* positions, std::size_t n,
                            const SensitivityTable* const* table, float* const* log_s, int tables);

struct MaskingConstants {
  float band_gain;   ///< 1 for the finest band, 2 for the others (the reference's scaling)
  float log2_k;      ///< log2 of the masking signal's coefficient
  float p, q;        ///< excitation and inhibition exponents
  float beta;        ///< spatial pooling exponent
  float log2_d_max;  ///< differences are clamped at 1e4
};

/// D^beta per sample: Weber contrasts of test and reference against the
/// adapting luminance, normalised by the sensitivity, through the masking
/// model D = |T - R|^p / (1 + (k min(|T|, |R|))^q).
void masked_difference(const float* test, const float* test_low, const float* reference,
                       const float* reference_low, const float* background, const float* log_s,
                       std::size_t n, const MaskingConstants& k, float* d_beta);

}  // namespace foveate::metrics::fvvdp
