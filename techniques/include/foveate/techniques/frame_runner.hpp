#pragma once
// The frame runner: one scene, one output target, a fixed frame clock and an
// optional overlay. Each call renders one frame of the scene with a technique
// for a gaze: the scene advances to the frame, the technique renders into the
// target, the overlay goes on top. The app (render, bench, view, demo), the
// tests and programs outside the tree all render through it, so the frame
// loop exists once.
#include <memory>
#include <optional>

#include "foveate/core/image.hpp"
#include "foveate/gpu/pass.hpp"
#include "foveate/techniques/overlay_pass.hpp"
#include "foveate/techniques/technique.hpp"

namespace foveate {

struct FrameRunnerOptions {
  int width = 0;  ///< output size in pixels (the display's, after Display::resized)
  int height = 0;
  double fps = 60.0;  ///< the fixed clock: frame k is at start_time_s + k / fps
  double start_time_s = 0.0;
  Vec2d mouse_px{0.0, 0.0};  ///< Shadertoy's mouse, pixels, origin top-left
  bool mouse_down = false;
  bool overlay = false;  ///< draw the technique's layer or region borders
  /// One eye of a stereo pair (StereoFrameRunner sets it): every FrameInput carries it.
  std::optional<EyeView> eye;
};

class FrameRunner {
 public:
  /// Renders `scene` (which must outlive the frame runner) into an RGBA8 output
  /// target of its own. Needs a current GL context; throws foveate::Error for
  /// a size the GL cannot allocate.
  FrameRunner(Scene& scene, const FrameRunnerOptions& options);
  /// Renders into `target` instead (e.g. a user's framebuffer or a window's).
  FrameRunner(Scene& scene, const FrameRunnerOptions& options, gpu::RenderTarget target);
  ~FrameRunner();
  FrameRunner(const FrameRunner&) = delete;
  FrameRunner& operator=(const FrameRunner&) = delete;

  /// The inputs of frame `frame` on the fixed clock.
  [[nodiscard]] FrameInput frame_input(int frame) const;
  /// Renders frame `frame` (fixed clock) with `technique` for `gaze`.
  FrameStats render(Technique& technique, int frame, const GazeState& gaze);
  /// Renders with explicit inputs (a live clock, a moving mouse).
  FrameStats render(Technique& technique, const FrameInput& input, const GazeState& gaze);

  [[nodiscard]] Scene& scene() const { return scene_; }
  [[nodiscard]] const gpu::RenderTarget& output() const { return target_; }
  /// The output as an image (owned targets, or any target by framebuffer read).
  [[nodiscard]] Image read_output() const;
  [[nodiscard]] const FrameRunnerOptions& options() const { return options_; }
  void set_overlay(bool on) { options_.overlay = on; }
  void set_mouse(Vec2d px, bool down) {
    options_.mouse_px = px;
    options_.mouse_down = down;
  }

 private:
  Scene& scene_;
  FrameRunnerOptions options_;
  gpu::RenderTarget target_;
  std::unique_ptr<OverlayPass> overlay_;
};

}  // namespace foveate
