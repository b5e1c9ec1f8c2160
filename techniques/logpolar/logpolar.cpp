// logpolar: Meng, Du, Zwicker, Varshney, "Kernel Foveated Rendering" (2018).
// The scene is shaded into a kernel log-polar buffer of (W/sigma) x (H/sigma)
// whose columns follow u = K^-1(log r / L) w with K(x) = x^alpha, then mapped
// back to the screen; two-level antialiasing blurs the result with a Gaussian
// whose screen-space width grows with eccentricity (a fixed footprint in the
// buffer). Mesh scenes are shaded deferred: their G-buffer is rasterised at
// native resolution and the lighting runs in the log-polar buffer.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

#include "../common/kit.hpp"
#include "../common/registry.hpp"

namespace foveate::tech {

namespace {

struct LogPolarParams {
  double sigma = 1.8;
  double alpha = 4.0;
  double blur = 0.6;
};

// The largest sigma for which the buffer samples at least as densely as the
// acuity model requires everywhere on screen, for a given alpha: at distance r
// from the gaze the buffer's pixel spans r L alpha t^(1-1/alpha) sigma / W
// radially and 2 pi r sigma / H around, which must not exceed the sampling
// factor s(e(r)) = max(1, w(e) / w*).
double acuity_sigma(const Display& d, const AcuityModel& a, double alpha) {
  const double W = d.width_px, H = d.height_px;
  const double L = std::log(std::hypot(W, H));
  double best = 16.0;
  const double rmax = std::hypot(W, H);
  for (double r = 2.0; r <= rmax; r *= 1.02) {
    const double t = std::log(r) / L;
    const double e = std::atan(r / d.focal_px()) * 180.0 / std::numbers::pi;
    const double s = std::max(1.0, a.mar_deg(e) / d.sharpness_deg());
    const double radial = r * L * alpha * std::pow(t, 1.0 - 1.0 / alpha) / W;
    const double around = 2.0 * std::numbers::pi * r / H;
    best = std::min(best, s / std::max(radial, around));
  }
  return std::clamp(best, 1.0, 16.0);
}

LogPolarParams derive(const TechniqueConfig& c, Params& p) {
  LogPolarParams o;
  // Default alpha: the kernel in the user study's range [1, 4] that lets the
  // acuity model accept the smallest buffer.
  double best_alpha = 1.0, best_sigma = 0.0;
  for (double a = 1.0; a <= 4.0 + 1e-9; a += 0.25) {
    const double s = acuity_sigma(c.display, c.acuity, a);
    if (s > best_sigma + 1e-9) best_sigma = s, best_alpha = a;
  }
  o.alpha = p.get("alpha", best_alpha);
  o.sigma = p.get("sigma", acuity_sigma(c.display, c.acuity, o.alpha));
  o.blur = p.get("blur", 0.6);
  return o;
}

class LogPolar final : public Technique {
 public:
  explicit LogPolar(const TechniqueConfig& c) : display_(c.display) {
    std::tie(opt_, values_) = derive_options<LogPolarParams>("logpolar", c, derive);
    model_ = KernelLogPolar{double(display_.width_px), double(display_.height_px), opt_.sigma,
                            opt_.alpha};
    model_.validate();
  }
  std::string name() const override { return "logpolar"; }
  std::vector<std::pair<std::string, double>> parameters() const override {
    auto v = values_;
    v.emplace_back("buffer_width", std::round(model_.buffer_w()));
    v.emplace_back("buffer_height", std::round(model_.buffer_h()));
    return v;
  }

