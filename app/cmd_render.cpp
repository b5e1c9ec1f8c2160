// foveate render: frames of any scene with any technique, to PNG files or a
// video.
#include <array>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli_util.hpp"
#include "commands.hpp"
#include "foveate/bench/session.hpp"
#include "foveate/bench/video.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"
#include "foveate/core/parse.hpp"
#include "foveate/techniques/supersampled_native.hpp"
#include "messages.hpp"
#include "output_dir.hpp"
#include "process_stats.hpp"
#include "progress.hpp"
#include "session_args.hpp"

namespace foveate::app {

namespace {

struct RenderArgs {
  SessionArgs session;
  int frames = 1;
  std::string out;
  bool overwrite = false;
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

// Pixels shaded over the run: both eyes together (or the one view), and each eye's.
struct Totals {
  double shaded = 0, native = 0;
  std::array<double, 2> eye_shaded{0, 0}, eye_native{0, 0};
};

// What one render run works with, checked before anything is created.
struct RenderSetup {
  bench::SessionOptions session;
  bench::ParamOverrides params;
  int reference = 1;
  int out_width = 0;
};

RenderSetup check(const RenderArgs& a) {
  if (a.frames < 1 || a.frames > 100000)
    throw Error("--frames: expected 1..100000, got " + std::to_string(a.frames));
  if (a.stats_every < 0) {
    throw Error("--stats: expected a frame interval >= 0, got " + std::to_string(a.stats_every));
  }
  RenderSetup s;
  s.session = to_session_options(a.session);
  if (!a.mouse.empty()) {
    s.session.mouse_px =
        parse_point_on_image(a.mouse, s.session.size.width, s.session.size.height, "--mouse");
    s.session.mouse_down = true;
  }
  with_flag("--technique", [&] { return technique_info(a.technique); });
  s.reference = with_flag("--reference", [&] { return parse_reference(a.reference); });
  // With --side-by-side native runs too (its parameters count).
  std::vector<std::string> run = {a.technique};
  if (a.side_by_side && a.technique != "native") run.push_back("native");
  s.params = session_params(a.session, run);
  if (a.out.empty() && a.video.empty() && !a.no_write)
    throw CLI::RequiredError("--out, --video or --no-write");
  if (a.no_write && !a.out.empty())
    throw Error("--no-write: writes no frames, so --out " + a.out +
                " would stay empty; give --out or --no-write, not both");
  if (s.reference > 1 && a.out.empty())
    throw Error("--reference: the reference frames are PNG files; give --out DIR too");
  if (s.session.stereo && a.side_by_side) {
    throw Error(
        "--side-by-side: not available with --stereo (a stereo frame is already the two eyes "
        "side by side)");
  }
  if (s.session.stereo && s.reference > 1) {
    throw Error(
        "--reference: the supersampled reference is monocular; not available with --stereo");
  }
  s.out_width = s.session.size.width * (s.session.stereo ? 2 : 1);
  return s;
}

std::string frame_file(const char* prefix, int k) {
  char name[64];
  std::snprintf(name, sizeof name, "%s-%04d.png", prefix, k);
  return name;
}

class RenderRun {
 public:
  RenderRun(const RenderArgs& a, const RenderSetup& s)
      : a_(a), s_(s), session_(s.session, session_callbacks()) {
    session_.set_overlay(a.overlay);
    technique_ = session_.make(a.technique, s.params);
    if (a.side_by_side) native_ = session_.make("native", s.params);
    if (s.reference > 1) supersampled_ = session_.make_reference(s.reference);
  }

  void run(bench::VideoWriter* video) {
    Progress progress("render", "frames", a_.frames, a_.frames > 1);
    for (int k = 0; k < a_.frames; ++k) {
      frame(k, video);
      progress.step(frame_file("frame", k));
    }
  }
  [[nodiscard]] const Totals& totals() const { return totals_; }
  [[nodiscard]] bench::Session& session() { return session_; }

 private:
  void frame(int k, bench::VideoWriter* video) {
    const GazeState gaze = session_.gaze().at(session_.frame_runner().frame_input(k).time_s);
    Image native_image;
    if (native_.view) {
      session_.watchdog().run("frame " + std::to_string(k) + " (native)",
                              [&] { return session_.render(native_, k, gaze); });
      native_image = session_.read_output();
    }
    const bench::SessionFrame st =
        session_.watchdog().run("frame " + std::to_string(k) + " (" + a_.technique + ")",
                                [&] { return session_.render(technique_, k, gaze); });
    add(st);
    if (a_.stats_every > 0 && (k % a_.stats_every == 0 || k + 1 == a_.frames))
      std::cerr << process_stats_line(k) << std::endl;
    Image image = session_.read_output();
    if (verbose())
      std::fprintf(stderr, "render: frame %d: %s shaded pixels\n", k,
                   format_number(st.total.shaded_pixels, 0).c_str());
    if (a_.no_write && !video) {
      // Read back as a written run would (the readback is part of the frame's cost).
      if (supersampled_) (void)reference_image(k);
      return;
    }
    if (!a_.out.empty() && !a_.no_write)
      write_png((std::filesystem::path(a_.out) / frame_file("frame", k)).string(), image);
    if (video && native_.view) {
      bench::mark_gaze(native_image, gaze.gaze_px);
      bench::mark_gaze(image, gaze.gaze_px);
      bench::label_tile(native_image, "native");
      bench::label_tile(image, a_.technique);
      video->write(bench::tile({&native_image, &image}));
    } else if (video) {
      video->write(image);
    }
    if (supersampled_ && !a_.no_write) {
      write_png((std::filesystem::path(a_.out) / frame_file("reference", k)).string(),
                reference_image(k));
    }
  }

