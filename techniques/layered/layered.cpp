// layered: Guenter, Finch, Drucker, Tan, Snyder, "Foveated 3D Graphics" (2012),
// section 4. Nested eccentricity layers from the planner, each rendered with
// an off-centre sub-frustum around the gaze at its sampling factor, bilinearly
// upsampled and composited with smoothstep masks; outer layers are updated at
// half rate, staggered.
//
// Antialiasing (section 4.2), in linear light:
//  * each subsampled layer is jittered over its own updates by a Halton (2, 3)
//    sequence of N positions covering the whole layer pixel (N = ceil(s^2),
//    at most 32: converged, the layer has native's sample density);
//  * the layer's history lives on its unjittered grid. While the scene's
//    image and the layer's rectangle stay the same, the last N jittered
//    samples of a pixel are averaged (a box filter over its footprint that
//    converges exactly: the same N samples, the same mean); a sample that
//    differs from the one of the same phase a cycle ago restarts the pixel.
//    When anything moves, the history is reprojected (through the scene's depth
//    and previous camera where it has them), clipped to the current samples'
//    neighbourhood in YCoCg (variance clipping) and blended exponentially;
//  * a coarser layer only shows where its sampling meets the acuity model:
//    inner layers are rendered beyond their planned radius e_i by the blend
//    band, and the blend runs from e_i outwards. The planner weighs the inner
//    layers' pixels by what that band costs, so the radii are re-planned for it.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>

#include "../common/registry.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/planner.hpp"
#include "foveate/gpu/profiler.hpp"
#include "foveate/techniques/depth_regions.hpp"
#include "foveate/techniques/pass_kit.hpp"

namespace foveate::tech {

namespace {

constexpr int kMaxLayers = 6;
constexpr int kMaxSlots = 32;
constexpr GLenum kDisplayFormat = GL_RGBA16F;  // precision for the exponential blend

// Radical inverse in base b of i >= 1: a low-discrepancy sequence in (0, 1).
double halton(int i, int b) {
  double f = 1.0, r = 0.0;
  for (int k = i; k > 0; k /= b) {
    f /= b;
    r += f * (k % b);
  }
  return r;
}

class Layered final : public Technique {
 public:
  Layered(const TechniqueConfig& c, const ParamValues& v)
      : display_(c.display),
        transition_(v.real("transition")),
        half_rate_(v.boolean("half_rate")),
        jitter_(v.boolean("jitter")),
        samples_(v.integer("samples")),
        history_(v.real("history")),
        history_screen_(v.real("history_screen")),
        reproject_(v.boolean("reproject")),
        msaa_(v.integer("msaa")),
        layer_lod_(v.integer("lod")) {
    PlannerOptions po;
    po.layers = v.integer("layers");
    po.grid_step_deg = v.real("grid_step");
    // Inner layers are rendered out to (1 + transition) of their radius: the
    // planner weighs their pixels by the area that adds.
    po.weights.assign(static_cast<size_t>(po.layers), (1 + transition_) * (1 + transition_));
    po.weights.back() = 1.0;
    plan_ = plan_layers(display_, c.acuity, po);
    if (msaa_ > 1) check_msaa(msaa_);
  }

  /// The declared range (1..8) is what the paper's hardware had; the G-buffer
  /// can take only what this GL implementation supports (GL_SAMPLES of its
  /// formats; a count between two supported ones is rounded up by GL), checked
  /// here rather than failing as an incomplete framebuffer.
  static void check_msaa(int samples) {
    const std::vector<int> ok = gbuffer_sample_counts();
    const int most = ok.empty() ? 1 : *std::max_element(ok.begin(), ok.end());
    if (samples <= most) return;
    const auto* r = glGetString(GL_RENDERER);
    throw Error("layered parameter msaa=" + std::to_string(samples) + ": " +
                (r ? reinterpret_cast<const char*>(r) : "this GL implementation") +
                " supports G-buffer MSAA of at most " + std::to_string(most) + " samples");
  }

  void reset() override {
    frames_ = 0;
    for (LayerState& st : state_) st.valid = false;
  }

