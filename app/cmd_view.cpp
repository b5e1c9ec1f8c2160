// foveate view: an interactive window. The gaze follows the mouse (Silvera's
// stand-in for an eye tracker) unless --gaze says otherwise; number keys switch
// techniques, O toggles the overlay, Escape quits.
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
#include "foveate/gpu/frame.hpp"
#include "session.hpp"

namespace foveate::app {

namespace {

struct ViewArgs {
  SessionArgs session;
  std::string technique = "layered";
  bool overlay = true;
  int frames = 0;
  std::string screenshot;
};

void run_view(const ViewArgs& a) {
  if (a.frames < 0) throw Error("--frames: must be >= 0 (0 = until the window closes)");
  SessionOptions o = to_session_options(a.session, "now");
  o.window = true;
  with_flag("--technique", [&] { return technique_info(a.technique); });
  const ParamArgs params = parse_params(a.session.params);
  validate_params(params, {a.technique});
  // The mouse is the gaze unless --gaze says otherwise (normalized, top-left).
  gpu::Window::Input last_input;
  gpu::Window* window = nullptr;
  Session session(o, a.session.gaze.empty() ? "mouse" : a.session.gaze,
                  [&]() -> std::optional<Vec2d> {
                    if (!last_input.mouse_inside || !window) return std::nullopt;
                    return Vec2d{last_input.mouse_x / window->framebuffer_width(),
                                 last_input.mouse_y / window->framebuffer_height()};
                  });
  window = session.window();
  Renderer& renderer = session.renderer();
  renderer.set_overlay(a.overlay);
  // The techniques this scene can run; the one asked for is refused with
  // render's message when it cannot.
  auto technique = session.make(a.technique, params);
  std::vector<std::string> names;
  for (const TechniqueInfo& t : techniques()) {
    if (scene_mismatch(t, session.scene().info()).empty()) names.push_back(t.name);
  }
  size_t current = 0;
  for (size_t i = 0; i < names.size(); ++i) {
    if (names[i] == a.technique) current = i;
  }
  gpu::FrameTimer timer;
  const auto start = std::chrono::steady_clock::now();
  double shown_ms = 0;
  std::fprintf(stderr, "foveate view: keys 1-%zu switch technique (%s), O overlay, Esc quit\n",
               names.size(),
               [&] {
                 std::string s;
                 for (size_t i = 0; i < names.size(); ++i)
                   s += (i ? ", " : "") + std::to_string(i + 1) + " " + names[i];
                 return s;
               }()
                   .c_str());
  for (int frame = 0; a.frames == 0 || frame < a.frames; ++frame) {
    const gpu::Window::Input in = window->poll();
    last_input = in;
    if (in.should_close) break;
    bool quit = false;
    for (int key : in.keys_pressed) {
      if (key == GLFW_KEY_ESCAPE || key == GLFW_KEY_Q) quit = true;
      if (key == GLFW_KEY_O) renderer.set_overlay(!renderer.options().overlay);
      if (key >= GLFW_KEY_1 && key < GLFW_KEY_1 + static_cast<int>(names.size())) {
        current = static_cast<size_t>(key - GLFW_KEY_1);
        technique = session.make(names[current], params);  // --param persists
      }
    }
    if (quit) break;
    const double t =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const GazeState gaze = session.gaze().at(t);
    FrameInput input = renderer.frame_input(frame);
    input.time_s = o.start_time + t;  // the viewer runs on the wall clock
    FrameStats s;
    const double ms =
        session.watchdog().run("frame " + std::to_string(frame) + " (" + names[current] + ")", [&] {
          timer.start();
          s = renderer.render(*technique, input, gaze);
          return timer.stop();
        });
    shown_ms = shown_ms == 0 ? ms : 0.9 * shown_ms + 0.1 * ms;
    session.present();
    char title[256];
    std::snprintf(title, sizeof title, "foveate: %s on %s, %.1f ms, %.0f %% of native pixels",
                  names[current].c_str(), session.scene().info().name.c_str(), shown_ms,
                  100.0 * s.shaded_pixels / s.native_pixels);
    window->set_title(title);
  }
  if (!a.screenshot.empty()) {
    write_png(a.screenshot,
              gpu::read_framebuffer(0, window->framebuffer_width(), window->framebuffer_height()));
    std::cout << "wrote " << a.screenshot << "\n";
  }
}

}  // namespace

void register_view(CLI::App& app) {
  auto a = std::make_shared<ViewArgs>();
  CLI::App* sub = app.add_subcommand("view", "Interactive window: the gaze follows the mouse");
  add_session_options(sub, a->session, false, "now");
  sub->add_option("--technique", a->technique, "Technique to start with")->capture_default_str();
  sub->add_flag(
      "--overlay,!--no-overlay", a->overlay,
      "Draw layer/region borders: on by default, --no-overlay starts without them (toggle "
      "with O)");
  sub->add_option("--frames", a->frames, "Quit after N frames (0 = run until closed)")
      ->capture_default_str();
  sub->add_option("--screenshot", a->screenshot, "Save the window's last frame as PNG on exit");
  sub->callback([a] { run_view(*a); });
}

const CommandRegistrar kView(25, register_view);

}  // namespace foveate::app
