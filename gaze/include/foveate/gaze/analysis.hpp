#pragma once
// Trace statistics: sample rate, dropouts, and fixations and saccades found
// by the velocity-threshold identification (I-VT) of Salvucci and Goldberg,
// "Identifying fixations and saccades in eye-tracking protocols" (ETRA 2000):
// point-to-point angular velocities above the threshold are saccade samples,
// the rest fixation samples; consecutive fixation samples form a fixation,
// kept when it lasts at least min_fixation_s.
#include <string>
#include <vector>

#include "foveate/gaze/trace.hpp"

namespace foveate::gaze {

struct IvtOptions {
  double velocity_deg_per_s = 100.0;
  double min_fixation_s = 0.06;
  double min_confidence = 0.6;  ///< samples below count as lost
  /// A gap between samples longer than this many median intervals (and at
  /// least 20 ms) is a dropout.
  double dropout_intervals = 3.0;
};

struct Fixation {
  double start_s = 0, end_s = 0;
  Vec2d pos{};  ///< mean position, normalized
};

struct Saccade {
  double start_s = 0, end_s = 0;
  double amplitude_deg = 0;
  double peak_deg_per_s = 0;
};

struct TraceStats {
  std::size_t samples = 0;
  double duration_s = 0;
  double rate_hz = 0;            ///< 1 / median interval
  std::size_t lost_samples = 0;  ///< invalid or below min_confidence
  std::size_t dropouts = 0;      ///< episodes: gaps and runs of lost samples
  double dropout_s = 0;          ///< total time in dropouts
  double longest_dropout_s = 0;
  std::vector<Fixation> fixations;
  std::vector<Saccade> saccades;
  double mean_fixation_s = 0;
  DropCounts dropped;
  bool has_latency = false;
  double latency_median_ms = 0, latency_p95_ms = 0, latency_max_ms = 0;
};

TraceStats analyze_trace(const Trace& trace, const Display& display,
                         const IvtOptions& options = {});

}  // namespace foveate::gaze
