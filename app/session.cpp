#include "session.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "foveate/core/parse.hpp"
#include "foveate/gaze/gaze.hpp"

namespace foveate::app {

ParamArgs parse_params(const std::vector<std::string>& items) {
  ParamArgs out;
  for (const std::string& item : items) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0) {
      throw Error("--param: expected KEY=VALUE or TECHNIQUE.KEY=VALUE, got '" + item + "'");
    }
    std::string key = item.substr(0, eq), tech;
    const std::string value = item.substr(eq + 1);
    char* end = nullptr;
    const double v = std::strtod(value.c_str(), &end);
    if (value.empty() || end != value.c_str() + value.size()) {
      throw Error("--param " + key + ": '" + value + "' is not a number");
    }
    const auto dot = key.find('.');
    if (dot != std::string::npos) {
      tech = key.substr(0, dot);
      key = key.substr(dot + 1);
      with_flag("--param " + item, [&] { return technique_info(tech); });
    }
    out.per_technique[tech][key] = v;
  }
  return out;
}

namespace {

bool declares(const TechniqueInfo& info, const std::string& key) {
  for (const ParamDecl& p : info.params) {
    if (p.key == key) return true;
  }
  return false;
}

}  // namespace

void validate_params(const ParamArgs& p, const std::vector<std::string>& techs) {
  auto all = p.per_technique.find("");
  if (all == p.per_technique.end()) return;
  for (const auto& [key, v] : all->second) {
    bool known = false;
    std::string names;
    for (const std::string& t : techs) {
      names += (names.empty() ? "" : ", ") + t;
      known = known || declares(technique_info(t), key);
    }
    if (!known) {
      throw Error("--param " + key + ": no such parameter in " + names +
                  " (see 'foveate techniques')");
    }
  }
}

std::map<std::string, double> params_for(const ParamArgs& p, const std::string& technique) {
  std::map<std::string, double> out;
  const TechniqueInfo& info = technique_info(technique);
  auto all = p.per_technique.find("");
  if (all != p.per_technique.end()) {
    for (const auto& [k, v] : all->second) {
      if (declares(info, k)) out[k] = v;
    }
  }
  auto mine = p.per_technique.find(technique);
  if (mine != p.per_technique.end()) {
    for (const auto& [k, v] : mine->second) out[k] = v;
  }
  return out;
}

void add_session_options(CLI::App* sub, SessionArgs& a, bool scene_required,
                         const char* default_date, bool stereo) {
  auto* scene = sub->add_option(
      "--scene", a.scene,
      "Built-in scene name (see 'foveate scenes'), Shadertoy .glsl file or mesh file");
  if (scene_required) {
    scene->required();
  } else {
    scene->capture_default_str();
  }
  sub->add_option("--size", a.size,
                  "Output size WxH in pixels (the display's field of view is kept; below about "
                  "1280x720 on a desktop display foveation has little to save, and a note says so)")
      ->capture_default_str();
  sub->add_option("--display", a.display,
                  "Display preset (" + Display::preset_names() +
                      ") or JSON file (its field of view is kept at --size)")
      ->capture_default_str();
  sub->add_option("--quality", a.quality, "Acuity preset A or B (default A)");
  sub->add_option("--slope", a.slope, "Custom MAR slope m (instead of --quality)");
  sub->add_option("--margin", a.margin,
                  "Plan every technique for an acuity this many times finer (slope and foveal "
                  "MAR divided by it, 1 to 4) than the one the metrics judge by: 1 = each "
                  "paper's plan; default: each technique's own margin, the least at which its "
                  "error stays within native's + 1 code (see 'foveate techniques'); the same as "
                  "--param margin=K");
  sub->add_option("--param", a.params,
                  "Technique parameter KEY=VALUE or TECHNIQUE.KEY=VALUE (repeatable; see "
                  "'foveate techniques')");
  sub->add_option("--gaze", a.gaze,
                  std::string("Gaze source; default the screen centre. ") + gaze::gaze_spec_help());
  sub->add_option("--camera-path", a.camera_path,
                  "Camera keyframes JSON (built-in and mesh scenes)");
  sub->add_option("--channel", a.channels,
                  "Image for iChannel0..3 of a Shadertoy shader (repeat, in order)");
  sub->add_option("--up", a.up,
                  "Up axis of a mesh file: y or z (default: the file's metadata, else y)");
  sub->add_option("--model-memory-limit", a.model_memory_limit,
                  "Refuse a mesh file whose declared size needs more memory than this to import "
                  "(e.g. 512M, 8G; default half the machine's memory)");
  sub->add_option("--fps", a.fps, "Frame rate of the fixed clock (frame k is at time + k / fps)")
      ->capture_default_str();
  sub->add_option("--time", a.time, "Scene time of the first frame in seconds")
      ->capture_default_str();
  sub->add_flag("--strict", a.strict,
                "A gaze trace (--gaze trace:FILE) row that cannot be read is an error (default: "
                "skipped with a warning naming its line)");
  sub->add_option("--frame-timeout", a.frame_timeout,
                  "Stop with an error when a frame takes longer than this many seconds "
                  "(0 = no limit; a GL draw cannot be interrupted, so the process exits)")
      ->capture_default_str();
  sub->add_option("--date", a.date,
                  std::string("Shadertoy iDate: now (the real clock), YYYY-MM-DD or "
                              "YYYY-MM-DDTHH:MM[:SS] (a fixed start that the scene time advances); "
                              "default ") +
                      (std::string_view(default_date) == "now"
                           ? "now"
                           : std::string(default_date) + " (fixed, for reproducible frames)"));
  if (!stereo) return;
  sub->add_flag("--stereo", a.stereo,
                "Render both eyes of a stereo head-mounted display (--display " +
                    Display::preset_names(true) +
                    " or a JSON file with fov_deg and ipd_mm), side by side, the left eye on the "
                    "left; --size is one eye's, and --gaze the combined gaze (the cyclopean "
                    "eye's, its centre straight ahead)");
  sub->add_option("--vergence", a.vergence,
                  "With --stereo: the distance in metres at which both eyes' gaze converges "
                  "(default inf: parallel, each eye looking the same way)");
}

