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
#include "gaze_input.hpp"
#include "session.hpp"

namespace foveate::app {

namespace {

struct ViewArgs {
  std::string scene = "raymarch";
  std::string size = "960x540";
  std::string technique = "layered";
  std::string quality;
  std::optional<double> slope;
  std::vector<std::string> params;
  std::string gaze;
  std::string display = "desktop-1080p";
  std::string camera_path;
  std::vector<std::string> channels;
  bool overlay = true;
  int frames = 0;
  std::string screenshot;
};

void run_view(const ViewArgs& a) {
  if (a.frames < 0) throw Error("--frames: must be >= 0 (0 = until the window closes)");
  SessionOptions o;
  o.scene = a.scene;
  o.size = parse_size(a.size, "--size");
  o.display = a.display;
  o.acuity = acuity_from_options(a.quality, a.slope);
  o.camera_path = a.camera_path;
  o.channels = a.channels;
  o.window = true;
  const ParamArgs params = parse_params(a.params);
  Session session(o);
  std::vector<std::string> names;
  for (const TechniqueInfo& t : techniques()) {
    if (t.name != "lodmask" || session.scene().info().has_mesh_lods) names.push_back(t.name);
  }
  size_t current = 0;
  for (size_t i = 0; i < names.size(); ++i) {
    if (names[i] == a.technique) current = i;
  }
  (void)technique_info(a.technique);
  validate_params(params, {a.technique});
  auto technique = session.make(names[current], params);
  // The mouse is the gaze unless --gaze says otherwise (normalized, top-left).
  gpu::Window::Input last_input;
  GazeInput gaze_input(a.gaze.empty() ? "mouse" : a.gaze, session, [&]() -> std::optional<Vec2d> {
    if (!last_input.mouse_inside) return std::nullopt;
    return Vec2d{last_input.mouse_x / session.window()->framebuffer_width(),
                 last_input.mouse_y / session.window()->framebuffer_height()};
  });
  bool overlay = a.overlay;
  gpu::FrameTimer timer;
  const auto start = std::chrono::steady_clock::now();
  double shown_ms = 0;
  std::printf("foveate view: keys 1-%zu switch technique (%s), O overlay, Esc quit\n", names.size(),
              [&] {
                std::string s;
                for (size_t i = 0; i < names.size(); ++i)
                  s += (i ? ", " : "") + std::to_string(i + 1) + " " + names[i];
                return s;
              }()
                  .c_str());
  for (int frame = 0; a.frames == 0 || frame < a.frames; ++frame) {
    const gpu::Window::Input in = session.window()->poll();
    last_input = in;
    if (in.should_close) break;
    bool quit = false;
    for (int key : in.keys_pressed) {
      if (key == GLFW_KEY_ESCAPE || key == GLFW_KEY_Q) quit = true;
      if (key == GLFW_KEY_O) overlay = !overlay;
      if (key >= GLFW_KEY_1 && key < GLFW_KEY_1 + static_cast<int>(names.size())) {
        current = static_cast<size_t>(key - GLFW_KEY_1);
        technique = session.make(names[current], ParamArgs{});
      }
    }
    if (quit) break;
    const double t =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const GazeState gaze = gaze_input.at(t);
    timer.start();
    const FrameStats s = session.render(*technique, frame, gaze, overlay);
    const double ms = timer.stop();
    shown_ms = shown_ms == 0 ? ms : 0.9 * shown_ms + 0.1 * ms;
    session.present();
    char title[256];
    std::snprintf(title, sizeof title, "foveate: %s on %s, %.1f ms, %.0f %% of native pixels",
                  names[current].c_str(), session.scene().info().name.c_str(), shown_ms,
                  100.0 * s.shaded_pixels / s.native_pixels);
    session.window()->set_title(title);
  }
  if (!a.screenshot.empty()) {
    write_png(a.screenshot, gpu::read_framebuffer(0, session.window()->framebuffer_width(),
                                                  session.window()->framebuffer_height()));
    std::cout << "wrote " << a.screenshot << "\n";
  }
}

}  // namespace

void register_view(CLI::App& app) {
  auto a = std::make_shared<ViewArgs>();
  CLI::App* sub = app.add_subcommand("view", "Interactive window: the gaze follows the mouse");
  sub->add_option("--scene", a->scene, "Built-in scene, Shadertoy .glsl file or mesh file")
      ->capture_default_str();
  sub->add_option("--size", a->size, "Window size WxH")->capture_default_str();
  sub->add_option("--technique", a->technique, "Technique to start with")->capture_default_str();
  sub->add_option("--quality", a->quality, "Acuity preset A or B (default A)");
  sub->add_option("--slope", a->slope, "Custom MAR slope m");
  sub->add_option("--param", a->params, "Technique parameter KEY=VALUE (repeatable)");
  sub->add_option("--gaze", a->gaze, "Gaze source instead of the mouse (X,Y | trace:FILE | synthetic | pupil[:HOST:PORT])");
  sub->add_option("--display", a->display, "Display preset or JSON file")->capture_default_str();
  sub->add_option("--camera-path", a->camera_path, "Camera keyframes JSON");
  sub->add_option("--channel", a->channels, "iChannel images for a Shadertoy shader");
  sub->add_flag("--overlay,!--no-overlay", a->overlay, "Draw layer/region borders (toggle with O)");
  sub->add_option("--frames", a->frames, "Quit after N frames (0 = run until closed)")
      ->capture_default_str();
  sub->add_option("--screenshot", a->screenshot, "Save the window's last frame as PNG on exit");
  sub->callback([a] { run_view(*a); });
}

const CommandRegistrar kView(25, register_view);

}  // namespace foveate::app
