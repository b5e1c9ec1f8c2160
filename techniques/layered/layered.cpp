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

struct LayeredParams {
  int layers = 3;
  double transition = 0.4;
  bool half_rate = true;
  bool jitter = true;
  double history = 0.5;
  bool reproject = true;
  int msaa = 1;
  double grid_step = 0.05;
};

LayeredParams derive(const TechniqueConfig&, Params& p) {
  LayeredParams o;
  o.layers = static_cast<int>(p.get("layers", 3));
  o.transition = p.get("transition", 0.4);
  o.half_rate = p.get("half_rate", 1) != 0.0;
  o.jitter = p.get("jitter", 1) != 0.0;
  o.history = p.get("history", 0.5);
  o.reproject = p.get("reproject", 1) != 0.0;
  o.msaa = static_cast<int>(p.get("msaa", 1));
  o.grid_step = p.get("grid_step", 0.05);
  return o;
}

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
  explicit Layered(const TechniqueConfig& c) : display_(c.display) {
    std::tie(opt_, values_) = derive_options<LayeredParams>("layered", c, derive);
    PlannerOptions po;
    po.layers = opt_.layers;
    po.grid_step_deg = opt_.grid_step;
    plan_ = plan_layers(display_, c.acuity, po);
  }

  std::string name() const override { return "layered"; }
  std::vector<std::pair<std::string, double>> parameters() const override {
    auto v = values_;
    for (size_t i = 0; i < plan_.layers.size(); ++i) {
      v.emplace_back("layer" + std::to_string(i + 1) + ".radius_deg", plan_.layers[i].radius_deg);
      v.emplace_back("layer" + std::to_string(i + 1) + ".sampling_factor",
                     plan_.layers[i].sampling_factor);
    }
    return v;
  }
  const LayerPlan& plan() const { return plan_; }
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
                    GLuint target) override {
    const int W = frame.width, H = frame.height;
    const size_t n = plan_.layers.size();
    const Vec2d g = to_gl(gaze.gaze_px, H);
    FrameStats stats;
    stats.native_pixels = double(W) * H;
    for (size_t i = 0; i < n; ++i) {
      const Layer& L = plan_.layers[i];
      LayerState& st = state_[i];
      // Staggered half rate: layer 2 (middle) on even frames, 3 (outer) on odd, and so on.
      const bool update = i == 0 || !opt_.half_rate || frames_ == 0 || !st.valid ||
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
      if (opt_.jitter && s > 1.0) {
        const double jx = (halton(frame.frame, 2) - 0.5) * s,
                     jy = (halton(frame.frame, 3) - 0.5) * s;
        v.x0 += jx, v.x1 += jx, v.y0 += jy, v.y1 += jy;
      }
      if (opt_.msaa > 1 && scene.info().has_meshes) v.samples = opt_.msaa;
      scene.prepass(v);
      st.current.ensure(v.target_width, v.target_height);
      st.current.bind_viewport();
      glClearColor(0, 0, 0, 1);
      glClear(GL_COLOR_BUFFER_BIT);
      const double margin = 1.5 * s;
      const double shaded = kit_.shade(scene, v, kMapRect, [&](const gpu::Program& p) {
        set_rect_mapping(p, v);
        p.set("u_keep_rect", float(-margin), float(-margin), float(W + margin), float(H + margin));
      });
      stats.parts.push_back({"layer " + std::to_string(i + 1), shaded});
      stats.shaded_pixels += shaded;
      accumulate(scene, st, v);
    }
    composite(W, H, target);
    ++frames_;
    return stats;
  }

  std::vector<OverlayShape> overlay(const GazeState& gaze) const override {
    static const float colours[kMaxLayers][3] = {{1, 0.1f, 0.1f}, {0.1f, 0.9f, 0.2f},
                                                 {0.2f, 0.4f, 1}, {1, 0.8f, 0.1f},
                                                 {0.8f, 0.2f, 1}, {0.1f, 0.9f, 0.9f}};
    std::vector<OverlayShape> out;
    for (size_t i = 0; i + 1 < plan_.layers.size(); ++i) {
      const double half = inner_size(i, gaze).first;
      const auto* c = colours[i];
      out.push_back({OverlayShape::Kind::Rect, gaze.gaze_px.x - half, gaze.gaze_px.y - half,
                     2 * half, 2 * half, c[0], c[1], c[2]});
      out.push_back({OverlayShape::Kind::Circle, gaze.gaze_px.x, gaze.gaze_px.y,
                     (1 - opt_.transition) * half, 0, c[0], c[1], c[2]});
    }
    const auto* c = colours[plan_.layers.size() - 1];
    out.push_back({OverlayShape::Kind::Rect, 1, 1, display_.width_px - 2.0,
                   display_.height_px - 2.0, c[0], c[1], c[2]});
    out.push_back(
        {OverlayShape::Kind::Dot, gaze.gaze_px.x, gaze.gaze_px.y, 4, 4, 1.0f, 0.3f, 0.8f});
    return out;
  }

 private:
  struct LayerState {
    Target current;
    std::array<Target, 2> history;
    int latest = 0;  // index of the newest history
    bool valid = false;
    std::array<double, 4> rect{};  // x0, y0, w, h of the newest history
    std::array<double, 4> prev_rect{};
    Vec2d centre{};  // unjittered gaze of the newest render
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
    Target& out = st.history[static_cast<size_t>(next)];
    out.ensure(v.target_width, v.target_height);
    out.bind_viewport();
    // The inner layer samples at native resolution and is not jittered:
    // blending its history would only add lag, so only subsampled layers blend.
    const bool blend = opt_.history > 0.0 && st.valid && v.pixel_scale > 1.0;
    // With scene depth and a camera, reverse reprojection through the
    // previous camera; otherwise in screen space.
    const auto vp = scene.view_projection();
    const bool reproject = blend && opt_.reproject && vp && st.has_view_proj;
    const gpu::Program& p =
        reproject ? kit_.scene_program(scene, "layered/temporal_reproject.frag", v.samples)
                  : kit_.fullscreen("layered/temporal.frag");
    if (reproject) {
      scene.bind(p, v);
      glProgramUniformMatrix4fv(p.id(), p.uniform("u_prev_view_proj"), 1, GL_FALSE,
                                st.view_proj.data());
      p.set("u_frame_size", float(display_.width_px), float(display_.height_px));
    }
    st.current.color.bind(Scene::kFirstTechniqueUnit);
    p.set("u_current", Scene::kFirstTechniqueUnit);
    if (blend) {
      st.history[static_cast<size_t>(st.latest)].color.bind(Scene::kFirstTechniqueUnit + 1);
    } else {
      st.current.color.bind(Scene::kFirstTechniqueUnit + 1);
    }
    p.set("u_history", Scene::kFirstTechniqueUnit + 1);
    p.set("u_rect", float(rect[0]), float(rect[1]), float(rect[2]), float(rect[3]));
    const auto& pr = blend ? st.rect : rect;
    p.set("u_prev_rect", float(pr[0]), float(pr[1]), float(pr[2]), float(pr[3]));
    p.set("u_history_weight", blend ? float(opt_.history) : 0.0f);
    st.has_view_proj = vp.has_value();
    if (vp) st.view_proj = *vp;
    kit_.draw_fullscreen(p);
    st.latest = next;
    st.prev_rect = st.rect;
    st.rect = rect;
    st.valid = true;
  }

  void composite(int W, int H, GLuint target) {
    const int n = static_cast<int>(plan_.layers.size());
    const gpu::Program& p = kit_.fullscreen("layered/composite.frag");
    float rects[kMaxLayers * 4] = {}, centres[kMaxLayers * 2] = {}, radii[kMaxLayers] = {};
    int units[kMaxLayers] = {};
    for (int i = 0; i < n; ++i) {
      const LayerState& st = state_[static_cast<size_t>(i)];
      const GLuint unit = static_cast<GLuint>(Scene::kFirstTechniqueUnit + i);
      st.history[static_cast<size_t>(st.latest)].color.bind(unit);
      units[i] = static_cast<int>(unit);
      for (int k = 0; k < 4; ++k) rects[i * 4 + k] = float(st.rect[static_cast<size_t>(k)]);
      centres[i * 2] = float(st.centre.x);
      centres[i * 2 + 1] = float(st.centre.y);
      radii[i] = float(st.radius);
    }
    glProgramUniform1iv(p.id(), p.uniform("u_layers[0]"), kMaxLayers, units);
    glProgramUniform4fv(p.id(), p.uniform("u_rects[0]"), n, rects);
    glProgramUniform2fv(p.id(), p.uniform("u_centres[0]"), n, centres);
    glProgramUniform1fv(p.id(), p.uniform("u_radii[0]"), n, radii);
    p.set("u_count", n);
    p.set("u_transition", float(opt_.transition));
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, W, H);
    kit_.draw_fullscreen(p);
  }

  Display display_;
  LayeredParams opt_;
  std::vector<std::pair<std::string, double>> values_;
  LayerPlan plan_;
  Kit kit_;
  std::array<LayerState, kMaxLayers> state_;
  int frames_ = 0;
};

}  // namespace

