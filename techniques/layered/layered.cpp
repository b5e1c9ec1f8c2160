// layered: Guenter, Finch, Drucker, Tan, Snyder, "Foveated 3D Graphics" (2012),
// section 4. Nested eccentricity layers from the planner, each rendered with
// an off-centre sub-frustum around the gaze at its sampling factor, jittered by
// up to half a layer pixel per frame, blended with its reprojected history,
// bilinearly upsampled and composited with smoothstep masks. Outer layers are
// updated at half rate, staggered.
#include <array>
#include <cmath>
#include <numbers>
#include <tuple>

#include "../common/kit.hpp"
#include "../common/registry.hpp"
#include "foveate/core/planner.hpp"

namespace foveate::tech {

namespace {

constexpr int kMaxLayers = 6;

// Radical inverse in base b: a low-discrepancy jitter sequence in [0, 1).
double halton(int i, int b) {
  double f = 1.0, r = 0.0;
  for (int k = i + 1; k > 0; k /= b) {
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
        history_(v.real("history")),
        reproject_(v.boolean("reproject")),
        msaa_(v.integer("msaa")) {
    PlannerOptions po;
    po.layers = v.integer("layers");
    po.grid_step_deg = v.real("grid_step");
    plan_ = plan_layers(display_, c.acuity, po);
  }

  void reset() override { frames_ = 0; }

  // On-screen half side (native pixels) and target side of inner layer i for this gaze.
  std::pair<double, int> inner_size(size_t i, const GazeState& g) const {
    const Layer& L = plan_.layers[i];
    const double e = L.radius_deg * g.fovea_scale + latency_margin_deg(g);
    if (e == L.radius_deg) return {0.5 * L.width_px * L.sampling_factor, L.width_px};
    const double r = display_.radius_px_at(e);
    const int side = std::max(1, static_cast<int>(std::lround(2.0 * r / L.sampling_factor)));
    return {0.5 * side * L.sampling_factor, side};
  }

  FrameStats render(Scene& scene, const FrameInput& frame, const GazeState& gaze,
                    const gpu::RenderTarget& target) override {
    const int W = target.width(), H = target.height();
    const size_t n = plan_.layers.size();
    const Vec2d g = to_gl(gaze.gaze_px, H);
    FrameStats stats;
    stats.native_pixels = double(W) * H;
    for (size_t i = 0; i < n; ++i) {
      const Layer& L = plan_.layers[i];
      LayerState& st = state_[i];
      // Staggered half rate: layer 2 (middle) on even frames, 3 (outer) on odd, and so on.
      const bool update = i == 0 || !half_rate_ || frames_ == 0 || !st.valid ||
                          (frame.frame % 2) == static_cast<int>((i + 1) % 2);
      if (!update) {
        stats.parts.push_back({"layer " + std::to_string(i + 1), 0.0});
        continue;
      }
      const double s = L.sampling_factor;
      View v;
      v.pixel_scale = s;
      if (i + 1 < n) {
        const auto [half, side] = inner_size(i, gaze);
        // Origins on the native pixel grid: a layer at s = 1 samples exactly
        // the native pixel centres.
        v.x0 = std::round(g.x - half);
        v.y0 = std::round(g.y - half);
        v.x1 = v.x0 + 2.0 * half;
        v.y1 = v.y0 + 2.0 * half;
        v.target_width = v.target_height = side;
        st.radius = half;
      } else {
        v = View{0, 0, double(W), double(H), L.width_px, L.height_px, s};
        st.radius = 0;
      }
      st.centre = g;
      if (jitter_ && s > 1.0) {
        const double jx = (halton(frame.frame, 2) - 0.5) * s,
                     jy = (halton(frame.frame, 3) - 0.5) * s;
        v.x0 += jx, v.x1 += jx, v.y0 += jy, v.y1 += jy;
      }
      if (msaa_ > 1 && scene.info().has_meshes) v.samples = msaa_;
      scene.prepass(v);
      st.current.ensure(v.target_width, v.target_height);
      st.current.clear(0, 0, 0, 1);
      const double margin = 1.5 * s;
      const double shaded =
          kit_.shade(scene, v, kMapRect, st.current, [&](const gpu::Program& p, gpu::Samplers&) {
            set_rect_mapping(p, v);
            p.set("u_keep_rect", float(-margin), float(-margin), float(W + margin),
                  float(H + margin));
          });
      stats.parts.push_back({"layer " + std::to_string(i + 1), shaded});
      stats.shaded_pixels += shaded;
      accumulate(scene, st, v);
    }
    composite(target);
    ++frames_;
    return stats;
  }

  std::vector<OverlayShape> overlay(const GazeState& gaze) const override {
    std::vector<OverlayShape> out;
    for (size_t i = 0; i + 1 < plan_.layers.size(); ++i) {
      const double half = inner_size(i, gaze).first;
      const auto* c = kRingColours[i];
      out.push_back({OverlayShape::Kind::Rect, gaze.gaze_px.x - half, gaze.gaze_px.y - half,
                     2 * half, 2 * half, c[0], c[1], c[2]});
      out.push_back({OverlayShape::Kind::Circle, gaze.gaze_px.x, gaze.gaze_px.y,
                     (1 - transition_) * half, 0, c[0], c[1], c[2]});
    }
    const auto* c = kRingColours[plan_.layers.size() - 1];
    out.push_back({OverlayShape::Kind::Rect, 1, 1, display_.width_px - 2.0,
                   display_.height_px - 2.0, c[0], c[1], c[2]});
    out.push_back(gaze_dot(gaze));
    return out;
  }

 protected:
  std::vector<std::pair<std::string, double>> derived() const override {
    std::vector<std::pair<std::string, double>> v;
    for (size_t i = 0; i < plan_.layers.size(); ++i) {
      v.emplace_back("layer" + std::to_string(i + 1) + ".radius_deg", plan_.layers[i].radius_deg);
      v.emplace_back("layer" + std::to_string(i + 1) + ".sampling_factor",
                     plan_.layers[i].sampling_factor);
    }
    return v;
  }

 private:
  struct LayerState {
    gpu::RenderTarget current;
    std::array<gpu::RenderTarget, 2> history;
    int latest = 0;  // index of the newest history
    bool valid = false;
    std::array<double, 4> rect{};  // x0, y0, w, h of the newest history
    Vec2d centre{};                // unjittered gaze of the newest render
    bool has_view_proj = false;
    std::array<float, 16> view_proj{};  // the scene camera of the newest render
    double radius = 0;                  // blend radius (half side), native pixels
  };

  // Temporal reverse reprojection in screen space: the previous result is
  // resampled at this frame's sample positions and clamped to the current
  // 3x3 neighbourhood (rejecting disoccluded or changed samples), then blended.
  void accumulate(Scene& scene, LayerState& st, const View& v) {
    const std::array<double, 4> rect{v.x0, v.y0, v.x1 - v.x0, v.y1 - v.y0};
    const int next = 1 - st.latest;
    gpu::RenderTarget& out = st.history[static_cast<size_t>(next)];
    out.ensure(v.target_width, v.target_height, GL_RGBA16F);  // precision for accumulation
    // The inner layer samples at native resolution and is not jittered:
    // blending its history would only add lag, so only subsampled layers blend.
    const bool blend = history_ > 0.0 && st.valid && v.pixel_scale > 1.0;
    // With scene depth and a camera, reverse reprojection through the
    // previous camera; otherwise in screen space.
    const auto vp = scene.view_projection();
    const bool reproject = blend && reproject_ && vp && st.has_view_proj;
    const auto& pr = blend ? st.rect : rect;
    const auto set = [&](const gpu::Program& p, gpu::Samplers& samplers) {
      samplers.bind(p, "u_current", st.current.color());
      samplers.bind(
          p, "u_history",
          blend ? st.history[static_cast<size_t>(st.latest)].color() : st.current.color());
      p.set("u_rect", float(rect[0]), float(rect[1]), float(rect[2]), float(rect[3]));
      p.set("u_prev_rect", float(pr[0]), float(pr[1]), float(pr[2]), float(pr[3]));
      p.set("u_history_weight", blend ? float(history_) : 0.0f);
      if (reproject) {
        glProgramUniformMatrix4fv(p.id(), p.uniform("u_prev_view_proj"), 1, GL_FALSE,
                                  st.view_proj.data());
        p.set("u_frame_size", float(display_.width_px), float(display_.height_px));
      }
    };
    if (reproject) {
      kit_.scene_pass(scene, v,
                      kit_.scene_program(scene, "layered/temporal_reproject.frag", v.samples), out,
                      {}, set);
    } else {
      kit_.pass(kit_.fullscreen("layered/temporal.frag"), out, {}, set);
    }
    st.has_view_proj = vp.has_value();
    if (vp) st.view_proj = *vp;
    st.latest = next;
    st.rect = rect;
    st.valid = true;
  }

  void composite(const gpu::RenderTarget& target) {
    const int n = static_cast<int>(plan_.layers.size());
    const gpu::Program& p = kit_.fullscreen("layered/composite.frag");
    kit_.pass(p, target, {}, [&](const gpu::Program& prog, gpu::Samplers& samplers) {
      float rects[kMaxLayers * 4] = {}, centres[kMaxLayers * 2] = {}, radii[kMaxLayers] = {};
      static const char* names[kMaxLayers] = {"u_layers[0]", "u_layers[1]", "u_layers[2]",
                                              "u_layers[3]", "u_layers[4]", "u_layers[5]"};
      for (int i = 0; i < n; ++i) {
        const LayerState& st = state_[static_cast<size_t>(i)];
        samplers.bind(prog, names[i], st.history[static_cast<size_t>(st.latest)].color());
        for (int k = 0; k < 4; ++k) rects[i * 4 + k] = float(st.rect[static_cast<size_t>(k)]);
        centres[i * 2] = float(st.centre.x);
        centres[i * 2 + 1] = float(st.centre.y);
        radii[i] = float(st.radius);
      }
      glProgramUniform4fv(prog.id(), prog.uniform("u_rects[0]"), n, rects);
      glProgramUniform2fv(prog.id(), prog.uniform("u_centres[0]"), n, centres);
      glProgramUniform1fv(prog.id(), prog.uniform("u_radii[0]"), n, radii);
      prog.set("u_count", n);
      prog.set("u_transition", float(transition_));
    });
  }

  Display display_;
  double transition_;
  bool half_rate_, jitter_;
  double history_;
  bool reproject_;
  int msaa_;
  LayerPlan plan_;
  Kit kit_;
  std::array<LayerState, kMaxLayers> state_;
  int frames_ = 0;
};

}  // namespace

TechniqueInfo layered_info() {
  TechniqueInfo t;
  t.name = "layered";
  t.summary =
      "Nested eccentricity layers from the acuity model, composited with smoothstep masks; "
      "jitter + temporal reprojection; outer layers at half rate.";
  t.source = "Guenter et al., Foveated 3D Graphics, 2012";
  t.params = {
      param("layers", "number of layers n (1 = native)", "", ParamType::Integer, 1, kMaxLayers, 3),
      param("transition", "blend transition as a fraction of the layer radius", "", ParamType::Real,
            0, 1, 0.4),
      param("half_rate", "update outer layers at half rate, staggered", "", ParamType::Boolean, 0,
            1, 1),
      param("jitter", "jitter each layer by up to half its pixel per frame", "", ParamType::Boolean,
            0, 1, 1),
      param("history", "weight of the reprojected history in the temporal blend (0 = off)", "",
            ParamType::Real, 0, 0.95, 0.5),
      param("reproject",
            "reverse-reproject history through the scene camera and depth when the scene has them "
            "(0 = screen space)",
            "", ParamType::Boolean, 0, 1, 1),
      param("msaa",
            "MSAA samples of mesh scenes' layers (1 = off; 4 as in the paper; native has none, so "
            "off "
            "by default)",
            "samples", ParamType::Integer, 1, 8, 1),
      param("grid_step", "planner search step", "deg", ParamType::Real, 0.01, 1.0, 0.05),
  };
  t.make = construct<Layered>();
  return t;
}

}  // namespace foveate::tech
