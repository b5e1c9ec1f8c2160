// The measured frames of a benchmark: every run renders frame k before any
// renders k + 1, in an order shuffled anew for every frame
// (interleaved_orders). Where every frame is judged or encoded, the timed
// pass reads nothing back and an image pass renders the frames again to read
// them; otherwise the last frame's images are read between its timed renders.
#include <cmath>

#include "bench_run.hpp"
#include "foveate/core/parse.hpp"
#include "report_common.hpp"

namespace foveate::bench {

namespace {

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

}  // namespace

GazeState BenchRun::gaze_at(int frame) {
  const auto f = static_cast<size_t>(frame);
  if (f < gazes_.size()) return gazes_[f];
  gazes_.push_back(session_.gaze().at(session_.frame_runner().frame_input(frame).time_s));
  // A gaze off the image or in the filter's fallback makes every technique
  // run its fallback: the frame is reported, not silently averaged in.
  const int k = frame - out_.warmup;
  if (k >= 0 && (session_.gaze().last().fallback || session_.gaze().last_off_image()))
    out_.fallback_frames.push_back(k);
  return gazes_.back();
}

BenchRun::Reference BenchRun::reference_frame(int frame) {
  // The image every run is judged against: native (read in the frame's
  // loop), or the supersampled reference (untimed, rendered from a scene of
  // its own).
  Reference reference;
  if (!reference_) return reference;
  const int n = options_.reference;
  ReferenceFrames* cache = options_.reference_frames.get();
  if (cache && cache->frames.count(frame)) {
    reference.out = cache->frames.at(frame);
    return reference;
  }
  reference.out = session_.watchdog().run(
      "frame " + std::to_string(frame) + " of the ssaa:" + std::to_string(n) + " reference",
      [&] { return reference_->render(session_.frame_runner().frame_input(frame)); },
      double(n) * n);
  if (cache) cache->frames[frame] = reference.out;
  return reference;
}

void BenchRun::measure(int k, bool read) {
  const std::vector<size_t>& order = orders_[static_cast<size_t>(k)];
  const int frame = out_.warmup + k;
  const bool last = k + 1 == options_.frames;
  const GazeState g = gaze_at(frame);
  Reference reference;
  if (read) reference = reference_frame(frame);
  std::vector<std::pair<size_t, Images>> images;
  for (size_t i : order) {
    Run& r = runs_[i];
    SessionFrame stats;
    if (profiler_) profiler_->begin_frame();
    const double ms =
        session_.watchdog().run("frame " + std::to_string(frame) + " (" + r.technique + ")", [&] {
          timer_.start();
          stats = session_.render(r.impl, frame, g);
          return timer_.stop();
        });
    record(r, stats, ms);
    if (read && (options_.image_metrics || last || video_)) keep_images(i, images, reference);
    step(r.technique + (options_.sweep.empty() ? "" : " @" + format_fixed(r.sweep_value, 4)));
  }
  if (read) finish_frame(k, images, reference, g);
}

void BenchRun::keep_images(size_t i, std::vector<std::pair<size_t, Images>>& images,
                           Reference& reference) const {
  Images img = read_images();
  if (i == 0 && !reference_) reference = {img.out, img.eyes};
  images.emplace_back(i, std::move(img));
}

void BenchRun::render_images(int k) {
  const int frame = out_.warmup + k;
  const GazeState g = gaze_at(frame);
  Reference reference = reference_frame(frame);
  std::vector<std::pair<size_t, Images>> images;
  // The timed pass's order: no technique reads the shared output before
  // drawing it, but nothing here need rely on that.
  for (size_t i : orders_[static_cast<size_t>(k)]) {
    Run& r = runs_[i];
    session_.watchdog().run("frame " + std::to_string(frame) + " (" + r.technique + ", images)",
                            [&] { session_.render(r.impl, frame, g); });
    keep_images(i, images, reference);
    step("images " + r.technique);
  }
  finish_frame(k, images, reference, g);
}

void BenchRun::finish_frame(int k, std::vector<std::pair<size_t, Images>>& images,
                            const Reference& reference, const GazeState& g) {
  const bool last = k + 1 == options_.frames;
  if (video_) write_video_frame(images, g);
  for (auto& [i, img] : images) judge(i, img, reference, g, last);
  if (last) {
    out_.native_sample = runs_[0].result.sample;
    if (reference_) out_.reference_sample = reference.out;
  }
}

void BenchRun::write_video_frame(const std::vector<std::pair<size_t, Images>>& images,
                                 const GazeState& g) {
  // Untimed: the frames were read back after the clock stopped.
  std::vector<Image> tiles(shown_.size());
  std::vector<const Image*> ptrs;
  for (size_t s = 0; s < shown_.size(); ++s) {
    for (const auto& [i, img] : images) {
      if (i == shown_[s]) tiles[s] = img.out;
    }
    if (options_.side_by_side && session_.options().stereo) {
      // Each eye's own gaze, in its half.
      const std::array<GazeState, 2> eg = session_.eye_gazes(g);
      mark_gaze(tiles[s], eg[0].gaze_px);
      mark_gaze(tiles[s], {eg[1].gaze_px.x + options_.session.size.width, eg[1].gaze_px.y});
    } else if (options_.side_by_side) {
      mark_gaze(tiles[s], g.gaze_px);
    }
    label_tile(tiles[s], label(out_, runs_[shown_[s]].result));
    ptrs.push_back(&tiles[s]);
  }
  video_->write(tile(ptrs));
}

void BenchRun::judge(size_t i, Images& img, const Reference& ref, const GazeState& g, bool last) {
  Run& r = runs_[i];
  const bool stereo = session_.options().stereo;
  const std::array<GazeState, 2> eye_gaze =
      stereo ? session_.eye_gazes(g) : std::array<GazeState, 2>{g, g};
  const bool judged = options_.image_metrics && (i != 0 || reference_);
  // FovVideoVDP's distortion map of the last frame, for the report.
  if (judged) {
    r.series->set_fvvdp_heatmap(last);
    for (auto& es : r.eye_series) {
      if (es) es->set_fvvdp_heatmap(last);
    }
  }
  if (judged && stereo) {
    for (size_t e = 0; e < 2; ++e)
      r.eye_series[e]->add(ref.eyes[e], img.eyes[e], eye_gaze[e].gaze_px);
    r.series->add(ref.eyes[0], img.eyes[0], eye_gaze[0].gaze_px);
    const Vec2d mirrored_gaze{options_.session.size.width - eye_gaze[1].gaze_px.x,
                              eye_gaze[1].gaze_px.y};
    r.series->add(mirrored(ref.eyes[1]), mirrored(img.eyes[1]), mirrored_gaze, 1);
    step("metrics " + r.technique, "metrics");
  } else if (judged) {
    r.series->add(ref.out, img.out, g.gaze_px);
    step("metrics " + r.technique, "metrics");
  }
  if (!last) return;
  if (judged) keep_heatmaps(r, img, ref, eye_gaze);
  r.result.sample = std::move(img.out);
  r.result.overlay = session_.overlay(r.impl, g);
  out_.sample_gaze_px = eye_gaze[0].gaze_px;
  out_.sample_eye_gaze_px = {eye_gaze[0].gaze_px, eye_gaze[1].gaze_px};
}

void BenchRun::keep_heatmaps(Run& r, const Images& img, const Reference& ref,
                             const std::array<GazeState, 2>& eye_gaze) {
  const auto fvvdp_picture = [](const metrics::QualitySeries& series, const Image& reference,
                                metrics::Map* distortion) {
    const metrics::QualitySummary q = series.summary();
    if (!q.fvvdp || q.fvvdp->worst_heatmap.values.empty()) return Image{};
    if (distortion) *distortion = q.fvvdp->worst_heatmap;
    return metrics::fvvdp_heatmap_image(q.fvvdp->worst_heatmap, reference, 1.0);
  };
  if (!session_.options().stereo) {
    r.result.fvvdp_heatmap = fvvdp_picture(*r.series, ref.out, &r.result.fvvdp_distortion);
    r.result.heatmap = metrics::error_heatmap(ref.out, img.out, 64.0);
    r.result.acuity_heatmap = metrics::acuity_error_heatmap(
        ref.out, img.out, r.series->display(), eye_gaze[0].gaze_px, r.series->options());
    return;
  }
  std::array<Image, 2> heat, acuity_heat;
  for (size_t e = 0; e < 2; ++e) {
    heat[e] = metrics::error_heatmap(ref.eyes[e], img.eyes[e], 64.0);
    acuity_heat[e] =
        metrics::acuity_error_heatmap(ref.eyes[e], img.eyes[e], r.eye_series[e]->display(),
                                      eye_gaze[e].gaze_px, r.eye_series[e]->options());
  }
  std::array<Image, 2> fvvdp_heat;
  for (size_t e = 0; e < 2; ++e) {
    fvvdp_heat[e] = fvvdp_picture(*r.eye_series[e], ref.eyes[e], nullptr);
  }
  if (!fvvdp_heat[0].empty() && !fvvdp_heat[1].empty()) {
    r.result.fvvdp_heatmap = tile({&fvvdp_heat[0], &fvvdp_heat[1]});
  }
  r.result.heatmap = tile({&heat[0], &heat[1]});
  r.result.acuity_heatmap = tile({&acuity_heat[0], &acuity_heat[1]});
}

}  // namespace foveate::bench
