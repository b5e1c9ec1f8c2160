// lodmask: Knapik and McGowen, "Foveal Rendering" (2016). Three mesh LODs
// (full, about 10 % and 1 % of the triangles) fill the G-buffer through
// stencil masks around the gaze (full inside the inner circle, mid in the
// ring to the outer one, coarse beyond), and lighting is deferred. The
// circles come from the acuity model: a LOD may show where half a resolvable
// cycle covers its silhouette error (the params below say how).
//
// The stencil marks every pixel's LOD before any is drawn and each LOD writes
// only its own pixels, so that inside the full-detail circle the image is
// native's, background included: a finer LOD drawn over a coarser one's
// G-buffer would leave the coarser surface wherever the finer mesh has none.
//
// Against popping at the LOD borders the circles are held still: their centre
// moves only when the gaze leaves a small disc around it (hold_deg, larger
// than fixational drift and microsaccades), and they are grown by that disc
// so the full-detail circle around the gaze is always covered. A border then
// moves only with a saccade, when saccadic suppression hides the change. (A
// band where the two LODs are dithered would need temporal accumulation:
// without it the dither is a visible pattern of its own, and it flickers.)
#include <algorithm>
#include <cmath>
#include <tuple>

#include "../registry/registry.hpp"
#include "foveate/core/error.hpp"
#include "foveate/techniques/pass_kit.hpp"

namespace foveate::tech {

namespace {

// Pixel centres (x + 0.5, y + 0.5) of a W x H screen within `r` of `c`, row by row.
double pixels_in_disc(Vec2d c, double r, int W, int H) {
  double n = 0;
  for (int y = 0; y < H; ++y) {
    const double dy = y + 0.5 - c.y;
    if (std::abs(dy) > r) continue;
    const double half = std::sqrt(r * r - dy * dy);
    const double x0 = std::max(0.0, std::ceil(c.x - half - 0.5)),
                 x1 = std::min(double(W) - 1, std::floor(c.x + half - 0.5));
    if (x1 >= x0) n += x1 - x0 + 1;
  }
  return n;
}

class LodMask final : public Technique {
 public:
  LodMask(const TechniqueConfig& c, const ParamValues& v)
      : display_(c.display),
        inner_deg_(v.real("inner_deg")),
        outer_deg_(v.real("outer_deg")),
        hold_px_(v.real("hold_deg") > 0.0 ? display_.radius_px_at(v.real("hold_deg")) : 0.0) {}

  void reset() override { held_ = false; }

  // Radii of the two circles around their centre: the LOD radii at this
  // gaze (fovea scale, latency travel) grown by the hold distance.
  std::pair<double, double> radii(const GazeState& g) const {
    const double extra = latency_travel_deg(g);
    return {display_.radius_px_at(inner_deg_ * g.fovea_scale + extra) + hold_px_,
            display_.radius_px_at(outer_deg_ * g.fovea_scale + extra) + hold_px_};
  }

  // The circles' centre (top-left pixels): the held one while the gaze stays
  // within hold_px_ of it, otherwise the gaze.
  Vec2d centre(const GazeState& g) const {
    if (held_ && std::hypot(g.gaze_px.x - held_centre_.x, g.gaze_px.y - held_centre_.y) <= hold_px_)
      return held_centre_;
    return g.gaze_px;
  }

