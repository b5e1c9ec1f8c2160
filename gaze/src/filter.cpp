#include "foveate/gaze/filter.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "foveate/core/error.hpp"

namespace foveate::gaze {

std::string FilterCounters::summary() const {
  std::string s = std::to_string(accepted) + " samples accepted, " + dropped.summary();
  s += ", " + std::to_string(low_confidence) + " low-confidence, " + std::to_string(invalid) +
       " invalid; " + std::to_string(hold_frames) + " of " + std::to_string(updates) +
       " frames held, " + std::to_string(fallback_frames) + " in fallback (" +
       std::to_string(fallbacks) + " times); " + std::to_string(saccades) + " saccades";
  return s;
}

GazeFilter::GazeFilter(FilterOptions options, Display display)
    : options_(options), display_(std::move(display)), validator_(options.off_screen_limit) {
  const FilterOptions& o = options_;
  auto bad = [](const char* what) { throw Error(std::string("gaze filter: ") + what); };
  if (!(o.min_confidence >= 0 && o.min_confidence <= 1)) bad("min_confidence must be in 0..1");
  if (!(o.hold_s >= 0 && o.hold_s <= 60)) bad("hold_s must be in 0..60 s");
  if (!(o.stale_s > 0 && o.stale_s <= 60)) bad("stale_s must be in (0, 60] s");
  if (!(o.fallback_fovea_scale >= 1 && o.fallback_fovea_scale <= 10)) {
    bad("fallback_fovea_scale must be in 1..10");
  }
  if (!(o.deadband_deg >= 0 && o.deadband_deg <= 10)) bad("deadband_deg must be in 0..10");
  if (!(o.saccade_threshold_deg_per_s > 0 && std::isfinite(o.saccade_threshold_deg_per_s))) {
    bad("saccade_threshold_deg_per_s must be > 0");
  }
  if (!(std::isfinite(o.fallback_pos.x) && std::isfinite(o.fallback_pos.y))) {
    bad("fallback_pos must be finite");
  }
  display_.validate();
}

FilteredGaze GazeFilter::update(const GazeSample& s, double now_s) {
  const FilterOptions& o = options_;
  ++counters_.updates;
  const bool repeat = have_last_ && s.time_s == last_.time_s && s.pos.x == last_.pos.x &&
                      s.pos.y == last_.pos.y && s.confidence == last_.confidence &&
                      s.valid == last_.valid;
  if (repeat) {
    ++counters_.repeats;  // the source had nothing new for this frame
  } else if (validator_.accept(s)) {
    ++counters_.accepted;
    have_last_ = true;
    last_ = s;
    const bool ok = s.valid && s.confidence >= o.min_confidence;
    if (!s.valid) {
      ++counters_.invalid;
    } else if (!ok) {
      ++counters_.low_confidence;
    }
    if (ok) {
      double velocity = 0.0;
      bool after_gap = !have_valid_ || last_was_lost_ || in_fallback_;
      if (have_valid_) {
        const double dt = s.time_s - last_valid_.time_s;
        if (dt > o.stale_s) {
          after_gap = true;  // a dropout: the jump since is not a velocity
        } else if (dt > 0) {
          velocity = angle_between_deg(display_, last_valid_.pos, s.pos) / dt;
        }
      }
      const bool was_saccade = in_saccade_;
      in_saccade_ = !after_gap && velocity > o.saccade_threshold_deg_per_s;
      if (in_saccade_ && !was_saccade) {
        ++counters_.saccades;
        sac_start_ = last_valid_.pos;
        sac_peak_ = 0.0;
      }
      if (in_saccade_) {
        sac_peak_ = std::max(sac_peak_, velocity);
        out_ = s.pos;
        if (o.predict_landing) {
          // Invert the main sequence: the peak velocity so far gives (a lower
          // bound of) the amplitude; continue along the direction travelled.
          const double done = angle_between_deg(display_, sac_start_, s.pos);
          const double predicted =
              std::max(done, o.main_sequence.amplitude_for_peak_deg(sac_peak_));
          if (done > 1e-9) {
            const double f = predicted / done;
            const double lo = -o.off_screen_limit, hi = 1.0 + o.off_screen_limit;
            out_ = {std::clamp(sac_start_.x + f * (s.pos.x - sac_start_.x), lo, hi),
                    std::clamp(sac_start_.y + f * (s.pos.y - sac_start_.y), lo, hi)};
          }
        }
      } else if (after_gap || was_saccade || settling_ ||
                 angle_between_deg(display_, out_, s.pos) >= o.deadband_deg) {
        // After a saccade the eye decelerates below the threshold before it
        // lands: follow it without the deadband until it has settled.
        settling_ = (was_saccade || settling_) && velocity > 0.25 * o.saccade_threshold_deg_per_s;
        out_ = s.pos;
      } else {
        ++counters_.deadband_suppressed;
      }
      have_valid_ = true;
      last_valid_ = s;
    }
    last_was_lost_ = !ok;
  }

  FilteredGaze f;
  const double age =
      have_valid_ ? now_s - last_valid_.time_s : std::numeric_limits<double>::infinity();
  if (have_valid_ && age <= o.hold_s) {
    f.pos = out_;
    f.valid = true;
    f.holding = last_was_lost_ || age > o.stale_s;
    f.in_saccade = in_saccade_ && !f.holding;
    f.fovea_scale = 1.0;
    f.sample_time_s = last_valid_.time_s;
    in_fallback_ = false;
    if (f.holding) ++counters_.hold_frames;
  } else {
    f.pos = o.fallback_pos;
    f.valid = false;
    f.fallback = true;
    f.fovea_scale = o.fallback_fovea_scale;
    f.sample_time_s = now_s;
    if (!in_fallback_ && have_valid_) ++counters_.fallbacks;
    in_fallback_ = true;
    in_saccade_ = false;
    settling_ = false;
    ++counters_.fallback_frames;
  }
  counters_.dropped = validator_.counts();
  return f;
}

}  // namespace foveate::gaze
