// inset: Swafford, Cosker, Mitchell, "Latency Aware Foveated Rendering in
// Unreal Engine 4" (2015). The periphery is rendered at a quarter of the
// pixels (half per axis) and upscaled with a slight blur; a full-resolution
// foveal inset, whose diameter follows the latency-aware formula (eq. 1), is
// blended over it with a vignette mask.
#include <cmath>
#include <tuple>

#include "../common/kit.hpp"
#include "../common/registry.hpp"

namespace foveate::tech {

namespace {

struct InsetParams {
  double scale = 0.5;
  double fovea_deg = 6.0;
  double border_frac = 0.2;
  double latency_ms = 0.0;
  double saccade = 200.0;
  double blur = 1.0;
};

InsetParams derive(const TechniqueConfig& c, Params& p) {
  InsetParams o;
  o.scale = p.get("scale", 0.5);
  // The fovea the inset must cover: where the acuity model first accepts the
  // periphery's sampling factor 1/scale (w(e) = w* / scale), on both sides.
  const double e = c.acuity.eccentricity_for_mar(c.display.sharpness_deg() / o.scale);
  o.fovea_deg = p.get("fovea_deg", std::clamp(2.0 * e, 1.0, 60.0));
  o.border_frac = p.get("border", 0.2);
  o.latency_ms = p.get("latency_ms", 0.0);
  o.saccade = p.get("saccade_deg_per_s", 200.0);
  o.blur = p.get("blur", 1.0);
  return o;
}

class Inset final : public Technique {
 public:
  explicit Inset(const TechniqueConfig& c) : display_(c.display) {
    std::tie(opt_, values_) = derive_options<InsetParams>("inset", c, derive);
  }
  std::string name() const override { return "inset"; }
  std::vector<std::pair<std::string, double>> parameters() const override {
    auto v = values_;
    v.emplace_back("diameter_px", fovea(GazeState{}).diameter_px(display_));
    return v;
  }

  // Eq. 1 with the larger of the configured and the measured latency.
  LatencyAwareFovea fovea(const GazeState& g) const {
    LatencyAwareFovea f;
    f.latency_ms = std::max(opt_.latency_ms, g.latency_ms);
    f.saccade_deg_per_s = g.latency_ms > opt_.latency_ms ? g.saccade_deg_per_s : opt_.saccade;
    f.fovea_deg = std::min(opt_.fovea_deg * g.fovea_scale, 170.0);
    f.blend_border_px = opt_.border_frac * 0.5 * display_.radius_px_at(0.5 * f.fovea_deg) * 2.0;
    return f;
  }

