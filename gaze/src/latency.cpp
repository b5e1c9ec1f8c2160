#include "foveate/gaze/latency.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "foveate/core/error.hpp"
#include "foveate/core/stats.hpp"

namespace foveate::gaze {

LatencyEstimator::LatencyEstimator(LatencyOptions options) : options_(options) {
  if (options_.window < 1) throw Error("latency window: must be at least 1 frame");
  if (!(options_.percentile >= 0 && options_.percentile <= 100)) {
    throw Error("latency percentile: expected 0..100");
  }
  if (!(std::isfinite(options_.extra_ms) && options_.extra_ms >= 0)) {
    throw Error("latency extra_ms: must be >= 0");
  }
}

void LatencyEstimator::record(double sample_time_s, double shown_time_s) {
  const double ms = (shown_time_s - sample_time_s) * 1e3;
  if (!std::isfinite(ms) || ms < 0.0) {
    ++rejected_;
    return;
  }
  window_.push_back(ms);
  while (window_.size() > options_.window) window_.pop_front();
}

void LatencyEstimator::record(const FilteredGaze& gaze, double shown_time_s) {
  if (!gaze.valid || gaze.holding || gaze.fallback) return;
  record(gaze.sample_time_s, shown_time_s);
}

double LatencyEstimator::percentile_ms(double p) const {
  if (window_.empty()) return options_.extra_ms;
  return quantile(std::vector<double>(window_.begin(), window_.end()), p / 100.0) +
         options_.extra_ms;
}

double LatencyEstimator::median_ms() const { return percentile_ms(50.0); }
double LatencyEstimator::p95_ms() const { return percentile_ms(95.0); }
double LatencyEstimator::max_ms() const { return percentile_ms(100.0); }

double LatencyEstimator::worst_case_ms() const {
  return std::clamp(percentile_ms(options_.percentile), 0.0, 1000.0);
}

LatencyAwareFovea LatencyEstimator::fovea_for(LatencyAwareFovea base) const {
  base.latency_ms = worst_case_ms();
  return base;
}

double LatencyEstimator::fovea_growth(const Display& display, LatencyAwareFovea base) const {
  LatencyAwareFovea zero = base;
  zero.latency_ms = 0.0;
  return fovea_for(base).diameter_px(display) / zero.diameter_px(display);
}

}  // namespace foveate::gaze
