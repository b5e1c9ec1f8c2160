#include "session.hpp"

#include <cstdlib>

#include "foveate/core/error.hpp"
#include "foveate/gpu/frame.hpp"

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
      (void)technique_info(tech);  // unknown technique names are errors
    }
    out.per_technique[tech][key] = v;
  }
  return out;
}

void validate_params(const ParamArgs& p, const std::vector<std::string>& techs) {
  auto all = p.per_technique.find("");
  if (all == p.per_technique.end()) return;
  for (const auto& [key, v] : all->second) {
    bool known = false;
    std::string names;
    for (const std::string& t : techs) {
      names += (names.empty() ? "" : ", ") + t;
      for (const ParamSpec& s : technique_info(t).params) known = known || s.key == key;
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
      for (const ParamSpec& s : info.params) {
        if (s.key == k) out[k] = v;
      }
    }
  }
  auto mine = p.per_technique.find(technique);
  if (mine != p.per_technique.end()) {
    for (const auto& [k, v] : mine->second) out[k] = v;
  }
  return out;
}

Session::Session(const SessionOptions& o) : options_(o) {
  display_ = Display::load(o.display).resized(o.size.width, o.size.height);
  if (o.window) {
    auto w = gpu::create_window(o.size.width, o.size.height, "foveate");
    window_ = w.get();
    context_ = std::move(w);
  } else {
    context_ = gpu::create_headless_context();
  }
  GLint max = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max);
  if (o.size.width > max || o.size.height > max) {
    throw Error("--size " + std::to_string(o.size.width) + "x" + std::to_string(o.size.height) +
                ": larger than this GL's maximum texture size " + std::to_string(max));
  }
  SceneOptions so;
  so.channels = o.channels;
  so.camera_path = o.camera_path;
  scene_ = load_scene(o.scene, so);
  color_ = gpu::Texture::create_2d(GL_RGBA8, o.size.width, o.size.height);
  fbo_ = gpu::Framebuffer::create();
  fbo_.attach(GL_COLOR_ATTACHMENT0, color_);
  fbo_.check("output");
}

std::unique_ptr<Technique> Session::make(const std::string& technique,
                                         const ParamArgs& params) const {
  TechniqueConfig c;
  c.display = display_;
  c.acuity = options_.acuity;
  c.params = params_for(params, technique);
  return make_technique(technique, c);
}

FrameInput Session::frame_input(int frame) const {
  FrameInput f;
  f.frame = frame;
  f.delta_s = 1.0 / options_.fps;
  f.time_s = options_.start_time + frame / options_.fps;
  f.width = options_.size.width;
  f.height = options_.size.height;
  f.mouse_px = {options_.mouse_px.x, options_.size.height - options_.mouse_px.y};
  f.mouse_down = options_.mouse_down;
  return f;
}

FrameStats Session::render(Technique& technique, int frame, const GazeState& gaze, bool overlay) {
  const FrameInput f = frame_input(frame);
  scene_->update(f);
  FrameStats s = technique.render(*scene_, f, gaze, fbo_.id());
  if (overlay) {
    if (!overlay_) overlay_ = std::make_unique<OverlayRenderer>();
    overlay_->draw(technique.overlay(gaze), f.width, f.height, fbo_.id());
  }
  return s;
}

void Session::present() {
  if (!window_) return;
  const int w = window_->framebuffer_width(), h = window_->framebuffer_height();
  glBlitNamedFramebuffer(fbo_.id(), 0, 0, 0, options_.size.width, options_.size.height, 0, 0, w, h,
                         GL_COLOR_BUFFER_BIT, GL_LINEAR);
  window_->swap_buffers();
}

Image Session::read_output() const { return gpu::read_texture(color_); }

}  // namespace foveate::app
