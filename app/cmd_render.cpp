// foveate render / scenes / techniques: render frames of any scene with any
// technique to PNG, and list what there is.
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "cli_util.hpp"
#include "commands.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"
#include "foveate/techniques/reference.hpp"
#include "output_dir.hpp"
#include "session.hpp"

namespace foveate::app {

namespace {

struct RenderArgs {
  SessionArgs session;
  int frames = 1;
  std::string out;
  std::string technique = "native";
  std::string mouse;
  std::string reference = "native";
  bool overlay = false;
  RenderArgs() { session.size = "640x360"; }
};

void run_render(const RenderArgs& a) {
  if (a.frames < 1 || a.frames > 100000)
    throw Error("--frames: expected 1..100000, got " + std::to_string(a.frames));
  SessionOptions o = to_session_options(a.session);
  if (!a.mouse.empty()) {
    o.mouse_px = parse_point(a.mouse, o.size.width, o.size.height, "--mouse");
    o.mouse_down = true;
  }
  with_flag("--technique", [&] { return technique_info(a.technique); });
  const int reference = with_flag("--reference", [&] { return parse_reference(a.reference); });
  const ParamArgs params = parse_params(a.session.params);
  validate_params(params, {a.technique});
  const OutputDirLock out_lock(a.out, "--out");
  Session session(o, a.session.gaze);
  Renderer& renderer = session.renderer();
  renderer.set_overlay(a.overlay);
  auto technique = session.make(a.technique, params);
  const std::unique_ptr<Reference> supersampled =
      reference > 1 ? session.make_reference(reference) : nullptr;
  double shaded = 0, native = 0;
  for (int k = 0; k < a.frames; ++k) {
    const GazeState gaze = session.gaze().at(renderer.frame_input(k).time_s);
    const std::string frame = "frame " + std::to_string(k) + " (" + a.technique + ")";
    const FrameStats s =
        session.watchdog().run(frame, [&] { return renderer.render(*technique, k, gaze); });
    shaded += s.shaded_pixels;
    native += s.native_pixels;
    char name[64];
    std::snprintf(name, sizeof name, "frame-%04d.png", k);
    write_png((std::filesystem::path(a.out) / name).string(), renderer.read_output());
    if (supersampled) {
      std::snprintf(name, sizeof name, "reference-%04d.png", k);
      const Image ref = session.watchdog().run(
          "frame " + std::to_string(k) + " of the ssaa:" + std::to_string(reference) + " reference",
          [&] { return supersampled->render(renderer.frame_input(k)); },
          double(reference) * reference);
      write_png((std::filesystem::path(a.out) / name).string(), ref);
    }
  }
  std::cout << "rendered " << a.frames << " frame(s) of " << session.scene().info().name << " with "
            << a.technique << " at " << o.size.width << 'x' << o.size.height << " to " << a.out
            << "/\n";
  std::cout << "shaded pixels: " << fmt(shaded / a.frames, 0) << " per frame ("
            << fmt(100.0 * shaded / native, 1) << " % of native)\n"
            << session.gaze().report() << "\n";
}

}  // namespace

void register_render(CLI::App& app) {
  auto a = std::make_shared<RenderArgs>();
  CLI::App* sub =
      app.add_subcommand("render", "Render frames of a scene with a technique to PNG files");
  add_session_options(sub, a->session, true);
  sub->add_option("--frames", a->frames, "Number of frames")->capture_default_str();
  sub->add_option("--mouse", a->mouse,
                  "Shadertoy iMouse position X,Y (pixels or normalized), button down");
  sub->add_option("--out", a->out, "Output directory (frame-0000.png, ...)")->required();
  sub->add_option("--technique", a->technique, "Technique (see 'foveate techniques')")
      ->capture_default_str();
  sub->add_flag("--overlay", a->overlay, "Draw layer/region borders and the gaze point");
  sub->add_option("--reference", a->reference,
                  "Also write reference-NNNN.png: ssaa[:N] = native with NxN supersampling "
                  "(default N = 4), box-filtered in linear light (native = none)")
      ->capture_default_str();
  sub->callback([a] { run_render(*a); });
}

void register_scenes(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("scenes", "List the built-in scenes");
  sub->callback([] {
    for (const SceneListing& s : builtin_scenes())
      std::printf("%-10s %s\n", s.name.c_str(), s.description.c_str());
    std::printf(
        "\nAlso: a Shadertoy shader file (.glsl, .frag) or a mesh file (OBJ, glTF/GLB, PLY, FBX, "
        "3DS, ...).\n");
  });
}

void register_techniques(CLI::App& app) {
  auto display = std::make_shared<std::string>("desktop-1080p");
  auto size = std::make_shared<std::string>("1920x1080");
  auto quality = std::make_shared<std::string>();
  auto slope = std::make_shared<std::optional<double>>();
  CLI::App* sub =
      app.add_subcommand("techniques", "List the techniques with their parameters and defaults");
  sub->add_option("--display", *display, "Display for the derived defaults")->capture_default_str();
  sub->add_option("--size", *size, "Render size for the derived defaults")->capture_default_str();
  sub->add_option("--quality", *quality, "Acuity preset A or B (default A)");
  sub->add_option("--slope", *slope, "Custom MAR slope m");
  sub->callback([=] {
    const Size sz = parse_size(*size, "--size");
    TechniqueConfig c;
    c.display = with_flag("--display", [&] {
                  return Display::load(*display);
                }).resized(sz.width, sz.height);
    c.acuity = acuity_from_options(*quality, *slope);
    std::printf("defaults derived for %s at %dx%d, MAR slope %.4f\n\n", c.display.name.c_str(),
                sz.width, sz.height, c.acuity.slope);
    for (const TechniqueInfo& t : techniques()) {
      std::printf("%s — %s\n  after: %s\n", t.name.c_str(), t.summary.c_str(), t.source.c_str());
      if (t.needs.meshes) std::printf("  needs: a scene with meshes\n");
      const ParamValues values = resolve_parameters(t, c);
      for (const ParamDecl& p : t.params) {
        const std::string value = fmt(values.real(p.key), p.type == ParamType::Real ? 3 : 0) +
                                  (p.unit.empty() ? "" : " " + p.unit);
        std::printf("  %-22s = %-14s %s [%g..%g]\n", p.key.c_str(), value.c_str(), p.help.c_str(),
                    p.min, p.max);
      }
      std::printf("\n");
    }
  });
}

const CommandRegistrar kRender(20, register_render);
const CommandRegistrar kScenes(21, register_scenes);
const CommandRegistrar kTechniques(22, register_techniques);

}  // namespace foveate::app
