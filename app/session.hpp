#pragma once
// What render, bench, demo and view share: a GL context, a scene, techniques
// configured from one acuity model, a fixed frame clock and a gaze.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "cli_util.hpp"
#include "foveate/core/image.hpp"
#include "foveate/gpu/context.hpp"
#include "foveate/techniques/technique.hpp"

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

struct SessionOptions {
  std::string scene = "raymarch";
  std::vector<std::string> channels;
  std::string camera_path;
  Size size{640, 360};
  std::string display = "desktop-1080p";
  AcuityModel acuity;
  double fps = 60.0;  ///< the fixed clock: frame k is at time start + k / fps
  double start_time = 0.0;
  Vec2d mouse_px{0, 0};
  bool mouse_down = false;
  /// Open a window (GLFW) instead of a headless context; the output is shown in it.
  bool window = false;
};

class Session {
 public:
  explicit Session(const SessionOptions& options);
  [[nodiscard]] Scene& scene() { return *scene_; }
  [[nodiscard]] const Display& display() const { return display_; }
  [[nodiscard]] const SessionOptions& options() const { return options_; }
  std::unique_ptr<Technique> make(const std::string& technique, const ParamArgs& params) const;
  [[nodiscard]] FrameInput frame_input(int frame) const;
  /// Renders frame `frame` with `technique` into the output target; returns stats.
  FrameStats render(Technique& technique, int frame, const GazeState& gaze, bool overlay = false);
  [[nodiscard]] Image read_output() const;
  [[nodiscard]] GLuint output_framebuffer() const { return fbo_.id(); }
  /// The window, when SessionOptions::window was set.
  [[nodiscard]] gpu::Window* window() const { return window_; }
  /// Copies the output to the window and swaps.
  void present();

 private:
  SessionOptions options_;
  std::unique_ptr<gpu::Context> context_;
  gpu::Window* window_ = nullptr;
  std::unique_ptr<Scene> scene_;
  Display display_;
  gpu::Texture color_;
  gpu::Framebuffer fbo_;
  std::unique_ptr<OverlayRenderer> overlay_;
};

}  // namespace foveate::app
