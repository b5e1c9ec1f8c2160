#pragma once
// The scene interface: everything a foveation technique needs from content,
// and nothing about foveation. A scene is
//   1. an optional geometry prepass that rasterises a region of the screen into
//      the scene's own G-buffer (mesh scenes; screen-space scenes have none), and
//   2. a GLSL function `vec4 scene_shade(vec2 screen_px)` that shades any
//      screen position (pixels of the full frame, origin bottom-left as
//      gl_FragCoord), reading the G-buffer if there is one.
// A technique decides which screen positions get shaded, at what rate and in
// which buffer (a layer, a log-polar buffer, a checkerboard); it supplies
// `vec2 foveate_map(vec2 frag_coord)` that turns its own fragment coordinate
// into a screen position. That split is what lets any technique run on any
// scene, and what a user implements to foveate their own renderer.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "foveate/core/display.hpp"
#include "foveate/core/stereo.hpp"
#include "foveate/gpu/pass.hpp"
#include "foveate/gpu/shader.hpp"

namespace foveate {

/// One view of a stereo pair (a head-mounted display's eye). A scene with a 3D
/// camera renders from the eye: the camera moved `offset_m` along its right
/// vector (scene units taken as metres) and an off-axis frustum with the
/// eye's image-plane tangents in place of the camera's own field of view.
/// Scenes without a camera (Shadertoy) render the same image for every view.
struct EyeView {
  double offset_m = 0.0;
  FrustumTangents frustum{-1.0, 1.0, -1.0, 1.0};
};

/// Per-frame inputs, on a fixed clock so that runs are deterministic.
struct FrameInput {
  double time_s = 0.0;
  double delta_s = 1.0 / 60.0;
  int frame = 0;
  int width = 0;  ///< full output resolution
  int height = 0;
  Vec2d mouse_px{0.0, 0.0};  ///< pixels, origin top-left (as every position outside GLSL)
  bool mouse_down = false;
  /// Set when rendering one eye of a stereo pair; empty = the scene's own camera.
  std::optional<EyeView> eye;
};

/// A region of the full screen rendered into a target of its own size.
struct View {
  /// Screen rectangle [x0, y0] - [x1, y1] in full-frame pixels (origin
  /// bottom-left); may extend beyond the screen. Off-centre sub-frustum.
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int target_width = 0;
  int target_height = 0;
  /// Geometric LOD scale: the scene draws meshes as coarse as for a target
  /// whose pixels are this many native pixels (a layer's sampling factor s).
  /// Techniques pass 1 (native's LOD) unless coarser geometry is their
  /// point: a coarser mesh moves silhouettes and normals by more than a
  /// subsampled layer's MAR hides.
  double pixel_scale = 1.0;
  /// Multisample antialiasing of the prepass (mesh scenes): 1 = off. With
  /// more, the scene's shading GLSL is compiled with FOVEATE_GBUFFER_SAMPLES
  /// defined, reads sample `foveate_sample`, and defines
  /// `bool scene_samples_differ(vec2 screen_px)` (true on edges, where each
  /// sample is shaded).
  int samples = 1;
  /// Objects wholly inside this screen rectangle (full-frame pixels, as x0..y1)
  /// never show in this draw: a technique fills it from another one
  /// (lodmask's finer LOD under its stencil circle, inset's inset), so
  /// prepass_draw may leave them out (the mesh scenes do; a scene that
  /// ignores it only draws more). Empty (skip_x1 <= skip_x0) by default.
  double skip_x0 = 0, skip_y0 = 0, skip_x1 = 0, skip_y1 = 0;
  [[nodiscard]] static View full(int w, int h) {
    return View{0, 0, double(w), double(h), w, h, 1.0};
  }
};

struct SceneInfo {
  std::string name;
  std::string description;
  bool has_meshes = false;     ///< rasterised geometry with a G-buffer prepass
  bool has_mesh_lods = false;  ///< discrete LODs selectable per draw (lodmask)
  size_t triangles = 0;        ///< at full detail
};

class Scene {
 public:
  virtual ~Scene() = default;
  [[nodiscard]] virtual SceneInfo info() const = 0;

  /// GLSL pieces defining `vec4 scene_shade(vec2 screen_px)` and its uniforms;
  /// must not define main(). A piece is literal text when its text is set,
  /// otherwise an embedded file name resolved against shader_files() (and the
  /// gpu and scenes modules' files). A stable key for caching programs.
  /// A scene that filters its materials by how far apart its samples lie
  /// defines FOVEATE_FOOTPRINT and a global `float foveate_footprint_px`
  /// (scenes/shaders/footprint.glsl): every shading pass then sets it, before
  /// each scene_shade, to the spacing of its samples on the screen in pixels
  /// (1 at native sampling; hardware VRS's coarse fragments also see 1).
  [[nodiscard]] virtual std::vector<gpu::StageSource::Piece> shade_source() const = 0;
  [[nodiscard]] virtual std::string shade_key() const = 0;
  /// Extra embedded files that the scene's GLSL includes (user scenes).
  [[nodiscard]] virtual std::vector<std::span<const embedded::EmbeddedFile>> shader_files() const {
    return {};
  }

  /// Advances the scene to this frame (camera, animation).
  virtual void update(const FrameInput& frame) = 0;

