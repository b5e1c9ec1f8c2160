#pragma once
// What a session is set up from, typed, with the library's defaults: the
// scene, the output size and display, the acuity model and planning margin,
// the gaze, the clock, stereo and the frame timeout. validate() names the
// field of any bad value.
#include <optional>
#include <string>

#include "foveate/bench/watchdog.hpp"
#include "foveate/core/acuity.hpp"
#include "foveate/core/display.hpp"
#include "foveate/core/parse.hpp"
#include "foveate/scenes/scene.hpp"

namespace foveate::bench {

struct SessionOptions {
  std::string scene = "raymarch";         ///< a built-in scene, a Shadertoy file or a mesh file
  SceneOptions scene_options;             ///< channels, camera path, up axis, model memory, iDate
  PixelSize size{1920, 1080};             ///< the output (one eye's in stereo)
  std::string display = "desktop-1080p";  ///< a preset or a JSON file, resized to `size`
  /// The display's photometry (what FovVideoVDP judges with), field by field
  /// over the display's own.
  PhotometryOverrides photometry;
  AcuityModel acuity;  ///< what the metrics judge by
  /// Every technique plans for `acuity.finer(margin)` (1 = the model
  /// itself); unset, each technique's own planning margin (kPlanMarginKey).
  std::optional<double> margin;
  std::string gaze;            ///< a gaze source spec (gaze::make_gaze_source); empty = the centre
  bool strict_traces = false;  ///< a gaze trace row that cannot be read is an error
  double fps = 60.0;           ///< the fixed clock: frame k is at start_time_s + k / fps
  double start_time_s = 0.0;
  Vec2d mouse_px{0, 0};  ///< Shadertoy's mouse, pixels, origin top-left
  bool mouse_down = false;
  /// Open a window (GLFW) instead of a headless context; the output is shown in it.
  bool window = false;
  /// The window's size (0 x 0: the output's): room for a UI beside the
  /// output, or less than the output where the screen is smaller (the front
  /// end then shows the output scaled).
  PixelSize window_size{0, 0};
  /// A frame running longer than this stops the run (0 = off; FrameWatchdog).
  double frame_timeout_s = kDefaultFrameTimeoutS;
  /// Render both eyes of a stereo head-mounted display; `size` is then one
  /// eye's and the output is twice as wide.
  bool stereo = false;
  /// Stereo: the distance in metres the eyes converge at; unset = parallel.
  std::optional<double> vergence_m;
  /// A debug GL context (headless sessions): the errors the driver reports
  /// are collected (Session::take_gl_errors; a benchmark ends with a warning
  /// per error), for tests and for hunting a technique's GL mistakes.
  bool gl_debug = false;
};

/// Throws an OptionError naming the field of the first bad value.
void validate(const SessionOptions& options);

/// The acuity model of an acuity preset ("A", "B": AcuityModel::preset) or a
/// slope, at most one of them given (fields "acuity_preset" and "slope");
/// preset A when neither is.
AcuityModel acuity_from(const std::string& preset, std::optional<double> slope);
/// Throws an OptionError of "margin" unless 1 <= margin <= 4.
void check_margin(double margin);

}  // namespace foveate::bench
