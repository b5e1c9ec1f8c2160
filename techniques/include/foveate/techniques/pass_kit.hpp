#pragma once
// The pass machinery every technique renders with, the built-in ones and
// those written outside the library: one shader compiler over every module's
// embedded GLSL (and the technique's own), passes with explicit state into
// explicit targets, shading passes that evaluate a scene's shading function
// at positions given by a mapping, and fragment counting with occlusion
// queries. Each pass is timed (gpu::ProfileScope) under its fragment file's
// stem: the names TechniqueInfo::resolve_passes lists.
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "foveate/gpu/gl.hpp"
#include "foveate/gpu/pass.hpp"
#include "foveate/gpu/shader.hpp"
#include "foveate/techniques/depth_regions.hpp"
#include "foveate/techniques/rect_pass.hpp"
#include "foveate/techniques/technique.hpp"

namespace foveate::tech {

/// Fragments counted by the occlusion queries of shading passes, read only
/// when asked. Reading a query right after its pass makes the CPU wait until
/// the GPU has finished that pass before it can send the next one, and the
/// GPU idle while it does. So a technique adds up its passes' counts and
/// reads them once, after it has sent its last pass (docs/performance.md).
/// Sums stay unread; a count must not outlive the PassKit that made it.
class PixelCount {
 public:
  PixelCount() = default;
  /// A count known on the CPU.
  explicit PixelCount(double known) : known_(known) {}
  /// The count: waits for the queries not read yet. Needs the context current.
  [[nodiscard]] double read() const;
  PixelCount& operator+=(const PixelCount& other);
  friend PixelCount operator+(PixelCount a, const PixelCount& b) { return a += b; }

  /// One count of PassKit's pools, free again when no count holds it: an
  /// occlusion query's, or a 4-byte buffer's (a count a pass wrote on the GPU).
  struct Slot {
    explicit Slot(gpu::Query q) : query(std::move(q)) {}
    explicit Slot(gpu::Buffer b) : buffer(std::move(b)) {}
    gpu::Query query;
    gpu::Buffer buffer;
    bool read = false;
    double value = 0.0;
  };