  FrameStats render(Scene& scene, const FrameInput&, const GazeState& gaze,
                    const gpu::RenderTarget& target) override {
    const int W = target.width(), H = target.height();
    held_centre_ = centre(gaze);
    held_ = true;
    const Vec2d g = to_gl(held_centre_, H);
    const auto [r_in, r_out] = radii(gaze);
    const View view = View::full(W, H);
    // The scene draws into its own G-buffer (bound and cleared by
    // prepass_begin); the stencil marks which LOD owns each pixel (2 inside
    // the inner circle, 1 in the ring, 0 outside) before anything is drawn,
    // and each LOD writes only its own pixels: where it has no surface the
    // G-buffer stays cleared and the background shows, as in native.
    // The masks are drawn over their discs only, and each finer LOD is drawn
    // for the part of the screen its circle spans (geometry outside it is
    // culled, and the scissor keeps the rasteriser within it), so no
    // full-screen pass is paid beyond the coarse LOD's; a coarser LOD leaves
    // out the objects that lie wholly inside the finer circle.
    // Where the outer circle covers the screen (the default on the built-in
    // displays: the coarse LOD's error would show everywhere), the ring is
    // everything outside the inner circle and the coarse LOD is not drawn.
    const bool outer_covers = std::hypot(std::max(g.x, W - g.x), std::max(g.y, H - g.y)) <= r_out;
    scene.prepass_begin(view);
    mask(g, r_in, W, H, GL_ALWAYS, 2, GL_REPLACE);
    if (!outer_covers) mask(g, r_out, W, H, GL_EQUAL, 0, GL_INCR);  // the ring: 0 -> 1
    gpu::PassState draw = gpu::PassState::stencil_equal();
    for (int lod = 0; lod < (outer_covers ? 2 : 3); ++lod) {
      View part = lod == 2 ? view : bounds(view, g, lod == 0 ? r_in : r_out);
      // Objects wholly inside the square inscribed in the next finer circle
      // are all under its mask: this LOD would draw nothing of them.
      if (lod > 0) {
        const double half = (lod == 1 ? r_in : r_out) / std::sqrt(2.0) - 1.0;
        part.skip_x0 = g.x - half;
        part.skip_y0 = g.y - half;
        part.skip_x1 = g.x + half;
        part.skip_y1 = g.y + half;
      }
      draw.stencil_ref = outer_covers && lod == 1 ? 0 : 2 - lod;
      draw.scissor = {int(part.x0), int(part.y0), int(part.x1 - part.x0), int(part.y1 - part.y0)};
      gpu::apply(draw);
      scene.prepass_draw(part, lod);
    }
    gpu::apply({});
    scene.prepass_end();
    const PixelCount shaded =
        kit_.shade(scene, view, kMapRect, target,
                   [&](const gpu::Program& p, gpu::Samplers&) { set_rect_mapping(p, view); });
    // Every pixel is lit (deferred); the parts say how many pixels got their
    // geometry from each LOD: pixel centres inside each stencil circle.
    const double in = pixels_in_disc(g, r_in, W, H), out = pixels_in_disc(g, r_out, W, H);
    FrameStats s;
    s.parts = {{"lod 0 (full detail)", in},
               {"lod 1 (about 10 %)", out - in},
               {"lod 2 (about 1 %)", double(W) * H - out}};
    s.shaded_pixels = shaded.read();
    s.native_pixels = double(W) * H;
    return s;
  }

  std::vector<OverlayShape> overlay(const GazeState& gaze) const override {
    const auto [r_in, r_out] = radii(gaze);
    const Vec2d c = centre(gaze);
    const auto* a = kRingColours[0];
    const auto* b = kRingColours[1];
    return {{OverlayShape::Kind::Circle, c.x, c.y, r_in, 0, a[0], a[1], a[2],
             "full-detail LOD inside (LOD 0)"},
            {OverlayShape::Kind::Circle, c.x, c.y, r_out, 0, b[0], b[1], b[2],
             "mid-detail LOD inside (LOD 1); coarse LOD beyond"},
            gaze_dot(gaze)};
  }

 private:
  // Inside the circle, where the stencil test (func, ref) passes, applies
  // `op` to the stencil; nothing else is written. Draws into the G-buffer
  // the prepass bound.
  void mask(Vec2d g, double radius, int W, int H, GLenum func, int ref, GLenum op) {
    const gpu::Program& p = kit_.over_rects("lodmask/mask.frag");
    p.set("u_centre", float(g.x), float(g.y));
    p.set("u_radius", float(radius));
    kit_.rect_pass_in_bound(p, disc_rects(g.x, g.y, radius, W, H), W, H,
                            gpu::PassState::stencil_mark(ref, func, op));
  }