  // Temporal samples (jitter positions) per pixel of layer i.
  int slots(size_t i) const {
    const double s = plan_.layers[i].sampling_factor;
    if (!jitter_ || s <= 1.0) return 1;
    if (samples_ > 0) return samples_;
    // As many samples as native pixels under a layer pixel: the converged
    // layer has native's sample density.
    return std::clamp(static_cast<int>(std::ceil(s * s - 1e-9)), 2, kMaxSlots);
  }

  // Blend radius (where the coarser layer starts to show: e_i, native pixels)
  // and the rendered half side and target side of inner layer i for this gaze.
  struct InnerSize {
    double blend_from = 0;  ///< e_i on screen
    double half = 0;        ///< rendered half side, >= blend_from * (1 + transition)
    int side = 1;           ///< target pixels per side
  };
  InnerSize inner_size(size_t i, const GazeState& g) const {
    const Layer& L = plan_.layers[i];
    const double e = L.radius_deg * g.fovea_scale + latency_margin_deg(g);
    const double r = display_.radius_px_at(e);
    const int side =
        std::max(1, static_cast<int>(std::ceil(2.0 * r * (1 + transition_) / L.sampling_factor)));
    return {r, 0.5 * side * L.sampling_factor, side};
  }

  FrameStats render(Scene& scene, const FrameInput& frame, const GazeState& gaze,
                    const gpu::RenderTarget& target) override {
    const int W = target.width(), H = target.height();
    const size_t n = plan_.layers.size();
    const Vec2d g = to_gl(gaze.gaze_px, H);
    const std::optional<std::uint64_t> key = scene.image_key();
    const bool can_reproject = reproject_ && scene.view_projection().has_value();
    FrameStats stats;
    stats.native_pixels = double(W) * H;
    for (size_t i = 0; i < n; ++i) {
      const Layer& L = plan_.layers[i];
      LayerState& st = state_[i];
      // Staggered half rate: layer 2 (middle) on even frames, 3 (outer) on odd,
      // and so on. A layer is shown stale only where it still lines up with
      // this frame: warped to the camera (mesh scenes), or an image that has
      // not changed since it was rendered. A moving image without camera and
      // depth (Shadertoy scenes) would show a periphery a frame behind (2.01
      // codes on raymarch against 1.49 at full rate): there every layer
      // updates every frame.
      const bool stale_lines_up = can_reproject || (key && key == st.image_key);
      // A layer rendered with a hole (below) may be shown stale only while
      // the inner layer still covers the hole.
      const LayerState* inner = i > 0 ? &state_[i - 1] : nullptr;
      const bool hole_uncovered =
          st.hole > 0.0 && inner &&
          (inner->centre.x != st.hole_centre.x || inner->centre.y != st.hole_centre.y ||
           inner->radius < st.hole_from);
      const bool update = i == 0 || !half_rate_ || frames_ == 0 || !st.valid || !stale_lines_up ||
                          hole_uncovered || (frame.frame % 2) == static_cast<int>((i + 1) % 2);
      st.updated = update;
      if (!update) {
        stats.parts.push_back({"layer " + std::to_string(i + 1), 0.0});
        continue;
      }
      const double s = L.sampling_factor;
      View v;  // unjittered
      // Geometric LOD: native's unless asked for. A coarser mesh moves
      // silhouettes and normals by more than the layer's MAR allows.
      const double lod_scale = layer_lod_ == 2 || (layer_lod_ == 1 && i + 1 == n) ? s : 1.0;
      v.pixel_scale = lod_scale;
      if (i + 1 < n) {
        const InnerSize sz = inner_size(i, gaze);
        // Origins on the native pixel grid: a layer at s = 1 samples exactly
        // the native pixel centres.
        v.x0 = std::round(g.x - sz.half);
        v.y0 = std::round(g.y - sz.half);
        v.x1 = v.x0 + 2.0 * sz.half;
        v.y1 = v.y0 + 2.0 * sz.half;
        v.target_width = v.target_height = sz.side;
        st.radius = sz.blend_from;
      } else {
        v = View{0, 0, double(W), double(H), L.width_px, L.height_px, lod_scale};
        st.radius = 0;
      }
      st.centre = g;
      const int slots_i = slots(i);
      const std::array<double, 4> rect{v.x0, v.y0, v.x1 - v.x0, v.y1 - v.y0};
      const bool moved = !st.valid || rect != st.rect || st.slot_count != slots_i ||
                         st.side != std::array<int, 2>{v.target_width, v.target_height};
      if (moved) st.updates = 0;
      const int phase = st.updates % slots_i;
      const bool same_image = !moved && key && key == st.image_key;
      // Jitter feeds the still image's ring, and reprojected history. Where
      // the image moves and history can only be found at the same screen
      // position (no camera and depth), it is noise: 2.64 -> 2.41 codes on
      // raymarch without it.
      View jv = v;  // this update's samples
      if (slots_i > 1 && (same_image || can_reproject)) {
        const double jx = (halton(phase + 1, 2) - 0.5) * s, jy = (halton(phase + 1, 3) - 0.5) * s;
        jv.x0 += jx, jv.x1 += jx, jv.y0 += jy, jv.y1 += jy;
      }
      if (msaa_ > 1 && scene.info().has_meshes) jv.samples = msaa_;
      scene.prepass(jv);
      st.spare.ensure(v.target_width, v.target_height);
      st.spare.clear(0, 0, 0, 1);
      // Only the part of the layer that the composite can show is shaded: an
      // inner layer's disc out to the end of its blend band (not its
      // square's corners), and, where this layer is rendered anew with the
      // layer inside it every frame (no half rate, or an image that moves
      // with no camera to warp by), not the disc inside that layer's radius,
      // where it has no weight. Margins: the bilinear read and the jitter
      // (2 layer pixels), and 3 layer pixels more at the hole for the
      // temporal pass's neighbourhood. Nor what lies beyond the screen by
      // more than 1.5 layer pixels (a layer's square reaching past an edge).
      const bool every_frame = !half_rate_ || !stale_lines_up;
      st.hole = 0.0;
      if (inner && inner->updated && every_frame) {
        st.hole = std::max(0.0, inner->radius - 5.0 * s);
        st.hole_centre = inner->centre;
        st.hole_from = inner->radius;
      }
      const double outer = i + 1 < n
                               ? st.radius * (1.0 + std::max(0.0, transition_)) + 2.0 * s + 1.0
                               : std::numeric_limits<double>::infinity();
      // In the layer's pixels (GL, origin at its lower-left corner).
      std::vector<PixelRect> cover = annulus_rects((g.x - v.x0) / s, (g.y - v.y0) / s, st.hole / s,
                                                   outer / s, v.target_width, v.target_height);
      const double margin = 1.5 * s;
      const PixelRect keep{pixel_index(std::floor((-margin - v.x0) / s)),
                           pixel_index(std::floor((-margin - v.y0) / s)),
                           pixel_index(std::ceil((W + margin - v.x0) / s)) + 1,
                           pixel_index(std::ceil((H + margin - v.y0) / s)) + 1};
      cover = clip_rects(cover, keep);
      const double shaded = kit_.shade(
          scene, jv, kMapRect, st.spare,
          [&](const gpu::Program& p, gpu::Samplers&) { set_rect_mapping(p, jv); }, {}, false,
          &cover);
      stats.parts.push_back({"layer " + std::to_string(i + 1), shaded});
      stats.shaded_pixels += shaded;
      // A moving image with no history to reproject and none wanted at the
      // same screen position (history_screen 0): the samples are shown as
      // rendered, with no temporal pass.
      const bool plain = !same_image && !can_reproject && history_screen_ == 0;
      const bool temporal =
          !plain && (slots_i > 1 || (std::max(history_, history_screen_) > 0 && s > 1.0));
      if (temporal) accumulate(scene, st, jv, rect, slots_i, phase, same_image);
      keep_positions(scene, st, jv, rect, i > 0 && half_rate_);
      st.image_key = key;
      st.rect = rect;
      st.side = {v.target_width, v.target_height};
      st.slot_count = slots_i;
      st.temporal = temporal;
      ++st.updates;
      st.valid = true;
    }
    composite(scene, target);
    ++frames_;
    return stats;
  }

