#pragma once
// One benchmark run, step by step: the runs (each technique, or each swept
// value), the warm-up, the measured frames interleaved across the runs, the
// judging against the reference and the video, then the figures.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "foveate/bench/bench.hpp"
#include "foveate/bench/video.hpp"
#include "foveate/gpu/frame.hpp"
#include "foveate/gpu/profiler.hpp"

namespace foveate::bench {

class BenchRun {
 public:
  /// Creates the session (the options were validated).
  BenchRun(const BenchOptions& options, const BenchCallbacks& callbacks);
  BenchResult run();

 private:
  /// A technique's run, or one value of a sweep.
  struct Run {
    std::string technique;
    double sweep_value = 0;
    AcuityModel acuity;
    ParamOverrides params;  ///< what it was made with, to make it again
    SessionTechnique impl;
    TechniqueResult result;
    /// Against the reference: the one view, or (stereo) both eyes' frames,
    /// the right eye's mirrored into the left eye's geometry.
    std::unique_ptr<metrics::QualitySeries> series;
    std::array<std::unique_ptr<metrics::QualitySeries>, 2> eye_series;  ///< stereo
  };
  /// One run's image of a frame: the output and (stereo) each eye's.
  struct Images {
    Image out;
    std::array<Image, 2> eyes;
  };
  /// What the runs are judged against in one frame.
  struct Reference {
    Image out;
    std::array<Image, 2> eyes;  ///< stereo: native's eyes
  };

  void choose_techniques();
  void check_gaze_source();
  void add_run(const std::string& technique, double value, bool swept, int run_index,
               const RunSpec* spec, bool measured);
  void add_runs();
  void open_video();
  /// The gaze of frame `frame`, asked of the gaze source once and kept: the
  /// image pass renders with the gazes the timed pass had.
  GazeState gaze_at(int frame);
  /// Renders the warm-up frames; `timed`: the timed pass's (its last frame
  /// pass by pass where the measured ones are).
  void warm_up(bool timed);
  /// The timed render of measured frame `k`; `read`: its images read back
  /// (every frame's where judged or encoded, else the last's), judged and
  /// encoded in the same pass (images_apart_ false).
  void measure(int k, bool read);
  /// Reads run `i`'s images of the frame into `images` (and native's, when
  /// it is the reference, into `reference`).
  void keep_images(size_t i, std::vector<std::pair<size_t, Images>>& images,
                   Reference& reference) const;
  /// The image pass's render of measured frame `k`: untimed, read back,
  /// judged and encoded.
  void render_images(int k);
  /// Each run's technique made anew, in the state it started the timed pass in.
  void remake_runs();
  [[nodiscard]] Reference reference_frame(int frame);
  void finish_frame(int k, std::vector<std::pair<size_t, Images>>& images,
                    const Reference& reference, const GazeState& gaze);
  void record(Run& run, const SessionFrame& frame, double ms);
  [[nodiscard]] Images read_images() const;
  void write_video_frame(const std::vector<std::pair<size_t, Images>>& images,
                         const GazeState& gaze);
  void judge(size_t index, Images& images, const Reference& reference, const GazeState& gaze,
             bool last);
  void keep_heatmaps(Run& run, const Images& images, const Reference& reference,
                     const std::array<GazeState, 2>& eye_gaze);
  void summarize();
  void step(const std::string& detail, const std::string& kind = {}) const;
  void notice(NoticeKind kind, FieldText text) const;

  const BenchOptions& options_;
  const BenchCallbacks& callbacks_;
  BenchResult out_;
  Session session_;
  std::unique_ptr<SupersampledScene> reference_;
  std::vector<Run> runs_;
  /// Whether the video shows native's tile (listed, or a shard's baseline):
  /// the results always hold native, the reference of every JOD below native.
  bool native_listed_ = false;
  /// The settle frames of runs made but not measured here (other shards'
  /// runs, BenchOptions::settle_runs).
  int unmeasured_settle_ = 0;
  std::vector<std::vector<size_t>> orders_;  ///< each measured frame's order of the runs
  std::vector<GazeState> gazes_;             ///< each frame's gaze, from frame 0
  /// Whether the frames are timed in a pass of their own, none of them read
  /// back, and rendered again to be judged (RunEnvironment::timed_apart).
  bool images_apart_ = false;
  std::vector<size_t> shown_;  ///< the runs the video shows, in order
  std::unique_ptr<VideoWriter> video_;
  std::optional<gpu::PassProfiler> profiler_;
  gpu::FrameTimer timer_;
};

}  // namespace foveate::bench
