#include "bench.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <sstream>

#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"
#include "foveate/core/stats.hpp"
#include "foveate/gpu/frame.hpp"
#include "foveate/metrics/metrics.hpp"
#include "foveate/techniques/reference.hpp"

namespace foveate::app {

namespace {

// 95 % bootstrap interval of median(native) / median(technique), resampling
// frames in pairs (the same frames were rendered by both), fixed seed.
std::pair<double, double> speedup_interval(const std::vector<double>& native,
                                           const std::vector<double>& tech) {
  const size_t n = std::min(native.size(), tech.size());
  if (n < 2) {
    const double s = quantile(native, 0.5) / quantile(tech, 0.5);
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
    ratios.push_back(quantile(a, 0.5) / quantile(b, 0.5));
  }
  return {quantile(ratios, 0.025), quantile(ratios, 0.975)};
}

class Progress {
 public:
  Progress(int total, bool enabled) : total_(total), enabled_(enabled), tty_(isatty(2) != 0) {
    t0_ = std::chrono::steady_clock::now();
  }
  void step(const std::string& what) {
    ++done_;
    if (!enabled_) return;
    const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    const double eta = done_ > 0 ? el / done_ * (total_ - done_) : 0.0;
    if (tty_) {
      const int width = 30, filled = total_ > 0 ? width * done_ / total_ : width;
      std::fprintf(stderr, "\r[%s%s] %3d%% %d/%d  ETA %5.0fs  %-28s",
                   std::string(size_t(filled), '#').c_str(),
                   std::string(size_t(width - filled), '.').c_str(),
                   100 * done_ / std::max(total_, 1), done_, total_, eta, what.c_str());
      if (done_ == total_) std::fprintf(stderr, "\n");
    } else if (done_ == total_ || done_ % std::max(1, total_ / 10) == 0) {
      std::fprintf(stderr, "bench: %d/%d frames rendered, %.0f s elapsed, about %.0f s left\n",
                   done_, total_, el, eta);
    }
    std::fflush(stderr);
  }

 private:
  int total_, done_ = 0;
  bool enabled_, tty_;
  std::chrono::steady_clock::time_point t0_;
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
  out.display = session.display();
  out.scene = session.scene().info().name;
  {
    const auto* r = glGetString(GL_RENDERER);
    out.renderer = r ? reinterpret_cast<const char*>(r) : "";
  }
  Renderer& renderer = session.renderer();
  gaze::GazeTracker& gaze = session.gaze();
  const std::unique_ptr<Reference> reference =
      o.reference > 1 ? session.make_reference(o.reference) : nullptr;

  // The runs: each technique once, or once per swept value.
  struct Run {
    std::string technique;
    double sweep_value = 0;
    AcuityModel acuity;
    std::unique_ptr<Technique> impl;
    TechniqueResult result;
    std::unique_ptr<metrics::QualitySeries> series;
  };
  std::vector<Run> runs;
  auto add_run = [&](const std::string& t, double value, bool swept) {
    Run r;
    r.technique = t;
    r.sweep_value = value;
    ParamArgs params = o.params;
    r.acuity = o.session.acuity;
    if (swept && o.sweep.param.empty()) {
      r.acuity = with_flag("--sweep", [&] { return AcuityModel::with_slope(value); });
    } else if (swept) {
      params.per_technique[t][o.sweep.param] = value;
    }
    r.impl = session.make(t, params, r.acuity);
    r.result.technique = t;
    r.result.sweep_value = value;
    r.result.parameters = r.impl->parameters();
    if (o.image_metrics) {
      metrics::QualityOptions qo;
      qo.acuity = r.acuity;
      r.series = std::make_unique<metrics::QualitySeries>(session.display(), qo);
    }
    runs.push_back(std::move(r));
  };
  // Native is the reference for speed and quality: always run, once.
  add_run("native", 0.0, false);
  for (const std::string& t : o.techniques) {
    if (t == "native") continue;
    if (o.sweep.applies_to(t)) {
      for (double v : o.sweep.values) add_run(t, v, true);
    } else {
      add_run(t, 0.0, false);
    }
  }
  const bool native_listed =
      std::find(o.techniques.begin(), o.techniques.end(), "native") != o.techniques.end();