  FrameStats render(Scene& scene, const FrameInput& frame, const GazeState& gaze,
                    GLuint target) override {
    const int W = frame.width, H = frame.height;
    const int bw = std::max(1, static_cast<int>(std::lround(W / opt_.sigma)));
    const int bh = std::max(1, static_cast<int>(std::lround(H / opt_.sigma)));
    // The log-polar centre must lie on the screen for the buffer to cover it:
    // a gaze off screen is moved to the nearest screen point.
    Vec2d g = to_gl(gaze.gaze_px, H);
    g.x = std::clamp(g.x, 0.0, double(W));
    g.y = std::clamp(g.y, 0.0, double(H));
    // L spans the screen from the gaze: log of the diagonal (Meng et al.), or
    // of the farthest corner when the gaze is off screen.
    double far = std::hypot(double(W), double(H));
    for (double cx : {0.0, double(W)}) {
      for (double cy : {0.0, double(H)}) far = std::max(far, std::hypot(cx - g.x, cy - g.y));
    }
    const float L = static_cast<float>(std::log(far));
    // Deferred: a mesh scene's G-buffer at native resolution.
    const View native = View::full(W, H);
    scene.prepass(native);
    buffer_.ensure(bw, bh);
    buffer_.color.set_wrap(GL_CLAMP_TO_EDGE);
    glTextureParameteri(buffer_.color.id(), GL_TEXTURE_WRAP_T,
                        GL_REPEAT);  // the angle wraps around
    buffer_.bind_viewport();
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    // Buffer texels whose screen position lies beyond the screen (plus a margin
    // for filtering) are not shaded.
    const double margin = 0.02 * std::hypot(W, H);
    const double shaded =
        kit_.shade(scene, native, "logpolar/map_logpolar.glsl", [&](const gpu::Program& p) {
          p.set("u_lp_gaze", float(g.x), float(g.y));
          p.set("u_lp_L", L);
          p.set("u_lp_alpha", float(opt_.alpha));
          p.set("u_lp_buffer", float(bw), float(bh));
          p.set("u_keep_rect", float(-margin), float(-margin), float(W + margin),
                float(H + margin));
        });
    // Inverse mapping with the two-level antialiasing blur.
    const gpu::Program& inv = kit_.fullscreen("logpolar/inverse.frag");
    buffer_.color.bind(Scene::kFirstTechniqueUnit);
    inv.set("u_buffer", Scene::kFirstTechniqueUnit);
    inv.set("u_lp_gaze", float(g.x), float(g.y));
    inv.set("u_lp_L", L);
    inv.set("u_lp_alpha", float(opt_.alpha));
    inv.set("u_lp_buffer", float(bw), float(bh));
    inv.set("u_blur", float(opt_.blur));
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, W, H);
    kit_.draw_fullscreen(inv);
    return one_pass_stats("log-polar buffer", shaded, W, H);
  }

  std::vector<OverlayShape> overlay(const GazeState& gaze) const override {
    // Rings where the buffer's radial pixel reaches 1, 2, 4 and 8 screen pixels.
    std::vector<OverlayShape> out;
    const float colours[4][3] = {
        {1, 0.1f, 0.1f}, {0.1f, 0.9f, 0.2f}, {0.2f, 0.4f, 1}, {1, 0.8f, 0.1f}};
    int k = 0;
    for (double r = 2.0; r < 4000 && k < 4; r *= 1.01) {
      const double t = std::log(r) / model_.log_extent();
      const double radial = r * model_.log_extent() * opt_.alpha *
                            std::pow(t, 1.0 - 1.0 / opt_.alpha) / model_.buffer_w();
      if (radial >= std::pow(2.0, k)) {
        out.push_back({OverlayShape::Kind::Circle, gaze.gaze_px.x, gaze.gaze_px.y, r, 0,
                       colours[k][0], colours[k][1], colours[k][2]});
        ++k;
      }
    }
    out.push_back(
        {OverlayShape::Kind::Dot, gaze.gaze_px.x, gaze.gaze_px.y, 4, 4, 1.0f, 0.3f, 0.8f});
    return out;
  }

 private:
  Display display_;
  LogPolarParams opt_;
  std::vector<std::pair<std::string, double>> values_;
  KernelLogPolar model_;
  Kit kit_;
  Target buffer_;
};

}  // namespace

TechniqueInfo logpolar_info() {
  return {"logpolar",
          "Shading in a kernel log-polar buffer (W/sigma x H/sigma, K(x) = x^alpha), mapped back "
          "with an eccentricity-growing Gaussian (two-level antialiasing).",
          "Meng, Du, Zwicker, Varshney, Kernel Foveated Rendering, 2018",
          {{"sigma", "buffer parameter W / w (1 = native size); default from the acuity model", 1.0,
            16.0, false},
           {"alpha", "kernel exponent, K(x) = x^alpha; default from the acuity model within [1, 4]",
            0.25, 8.0, false},
           {"blur", "antialiasing Gaussian sigma in buffer texels (0 = off)", 0.0, 3.0, false}},
          [](const TechniqueConfig& c) { return std::make_unique<LogPolar>(c); },
          [](const TechniqueConfig& c) {
            return derive_options<LogPolarParams>("logpolar", c, derive).second;
          }};
}

}  // namespace foveate::tech
