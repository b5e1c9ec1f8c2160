#pragma once
// The viewer's panel (Dear ImGui, Debian's libimgui-dev with its GLFW and
// OpenGL 3 backends) beside the output: technique, parameters with their
// ranges and units, acuity model, display, A/B and split screen against
// native, frame time and measured speedup with a graph of frame times per
// technique against native, shaded share, the overlay's legend, the gaze
// (following the mouse, held or frozen), and saving the parameters or
// copying them as a command line. Every change goes through Viewer's
// actions. The panel scrolls when the window cannot be tall enough for it.
#include <map>
#include <string>

#include "foveate/gpu/context.hpp"
#include "viewer/viewer.hpp"

namespace foveate::app::viewer {

/// Width of the panel right of the output, in pixels.
inline constexpr int kPanelWidth = 380;

class Ui {
 public:
  /// Binds ImGui to the window (its input callbacks chain to the window's own).
  explicit Ui(gpu::Window& window);
  ~Ui();
  Ui(const Ui&) = delete;
  Ui& operator=(const Ui&) = delete;

  /// Builds and draws the panel into the window's framebuffer (call after
  /// Viewer::render_frame, before swapping). Handles the split divider's drag.
  void draw(Viewer& viewer);
  /// Whether ImGui takes the mouse (over the panel) or the keyboard (typing).
  [[nodiscard]] bool wants_mouse() const;
  [[nodiscard]] bool wants_keyboard() const;
  /// Whether the mouse is dragging the split divider (the gaze then holds).
  [[nodiscard]] bool dragging_divider() const { return dragging_; }
  /// The height the panel's contents need, and whether it scrolls in the
  /// window it has (as of the last draw).
  [[nodiscard]] float content_height() const { return content_height_; }
  [[nodiscard]] bool scrolls() const { return scrolls_; }

 private:
  void parameters(Viewer& v);
  void measurements(Viewer& v);
  void legend_and_gaze(Viewer& v);
  void frame_time_graph(Viewer& v);
  void save_and_share(Viewer& v);
  void acuity_and_display(Viewer& v);
  void draw_divider(Viewer& v);
  /// Runs a Viewer action, keeping its error to show.
  template <class Fn>
  void act(Fn&& fn);

  void* window_;                           // the GLFW window (its clipboard)
  std::map<std::string, double> pending_;  // slider values being dragged
  std::string error_;
  std::string done_;  // what the last save or copy did
  char params_path_[512] = "foveate-params.json";
  bool dragging_ = false;
  float content_height_ = 0;
  bool scrolls_ = false;
};

}  // namespace foveate::app::viewer