  const int total = static_cast<int>(runs.size()) * (o.frames + o.warmup);
  Progress progress(total, o.progress);
  gpu::FrameTimer timer;
  // Warm-up: compile shaders, allocate targets, fill temporal history.
  for (int k = 0; k < o.warmup; ++k) {
    const double t = renderer.frame_input(k).time_s;
    const GazeState g = gaze.at(t);
    for (Run& r : runs) {
      session.watchdog().run("warm-up frame " + std::to_string(k) + " (" + r.technique + ")",
                             [&] { renderer.render(*r.impl, k, g); });
      progress.step("warm-up " + r.technique);
    }
  }
  for (Run& r : runs) r.impl->reset();
  // Measured frames, interleaved: every technique renders frame k before any
  // renders k + 1, and the order rotates so that no technique is always first.
  for (int k = 0; k < o.frames; ++k) {
    const int frame = o.warmup + k;
    const double t = renderer.frame_input(frame).time_s;
    const GazeState g = gaze.at(t);
    // The image every run is judged against: native, or the supersampled
    // reference (untimed, rendered from a scene of its own).
    Image reference_image;
    if (reference) {
      reference_image = session.watchdog().run(
          "frame " + std::to_string(frame) + " of the ssaa:" + std::to_string(o.reference) +
              " reference",
          [&] { return reference->render(renderer.frame_input(frame)); },
          double(o.reference) * o.reference);
    }
    std::vector<std::pair<size_t, Image>> images;
    for (size_t i = 0; i < runs.size(); ++i) {
      Run& r = runs[(i + static_cast<size_t>(k)) % runs.size()];
      FrameStats s;
      const double ms =
          session.watchdog().run("frame " + std::to_string(frame) + " (" + r.technique + ")", [&] {
            timer.start();
            s = renderer.render(*r.impl, frame, g);
            return timer.stop();
          });
      r.result.frame_ms.push_back(ms);
      if (std::isfinite(timer.gpu_ms())) r.result.gpu_ms.push_back(timer.gpu_ms());
      r.result.shaded_pixels += s.shaded_pixels;
      r.result.native_pixels += s.native_pixels;
      if (r.result.parts.empty())
        r.result.parts = s.parts;
      else
        for (size_t p = 0; p < s.parts.size() && p < r.result.parts.size(); ++p)
          r.result.parts[p].pixels += s.parts[p].pixels;
      if (o.image_metrics || k + 1 == o.frames) {
        Image img = renderer.read_output();
        if (&r == &runs[0] && !reference) reference_image = img;
        images.emplace_back(static_cast<size_t>(&r - &runs[0]), std::move(img));
      }
      progress.step(r.technique + (o.sweep.empty() ? "" : " @" + fmt(r.sweep_value, 4)));
    }
    for (auto& [idx, img] : images) {
      Run& r = runs[idx];
      const bool judged = o.image_metrics && (idx != 0 || reference);
      if (judged) r.series->add(reference_image, img, g.gaze_px);
      if (k + 1 == o.frames) {
        if (judged) {
          r.result.heatmap = metrics::error_heatmap(reference_image, img, 64.0);
          r.result.acuity_heatmap = metrics::acuity_error_heatmap(
              reference_image, img, r.series->display(), g.gaze_px, r.series->options());
        }
        r.result.sample = std::move(img);
        out.sample_gaze_px = g.gaze_px;
      }
    }
    if (k + 1 == o.frames) {
      out.native_sample = runs[0].result.sample;
      if (reference) out.reference_sample = reference_image;
    }
  }

  out.gaze_report = gaze.report();
  const std::vector<double> native_ms =
      runs[0].result.frame_ms;  // a copy: results are moved out below
  const double native_median = quantile(native_ms, 0.5);
  for (size_t i = 0; i < runs.size(); ++i) {
    Run& r = runs[i];
    TechniqueResult& res = r.result;
    if (i == 0 && !native_listed) continue;
    res.median_ms = quantile(res.frame_ms, 0.5);
    res.p90_ms = quantile(res.frame_ms, 0.9);
    double sum = 0;
    for (double x : res.frame_ms) sum += x;
    res.mean_ms = sum / static_cast<double>(res.frame_ms.size());
    res.speedup = native_median / res.median_ms;
    std::tie(res.speedup_lo, res.speedup_hi) = speedup_interval(native_ms, res.frame_ms);
    res.shaded_pixels /= o.frames;
    res.native_pixels /= o.frames;
    for (PixelPart& p : res.parts) p.pixels /= o.frames;
    res.pixel_ratio = res.shaded_pixels / res.native_pixels;
    res.bound_share = res.speedup * res.pixel_ratio;
    if (r.series && r.series->frames() > 0) res.metrics = r.series->summary();
    out.results.push_back(std::move(res));
  }
  return out;
}

}  // namespace foveate::app