  // A half-rate layer is first rendered, then rendered with history to
  // reproject, then shown stale and warped: both phases, twice.
  [[nodiscard]] int settle_frames() const override { return half_rate_ ? 6 : 3; }

  std::string layer_label(size_t i) const {
    char s[96];
    const Layer& l = plan_.layers[i];
    if (l.sampling_factor <= 1.0) {
      std::snprintf(s, sizeof s, "layer %zu (native, to %.1f deg)", i + 1, l.radius_deg);
    } else {
      std::snprintf(s, sizeof s, "layer %zu (%.2fx coarser pixels, to %.1f deg)", i + 1,
                    l.sampling_factor, l.radius_deg);
    }
    return s;
  }

  std::vector<OverlayShape> overlay(const GazeState& gaze) const override {
    std::vector<OverlayShape> out;
    for (size_t i = 0; i + 1 < plan_.layers.size(); ++i) {
      const InnerSize sz = inner_size(i, gaze);
      const auto* c = kRingColours[i];
      const std::string layer = layer_label(i);
      out.push_back({OverlayShape::Kind::Rect, gaze.gaze_px.x - sz.half, gaze.gaze_px.y - sz.half,
                     2 * sz.half, 2 * sz.half, c[0], c[1], c[2], layer + ": its render target"});
      out.push_back({OverlayShape::Kind::Circle, gaze.gaze_px.x, gaze.gaze_px.y, sz.blend_from, 0,
                     c[0], c[1], c[2], layer + ": blends into the next layer from this ring"});
    }
    const size_t last = plan_.layers.size() - 1;
    const auto* c = kRingColours[last];
    out.push_back(
        {OverlayShape::Kind::Rect, 1, 1, display_.width_px - 2.0, display_.height_px - 2.0, c[0],
         c[1], c[2],
         layer_label(last) + ": the whole frame" + (half_rate_ && last > 0 ? ", half rate" : "")});
    out.push_back(gaze_dot(gaze));
    return out;
  }

