#pragma once
// What rendering, benchmarking and viewing share: a GL context, a scene, the
// frame runner (one view, or both eyes of a stereo display), the gaze
// tracker, the frame watchdog, and techniques configured from one acuity
// model. One frame function serves mono and stereo.
#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "foveate/bench/notice.hpp"
#include "foveate/bench/params.hpp"
#include "foveate/bench/session_options.hpp"
#include "foveate/bench/watchdog.hpp"
#include "foveate/core/image.hpp"
#include "foveate/core/stereo.hpp"
#include "foveate/gaze/tracker.hpp"
#include "foveate/gpu/context.hpp"
#include "foveate/techniques/frame_runner.hpp"
#include "foveate/techniques/stereo_frame_runner.hpp"
#include "foveate/techniques/supersampled_native.hpp"

namespace foveate::bench {

/// What a session tells its front end while it runs.
struct SessionCallbacks {
  NoticeFn notice;               ///< the set-up (Detail), notes and warnings
  FrameTimeoutFn frame_timeout;  ///< a frame ran past frame_timeout_s (FrameWatchdog)
  /// The window's mouse (normalized, top-left) for the `mouse` gaze source.
  std::function<std::optional<Vec2d>()> mouse;
};

/// A technique as a session renders it: one instance for the one view, or
/// one per eye, each made for its eye's display.
struct SessionTechnique {
  std::unique_ptr<Technique> view;   ///< the one view's, or the left eye's
  std::unique_ptr<Technique> right;  ///< stereo: the right eye's own instance
};

/// One frame's pixel counts: both eyes together (or the one view) and, in
/// stereo, each eye's.
struct SessionFrame {
  FrameStats total;
  std::array<FrameStats, 2> eyes;
};

/// Native with N x N supersampling for a session's scene: its own copy of
/// the scene (so neither reallocates per frame) and the resolve.
struct SupersampledScene {
  std::unique_ptr<Scene> scene;
  std::unique_ptr<SupersampledNative> supersampled;
  /// The reference image of frame `input`.
  Image render(const FrameInput& input);
};

class Session {
 public:
  /// Creates the context, loads the scene, the frame runner and the gaze tracker.
  /// Throws an OptionError naming the field of a bad value.
  explicit Session(const SessionOptions& options, SessionCallbacks callbacks = {});
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  [[nodiscard]] Scene& scene() { return *scene_; }
  [[nodiscard]] const Display& display() const { return display_; }
  [[nodiscard]] const SessionOptions& options() const { return options_; }
  /// The frame runner; in stereo the left eye's (its clock is both eyes').
  [[nodiscard]] FrameRunner& frame_runner() {
    return stereo_ ? stereo_->eye(Eye::Left) : *frame_runner_;
  }
  /// Stereo sessions: both eyes and the frame runner that puts them side by side; null otherwise.
  [[nodiscard]] StereoFrameRunner* stereo() { return stereo_.get(); }
  [[nodiscard]] const StereoDisplay& stereo_display() const { return stereo_display_; }
  /// Each eye's gaze for the tracker's combined gaze (stereo sessions).
  [[nodiscard]] std::array<GazeState, 2> eye_gazes(const GazeState& combined) const;
  [[nodiscard]] gaze::GazeTracker& gaze() { return *gaze_; }
  /// Every frame is drawn through it (SessionOptions::frame_timeout_s).
  [[nodiscard]] FrameWatchdog& watchdog() { return *watchdog_; }
  /// The GL renderer's name (GL_RENDERER).
  [[nodiscard]] std::string gl_renderer() const { return context_->renderer(); }
  /// The GL errors reported since the last call (SessionOptions::gl_debug).
  std::vector<std::string> take_gl_errors();

  /// The configuration a technique for `eye` (Left for the one view) gets:
  /// the display, `acuity` (the session's when unset) and the margin.
  [[nodiscard]] TechniqueConfig technique_config(
      Eye eye = Eye::Left, std::optional<AcuityModel> acuity = std::nullopt) const;
  /// A technique (one per eye in stereo) planned with the session's margin,
  /// or its own; refused with a clear error when it cannot render the scene.
  /// Bad parameters are an OptionError of "params".
  SessionTechnique make(const std::string& technique, const ParamOverrides& params,
                        std::optional<AcuityModel> acuity = std::nullopt) const;
  /// The largest planning margin of the techniques made so far (the finest
  /// plan, with its parameters and the session's margin applied); unset
  /// while none that plans by a margin was made. The savings note
  /// (bench::check_savings) is for this plan: checked at the first frame
  /// rendered, and again at the first frame after a technique with a finer
  /// plan was made (the viewer's switch to it).
  [[nodiscard]] std::optional<double> largest_plan_margin() const { return largest_margin_; }
  /// Renders frame `frame` of the fixed clock (or `input`) for the combined gaze.
  SessionFrame render(SessionTechnique& technique, int frame, const GazeState& gaze);
  SessionFrame render(SessionTechnique& technique, const FrameInput& input, const GazeState& gaze);
  /// The output (both eyes side by side in stereo) and each eye's image.
  [[nodiscard]] Image read_output() const;
  [[nodiscard]] Image read_eye(Eye eye) const;
  /// The technique's overlay shapes for the combined gaze: in stereo the
  /// right eye's over the right half of the output.
  [[nodiscard]] std::vector<OverlayShape> overlay(const SessionTechnique& technique,
                                                  const GazeState& gaze) const;
  void set_overlay(bool on);

  /// The supersampled reference (`factor` > 1; refused in stereo).
  [[nodiscard]] std::unique_ptr<SupersampledScene> make_reference(int factor) const;
  /// The window, when SessionOptions::window was set.
  [[nodiscard]] gpu::Window* window() const { return window_; }
  /// Copies the output to the window and swaps.
  void present();
  /// Switches to another display (preset or JSON file, resized to the
  /// output's size); the gaze tracker restarts with it. Techniques made
  /// before keep the old display: make them again.
  void set_display(const std::string& display);

 private:
  /// The options' photometry over the display's own; an OptionError of
  /// "photometry.KEY" for a bad value.
  void apply_photometry(Display& display) const;
  void make_context();
  void make_frame_runners();
  void make_tracker();
  void announce() const;
  /// The savings note before a frame, for the finest plan made (margins are
  /// known only once techniques are made): checked at the first frame, and
  /// again only when a finer plan was made since.
  void note_savings();

  SessionOptions options_;
  SessionCallbacks callbacks_;
  /// options_.scene_options with the scene's load warnings sent to the
  /// session's notices, each once per session however often it loads the
  /// scene (a stereo pair's second eye, the supersampled reference).
  SceneOptions scene_options_;
  mutable std::optional<double> largest_margin_;  ///< made techniques' (make is const)
  std::optional<double> savings_checked_;         ///< the margin note_savings last checked
  std::unique_ptr<gpu::Context> context_;
  gpu::Window* window_ = nullptr;
  std::unique_ptr<Scene> scene_;
  std::unique_ptr<Scene> right_scene_;  ///< stereo: the right eye's own instance
  Display display_;
  StereoDisplay stereo_display_;
  std::unique_ptr<FrameRunner> frame_runner_;
  std::unique_ptr<StereoFrameRunner> stereo_;
  std::unique_ptr<gaze::GazeTracker> gaze_;
  std::unique_ptr<FrameWatchdog> watchdog_;
};

}  // namespace foveate::bench