  FrameStats render(Scene& scene, const FrameInput& frame, const GazeState& gaze,
                    GLuint target) override {
    const int W = frame.width, H = frame.height;
    const Vec2d g = to_gl(gaze.gaze_px, H);
    FrameStats s;
    s.native_pixels = double(W) * H;
    // Periphery: the whole screen at `scale` per axis.
    const int pw = std::max(1, static_cast<int>(std::lround(W * opt_.scale)));
    const int ph = std::max(1, static_cast<int>(std::lround(H * opt_.scale)));
    const View pv{0, 0, double(W), double(H), pw, ph, 1.0 / opt_.scale};
    scene.prepass(pv);
    periphery_.ensure(pw, ph);
    periphery_.bind_viewport();
    const double np =
        kit_.shade(scene, pv, kMapRect, [&](const gpu::Program& p) { set_rect_mapping(p, pv); });
    s.parts.push_back({"periphery", np});
    // Foveal inset at native resolution, clipped to the screen.
    const LatencyAwareFovea f = fovea(gaze);
    const double diameter = f.diameter_px(display_);
    const double half = 0.5 * diameter;
    const double x0 = std::max(0.0, std::floor(g.x - half)),
                 y0 = std::max(0.0, std::floor(g.y - half));
    const double x1 = std::min(double(W), std::ceil(g.x + half)),
                 y1 = std::min(double(H), std::ceil(g.y + half));
    double ni = 0.0;
    const bool has_inset = x1 > x0 && y1 > y0;
    if (has_inset) {
      const View iv{x0, y0, x1, y1, static_cast<int>(x1 - x0), static_cast<int>(y1 - y0), 1.0};
      scene.prepass(iv);
      inset_.ensure(iv.target_width, iv.target_height);
      inset_.bind_viewport();
      ni = kit_.shade(scene, iv, kMapRect, [&](const gpu::Program& p) { set_rect_mapping(p, iv); });
    }
    s.parts.push_back({"inset", ni});
    s.shaded_pixels = np + ni;
    // Composite: blurred upscale of the periphery, the inset over it with a vignette.
    const gpu::Program& c = kit_.fullscreen("inset/composite.frag");
    periphery_.color.bind(Scene::kFirstTechniqueUnit);
    c.set("u_periphery", Scene::kFirstTechniqueUnit);
    if (has_inset) inset_.color.bind(Scene::kFirstTechniqueUnit + 1);
    c.set("u_inset", Scene::kFirstTechniqueUnit + 1);
    c.set("u_has_inset", has_inset ? 1 : 0);
    c.set("u_inset_rect", float(x0), float(y0), float(x1 - x0), float(y1 - y0));
    c.set("u_gaze", float(g.x), float(g.y));
    c.set("u_radius", float(half));
    c.set("u_border", float(f.blend_border_px));
    c.set("u_blur", float(opt_.blur));
    c.set("u_screen", float(W), float(H));
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, W, H);
    kit_.draw_fullscreen(c);
    return s;
  }

  std::vector<OverlayShape> overlay(const GazeState& gaze) const override {
    const LatencyAwareFovea f = fovea(gaze);
    const double half = 0.5 * f.diameter_px(display_);
    return {{OverlayShape::Kind::Circle, gaze.gaze_px.x, gaze.gaze_px.y, half, 0, 1, 0.1f, 0.1f},
            {OverlayShape::Kind::Circle, gaze.gaze_px.x, gaze.gaze_px.y, half - f.blend_border_px,
             0, 0.1f, 0.9f, 0.2f},
            {OverlayShape::Kind::Dot, gaze.gaze_px.x, gaze.gaze_px.y, 4, 4, 1.0f, 0.3f, 0.8f}};
  }

 private:
  Display display_;
  InsetParams opt_;
  std::vector<std::pair<std::string, double>> values_;
  Kit kit_;
  Target periphery_, inset_;
};

}  // namespace

TechniqueInfo inset_info() {
  return {
      "inset",
      "Quarter-resolution periphery upscaled with a slight blur, and a full-resolution foveal "
      "inset sized by the latency-aware formula, blended with a vignette.",
      "Swafford, Cosker, Mitchell, Latency Aware Foveated Rendering in UE4, 2015",
      {{"scale", "periphery resolution per axis (0.5 = a quarter of the pixels)", 0.05, 1.0, false},
       {"fovea_deg", "angle the fovea subtends (alpha of eq. 1); default from the acuity model",
        0.5, 170.0, false},
       {"border", "vignette blend border as a fraction of the foveal radius", 0.0, 1.0, false},
       {"latency_ms",
        "worst-case total latency L_tot (the measured gaze latency is used if larger)", 0.0, 1000.0,
        false},
       {"saccade_deg_per_s", "maximal saccade speed S_max", 0.0, 1000.0, false},
       {"blur", "upscale blur radius in periphery texels (0 = plain bilinear)", 0.0, 4.0, false}},
      [](const TechniqueConfig& c) { return std::make_unique<Inset>(c); },
      [](const TechniqueConfig& c) {
        return derive_options<InsetParams>("inset", c, derive).second;
      }};
}

}  // namespace foveate::tech