 protected:
  std::vector<std::pair<std::string, double>> derived() const override {
    std::vector<std::pair<std::string, double>> v;
    for (size_t i = 0; i < plan_.layers.size(); ++i) {
      const std::string k = "layer" + std::to_string(i + 1);
      v.emplace_back(k + ".radius_deg", plan_.layers[i].radius_deg);
      v.emplace_back(k + ".sampling_factor", plan_.layers[i].sampling_factor);
      v.emplace_back(k + ".temporal_samples", slots(i));
    }
    return v;
  }

 private:
  struct LayerState {
    // This update's render, and the last N, one per jitter phase (layer j of
    // the array = phase j), into which it is copied after the temporal pass.
    gpu::RenderTarget spare;
    gpu::Texture ring;
    // The resolved layer (rgb, linear) and the pixel's count of consecutive
    // same-image samples (a), on the unjittered grid.
    std::array<gpu::RenderTarget, 2> display;
    int latest = 0;
    int updates = 0;  // since the rectangle last changed: the jitter phase is updates % N
    int slot_count = 0;
    bool valid = false;
    bool temporal = false;
    std::array<double, 4> rect{};  // unjittered x0, y0, w, h of the newest display
    std::array<int, 2> side{};
    Vec2d centre{};     // gaze of the newest render (GL pixels)
    double radius = 0;  // where the blend to the next layer starts (native pixels)
    std::optional<std::uint64_t> image_key;
    bool has_view_proj = false;
    std::array<float, 16> view_proj{};  // the scene camera of the newest render
    // The world points of the newest render (mesh scenes), to reproject the
    // layer on the frames it is not updated.
    gpu::RenderTarget positions;
    bool has_positions = false;
    gpu::RenderTarget warped;  // the display moved to this frame's camera (when stale)
    bool updated = false;      // this frame
    // The disc (screen pixels) left unshaded in the newest render, inside the
    // inner layer's radius `hole_from` around `hole_centre`; 0 = none.
    double hole = 0, hole_from = 0;
    Vec2d hole_centre{};
  };