SessionOptions to_session_options(const SessionArgs& a, const char* default_date) {
  SessionOptions o;
  o.date = with_flag("--date", [&] {
    return parse_shadertoy_date(a.date.empty() ? std::string(default_date) : a.date);
  });
  o.scene = a.scene;
  o.channels = a.channels;
  o.camera_path = a.camera_path;
  if (!a.up.empty() && a.up != "y" && a.up != "z") {
    throw Error("--up: expected y or z, got '" + a.up + "'");
  }
  o.up = a.up;
  if (!a.model_memory_limit.empty()) {
    o.model_memory_limit = parse_byte_size(a.model_memory_limit, "--model-memory-limit");
  }
  o.size = parse_size(a.size, "--size");
  o.display = a.display;
  o.acuity = acuity_from_options(a.quality, a.slope);
  if (a.margin) o.margin = checked_margin(*a.margin);
  if (!(a.fps > 0.0 && a.fps <= 10000.0)) {
    char got[32];
    std::snprintf(got, sizeof got, "%g", a.fps);
    throw Error(
        std::string("--fps: expected a rate above 0 and at most 10000 frames per second, got ") +
        got);
  }
  if (!std::isfinite(a.time)) throw Error("--time: must be finite");
  o.fps = a.fps;
  o.start_time = a.time;
  o.stereo = a.stereo;
  if (!a.vergence.empty()) {
    if (!a.stereo)
      throw Error("--vergence: only with --stereo (it sets where the two eyes converge)");
    double v = 0.0;
    if (a.vergence == "inf") {
      v = std::numeric_limits<double>::infinity();
    } else if (!parse_number(a.vergence, v) || !(v > 0.0) || !std::isfinite(v)) {
      throw Error("--vergence: expected a distance in metres > 0 (or inf), got '" + a.vergence +
                  "'");
    }
    o.vergence_m = v;
  }
  o.strict_traces = a.strict;
  o.frame_timeout_s = check_frame_timeout(a.frame_timeout);
  return o;
}

Session::Session(const SessionOptions& o, const std::string& gaze_spec,
                 std::function<std::optional<Vec2d>()> mouse)
    : options_(o), gaze_spec_(gaze_spec), mouse_(std::move(mouse)) {
  display_ = with_flag("--display", [&] {
               return Display::load(o.display);
             }).resized(o.size.width, o.size.height);
  if (o.stereo) {
    stereo_display_ = with_flag("--stereo", [&] { return StereoDisplay::from(display_); });
  }
  if (o.window) {
    auto w = gpu::create_window(std::max(o.size.width, o.window_size.width),
                                std::max(o.size.height, o.window_size.height), "foveate");
    window_ = w.get();
    context_ = std::move(w);
  } else {
    context_ = gpu::create_headless_context();
  }
  SceneOptions so;
  so.channels = o.channels;
  so.camera_path = o.camera_path;
  so.up = o.up;
  so.model_memory_limit = o.model_memory_limit;
  so.date = o.date;
  scene_ = load_scene(o.scene, so);
  if (o.stereo) right_scene_ = load_scene(o.scene, so);
  RendererOptions ro;
  ro.width = o.size.width;
  ro.height = o.size.height;
  ro.fps = o.fps;
  ro.start_time_s = o.start_time;
  ro.mouse_px = o.mouse_px;
  ro.mouse_down = o.mouse_down;
  if (o.stereo) {
    stereo_ = with_flag("--size", [&] {
      return std::make_unique<StereoRenderer>(*scene_, *right_scene_, stereo_display_, ro);
    });
  } else {
    renderer_ = with_flag("--size", [&] { return std::make_unique<Renderer>(*scene_, ro); });
  }
  watchdog_ = std::make_unique<FrameWatchdog>(o.frame_timeout_s, scene_->info().name);
  make_tracker();
  if (verbose()) {
    const Vec2d c{0.5 * o.size.width, 0.5 * o.size.height};
    std::fprintf(stderr,
                 "foveate: renderer %s; scene %s; display %s at %dx%d, %s px/deg at the centre; "
                 "gaze %s\n",
                 context_->renderer().c_str(), scene_->info().name.c_str(), display_.name.c_str(),
                 o.size.width, o.size.height, fmt(display_.pixels_per_degree(c, c), 1).c_str(),
                 gaze_->describe().c_str());
  }
  note_savings(display_, o.acuity);
}