 private:
  friend class PassKit;
  std::vector<std::shared_ptr<Slot>> terms_;
  double known_ = 0.0;
};

/// Sets a pass's uniforms and binds its textures (after the scene's).
using SetUniforms = std::function<void(const gpu::Program&, gpu::Samplers&)>;

/// Compiler over gpu, scenes and techniques GLSL; a full-screen triangle VAO.
class PassKit {
 public:
  /// `shaders`: GLSL files of a technique outside the library (its own
  /// fragment shaders and includes), found by name beside the library's.
  explicit PassKit(std::vector<std::span<const embedded::EmbeddedFile>> shaders = {});
  [[nodiscard]] const gpu::ShaderCompiler& compiler() const { return compiler_; }
  /// A program of fullscreen.vert + `fragment` (embedded name), cached.
  const gpu::Program& fullscreen(const std::string& fragment);
  /// The program shading `scene` at positions from `mapping` (an embedded
  /// GLSL file defining vec2 foveate_map(vec2 frag_coord)), cached per scene.
  /// With `early`, depth and stencil tests run before shading (stencil masks
  /// really save the work) and there is no off-screen discard.
  const gpu::Program& shading(const Scene& scene, const std::string& mapping, bool early = false,
                              int samples = 1);
  /// A program of the scene's shading GLSL followed by `main` (an embedded
  /// file with main() that may call the scene's functions), cached per scene.
  const gpu::Program& scene_program(const Scene& scene, const std::string& main, int samples = 1);
  /// One full-screen pass of `program` into `target` with `state`; binds the
  /// textures `set` asks for.
  void pass(const gpu::Program& program, const gpu::RenderTarget& target,
            const gpu::PassState& state = {}, const SetUniforms& set = {});
  /// A program of pass_kit/rects.vert + `fragment`, cached: passes drawn over
  /// rectangles only (rect_pass).
  const gpu::Program& over_rects(const std::string& fragment);
  /// A program of pass_kit/region.vert + `fragment`, cached: one region of a
  /// pass split by DepthRegions (the fragment shader declares
  /// layout(early_fragment_tests)).
  const gpu::Program& over_regions(const std::string& fragment);
  /// One full-screen pass split around a disc (GL pixels of `target`), so
  /// that each pixel runs only the shader its region needs: `inside` over
  /// the pixels within `inner_px`, `band` over the rest of the disc of `outer_px`,
  /// `outside` beyond (each an over_regions fragment shader); `set` sets up
  /// each program. Timed as `band`'s pass. Into a target without a colour
  /// texture (a window) one full-screen pass of `band`, which must then
  /// handle every region itself.
  void pass_around_disc(const gpu::RenderTarget& target, Vec2d centre, double inner_px,
                        double outer_px, const std::string& inside, const std::string& band,
                        const std::string& outside, const SetUniforms& set);
  /// A pass of an over_rects program into `target` with `state`, covering
  /// only `rects` (GL pixels of the target).
  void rect_pass(const gpu::Program& program, const std::vector<PixelRect>& rects,
                 const gpu::RenderTarget& target, const gpu::PassState& state = {},
                 const SetUniforms& set = {});
  /// The same into whatever framebuffer is bound (of size width x height).
  void rect_pass_in_bound(const gpu::Program& program, const std::vector<PixelRect>& rects,
                          int width, int height, const gpu::PassState& state);
  /// A full-screen pass into whatever framebuffer is bound: a scene's
  /// G-buffer between prepass_begin and prepass_end (lodmask's masks).
  void pass_in_bound(const gpu::Program& program, const gpu::PassState& state);
  /// A full-screen pass into `target` of a program that runs the scene's
  /// shading (binds the scene's uniforms and textures for `view` first).
  /// With a `cover` (GL pixels of `target`) it is drawn over those
  /// rectangles only, merged into fewer where that shades little more (an
  /// empty cover draws nothing).
  void scene_pass(Scene& scene, const View& view, const gpu::Program& program,
                  const gpu::RenderTarget& target, const gpu::PassState& state = {},
                  const SetUniforms& set = {}, const std::vector<PixelRect>* cover = nullptr);
  /// A shading pass over `target`: the scene shaded at the mapping's
  /// positions. Returns the fragments that reached the shader (an occlusion
  /// query, read when the count is; stencil-rejected and discarded fragments
  /// do not count). With a
  /// `cover`, drawn over its rectangles only (scene_pass): what a technique
  /// does not show is never run. The shading variants have no discard (on
  /// llvmpipe a shader that can discard is slower everywhere, and a
  /// discarded fragment costs as much as a shaded one).
  PixelCount shade(Scene& scene, const View& view, const std::string& mapping,
                   const gpu::RenderTarget& target, const SetUniforms& set,
                   const gpu::PassState& state = {}, bool early = false,
                   const std::vector<PixelRect>* cover = nullptr);
  /// Antialiasing in a subsampled buffer (marwarp, logpolar, vrs): marks the
  /// texels of `cover` (columns [first, last); of the buffer's first `rows`
  /// rows, all when 0, which wrap with `wrap_rows`, as a polar buffer's
  /// angles do) whose linear luminance
  /// differs from a neighbour's by more than `contrast` of the brighter
  /// (pass_kit/edges.frag, reading a copy of the colour in `scratch`, a
  /// texture of the buffer's size and format: reading the framebuffer drawn
  /// into is a feedback loop, which llvmpipe's threads resolve differently
  /// from run to run), lists them in order (edges_list.comp), reshades them
  /// packed side by side through `mapping` (shade_edges.frag; `set` sets
  /// the mapping's uniforms) with `samples` new samples: 4 on a rotated
  /// grid, or 2 on the texel's diagonal averaged with the centre sample the
  /// texel holds; and stores each back into its texel (edges_scatter.comp). `buffer`'s
  /// colour is RGBA16F or GL_SRGB8_ALPHA8 (immutable storage). Packed, only marked
  /// texels are shaded: over the buffer itself a stencil test leaves whole
  /// 4x4 blocks (llvmpipe) or 2x2 quads (GPUs) running for one marked texel.
  /// Returns the texels reshaded (each costs `samples` samples), read when
  /// the count is. With indirect_edges() the GPU sizes the packed pass and
  /// the store from the total it listed, and nothing waits for it; without,
  /// the total is read back first and the packed pass drawn over scissored
  /// rectangles, about 1 ms a frame cheaper on llvmpipe, which runs the
  /// passes as they are sent (docs/performance.md). The two give the same
  /// texels.
  PixelCount supersample_edges(Scene& scene, const View& view, const std::string& mapping,
                               const gpu::RenderTarget& buffer, const gpu::Texture& scratch,
                               const std::vector<PixelRect>& cover, int first, int last,
                               double contrast, const SetUniforms& set, bool wrap_rows = true,
                               int rows = 0, int samples = 4);
  /// Whether supersample_edges runs without reading the total back: by
  /// default on hardware renderers (gpu::FrameTimer::gpu_timer_meaningful),
  /// not on software ones; FOVEATE_EDGES=indirect or readback in the
  /// environment forces one (an Error names any other value), and the setter
  /// overrides both.
  [[nodiscard]] bool indirect_edges();
  void set_indirect_edges(bool on) { indirect_edges_ = on; }

