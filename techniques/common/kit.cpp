#include "kit.hpp"

#include <cmath>

#include "foveate/core/error.hpp"
#include "foveate_embedded/techniques_shaders.hpp"

namespace foveate::tech {

Params::Params(const std::string& technique, const TechniqueConfig& config)
    : info_(technique_info(technique)), overrides_(config.params) {}

double Params::get(const std::string& key, double fallback) {
  const ParamSpec* spec = nullptr;
  for (const ParamSpec& s : info_.params) {
    if (s.key == key) spec = &s;
  }
  if (!spec)
    throw Error("technique " + info_.name + ": internal: parameter '" + key + "' has no spec");
  double v = fallback;
  auto it = overrides_.find(key);
  if (it != overrides_.end()) {
    v = it->second;
    overrides_.erase(it);
    if (!std::isfinite(v) || v < spec->min || v > spec->max) {
      throw Error("--param " + key + "=" + std::to_string(v) + ": out of range for " + info_.name +
                  " [" + std::to_string(spec->min) + ", " + std::to_string(spec->max) + "]");
    }
    if (spec->integer && v != std::floor(v)) {
      throw Error("--param " + key + ": must be a whole number for " + info_.name);
    }
  }
  values_.emplace_back(key, v);
  return v;
}

void Params::finish() const {
  if (overrides_.empty()) return;
  std::string known;
  for (const ParamSpec& s : info_.params) known += (known.empty() ? "" : ", ") + s.key;
  throw Error("--param " + overrides_.begin()->first + ": " + info_.name +
              " has no such parameter (it has: " + (known.empty() ? "none" : known) + ")");
}

Kit::Kit()
    : compiler_({embedded::techniques_shaders(), scene_shader_files()}),
      vao_(gpu::VertexArray::create()),
      query_(gpu::Query::create(GL_SAMPLES_PASSED)) {}

const gpu::Program& Kit::fullscreen(const std::string& fragment) {
  auto it = programs_.find(fragment);
  if (it != programs_.end()) return it->second;
  return programs_.emplace(fragment, compiler_.build("fullscreen.vert", fragment)).first->second;
}

const gpu::Program& Kit::shading(const Scene& scene, const std::string& mapping, bool early,
                                 int samples) {
  if (samples > 1)
    return scene_program_with(scene, mapping, "common/shade_main_msaa.frag", samples);
  return scene_program_with(scene, mapping,
                            early ? "common/shade_main_early.frag" : "common/shade_main.frag");
}

const gpu::Program& Kit::scene_program(const Scene& scene, const std::string& main, int samples) {
  return scene_program_with(scene, "", main, samples);
}

const gpu::Program& Kit::scene_program_with(const Scene& scene, const std::string& before,
                                            const std::string& main, int samples) {
  const std::string key =
      scene.shade_key() + "|" + before + "|" + main + "|" + std::to_string(samples);
  auto it = programs_.find(key);
  if (it != programs_.end()) return it->second;
  std::vector<gpu::StageSource::Piece> pieces = scene.shade_source();
  if (!before.empty()) pieces.insert(pieces.begin(), {before, {}});
  if (samples > 1) {
    pieces.insert(pieces.begin(),
                  {"msaa", "#define FOVEATE_GBUFFER_SAMPLES " + std::to_string(samples) + "\n"});
  }
  pieces.push_back({main, {}});
  auto tables = scene.shader_files();
  tables.push_back(embedded::techniques_shaders());
  tables.push_back(scene_shader_files());
  const gpu::ShaderCompiler c(tables);
  gpu::Program p = c.build({gpu::StageSource{GL_VERTEX_SHADER, {{"fullscreen.vert", {}}}},
                            gpu::StageSource{GL_FRAGMENT_SHADER, pieces}},
                           "scene '" + scene.info().name + "'");
  return programs_.emplace(key, std::move(p)).first->second;
}

void Kit::draw_fullscreen(const gpu::Program& program) const {
  program.use();
  glBindVertexArray(vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

double Kit::shade(Scene& scene, const View& view, const std::string& mapping,
                  const std::function<void(const gpu::Program&)>& set_uniforms, bool early) {
  const gpu::Program& p = shading(scene, mapping, early, view.samples);
  scene.bind(p, view);
  if (set_uniforms) set_uniforms(p);
  glBeginQuery(GL_SAMPLES_PASSED, query_.id());
  draw_fullscreen(p);
  glEndQuery(GL_SAMPLES_PASSED);
  GLuint64 samples = 0;
  glGetQueryObjectui64v(query_.id(), GL_QUERY_RESULT, &samples);
  return static_cast<double>(samples);
}

void Target::ensure(int w, int h, GLenum format, bool with_stencil) {
  if (color && width == w && height == h && color.format() == format &&
      static_cast<bool>(depth_stencil) == with_stencil) {
    return;
  }
  width = w;
  height = h;
  color = gpu::Texture::create_2d(format, w, h);
  fbo = gpu::Framebuffer::create();
  fbo.attach(GL_COLOR_ATTACHMENT0, color);
  depth_stencil.reset();
  if (with_stencil) {
    depth_stencil = gpu::Renderbuffer::create(GL_DEPTH24_STENCIL8, w, h);
    fbo.attach(GL_DEPTH_STENCIL_ATTACHMENT, depth_stencil);
  }
  fbo.check("technique target");
}

void Target::bind_viewport() const {
  fbo.bind();
  glViewport(0, 0, width, height);
}

void set_rect_mapping(const gpu::Program& p, const View& v) {
  p.set("u_map_rect", float(v.x0), float(v.y0), float(v.x1 - v.x0), float(v.y1 - v.y0));
  p.set("u_map_target", float(v.target_width), float(v.target_height));
}

FrameStats one_pass_stats(const char* name, double shaded, int width, int height) {
  FrameStats s;
  s.parts.push_back({name, shaded});
  s.shaded_pixels = shaded;
  s.native_pixels = double(width) * height;
  return s;
}

double latency_margin_deg(const GazeState& g) {
  return std::max(0.0, g.latency_ms) * std::max(0.0, g.saccade_deg_per_s) / 1000.0;
}

}  // namespace foveate::tech