  Image reference_image(int k) {
    return session_.watchdog().run(
        "frame " + std::to_string(k) + " of the ssaa:" + std::to_string(s_.reference) +
            " reference",
        [&] { return supersampled_->render(session_.frame_runner().frame_input(k)); },
        double(s_.reference) * s_.reference);
  }

  void add(const bench::SessionFrame& st) {
    totals_.shaded += st.total.shaded_pixels;
    totals_.native += st.total.native_pixels;
    if (!session_.options().stereo) return;
    for (size_t i = 0; i < 2; ++i) {
      totals_.eye_shaded[i] += st.eyes[i].shaded_pixels;
      totals_.eye_native[i] += st.eyes[i].native_pixels;
    }
  }

  const RenderArgs& a_;
  const RenderSetup& s_;
  bench::Session session_;
  bench::SessionTechnique technique_, native_;
  std::unique_ptr<bench::SupersampledScene> supersampled_;
  Totals totals_;
};

void print_json(const RenderArgs& a, const RenderSetup& s, RenderRun& run) {
  bench::Session& session = run.session();
  const Totals& t = run.totals();
  const bench::SessionOptions& o = s.session;
  nlohmann::json j = {
      {"frames", a.frames},
      {"scene", session.scene().info().name},
      {"technique", a.technique},
      {"size", {s.out_width, o.size.height}},
      {"out", a.out.empty()
                  ? nlohmann::json(nullptr)
                  : nlohmann::json(std::filesystem::path(a.out).lexically_normal().string())},
      {"video", a.video.empty() ? nlohmann::json(nullptr) : nlohmann::json(a.video)},
      {"shaded_pixels_per_frame", t.shaded / a.frames},
      {"native_pixels_per_frame", t.native / a.frames},
      {"pixel_ratio", t.shaded / t.native},
      {"gaze_report", session.gaze().report()}};
  if (o.stereo) {
    const double v = o.vergence_m.value_or(std::numeric_limits<double>::infinity());
    j["stereo"] = {{"display", session.stereo_display().left.name},
                   {"eye_size", {o.size.width, o.size.height}},
                   {"ipd_mm", session.stereo_display().ipd_mm},
                   {"vergence_m", std::isfinite(v) ? nlohmann::json(v) : nlohmann::json("inf")}};
    for (Eye e : kEyes) {
      const size_t i = static_cast<size_t>(e);
      j["stereo"]["eyes"][eye_name(e)] = {{"shaded_pixels_per_frame", t.eye_shaded[i] / a.frames},
                                          {"pixel_ratio", t.eye_shaded[i] / t.eye_native[i]}};
    }
  }
  std::cout << j.dump(2) << '\n';
}

void print_text(const RenderArgs& a, const RenderSetup& s, RenderRun& run) {
  bench::Session& session = run.session();
  const Totals& t = run.totals();
  const PixelSize size = s.session.size;
  const std::string where =
      a.out.empty() ? (a.video.empty() ? std::string(" (not written)") : " to " + a.video)
                    : " to " + (std::filesystem::path(a.out) / "").lexically_normal().string() +
                          (a.video.empty() ? "" : " and " + a.video);
  std::cout << "rendered " << a.frames << " frame(s) of " << session.scene().info().name << " with "
            << a.technique << " at " << s.out_width << 'x' << size.height
            << (s.session.stereo ? " (two " + std::to_string(size.width) + "x" +
                                       std::to_string(size.height) + " eyes side by side)"
                                 : std::string())
            << where << "\n";
  std::cout << "shaded pixels: " << format_fixed(t.shaded / a.frames, 0) << " per frame ("
            << format_fixed(100.0 * t.shaded / t.native, 1) << " % of native)\n"
            << (s.session.stereo ? "per eye: left " +
                                       format_fixed(100.0 * t.eye_shaded[0] / t.eye_native[0], 1) +
                                       " %, right " +
                                       format_fixed(100.0 * t.eye_shaded[1] / t.eye_native[1], 1) +
                                       " % of native\n"
                                 : std::string())
            << session.gaze().report() << "\n";
}

void run_render(const RenderArgs& a) {
  const RenderSetup s = check(a);
  std::optional<OutputDirLock> out_lock;
  if (!a.out.empty() && !a.no_write) out_lock.emplace(a.out, "--out", a.overwrite);
  // Opened before rendering, so that a bad path fails at once.
  std::unique_ptr<bench::VideoWriter> video;
  if (!a.video.empty()) {
    video = with_flag("--video", [&] {
      return std::make_unique<bench::VideoWriter>(a.video, s.out_width * (a.side_by_side ? 2 : 1),
                                                  s.session.size.height, s.session.fps);
    });
  }
  RenderRun run(a, s);
  run.run(video.get());
  if (video) {
    video->finish();
    std::cerr << bench::video_summary(*video, s.session.fps) << "\n";
  }
  if (a.json) {
    print_json(a, s, run);
  } else {
    print_text(a, s, run);
  }
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
  add_overwrite_flag(sub, a->overwrite);
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

const CommandRegistrar kRender(20, register_render);

}  // namespace foveate::app
