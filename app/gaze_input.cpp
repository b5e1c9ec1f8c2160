#include "gaze_input.hpp"

#include <sstream>

#include "cli_util.hpp"
#include "foveate/gaze/filter.hpp"
#include "foveate/gaze/gaze.hpp"
#include "foveate/gaze/latency.hpp"
#include "session.hpp"

namespace foveate::app {

struct GazeInput::Impl {
  std::unique_ptr<gaze::GazeSource> source;
  std::unique_ptr<gaze::GazeFilter> filter;
  gaze::LatencyEstimator latency;
  int width = 0, height = 0;
  int frames = 0, held = 0, fallback = 0, saccades = 0;
};

GazeInput::GazeInput(const std::string& spec, Session& session,
                     std::function<std::optional<Vec2d>()> mouse)
    : impl_(std::make_unique<Impl>()) {
  impl_->width = session.options().size.width;
  impl_->height = session.options().size.height;
  gaze::GazeContext ctx;
  ctx.display = session.display();
  ctx.mouse = std::move(mouse);
  Scene* scene = &session.scene();
  const double w = impl_->width, h = impl_->height;
  ctx.objects = [scene, w, h](double) {
    std::vector<Vec2d> out;
    for (const Vec2d& p : scene->object_positions()) out.push_back({p.x / w, p.y / h});
    return out;
  };
  impl_->source = gaze::make_gaze_source(spec.empty() ? "fixed:0.5,0.5" : spec, ctx);
  impl_->filter = std::make_unique<gaze::GazeFilter>(gaze::FilterOptions{}, session.display());
}

GazeInput::~GazeInput() = default;

GazeState GazeInput::at(double time_s, std::optional<double> shown_s) {
  const gaze::GazeSample sample = impl_->source->sample(time_s);
  const gaze::FilteredGaze f = impl_->filter->update(sample, time_s);
  impl_->latency.record(f, shown_s.value_or(time_s));
  ++impl_->frames;
  impl_->held += f.holding ? 1 : 0;
  impl_->fallback += f.fallback ? 1 : 0;
  impl_->saccades += f.in_saccade ? 1 : 0;
  GazeState g;
  g.gaze_px = {f.pos.x * impl_->width, f.pos.y * impl_->height};
  g.fovea_scale = f.fovea_scale;
  g.latency_ms = impl_->latency.count() > 0 ? impl_->latency.worst_case_ms() : 0.0;
  return g;
}

std::string GazeInput::describe() const { return impl_->source->describe(); }

std::string GazeInput::report() const {
  std::ostringstream s;
  s << "gaze: " << impl_->source->describe() << "; " << impl_->frames << " frames, " << impl_->held
    << " holding, " << impl_->fallback << " in fallback, " << impl_->saccades << " in saccades";
  if (impl_->latency.count() > 0) {
    s << "; latency median " << fmt(impl_->latency.median_ms(), 1) << " ms, worst case "
      << fmt(impl_->latency.worst_case_ms(), 1) << " ms";
  }
  const std::string src = impl_->source->report();
  if (!src.empty()) s << "; " << src;
  s << "; filter: " << impl_->filter->counters().summary();
  return s.str();
}

}  // namespace foveate::app
