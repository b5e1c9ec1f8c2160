#include "foveate/bench/session.hpp"

#include <algorithm>
#include <limits>
#include <memory>
#include <set>
#include <string>

#include "foveate/bench/savings.hpp"
#include "foveate/core/parse.hpp"
#include "foveate/gaze/gaze.hpp"

namespace foveate::bench {

Session::Session(const SessionOptions& o, SessionCallbacks callbacks)
    : options_(o), callbacks_(std::move(callbacks)) {
  validate(o);
  display_ = for_field("display", [&] {
               return Display::load(o.display);
             }).resized(o.size.width, o.size.height);
  apply_photometry(display_);
  if (o.stereo) {
    stereo_display_ = for_field("stereo", [&] { return StereoDisplay::from(display_); });
  }
  make_context();
  // The scene's load warnings are the session's notices (so --quiet and
  // Python's warnings see them).
  scene_options_ = o.scene_options;
  if (callbacks_.notice && !scene_options_.warning) {
    scene_options_.warning =
        [notice = callbacks_.notice,
         said = std::make_shared<std::set<std::string>>()](const std::string& text) {
          if (said->insert(text).second) notice({NoticeKind::Warning, {text, {}}});
        };
  }
  scene_ = load_scene(o.scene, scene_options_);
  if (o.stereo) right_scene_ = load_scene(o.scene, scene_options_);
  make_frame_runners();
  watchdog_ = std::make_unique<FrameWatchdog>(o.frame_timeout_s, scene_->info().name,
                                              callbacks_.frame_timeout);
  make_tracker();
  announce();
}

Session::~Session() = default;

void Session::apply_photometry(Display& display) const {
  if (!options_.photometry.any()) return;
  options_.photometry.apply_to(display.photometry);
  std::string field;
  try {
    display.photometry.validate([&](const char* key) {
      field = std::string("photometry.") + key;
      return "{" + field + "}";
    });
  } catch (const OptionError&) {
    throw;
  } catch (const Error& e) {
    throw OptionError(field, FieldText{e.what(), {field}});
  }
}

void Session::make_context() {
  if (!options_.window) {
    gpu::ContextOptions co;
    co.debug = options_.gl_debug;
    context_ = gpu::create_headless_context(co);
    return;
  }
  // The window's own size when given (the front end shows the output in it,
  // scaled if need be), else the output's.
  const bool sized = options_.window_size.width > 0 && options_.window_size.height > 0;
  auto w =
      gpu::create_window(sized ? options_.window_size.width : options_.size.width,
                         sized ? options_.window_size.height : options_.size.height, "foveate");
  window_ = w.get();
  context_ = std::move(w);
}

void Session::make_frame_runners() {
  FrameRunnerOptions ro;
  ro.width = options_.size.width;
  ro.height = options_.size.height;
  ro.fps = options_.fps;
  ro.start_time_s = options_.start_time_s;
  ro.mouse_px = options_.mouse_px;
  ro.mouse_down = options_.mouse_down;
  if (options_.stereo) {
    stereo_ = for_field("size", [&] {
      return std::make_unique<StereoFrameRunner>(*scene_, *right_scene_, stereo_display_, ro);
    });
  } else {
    frame_runner_ = for_field("size", [&] { return std::make_unique<FrameRunner>(*scene_, ro); });
  }
}

void Session::make_tracker() {
  gaze::GazeContext ctx;
  // Stereo: the combined gaze is a position in the cyclopean view.
  ctx.display = options_.stereo ? stereo_display_.cyclopean() : display_;
  ctx.strict_traces = options_.strict_traces;
  ctx.warn = [notice = callbacks_.notice](const std::string& w) {
    if (notice) notice({NoticeKind::Warning, {w, {}}});
  };
  ctx.mouse = callbacks_.mouse;
  Scene* scene = scene_.get();
  const double w = options_.size.width, h = options_.size.height;
  ctx.objects = [scene, w, h](double) {
    std::vector<Vec2d> out;
    for (const Vec2d& p : scene->object_positions()) out.push_back({p.x / w, p.y / h});
    return out;
  };
  gaze_ =
      for_field("gaze", [&] { return std::make_unique<gaze::GazeTracker>(options_.gaze, ctx); });
}

void Session::announce() const {
  if (!callbacks_.notice) return;
  const Vec2d c{0.5 * options_.size.width, 0.5 * options_.size.height};
  callbacks_.notice(
      {NoticeKind::Detail,
       {"renderer " + context_->renderer() + "; scene " + scene_->info().name + "; display " +
            display_.name + " at " + std::to_string(options_.size.width) + "x" +
            std::to_string(options_.size.height) + ", " +
            format_fixed(display_.pixels_per_degree(c, c), 1) + " px/deg at the centre; gaze " +
            gaze_->describe(),
        {}}});
}

void Session::note_savings() {
  if (!largest_margin_ || (savings_checked_ && *largest_margin_ <= *savings_checked_)) return;
  savings_checked_ = largest_margin_;
  if (!callbacks_.notice) return;
  const SavingsCheck savings = check_savings(display_, options_.acuity, *largest_margin_);
  if (savings.nothing_to_save) callbacks_.notice({NoticeKind::Note, savings.note});
}

std::vector<std::string> Session::take_gl_errors() {
  std::vector<std::string> out;
  for (const gpu::DebugMessage& m : context_->take_debug_errors()) out.push_back(m.text);
  return out;
}

std::array<GazeState, 2> Session::eye_gazes(const GazeState& combined) const {
  return eye_gaze_states(stereo_display_, combined,
                         options_.vergence_m.value_or(std::numeric_limits<double>::infinity()));
}

void Session::set_display(const std::string& display) {
  if (stereo_) throw OptionError("display", "the display of a stereo session is fixed");
  display_ = for_field("display", [&] {
               return Display::load(display);
             }).resized(options_.size.width, options_.size.height);
  apply_photometry(display_);
  options_.display = display;
  make_tracker();
}

TechniqueConfig Session::technique_config(Eye eye, std::optional<AcuityModel> acuity) const {
  TechniqueConfig c;
  c.display = stereo_ ? stereo_display_.eye(eye) : display_;
  c.acuity = acuity.value_or(options_.acuity);
  c.margin = options_.margin;
  return c;
}

SessionTechnique Session::make(const std::string& technique, const ParamOverrides& params,
                               std::optional<AcuityModel> acuity) const {
  check_scene(technique_info(technique), scene_->info());
  const auto make_for = [&](Eye eye) {
    TechniqueConfig c = technique_config(eye, acuity);
    c.params = params.for_technique(technique);
    return for_field("params", [&] { return make_technique(technique, c); });
  };
  SessionTechnique t;
  t.view = make_for(Eye::Left);
  if (stereo_) t.right = make_for(Eye::Right);
  if (t.view->values().has(kPlanMarginKey)) {
    const double m = t.view->values().real(kPlanMarginKey);
    largest_margin_ = std::max(largest_margin_.value_or(m), m);
  }
  return t;
}

SessionFrame Session::render(SessionTechnique& t, int frame, const GazeState& gaze) {
  return render(t, frame_runner().frame_input(frame), gaze);
}

SessionFrame Session::render(SessionTechnique& t, const FrameInput& input, const GazeState& gaze) {
  note_savings();
  SessionFrame out;
  if (!stereo_) {
    out.total = frame_runner_->render(*t.view, input, gaze);
    out.eyes[0] = out.total;
    return out;
  }
  out.eyes = stereo_->render(*t.view, *t.right, input, eye_gazes(gaze));
  out.total = out.eyes[0];
  out.total.shaded_pixels += out.eyes[1].shaded_pixels;
  out.total.native_pixels += out.eyes[1].native_pixels;
  for (size_t p = 0; p < out.total.parts.size() && p < out.eyes[1].parts.size(); ++p)
    out.total.parts[p].pixels += out.eyes[1].parts[p].pixels;
  return out;
}

Image Session::read_output() const {
  return stereo_ ? stereo_->read_output() : frame_runner_->read_output();
}

Image Session::read_eye(Eye eye) const {
  return stereo_ ? stereo_->read_eye(eye) : frame_runner_->read_output();
}

std::vector<OverlayShape> Session::overlay(const SessionTechnique& t, const GazeState& gaze) const {
  if (!stereo_) return t.view->overlay(gaze);
  const std::array<GazeState, 2> eyes = eye_gazes(gaze);
  std::vector<OverlayShape> shapes = t.view->overlay(eyes[0]);
  for (OverlayShape shape : t.right->overlay(eyes[1])) {
    shape.x += options_.size.width;
    shapes.push_back(shape);
  }
  return shapes;
}

void Session::set_overlay(bool on) {
  frame_runner().set_overlay(on);
  if (stereo_) stereo_->set_overlay(on);
}

Image SupersampledScene::render(const FrameInput& input) {
  supersampled->render(*scene, input);
  return supersampled->read();
}

std::unique_ptr<SupersampledScene> Session::make_reference(int factor) const {
  if (stereo_) {
    throw OptionError("reference", FieldText{"{reference}: the supersampled reference is "
                                             "monocular; not available with {stereo}",
                                             {"reference", "stereo"}});
  }
  auto r = std::make_unique<SupersampledScene>();
  r->scene = load_scene(options_.scene, scene_options_);
  r->supersampled = for_field(
      "reference", [&] { return std::make_unique<SupersampledNative>(display_, factor); });
  return r;
}

void Session::present() {
  if (!window_) return;
  const int w = window_->framebuffer_width(), h = window_->framebuffer_height();
  // The output holds sRGB-encoded bytes: copied as they are (no decode on
  // read, no encode on write), whatever the window's framebuffer encoding.
  glDisable(GL_FRAMEBUFFER_SRGB);
  const gpu::RenderTarget& out = stereo_ ? stereo_->output() : frame_runner_->output();
  glBlitNamedFramebuffer(out.framebuffer(), 0, 0, 0, out.width(), out.height(), 0, 0, w, h,
                         GL_COLOR_BUFFER_BIT, GL_LINEAR);
  window_->swap_buffers();
}

}  // namespace foveate::bench
