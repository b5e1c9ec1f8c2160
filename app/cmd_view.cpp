// foveate view: a live window with a panel (app/viewer/): the gaze follows the
// mouse over the image unless --gaze says otherwise, and holds while the
// mouse is elsewhere; technique, parameters, acuity model, display, A/B and
// split screen against native, measured frame time and speedup. The window
// fits the screen it opens on. --commands / --script drive the same actions
// from a script.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include "cli_util.hpp"
#include "commands.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"
#include "foveate/gaze/gaze.hpp"
#include "foveate/gpu/frame.hpp"
#include "messages.hpp"
#include "session_args.hpp"
#include "viewer/viewer.hpp"
#include "viewer/viewer_script.hpp"
#include "viewer/viewer_ui.hpp"

namespace foveate::app {

namespace {

struct ViewArgs {
  SessionArgs session;
  std::string technique = "layered";
  bool overlay = true;
  int frames = 0;
  std::string screenshot;
  std::string commands;
  std::string script;
};

const char* kKeys =
    "1-9 technique, Space A/B (native), S split screen, O overlay, F freeze the gaze, "
    "R reset parameters, Esc or Q quit";

// Room left on the screen for the window's title bar and borders, which the
// window's size does not include.
constexpr int kDecorationPx = 40;

// The work area of the primary monitor (the screen less its task bars), or
// nullopt when GLFW cannot tell (no display: creating the window then fails
// with its own message).
std::optional<PixelSize> screen_work_area() {
  if (!glfwInit()) return std::nullopt;
  GLFWmonitor* monitor = glfwGetPrimaryMonitor();
  if (!monitor) return std::nullopt;
  int x = 0, y = 0, w = 0, h = 0;
  glfwGetMonitorWorkarea(monitor, &x, &y, &w, &h);
  if (w <= 0 || h <= 0) {
    const GLFWvidmode* mode = glfwGetVideoMode(monitor);
    if (!mode) return std::nullopt;
    w = mode->width, h = mode->height;
  }
  return PixelSize{w, h};
}

// The window: the image beside the panel, the image shrunk (never enlarged)
// until the window fits the work area; and the image's scale.
struct WindowFit {
  PixelSize window;
  double scale = 1.0;
};
WindowFit fit_window(int image_w, int image_h, std::optional<PixelSize> area) {
  constexpr int kMinPanelHeight = 560;
  WindowFit f{{image_w + viewer::kPanelWidth, std::max(image_h, kMinPanelHeight)}, 1.0};
  if (!area) return f;
  const int max_w = area->width, max_h = std::max(area->height - kDecorationPx, 200);
  f.scale = std::min({1.0, double(max_w - viewer::kPanelWidth) / image_w, double(max_h) / image_h});
  f.scale = std::max(f.scale, 0.1);
  const int shown_w = static_cast<int>(std::lround(image_w * f.scale));
  const int shown_h = static_cast<int>(std::lround(image_h * f.scale));
  f.window = {std::min(shown_w + viewer::kPanelWidth, max_w),
              std::min(std::max(shown_h, kMinPanelHeight), max_h)};
  return f;
}

/// The window's framebuffer as an opaque image.
Image grab_window(gpu::Window& w) {
  Image img = gpu::read_framebuffer(0, w.framebuffer_width(), w.framebuffer_height());
  for (size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 255;
  return img;
}

/// The viewer's keys; true when one asks to quit.
bool handle_keys(viewer::Viewer& view, const std::vector<int>& keys) {
  bool quit = false;
  for (int key : keys) {
    if (key == GLFW_KEY_ESCAPE || key == GLFW_KEY_Q) quit = true;
    if (key == GLFW_KEY_O) view.set_overlay(!view.overlay());
    if (key == GLFW_KEY_SPACE) view.set_show_native(!view.show_native());
    if (key == GLFW_KEY_S) view.set_split(!view.split());
    if (key == GLFW_KEY_R) view.reset_params();
    if (key == GLFW_KEY_F) view.mouse_gaze().set_frozen(!view.mouse_gaze().frozen());
    const int n = static_cast<int>(view.available().size());
    if (key >= GLFW_KEY_1 && key < GLFW_KEY_1 + std::min(n, 9)) {
      try {
        view.set_technique(view.available()[static_cast<size_t>(key - GLFW_KEY_1)]);
      } catch (const Error& e) {
        std::fprintf(stderr, "foveate view: %s\n", e.what());
      }
    }
  }
  return quit;
}

/// The mouse gaze follows the pointer over the image (in the image's pixels:
/// it may be shown scaled), and holds where the panel or nothing is under it.
void follow_pointer(viewer::Viewer& view, bench::Session& session, const viewer::Pointer& pointer,
                    bool ui_has_it) {
  const double mx = pointer.x / view.display_scale(), my = pointer.y / view.display_scale();
  const bool over_image =
      pointer.inside && mx >= 0 && my >= 0 && mx < view.width() && my < view.height() && !ui_has_it;
  if (over_image && session.stereo()) {
    // Over either eye: the combined gaze that puts this eye's gaze (parallel
    // gaze) under the mouse, as a position in the cyclopean view.
    const int W = view.width() / 2, H = view.height();
    const bool right = mx >= W;
    const Vec2d axis =
        session.stereo_display().eye(right ? Eye::Right : Eye::Left).principal_point();
    const double x = mx - (right ? W : 0);
    view.mouse_gaze().update(Vec2d{(0.5 * W + x - axis.x) / W, (0.5 * H + my - axis.y) / H});
  } else if (over_image) {
    view.mouse_gaze().update(Vec2d{mx / view.width(), my / view.height()});
  } else {
    view.mouse_gaze().update(std::nullopt);
  }
}

/// The window made tall enough for the panel's contents where the screen
/// allows (the panel scrolls beyond), grown as they grow (the graphs appear
/// with the first measurements) but never past a height already fitted, so
/// a window the user made smaller stays so.
void fit_panel(gpu::Window& window, viewer::Ui& ui, PixelSize area, int& fitted_height) {
  const int want =
      std::min(static_cast<int>(std::ceil(ui.content_height())), area.height - kDecorationPx);
  if (want > fitted_height && want > window.framebuffer_height()) {
    glfwSetWindowSize(static_cast<GLFWwindow*>(window.native_handle()), window.framebuffer_width(),
                      want);
  }
  fitted_height = std::max(fitted_height, want);
}

void run_view(const ViewArgs& a) {
  using namespace viewer;
  if (a.frames < 0) throw Error("--frames: must be >= 0 (0 = until the window closes)");
  if (!a.commands.empty() && !a.script.empty())
    throw Error("--commands and --script: give one of them");
  std::optional<Script> script;
  if (!a.commands.empty()) script.emplace(a.commands, "--commands");
  if (!a.script.empty()) script.emplace(read_file(a.script), "--script " + a.script);
  bench::SessionOptions o = to_session_options(a.session, "now");
  o.window = true;
  const std::optional<PixelSize> area = screen_work_area();
  const WindowFit fit = fit_window(o.size.width * (o.stereo ? 2 : 1), o.size.height, area);
  o.window_size = fit.window;
  with_flag("--technique", [&] { return technique_info(a.technique); });
  // Any technique can be switched to: a value must belong to one of them.
  const bench::ParamOverrides params = session_params(a.session, technique_names());
  // The mouse is the gaze unless --gaze says otherwise (normalized, top-left):
  // where it is over the image, or where it last was (MouseGaze).
  if (o.gaze.empty()) o.gaze = "mouse";
  Viewer* viewer = nullptr;
  bench::SessionCallbacks callbacks = session_callbacks();
  callbacks.mouse = [&]() -> std::optional<Vec2d> {
    return viewer ? viewer->mouse_gaze().position() : Vec2d{0.5, 0.5};
  };
  bench::Session session(o, callbacks);
  gpu::Window& window = *session.window();
  Viewer view(session, a.technique, params, a.session.acuity_preset, a.session.slope);
  viewer = &view;
  view.set_overlay(a.overlay);
  view.set_display_scale(fit.scale);
  Ui ui(window);
  std::fprintf(stderr, "foveate view: keys %s; techniques:", kKeys);
  for (size_t i = 0; i < view.available().size(); ++i)
    std::fprintf(stderr, " %zu %s", i + 1, view.available()[i].c_str());
  std::fprintf(stderr, "\n");

  const auto start = std::chrono::steady_clock::now();
  Image last;
  std::optional<Pointer> scripted;  // a script's pointer, instead of the real one
  int fitted_height = 0;            // the tallest the window was made for the panel
  for (int frame = 0; a.frames == 0 || frame < a.frames; ++frame) {
    const gpu::Window::Input in = window.poll();
    if (in.should_close) break;
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    FrameActions actions;
    if (script) script->begin_frame(view, frame, wall, actions);
    if (actions.quit) break;
    if (actions.pointer) scripted = actions.pointer;
    const Pointer pointer = scripted ? *scripted : Pointer{in.mouse_inside, in.mouse_x, in.mouse_y};
    if (!ui.wants_keyboard() && handle_keys(view, in.keys_pressed)) break;
    // (ImGui follows the real mouse: a script's pointer is judged by its place alone.)
    const bool ui_has_it = !scripted && (ui.wants_mouse() || ui.dragging_divider());
    follow_pointer(view, session, pointer, ui_has_it);
    const GazeState gaze = session.gaze().at(wall);
    FrameInput input = session.frame_runner().frame_input(frame);
    input.time_s = o.start_time_s + wall;  // the viewer runs on the wall clock
    session.watchdog().run("frame " + std::to_string(frame) + " (" + view.technique().name() + ")",
                           [&] { view.render_frame(input, gaze, wall); });
    ui.draw(view);
    if (area) fit_panel(window, ui, *area, fitted_height);
    // Before the swap: the back buffer holds what is about to be shown.
    for (const std::string& path : actions.screenshots) {
      write_png(path, grab_window(window));
      std::fprintf(stderr, "foveate view: wrote %s\n", path.c_str());
    }
    if (!a.screenshot.empty()) last = grab_window(window);
    for (int i = 0; i < actions.print_state; ++i) {
      nlohmann::json state = view.state();
      state["window"] = {{"width", window.framebuffer_width()},
                         {"height", window.framebuffer_height()}};
      if (area) state["screen"] = {{"width", area->width}, {"height", area->height}};
      state["panel"] = {{"content_height", ui.content_height()}, {"scrolls", ui.scrolls()}};
      std::cout << state.dump() << std::endl;
    }
    window.swap_buffers();
    char title[256];
    std::snprintf(title, sizeof title, "foveate: %s on %s, %.1f ms", view.technique_name().c_str(),
                  session.scene().info().name.c_str(), view.stats().frame_ms);
    window.set_title(title);
  }
  if (!a.screenshot.empty() && last.width > 0) {
    write_png(a.screenshot, last);
    std::fprintf(stderr, "foveate view: wrote %s\n", a.screenshot.c_str());
  }
}

}  // namespace

void register_view(CLI::App& app) {
  auto a = std::make_shared<ViewArgs>();
  CLI::App* sub = app.add_subcommand(
      "view", "Live window with a control panel: the gaze follows the mouse over the image");
  sub->footer(
      std::string("Keys: ") + kKeys +
      ".\nThe panel beside the image: technique; a slider per parameter with its range "
      "and unit (hover for its meaning; Ctrl+click to type; * = set by you or --param, "
      "kept across technique switches); acuity preset A/B and MAR slope; display; show native "
      "or split screen (native left, foveated right, drag the divider); frame time, "
      "native sampled once a second on the same frame and the speedup; the share of "
      "pixels shaded; what each overlay colour marks; the gaze source and filter.\n\n" +
      viewer::Script::help() + "\n");
  add_session_options(sub, a->session, false, "now", true);
  sub->get_option("--gaze")->description(
      std::string("Gaze source; default the mouse over the image. ") + gaze::gaze_spec_help());
  sub->add_option("--technique", a->technique, "Technique to start with")->capture_default_str();
  sub->add_flag(
      "--overlay,!--no-overlay", a->overlay,
      "Draw layer/region borders: on by default, --no-overlay hides them (toggle with O)");
  sub->add_option("--frames", a->frames, "Quit after N frames (0 = run until closed)")
      ->capture_default_str();
  sub->add_option("--screenshot", a->screenshot,
                  "Save the window's last frame (image and panel) as PNG on exit");
  sub->add_option("--commands", a->commands,
                  "Script to run, commands separated by ';' (see below), e.g. \"param "
                  "layers=2; technique logpolar; frames 3; screenshot s.png; print-state; quit\"");
  sub->add_option("--script", a->script, "Script file (one command per line)");
  sub->callback([a] { run_view(*a); });
}

const CommandRegistrar kView(25, register_view);

}  // namespace foveate::app
