#include "foveate/gaze/tracker.hpp"

#include <cstdio>
#include <sstream>

namespace foveate::gaze {

struct GazeTracker::Impl {
  std::unique_ptr<GazeSource> source;
  GazeFilter filter;
  LatencyEstimator latency;
  TrackerOptions options;
  int width = 0, height = 0;
  FilteredGaze last;
  int frames = 0, held = 0, fallback = 0, saccades = 0;

  Impl(std::unique_ptr<GazeSource> s, const Display& d, TrackerOptions o)
      : source(std::move(s)),
        filter(o.filter, d),
        latency(o.latency),
        options(o),
        width(d.width_px),
        height(d.height_px) {}
};

GazeTracker::GazeTracker(std::unique_ptr<GazeSource> source, const Display& display,
                         TrackerOptions options)
    : impl_(std::make_unique<Impl>(std::move(source), display, options)) {}

GazeTracker::GazeTracker(const std::string& spec, const GazeContext& context,
                         TrackerOptions options)
    : GazeTracker(make_gaze_source(spec.empty() ? "fixed:0.5,0.5" : spec, context), context.display,
                  options) {}

GazeTracker::~GazeTracker() = default;
GazeTracker::GazeTracker(GazeTracker&&) noexcept = default;
GazeTracker& GazeTracker::operator=(GazeTracker&&) noexcept = default;

GazeState GazeTracker::at(double time_s, std::optional<double> shown_s) {
  Impl& m = *impl_;
  const GazeSample sample = m.source->sample(time_s);
  m.last = m.filter.update(sample, time_s);
  m.latency.record(m.last, shown_s.value_or(time_s));
  ++m.frames;
  m.held += m.last.holding ? 1 : 0;
  m.fallback += m.last.fallback ? 1 : 0;
  m.saccades += m.last.in_saccade ? 1 : 0;
  GazeState g;
  g.gaze_px = {m.last.pos.x * m.width, m.last.pos.y * m.height};
  g.fovea_scale = m.last.fovea_scale;
  g.latency_ms = m.latency.count() > 0 ? m.latency.worst_case_ms() : 0.0;
  g.max_saccade_deg_per_s = m.options.max_saccade_deg_per_s;
  return g;
}

const FilteredGaze& GazeTracker::last() const { return impl_->last; }
const GazeSource& GazeTracker::source() const { return *impl_->source; }
const GazeFilter& GazeTracker::filter() const { return impl_->filter; }
const LatencyEstimator& GazeTracker::latency() const { return impl_->latency; }
std::string GazeTracker::describe() const { return impl_->source->describe(); }

std::string GazeTracker::report() const {
  const Impl& m = *impl_;
  std::ostringstream s;
  s << "gaze: " << m.source->describe() << "; " << m.frames << " frames, " << m.held << " holding, "
    << m.fallback << " in fallback, " << m.saccades << " in saccades";
  if (m.latency.count() > 0) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "; latency median %.1f ms, worst case %.1f ms",
                  m.latency.median_ms(), m.latency.worst_case_ms());
    s << buf;
  }
  const std::string src = m.source->report();
  if (!src.empty()) s << "; " << src;
  s << "; filter: " << m.filter.counters().summary();
  return s.str();
}

}  // namespace foveate::gaze
