#pragma once
// Quality figures of a technique against native over a benchmark's frames.
#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "foveate/core/acuity.hpp"
#include "foveate/core/display.hpp"
#include "foveate/core/image.hpp"

namespace foveate::app {

class QualityAccumulator {
 public:
  QualityAccumulator(const Display& display, const AcuityModel& acuity);
  ~QualityAccumulator();
  /// One frame: the native image and the technique's, rendered with the same inputs.
  void add(const Image& reference, const Image& test, Vec2d gaze_px);
  /// Means over the frames added (JSON: psnr_db, ssim, bands[], acuity_rmse, ...).
  [[nodiscard]] nlohmann::json summary() const;
  /// Peripheral flicker relative to native's own frame-to-frame change.
  [[nodiscard]] double flicker_ratio() const;
  static Image heatmap(const Image& reference, const Image& test);
  [[nodiscard]] Image acuity_heatmap(const Image& reference, const Image& test,
                                     Vec2d gaze_px) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace foveate::app
