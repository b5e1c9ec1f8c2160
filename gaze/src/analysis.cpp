#include "foveate/gaze/analysis.hpp"

#include <algorithm>
#include <cmath>

#include "foveate/core/error.hpp"
#include "foveate/core/stats.hpp"

namespace foveate::gaze {

namespace {

// I-VT over a trace's samples: fixation and saccade runs between dropouts,
// appended to `st` as they close.
class IvtRuns {
 public:
  IvtRuns(const std::vector<GazeSample>& v, const Display& display, const IvtOptions& o,
          double gap_s, TraceStats& st)
      : v_(v), display_(display), o_(o), gap_s_(gap_s), st_(st) {}

  void run() {
    for (size_t i = 0; i < v_.size(); ++i) step(i);
    if (lost_since_) {  // lost until the end
      add_dropout(v_.back().time_s - (have_prev_ ? v_[prev_].time_s : v_.front().time_s));
    }
    if (have_prev_) close_run(prev_);
  }

 private:
  enum class Run { kNone, kFixation, kSaccade };

  [[nodiscard]] bool good(const GazeSample& s) const {
    return s.valid && s.confidence >= o_.min_confidence;
  }

  void add_dropout(double len) {
    ++st_.dropouts;
    st_.dropout_s += len;
    st_.longest_dropout_s = std::max(st_.longest_dropout_s, len);
  }

  void step(size_t i) {
    if (!good(v_[i])) {
      ++st_.lost_samples;
      lost_since_ = true;
      return;
    }
    const bool gap = have_prev_ && (lost_since_ || v_[i].time_s - v_[prev_].time_s > gap_s_);
    if (gap || (!have_prev_ && lost_since_)) {
      add_dropout(v_[i].time_s - (have_prev_ ? v_[prev_].time_s : v_.front().time_s));
      if (have_prev_) close_run(prev_);
      run_ = Run::kNone;
    }
    Run kind = Run::kFixation;
    double vel = 0.0;
    if (have_prev_ && !gap) {
      const double dt = v_[i].time_s - v_[prev_].time_s;
      vel = angle_between_deg(display_, v_[prev_].pos, v_[i].pos) / dt;
      if (vel > o_.velocity_deg_per_s) kind = Run::kSaccade;
    }
    if (kind != run_) {
      if (run_ != Run::kNone) close_run(prev_);
      run_ = kind;
      run_first_ = i;
      run_anchor_ = have_prev_ && !gap ? prev_ : i;
      run_peak_ = 0.0;
    }
    if (kind == Run::kSaccade) run_peak_ = std::max(run_peak_, vel);
    prev_ = i;
    have_prev_ = true;
    lost_since_ = false;
  }

  void close_run(size_t last) {
    if (run_ == Run::kFixation) {
      const double dur = v_[last].time_s - v_[run_first_].time_s;
      if (dur >= o_.min_fixation_s) {
        Fixation f;
        f.start_s = v_[run_first_].time_s;
        f.end_s = v_[last].time_s;
        double sx = 0, sy = 0;
        for (size_t k = run_first_; k <= last; ++k) {
          if (!good(v_[k])) continue;
          sx += v_[k].pos.x;
          sy += v_[k].pos.y;
        }
        const double n = static_cast<double>(last - run_first_ + 1);
        f.pos = {sx / n, sy / n};
        st_.fixations.push_back(f);
      }
    } else if (run_ == Run::kSaccade) {
      Saccade s;
      s.start_s = v_[run_anchor_].time_s;
      s.end_s = v_[last].time_s;
      s.amplitude_deg = angle_between_deg(display_, v_[run_anchor_].pos, v_[last].pos);
      s.peak_deg_per_s = run_peak_;
      st_.saccades.push_back(s);
    }
    run_ = Run::kNone;
  }

  const std::vector<GazeSample>& v_;
  const Display& display_;
  const IvtOptions& o_;
  double gap_s_;
  TraceStats& st_;
  Run run_ = Run::kNone;
  size_t run_first_ = 0;   // first sample of the run
  size_t run_anchor_ = 0;  // saccades: the sample before the run (its start point)
  double run_peak_ = 0.0;
  size_t prev_ = 0;  // previous good sample
  bool have_prev_ = false;
  bool lost_since_ = false;
};

}  // namespace

TraceStats analyze_trace(const Trace& trace, const Display& display, const IvtOptions& o) {
  if (!(o.velocity_deg_per_s > 0) || !(o.min_fixation_s >= 0) || !(o.dropout_intervals > 0)) {
    throw Error("I-VT: the velocity threshold and dropout interval must be > 0");
  }
  TraceStats st;
  const auto& v = trace.samples;
  st.samples = v.size();
  st.duration_s = trace.duration_s();
  st.dropped = trace.dropped;
  if (v.empty()) return st;

  std::vector<double> dts;
  for (size_t i = 1; i < v.size(); ++i) dts.push_back(v[i].time_s - v[i - 1].time_s);
  const double median_dt = quantile(dts, 0.5);
  st.rate_hz = median_dt > 0 ? 1.0 / median_dt : 0.0;
  const double gap_s = std::max(0.02, o.dropout_intervals * median_dt);
  IvtRuns(v, display, o, gap_s, st).run();

  double fix_total = 0;
  for (const Fixation& f : st.fixations) fix_total += f.end_s - f.start_s;
  st.mean_fixation_s =
      st.fixations.empty() ? 0.0 : fix_total / static_cast<double>(st.fixations.size());

  std::vector<double> lat;
  for (double x : trace.latency_ms) {
    if (std::isfinite(x)) lat.push_back(x);
  }
  if (!lat.empty()) {
    st.has_latency = true;
    st.latency_median_ms = quantile(lat, 0.5);
    st.latency_p95_ms = quantile(lat, 0.95);
    st.latency_max_ms = quantile(lat, 1.0);
  }
  return st;
}

}  // namespace foveate::gaze
