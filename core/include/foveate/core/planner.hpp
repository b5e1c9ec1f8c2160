#pragma once
// Eccentricity layer planner of Guenter et al. (2012), section 4.3.
// Given the display and an MAR slope, choose the radii e_1 < ... < e_{n-1} of n
// nested layers that minimise the weighted pixel count (eq. 5), with each
// layer's sampling factor following from the previous radius (eq. 2), sizes
// from eq. 3 and pixel counts from eq. 4. The minimisation is exact over the
// grid of radii: the objective is a chain (layer i depends on e_{i-1} and e_i),
// so dynamic programming visits every combination the paper's brute force does
// in O(n * G^2).
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <vector>

#include "foveate/core/acuity.hpp"
#include "foveate/core/display.hpp"

namespace foveate {

struct PlannerOptions {
  int layers = 3;                  ///< n, 1..6 (1 = native rendering)
  double grid_step_deg = 0.05;     ///< discretisation of the radii
  std::vector<double> weights;     ///< w_i of eq. 5; empty = all 1
  std::optional<double> fixed_s2;  ///< the paper's "3*": s_2 fixed (e.g. 2)
  /// Most candidate radii (e* / grid_step_deg) searched; the search takes
  /// O(layers * G^2) time, so a finer step is refused with an error naming the
  /// limit (foveate plan --max-grid raises it).
  int max_grid_points = 10000;
  /// For a display with a lens: where the gaze is (pixels). The panel's
  /// resolution depends on where the layers fall, so every layer's sampling
  /// factor is at least the least buffer-pixels-per-panel-pixel (the finer of
  /// the panel's two directions) over the view angles its ring around this
  /// gaze covers. Without a gaze the plan must hold for any gaze: the least
  /// over the whole buffer. Ignored without a lens.
  std::optional<Vec2d> gaze;
};

struct Layer {
  double radius_deg = 0.0;       ///< e_i (the outer layer: e*)
  double radius_px = 0.0;        ///< e_i as a radius in native pixels at the display centre
  double sampling_factor = 1.0;  ///< s_i, pixel size as a multiple of the native pixel
  int width_px = 0;              ///< render-target size of the layer
  int height_px = 0;
  double pixels = 0.0;  ///< width_px * height_px (P_i)
};

struct LayerPlan {
  Display display;
  AcuityModel acuity;
  std::vector<Layer> layers;
  double native_pixels = 0.0;           ///< P* (eq. 8)
  double total_pixels = 0.0;            ///< sum of P_i
  double total_pixels_half_rate = 0.0;  ///< P_1 + sum_{i>1} P_i / 2
  /// P* / P: the speedup in pixels (the paper's "pixels" curve).
  [[nodiscard]] double pixel_ratio() const { return native_pixels / total_pixels; }
  /// P* / P with the outer layers counted at half rate (how the paper counts its
  /// measured 13.3x and 9.8x).
  [[nodiscard]] double pixel_ratio_half_rate() const {
    return native_pixels / total_pixels_half_rate;
  }
};

/// Throws foveate::Error for invalid options (layers outside 1..6, bad step, ...).
LayerPlan plan_layers(const Display& display, const AcuityModel& acuity,
                      const PlannerOptions& options = {});

/// Sampling factor s_{i+1} for a layer just outside eccentricity e (eq. 2), >= 1
/// (the acuity term alone: the lens term depends on the gaze, see PlannerOptions::gaze).
double sampling_factor_at(double eccentricity_deg, const AcuityModel& acuity, const Display& d);

void to_json(nlohmann::json& j, const LayerPlan& plan);

/// One row of the field-of-view sweep (eq. 9): a display whose sharpness equals
/// foveal acuity (w* = w0), aspect 3/4, for fields of view theta*.
struct SweepRow {
  double fov_deg = 0.0;
  double display_width_px = 0.0;  ///< D*(theta*) of eq. 9
  double native_pixels = 0.0;
  /// P*/P (unweighted, as the paper predicts) per variant, in the order of
  /// sweep_variants(), for quality A then B.
  std::vector<double> speedup_a;
  std::vector<double> speedup_b;
  std::vector<double> pixels_a;  ///< foveated pixel counts P, same order
  std::vector<double> pixels_b;
};

struct SweepVariant {
  const char* name;  ///< "2", "3", "4", "3*"
  int layers;
  std::optional<double> fixed_s2;
};
const std::vector<SweepVariant>& sweep_variants();

/// The data behind Figures 12 and 13 of Guenter et al.
std::vector<SweepRow> fov_sweep(double fov_from_deg = 10.0, double fov_to_deg = 120.0,
                                double fov_step_deg = 5.0, double grid_step_deg = 0.05,
                                int max_grid_points = PlannerOptions{}.max_grid_points);

}  // namespace foveate
