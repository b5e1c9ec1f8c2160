// inset: Swafford, Cosker, Mitchell, "Latency Aware Foveated Rendering in
// Unreal Engine 4" (2015). The periphery is rendered at reduced resolution
// (half per axis in the paper) and upscaled with a slight blur; a full-resolution
// foveal inset, whose diameter follows the latency-aware formula (eq. 1), is
// blended over it with a vignette mask.
#include <cmath>
#include <limits>
#include <tuple>
#include <vector>

#include "../registry/registry.hpp"
#include "foveate/techniques/pass_kit.hpp"
#include "foveate/techniques/rect_pass.hpp"

namespace foveate::tech {

namespace {

class Inset final : public Technique {
 public:
  Inset(const TechniqueConfig& c, const ParamValues& v)
      : display_(c.display),
        scale_(v.real("scale")),
        fovea_deg_(v.real("fovea_deg")),
        border_frac_(v.real("border")),
        latency_ms_(v.real("latency_ms")),
        max_saccade_(v.real("max_saccade_deg_per_s")),
        blur_(v.real("blur")) {}

  // Eq. 1 with the larger of the configured and the measured latency.
  LatencyAwareFovea fovea(const GazeState& g) const {
    LatencyAwareFovea f;
    f.latency_ms = std::max(latency_ms_, g.latency_ms);
    f.max_saccade_deg_per_s = g.latency_ms > latency_ms_ ? g.max_saccade_deg_per_s : max_saccade_;
    f.fovea_deg = std::min(fovea_deg_ * g.fovea_scale, 170.0);
    f.blend_border_px = border_frac_ * 0.5 * display_.radius_px_at(0.5 * f.fovea_deg) * 2.0;
    return f;
  }

  FrameStats render(Scene& scene, const FrameInput&, const GazeState& gaze,
                    const gpu::RenderTarget& target) override {
    const int W = target.width(), H = target.height();
    const Vec2d g = to_gl(gaze.gaze_px, H);
    FrameStats s;
    s.native_pixels = double(W) * H;
    // Periphery: the whole screen at `scale` per axis.
    const int pw = std::max(1, static_cast<int>(std::lround(W * scale_)));
    const int ph = std::max(1, static_cast<int>(std::lround(H * scale_)));
    const LatencyAwareFovea f = fovea(gaze);
    const double diameter = f.diameter_px(display_);
    const double half = 0.5 * diameter;
    // Native's geometric LOD (pixel scale 1): a coarser mesh would move
    // silhouettes by more than the periphery's MAR hides. Objects wholly
    // inside the square inscribed in the inset's opaque disc, less what the
    // blur and the two bilinear reads reach, never show in the periphery.
    View pv{0, 0, double(W), double(H), pw, ph, 1.0};
    const double hidden = (half - f.blend_border_px - (blur_ + 3.0) / scale_) / std::sqrt(2.0);
    if (hidden > 0.0) {
      pv.skip_x0 = g.x - hidden;
      pv.skip_y0 = g.y - hidden;
      pv.skip_x1 = g.x + hidden;
      pv.skip_y1 = g.y + hidden;
    }
    // Foveal inset at native resolution, clipped to the screen.
    const double x0 = std::max(0.0, std::floor(g.x - half)),
                 y0 = std::max(0.0, std::floor(g.y - half));
    const double x1 = std::min(double(W), std::ceil(g.x + half)),
                 y1 = std::min(double(H), std::ceil(g.y + half));
    const bool has_inset = x1 > x0 && y1 > y0;
    scene.prepass(pv);
    periphery_.ensure(pw, ph);
    // The periphery is shaded around a hole where the inset is opaque
    // (weight 1 within its radius less the border), less what the blur and
    // the upscale's bilinear read reach into it: every screen pixel that
    // shows a texel of the hole, or a blur of one, is overwritten whole by
    // the inset.
    const double sx = double(pw) / W, sy = double(ph) / H;
    const double hole = (half - f.blend_border_px) * std::min(sx, sy) - (blur_ + 3.0);
    const std::vector<PixelRect> around =
        annulus_rects(g.x * sx, g.y * sy, has_inset ? std::max(0.0, hole) : 0.0,
                      std::numeric_limits<double>::infinity(), pw, ph);
    const PixelCount np = kit_.shade(
        scene, pv, kMapRect, periphery_,
        [&](const gpu::Program& p, gpu::Samplers&) { set_rect_mapping(p, pv); }, {}, false,
        &around);
    PixelCount ni;
    if (has_inset) {
      const View iv{x0, y0, x1, y1, static_cast<int>(x1 - x0), static_cast<int>(y1 - y0), 1.0};
      scene.prepass(iv);
      inset_.ensure(iv.target_width, iv.target_height);
      // Only the disc the composite shows (its texels are the screen's
      // pixels, read at their centres: nothing beyond the disc is fetched).
      const std::vector<PixelRect> disc =
          disc_rects(g.x - x0, g.y - y0, half, iv.target_width, iv.target_height);
      ni = kit_.shade(
          scene, iv, kMapRect, inset_,
          [&](const gpu::Program& p, gpu::Samplers&) { set_rect_mapping(p, iv); }, {}, false,
          &disc);
    }
    // Composite: the periphery blurred at its own resolution (no pass at
    // blur 0), upscaled over the screen (one fetch per pixel), then the inset
    // blended over its own rectangle only.
    const gpu::RenderTarget* shown = &periphery_;
    if (blur_ > 0.0) {
      blurred_.ensure(pw, ph);
      kit_.pass(kit_.fullscreen("inset/blur.frag"), blurred_, {},
                [&](const gpu::Program& c, gpu::Samplers& samplers) {
                  samplers.bind(c, "u_periphery", periphery_.color());
                  c.set("u_blur", float(blur_));
                });
      shown = &blurred_;
    }
    kit_.pass(kit_.fullscreen("inset/upscale.frag"), target, {},
              [&](const gpu::Program& c, gpu::Samplers& samplers) {
                samplers.bind(c, "u_periphery", shown->color());
              });
    if (has_inset) {
      gpu::PassState over;
      over.alpha_blend = true;
      over.scissor = {static_cast<int>(x0), static_cast<int>(y0), static_cast<int>(x1 - x0),
                      static_cast<int>(y1 - y0)};
      kit_.pass(kit_.fullscreen("inset/composite.frag"), target, over,
                [&](const gpu::Program& c, gpu::Samplers& samplers) {
                  samplers.bind(c, "u_inset", inset_.color());
                  c.set("u_inset_rect", float(x0), float(y0), float(x1 - x0), float(y1 - y0));
                  c.set("u_gaze_gl", float(g.x), float(g.y));
                  c.set("u_radius", float(half));
                  c.set("u_border", float(f.blend_border_px));
                });
    }
    // Read once the frame's last pass is sent (PixelCount).
    s.parts = {{"periphery", np.read()}, {"inset", ni.read()}};
    s.shaded_pixels = s.parts[0].pixels + s.parts[1].pixels;
    return s;
  }

