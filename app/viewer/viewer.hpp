#pragma once
// The live viewer's state and actions, without any UI: the technique and its
// parameters (kept per technique, so a switch keeps what was set), the acuity
// model, the display, the A/B toggle and split screen against native, and the
// frame loop's measurements (frame time, native sampled periodically, the
// shaded share). The ImGui panel and the scripted mode (--commands) both drive
// it through the same calls. In a stereo session (--stereo) every technique is
// a pair, one instance per eye, shown side by side.
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "foveate/bench/params_file.hpp"
#include "foveate/bench/session.hpp"
#include "foveate/gpu/frame.hpp"

namespace foveate::app::viewer {

/// One entry of the overlay's legend: a colour, the shape it is drawn as (a
/// layer's target and its blend ring share a colour) and what it marks.
struct LegendEntry {
  float r = 1, g = 1, b = 1;
  std::string label;
  OverlayShape::Kind kind = OverlayShape::Kind::Rect;
};

/// Where the gaze is while it follows the mouse (no --gaze): the mouse over
/// the image; held at its last place on the image while the mouse is over
/// the panel, off the image or dragging the divider, or while frozen (F), so
/// that reaching for a slider never moves the gaze the image is tuned at
/// (nor drops it into the gaze filter's fallback). It starts at the centre.
class MouseGaze {
 public:
  /// This frame's pointer: its normalized place on the image (origin
  /// top-left) when it is over the image and the panel does not have it;
  /// nullopt otherwise.
  void update(std::optional<Vec2d> on_image);
  void set_frozen(bool on) { frozen_ = on; }
  [[nodiscard]] bool frozen() const { return frozen_; }
  /// What the gaze source reads (normalized, origin top-left).
  [[nodiscard]] Vec2d position() const { return position_; }
  /// "following", "held" (the mouse is not over the image) or "frozen".
  [[nodiscard]] const char* state() const;

 private:
  Vec2d position_{0.5, 0.5};
  bool frozen_ = false;
  bool away_ = false;
};

/// Frame times kept for the panel's graphs: the last this many per technique.
inline constexpr size_t kHistoryFrames = 240;

struct ViewerStats {
  double frame_ms = 0.0;  ///< the shown technique's frame time (smoothed), glFinish-bracketed
  double last_ms = 0.0;   ///< the last frame's
  std::optional<double> native_ms;  ///< native's, sampled about once a second
  FrameStats last;                  ///< the shown technique's last frame
  int native_samples = 0;
};

class Viewer {
 public:
  /// `params` (from --param) seed every technique's parameters; the acuity
  /// preset ("A", "B" or "" for A) or `slope` the acuity model.
  Viewer(bench::Session& session, const std::string& technique, const bench::ParamOverrides& params,
         const std::string& acuity_preset, std::optional<double> slope);
  ~Viewer();

  // Actions. Each throws foveate::Error naming the input when it is refused,
  // and then leaves the state as it was.
  void set_technique(const std::string& name);
  /// `technique` empty = the current one.
  void set_param(const std::string& technique, const std::string& key, double value);
  /// Forgets the current technique's overrides (back to the derived defaults).
  void reset_params();
  void set_acuity_preset(const std::string& preset);  ///< "A" or "B"
  void set_slope(double m);
  void set_display(const std::string& spec);
  void set_show_native(bool on) { show_native_ = on; }
  void set_split(bool on) { split_ = on; }
  void set_divider(double fraction);  ///< split position, 0..1 of the width
  void set_overlay(bool on);
  /// Measure native on the next frame (otherwise about once a second).
  void request_native_sample() { next_native_s_ = -1.0; }
  /// The image is shown at this scale (<= 1) so that the window fits the
  /// screen; rendering and measuring stay at the output's size.
  void set_display_scale(double scale);
  /// Writes every technique's parameters set here or by --param /
  /// --params-file to `path` as a parameters file (--params-file reads it).
  void save_params(const std::string& path) const;