  // Resolves this update's samples (st.spare, taken at jittered view `jv`)
  // with the layer's history into st.display, then files them in the ring.
  void accumulate(Scene& scene, LayerState& st, const View& jv, const std::array<double, 4>& rect,
                  int slots_i, int phase, bool same_image) {
    const int next = 1 - st.latest;
    gpu::RenderTarget& out = st.display[static_cast<size_t>(next)];
    out.ensure(jv.target_width, jv.target_height, kDisplayFormat);
    if (!st.ring || st.ring.width() != jv.target_width || st.ring.height() != jv.target_height ||
        st.ring.layers() != slots_i) {
      st.ring = gpu::Texture::create_2d_array(GL_SRGB8_ALPHA8, jv.target_width, jv.target_height,
                                              slots_i);
    }
    const bool have_history = st.valid && st.temporal;
    const auto vp = scene.view_projection();
    const bool reproject = have_history && reproject_ && vp && st.has_view_proj;
    const auto& prev = have_history ? st.rect : rect;
    const auto set = [&](const gpu::Program& p, gpu::Samplers& samplers) {
      samplers.bind(p, "u_sample", st.spare.color());
      samplers.bind(
          p, "u_prev",
          have_history ? st.display[static_cast<size_t>(st.latest)].color() : st.spare.color());
      samplers.bind(p, "u_ring", st.ring);
      p.set("u_slot_count", slots_i);
      p.set("u_phase", phase);
      p.set("u_have_history", have_history ? 1 : 0);
      p.set("u_same_image", same_image ? 1 : 0);
      p.set("u_rect", float(rect[0]), float(rect[1]), float(rect[2]), float(rect[3]));
      p.set("u_prev_rect", float(prev[0]), float(prev[1]), float(prev[2]), float(prev[3]));
      // Without the scene's camera and depth the history is found at the
      // same screen position and trails the motion: it gets less weight.
      p.set("u_blend", float(1.0 - (reproject ? history_ : history_screen_)));
      if (reproject) {
        p.set_mat4("u_view_proj", vp->data());
        p.set_mat4("u_prev_view_proj", st.view_proj.data());
        p.set("u_frame_size", float(display_.width_px), float(display_.height_px));
      }
    };
    if (reproject) {
      kit_.scene_pass(scene, jv,
                      kit_.scene_program(scene, "layered/temporal_reproject.frag", jv.samples), out,
                      {}, set);
    } else {
      kit_.pass(kit_.fullscreen("layered/temporal.frag"), out, {}, set);
    }
    st.has_view_proj = vp.has_value();
    if (vp) st.view_proj = *vp;
    st.latest = next;
    const gpu::ProfileScope timed("copy");
    glCopyImageSubData(st.spare.color().id(), GL_TEXTURE_2D, 0, 0, 0, 0, st.ring.id(),
                       GL_TEXTURE_2D_ARRAY, 0, 0, 0, phase, jv.target_width, jv.target_height, 1);
  }

  // Stores the world points of the layer's grid where it will be shown stale.
  void keep_positions(Scene& scene, LayerState& st, const View& jv,
                      const std::array<double, 4>& rect, bool will_be_stale) {
    const auto vp = scene.view_projection();
    st.has_positions = will_be_stale && reproject_ && vp.has_value();
    if (!st.has_positions) return;
    st.view_proj = *vp;
    st.has_view_proj = true;
    st.positions.ensure(jv.target_width, jv.target_height, GL_RGBA32F);
    kit_.scene_pass(scene, jv, kit_.scene_program(scene, "layered/positions.frag", jv.samples),
                    st.positions, {}, [&](const gpu::Program& p, gpu::Samplers& samplers) {
                      samplers.bind(p, "u_sample", st.positions.color());
                      p.set("u_rect", float(rect[0]), float(rect[1]), float(rect[2]),
                            float(rect[3]));
                    });
  }