  std::vector<OverlayShape> overlay(const GazeState& gaze) const override {
    const LatencyAwareFovea f = fovea(gaze);
    const double half = 0.5 * f.diameter_px(display_);
    return {{OverlayShape::Kind::Circle, gaze.gaze_px.x, gaze.gaze_px.y, half, 0, 1, 0.1f, 0.1f,
             "full-resolution inset: edge (reduced-resolution periphery outside)"},
            {OverlayShape::Kind::Circle, gaze.gaze_px.x, gaze.gaze_px.y, half - f.blend_border_px,
             0, 0.1f, 0.9f, 0.2f, "inset blends into the periphery from this ring (vignette)"},
            gaze_dot(gaze)};
  }

 protected:
  std::vector<std::pair<std::string, double>> derived() const override {
    return {{"diameter_px", fovea(GazeState{}).diameter_px(display_)}};
  }

 private:
  Display display_;
  double scale_, fovea_deg_, border_frac_, latency_ms_, max_saccade_, blur_;
  PassKit kit_;
  gpu::RenderTarget blurred_;  // the periphery after the tent blur
  gpu::RenderTarget periphery_, inset_;
};

}  // namespace

TechniqueInfo inset_info() {
  TechniqueInfo t;
  t.name = "inset";
  t.summary =
      "Reduced-resolution periphery (a quarter of the pixels in the paper), upscaled, and a "
      "full-resolution foveal inset sized by the latency-aware formula, blended with a vignette.";
  t.source = "Swafford, Cosker, Mitchell, Latency Aware Foveated Rendering in UE4, 2015";
  t.params = {
      plan_margin_param(1.0),
      tuned(param("scale",
                  "periphery resolution per axis (the paper's 0.5 = a quarter of the pixels; the "
                  "default is tune's, docs/fidelity.md)",
                  "", ParamType::Real, 0.05, 1.0, 0.55),
            {0.35, 0.5, 0.55, 0.6, 0.65}),
      // The fovea the inset must cover: where the acuity model first accepts
      // the periphery's sampling factor 1/scale (w(e) = w* / scale), both sides.
      {"fovea_deg", "angle the fovea subtends (alpha of eq. 1); default from the acuity model",
       "deg", ParamType::Real, 0.5, 170.0, 6.0,
       [](const TechniqueConfig& c, const ParamValues& v) {
         const double e =
             c.acuity.eccentricity_for_mar(c.display.sharpness_deg() / v.real("scale"));
         return std::clamp(2.0 * e, 1.0, 60.0);
       }},
      tuned(param("border", "vignette blend border as a fraction of the foveal radius", "",
                  ParamType::Real, 0.0, 1.0, 0.4),
            {0.1, 0.2, 0.4}),
      param("latency_ms",
            "worst-case total latency L_tot (the measured gaze latency is used if larger)", "ms",
            ParamType::Real, 0.0, 1000.0, 0.0),
      param("max_saccade_deg_per_s", "maximal saccade speed S_max of eq. 1", "deg/s",
            ParamType::Real, 0.0, 1000.0, 200.0),
      tuned(param("blur",
                  "upscale blur radius in periphery texels (0 = plain bilinear, no blur pass)",
                  "texels", ParamType::Real, 0.0, 4.0, 0.0),
            {0, 0.5, 1}),
  };
  t.resolve_passes = {"blur", "upscale", "composite"};
  t.make = construct<Inset>();
  return t;
}

}  // namespace foveate::tech
