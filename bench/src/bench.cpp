#include "foveate/bench/bench.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "bench_run.hpp"
#include "foveate/bench/frame_order.hpp"
#include "foveate/bench/statistics.hpp"
#include "foveate/core/parse.hpp"
#include "foveate/core/stats.hpp"

namespace foveate::bench {

Shard parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  double k = 0, n = 0;
  const bool numbers = slash != std::string::npos && parse_number(text.substr(0, slash), k) &&
                       parse_number(text.substr(slash + 1), n);
  if (!numbers || k != std::floor(k) || n != std::floor(n) || n < 1 || k < 1 || k > n || n > 1000) {
    throw OptionError("shard",
                      "expected K/N, job K of N (1 <= K <= N <= 1000), got '" + text + "'");
  }
  return {static_cast<int>(k) - 1, static_cast<int>(n)};
}

void validate(const BenchOptions& o) {
  validate(o.session);
  if (o.frames < 1 || o.frames > 100000) throw OptionError("frames", "expected 1..100000");
  if (o.warmup < 0 || o.warmup > 1000) throw OptionError("warmup", "expected 0..1000");
  if (o.techniques) {
    if (o.techniques->empty()) throw OptionError("techniques", "give at least one technique");
    for (const std::string& t : *o.techniques)
      for_field("techniques", [&] { return technique_info(t); });
    reject_repeats("techniques", *o.techniques,
                   {"each runs once; compare settings of one technique with {sweep}", {"sweep"}});
  }
  o.params.validate(o.techniques.value_or(technique_names()));
  if (o.runs.empty()) o.sweep.check_values(o.techniques.value_or(technique_names()));
  // Every technique's margin swept replaces the session's in every run:
  // results.json would record a margin no run used.
  if (o.session.margin && o.sweep.technique.empty() && o.sweep.param == kPlanMarginKey) {
    throw OptionError("sweep", FieldText{"{sweep} " + o.sweep.key +
                                             " and {margin}: the sweep sets each run's margin; "
                                             "give one of them",
                                         {"sweep", "margin"}});
  }
  const auto check_runs = [](const std::vector<RunSpec>& runs, const std::string& field) {
    for (size_t i = 0; i < runs.size(); ++i) {
      const RunSpec& r = runs[i];
      const std::string where = field + "[" + std::to_string(i) + "]";
      const TechniqueInfo info = for_field(field, [&] { return technique_info(r.technique); });
      for (const auto& [key, value] : r.params) {
        // (A named copy: clang 15 cannot capture a structured binding.)
        const std::string& name = key;
        const bool known = std::any_of(info.params.begin(), info.params.end(),
                                       [&](const ParamDecl& d) { return d.key == name; });
        if (!known) {
          throw OptionError(field, where + ": " + r.technique + " has no parameter '" + key + "'");
        }
        if (!std::isfinite(value)) {
          throw OptionError(field, where + ": " + r.technique + "." + key + " is not finite");
        }
      }
    }
  };
  check_runs(o.runs, "runs");
  check_runs(o.settle_runs, "settle_runs");
  if (!o.runs.empty() && (o.techniques || !o.sweep.empty())) {
    throw OptionError("runs", FieldText{"{runs}: give explicit runs or {techniques} and "
                                        "{sweep}, not both",
                                        {"runs", "techniques", "sweep"}});
  }
  if (o.shard.count < 1 || o.shard.count > 1000 || o.shard.index < 0 ||
      o.shard.index >= o.shard.count) {
    throw OptionError("shard", "expected K/N with 1 <= K <= N <= 1000 (job K of N), got " +
                                   std::to_string(o.shard.index + 1) + "/" +
                                   std::to_string(o.shard.count));
  }
  if (!(o.memory_limit_bytes >= 0.0) || !std::isfinite(o.memory_limit_bytes)) {
    throw OptionError("memory_limit",
                      "expected a size of at least 0 bytes (0 = 70 % of the "
                      "memory available)");
  }
  if (o.group.count < 1 || o.group.index < 0 || o.group.index >= o.group.count) {
    throw OptionError("group", "expected group index 0 <= K < N, got " +
                                   std::to_string(o.group.index) + " of " +
                                   std::to_string(o.group.count));
  }
  if (o.reference != 1 && !(o.reference >= 2 && o.reference <= 8)) {
    throw OptionError("reference", "expected 1 (native itself) or 2..8 samples per pixel and axis");
  }
  if (o.reference > 1 && o.session.stereo) {
    throw OptionError("reference",
                      FieldText{"{reference}: the supersampled reference is monocular; not "
                                "available with {stereo} (each eye is judged against native for "
                                "that eye)",
                                {"reference", "stereo"}});
  }
  if (o.reference > 1 && !o.image_metrics) {
    // It would be rendered every frame, at N x N the pixels, and judged
    // nothing against, while results.json recorded it.
    throw OptionError("reference",
                      FieldText{"{reference}: the supersampled reference is what the image "
                                "metrics judge against, and {image_metrics} turns them off",
                                {"reference", "image_metrics"}});
  }
  if (o.side_by_side && o.video.empty()) {
    throw OptionError("side_by_side",
                      FieldText{"{side_by_side}: only with {video}", {"side_by_side", "video"}});
  }
}

