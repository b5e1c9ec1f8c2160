// foveate view: a live window with a panel (app/viewer/): the gaze follows the
// mouse unless --gaze says otherwise; technique, parameters, acuity model,
// display, A/B and split screen against native, measured frame time and
// speedup. --commands / --script drive the same actions from a script.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <chrono>
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
    "1-9 technique, Space A/B (native), S split screen, O overlay, R reset parameters, "
    "Esc or Q quit";

/// The window's framebuffer as an opaque image.
Image grab_window(gpu::Window& w) {
  Image img = gpu::read_framebuffer(0, w.framebuffer_width(), w.framebuffer_height());
  for (size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 255;
  return img;
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
  o.window_size = {o.size.width * (o.stereo ? 2 : 1) + kPanelWidth, std::max(o.size.height, 560)};
  with_flag("--technique", [&] { return technique_info(a.technique); });
  // Any technique can be switched to: a value must belong to one of them.
  const bench::ParamOverrides params = session_params(a.session, technique_names());
  // The mouse is the gaze unless --gaze says otherwise (normalized, top-left),
  // while it is over the image and not over the panel or the divider.
  std::optional<Vec2d> mouse;
  if (o.gaze.empty()) o.gaze = "mouse";
  bench::SessionCallbacks callbacks = session_callbacks();
  callbacks.mouse = [&]() -> std::optional<Vec2d> { return mouse; };
  bench::Session session(o, callbacks);
  gpu::Window& window = *session.window();
  Viewer view(session, a.technique, params, a.session.acuity_preset, a.session.slope);
  view.set_overlay(a.overlay);
  Ui ui(window);
  std::fprintf(stderr, "foveate view: keys %s; techniques:", kKeys);
  for (size_t i = 0; i < view.available().size(); ++i)
    std::fprintf(stderr, " %zu %s", i + 1, view.available()[i].c_str());
  std::fprintf(stderr, "\n");

  const auto start = std::chrono::steady_clock::now();
  Image last;
  for (int frame = 0; a.frames == 0 || frame < a.frames; ++frame) {
    const gpu::Window::Input in = window.poll();
    if (in.should_close) break;
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    FrameActions actions;
    if (script) script->begin_frame(view, frame, wall, actions);
    if (actions.quit) break;
    bool quit = false;
    if (!ui.wants_keyboard()) {
      for (int key : in.keys_pressed) {
        if (key == GLFW_KEY_ESCAPE || key == GLFW_KEY_Q) quit = true;
        if (key == GLFW_KEY_O) view.set_overlay(!view.overlay());
        if (key == GLFW_KEY_SPACE) view.set_show_native(!view.show_native());
        if (key == GLFW_KEY_S) view.set_split(!view.split());
        if (key == GLFW_KEY_R) view.reset_params();
        const int n = static_cast<int>(view.available().size());
        if (key >= GLFW_KEY_1 && key < GLFW_KEY_1 + std::min(n, 9)) {
          try {
            view.set_technique(view.available()[static_cast<size_t>(key - GLFW_KEY_1)]);
          } catch (const Error& e) {
            std::fprintf(stderr, "foveate view: %s\n", e.what());
          }
        }
      }
    }
    if (quit) break;
    const bool over_image = in.mouse_inside && in.mouse_x >= 0 && in.mouse_y >= 0 &&
                            in.mouse_x < view.width() && in.mouse_y < view.height();
    if (over_image && !ui.wants_mouse() && !ui.dragging_divider() && session.stereo()) {
      // Over either eye: the combined gaze that puts this eye's gaze (parallel
      // gaze) under the mouse, as a position in the cyclopean view.
      const int W = o.size.width, H = o.size.height;
      const bool right = in.mouse_x >= W;
      const Vec2d axis =
          session.stereo_display().eye(right ? Eye::Right : Eye::Left).principal_point();
      const double x = in.mouse_x - (right ? W : 0);
      mouse = Vec2d{(0.5 * W + x - axis.x) / W, (0.5 * H + in.mouse_y - axis.y) / H};
    } else if (over_image && !ui.wants_mouse() && !ui.dragging_divider()) {
      mouse = Vec2d{in.mouse_x / view.width(), in.mouse_y / view.height()};
    } else {
      mouse.reset();
    }
    const GazeState gaze = session.gaze().at(wall);
    FrameInput input = session.frame_runner().frame_input(frame);
    input.time_s = o.start_time_s + wall;  // the viewer runs on the wall clock
    session.watchdog().run("frame " + std::to_string(frame) + " (" + view.technique().name() + ")",
                           [&] { view.render_frame(input, gaze, wall); });
    ui.draw(view);
    // Before the swap: the back buffer holds what is about to be shown.
    for (const std::string& path : actions.screenshots) {
      write_png(path, grab_window(window));
      std::fprintf(stderr, "foveate view: wrote %s\n", path.c_str());
    }
    if (!a.screenshot.empty()) last = grab_window(window);
    for (int i = 0; i < actions.print_state; ++i) std::cout << view.state().dump() << std::endl;
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