void Session::make_tracker() {
  gaze::GazeContext ctx;
  // Stereo: the combined gaze is a position in the cyclopean view.
  ctx.display = options_.stereo ? stereo_display_.cyclopean() : display_;
  ctx.strict_traces = options_.strict_traces;
  ctx.warn = [](const std::string& w) {
    std::fprintf(stderr, "foveate: warning: %s\n", w.c_str());
  };
  ctx.mouse = mouse_;
  Scene* scene = scene_.get();
  const double w = options_.size.width, h = options_.size.height;
  ctx.objects = [scene, w, h](double) {
    std::vector<Vec2d> out;
    for (const Vec2d& p : scene->object_positions()) out.push_back({p.x / w, p.y / h});
    return out;
  };
  gaze_ = with_flag("--gaze", [&] { return std::make_unique<gaze::GazeTracker>(gaze_spec_, ctx); });
}

void Session::set_display(const std::string& display) {
  if (stereo_) throw Error("--display: the display of a stereo session is fixed");
  Display d = with_flag("--display", [&] {
                return Display::load(display);
              }).resized(options_.size.width, options_.size.height);
  display_ = d;
  options_.display = display;
  make_tracker();
}

Session::~Session() = default;

std::array<std::unique_ptr<Technique>, 2> Session::make_stereo(
    const std::string& technique, const ParamArgs& params,
    std::optional<AcuityModel> acuity) const {
  if (!stereo_) throw Error("internal: make_stereo on a session without --stereo");
  const TechniqueInfo& info = technique_info(technique);
  check_scene(info, scene_->info());
  std::array<std::unique_ptr<Technique>, 2> out;
  for (Eye e : kEyes) {
    TechniqueConfig c;
    c.display = stereo_display_.eye(e);
    c.acuity = acuity.value_or(options_.acuity);
    c.margin = options_.margin;
    c.params = params_for(params, technique);
    out[static_cast<size_t>(e)] =
        with_flag("--param", [&] { return make_technique(technique, c); });
  }
  return out;
}

std::unique_ptr<Technique> Session::make(const std::string& technique, const ParamArgs& params,
                                         std::optional<AcuityModel> acuity) const {
  const TechniqueInfo& info = technique_info(technique);
  check_scene(info, scene_->info());
  TechniqueConfig c;
  c.display = display_;
  c.acuity = acuity.value_or(options_.acuity);
  c.margin = options_.margin;
  c.params = params_for(params, technique);
  return with_flag("--param", [&] { return make_technique(technique, c); });
}

Image Reference::render(const FrameInput& input) {
  supersampled->render(*scene, input);
  return supersampled->read();
}

std::unique_ptr<Reference> Session::make_reference(int factor) const {
  if (stereo_) {
    throw Error(
        "--reference: the supersampled reference is monocular; not available with --stereo");
  }
  auto r = std::make_unique<Reference>();
  SceneOptions so;
  so.channels = options_.channels;
  so.camera_path = options_.camera_path;
  so.up = options_.up;
  so.model_memory_limit = options_.model_memory_limit;
  so.date = options_.date;
  r->scene = load_scene(options_.scene, so);
  r->supersampled = with_flag(
      "--reference", [&] { return std::make_unique<SupersampledReference>(display_, factor); });
  return r;
}

void Session::present() {
  if (!window_) return;
  const int w = window_->framebuffer_width(), h = window_->framebuffer_height();
  // The output holds sRGB-encoded bytes: copied as they are (no decode on
  // read, no encode on write), whatever the window's framebuffer encoding.
  glDisable(GL_FRAMEBUFFER_SRGB);
  const gpu::RenderTarget& out = stereo_ ? stereo_->output() : renderer_->output();
  glBlitNamedFramebuffer(out.framebuffer(), 0, 0, 0, out.width(), out.height(), 0, 0, w, h,
                         GL_COLOR_BUFFER_BIT, GL_LINEAR);
  window_->swap_buffers();
}

}  // namespace foveate::app
