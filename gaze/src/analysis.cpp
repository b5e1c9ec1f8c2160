#include "foveate/gaze/analysis.hpp"

#include <algorithm>
#include <cmath>

#include "foveate/core/error.hpp"
#include "foveate/core/stats.hpp"

namespace foveate::gaze {

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

  auto good = [&](const GazeSample& s) { return s.valid && s.confidence >= o.min_confidence; };

  // Fixation and saccade runs between dropouts.
  enum class Run { kNone, kFixation, kSaccade };
  Run run = Run::kNone;
  size_t run_first = 0;   // first sample of the run
  size_t run_anchor = 0;  // saccades: the sample before the run (its start point)
  double run_peak = 0.0;
  size_t prev = 0;  // previous good sample
  bool have_prev = false;
  bool lost_since = false;

  auto close_run = [&](size_t last) {
    if (run == Run::kFixation) {
      const double dur = v[last].time_s - v[run_first].time_s;
      if (dur >= o.min_fixation_s) {
        Fixation f;
        f.start_s = v[run_first].time_s;
        f.end_s = v[last].time_s;
        double sx = 0, sy = 0;
        for (size_t k = run_first; k <= last; ++k) {
          if (!good(v[k])) continue;
          sx += v[k].pos.x;
          sy += v[k].pos.y;
        }
        const double n = static_cast<double>(last - run_first + 1);
        f.pos = {sx / n, sy / n};
        st.fixations.push_back(f);
      }
    } else if (run == Run::kSaccade) {
      Saccade s;
      s.start_s = v[run_anchor].time_s;
      s.end_s = v[last].time_s;
      s.amplitude_deg = angle_between_deg(display, v[run_anchor].pos, v[last].pos);
      s.peak_deg_per_s = run_peak;
      st.saccades.push_back(s);
    }
    run = Run::kNone;
  };

  for (size_t i = 0; i < v.size(); ++i) {
    if (!good(v[i])) {
      ++st.lost_samples;
      lost_since = true;
      continue;
    }
    const bool gap = have_prev && (lost_since || v[i].time_s - v[prev].time_s > gap_s);
    if (gap || (!have_prev && lost_since)) {
      const double from = have_prev ? v[prev].time_s : v.front().time_s;
      const double len = v[i].time_s - from;
      ++st.dropouts;
      st.dropout_s += len;
      st.longest_dropout_s = std::max(st.longest_dropout_s, len);
      if (have_prev) close_run(prev);
      run = Run::kNone;
    }
    Run kind = Run::kFixation;
    double vel = 0.0;
    if (have_prev && !gap) {
      const double dt = v[i].time_s - v[prev].time_s;
      vel = angle_between_deg(display, v[prev].pos, v[i].pos) / dt;
      if (vel > o.velocity_deg_per_s) kind = Run::kSaccade;
    }
    if (kind != run) {
      if (run != Run::kNone) close_run(prev);
      run = kind;
      run_first = i;
      run_anchor = have_prev && !gap ? prev : i;
      run_peak = 0.0;
    }
    if (kind == Run::kSaccade) run_peak = std::max(run_peak, vel);
    prev = i;
    have_prev = true;
    lost_since = false;
  }
  if (lost_since) {  // lost until the end
    const double from = have_prev ? v[prev].time_s : v.front().time_s;
    const double len = v.back().time_s - from;
    ++st.dropouts;
    st.dropout_s += len;
    st.longest_dropout_s = std::max(st.longest_dropout_s, len);
  }
  if (have_prev) close_run(prev);

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