 private:
  /// A program of two files from the technique shaders, cached under `key`.
  const gpu::Program& built(const std::string& key, const std::string& vertex,
                            const std::string& fragment);
  const gpu::Program& scene_program_with(const Scene& scene, const std::string& before,
                                         const std::string& main, int samples = 1,
                                         const std::string& vertex = "fullscreen.vert");
  /// A count in a pooled 4-byte buffer, copied from `source` at `offset`.
  PixelCount count_from(const gpu::Buffer& source, GLintptr offset);
  void draw_triangle(const gpu::Program& program) const;
  /// What a program's passes are timed as (gpu::ProfileScope).
  [[nodiscard]] const char* pass_name(const gpu::Program& program) const;
  std::vector<std::span<const embedded::EmbeddedFile>> shaders_;  ///< the technique's own
  gpu::ShaderCompiler compiler_;
  gpu::VertexArray vao_;
  std::vector<std::shared_ptr<PixelCount::Slot>> counts_;         ///< shade's queries
  std::vector<std::shared_ptr<PixelCount::Slot>> buffer_counts_;  ///< count_from's
  std::optional<bool> indirect_edges_;
  RectPass rect_pass_;
  DepthRegions regions_;  ///< pass_around_disc's
  std::map<std::string, gpu::Program> programs_;
  std::map<GLuint, std::string> pass_names_;  ///< by program id
  /// supersample_edges' working storage, of one buffer's size.
  struct EdgeScratch {
    gpu::Texture marks;        ///< R32UI: a bit per texel, 1 = reshade
    gpu::Texture list;         ///< R32UI: the marked texels, packed
    gpu::RenderTarget shaded;  ///< their samples' means, packed as the list
    gpu::Buffer rows;          ///< head and rows (pass_kit/edges_rows.glsl)
    int columns = 1;           ///< the packed target's 4x4 blocks to a row
  };
  /// The storage for a w x h buffer (made on first use), and the programs.
  EdgeScratch& edge_scratch(int w, int h);
  /// supersample_edges' marks and list (edges.frag, edges_list.comp).
  void list_edges(const EdgeScratch& e, const gpu::RenderTarget& buffer,
                  const gpu::Texture& scratch, const std::vector<PixelRect>& cover, int first,
                  int last, double contrast, bool wrap_rows, int rows);
  /// One per buffer size, kept: vrs reshades several class targets of
  /// different sizes every frame.
  std::map<std::pair<int, int>, EdgeScratch> edges_;
  gpu::Program edge_list_;     ///< edges_list.comp
  gpu::Program edge_scatter_;  ///< edges_scatter.comp
};

/// GL coordinates (origin bottom-left) of a top-left-origin point.
inline Vec2d to_gl(Vec2d p, int height) { return {p.x, height - p.y}; }

/// The rect mapping file and its uniforms for `view`.
inline constexpr const char* kMapRect = "pass_kit/map_rect.glsl";
void set_rect_mapping(const gpu::Program& p, const View& view);

/// Stats of a technique whose shading is one pass (`name`: what it shaded).
FrameStats one_pass_stats(const char* name, double shaded, int width, int height);

/// Extra eccentricity (degrees) that the eye can travel during the gaze latency.
double latency_travel_deg(const GazeState& gaze);

/// The gaze marker every overlay ends with.
OverlayShape gaze_dot(const GazeState& gaze);

/// Overlay colours by ring, innermost first (layers, regions, LODs).
inline constexpr float kRingColours[6][3] = {{1, 0.1f, 0.1f}, {0.1f, 0.9f, 0.2f},
                                             {0.2f, 0.4f, 1}, {1, 0.8f, 0.1f},
                                             {0.8f, 0.2f, 1}, {0.1f, 0.9f, 0.9f}};

}  // namespace foveate::tech
