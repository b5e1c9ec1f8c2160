#include "foveate/techniques/pass_kit.hpp"

#include <algorithm>
#include <cstdlib>

#include "foveate/core/error.hpp"
#include "foveate/gpu/frame.hpp"
#include "foveate/gpu/profiler.hpp"
#include "foveate_embedded/techniques_shaders.hpp"

namespace foveate::tech {

namespace {
// The name a pass is timed under: its fragment file's stem
// ("layered/temporal.frag" -> "temporal"); every shading main is "shade".
std::string pass_name_of(const std::string& file) {
  if (file.starts_with("pass_kit/shade_main")) return "shade";
  const size_t slash = file.rfind('/');
  std::string stem = slash == std::string::npos ? file : file.substr(slash + 1);
  const size_t dot = stem.find('.');
  return dot == std::string::npos ? stem : stem.substr(0, dot);
}

// A slot of `pool` no count holds any more (a frame's counts are dropped
// once read), else a new one of what `make` gives: a pool grows to the
// counts of one frame.
template <class Make>
std::shared_ptr<PixelCount::Slot> free_slot(std::vector<std::shared_ptr<PixelCount::Slot>>& pool,
                                            const Make& make) {
  for (const auto& s : pool) {
    if (s.use_count() == 1) {
      s->read = false;
      return s;
    }
  }
  return pool.emplace_back(std::make_shared<PixelCount::Slot>(make()));
}

// The tables a PassKit compiles from: the library's technique and scene GLSL,
// then the technique's own.
std::vector<std::span<const embedded::EmbeddedFile>> with_library(
    std::vector<std::span<const embedded::EmbeddedFile>> tables) {
  tables.insert(tables.begin(), {embedded::techniques_shaders(), scene_shader_files()});
  return tables;
}

}  // namespace

PassKit::PassKit(std::vector<std::span<const embedded::EmbeddedFile>> shaders)
    : shaders_(std::move(shaders)),
      compiler_(with_library(shaders_)),
      vao_(gpu::VertexArray::create()) {}

const gpu::Program& PassKit::fullscreen(const std::string& fragment) {
  return built(fragment, "fullscreen.vert", fragment);
}

const gpu::Program& PassKit::built(const std::string& key, const std::string& vertex,
                                   const std::string& fragment) {
  auto it = programs_.find(key);
  if (it != programs_.end()) return it->second;
  const gpu::Program& p = programs_.emplace(key, compiler_.build(vertex, fragment)).first->second;
  pass_names_[p.id()] = pass_name_of(fragment);
  return p;
}

const gpu::Program& PassKit::shading(const Scene& scene, const std::string& mapping, bool early,
                                     int samples) {
  if (samples > 1)
    return scene_program_with(scene, mapping, "pass_kit/shade_main_msaa.frag", samples);
  return scene_program_with(scene, mapping,
                            early ? "pass_kit/shade_main_early.frag" : "pass_kit/shade_main.frag");
}

const gpu::Program& PassKit::scene_program(const Scene& scene, const std::string& main,
                                           int samples) {
  return scene_program_with(scene, "", main, samples);
}

const gpu::Program& PassKit::scene_program_with(const Scene& scene, const std::string& before,
                                                const std::string& main, int samples,
                                                const std::string& vertex) {
  const std::string key =
      scene.shade_key() + "|" + before + "|" + main + "|" + std::to_string(samples) + "|" + vertex;
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
  for (const auto& t : with_library(shaders_)) tables.push_back(t);
  const gpu::ShaderCompiler c(tables);
  gpu::Program p = c.build({gpu::StageSource{GL_VERTEX_SHADER, {{vertex, {}}}},
                            gpu::StageSource{GL_FRAGMENT_SHADER, pieces}},
                           "scene '" + scene.info().name + "' with " + main);
  const gpu::Program& stored = programs_.emplace(key, std::move(p)).first->second;
  pass_names_[stored.id()] = pass_name_of(main);
  return stored;
}

void PassKit::draw_triangle(const gpu::Program& program) const {
  program.use();
  glBindVertexArray(vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

const char* PassKit::pass_name(const gpu::Program& program) const {
  const auto it = pass_names_.find(program.id());
  return it == pass_names_.end() ? "pass" : it->second.c_str();
}

void PassKit::pass(const gpu::Program& program, const gpu::RenderTarget& target,
                   const gpu::PassState& state, const SetUniforms& set) {
  const gpu::ProfileScope timed(pass_name(program));
  gpu::Samplers samplers;
  if (set) set(program, samplers);
  target.bind();
  gpu::apply(state);
  draw_triangle(program);
}

void PassKit::pass_around_disc(const gpu::RenderTarget& target, Vec2d centre, double inner,
                               double outer, const std::string& inside, const std::string& band,
                               const std::string& outside, const SetUniforms& set) {
  if (!DepthRegions::usable(target)) {
    pass(fullscreen(band), target, {}, set);
    return;
  }
  const gpu::Program& band_program = over_regions(band);
  const gpu::ProfileScope timed(pass_name(band_program));
  regions_.begin(target, 3);
  gpu::Samplers samplers;
  const gpu::Program& in = over_regions(inside);
  set(in, samplers);
  regions_.disc(in, centre, inner, true);
  set(band_program, samplers);
  regions_.disc(band_program, centre, outer, false);
  const gpu::Program& out = over_regions(outside);
  set(out, samplers);
  regions_.rest(out);
}

const gpu::Program& PassKit::over_rects(const std::string& fragment) {
  return built("rects|" + fragment, "pass_kit/rects.vert", fragment);
}

const gpu::Program& PassKit::over_regions(const std::string& fragment) {
  return built("regions|" + fragment, "pass_kit/region.vert", fragment);
}

void PassKit::rect_pass(const gpu::Program& program, const std::vector<PixelRect>& rects,
                        const gpu::RenderTarget& target, const gpu::PassState& state,
                        const SetUniforms& set) {
  const gpu::ProfileScope timed(pass_name(program));
  gpu::Samplers samplers;
  if (set) set(program, samplers);
  rect_pass_.draw(program, rects, target, state);
}

void PassKit::rect_pass_in_bound(const gpu::Program& program, const std::vector<PixelRect>& rects,
                                 int width, int height, const gpu::PassState& state) {
  const gpu::ProfileScope timed(pass_name(program));
  gpu::apply(state);
  rect_pass_.draw(program, rects, width, height);
}

void PassKit::pass_in_bound(const gpu::Program& program, const gpu::PassState& state) {
  const gpu::ProfileScope timed(pass_name(program));
  gpu::apply(state);
  draw_triangle(program);
}

void PassKit::scene_pass(Scene& scene, const View& view, const gpu::Program& program,
                         const gpu::RenderTarget& target, const gpu::PassState& state,
                         const SetUniforms& set, const std::vector<PixelRect>* cover) {
  const gpu::ProfileScope timed(pass_name(program));
  gpu::Samplers samplers;
  scene.bind(program, view, samplers);
  if (set) set(program, samplers);
  target.bind();
  if (!cover) {
    gpu::apply(state);
    draw_triangle(program);
    return;
  }
  // One scissored full-screen triangle per rectangle rather than a quad of
  // two triangles each: llvmpipe shades a 4x4 block once per triangle that
  // touches it, and the diagonal of a long thin quad touches nearly every
  // block of it. The scissor clips exactly, on whole blocks where the
  // rectangles are aligned to them. Each draw has a fixed cost (on cheap
  // scenes more than the pixels it saves: docs/performance.md), so bands are
  // merged where that shades at most 8 % more.
  gpu::PassState clipped = state;
  for (const PixelRect& r : coarsen_runs(*cover, 0.08)) {
    clipped.scissor = {r[0], r[1], r[2] - r[0], r[3] - r[1]};
    gpu::apply(clipped);
    draw_triangle(program);
  }
  gpu::apply(state);
}

PixelCount PassKit::shade(Scene& scene, const View& view, const std::string& mapping,
                          const gpu::RenderTarget& target, const SetUniforms& set,
                          const gpu::PassState& state, bool early,
                          const std::vector<PixelRect>* cover) {
  const gpu::Program& p = shading(scene, mapping, early, view.samples);
  std::shared_ptr<PixelCount::Slot> slot =
      free_slot(counts_, [] { return gpu::Query::create(GL_SAMPLES_PASSED); });
  const gpu::ProfileScope timed("shade");
  glBeginQuery(GL_SAMPLES_PASSED, slot->query.id());
  scene_pass(scene, view, p, target, state, set, cover);
  glEndQuery(GL_SAMPLES_PASSED);
  PixelCount count;
  count.terms_.push_back(std::move(slot));
  return count;
}

PixelCount PassKit::count_from(const gpu::Buffer& source, GLintptr offset) {
  std::shared_ptr<PixelCount::Slot> slot =
      free_slot(buffer_counts_, [] { return gpu::Buffer::create(sizeof(GLuint), nullptr); });
  glCopyNamedBufferSubData(source.id(), slot->buffer.id(), offset, 0, sizeof(GLuint));
  PixelCount count;
  count.terms_.push_back(std::move(slot));
  return count;
}

bool PassKit::indirect_edges() {
  if (indirect_edges_) return *indirect_edges_;
  // FOVEATE_EDGES=indirect or readback forces a path (to compare them on
  // one renderer); else the renderer decides.
  const char* env = std::getenv("FOVEATE_EDGES");
  const std::string force = env ? env : "";
  if (force == "indirect" || force == "readback") {
    indirect_edges_ = force == "indirect";
  } else if (!force.empty()) {
    throw Error("FOVEATE_EDGES='" + force + "': expected 'indirect' or 'readback'");
  } else {
    indirect_edges_ = gpu::FrameTimer::gpu_timer_meaningful();
  }
  return *indirect_edges_;
}

double PixelCount::read() const {
  double total = known_;
  for (const auto& slot : terms_) {
    if (!slot->read && slot->query) {
      GLuint64 samples = 0;
      glGetQueryObjectui64v(slot->query.id(), GL_QUERY_RESULT, &samples);
      slot->value = static_cast<double>(samples);
      slot->read = true;
    } else if (!slot->read) {
      GLuint n = 0;
      glGetNamedBufferSubData(slot->buffer.id(), 0, sizeof(GLuint), &n);
      slot->value = static_cast<double>(n);
      slot->read = true;
    }
    total += slot->value;
  }
  return total;
}

PixelCount& PixelCount::operator+=(const PixelCount& other) {
  terms_.insert(terms_.end(), other.terms_.begin(), other.terms_.end());
  known_ += other.known_;
  return *this;
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

double latency_travel_deg(const GazeState& g) {
  return std::max(0.0, g.latency_ms) * std::max(0.0, g.max_saccade_deg_per_s) / 1000.0;
}

OverlayShape gaze_dot(const GazeState& g) {
  return {OverlayShape::Kind::Dot, g.gaze_px.x, g.gaze_px.y, 4, 4, 1.0f, 0.3f, 0.8f, "gaze"};
}

}  // namespace foveate::tech
