#pragma once
// Stereo frames for head-mounted displays: the two eyes side by side in one
// output image (the left eye in the left half). Nothing is shared between the
// eyes: each eye has its own scene instance (camera moved to the eye, its
// off-axis frustum; multipass buffers and G-buffers of its own), its own
// FrameRunner and target, and its own technique instance (history, jitter,
// masks), configured for the eye's display and following the eye's gaze.
#include <array>
#include <memory>

#include "foveate/core/stereo.hpp"
#include "foveate/techniques/frame_runner.hpp"

namespace foveate {

/// Each eye's GazeState for a combined gaze `cyclopean` (its gaze_px a
/// position in StereoDisplay::cyclopean()) fixating at `vergence_m` metres
/// (infinity = parallel): fovea scale, latency and saccade speed are shared.
std::array<GazeState, 2> eye_gaze_states(const StereoDisplay& display, const GazeState& cyclopean,
                                         double vergence_m);

/// The per-eye frame inputs for an eye of `display` (its offset and frustum).
EyeView eye_view(const StereoDisplay& display, Eye eye);

class StereoFrameRunner {
 public:
  /// `display` at the per-eye render size (Display::resized of the left eye,
  /// then StereoDisplay::from); `options` holds the per-eye size. The scenes
  /// (one per eye, distinct instances) must outlive the frame runner. Needs a
  /// current GL context.
  StereoFrameRunner(Scene& left, Scene& right, const StereoDisplay& display,
                    const FrameRunnerOptions& options);
  ~StereoFrameRunner();
  StereoFrameRunner(const StereoFrameRunner&) = delete;
  StereoFrameRunner& operator=(const StereoFrameRunner&) = delete;

  /// Renders frame `frame` of both eyes, each with its own technique (made
  /// for that eye's display: refused otherwise) for its own gaze, then
  /// copies them side by side into the output. Returns each eye's stats.
  std::array<FrameStats, 2> render(Technique& left, Technique& right, int frame,
                                   const std::array<GazeState, 2>& gaze);
  /// The same with explicit inputs (a live clock): each eye gets `input` with
  /// its own EyeView.
  std::array<FrameStats, 2> render(Technique& left, Technique& right, const FrameInput& input,
                                   const std::array<GazeState, 2>& gaze);
  [[nodiscard]] FrameRunner& eye(Eye e) { return *eyes_[static_cast<size_t>(e)]; }
  [[nodiscard]] const StereoDisplay& display() const { return display_; }
  /// The side-by-side output, twice the eye's width.
  [[nodiscard]] const gpu::RenderTarget& output() const { return output_; }
  [[nodiscard]] Image read_output() const;
  /// One eye's image (its own target).
  [[nodiscard]] Image read_eye(Eye e) const;
  void set_overlay(bool on);

 private:
  StereoDisplay display_;
  std::array<std::unique_ptr<FrameRunner>, 2> eyes_;
  gpu::RenderTarget output_;
};

}  // namespace foveate