double available_memory_bytes() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key, unit;
  double kib = 0;
  while (meminfo >> key >> kib >> unit) {
    if (key == "MemAvailable:") return kib * 1024.0;
  }
  const long pages = ::sysconf(_SC_AVPHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  return pages > 0 && page > 0 ? double(pages) * double(page) : 0.0;
}

double judged_run_bytes(const BenchOptions& o) {
  if (!o.image_metrics) return 0.0;
  metrics::QualityOptions q;
  q.diagnostics = o.diagnostics;
  q.fvvdp_options.fps = o.session.fps;
  const int w = o.session.size.width, h = o.session.size.height;
  // A stereo run is judged in four series of one eye's size (both eyes as
  // two streams of one, and each eye alone) and renders two views.
  const double series = o.session.stereo ? 4.0 : 1.0, views = o.session.stereo ? 2.0 : 1.0;
  // About 30 bytes a pixel for a technique's targets and history.
  return series * metrics::QualitySeries::memory_estimate(w, h, o.frames, q) +
         views * 30.0 * double(w) * double(h);
}

namespace {

// "1.5 GiB", "300 MiB".
std::string memory_text(double bytes) {
  const double mib = bytes / double(1 << 20);
  return mib >= 1024.0 ? format_number(mib / 1024.0, 2) + " GiB"
                       : format_number(std::round(mib), 0) + " MiB";
}

}  // namespace

int judging_groups(const BenchOptions& o, double limit_bytes) {
  const double per_run = judged_run_bytes(o);
  if (limit_bytes <= 0.0 || per_run <= 0.0) return 1;
  // This shard's runs (the count add_runs deals it; every technique listed
  // or registered, which may be more than the scene runs).
  int runs = 0;
  if (!o.runs.empty()) {
    runs = static_cast<int>(o.runs.size());
  } else {
    for (const std::string& t : o.techniques.value_or(technique_names())) {
      if (t != "native")
        runs += o.sweep.applies_to(t) ? static_cast<int>(o.sweep.values.size()) : 1;
    }
  }
  const int mine = runs / o.shard.count + (o.shard.index < runs % o.shard.count ? 1 : 0);
  const auto at_once = static_cast<int>(std::floor(limit_bytes / per_run));
  if (at_once < 2) {
    throw OptionError(
        "memory_limit",
        FieldText{"{memory_limit}: " + memory_text(limit_bytes) +
                      " holds not even native and one run judged at " +
                      std::to_string(o.session.size.width) + "x" +
                      std::to_string(o.session.size.height) + " (about " + memory_text(per_run) +
                      " each); allow more, or judge a smaller {size}",
                  {"memory_limit", "size"}});
  }
  const int groups = mine <= 0 ? 1 : (mine + at_once - 2) / (at_once - 1);
  if (groups > 1 && !o.video.empty()) {
    throw OptionError(
        "video",
        FieldText{"{video}: every run's frames are tiled in one video, but " +
                      std::to_string(mine + 1) + " runs judged at once (" +
                      memory_text((mine + 1) * per_run) + ") exceed {memory_limit} (" +
                      memory_text(limit_bytes) + "); write the video of fewer {techniques}",
                  {"video", "memory_limit", "techniques"}});
  }
  return groups;
}

