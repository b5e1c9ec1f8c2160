#pragma once
// The gaze filter between a source and the renderer: a confidence gate; the
// last valid gaze is held through blinks and dropouts for a bounded time, then
// the gaze falls back to a fixed point (the centre) with a widened fovea; a
// deadband against fixational jitter; saccade detection by velocity (I-VT),
// with an optional prediction of the landing point by inverting the main
// sequence. Bad samples are dropped and counted by the shared SampleValidator.
#include <cstdint>
#include <string>

#include "foveate/gaze/gaze.hpp"
#include "foveate/gaze/main_sequence.hpp"

namespace foveate::gaze {

struct FilterOptions {
  double min_confidence = 0.6;        ///< samples below are treated as lost
  double hold_s = 0.5;                ///< hold the last valid gaze this long
  double stale_s = 0.1;               ///< no new valid sample this long counts as holding
  Vec2d fallback_pos{0.5, 0.5};       ///< where to look after the hold (normalized)
  double fallback_fovea_scale = 2.0;  ///< how much wider the fovea is in fallback
  double deadband_deg = 0.3;          ///< moves smaller than this (outside saccades) are ignored
  double saccade_threshold_deg_per_s = 100.0;  ///< I-VT velocity threshold
  bool predict_landing = false;    ///< during saccades, report the predicted landing point
  MainSequence main_sequence;      ///< for the landing prediction
  double off_screen_limit = 0.25;  ///< SampleValidator's
};

struct FilteredGaze {
  Vec2d pos{0.5, 0.5};    ///< normalized, origin top-left
  bool valid = false;     ///< follows tracker data (live or held); false in fallback
  bool holding = false;   ///< the tracker lost the eye (blink, dropout): last gaze held
  bool fallback = false;  ///< held too long: fallback_pos with a widened fovea
  bool in_saccade = false;
  double fovea_scale = 1.0;    ///< 1 normally, fallback_fovea_scale in fallback
  double sample_time_s = 0.0;  ///< time of the sample behind pos (for latency)
};

struct FilterCounters {
  DropCounts dropped;
  std::uint64_t accepted = 0;
  std::uint64_t repeats = 0;  ///< the same sample again (no new data): ignored
  std::uint64_t low_confidence = 0;
  std::uint64_t invalid = 0;  ///< samples flagged invalid by the source
  std::uint64_t updates = 0;  ///< frames
  std::uint64_t hold_frames = 0;
  std::uint64_t fallback_frames = 0;
  std::uint64_t fallbacks = 0;  ///< times the filter entered fallback
  std::uint64_t saccades = 0;   ///< saccade onsets
  std::uint64_t deadband_suppressed = 0;
  [[nodiscard]] std::string summary() const;
};

class GazeFilter {
 public:
  GazeFilter(FilterOptions options, Display display);
  /// Feeds the source's sample for the frame at render time now_s.
  FilteredGaze update(const GazeSample& sample, double now_s);
  [[nodiscard]] const FilterCounters& counters() const { return counters_; }
  [[nodiscard]] const FilterOptions& options() const { return options_; }

 private:
  FilterOptions options_;
  Display display_;
  SampleValidator validator_;
  FilterCounters counters_;
  bool have_last_ = false;
  GazeSample last_;  ///< last accepted sample (any validity)
  bool have_valid_ = false;
  GazeSample last_valid_;  ///< last accepted valid, confident sample
  bool last_was_lost_ = false;
  Vec2d out_{0.5, 0.5};  ///< current output (after deadband)
  bool in_saccade_ = false;
  bool settling_ = false;  ///< just after a saccade: no deadband until the eye is slow
  bool in_fallback_ = false;
  Vec2d sac_start_{};
  double sac_peak_ = 0.0;
};

}  // namespace foveate::gaze
