// foveate render / scenes / techniques: render frames of any scene with any
// technique to PNG, and list what there is.
#include <array>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli_util.hpp"
#include "commands.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"
#include "foveate/core/parse.hpp"
#include "foveate/techniques/reference.hpp"
#include "output_dir.hpp"
#include "process_stats.hpp"
#include "progress.hpp"
#include "session.hpp"
#include "video.hpp"

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
  std::string video;
  bool side_by_side = false;
  bool no_write = false;
  int stats_every = 0;
  bool json = false;
};

void run_render(const RenderArgs& a) {
  if (a.frames < 1 || a.frames > 100000)
    throw Error("--frames: expected 1..100000, got " + std::to_string(a.frames));
  if (a.stats_every < 0) {
    throw Error("--stats: expected a frame interval >= 0, got " + std::to_string(a.stats_every));
  }
  SessionOptions o = to_session_options(a.session);
  if (!a.mouse.empty()) {
    o.mouse_px = parse_point(a.mouse, o.size.width, o.size.height, "--mouse");
    o.mouse_down = true;
  }
  with_flag("--technique", [&] { return technique_info(a.technique); });
  const int reference = with_flag("--reference", [&] { return parse_reference(a.reference); });
  const ParamArgs params = parse_params(a.session.params);
  validate_params(params, {a.technique});
  if (a.out.empty() && a.video.empty() && !a.no_write)
    throw CLI::RequiredError("--out, --video or --no-write");
  if (reference > 1 && a.out.empty())
    throw Error("--reference: the reference frames are PNG files; give --out DIR too");
  if (o.stereo && a.side_by_side) {
    throw Error(
        "--side-by-side: not available with --stereo (a stereo frame is already the two eyes "
        "side by side)");
  }
  if (o.stereo && reference > 1) {
    throw Error(
        "--reference: the supersampled reference is monocular; not available with --stereo");
  }
  const int out_width = o.size.width * (o.stereo ? 2 : 1);
  std::optional<OutputDirLock> out_lock;
  if (!a.out.empty() && !a.no_write) out_lock.emplace(a.out, "--out");
  // Opened before rendering, so that a bad path fails at once.
  std::unique_ptr<VideoWriter> video;
  if (!a.video.empty()) {
    video = with_flag("--video", [&] {
      return std::make_unique<VideoWriter>(a.video, out_width * (a.side_by_side ? 2 : 1),
                                           o.size.height, o.fps);
    });
  }
  Session session(o, a.session.gaze);
  Renderer& renderer = session.renderer();
  StereoRenderer* stereo = session.stereo();
  renderer.set_overlay(a.overlay);
  if (stereo) stereo->set_overlay(a.overlay);
  std::unique_ptr<Technique> technique;
  std::array<std::unique_ptr<Technique>, 2> eyes;
  if (stereo) {
    eyes = session.make_stereo(a.technique, params);
  } else {
    technique = session.make(a.technique, params);
  }
  std::array<double, 2> eye_shaded{0, 0}, eye_native{0, 0};
  const auto native = a.side_by_side ? session.make("native", params) : nullptr;
  const std::unique_ptr<Reference> supersampled =
      reference > 1 ? session.make_reference(reference) : nullptr;
  double shaded = 0, native_pixels = 0;
  Progress progress("render", "frames", a.frames, a.frames > 1);
  for (int k = 0; k < a.frames; ++k) {
    const GazeState gaze = session.gaze().at(renderer.frame_input(k).time_s);
    Image native_image;
    if (native) {
      session.watchdog().run("frame " + std::to_string(k) + " (native)",
                             [&] { return renderer.render(*native, k, gaze); });
      native_image = renderer.read_output();
    }
    const std::string frame = "frame " + std::to_string(k) + " (" + a.technique + ")";
    FrameStats s;
    if (stereo) {
      const std::array<GazeState, 2> g = session.eye_gazes(gaze);
      const std::array<FrameStats, 2> st =
          session.watchdog().run(frame, [&] { return stereo->render(*eyes[0], *eyes[1], k, g); });
      for (size_t i = 0; i < 2; ++i) {
        s.shaded_pixels += st[i].shaded_pixels;
        s.native_pixels += st[i].native_pixels;
        eye_shaded[i] += st[i].shaded_pixels;
        eye_native[i] += st[i].native_pixels;
      }
    } else {
      s = session.watchdog().run(frame, [&] { return renderer.render(*technique, k, gaze); });
    }
    shaded += s.shaded_pixels;
    native_pixels += s.native_pixels;
    if (a.stats_every > 0 && (k % a.stats_every == 0 || k + 1 == a.frames)) {
      std::cerr << process_stats_line(k) << std::endl;
    }
    Image image = stereo ? stereo->read_output() : renderer.read_output();
    if (verbose())
      std::fprintf(stderr, "render: frame %d: %s shaded pixels\n", k,
                   format_number(s.shaded_pixels, 0).c_str());
    char name[64];
    std::snprintf(name, sizeof name, "frame-%04d.png", k);
    const auto reference_image = [&] {
      return session.watchdog().run(
          "frame " + std::to_string(k) + " of the ssaa:" + std::to_string(reference) + " reference",
          [&] { return supersampled->render(renderer.frame_input(k)); },
          double(reference) * reference);
    };
    if (a.no_write && !video) {
      // Read back as a written run would (the readback is part of the frame's cost).
      if (supersampled) (void)reference_image();
      progress.step(name);
      continue;
    }
    if (!a.out.empty() && !a.no_write)
      write_png((std::filesystem::path(a.out) / name).string(), image);
    if (video && native) {
      mark_gaze(native_image, gaze.gaze_px);
      mark_gaze(image, gaze.gaze_px);
      video->write(tile({&native_image, &image}));
    } else if (video) {
      video->write(image);
    }
    if (supersampled && !a.no_write) {
      char ref[64];
      std::snprintf(ref, sizeof ref, "reference-%04d.png", k);
      write_png((std::filesystem::path(a.out) / ref).string(), reference_image());
    }
    progress.step(name);
  }
  if (video) {
    video->finish();
    std::cerr << video_summary(*video, o.fps) << "\n";
  }
  if (a.json) {
    nlohmann::json j = {
        {"frames", a.frames},
        {"scene", session.scene().info().name},
        {"technique", a.technique},
        {"size", {out_width, o.size.height}},
        {"out", a.out.empty()
                    ? nlohmann::json(nullptr)
                    : nlohmann::json(std::filesystem::path(a.out).lexically_normal().string())},
        {"video", a.video.empty() ? nlohmann::json(nullptr) : nlohmann::json(a.video)},
        {"shaded_pixels_per_frame", shaded / a.frames},
        {"native_pixels_per_frame", native_pixels / a.frames},
        {"pixel_ratio", shaded / native_pixels},
        {"gaze_report", session.gaze().report()}};
    if (stereo) {
      j["stereo"] = {{"display", session.stereo_display().left.name},
                     {"eye_size", {o.size.width, o.size.height}},
                     {"ipd_mm", session.stereo_display().ipd_mm},
                     {"vergence_m", std::isfinite(o.vergence_m) ? nlohmann::json(o.vergence_m)
                                                                : nlohmann::json("inf")}};
      for (Eye e : kEyes) {
        const size_t i = static_cast<size_t>(e);
        j["stereo"]["eyes"][eye_name(e)] = {{"shaded_pixels_per_frame", eye_shaded[i] / a.frames},
                                            {"pixel_ratio", eye_shaded[i] / eye_native[i]}};
      }
    }
    std::cout << j.dump(2) << '\n';
    return;
  }
  std::cout << "rendered " << a.frames << " frame(s) of " << session.scene().info().name << " with "
            << a.technique << " at " << out_width << 'x' << o.size.height
            << (stereo ? " (two " + std::to_string(o.size.width) + "x" +
                             std::to_string(o.size.height) + " eyes side by side)"
                       : std::string())
            << (a.out.empty()
                    ? (a.video.empty() ? std::string(" (not written)") : " to " + a.video)
                    : " to " + (std::filesystem::path(a.out) / "").lexically_normal().string() +
                          (a.video.empty() ? "" : " and " + a.video))
            << "\n";
  std::cout << "shaded pixels: " << fmt(shaded / a.frames, 0) << " per frame ("
            << fmt(100.0 * shaded / native_pixels, 1) << " % of native)\n"
            << (stereo ? "per eye: left " + fmt(100.0 * eye_shaded[0] / eye_native[0], 1) +
                             " %, right " + fmt(100.0 * eye_shaded[1] / eye_native[1], 1) +
                             " % of native\n"
                       : std::string())
            << session.gaze().report() << "\n";
}

}  // namespace

