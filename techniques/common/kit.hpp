#pragma once
// Shared machinery of the techniques: one shader compiler over every module's
// embedded GLSL, shading passes that evaluate a scene's shading function at
// positions given by a mapping, fragment counting with occlusion queries, and
// parameter handling.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "foveate/gpu/shader.hpp"
#include "foveate/techniques/technique.hpp"

namespace foveate::tech {

/// Parameter values with their specs; read() checks range and integer-ness.
class Params {
 public:
  Params(const std::string& technique, const TechniqueConfig& config);
  /// The override for `key` if given, else `fallback`; checks the spec's range.
  double get(const std::string& key, double fallback);
  /// Throws if an override was not read by the technique (unknown key).
  void finish() const;
  [[nodiscard]] const std::vector<std::pair<std::string, double>>& values() const {
    return values_;
  }

 private:
  const TechniqueInfo& info_;
  std::map<std::string, double> overrides_;
  std::vector<std::pair<std::string, double>> values_;
};

/// Derives a technique's options from the configuration with
/// `derive(config, params)`, then checks that every override was used.
/// Returns the options and every parameter value in use.
template <class Options, class Derive>
std::pair<Options, std::vector<std::pair<std::string, double>>> derive_options(
    const std::string& technique, const TechniqueConfig& config, Derive derive) {
  Params p(technique, config);
  Options o = derive(config, p);
  p.finish();
  return {o, p.values()};
}

/// Compiler over gpu, scenes and techniques GLSL; a full-screen triangle VAO.
class Kit {
 public:
  Kit();
  [[nodiscard]] const gpu::ShaderCompiler& compiler() const { return compiler_; }
  /// A program of fullscreen.vert + `fragment` (embedded name), cached.
  const gpu::Program& fullscreen(const std::string& fragment);
  /// The program shading `scene` at positions from `mapping` (an embedded GLSL
  /// file defining vec2 foveate_map(vec2 frag_coord)), cached per scene.
  /// With `early`, depth and stencil tests run before shading (stencil masks
  /// really save the work) and there is no off-screen discard.
  const gpu::Program& shading(const Scene& scene, const std::string& mapping, bool early = false,
                              int samples = 1);
  /// A program of the scene's shading GLSL followed by `main` (an embedded
  /// file with main() that may call the scene's functions), cached per scene.
  const gpu::Program& scene_program(const Scene& scene, const std::string& main, int samples = 1);
  /// Draws the full-screen triangle with `program` into the bound framebuffer.
  void draw_fullscreen(const gpu::Program& program) const;
  /// Runs a shading pass over the bound framebuffer's viewport and returns the
  /// number of fragments that reached the shader (occlusion query; stencil
  /// rejected and discarded fragments do not count).
  double shade(Scene& scene, const View& view, const std::string& mapping,
               const std::function<void(const gpu::Program&)>& set_uniforms, bool early = false);

 private:
  const gpu::Program& scene_program_with(const Scene& scene, const std::string& before,
                                         const std::string& main, int samples = 1);
  gpu::ShaderCompiler compiler_;
  gpu::VertexArray vao_;
  gpu::Query query_;
  std::map<std::string, gpu::Program> programs_;
};

/// A colour texture with its framebuffer (and optionally depth-stencil).
struct Target {
  gpu::Texture color;
  gpu::Renderbuffer depth_stencil;
  gpu::Framebuffer fbo;
  int width = 0, height = 0;
  /// (Re)allocates when the size or format changes.
  void ensure(int w, int h, GLenum format = GL_RGBA8, bool with_stencil = false);
  void bind_viewport() const;
};

/// GL coordinates (origin bottom-left) of a top-left-origin point.
inline Vec2d to_gl(Vec2d p, int height) { return {p.x, height - p.y}; }

/// The rect mapping file and its uniforms for `view`.
inline constexpr const char* kMapRect = "common/map_rect.glsl";
void set_rect_mapping(const gpu::Program& p, const View& view);

/// Stats of a technique whose shading is one pass (`name`: what it shaded).
FrameStats one_pass_stats(const char* name, double shaded, int width, int height);

/// Extra eccentricity (degrees) that the eye can travel during the gaze latency.
double latency_margin_deg(const GazeState& gaze);

}  // namespace foveate::tech