  void composite(Scene& scene, const gpu::RenderTarget& target) {
    const int n = static_cast<int>(plan_.layers.size());
    const auto vp = scene.view_projection();
    // Layers shown stale (half rate) move with the camera: each is warped to
    // this frame at its own resolution before the composite reads it.
    std::array<const gpu::Texture*, kMaxLayers> source{};
    for (int i = 0; i < n; ++i) {
      LayerState& st = state_[static_cast<size_t>(i)];
      // A layer without temporal resolve (the native-rate inner one) is its
      // last render; the others their resolved display.
      const gpu::RenderTarget& shown =
          st.temporal ? st.display[static_cast<size_t>(st.latest)] : st.spare;
      source[static_cast<size_t>(i)] = &shown.color();
      if (st.updated || !st.has_positions || !vp) continue;
      st.warped.ensure(shown.width(), shown.height(), kDisplayFormat);
      kit_.pass(kit_.fullscreen("layered/warp.frag"), st.warped, {},
                [&](const gpu::Program& p, gpu::Samplers& samplers) {
                  samplers.bind(p, "u_layer", shown.color());
                  samplers.bind(p, "u_positions", st.positions.color());
                  p.set("u_rect", float(st.rect[0]), float(st.rect[1]), float(st.rect[2]),
                        float(st.rect[3]));
                  p.set_mat4("u_layer_view_proj", st.view_proj.data());
                  p.set_mat4("u_view_proj", vp->data());
                  p.set("u_frame_size", float(display_.width_px), float(display_.height_px));
                });
      source[static_cast<size_t>(i)] = &st.warped.color();
    }
    auto set = [&](const gpu::Program& prog, gpu::Samplers& samplers) {
      float rects[kMaxLayers * 4] = {}, centres[kMaxLayers * 2] = {}, radii[kMaxLayers] = {};
      static const char* names[kMaxLayers] = {"u_layers[0]", "u_layers[1]", "u_layers[2]",
                                              "u_layers[3]", "u_layers[4]", "u_layers[5]"};
      for (int i = 0; i < n; ++i) {
        const LayerState& st = state_[static_cast<size_t>(i)];
        samplers.bind(prog, names[i], *source[static_cast<size_t>(i)]);
        for (int k = 0; k < 4; ++k) rects[i * 4 + k] = float(st.rect[static_cast<size_t>(k)]);
        centres[i * 2] = float(st.centre.x);
        centres[i * 2 + 1] = float(st.centre.y);
        radii[i] = float(st.radius);
      }
      glProgramUniform4fv(prog.id(), prog.uniform("u_rects[0]"), n, rects);
      glProgramUniform2fv(prog.id(), prog.uniform("u_centres[0]"), n, centres);
      glProgramUniform1fv(prog.id(), prog.uniform("u_radii[0]"), n, radii);
      prog.set("u_count", n);
      prog.set("u_first", 0);
      prog.set("u_band", float(transition_));
    };
    if (!DepthRegions::usable(target)) {
      // A target without a colour texture (a window's framebuffer): one pass
      // over every pixel, reading every layer.
      kit_.pass(kit_.fullscreen("layered/composite.frag"), target, {}, set);
      return;
    }
    // The regions, innermost first: within the inner layer's radius only that
    // layer shows (one read); the disc of layer k's blend band reads layers
    // k..n-1; outside every disc only the outer layer is read. A depth test
    // keeps each pixel to the first region that covers it (early, so
    // llvmpipe skips the 4x4 blocks already written).
    const gpu::ProfileScope timed("composite");
    const gpu::Program& prog = kit_.over_regions("layered/composite.frag");
    const bool inner = n > 1;
    regions_.begin(target, inner ? n + 1 : n);
    if (inner) {
      const gpu::Program& only = kit_.over_regions("layered/composite_inner.frag");
      const LayerState& st = state_[0];
      gpu::Samplers own;
      own.bind(only, "u_inner", *source[0]);
      only.set("u_inner_rect", float(st.rect[0]), float(st.rect[1]), float(st.rect[2]),
               float(st.rect[3]));
      regions_.disc(only, st.centre, st.radius - 1.0, true);
    }
    gpu::Samplers samplers;
    set(prog, samplers);
    for (int k = 0; k < n; ++k) {
      prog.set("u_first", k);
      const LayerState& st = state_[static_cast<size_t>(k)];
      if (k + 1 < n) {
        regions_.disc(prog, st.centre, st.radius * (1.0 + std::max(0.0, transition_)) + 1.0, false);
      } else {
        regions_.rest(prog);
      }
    }
  }

