#pragma once
// End-to-end gaze latency: from the time of the gaze sample behind a frame to
// the time that frame is shown. The worst case over a sliding window feeds the
// latency-aware foveal size of Swafford et al., "Latency Aware Foveated
// Rendering in Unreal Engine 4" (2015), eq. 1 (foveate::LatencyAwareFovea).
#include <cstddef>
#include <cstdint>
#include <deque>

#include "foveate/core/models.hpp"
#include "foveate/gaze/filter.hpp"

namespace foveate::gaze {

struct LatencyOptions {
  std::size_t window = 600;  ///< frames kept (10 s at 60 Hz)
  double percentile = 95.0;  ///< the "worst case": this percentile, not the single max
  double extra_ms = 0.0;     ///< latency the renderer cannot see (display scan-out, ...)
};

class LatencyEstimator {
 public:
  explicit LatencyEstimator(LatencyOptions options = {});
  /// One frame: its gaze sample's time and the time it was shown (same clock).
  /// Negative or non-finite latencies are rejected and counted.
  void record(double sample_time_s, double shown_time_s);
  /// The same from the filter's output; held and fallback frames are skipped
  /// (their sample is not the gaze the frame follows).
  void record(const FilteredGaze& gaze, double shown_time_s);

  [[nodiscard]] std::size_t count() const { return window_.size(); }
  [[nodiscard]] std::uint64_t rejected() const { return rejected_; }
  /// Over the window, in milliseconds (0 when empty); extra_ms included.
  [[nodiscard]] double median_ms() const;
  [[nodiscard]] double p95_ms() const;
  [[nodiscard]] double max_ms() const;
  [[nodiscard]] double percentile_ms(double p) const;
  /// The latency to design for: the configured percentile (clamped to 0..1000 ms).
  [[nodiscard]] double worst_case_ms() const;
  /// `base` with latency_ms = worst_case_ms().
  [[nodiscard]] LatencyAwareFovea fovea_for(LatencyAwareFovea base = {}) const;
  /// Ratio of the latency-aware foveal diameter to the one without latency:
  /// how much a technique's foveal region should grow (>= 1).
  [[nodiscard]] double fovea_growth(const Display& display, LatencyAwareFovea base = {}) const;

 private:
  LatencyOptions options_;
  std::deque<double> window_;
  std::uint64_t rejected_ = 0;
};

}  // namespace foveate::gaze
