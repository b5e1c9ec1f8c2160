// layered: Guenter, Finch, Drucker, Tan, Snyder, "Foveated 3D Graphics" (2012),
// section 4. Nested eccentricity layers from the planner, each rendered with
// an off-centre sub-frustum around the gaze at its sampling factor, bilinearly
// upsampled and composited with smoothstep masks; with half_rate, outer layers
// are updated at half rate, staggered (the paper's; off by default).
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
#include "layered.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "../registry/registry.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/parse.hpp"

namespace foveate::tech {

namespace layered {

namespace {

// Radical inverse in base b of i >= 1: a low-discrepancy sequence in (0, 1).
double halton(int i, int b) {
  double f = 1.0, r = 0.0;
  for (int k = i; k > 0; k /= b) {
    f /= b;
    r += f * (k % b);
  }
  return r;
}

}  // namespace

Layered::Layered(const TechniqueConfig& c, const ParamValues& v)
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
  if (v.real("s2") > 0.0) po.fixed_s2 = v.real("s2");
  try {
    plan_ = plan_layers(display_, c.acuity, po);
  } catch (const Error& e) {
    if (!po.fixed_s2) throw;
    throw Error("layered parameter s2=" + format_number(*po.fixed_s2) + ": " + e.what());
  }
  if (msaa_ > 1) check_msaa(msaa_);
}

// The declared range (1..8) is what the paper's hardware had; the G-buffer
// can take only what this GL implementation supports (GL_SAMPLES of its
// formats; a count between two supported ones is rounded up by GL), checked
// here rather than failing as an incomplete framebuffer.
void Layered::check_msaa(int samples) {
  const std::vector<int> ok = gbuffer_sample_counts();
  const int most = ok.empty() ? 1 : *std::max_element(ok.begin(), ok.end());
  if (samples <= most) return;
  const auto* r = glGetString(GL_RENDERER);
  throw Error("layered parameter msaa=" + std::to_string(samples) + ": " +
              (r ? reinterpret_cast<const char*>(r) : "this GL implementation") +
              " supports G-buffer MSAA of at most " + std::to_string(most) + " samples");
}

int Layered::slots(size_t i) const {
  const double s = plan_.layers[i].sampling_factor;
  if (!jitter_ || s <= 1.0) return 1;
  if (samples_ > 0) return samples_;
  // As many samples as native pixels under a layer pixel: the converged
  // layer has native's sample density.
  return std::clamp(static_cast<int>(std::ceil(s * s - 1e-9)), 2, kMaxSlots);
}

Layered::InnerSize Layered::inner_size(size_t i, const GazeState& g) const {
  const Layer& L = plan_.layers[i];
  const double e = L.radius_deg * g.fovea_scale + latency_travel_deg(g);
  const double r = display_.radius_px_at(e);
  const int side =
      std::max(1, static_cast<int>(std::ceil(2.0 * r * (1 + transition_) / L.sampling_factor)));
  return {r, 0.5 * side * L.sampling_factor, side};
}

FrameStats Layered::render(Scene& scene, const FrameInput& frame, const GazeState& gaze,
                           const gpu::RenderTarget& target) {
  FrameFacts f;
  f.width = target.width();
  f.height = target.height();
  f.gaze = to_gl(gaze.gaze_px, f.height);
  f.image_key = scene.image_key();
  f.can_reproject = reproject_ && scene.view_projection().has_value();
  FrameStats stats;
  stats.native_pixels = double(f.width) * f.height;
  std::vector<PixelCount> shaded(plan_.layers.size());
  for (size_t i = 0; i < plan_.layers.size(); ++i) {
    const bool update = updates_now(i, frame, f);
    state_[i].updated = update;
    if (update) shaded[i] = render_layer(scene, i, gaze, f);
  }
  composite(scene, target);
  // Read once the frame's last pass is sent (PixelCount).
  for (size_t i = 0; i < shaded.size(); ++i) {
    const double px = shaded[i].read();
    stats.parts.push_back({"layer " + std::to_string(i + 1), px});
    stats.shaded_pixels += px;
  }
  ++frames_;
  return stats;
}

bool Layered::updates_now(size_t i, const FrameInput& frame, const FrameFacts& f) const {
  const LayerState& st = state_[i];
  // Staggered half rate: layer 2 (middle) on even frames, 3 (outer) on odd,
  // and so on. A layer is shown stale only where it still lines up with this
  // frame: warped to the camera (mesh scenes), or an image that has not
  // changed since it was rendered. A moving image without camera and depth
  // (Shadertoy scenes) would show a periphery a frame behind
  // (docs/fidelity.md): there every layer updates every frame.
  const bool stale_lines_up = f.can_reproject || (f.image_key && f.image_key == st.image_key);
  // A layer rendered with a hole (render_layer) may be shown stale only while
  // the inner layer still covers the hole.
  const LayerState* inner = i > 0 ? &state_[i - 1] : nullptr;
  const bool hole_uncovered =
      st.hole_px > 0.0 && inner &&
      (inner->centre.x != st.hole_centre.x || inner->centre.y != st.hole_centre.y ||
       inner->radius_px < st.hole_from_px);
  return i == 0 || !half_rate_ || frames_ == 0 || !st.valid || !stale_lines_up || hole_uncovered ||
         (frame.frame % 2) == static_cast<int>((i + 1) % 2);
}

PixelCount Layered::render_layer(Scene& scene, size_t i, const GazeState& gaze,
                                 const FrameFacts& f) {
  const size_t n = plan_.layers.size();
  const Layer& L = plan_.layers[i];
  LayerState& st = state_[i];
  const double s = L.sampling_factor;
  View v;  // unjittered
  // Geometric LOD: native's unless asked for. A coarser mesh moves
  // silhouettes and normals by more than the layer's MAR allows.
  const double lod_scale = layer_lod_ == 2 || (layer_lod_ == 1 && i + 1 == n) ? s : 1.0;
  v.pixel_scale = lod_scale;
  if (i + 1 < n) {
    const InnerSize sz = inner_size(i, gaze);
    // Origins on the native pixel grid: a layer at s = 1 samples exactly the
    // native pixel centres.
    v.x0 = std::round(f.gaze.x - sz.half_px);
    v.y0 = std::round(f.gaze.y - sz.half_px);
    v.x1 = v.x0 + 2.0 * sz.half_px;
    v.y1 = v.y0 + 2.0 * sz.half_px;
    v.target_width = v.target_height = sz.side;
    st.radius_px = sz.blend_from_px;
  } else {
    v = View{0, 0, double(f.width), double(f.height), L.width_px, L.height_px, lod_scale};
    st.radius_px = 0;
  }
  st.centre = f.gaze;
  const int slots_i = slots(i);
  const std::array<double, 4> rect{v.x0, v.y0, v.x1 - v.x0, v.y1 - v.y0};
  const bool moved = !st.valid || rect != st.rect || st.slot_count != slots_i ||
                     st.side != std::array<int, 2>{v.target_width, v.target_height};
  if (moved) st.updates = 0;
  const int phase = st.updates % slots_i;
  const bool same_image = !moved && f.image_key && f.image_key == st.image_key;
  // Jitter feeds the still image's ring, and reprojected history. Where the
  // image moves and history can only be found at the same screen position
  // (no camera and depth), it is noise (docs/fidelity.md).
  View jv = v;  // this update's samples
  if (slots_i > 1 && (same_image || f.can_reproject)) {
    const double jx = (halton(phase + 1, 2) - 0.5) * s, jy = (halton(phase + 1, 3) - 0.5) * s;
    jv.x0 += jx, jv.x1 += jx, jv.y0 += jy, jv.y1 += jy;
  }
  if (msaa_ > 1 && scene.info().has_meshes) jv.samples = msaa_;
  scene.prepass(jv);
  st.spare.ensure(v.target_width, v.target_height);
  st.spare.clear(0, 0, 0, 1);
  const bool stale_lines_up = f.can_reproject || (f.image_key && f.image_key == st.image_key);
  const std::vector<PixelRect> cover = shown_cover(i, v, !half_rate_ || !stale_lines_up, f);
  PixelCount shaded = kit_.shade(
      scene, jv, kMapRect, st.spare,
      [&](const gpu::Program& p, gpu::Samplers&) { set_rect_mapping(p, jv); }, {}, false, &cover);
  // A moving image with no history to reproject and none wanted at the same
  // screen position (history_screen 0): the samples are shown as rendered,
  // with no temporal pass.
  const bool plain = !same_image && !f.can_reproject && history_screen_ == 0;
  const bool temporal =
      !plain && (slots_i > 1 || (std::max(history_, history_screen_) > 0 && s > 1.0));
  if (temporal) accumulate(scene, st, jv, rect, slots_i, phase, same_image);
  keep_positions(scene, st, jv, rect, i > 0 && half_rate_);
  st.image_key = f.image_key;
  st.rect = rect;
  st.side = {v.target_width, v.target_height};
  st.slot_count = slots_i;
  st.temporal = temporal;
  ++st.updates;
  st.valid = true;
  return shaded;
}

// Only the part of the layer that the composite can show is shaded: an inner
// layer's disc out to the end of its blend band (not its square's corners),
// and, where this layer is rendered anew with the layer inside it every frame
// (no half rate, or an image that moves with no camera to warp by), not the
// disc inside that layer's radius, where it has no weight. Slack: the
// bilinear read and the jitter (2 layer pixels), and 3 layer pixels more at
// the hole for the temporal pass's neighbourhood. Nor what lies beyond the
// screen by more than 1.5 layer pixels (a layer's square reaching past an
// edge).
std::vector<PixelRect> Layered::shown_cover(size_t i, const View& v, bool every_frame,
                                            const FrameFacts& f) {
  const size_t n = plan_.layers.size();
  const double s = plan_.layers[i].sampling_factor;
  LayerState& st = state_[i];
  const LayerState* inner = i > 0 ? &state_[i - 1] : nullptr;
  st.hole_px = 0.0;
  if (inner && inner->updated && every_frame) {
    st.hole_px = std::max(0.0, inner->radius_px - 5.0 * s);
    st.hole_centre = inner->centre;
    st.hole_from_px = inner->radius_px;
  }
  const double outer_px = i + 1 < n
                              ? st.radius_px * (1.0 + std::max(0.0, transition_)) + 2.0 * s + 1.0
                              : std::numeric_limits<double>::infinity();
  // In the layer's pixels (GL, origin at its lower-left corner).
  const std::vector<PixelRect> cover =
      annulus_rects((f.gaze.x - v.x0) / s, (f.gaze.y - v.y0) / s, st.hole_px / s, outer_px / s,
                    v.target_width, v.target_height);
  const double past_edge_px = 1.5 * s;
  const PixelRect keep{pixel_index(std::floor((-past_edge_px - v.x0) / s)),
                       pixel_index(std::floor((-past_edge_px - v.y0) / s)),
                       pixel_index(std::ceil((f.width + past_edge_px - v.x0) / s)) + 1,
                       pixel_index(std::ceil((f.height + past_edge_px - v.y0) / s)) + 1};
  return clip_rects(cover, keep);
}

std::string Layered::layer_label(size_t i) const {
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

std::vector<OverlayShape> Layered::overlay(const GazeState& gaze) const {
  std::vector<OverlayShape> out;
  for (size_t i = 0; i + 1 < plan_.layers.size(); ++i) {
    const InnerSize sz = inner_size(i, gaze);
    const auto* c = kRingColours[i];
    const std::string layer = layer_label(i);
    out.push_back({OverlayShape::Kind::Rect, gaze.gaze_px.x - sz.half_px,
                   gaze.gaze_px.y - sz.half_px, 2 * sz.half_px, 2 * sz.half_px, c[0], c[1], c[2],
                   layer + ": its render target"});
    out.push_back({OverlayShape::Kind::Circle, gaze.gaze_px.x, gaze.gaze_px.y, sz.blend_from_px, 0,
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

std::vector<std::pair<std::string, double>> Layered::derived() const {
  std::vector<std::pair<std::string, double>> v;
  for (size_t i = 0; i < plan_.layers.size(); ++i) {
    const std::string k = "layer" + std::to_string(i + 1);
    v.emplace_back(k + ".radius_deg", plan_.layers[i].radius_deg);
    v.emplace_back(k + ".sampling_factor", plan_.layers[i].sampling_factor);
    v.emplace_back(k + ".temporal_samples", slots(i));
  }
  return v;
}
}  // namespace layered

TechniqueInfo layered_info() {
  TechniqueInfo t;
  t.name = "layered";
  t.summary =
      "Nested eccentricity layers from the acuity model, composited with smoothstep masks outside "
      "each layer's radius; per-layer jitter with temporal accumulation and reprojection; the "
      "paper's half-rate outer layers on request.";
  t.source = "Guenter et al., Foveated 3D Graphics, 2012";
  t.params = {
      plan_margin_param(1.5),
      tuned(param("layers", "number of layers n (1 = native)", "", ParamType::Integer, 1,
                  layered::kMaxLayers, 2),
            {2, 3, 4}),
      param("s2",
            "sampling factor of the second layer, fixed (the paper's 3* plan fixes it at 2): the "
            "first layer then ends where the planned MAR reaches it, and the optimiser places any "
            "further layers; 0 = chosen by the optimiser with the rest",
            "", ParamType::Real, 0.0, 8.0, 0.0),
      tuned(
          param(
              "transition",
              "width of the smoothstep blend band outside each inner layer's radius, as a fraction "
              "of that radius (the inner layer is rendered out to its end)",
              "", ParamType::Real, 0, 1, 0.2),
          {0.1, 0.2, 0.4}),
      tuned(param("half_rate",
                  "update outer layers at half rate, staggered, where a stale layer still lines up "
                  "(warped to the camera on mesh scenes, or a still image); a moving image without "
                  "camera and depth updates every layer every frame",
                  "", ParamType::Boolean, 0, 1, 0),
            {0, 1}),
      param("jitter", "jitter subsampled layers over their own updates (Halton 2, 3)", "",
            ParamType::Boolean, 0, 1, 1),
      param("samples",
            "jitter positions per subsampled layer pixel, averaged while the image holds still (0 "
            "= from the sampling factor: ceil(s^2), 2..32: native's sample density once converged)",
            "", ParamType::Integer, 0, layered::kMaxSlots, 0),
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
  t.check = [](const ParamValues& v) {
    const double s2 = v.real("s2");
    if (s2 > 0.0 && s2 < 1.0)
      throw Error("layered parameter s2 must be 0 (the optimiser's) or at least 1, got " +
                  format_number(s2));
    if (s2 > 0.0 && v.integer("layers") < 2)
      throw Error("layered parameter s2 needs layers >= 2 (one layer is native)");
  };
  t.resolve_passes = {"temporal", "temporal_reproject", "copy",
                      "warp",     "composite",          "composite_one"};
  t.make = construct<layered::Layered>();
  return t;
}

}  // namespace foveate::tech