namespace {

// The groups' results as one: native from the first, every other run from
// the group that measured it, in the order of one run.
BenchResult join_groups(std::vector<BenchResult> parts) {
  BenchResult out = std::move(parts.front());
  for (size_t g = 1; g < parts.size(); ++g) {
    out.warmup = std::max(out.warmup, parts[g].warmup);
    for (TechniqueResult& r : parts[g].results) {
      if (r.run_index != 0) out.results.push_back(std::move(r));
    }
  }
  std::stable_sort(
      out.results.begin(), out.results.end(),
      [](const TechniqueResult& a, const TechniqueResult& b) { return a.run_index < b.run_index; });
  out.techniques.clear();
  for (const TechniqueResult& r : out.results) out.techniques.push_back(r.technique);
  out.memory_groups = static_cast<int>(parts.size());
  out.options.group = {};
  // The machine around the whole benchmark, from the first group's start.
  finish_environment(out.environment);
  return out;
}

// Once per benchmark, however many groups judged it.
BenchResult said_if_busy(BenchResult r, const BenchCallbacks& callbacks) {
  if (const auto busy = busy_machine(r.environment); busy && callbacks.session.notice)
    callbacks.session.notice({NoticeKind::Warning, {*busy, {}}});
  return r;
}

}  // namespace

BenchResult run_bench(const BenchOptions& options, const BenchCallbacks& callbacks) {
  validate(options);
  const double limit =
      options.memory_limit_bytes > 0 ? options.memory_limit_bytes : 0.7 * available_memory_bytes();
  const int groups = options.group.count > 1 ? 1 : judging_groups(options, limit);
  if (groups == 1) return said_if_busy(BenchRun(options, callbacks).run(), callbacks);
  if (callbacks.session.notice) {
    callbacks.session.notice(
        {NoticeKind::Note,
         FieldText{"the runs judged at once would hold more memory than {memory_limit} allows (" +
                       memory_text(limit) + "): they are judged in " + std::to_string(groups) +
                       " groups, one after another, each timed against its own native",
                   {"memory_limit"}}});
  }
  // One progress over every group: the first group's count of steps for
  // each (the groups differ by a run at most), one finish at the end.
  BenchCallbacks each = callbacks;
  each.finish = nullptr;
  // Each group sets up the same session: what it notes once is said once.
  auto said = std::make_shared<std::set<std::string>>();
  if (callbacks.session.notice) {
    each.session.notice = [said, notice = callbacks.session.notice](const Notice& n) {
      if (said->insert(n.text.render()).second) notice(n);
    };
  }
  std::vector<BenchResult> parts;
  for (int g = 0; g < groups; ++g) {
    BenchOptions o = options;
    o.group = {g, groups};
    each.start = nullptr;
    if (g == 0 && callbacks.start) {
      each.start = [&](int steps, int metrics_steps) {
        callbacks.start(steps * groups, metrics_steps * groups);
      };
    }
    parts.push_back(BenchRun(o, each).run());
  }
  if (callbacks.finish) callbacks.finish();
  return said_if_busy(join_groups(std::move(parts)), callbacks);
}

