#include "viewer/viewer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cli_util.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/parse.hpp"
#include "foveate/techniques/palette.hpp"
#include "invocation.hpp"

namespace foveate::app::viewer {

namespace {

// EMA weights: the frame time follows within a few frames; native, sampled
// once a second, within two samples.
constexpr double kFrameWeight = 0.2;
constexpr double kNativeWeight = 0.5;
constexpr double kNativePeriodS = 1.0;

double ema(double old, double sample, double weight, bool first) {
  return first ? sample : (1.0 - weight) * old + weight * sample;
}

}  // namespace

void MouseGaze::update(std::optional<Vec2d> on_image) {
  away_ = !on_image;
  if (on_image && !frozen_) position_ = *on_image;
}

const char* MouseGaze::state() const { return frozen_ ? "frozen" : away_ ? "held" : "following"; }

Viewer::Viewer(bench::Session& session, const std::string& technique,
               const bench::ParamOverrides& params, const std::string& preset,
               std::optional<double> slope)
    : session_(session), name_(technique) {
  acuity_ = bench::acuity_from(preset, slope);
  acuity_preset_ =
      slope ? "custom" : (preset.empty() ? "A" : std::string(1, char(std::toupper(preset[0]))));
  for (const TechniqueInfo& t : techniques()) {
    if (!scene_mismatch(t, session_.scene().info()).empty()) continue;
    available_.push_back(t.name);
    params_[t.name] = params.for_technique(t.name);
  }
  // The one asked for: refused with render's message when the scene cannot
  // run it (lodmask without meshes), its --param values checked.
  with_flag("--technique", [&] { return technique_info(technique); });
  params_[technique] = params.for_technique(technique);
  technique_ = build(technique);
  native_ = build("native");
}

Viewer::~Viewer() = default;

bench::SessionTechnique Viewer::build(const std::string& name) const {
  bench::ParamOverrides mine;
  if (const auto it = params_.find(name); it != params_.end())
    mine.per_technique[name] = it->second;
  return session_.make(name, mine, acuity_);
}

void Viewer::rebuild() {
  technique_ = build(name_);
  frames_since_build_ = 0;
}

const std::map<std::string, double>& Viewer::overrides() const { return params_.at(name_); }

void Viewer::set_technique(const std::string& name) {
  if (name == name_) return;
  const TechniqueInfo& info = technique_info(name);  // names the unknown one
  check_scene(info, session_.scene().info());
  technique_ = build(name);
  name_ = name;
  frames_since_build_ = 0;
}

void Viewer::set_param(const std::string& technique, const std::string& key, double value) {
  const std::string tech = technique.empty() ? name_ : technique;
  const TechniqueInfo& info = technique_info(tech);
  if (std::none_of(info.params.begin(), info.params.end(),
                   [&](const ParamDecl& d) { return d.key == key; })) {
    throw Error("param " + tech + "." + key + ": " + tech + " has no parameter '" + key +
                "' (see 'foveate techniques')");
  }
  auto& mine = params_[tech];
  const std::map<std::string, double> before = mine;
  mine[key] = value;
  try {
    if (tech == name_) {
      rebuild();
    } else {
      TechniqueConfig c = session_.technique_config(Eye::Left, acuity_);
      c.params = mine;
      const ParamValues v = resolve_parameters(info, c);
      if (info.check) info.check(v);
    }
  } catch (const Error&) {
    mine = before;
    if (tech == name_) rebuild();
    throw;
  }
}

void Viewer::reset_params() {
  params_[name_].clear();
  rebuild();
}

void Viewer::use_acuity(const AcuityModel& next) {
  const AcuityModel before = acuity_;
  acuity_ = next;
  try {
    rebuild();
  } catch (const Error&) {
    acuity_ = before;  // the technique refused it: keep the one that worked
    rebuild();
    throw;
  }
}

void Viewer::set_acuity_preset(const std::string& preset) {
  use_acuity(AcuityModel::preset(preset));
  acuity_preset_ = std::string(1, char(std::toupper(preset[0])));
}

void Viewer::set_slope(double m) {
  use_acuity(with_flag("slope", [&] { return AcuityModel::with_slope(m); }));
  acuity_preset_ = m == kSlopePresetA ? "A" : m == kSlopePresetB ? "B" : "custom";
}

void Viewer::set_display(const std::string& spec) {
  if (session_.options().stereo) {
    throw Error("display: the display of a stereo view is fixed (restart with another --display)");
  }
  const std::string before = session_.options().display;
  session_.set_display(spec);
  try {
    rebuild();
    native_ = build("native");
    native_renders_ = 0;
  } catch (const Error&) {
    session_.set_display(before);
    rebuild();
    throw;
  }
  stats_.native_ms.reset();
  stats_.native_samples = 0;
  next_native_s_ = -1.0;
}

void Viewer::set_divider(double fraction) {
  if (!(fraction >= 0.0 && fraction <= 1.0))
    throw Error("divider: expected a fraction of the width in [0, 1]");
  divider_ = fraction;
}

void Viewer::set_overlay(bool on) { session_.set_overlay(on); }

void Viewer::set_display_scale(double scale) {
  if (!(scale > 0.0 && scale <= 1.0))
    throw Error("display scale: expected a fraction in (0, 1], got " + format_number(scale));
  scale_ = scale;
}

int Viewer::shown_width() const { return static_cast<int>(std::lround(width() * scale_)); }
int Viewer::shown_height() const { return static_cast<int>(std::lround(height() * scale_)); }

bool Viewer::gaze_follows_mouse() const { return session_.options().gaze.rfind("mouse", 0) == 0; }

void Viewer::record(const std::string& technique, double ms) {
  std::vector<float>& h = history_[technique];
  h.push_back(static_cast<float>(ms));
  if (h.size() > kHistoryFrames) h.erase(h.begin(), h.end() - kHistoryFrames);
}

bench::TechniqueParams Viewer::saved_params() const {
  bench::TechniqueParams out;
  for (const auto& [t, m] : params_) {
    if (!m.empty()) out[t] = m;
  }
  return out;
}

void Viewer::save_params(const std::string& path) const {
  const bench::SessionOptions& o = session_.options();
  bench::write_params_file(
      path, saved_params(),
      "saved by foveate view: scene " + o.scene + " at " + std::to_string(o.size.width) + "x" +
          std::to_string(o.size.height) + " on " + o.display + ", MAR slope " +
          format_number(acuity_.slope, 6) + "; the command line: " + command_line());
}

std::string Viewer::command_line() const {
  const bench::SessionOptions& o = session_.options();
  std::string s = "foveate view --scene " + shell_quote(o.scene) + " --size " +
                  std::to_string(o.size.width) + "x" + std::to_string(o.size.height) +
                  " --display " + shell_quote(o.display);
  if (acuity_preset_ == "custom") {
    s += " --slope " + format_number(acuity_.slope, 6);
  } else if (acuity_preset_ != "A") {
    s += " --acuity " + acuity_preset_;
  }
  if (o.margin) s += " --margin " + format_number(*o.margin, 6);
  if (o.stereo) s += " --stereo";
  if (!o.gaze.empty() && !gaze_follows_mouse()) s += " --gaze " + shell_quote(o.gaze);
  s += " --technique " + shell_quote(name_);
  for (const auto& [t, m] : params_) {
    for (const auto& [k, v] : m)
      s += " --param " + shell_quote(t + "." + k + "=" + format_number(v, 6));
  }
  return s;
}

std::optional<double> Viewer::speedup() const {
  if (name_ == "native") return 1.0;
  if (!stats_.native_ms || stats_.frame_ms <= 0.0) return std::nullopt;
  return *stats_.native_ms / stats_.frame_ms;
}

std::vector<LegendEntry> Viewer::legend() const {
  std::vector<LegendEntry> out;
  for (const OverlayShape& s : overlay_legend(technique_.view->overlay(gaze_)))
    out.push_back({s.r, s.g, s.b, s.label.empty() ? "(unlabelled)" : s.label, s.kind});
  return out;
}

double Viewer::timed_render(bench::SessionTechnique& t, const FrameInput& input,
                            const GazeState& gaze, bool with_overlay, FrameStats* stats) {
  const bool was = overlay();
  session_.set_overlay(with_overlay && was);
  timer_.start();
  FrameStats s = session_.render(t, input, gaze).total;
  const double ms = timer_.stop();
  session_.set_overlay(was);
  if (stats) *stats = std::move(s);
  return ms;
}

void Viewer::blit_columns(int x0, int x1) {
  if (x1 <= x0) return;
  const int H = height();
  const int fb_h = session_.window() ? session_.window()->framebuffer_height() : H;
  // The output holds sRGB-encoded bytes: copied as they are.
  glDisable(GL_FRAMEBUFFER_SRGB);
  const gpu::RenderTarget& out =
      session_.stereo() ? session_.stereo()->output() : session_.frame_runner().output();
  // Scaled to fit the window when it must be (set_display_scale).
  auto shown = [&](int x) { return static_cast<GLint>(std::lround(x * scale_)); };
  glBlitNamedFramebuffer(out.framebuffer(), 0, x0, 0, x1, H, shown(x0), fb_h - shown_height(),
                         shown(x1), fb_h, GL_COLOR_BUFFER_BIT,
                         scale_ == 1.0 ? GL_NEAREST : GL_LINEAR);
}

void Viewer::render_frame(const FrameInput& input, const GazeState& gaze, double wall_s) {
  gaze_ = gaze;
  const bool native_due =
      !split_ && name_ != "native" && (next_native_s_ < 0 || wall_s >= next_native_s_);
  auto record_native = [&](double ms) {
    if (native_renders_++ == 0) {  // compiled its shaders: not a measurement
      next_native_s_ = -1.0;
      return;
    }
    stats_.native_ms =
        ema(stats_.native_ms.value_or(ms), ms, kNativeWeight, stats_.native_samples == 0);
    ++stats_.native_samples;
    record("native", ms);
  };
  // Clear the window (the UI's part) before drawing into it.
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (session_.window()) {
    glViewport(0, 0, session_.window()->framebuffer_width(),
               session_.window()->framebuffer_height());
  }
  glDisable(GL_SCISSOR_TEST);
  glClearColor(0.06f, 0.06f, 0.07f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  if (native_due) {
    // Native on the same frame, timed alike; its image is not shown.
    next_native_s_ = wall_s + kNativePeriodS;
    record_native(timed_render(native_, input, gaze, false, nullptr));
  }
  const int W = width();
  const int split_px = std::clamp(static_cast<int>(std::lround(divider_ * W)), 0, W);
  if (split_) {
    // Left: native; right: the technique.
    const double nms = timed_render(native_, input, gaze, false, nullptr);
    record_native(nms);
    blit_columns(0, split_px);
  }
  if (show_native_ && !split_) {
    const double nms = timed_render(native_, input, gaze, false, nullptr);
    record_native(nms);
    blit_columns(0, W);
  } else {
    FrameStats s;
    const double ms = timed_render(technique_, input, gaze, true, &s);
    stats_.last = std::move(s);
    stats_.last_ms = ms;
    // The first frames after a (re)build compile shaders and fill history.
    const bool settling = frames_since_build_ <= technique_.view->settle_frames();
    stats_.frame_ms = ema(stats_.frame_ms, ms, kFrameWeight, settling || stats_.frame_ms <= 0);
    if (!settling) record(name_, ms);
    ++frames_since_build_;
    blit_columns(split_ ? split_px : 0, W);
  }
  if (name_ == "native" && !show_native_ && !split_) {
    stats_.native_ms = stats_.frame_ms;
    stats_.native_samples = std::max(stats_.native_samples, 1);
  }
  ++frame_;
}

nlohmann::json Viewer::state() const {
  nlohmann::json j;
  j["frame"] = frame_;
  j["technique"] = name_;
  nlohmann::json params = nlohmann::json::object();
  for (const auto& [k, v] : technique_.view->values().items()) params[k] = v;
  j["params"] = params;
  nlohmann::json over = nlohmann::json::object();
  for (const auto& [k, v] : overrides()) over[k] = v;
  j["overrides"] = over;
  nlohmann::json all = nlohmann::json::object();
  for (const auto& [t, m] : params_) {
    if (m.empty()) continue;
    for (const auto& [k, v] : m) all[t][k] = v;
  }
  j["overrides_by_technique"] = all;
  j["quality"] = acuity_preset_;  // print-state's key, which scripts read
  j["slope"] = acuity_.slope;
  j["margin"] =
      session_.options().margin ? nlohmann::json(*session_.options().margin) : nlohmann::json();
  j["display"] = display_spec();
  j["shown"] = split_ ? "split" : show_native_ ? "native" : "foveated";
  j["split"] = split_;
  j["divider"] = divider_;
  j["overlay"] = overlay();
  j["frame_ms"] = stats_.frame_ms;
  j["native_ms"] = stats_.native_ms ? nlohmann::json(*stats_.native_ms) : nlohmann::json();
  const auto sp = speedup();
  j["speedup"] = sp ? nlohmann::json(*sp) : nlohmann::json();
  j["shaded_pixels"] = stats_.last.shaded_pixels;
  j["native_pixels"] = stats_.last.native_pixels;
  j["shaded_share"] =
      stats_.last.native_pixels > 0 ? stats_.last.shaded_pixels / stats_.last.native_pixels : 0.0;
  auto& g = session_.gaze();
  const auto& f = g.last();
  j["gaze"] = {{"source", g.describe()},  {"x_px", gaze_.gaze_px.x},
               {"y_px", gaze_.gaze_px.y}, {"valid", f.valid},
               {"holding", f.holding},    {"fallback", f.fallback},
               {"saccade", f.in_saccade}, {"latency_ms", gaze_.latency_ms}};
  // Following the mouse: whether it follows, holds its last place on the
  // image, or is frozen.
  j["gaze"]["hold"] = gaze_follows_mouse() ? nlohmann::json(mouse_gaze_.state()) : nlohmann::json();
  j["display_scale"] = scale_;
  nlohmann::json history = nlohmann::json::object();
  for (const auto& [t, h] : history_) history[t] = h.size();
  j["history_frames"] = history;
  j["command_line"] = command_line();
  if (session_.options().stereo) {
    // The gaze above is the combined (cyclopean) one; here each eye's.
    const std::array<GazeState, 2> eyes = session_.eye_gazes(gaze_);
    j["stereo"] = {{"left_px", {eyes[0].gaze_px.x, eyes[0].gaze_px.y}},
                   {"right_px", {eyes[1].gaze_px.x, eyes[1].gaze_px.y}}};
  }
  nlohmann::json legend = nlohmann::json::array();
  for (const LegendEntry& e : this->legend()) {
    char hex[8];
    auto byte = [](float c) {
      return static_cast<int>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255));
    };
    std::snprintf(hex, sizeof hex, "#%02x%02x%02x", byte(e.r), byte(e.g), byte(e.b));
    const char* shape = e.kind == OverlayShape::Kind::Rect     ? "rectangle"
                        : e.kind == OverlayShape::Kind::Circle ? "ring"
                                                               : "dot";
    legend.push_back({{"colour", hex}, {"label", e.label}, {"shape", shape}});
  }
  j["legend"] = legend;
  return j;
}

}  // namespace foveate::app::viewer
