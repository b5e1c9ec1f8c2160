#include "bench_run.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "foveate/bench/frame_order.hpp"
#include "foveate/bench/statistics.hpp"
#include "foveate/core/parse.hpp"
#include "foveate/core/stats.hpp"
#include "foveate/gaze/pupil.hpp"

namespace foveate::bench {

BenchRun::BenchRun(const BenchOptions& o, const BenchCallbacks& callbacks)
    : options_(o), callbacks_(callbacks), session_(o.session, callbacks.session) {}

void BenchRun::step(const std::string& detail, const std::string& kind) const {
  if (callbacks_.step) callbacks_.step(detail, kind);
}

void BenchRun::notice(NoticeKind kind, FieldText text) const {
  if (callbacks_.session.notice) callbacks_.session.notice({kind, std::move(text)});
}

void BenchRun::choose_techniques() {
  if (!options_.runs.empty()) {
    // Explicit runs name their techniques (add_runs leaves out what the
    // scene cannot run).
    for (const RunSpec& r : options_.runs) {
      if (std::find(out_.techniques.begin(), out_.techniques.end(), r.technique) ==
          out_.techniques.end())
        out_.techniques.push_back(r.technique);
    }
    return;
  }
  if (options_.techniques) {
    out_.techniques = *options_.techniques;
    return;
  }
  // The default: every registered technique; what this scene cannot run is
  // left out, with a note.
  for (const std::string& t : technique_names()) {
    const std::string why = scene_mismatch(technique_info(t), session_.scene().info());
    if (why.empty()) {
      out_.techniques.push_back(t);
      continue;
    }
    out_.skipped.push_back(t + " (" + why + ")");
    notice(NoticeKind::Note, {"skipping " + t + ": " + why, {}});
  }
}

void BenchRun::check_gaze_source() {
  // A live tracker that never answers would silently bench the centre
  // fallback: an error unless the user accepts that.
  const auto* pupil = dynamic_cast<const gaze::PupilSource*>(&session_.gaze().source());
  if (!pupil || pupil->wait_connected(options_.connect_timeout_s)) return;
  const std::string& spec = options_.session.gaze;
  if (!options_.allow_fallback) {
    throw OptionError(
        "gaze", FieldText{"{gaze} " + spec + ": no eye tracker answered (" +
                              session_.gaze().source().describe() + ", waited " +
                              format_fixed(options_.connect_timeout_s, 1) +
                              " s); start Pupil Capture or Pupil Service, or pass {allow_fallback} "
                              "to measure with the gaze held at the centre",
                          {"gaze", "allow_fallback"}});
  }
  out_.gaze_fallback = true;
  notice(NoticeKind::Warning, {"{gaze} " + spec +
                                   ": no eye tracker answered; measuring with the fallback gaze "
                                   "({allow_fallback})",
                               {"gaze", "allow_fallback"}});
}

void BenchRun::add_run(const std::string& technique, double value, bool swept, int run_index,
                       const RunSpec* spec, bool measured) {
  Run r;
  r.technique = technique;
  r.sweep_value = value;
  r.result.run_index = run_index;
  ParamOverrides params = options_.params;
  if (spec) {
    for (const auto& [key, v] : spec->params) params.per_technique[technique][key] = v;
    r.result.label = spec->label.empty() ? run_spec_label(*spec) : spec->label;
  }
  r.acuity = options_.session.acuity;
  if (swept && options_.sweep.key == "slope") {
    r.acuity = for_field("sweep", [&] { return AcuityModel::with_slope(value); });
  } else if (swept) {
    params.per_technique[technique][options_.sweep.param] = value;
  }
  r.impl = session_.make(technique, params, r.acuity);
  r.params = params;
  if (!measured) {
    // Another shard's run, or one made only to settle (settle_runs): only
    // how long it needs to settle, so that every benchmark of the campaign
    // warms up alike and measures the same frames.
    unmeasured_settle_ = std::max(unmeasured_settle_, r.impl.view->settle_frames());
    return;
  }
  if (session_.stereo()) r.result.eyes.resize(2);
  r.result.technique = technique;
  r.result.sweep_value = value;
  r.result.parameters = r.impl.view->parameters();
  if (options_.image_metrics) {
    metrics::QualityOptions qo;
    qo.diagnostics = options_.diagnostics;
    qo.acuity = r.acuity;
    // One display for every measure: FovVideoVDP's photometry, and the JND
    // diagnostic's light from the same.
    const Photometry& light = session_.display().photometry;
    qo.contrast.peak_cd_m2 = light.peak_cd_m2;
    qo.contrast.black_cd_m2 = light.black_cd_m2();
    qo.fvvdp_options.fps = options_.session.fps;
    r.series = std::make_unique<metrics::QualitySeries>(session_.display(), qo);
    if (StereoFrameRunner* stereo = session_.stereo()) {
      for (Eye e : kEyes) {
        r.eye_series[static_cast<size_t>(e)] =
            std::make_unique<metrics::QualitySeries>(stereo->display().eye(e), qo);
      }
    }
  }
  runs_.push_back(std::move(r));
}

void BenchRun::add_runs() {
  // Native is the reference for speed and quality: always run, once, in
  // every shard. The other runs are numbered in one order for every shard
  // and dealt out in turn.
  add_run("native", 0.0, false, 0, nullptr, true);
  for (const RunSpec& spec : options_.settle_runs) {
    if (scene_mismatch(technique_info(spec.technique), session_.scene().info()).empty())
      add_run(spec.technique, 0.0, false, 0, &spec, false);
  }
  int index = 0;
  const Shard& shard = options_.shard;
  const Shard& group = options_.group;
  // Every shard.count-th run from shard.index, and of those every
  // group.count-th from group.index (run_bench's groups).
  int dealt = 0;
  const auto mine = [&] {
    if ((index - 1) % shard.count != shard.index) return false;
    return dealt++ % group.count == group.index;
  };
  if (!options_.runs.empty()) {
    std::set<std::string> skipped;
    for (const RunSpec& spec : options_.runs) {
      ++index;
      const bool measured = mine();
      const std::string why =
          scene_mismatch(technique_info(spec.technique), session_.scene().info());
      if (!why.empty() && options_.skip_unrunnable) {
        if (skipped.insert(spec.technique).second) {
          out_.skipped.push_back(spec.technique + " (" + why + ")");
          notice(NoticeKind::Note, {"skipping " + spec.technique + ": " + why, {}});
        }
        continue;
      }
      add_run(spec.technique, 0.0, false, index, &spec, measured);
    }
    native_listed_ = true;  // explicit runs are judged against native's figures
    return;
  }
  for (const std::string& t : out_.techniques) {
    if (t == "native") continue;
    if (options_.sweep.applies_to(t)) {
      for (double v : options_.sweep.values) {
        ++index;
        add_run(t, v, true, index, nullptr, mine());
      }
    } else {
      ++index;
      add_run(t, 0.0, false, index, nullptr, mine());
    }
  }
  native_listed_ = shard.count > 1 || std::find(out_.techniques.begin(), out_.techniques.end(),
                                                "native") != out_.techniques.end();
}

std::string run_spec_label(const RunSpec& spec) {
  std::string s = spec.technique + " {";
  bool first = true;
  for (const auto& [key, value] : spec.params) {
    s += (first ? "" : ", ") + key + "=" + format_number(value, 4);
    first = false;
  }
  return s + "}";
}

void BenchRun::open_video() {
  // Opened before any frame is rendered, so that a bad path fails at once.
  for (size_t i = 0; i < runs_.size(); ++i) {
    if (i > 0 || native_listed_ || options_.side_by_side) shown_.push_back(i);
  }
  if (options_.video.empty()) return;
  int cols = 0, rows = 0;
  tile_layout(static_cast<int>(shown_.size()), cols, rows);
  const PixelSize size = options_.session.size;
  const int frame_width = size.width * (session_.stereo() ? 2 : 1);
  video_ = for_field("video", [&] {
    return std::make_unique<VideoWriter>(options_.video, cols * frame_width, rows * size.height,
                                         options_.session.fps);
  });
}

void BenchRun::warm_up(bool timed) {
  // Compile shaders, allocate targets, start every cadence. No reset after
  // it: the measured frames continue from the techniques' steady state, as
  // they would in an application.
  for (int k = 0; k < out_.warmup; ++k) {
    const GazeState g = gaze_at(k);
    for (Run& r : runs_) {
      // On llvmpipe the last warm-up frame runs as the measured ones do,
      // pass by pass: after a pipelined frame the first measured one took
      // 90 ms longer. The earlier ones stay pipelined: with every warm-up
      // frame pass by pass, the first three or four measured frames of every
      // technique took 100 ms longer (docs/performance.md).
      const bool by_pass = timed && profiler_ && k + 1 == out_.warmup;
      if (by_pass) profiler_->begin_frame();
      session_.watchdog().run("warm-up frame " + std::to_string(k) + " (" + r.technique + ")",
                              [&] { session_.render(r.impl, k, g); });
      if (by_pass) profiler_->end_frame();
      step((timed ? "warm-up " : "images warm-up ") + r.technique);
    }
  }
}

void BenchRun::remake_runs() {
  // Each technique's history, cadences and adaptive state start again, so
  // that the image pass renders the frames the timed pass did. The old one
  // is freed first: two of every technique would double the memory held.
  for (Run& r : runs_) {
    r.impl = {};
    r.impl = session_.make(r.technique, r.params, r.acuity);
  }
}

void BenchRun::record(Run& r, const SessionFrame& frame, double ms) {
  TechniqueResult& res = r.result;
  for (size_t e = 0; e < res.eyes.size(); ++e) {
    res.eyes[e].shaded_pixels += frame.eyes[e].shaded_pixels;
    res.eyes[e].native_pixels += frame.eyes[e].native_pixels;
  }
  res.frame_ms.push_back(ms);
  if (profiler_) {
    const std::vector<gpu::PassTime>& passes = profiler_->end_frame();
    if (options_.passes) add_pass_times(res.passes, passes, ms);
  }
  if (std::isfinite(timer_.gpu_ms())) res.gpu_ms.push_back(timer_.gpu_ms());
  const FrameStats& s = frame.total;
  res.shaded_pixels += s.shaded_pixels;
  res.native_pixels += s.native_pixels;
  if (res.parts.empty()) {
    res.parts = s.parts;
    return;
  }
  for (size_t p = 0; p < s.parts.size() && p < res.parts.size(); ++p)
    res.parts[p].pixels += s.parts[p].pixels;
}

BenchRun::Images BenchRun::read_images() const {
  Images im;
  im.out = session_.read_output();
  if (!session_.options().stereo) return im;
  for (Eye e : kEyes) im.eyes[static_cast<size_t>(e)] = session_.read_eye(e);
  return im;
}

}  // namespace foveate::bench
