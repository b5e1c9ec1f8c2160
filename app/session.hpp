#pragma once
// What render, bench, demo and view share: a GL context, a scene, the frame
// runner (foveate::Renderer), the gaze tracker, techniques configured from one
// acuity model, and the command-line options that set them up (one set,
// registered by each command).
#include <CLI/CLI.hpp>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli_util.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/image.hpp"
#include "foveate/core/stereo.hpp"
#include "foveate/gaze/tracker.hpp"
#include "foveate/gpu/context.hpp"
#include "foveate/techniques/reference.hpp"
#include "foveate/techniques/renderer.hpp"
#include "foveate/techniques/stereo_renderer.hpp"
#include "watchdog.hpp"

namespace foveate::app {

/// --param values: "KEY=VALUE" applies to every technique that has KEY;
/// "TECHNIQUE.KEY=VALUE" to that technique only.
struct ParamArgs {
  std::map<std::string, std::map<std::string, double>> per_technique;  // "" = all
};
ParamArgs parse_params(const std::vector<std::string>& items);
/// Throws when a KEY without a technique prefix belongs to none of `techniques`.
void validate_params(const ParamArgs& p, const std::vector<std::string>& techniques);
/// The overrides for one technique (only keys it knows when given without prefix).
std::map<std::string, double> params_for(const ParamArgs& p, const std::string& technique);

/// iDate of render and bench unless --date says otherwise: runs stay
/// deterministic (a clock shader shows midnight plus the scene time).
inline constexpr const char* kFixedDate = "2026-01-01T00:00:00";

struct SessionOptions {
  std::string scene = "raymarch";
  std::vector<std::string> channels;
  std::string camera_path;
  std::string up;                        ///< mesh files: "y", "z" or "" (the file's)
  std::uint64_t model_memory_limit = 0;  ///< mesh files: bytes; 0 = the default
  ShadertoyDate date;                    ///< iDate of Shadertoy scenes
  Size size{1920, 1080};
  std::string display = "desktop-1080p";
  AcuityModel acuity;  ///< what the metrics judge by
  /// --margin: every technique plans for `acuity.finer(margin)` (1 = the
  /// model itself); unset, each technique's own planning margin (kPlanMarginKey).
  std::optional<double> margin;
  double fps = 60.0;  ///< the fixed clock: frame k is at time start + k / fps
  double start_time = 0.0;
  Vec2d mouse_px{0, 0};  ///< Shadertoy's mouse, pixels, origin top-left
  bool mouse_down = false;
  /// Open a window (GLFW) instead of a headless context; the output is shown in it.
  bool window = false;
  /// trace:FILE gaze: a row that cannot be read is an error (--strict).
  bool strict_traces = false;
  /// A frame running longer than this stops the run (--frame-timeout; 0 = off).
  double frame_timeout_s = kDefaultFrameTimeoutS;
  /// The window's size when larger than `size` (room for a UI beside the
  /// output); 0 = `size`.
  Size window_size{0, 0};
  /// Render both eyes of a stereo head-mounted display (--stereo); `size` is
  /// then one eye's and the output is twice as wide.
  bool stereo = false;
  /// The distance the two eyes converge at, metres (--vergence; inf = parallel).
  double vergence_m = std::numeric_limits<double>::infinity();
};

/// The options every rendering command has, as typed on the command line.
struct SessionArgs {
  std::string scene = "raymarch";
  std::string size = kDefaultSize;
  std::string display = "desktop-1080p";
  std::string quality;
  std::optional<double> slope;
  std::optional<double> margin;
  std::vector<std::string> params;
  std::string gaze;
  std::string camera_path;
  std::vector<std::string> channels;
  std::string up;
  std::string model_memory_limit;
  double fps = 60.0;
  double time = 0.0;
  bool strict = false;
  double frame_timeout = kDefaultFrameTimeoutS;
  std::string date;  ///< --date; empty = the command's default
  bool stereo = false;
  std::string vergence;  ///< --vergence; empty = infinity
};
/// Registers --scene --size --display --quality --slope --margin --param --gaze
/// --camera-path --channel --up --model-memory-limit --fps --time --strict --frame-timeout --date
/// on `sub`. `scene_required` makes --scene mandatory (render). `default_date` is what --date
/// means when not given ("now" in view; a fixed date elsewhere, for determinism).
/// `stereo` adds --stereo and --vergence (render and bench).
void add_session_options(CLI::App* sub, SessionArgs& args, bool scene_required = false,
                         const char* default_date = kFixedDate, bool stereo = false);
/// Checks the values and names the flag of any bad one; an empty --date
/// gives `default_date`.
SessionOptions to_session_options(const SessionArgs& args, const char* default_date = kFixedDate);

/// Runs `fn`, prefixing any foveate::Error it throws with `flag` ("--gaze: ...").
template <class Fn>
auto with_flag(const std::string& flag, Fn&& fn) -> decltype(fn()) {
  try {
    return fn();
  } catch (const Error& e) {
    throw Error(flag + ": " + e.what());
  }
}

/// Native with N x N supersampling for a session's scene: its own copy of
/// the scene (so neither reallocates per frame) and the resolve.
struct Reference {
  std::unique_ptr<Scene> scene;
  std::unique_ptr<SupersampledReference> supersampled;
  /// The reference image of frame `input`.
  Image render(const FrameInput& input);
};

class Session {
 public:
  /// Creates the context, loads the scene, the renderer and the gaze tracker
  /// for `gaze` (a spec; empty = the screen centre). `mouse` gives the
  /// window's mouse (normalized, top-left) for the `mouse` gaze source.
  Session(const SessionOptions& options, const std::string& gaze,
          std::function<std::optional<Vec2d>()> mouse = {});
  ~Session();
  [[nodiscard]] Scene& scene() { return *scene_; }
  [[nodiscard]] const Display& display() const { return display_; }
  [[nodiscard]] const SessionOptions& options() const { return options_; }
  /// The frame runner; in stereo the left eye's (its clock is both eyes').
  [[nodiscard]] Renderer& renderer() { return stereo_ ? stereo_->eye(Eye::Left) : *renderer_; }
  /// Stereo sessions (--stereo: render, bench, view): both eyes, their displays and the
  /// renderer that puts them side by side; null otherwise.
  [[nodiscard]] StereoRenderer* stereo() { return stereo_.get(); }
  [[nodiscard]] const StereoDisplay& stereo_display() const { return stereo_display_; }
  /// Each eye's gaze for the tracker's combined gaze (stereo sessions).
  [[nodiscard]] std::array<GazeState, 2> eye_gazes(const GazeState& combined) const {
    return eye_gaze_states(stereo_display_, combined, options_.vergence_m);
  }
  /// One technique per eye, each made for its eye's display (stereo sessions).
  std::array<std::unique_ptr<Technique>, 2> make_stereo(
      const std::string& technique, const ParamArgs& params,
      std::optional<AcuityModel> acuity = std::nullopt) const;
  [[nodiscard]] gaze::GazeTracker& gaze() { return *gaze_; }
  /// Every frame is drawn through it (--frame-timeout).
  [[nodiscard]] FrameWatchdog& watchdog() { return *watchdog_; }
  /// A technique for this session's display and acuity (`acuity` overrides
  /// it), planned with --margin where given and its own planning margin
  /// otherwise, refused with a clear error when it cannot render this scene.
  std::unique_ptr<Technique> make(const std::string& technique, const ParamArgs& params,
                                  std::optional<AcuityModel> acuity = std::nullopt) const;
  /// The supersampled reference (`factor` from parse_reference, > 1).
  [[nodiscard]] std::unique_ptr<Reference> make_reference(int factor) const;
  /// The window, when SessionOptions::window was set.
  [[nodiscard]] gpu::Window* window() const { return window_; }
  /// Copies the output to the window and swaps.
  void present();
  /// Switches to another display (preset or JSON file, resized to the
  /// output's size); the gaze tracker restarts with it. Techniques made
  /// before keep the old display: make them again.
  void set_display(const std::string& display);

 private:
  SessionOptions options_;
  std::unique_ptr<gpu::Context> context_;
  gpu::Window* window_ = nullptr;
  std::unique_ptr<Scene> scene_;
  std::unique_ptr<Scene> right_scene_;  ///< stereo: the right eye's own instance
  Display display_;
  StereoDisplay stereo_display_;
  std::unique_ptr<Renderer> renderer_;
  std::unique_ptr<StereoRenderer> stereo_;
  std::unique_ptr<gaze::GazeTracker> gaze_;
  std::unique_ptr<FrameWatchdog> watchdog_;
  std::string gaze_spec_;
  std::function<std::optional<Vec2d>()> mouse_;
  void make_tracker();
};

}  // namespace foveate::app
