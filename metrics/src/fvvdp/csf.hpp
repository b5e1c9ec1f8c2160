#pragma once
// FovVideoVDP's contrast sensitivity: how sensitive the eye is to a band of
// spatial frequency rho (cycles per degree) and temporal frequency omega (Hz)
// on a background of luminance L (cd/m^2) at eccentricity e (degrees). The
// metric reads it from a table over (log2 rho, log2 L, sqrt e), interpolated
// linearly, as its reference implementation does.
#include <array>
#include <vector>

#include "foveate/metrics/fvvdp.hpp"

namespace foveate::metrics::fvvdp {

/// Sensitivity (1 / threshold Weber contrast) before the metric's gain:
///  * cortical magnification (Dougherty et al. 2003, M(e) = 29.2 / (e + 3.67)
///    mm/deg) relative to the fovea, raised to k_cm, scales the stimulus:
///    the frequency becomes rho / M_rel and the size sigma M_rel;
///  * the stimulus is a disc of radius sigma = 1.5 cycles (csf_sigma < 0);
///  * the achromatic CSF of Mantiuk et al. 2020 ("Practical colour contrast
///    sensitivity functions for luminance levels up to 10 000 cd/m^2", CIC
///    28), evaluated for a D65 background of luminance L, gives the
///    sensitivity to a static pattern of that frequency, size and luminance;
///  * the spatio-velocity CSF of Laird et al. 2006 (Daly's model) gives the
///    relative change with temporal frequency, S(rho, omega) / S(rho, 0).
double sensitivity(double rho_cpd, double omega_hz, double luminance_cd_m2, double ecc_deg,
                   const FvvdpParameters& parameters);

/// Where a query falls on a table's axis: value = (1 - frac) at[lo] + frac at[hi].
struct AxisPosition {
  int lo = 0;
  int hi = 0;
  float frac = 0;
};

/// A 32 x 32 x 32 table of log2 sensitivity over log2 luminance (0.001 to
/// 10 000 cd/m^2), log2 frequency (1/16 to 64 cpd) and the square root of
/// eccentricity (0 to 120 degrees), in single precision like the reference's.
struct SensitivityTable {
  static constexpr int kSize = 32;
  std::array<float, kSize> luminance{};  ///< cd/m^2
  std::array<float, kSize> rho{};        ///< cycles per degree
  std::array<float, kSize> ecc{};        ///< degrees
  std::array<float, kSize> luminance_log2{};
  std::array<float, kSize> rho_log2{};
  std::array<float, kSize> ecc_sqrt{};
  /// log2 sensitivity at [luminance][rho][ecc], including the metric's gain.
  std::vector<float> values;

  [[nodiscard]] float at(int luminance_index, int rho_index, int ecc_index) const {
    return values[(static_cast<size_t>(luminance_index) * kSize + rho_index) * kSize + ecc_index];
  }
  /// Positions of a query on each axis, clamped to the table's range.
  [[nodiscard]] AxisPosition locate_luminance(float cd_m2) const;
  [[nodiscard]] AxisPosition locate_rho(float cpd) const;
  [[nodiscard]] AxisPosition locate_ecc(float deg) const;
  /// Trilinear interpolation of log2 sensitivity.
  [[nodiscard]] float lookup(const AxisPosition& luminance_pos, const AxisPosition& rho_pos,
                             const AxisPosition& ecc_pos) const;
};

/// The table for one temporal frequency, with the gain
/// 10^(sensitivity_correction_db / 20) folded in.
SensitivityTable make_sensitivity_table(double omega_hz, const FvvdpParameters& parameters);

/// Position of `q` on an ascending grid as the reference interpolates it: the
/// upper node is the first not below q, the fraction is taken against the
/// nodes' distance plus 1e-6 and never negative.
AxisPosition locate(const std::array<float, SensitivityTable::kSize>& grid, float q);

}  // namespace foveate::metrics::fvvdp