void register_render(CLI::App& app) {
  auto a = std::make_shared<RenderArgs>();
  CLI::App* sub = app.add_subcommand(
      "render", "Render frames of a scene with a technique to PNG files or a video");
  add_session_options(sub, a->session, true, kFixedDate, true);
  sub->add_option("--frames", a->frames, "Number of frames")->capture_default_str();
  sub->add_option("--mouse", a->mouse,
                  "Shadertoy iMouse position X,Y (pixels or normalized), button down");
  sub->add_option("--out", a->out,
                  "Output directory (frame-0000.png, ...); required unless --video or --no-write "
                  "is given");
  sub->add_flag("--no-write", a->no_write,
                "Render (and read back) without writing PNG files: soak and leak tests");
  sub->add_option("--stats", a->stats_every,
                  "Every N frames (and after the last), print to stderr the process's resident "
                  "memory, heap in use and live GL objects per type (0 = off)")
      ->capture_default_str();
  sub->add_option("--technique", a->technique, "Technique (see 'foveate techniques')")
      ->capture_default_str();
  sub->add_flag("--overlay", a->overlay,
                "Draw the technique's layer/region borders and the gaze point (off by default)");
  sub->add_flag("--json", a->json, "Print the summary as JSON");
  CLI::Option* video =
      sub->add_option("--video", a->video,
                      "Also (or only) write the frames as a video, e.g. out.mp4: H.264 (libx264) "
                      "yuv420p at --fps, written atomically");
  sub->add_flag("--side-by-side", a->side_by_side,
                "In the video, native on the left and the technique on the right, the gaze "
                "marked on both (twice the width)")
      ->needs(video);
  sub->add_option("--reference", a->reference,
                  "Also write reference-NNNN.png: ssaa[:N] = native with NxN supersampling "
                  "(default N = 4), box-filtered in linear light (native = none)")
      ->capture_default_str();
  sub->callback([a] { run_render(*a); });
}