  // The part of `full` that the disc of `radius` around `g` (GL pixels)
  // spans: the view a finer LOD is culled to.
  static View bounds(const View& full, Vec2d g, double radius) {
    View v = full;
    v.x0 = std::clamp(std::floor(g.x - radius) - 1.0, full.x0, full.x1);
    v.x1 = std::clamp(std::ceil(g.x + radius) + 1.0, full.x0, full.x1);
    v.y0 = std::clamp(std::floor(g.y - radius) - 1.0, full.y0, full.y1);
    v.y1 = std::clamp(std::ceil(g.y + radius) + 1.0, full.y0, full.y1);
    return v;
  }

  Display display_;
  double inner_deg_, outer_deg_;
  double hold_px_;
  bool held_ = false;
  Vec2d held_centre_{};
  PassKit kit_;
};

}  // namespace

TechniqueInfo lodmask_info() {
  TechniqueInfo t;
  t.name = "lodmask";
  t.summary =
      "Mesh level of detail per screen region: coarse LOD everywhere, finer LODs inside stencil "
      "circles around the gaze, deferred lighting. Mesh scenes only.";
  t.source = "Knapik and McGowen, Foveal Rendering, 2016";
  t.needs.meshes = true;
  t.needs.mesh_lods = true;
  // A coarser LOD moves silhouettes by its geometric (chord) error. Each LOD
  // has about a tenth of the previous one's triangles (Knapik and McGowen),
  // and on a smooth surface the chord error grows as 1 / triangles, so LOD k
  // errs by about kNativeErrorPx * 10^k pixels if native's LOD errs by half a
  // pixel. It may be drawn only where that is at most half a resolvable cycle
  // (the rule that places checkerboard's regions): w(e) ppd >= 2 * error, that
  // is w(e) >= error * w* (w* = 2 / ppd degrees per cycle).
  constexpr double kNativeErrorPx = 0.5, kLevelRatio = 10.0;
  const auto radius_for = [](const TechniqueConfig& c, int level) {
    const double error_px = kNativeErrorPx * std::pow(kLevelRatio, level);
    return std::min(90.0, c.acuity.eccentricity_for_mar(error_px * c.display.sharpness_deg()));
  };
  t.params = {
      plan_margin_param(2.0),
      {"inner_deg",
       "radius of the full-detail circle; default where half a resolvable cycle covers the mid "
       "LOD's silhouette error (about 10 x native's half pixel: w(e) = 5 w*)",
       "deg", ParamType::Real, 0.0, 90.0, 3.0,
       [radius_for](const TechniqueConfig& c, const ParamValues&) {
         return std::max(2.5, radius_for(c, 1));
       }},
      {"outer_deg",
       "radius of the mid-detail circle; default where half a resolvable cycle covers the "
       "coarse LOD's (100 x: w(e) = 50 w*; beyond the screen on the built-in displays, so the "
       "coarse LOD is not drawn)",
       "deg", ParamType::Real, 0.0, 90.0, 6.0,
       [radius_for](const TechniqueConfig& c, const ParamValues& v) {
         return std::max(v.real("inner_deg"), radius_for(c, 2));
       }},
  };
  t.params.push_back(param(
      "hold_deg",
      "the circles stay put while the gaze stays within this angle of their centre (fixational "
      "drift and microsaccades are under 0.5 deg, the gaze filter's deadband 0.3 deg) and are "
      "grown "
      "by it, so the full-detail circle always covers the gaze's; LOD borders then move only with "
      "saccades (0 = follow the gaze every frame)",
      "deg", ParamType::Real, 0.0, 10.0, 1.0));
  t.check = [](const ParamValues& v) {
    if (v.real("outer_deg") < v.real("inner_deg"))
      throw Error("lodmask parameter outer_deg must be >= inner_deg");
  };
  t.make = construct<LodMask>();
  return t;
}

}  // namespace foveate::tech
