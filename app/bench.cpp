#include "bench.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <random>
#include <sstream>

#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"
#include "foveate/core/stats.hpp"
#include "foveate/gaze/pupil.hpp"
#include "foveate/gpu/frame.hpp"
#include "foveate/metrics/metrics.hpp"
#include "foveate/techniques/reference.hpp"
#include "progress.hpp"
#include "video.hpp"

namespace foveate::app {

std::vector<std::vector<size_t>> interleaved_orders(size_t runs, int frames) {
  std::vector<std::vector<size_t>> out;
  std::vector<size_t> order(runs);
  std::iota(order.begin(), order.end(), size_t{0});
  std::mt19937 shuffler(20261125u);
  for (int k = 0; k < frames; ++k) {
    std::shuffle(order.begin(), order.end(), shuffler);
    out.push_back(order);
  }
  return out;
}

namespace {

// 95 % bootstrap interval of mean(native) / mean(technique), resampling
// frames in pairs (the same frames were rendered by both), fixed seed.
std::pair<double, double> speedup_interval(const std::vector<double>& native,
                                           const std::vector<double>& tech) {
  const size_t n = std::min(native.size(), tech.size());
  if (n < 2) {
    const double s = mean(native) / mean(tech);
    return {s, s};
  }
  std::mt19937 rng(12345);
  std::uniform_int_distribution<size_t> pick(0, n - 1);
  std::vector<double> ratios;
  std::vector<double> a(n), b(n);
  for (int r = 0; r < 1000; ++r) {
    for (size_t k = 0; k < n; ++k) {
      const size_t i = pick(rng);
      a[k] = native[i];
      b[k] = tech[i];
    }
    ratios.push_back(mean(a) / mean(b));
  }
  return {quantile(ratios, 0.025), quantile(ratios, 0.975)};
}

// Adds a frame's pass times to the running sums, and the rest of the frame
// (time outside every timed pass) as "other", kept last.
void add_passes(std::vector<gpu::PassTime>& sums, const std::vector<gpu::PassTime>& frame,
                double frame_ms) {
  gpu::PassTime other{"other", 0.0};
  if (!sums.empty() && sums.back().name == "other") {
    other = sums.back();
    sums.pop_back();
  }
  double timed = 0;
  for (const gpu::PassTime& p : frame) {
    timed += p.ms;
    auto it = std::find_if(sums.begin(), sums.end(),
                           [&](const gpu::PassTime& s) { return s.name == p.name; });
    if (it == sums.end()) {
      sums.push_back(p);
    } else {
      it->ms += p.ms;
    }
  }
  other.ms += std::max(0.0, frame_ms - timed);
  sums.push_back(other);
}

// The image mirrored left to right: the right eye of a stereo display is the
// left eye's geometry mirrored, so a mirrored right-eye frame (and gaze) can
// be judged with the left eye's display, in one series with the left's.
Image mirrored(const Image& in) {
  Image out(in.width, in.height);
  for (int y = 0; y < in.height; ++y) {
    for (int x = 0; x < in.width; ++x) std::copy_n(in.at(x, y), 4, out.at(in.width - 1 - x, y));
  }
  return out;
}

// One frame of a run: both eyes' images side by side (or the one view) and
// each eye's image for the metrics.
struct RunImages {
  Image out;
  std::array<Image, 2> eyes;
};

}  // namespace

Sweep Sweep::parse(const std::string& text) {
  const auto eq = text.find('=');
  std::vector<std::string> parts;
  if (eq != std::string::npos) {
    std::stringstream in(text.substr(eq + 1));
    for (std::string item; std::getline(in, item, ':');) parts.push_back(item);
  }
  if (eq == std::string::npos || eq == 0 || parts.size() != 3) {
    throw Error(
        "--sweep: expected KEY=FROM:TO:STEP (e.g. slope=0.015:0.035:0.005 or "
        "layered.layers=2:5:1), got '" +
        text + "'");
  }
  double v[3];
  for (size_t i = 0; i < 3; ++i) {
    if (!parse_number(parts[i], v[i]) || !std::isfinite(v[i]))
      throw Error("--sweep: '" + parts[i] + "' is not a number");
  }
  if (!(v[2] > 0) || v[1] < v[0]) throw Error("--sweep: need FROM <= TO and STEP > 0");
  // Counted, not accumulated: a step too small to change the value cannot loop.
  const double count = std::floor((v[1] - v[0]) / v[2] + 1e-9) + 1;
  if (!(count <= kMaxSweepValues)) {
    char msg[200];
    std::snprintf(msg, sizeof msg, "%.0f values, over the limit of %d; use a larger STEP", count,
                  kMaxSweepValues);
    throw Error("--sweep " + text + ": " + msg);
  }
  Sweep s;
  s.key = text.substr(0, eq);
  for (int i = 0; i < static_cast<int>(count); ++i) s.values.push_back(v[0] + i * v[2]);
  if (s.key == "slope") return s;
  const auto dot = s.key.find('.');
  s.technique = dot == std::string::npos ? "" : s.key.substr(0, dot);
  s.param = dot == std::string::npos ? s.key : s.key.substr(dot + 1);
  bool known = false;
  for (const TechniqueInfo& t : techniques()) known = known || s.applies_to(t.name);
  if (!known) {
    throw Error("--sweep: no technique has a parameter '" + s.key + "' (see 'foveate techniques')");
  }
  // Each value against each declaration it will be given to, before anything runs.
  for (const TechniqueInfo& t : techniques()) {
    if (!s.applies_to(t.name)) continue;
    for (double x : s.values) with_flag("--sweep", [&] { check_parameter(t, s.param, x); });
  }
  return s;
}

bool Sweep::applies_to(const std::string& name) const {
  if (empty()) return false;
  if (param.empty()) return true;  // the slope changes every technique
  if (!technique.empty() && technique != name) return false;
  for (const ParamDecl& p : technique_info(name).params) {
    if (p.key == param) return true;
  }
  return false;
}

BenchResult run_bench(const BenchOptions& o) {
  if (o.frames < 1 || o.frames > 100000) throw Error("--frames: expected 1..100000");
  if (o.warmup < 0 || o.warmup > 1000) throw Error("--warmup: expected 0..1000");
  if (o.techniques.empty()) throw Error("--techniques: give at least one technique");
  for (const std::string& t : o.techniques) (void)technique_info(t);

  BenchResult out;
  out.options = o;
  Session session(o.session, o.gaze);
  // The default list: what this scene cannot run is left out, with a note.
  if (o.skip_unfit) {
    std::vector<std::string> kept;
    for (const std::string& t : o.techniques) {
      const std::string why = scene_mismatch(technique_info(t), session.scene().info());
      if (why.empty()) {
        kept.push_back(t);
      } else {
        out.skipped.push_back(t + " (" + why + ")");
        if (!quiet())
          std::fprintf(stderr, "foveate: note: skipping %s: %s\n", t.c_str(), why.c_str());
      }
    }
    out.options.techniques = kept;
  }
  // A live tracker that never answers would silently bench the centre
  // fallback: an error unless the user accepts that.
  if (const auto* pupil = dynamic_cast<const gaze::PupilSource*>(&session.gaze().source())) {
    if (!pupil->wait_connected(o.connect_timeout_s)) {
      if (!o.allow_fallback) {
        throw Error("--gaze " + o.gaze + ": no eye tracker answered (" +
                    session.gaze().source().describe() + ", waited " + fmt(o.connect_timeout_s, 1) +
                    " s); start Pupil Capture or Pupil Service, or pass --allow-fallback to "
                    "measure with the gaze held at the centre");
      }
      out.gaze_fallback = true;
      if (!quiet())
        std::fprintf(stderr,
                     "foveate: warning: --gaze %s: no eye tracker answered; measuring with the "
                     "fallback gaze (--allow-fallback)\n",
                     o.gaze.c_str());
    }
  }
  out.display = session.display();
  StereoRenderer* stereo = session.stereo();
  if (stereo) out.stereo = session.stereo_display();
  out.scene = session.scene().info().name;
  out.environment = capture_environment(invocation().empty() ? o.command_line : invocation());
  out.renderer = out.environment.renderer;
  Renderer& renderer = session.renderer();
  gaze::GazeTracker& gaze = session.gaze();
  const std::unique_ptr<Reference> reference =
      o.reference > 1 ? session.make_reference(o.reference) : nullptr;

  // The runs: each technique once, or once per swept value.
  struct Run {
    std::string technique;
    double sweep_value = 0;
    AcuityModel acuity;
    std::unique_ptr<Technique> impl;   ///< the one view, or the left eye (stereo)
    std::unique_ptr<Technique> right;  ///< stereo: the right eye's own instance
    TechniqueResult result;
    /// Against the reference: the one view, or (stereo) both eyes' frames,
    /// the right eye's mirrored into the left eye's geometry.
    std::unique_ptr<metrics::QualitySeries> series;
    std::array<std::unique_ptr<metrics::QualitySeries>, 2> eye_series;  ///< stereo
  };
  std::vector<Run> runs;
  auto add_run = [&](const std::string& t, double value, bool swept) {
    Run r;
    r.technique = t;
    r.sweep_value = value;
    ParamArgs params = o.params;
    r.acuity = o.session.acuity;
    if (swept && o.sweep.key == "slope") {
      r.acuity = with_flag("--sweep", [&] { return AcuityModel::with_slope(value); });
    } else if (swept) {
      params.per_technique[t][o.sweep.param] = value;
    }
    if (stereo) {
      auto eyes = session.make_stereo(t, params, r.acuity);
      r.impl = std::move(eyes[0]);
      r.right = std::move(eyes[1]);
      r.result.eyes.resize(2);
    } else {
      r.impl = session.make(t, params, r.acuity);
    }
    r.result.technique = t;
    r.result.sweep_value = value;
    r.result.parameters = r.impl->parameters();
    if (o.image_metrics) {
      metrics::QualityOptions qo;
      qo.acuity = r.acuity;
      r.series = std::make_unique<metrics::QualitySeries>(session.display(), qo);
      if (stereo) {
        for (Eye e : kEyes) {
          r.eye_series[static_cast<size_t>(e)] =
              std::make_unique<metrics::QualitySeries>(stereo->display().eye(e), qo);
        }
      }
    }
    runs.push_back(std::move(r));
  };
  // Native is the reference for speed and quality: always run, once.
  add_run("native", 0.0, false);
  for (const std::string& t : out.options.techniques) {
    if (t == "native") continue;
    if (o.sweep.applies_to(t)) {
      for (double v : o.sweep.values) add_run(t, v, true);
    } else {
      add_run(t, 0.0, false);
    }
  }
  const bool native_listed = std::find(out.options.techniques.begin(), out.options.techniques.end(),
                                       "native") != out.options.techniques.end();

  // Warm up until every technique is steady (its own settle_frames), at
  // least as long as asked.
  int warmup = o.warmup;
  for (const Run& r : runs) warmup = std::max(warmup, r.impl->settle_frames());
  out.warmup = warmup;
  // The runs the video shows, in order, and the video (opened before any
  // frame is rendered, so that a bad path fails at once).
  std::vector<size_t> shown;
  for (size_t i = 0; i < runs.size(); ++i) {
    if (i > 0 || native_listed || o.side_by_side) shown.push_back(i);
  }
  std::unique_ptr<VideoWriter> video;
  if (!o.video.empty()) {
    int cols = 0, rows = 0;
    tile_layout(static_cast<int>(shown.size()), cols, rows);
    const int frame_width = o.session.size.width * (stereo ? 2 : 1);
    video = with_flag("--video", [&] {
      return std::make_unique<VideoWriter>(o.video, cols * frame_width,
                                           rows * o.session.size.height, o.session.fps);
    });
  }

  // Steps: every frame rendered, and every frame judged (the metrics take as
  // long as the rendering on a CPU), so that the time left is honest.
  int judged_runs = 0;
  if (o.image_metrics) judged_runs = static_cast<int>(runs.size()) - (reference ? 0 : 1);
  const int total = static_cast<int>(runs.size()) * (o.frames + warmup) + judged_runs * o.frames;
  Progress progress("bench", "steps", total, o.progress);
  progress.expect("metrics", judged_runs * o.frames);
  gpu::FrameTimer timer;
  // One frame of a run: the one view, or both eyes (each eye's stats in `eyes`).
  auto render_run = [&](Run& r, int frame, const GazeState& g,
                        std::array<FrameStats, 2>* eyes = nullptr) {
    if (!stereo) return renderer.render(*r.impl, frame, g);
    const std::array<FrameStats, 2> st =
        stereo->render(*r.impl, *r.right, frame, session.eye_gazes(g));
    if (eyes) *eyes = st;
    FrameStats sum = st[0];
    sum.shaded_pixels += st[1].shaded_pixels;
    sum.native_pixels += st[1].native_pixels;
    for (size_t p = 0; p < sum.parts.size() && p < st[1].parts.size(); ++p)
      sum.parts[p].pixels += st[1].parts[p].pixels;
    return sum;
  };
  auto read_run = [&] {
    RunImages im;
    if (!stereo) {
      im.out = renderer.read_output();
      return im;
    }
    im.out = stereo->read_output();
    for (Eye e : kEyes) im.eyes[static_cast<size_t>(e)] = stereo->read_eye(e);
    return im;
  };
  std::optional<gpu::PassProfiler> profiler;
  if (o.passes) profiler.emplace();
  // Warm-up: compile shaders, allocate targets, start every cadence.
  for (int k = 0; k < warmup; ++k) {
    const double t = renderer.frame_input(k).time_s;
    const GazeState g = gaze.at(t);
    for (Run& r : runs) {
      session.watchdog().run("warm-up frame " + std::to_string(k) + " (" + r.technique + ")",
                             [&] { render_run(r, k, g); });
      progress.step("warm-up " + r.technique);
    }
  }
  // No reset after the warm-up: the measured frames continue from the
  // techniques' steady state (every layer rendered, half-rate cadence and
  // temporal history running), as they would in an application.
  // Measured frames, interleaved: every technique renders frame k before any
  // renders k + 1, in an order shuffled anew for every frame. With a fixed
  // rotation each technique followed the same predecessor every frame, and
  // on llvmpipe the technique after logpolar paid 20-26 ms more in its
  // G-buffer pass (docs/performance.md).
  const std::vector<std::vector<size_t>> orders = interleaved_orders(runs.size(), o.frames);
  for (int k = 0; k < o.frames; ++k) {
    const std::vector<size_t>& order = orders[static_cast<size_t>(k)];
    const int frame = warmup + k;
    const double t = renderer.frame_input(frame).time_s;
    const GazeState g = gaze.at(t);
    // The image every run is judged against: native, or the supersampled
    // reference (untimed, rendered from a scene of its own).
    Image reference_image;
    std::array<Image, 2> reference_eyes;  // stereo: native's eyes
    if (reference) {
      reference_image = session.watchdog().run(
          "frame " + std::to_string(frame) + " of the ssaa:" + std::to_string(o.reference) +
              " reference",
          [&] { return reference->render(renderer.frame_input(frame)); },
          double(o.reference) * o.reference);
    }
    std::vector<std::pair<size_t, RunImages>> images;
    for (size_t i = 0; i < runs.size(); ++i) {
      Run& r = runs[order[i]];
      FrameStats s;
      std::array<FrameStats, 2> eye_stats;
      if (profiler) profiler->begin_frame();
      const double ms =
          session.watchdog().run("frame " + std::to_string(frame) + " (" + r.technique + ")", [&] {
            timer.start();
            s = render_run(r, frame, g, &eye_stats);
            return timer.stop();
          });
      for (size_t e = 0; e < r.result.eyes.size(); ++e) {
        r.result.eyes[e].shaded_pixels += eye_stats[e].shaded_pixels;
        r.result.eyes[e].native_pixels += eye_stats[e].native_pixels;
      }
      r.result.frame_ms.push_back(ms);
      if (profiler) add_passes(r.result.passes, profiler->end_frame(), ms);
      if (std::isfinite(timer.gpu_ms())) r.result.gpu_ms.push_back(timer.gpu_ms());
      r.result.shaded_pixels += s.shaded_pixels;
      r.result.native_pixels += s.native_pixels;
      if (r.result.parts.empty())
        r.result.parts = s.parts;
      else
        for (size_t p = 0; p < s.parts.size() && p < r.result.parts.size(); ++p)
          r.result.parts[p].pixels += s.parts[p].pixels;
      if (o.image_metrics || k + 1 == o.frames || video) {
        RunImages img = read_run();
        if (&r == &runs[0] && !reference) {
          reference_image = img.out;
          reference_eyes = img.eyes;
        }
        images.emplace_back(static_cast<size_t>(&r - &runs[0]), std::move(img));
      }
      progress.step(r.technique + (o.sweep.empty() ? "" : " @" + fmt(r.sweep_value, 4)));
    }
    if (video) {
      // Untimed: the frames were read back after the clock stopped.
      std::vector<Image> tiles(shown.size());
      std::vector<const Image*> ptrs;
      for (size_t s = 0; s < shown.size(); ++s) {
        for (const auto& [idx, img] : images) {
          if (idx == shown[s]) tiles[s] = img.out;
        }
        if (o.side_by_side && stereo) {
          // Each eye's own gaze, in its half.
          const std::array<GazeState, 2> eg = session.eye_gazes(g);
          mark_gaze(tiles[s], eg[0].gaze_px);
          mark_gaze(tiles[s], {eg[1].gaze_px.x + o.session.size.width, eg[1].gaze_px.y});
        } else if (o.side_by_side) {
          mark_gaze(tiles[s], g.gaze_px);
        }
        ptrs.push_back(&tiles[s]);
      }
      video->write(tile(ptrs));
    }
    const std::array<GazeState, 2> eye_gaze =
        stereo ? session.eye_gazes(g) : std::array<GazeState, 2>{g, g};
    for (auto& [idx, img] : images) {
      Run& r = runs[idx];
      const bool judged = o.image_metrics && (idx != 0 || reference);
      if (judged && stereo) {
        for (size_t e = 0; e < 2; ++e)
          r.eye_series[e]->add(reference_eyes[e], img.eyes[e], eye_gaze[e].gaze_px);
        r.series->add(reference_eyes[0], img.eyes[0], eye_gaze[0].gaze_px);
        const Vec2d mirrored_gaze{o.session.size.width - eye_gaze[1].gaze_px.x,
                                  eye_gaze[1].gaze_px.y};
        r.series->add(mirrored(reference_eyes[1]), mirrored(img.eyes[1]), mirrored_gaze, 1);
        progress.step("metrics " + r.technique, "metrics");
      } else if (judged) {
        r.series->add(reference_image, img.out, g.gaze_px);
        progress.step("metrics " + r.technique, "metrics");
      }
      if (k + 1 == o.frames) {
        if (judged && stereo) {
          std::array<Image, 2> heat, acuity_heat;
          for (size_t e = 0; e < 2; ++e) {
            heat[e] = metrics::error_heatmap(reference_eyes[e], img.eyes[e], 64.0);
            acuity_heat[e] = metrics::acuity_error_heatmap(
                reference_eyes[e], img.eyes[e], r.eye_series[e]->display(), eye_gaze[e].gaze_px,
                r.eye_series[e]->options());
          }
          r.result.heatmap = tile({&heat[0], &heat[1]});
          r.result.acuity_heatmap = tile({&acuity_heat[0], &acuity_heat[1]});
        } else if (judged) {
          r.result.heatmap = metrics::error_heatmap(reference_image, img.out, 64.0);
          r.result.acuity_heatmap = metrics::acuity_error_heatmap(
              reference_image, img.out, r.series->display(), g.gaze_px, r.series->options());
        }
        r.result.sample = std::move(img.out);
        r.result.overlay = r.impl->overlay(eye_gaze[0]);
        if (stereo) {
          // The right eye's shapes over the right half.
          for (OverlayShape shape : r.right->overlay(eye_gaze[1])) {
            shape.x += o.session.size.width;
            r.result.overlay.push_back(shape);
          }
        }
        out.sample_gaze_px = eye_gaze[0].gaze_px;
        out.sample_eye_gaze_px = {eye_gaze[0].gaze_px, eye_gaze[1].gaze_px};
      }
    }
    if (k + 1 == o.frames) {
      out.native_sample = runs[0].result.sample;
      if (reference) out.reference_sample = reference_image;
    }
  }

  progress.finish();
  out.gaze_report = gaze.report();
  finish_environment(out.environment);
  if (video) {
    video->finish();
    out.video_summary = video_summary(*video, o.session.fps);
  }
  const std::vector<double> native_ms =
      runs[0].result.frame_ms;  // a copy: results are moved out below
  // Speedups are ratios of mean frame times (throughput): a technique whose
  // cost alternates from frame to frame (half-rate layers) is judged by its
  // average, where a median would pick one phase.
  const double native_mean = mean(native_ms);
  for (size_t i = 0; i < runs.size(); ++i) {
    Run& r = runs[i];
    TechniqueResult& res = r.result;
    if (i == 0 && !native_listed) continue;
    res.median_ms = quantile(res.frame_ms, 0.5);
    res.p90_ms = quantile(res.frame_ms, 0.9);
    res.mean_ms = mean(res.frame_ms);
    res.speedup = native_mean / res.mean_ms;
    std::tie(res.speedup_lo, res.speedup_hi) = speedup_interval(native_ms, res.frame_ms);
    res.shaded_pixels /= o.frames;
    res.native_pixels /= o.frames;
    for (PixelPart& p : res.parts) p.pixels /= o.frames;
    for (gpu::PassTime& p : res.passes) p.ms /= o.frames;
    res.pixel_ratio = res.shaded_pixels / res.native_pixels;
    res.bound_share = res.speedup * res.pixel_ratio;
    if (r.series && r.series->frames() > 0) res.metrics = r.series->summary();
    for (size_t e = 0; e < res.eyes.size(); ++e) {
      TechniqueResult::Eye& eye = res.eyes[e];
      eye.shaded_pixels /= o.frames;
      eye.native_pixels /= o.frames;
      eye.pixel_ratio = eye.shaded_pixels / eye.native_pixels;
      if (r.eye_series[e] && r.eye_series[e]->frames() > 0)
        eye.metrics = r.eye_series[e]->summary();
    }
    out.results.push_back(std::move(res));
  }
  return out;
}

}  // namespace foveate::app