const LayerPlan* layered_plan(const Technique& t) {
  const auto* l = dynamic_cast<const Layered*>(&t);
  return l ? &l->plan() : nullptr;
}

TechniqueInfo layered_info() {
  return {"layered",
          "Nested eccentricity layers from the acuity model, composited with smoothstep masks; "
          "jitter + temporal reprojection; outer layers at half rate.",
          "Guenter et al., Foveated 3D Graphics, 2012",
          {{"layers", "number of layers n (1 = native)", 1, kMaxLayers, true},
           {"transition", "blend transition as a fraction of the layer radius", 0.0, 1.0, false},
           {"half_rate", "update outer layers at half rate, staggered (0 or 1)", 0, 1, true},
           {"jitter", "jitter each layer by up to half its pixel per frame (0 or 1)", 0, 1, true},
           {"history", "weight of the reprojected history in the temporal blend (0 = off)", 0.0,
            0.95, false},
           {"reproject",
            "reverse-reproject history through the scene camera and depth when the scene has them "
            "(0 = screen space)",
            0, 1, true},
           {"msaa",
            "MSAA samples of mesh scenes' layers (1 = off; 4 as in the paper; native has none, so "
            "off by default)",
            1, 8, true},
           {"grid_step", "planner search step in degrees", 0.01, 1.0, false}},
          [](const TechniqueConfig& c) { return std::make_unique<Layered>(c); },
          [](const TechniqueConfig& c) {
            return derive_options<LayeredParams>("layered", c, derive).second;
          }};
}

}  // namespace foveate::tech
