#include "session.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

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

void add_session_options(CLI::App* sub, SessionArgs& a, bool scene_required) {
  auto* scene = sub->add_option(
      "--scene", a.scene,
      "Built-in scene name (see 'foveate scenes'), Shadertoy .glsl file or mesh file");
  if (scene_required) {
    scene->required();
  } else {
    scene->capture_default_str();
  }
  sub->add_option("--size", a.size, "Output size WxH in pixels")->capture_default_str();
  sub->add_option("--display", a.display,
                  "Display preset or JSON file (its field of view is kept at --size)")
      ->capture_default_str();
  sub->add_option("--quality", a.quality, "Acuity preset A or B (default A)");
  sub->add_option("--slope", a.slope, "Custom MAR slope m (instead of --quality)");
  sub->add_option("--param", a.params,
                  "Technique parameter KEY=VALUE or TECHNIQUE.KEY=VALUE (repeatable; see "
                  "'foveate techniques')");
  sub->add_option("--gaze", a.gaze,
                  std::string("Gaze source; default the screen centre. ") + gaze::gaze_spec_help());
  sub->add_option("--camera-path", a.camera_path,
                  "Camera keyframes JSON (built-in and mesh scenes)");
  sub->add_option("--channel", a.channels,
                  "Image for iChannel0..3 of a Shadertoy shader (repeat, in order)");
  sub->add_option("--fps", a.fps, "Frame rate of the fixed clock (frame k is at time + k / fps)")
      ->capture_default_str();
  sub->add_option("--time", a.time, "Scene time of the first frame in seconds")
      ->capture_default_str();
}

SessionOptions to_session_options(const SessionArgs& a) {
  SessionOptions o;
  o.scene = a.scene;
  o.channels = a.channels;
  o.camera_path = a.camera_path;
  o.size = parse_size(a.size, "--size");
  o.display = a.display;
  o.acuity = acuity_from_options(a.quality, a.slope);
  if (!(a.fps > 0.0 && a.fps <= 10000.0))
    throw Error("--fps: expected a rate in (0, 10000] frames per second");
  if (!std::isfinite(a.time)) throw Error("--time: must be finite");
  o.fps = a.fps;
  o.start_time = a.time;
  return o;
}

Session::Session(const SessionOptions& o, const std::string& gaze_spec,
                 std::function<std::optional<Vec2d>()> mouse)
    : options_(o), gaze_spec_(gaze_spec), mouse_(std::move(mouse)) {
  display_ = with_flag("--display", [&] {
               return Display::load(o.display);
             }).resized(o.size.width, o.size.height);
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
  scene_ = load_scene(o.scene, so);
  RendererOptions ro;
  ro.width = o.size.width;
  ro.height = o.size.height;
  ro.fps = o.fps;
  ro.start_time_s = o.start_time;
  ro.mouse_px = o.mouse_px;
  ro.mouse_down = o.mouse_down;
  renderer_ = with_flag("--size", [&] { return std::make_unique<Renderer>(*scene_, ro); });
  make_tracker();
}

void Session::make_tracker() {
  gaze::GazeContext ctx;
  ctx.display = display_;
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
  Display d = with_flag("--display", [&] {
                return Display::load(display);
              }).resized(options_.size.width, options_.size.height);
  display_ = d;
  options_.display = display;
  make_tracker();
}

Session::~Session() = default;

std::unique_ptr<Technique> Session::make(const std::string& technique, const ParamArgs& params,
                                         std::optional<AcuityModel> acuity) const {
  const TechniqueInfo& info = technique_info(technique);
  check_scene(info, scene_->info());
  TechniqueConfig c;
  c.display = display_;
  c.acuity = acuity.value_or(options_.acuity);
  c.params = params_for(params, technique);
  return with_flag("--param", [&] { return make_technique(technique, c); });
}

Image Reference::render(const FrameInput& input) {
  supersampled->render(*scene, input);
  return supersampled->read();
}

std::unique_ptr<Reference> Session::make_reference(int factor) const {
  auto r = std::make_unique<Reference>();
  SceneOptions so;
  so.channels = options_.channels;
  so.camera_path = options_.camera_path;
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
  glBlitNamedFramebuffer(renderer_->output().framebuffer(), 0, 0, 0, options_.size.width,
                         options_.size.height, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  window_->swap_buffers();
}

}  // namespace foveate::app