BenchResult BenchRun::run() {
  out_.options = options_;
  choose_techniques();
  check_gaze_source();
  out_.display = session_.display();
  if (session_.options().stereo) out_.stereo = session_.stereo_display();
  out_.scene = session_.scene().info().name;
  out_.environment = capture_environment(options_.command);
  out_.renderer = out_.environment.renderer;
  if (options_.reference > 1) reference_ = session_.make_reference(options_.reference);
  add_runs();
  // Warm up until every technique is steady (its own settle_frames), at
  // least as long as asked.
  out_.warmup = options_.warmup;
  for (const Run& r : runs_) out_.warmup = std::max(out_.warmup, r.impl.view->settle_frames());
  out_.warmup = std::max(out_.warmup, unmeasured_settle_);
  if (out_.warmup > options_.warmup) {
    // Said, since the frames measured are not the ones asked for.
    std::string who;
    for (const Run& r : runs_) {
      if (r.impl.view->settle_frames() == out_.warmup) {
        who = r.result.label.empty() ? r.technique : r.result.label;
        break;
      }
    }
    const std::string n = std::to_string(out_.warmup);
    notice(NoticeKind::Note,
           {"warm-up of " + n + " frames, not the " + std::to_string(options_.warmup) +
                " asked ({warmup}): " +
                (who.empty() ? "a run of the campaign (settle_runs) needs " + n +
                                   " to settle, and every benchmark of it measures the same "
                                   "frames"
                             : who + " needs " + n + " to settle (its work per frame steady)") +
                "; frames " + n + "-" + std::to_string(out_.warmup + options_.frames - 1) +
                " are measured",
            {"warmup"}});
  }
  open_video();
  // Where every frame is read back (to be judged or encoded), the frames are
  // timed in a pass of their own that reads nothing back, then rendered again
  // from the start to be read: on llvmpipe a frame rendered after a read-back
  // and the judging took up to 12 % longer, the cheaper techniques' the most
  // (docs/performance.md), so judged runs understated their speedups.
  images_apart_ = options_.time_apart && (options_.image_metrics || video_);
  out_.environment.timed_apart = images_apart_;
  // Steps: every frame rendered (twice where apart), and every frame judged
  // (the metrics take as long as the rendering on a CPU), so that the time
  // left is honest.
  int judged_runs = 0;
  if (options_.image_metrics) judged_runs = static_cast<int>(runs_.size()) - (reference_ ? 0 : 1);
  const int steps =
      static_cast<int>(runs_.size()) * (options_.frames + out_.warmup) * (images_apart_ ? 2 : 1) +
      judged_runs * options_.frames;
  if (callbacks_.start) callbacks_.start(steps, judged_runs * options_.frames);
  // On a renderer without GPU timers (llvmpipe) every measured frame runs
  // pass by pass, glFinish around each, with or without --passes: pipelined,
  // a frame's time depended on the technique rendered before it (on guenter
  // at 1080p native took about 300 ms after a frame of layered and 215 after
  // its own; docs/performance.md), so the shuffled order decided part of
  // every speedup. With GPU timers the profiler runs only for --passes.
  const bool pass_by_pass =
      gpu::PassProfiler::clock_for_current_renderer() == gpu::PassProfiler::Clock::Finish;
  if (options_.passes || pass_by_pass) profiler_.emplace();
  out_.environment.pass_by_pass = pass_by_pass;
  warm_up(true);
  orders_ = interleaved_orders(runs_.size(), options_.frames);
  for (int k = 0; k < options_.frames; ++k) measure(k, !images_apart_);
  if (images_apart_) {
    remake_runs();
    warm_up(false);
    for (int k = 0; k < options_.frames; ++k) render_images(k);
  }
  if (callbacks_.finish) callbacks_.finish();
  for (const std::string& e : session_.take_gl_errors())
    notice(NoticeKind::Warning, {"GL debug error: " + e, {}});
  out_.gaze_report = session_.gaze().report();
  // The finest plan the runs were made at (parameters and sweeps included).
  out_.savings = check_savings(session_.display(), options_.session.acuity,
                               session_.largest_plan_margin().value_or(strictest_plan_margin(
                                   options_.session.margin, out_.techniques)));
  finish_environment(out_.environment);
  if (video_) {
    video_->finish();
    out_.video_summary = video_summary(*video_, options_.session.fps);
  }
  summarize();
  return std::move(out_);
}

void BenchRun::summarize() {
  const std::vector<double> native_ms = runs_[0].result.frame_ms;  // results are moved out below
  // Speedups are ratios of mean frame times (throughput): a technique whose
  // cost alternates from frame to frame (half-rate layers) is judged by its
  // average, where a median would pick one phase.
  const double native_mean = mean(native_ms);
  const double frames = options_.frames;
  for (size_t i = 0; i < runs_.size(); ++i) {
    Run& r = runs_[i];
    TechniqueResult& res = r.result;
    res.median_ms = quantile(res.frame_ms, 0.5);
    res.p90_ms = quantile(res.frame_ms, 0.9);
    res.mean_ms = mean(res.frame_ms);
    res.speedup = native_mean / res.mean_ms;
    std::tie(res.speedup_lo, res.speedup_hi) = speedup_interval(native_ms, res.frame_ms);
    res.shaded_pixels /= frames;
    res.native_pixels /= frames;
    for (PixelPart& p : res.parts) p.pixels /= frames;
    for (gpu::PassTime& p : res.passes) p.ms /= frames;
    res.pixel_ratio = res.shaded_pixels / res.native_pixels;
    res.bound_share = res.speedup * res.pixel_ratio;
    if (r.series && r.series->frames() > 0) res.metrics = r.series->summary();
    for (size_t e = 0; e < res.eyes.size(); ++e) {
      TechniqueResult::Eye& eye = res.eyes[e];
      eye.shaded_pixels /= frames;
      eye.native_pixels /= frames;
      eye.pixel_ratio = eye.shaded_pixels / eye.native_pixels;
      if (r.eye_series[e] && r.eye_series[e]->frames() > 0)
        eye.metrics = r.eye_series[e]->summary();
    }
    out_.results.push_back(std::move(res));
  }
}

}  // namespace foveate::bench