  // State.
  [[nodiscard]] const std::vector<std::string>& available() const { return available_; }
  [[nodiscard]] const std::string& technique_name() const { return name_; }
  [[nodiscard]] const Technique& technique() const { return *technique_.view; }
  [[nodiscard]] const std::map<std::string, double>& overrides() const;
  /// "A", "B" or "custom" (a slope of its own).
  [[nodiscard]] const std::string& acuity_preset() const { return acuity_preset_; }
  [[nodiscard]] double slope() const { return acuity_.slope; }
  [[nodiscard]] const std::string& display_spec() const { return session_.options().display; }
  [[nodiscard]] bool show_native() const { return show_native_; }
  [[nodiscard]] bool split() const { return split_; }
  [[nodiscard]] double divider() const { return divider_; }
  [[nodiscard]] bool overlay() const { return session_.frame_runner().options().overlay; }
  [[nodiscard]] const ViewerStats& stats() const { return stats_; }
  [[nodiscard]] std::optional<double> speedup() const;
  [[nodiscard]] const GazeState& gaze() const { return gaze_; }
  [[nodiscard]] std::vector<LegendEntry> legend() const;
  /// The image's width: one eye's size twice in stereo.
  [[nodiscard]] int width() const {
    return session_.options().size.width * (session_.options().stereo ? 2 : 1);
  }
  [[nodiscard]] int height() const { return session_.options().size.height; }
  [[nodiscard]] double display_scale() const { return scale_; }
  /// The image's size in the window.
  [[nodiscard]] int shown_width() const;
  [[nodiscard]] int shown_height() const;
  [[nodiscard]] MouseGaze& mouse_gaze() { return mouse_gaze_; }
  [[nodiscard]] const MouseGaze& mouse_gaze() const { return mouse_gaze_; }
  /// Whether the gaze follows the mouse (no --gaze given).
  [[nodiscard]] bool gaze_follows_mouse() const;
  /// The last frame times (ms) of each technique shown, native's samples
  /// under "native"; at most kHistoryFrames each, oldest first.
  [[nodiscard]] const std::map<std::string, std::vector<float>>& history() const {
    return history_;
  }
  /// The parameters set (save_params writes them), by technique.
  [[nodiscard]] bench::TechniqueParams saved_params() const;
  /// A `foveate view` command line that starts the viewer as it is now: the
  /// scene, size, display, acuity, margin, technique and every parameter set.
  [[nodiscard]] std::string command_line() const;
  [[nodiscard]] bench::Session& session() { return session_; }

  /// Renders one frame (wall time `wall_s` since the start) and copies it to
  /// the window's top-left W x H; the rest of the window is cleared for the UI.
  void render_frame(const FrameInput& input, const GazeState& gaze, double wall_s);
  /// Everything above as one JSON object (the scripted mode's print-state).
  [[nodiscard]] nlohmann::json state() const;

 private:
  void rebuild();
  /// Rebuilds with `next`; restores the previous model when that fails.
  void use_acuity(const AcuityModel& next);
  /// The technique with its overrides (one instance per eye in stereo).
  bench::SessionTechnique build(const std::string& name) const;
  double timed_render(bench::SessionTechnique& t, const FrameInput& input, const GazeState& gaze,
                      bool with_overlay, FrameStats* stats);
  void blit_columns(int x0, int x1);
  void record(const std::string& technique, double ms);

  bench::Session& session_;
  std::vector<std::string> available_;
  std::map<std::string, std::map<std::string, double>> params_;  // per technique
  std::string name_;
  std::string acuity_preset_ = "A";
  AcuityModel acuity_;
  bench::SessionTechnique technique_;
  bench::SessionTechnique native_;
  bool show_native_ = false;
  bool split_ = false;
  double divider_ = 0.5;
  ViewerStats stats_;
  GazeState gaze_;
  int frames_since_build_ = 0;
  int native_renders_ = 0;  ///< since native_ was built (the first is not timed)
  int frame_ = 0;
  double next_native_s_ = -1.0;
  gpu::FrameTimer timer_;
  double scale_ = 1.0;
  MouseGaze mouse_gaze_;
  std::map<std::string, std::vector<float>> history_;
};

}  // namespace foveate::app::viewer