  DepthRegions regions_;

  Display display_;
  double transition_;
  bool half_rate_, jitter_;
  int samples_;
  double history_;
  double history_screen_;
  bool reproject_;
  int msaa_;
  int layer_lod_;
  LayerPlan plan_;
  PassKit kit_;
  std::array<LayerState, kMaxLayers> state_;
  int frames_ = 0;
};

}  // namespace

TechniqueInfo layered_info() {
  TechniqueInfo t;
  t.name = "layered";
  t.summary =
      "Nested eccentricity layers from the acuity model, composited with smoothstep masks outside "
      "each layer's radius; per-layer jitter with temporal accumulation and reprojection; outer "
      "layers at half rate.";
  t.source = "Guenter et al., Foveated 3D Graphics, 2012";
  t.params = {
      plan_margin_param(2.0),
      param("layers", "number of layers n (1 = native)", "", ParamType::Integer, 1, kMaxLayers, 3),
      param("transition",
            "width of the smoothstep blend band outside each inner layer's radius, as a fraction "
            "of that radius (the inner layer is rendered out to its end)",
            "", ParamType::Real, 0, 1, 0.2),
      param("half_rate",
            "update outer layers at half rate, staggered, where a stale layer still lines up "
            "(warped to the camera on mesh scenes, or a still image); a moving image without "
            "camera and depth updates every layer every frame",
            "", ParamType::Boolean, 0, 1, 1),
      param("jitter", "jitter subsampled layers over their own updates (Halton 2, 3)", "",
            ParamType::Boolean, 0, 1, 1),
      param("samples",
            "jitter positions per subsampled layer pixel, averaged while the image holds still (0 "
            "= from the sampling factor: ceil(s^2), 2..32: native's sample density once converged)",
            "", ParamType::Integer, 0, kMaxSlots, 0),
      param("history",
            "weight of the reprojected history when the image moves (1 - the new sample's weight)",
            "", ParamType::Real, 0, 0.95, 0.5),
      param("history_screen",
            "the same where history is not reprojected (reproject=0, or Shadertoy scenes, which "
            "have no camera and depth to reproject by): found at the same screen position, it "
            "trails the motion; at 0 a moving image's samples are shown as rendered, unjittered, "
            "with no temporal pass (a still image still converges)",
            "", ParamType::Real, 0, 0.95, 0.0),
      param("reproject",
            "reverse-reproject history through the scene camera and depth when the scene has them "
            "(0 = screen space)",
            "", ParamType::Boolean, 0, 1, 1),
      param("msaa",
            "MSAA samples of mesh scenes' layers (1 = off; 4 as in the paper; native has none, so "
            "off by default; at most what the GL implementation supports, checked at run time)",
            "samples", ParamType::Integer, 1, 8, 1),
      param("lod",
            "geometric LOD of mesh scenes' subsampled layers: 0 = native's in every layer; 1 = "
            "the outer layer's coarsened by its sampling factor (the paper coarsens only the outer "
            "layer); 2 = every subsampled layer's. Coarser meshes move silhouettes and bend "
            "normals by more than the MAR hides",
            "", ParamType::Integer, 0, 2, 0),
      param("grid_step", "planner search step", "deg", ParamType::Real, 0.01, 1.0, 0.05),
  };
  t.resolve_passes = {"temporal", "temporal_reproject", "copy",
                      "warp",     "composite",          "composite_inner"};
  t.make = construct<Layered>();
  return t;
}

}  // namespace foveate::tech