  /// Geometry prepass for `view`. The default does begin + draw(-1) + end.
  virtual void prepass(const View& view);
  /// Fine-grained prepass for techniques that mask geometry (lodmask):
  /// begin binds the G-buffer framebuffer (with a depth-stencil attachment) at
  /// the view's size and clears it; draw rasterises the geometry with the
  /// scene's automatic LOD (by distance and view.pixel_scale) when `lod` is
  /// -1 or 0, and at least as coarse as discrete level `lod` (1 about 10 %, 2
  /// about 1 % of the triangles) otherwise, with the depth test it needs and
  /// the stencil state the caller set (a `view` whose rectangle lies within
  /// begin's culls the geometry to that rectangle, still drawn with begin's
  /// projection: lodmask's finer LODs); end restores the framebuffer binding
  /// and viewport that begin found. No-ops for screen-space scenes.
  virtual void prepass_begin(const View& view);
  virtual void prepass_draw(const View& view, int lod);
  virtual void prepass_end();

  /// Binds uniforms and textures of the shading function on `program` for a
  /// pass over `view` (the same view as the last prepass); textures take
  /// their units from `samplers`, and the technique's take the next ones.
  virtual void bind(const gpu::Program& program, const View& view, gpu::Samplers& samplers) = 0;

  /// Screen positions (pixels, origin top-left) of the scene's objects at the
  /// current frame, nearest first; empty when the scene has no objects. For
  /// an eye of a stereo pair (FrameInput::eye), as seen from midway between
  /// the eyes with the eye's focal length and the axis at the image centre.
  [[nodiscard]] virtual std::vector<Vec2d> object_positions() const { return {}; }

  /// For temporal reverse reprojection: the full frame's view-projection
  /// matrix at the current frame (column-major), when the scene has a 3D
  /// camera and depth. A scene that returns one also defines, in its shading
  /// GLSL, `vec3 scene_world_position(vec2 screen_px)`: the world point seen
  /// there in the last prepass (a far point along the ray for background).
  [[nodiscard]] virtual std::optional<std::array<float, 16>> view_projection() const {
    return std::nullopt;
  }

  /// A value that changes whenever the image could (camera, animation, size,
  /// mouse) at the current frame: a temporal technique compares it across
  /// its own frames and keeps accumulating samples without reprojection while
  /// it stays the same. Empty, the default, means "unknown: assume it changed".
  [[nodiscard]] virtual std::optional<std::uint64_t> image_key() const { return std::nullopt; }
};

/// Folds `bytes` into an FNV-1a hash (for image_key()).
std::uint64_t hash_bytes(std::uint64_t hash, const void* bytes, std::size_t size);

/// The scenes module's embedded GLSL files (shade_source() names resolve here).
std::span<const embedded::EmbeddedFile> scene_shader_files();

/// Built-in scene names and one-line descriptions.
struct SceneListing {
  std::string name;
  std::string description;
};
std::vector<SceneListing> builtin_scenes();

/// Shadertoy's iDate (year, month from 0, day, seconds since midnight): a
/// fixed start that the scene clock advances (frame k at time t shows the
/// start plus t seconds), or the real local clock.
struct ShadertoyDate {
  int year = 2026;
  int month = 1;  ///< 1-12 (iDate.y holds month - 1, as JavaScript's getMonth)
  int day = 1;
  double seconds = 0.0;  ///< time of day
  bool real_clock = false;
};
/// "now" (the real clock), "YYYY-MM-DD" or "YYYY-MM-DDTHH:MM[:SS]" (also with
/// a space for the T); throws foveate::Error naming the text otherwise.
ShadertoyDate parse_shadertoy_date(const std::string& text);
/// iDate for a frame at scene time `time_s`.
std::array<float, 4> shadertoy_idate(const ShadertoyDate& date, double time_s);

struct SceneOptions {
  std::vector<std::string> channels;  ///< iChannel0..3 image files (Shadertoy scenes)
  std::string camera_path;            ///< keyframes JSON; empty = the scene's default
  /// Mesh files: "y" or "z" overrides the up axis; empty = the file's
  /// metadata (assimp's UpAxis), else Y.
  std::string up;
  /// Mesh files: refuse a model whose declared size would need more bytes
  /// than this to import; 0 = half the machine's memory.
  std::uint64_t model_memory_limit = 0;
  /// iDate of Shadertoy scenes; by default 2026-01-01 00:00 (deterministic).
  ShadertoyDate date;
  /// Where load_scene's warnings go (a Shadertoy channel sampled but bound to
  /// nothing, an ignored directive, a mesh file's repaired faces), each
  /// distinct one once per load; unset: "foveate: warning: ..." on stderr,
  /// each distinct one once per process.
  std::function<void(const std::string&)> warning;
};

/// The MSAA sample counts (above 1) a mesh scene's G-buffer can have on the
/// current GL implementation, highest first: those every attachment's format
/// supports. Needs a current context.
std::vector<int> gbuffer_sample_counts();

/// A built-in scene by name, or a file: .glsl/.frag (Shadertoy), .json (a
/// multipass Shadertoy project, docs/shadertoy.md) or a mesh file assimp reads. Needs a current GL
/// context. Throws foveate::Error with the file and the reason for bad input.
std::unique_ptr<Scene> load_scene(const std::string& name_or_path,
                                  const SceneOptions& options = {});

}  // namespace foveate
