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
  bool off_image = false;
  TrackerCounts counts;

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
  const Vec2d p = m.last.pos;
  m.off_image = !(p.x >= 0.0 && p.x <= 1.0 && p.y >= 0.0 && p.y <= 1.0);
  TrackerCounts& c = m.counts;
  ++c.frames;
  c.holding += m.last.holding ? 1 : 0;
  c.fallback += m.last.fallback ? 1 : 0;
  c.saccades += m.last.in_saccade ? 1 : 0;
  c.off_image += m.off_image ? 1 : 0;
  GazeState g;
  g.gaze_px = {m.last.pos.x * m.width, m.last.pos.y * m.height};
  g.fovea_scale = m.last.fovea_scale;
  g.latency_ms = m.latency.count() > 0 ? m.latency.worst_case_ms() : 0.0;
  g.max_saccade_deg_per_s = m.options.max_saccade_deg_per_s;
  return g;
}

const FilteredGaze& GazeTracker::last() const { return impl_->last; }
bool GazeTracker::last_off_image() const { return impl_->off_image; }
const TrackerCounts& GazeTracker::counts() const { return impl_->counts; }
const GazeSource& GazeTracker::source() const { return *impl_->source; }
const GazeFilter& GazeTracker::filter() const { return impl_->filter; }
const LatencyEstimator& GazeTracker::latency() const { return impl_->latency; }
std::string GazeTracker::describe() const { return impl_->source->describe(); }

std::string GazeTracker::report() const {
  const Impl& m = *impl_;
  std::ostringstream s;
  const TrackerCounts& c = m.counts;
  s << "gaze: " << m.source->describe() << "; " << c.frames << " frames, " << c.holding
    << " holding, " << c.fallback << " in fallback, " << c.saccades << " in saccades, "
    << c.off_image << " off the image";
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