void register_scenes(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("scenes", "List the built-in scenes");
  auto json = std::make_shared<bool>(false);
  sub->add_flag("--json", *json, "Print the list as JSON");
  sub->callback([json] {
    if (*json) {
      nlohmann::json j = nlohmann::json::array();
      for (const SceneListing& s : builtin_scenes())
        j.push_back({{"name", s.name}, {"description", s.description}});
      std::cout << j.dump(2) << '\n';
      return;
    }
    for (const SceneListing& s : builtin_scenes())
      std::printf("%-10s %s\n", s.name.c_str(), s.description.c_str());
    std::printf(
        "\nAlso: a Shadertoy shader file (.glsl, .frag) or a mesh file (OBJ, glTF/GLB, PLY, FBX, "
        "3DS, ...).\n");
  });
}

void register_techniques(CLI::App& app) {
  auto display = std::make_shared<std::string>("desktop-1080p");
  auto size = std::make_shared<std::string>(kDefaultSize);
  auto json = std::make_shared<bool>(false);
  auto quality = std::make_shared<std::string>();
  auto slope = std::make_shared<std::optional<double>>();
  auto margin = std::make_shared<std::optional<double>>();
  CLI::App* sub =
      app.add_subcommand("techniques", "List the techniques with their parameters and defaults");
  sub->add_option("--display", *display, "Display for the derived defaults")->capture_default_str();
  sub->add_option("--size", *size, "Render size for the derived defaults (render's default)")
      ->capture_default_str();
  sub->add_flag("--json", *json, "Print the techniques, parameters and defaults as JSON");
  sub->add_option("--quality", *quality, "Acuity preset A or B (default A)");
  sub->add_option("--slope", *slope, "Custom MAR slope m");
  sub->add_option("--margin", *margin,
                  "Derive the defaults for every technique planned with this margin (as "
                  "render's and bench's --margin, 1 to 4; default: each technique's own)");
  sub->callback([=] {
    const Size sz = parse_size(*size, "--size");
    TechniqueConfig c;
    c.display = with_flag("--display", [&] {
                  return Display::load(*display);
                }).resized(sz.width, sz.height);
    const AcuityModel judged = acuity_from_options(*quality, *slope);
    note_savings(c.display, judged);
    c.acuity = judged;
    const std::optional<double> forced =
        *margin ? std::optional<double>(checked_margin(**margin)) : std::nullopt;
    c.margin = forced;
    if (*json) {
      nlohmann::json j = {{"display", c.display},
                          {"size", {sz.width, sz.height}},
                          {"acuity", {{"slope", judged.slope}, {"w0_deg", judged.w0_deg}}},
                          {"margin", forced ? nlohmann::json(*forced) : nlohmann::json()}};
      nlohmann::json list = nlohmann::json::array();
      for (const TechniqueInfo& t : techniques()) {
        const ParamValues values = resolve_parameters(t, c);
        nlohmann::json params = nlohmann::json::array();
        for (const ParamDecl& p : t.params) {
          params.push_back({{"key", p.key},
                            {"value", values.real(p.key)},
                            {"unit", p.unit},
                            {"type", p.type == ParamType::Real      ? "real"
                                     : p.type == ParamType::Integer ? "integer"
                                                                    : "boolean"},
                            {"min", p.min},
                            {"max", p.max},
                            {"help", p.help}});
        }
        list.push_back({{"name", t.name},
                        {"summary", t.summary},
                        {"after", t.source},
                        {"needs_meshes", t.needs.meshes},
                        {"parameters", params}});
      }
      j["techniques"] = list;
      std::cout << j.dump(2) << '\n';
      return;
    }
    std::printf("defaults derived for %s at %dx%d, MAR slope %s%s\n\n", c.display.name.c_str(),
                sz.width, sz.height, format_number(judged.slope, 4).c_str(),
                forced ? (", margin " + format_number(*forced, 3)).c_str()
                       : " (each technique planned with its own margin)");
    for (const TechniqueInfo& t : techniques()) {
      std::printf("%s — %s\n  after: %s\n", t.name.c_str(), t.summary.c_str(), t.source.c_str());
      if (t.needs.meshes) std::printf("  needs: a scene with meshes\n");
      const ParamValues values = resolve_parameters(t, c);
      for (const ParamDecl& p : t.params) {
        const std::string value = fmt(values.real(p.key), p.type == ParamType::Real ? 3 : 0) +
                                  (p.unit.empty() ? "" : " " + p.unit);
        std::printf("  %-22s = %-14s %s [%s..%s]\n", p.key.c_str(), value.c_str(), p.help.c_str(),
                    format_number(p.min).c_str(), format_number(p.max).c_str());
      }
      std::printf("\n");
    }
  });
}

const CommandRegistrar kRender(20, register_render);
const CommandRegistrar kScenes(21, register_scenes);
const CommandRegistrar kTechniques(22, register_techniques);

}  // namespace foveate::app
