// vrs: variable-rate shading with the rates the acuity model gives
// (core/shading_rate.hpp: per 16-px tile the coarsest of 1x1 .. 4x4 whose
// sample spacing keeps two samples per MAR cycle), as engines and headsets
// foveate today: the driver's (hardware_path.hpp) where it has it, else
// emulated (emulated_path.hpp). `fixed` takes the rates from the screen
// centre instead of the gaze (headsets without eye tracking).
#include <algorithm>
#include <array>
#include <optional>
#include <string>

#include "../registry/registry.hpp"
#include "emulated_path.hpp"
#include "hardware_path.hpp"

namespace foveate::tech {

namespace {

class Vrs final : public Technique {
 public:
  Vrs(const TechniqueConfig& c, const ParamValues& v)
      : display_(c.display),
        acuity_(c.acuity),
        tile_(v.integer("tile")),
        min_class_(v.real("min_class")),
        // The driver's coarse pixels cannot be reshaded at their edges: the
        // edges ask for the emulation (else the same plan would lose the
        // JOD they buy on a GPU only).
        simulate_(driver_rates(v) && v.boolean("simulate_driver") &&
                  !vrs::hardware_available(v.integer("tile"))),
        hardware_(driver_rates(v) && (simulate_ || vrs::hardware_available(v.integer("tile")))),
        fixed_(v.boolean("fixed")),
        hardware_path_(tile_, simulate_),
        emulated_path_(tile_, v.real("edge_contrast"), v.integer("edge_samples"), v.real("adapt"),
                       v.real("smooth")) {
    ShadingRateOptions o;
    o.tile_px = tile_;
    o.validate();
  }

  static bool driver_rates(const ParamValues& v) {
    return v.boolean("hardware") && v.real("edge_contrast") == 0.0;
  }

  // The rates for this gaze (GL grid: rows from the bottom, as the shaders
  // read them). The planner keeps what the display alone decides, and the
  // image is kept while the gaze holds still (a moving gaze costs CPU time
  // every frame: docs/performance.md).
  const ShadingRateImage& rates(const GazeState& g, int w, int h) const {
    if (!planner_ || planner_->display().width_px != w || planner_->display().height_px != h) {
      const Display d =
          w == display_.width_px && h == display_.height_px ? display_ : display_.resized(w, h);
      ShadingRateOptions o;
      o.tile_px = tile_;
      o.origin_bottom_left = true;
      planner_.emplace(d, acuity_, o);
      cached_ = false;
    }
    const Vec2d at = fixed_ ? planner_->display().principal_point() : g.gaze_px;
    const double travel = fixed_ ? 0.0 : latency_travel_deg(g);
    const double scale = fixed_ ? 1.0 : std::max(1.0, g.fovea_scale);
    const std::array<double, 4> key = {at.x, at.y, travel, scale};
    if (!cached_ || key != cached_key_) {
      cached_rates_ = planner_->image(at, travel, scale);
      cached_key_ = key;
      cached_ = true;
    }
    return cached_rates_;
  }

  FrameStats render(Scene& scene, const FrameInput&, const GazeState& gaze,
                    const gpu::RenderTarget& target) override {
    const ShadingRateImage& m = rates(gaze, target.width(), target.height());
    vrs::TileClasses classes = vrs::tile_classes(m);
    if (hardware_) return hardware_path_.render(kit_, scene, m, classes.of_tile, target);
    emulated_path_.adapt(classes, m.tiles_x, m.tiles_y, target.width(), target.height());
    vrs::merge_small_classes(classes, min_class_);
    return emulated_path_.render(kit_, scene, classes, m.tiles_x, m.tiles_y, target);
  }

  std::vector<OverlayShape> overlay(const GazeState& gaze) const override {
    const ShadingRateImage& m = rates(gaze, display_.width_px, display_.height_px);
    const Vec2d c = fixed_ ? display_.principal_point() : gaze.gaze_px;
    std::vector<OverlayShape> shapes = {
        {OverlayShape::Kind::Circle, c.x, c.y, vrs::native_radius(m, c), 0, 1, 0.1f, 0.1f}};
    shapes.push_back(gaze_dot(gaze));
    return shapes;
  }

 protected:
  std::vector<std::pair<std::string, double>> derived() const override {
    GazeState g;
    g.gaze_px = display_.principal_point();
    const ShadingRateImage& m = rates(g, display_.width_px, display_.height_px);
    return {{"native_radius_px", vrs::native_radius(m, g.gaze_px)},
            {"pixel_ratio", m.pixel_ratio()},
            {"fraction_4x4", m.fraction({4, 4})},
            {"hardware_path", hardware_ ? 1.0 : 0.0},
            {"simulated_driver", simulate_ ? 1.0 : 0.0}};
  }

 private:
  Display display_;
  AcuityModel acuity_;
  int tile_;
  double min_class_;
  bool simulate_;
  bool hardware_;
  bool fixed_;
  mutable std::optional<ShadingRatePlanner> planner_;
  mutable bool cached_ = false;
  mutable std::array<double, 4> cached_key_{};
  mutable ShadingRateImage cached_rates_;
  PassKit kit_;
  vrs::HardwarePath hardware_path_;
  vrs::EmulatedPath emulated_path_;
};

}  // namespace

TechniqueInfo vrs_info() {
  TechniqueInfo t;
  t.name = "vrs";
  t.summary =
      "Variable-rate shading with the acuity model's rates per tile (1x1 .. 4x4), tiles of busy "
      "content refined to 2x2 and tiles of smooth content coarsened a step from the last frame: "
      "the driver's (GL_NV_shading_rate_image) where it has it, else emulated: each rate class "
      "shaded at its reduced resolution over its tiles, reconstructed in linear light.";
  t.source = "VK_KHR_fragment_shading_rate / D3D12 VRS tier 2, rates from Guenter et al.'s model";
  t.params = {
      plan_margin_param(1.0),
      listed(tuned(param("tile", "shading-rate tile size", "px", ParamType::Integer, 8, 32, 16),
                   {8, 16}),
             {kShadingRateTiles.begin(), kShadingRateTiles.end()}),
      param("fixed",
            "rates from the lens centre (the principal point), not the gaze (no eye tracking)", "",
            ParamType::Boolean, 0, 1, 0),
  };
  t.params.push_back(tuned(
      param(
          "min_class",
          "a rate class with fewer than this fraction of the tiles is shaded at a finer class "
          "present (each class costs the emulation a pass of its own; 0 = every class as the model "
          "gives it)",
          "", ParamType::Real, 0.0, 0.5, 0.02),
      {0.0, 0.02, 0.05}));
  t.params.push_back(edge_contrast_param(
      "in the coarse classes, the emulation's only: above 0 vrs takes the emulation on every "
      "driver"));
  t.params.push_back(edge_samples_param(2.0));
  t.params.push_back(tuned(
      param("adapt",
            "content-adaptive rates, the emulation's only: a tile the model gives a rate of 4 in "
            "either axis is shaded at 2x2 while at least this share of its last frame's samples, "
            "4 pixels apart, differ from their neighbour by more than edge_contrast (0.25 when "
            "edges are off), and for 8 frames after; small objects and fine texture blur at a "
            "4-pixel spacing where smooth content does not (0 = off; the driver's rates, with "
            "edge_contrast=0, are not refined: plan those at margin 1.5, as foveate rates does)",
            "", ParamType::Real, 0.0, 1.0, 0.4),
      {0.0, 0.1, 0.25, 0.4, 0.5}));
  t.params.push_back(tuned(
      param("smooth",
            "content-adaptive rates for smooth content, the emulation's only: a tile the model "
            "gives 1x1 or 2x2 is shaded a step coarser (2x2 or 4x4) while every texel its last "
            "frame shaded lies within this share of its luminance of the mean of its two "
            "neighbours along each axis (four times that once coarsened: the same curvature at "
            "twice the spacing), where interpolating at the coarser spacing would change nothing "
            "the eye sees; a tile refined by adapt is not (0 = off)",
            "", ParamType::Real, 0.0, 0.5, 0.2),
      {0.0, 0.05, 0.1, 0.2}));
  t.params.push_back(param("hardware",
                           "shade with the driver's variable-rate shading "
                           "(GL_NV_shading_rate_image) where it has the extension with this "
                           "tile size and edge_contrast is 0; 0 = always the emulation",
                           "", ParamType::Boolean, 0, 1, 1));
  t.params.push_back(param("simulate_driver",
                           "with hardware=1 where the driver has no shading-rate image "
                           "(llvmpipe): take the hardware path anyway, the driver's coarse "
                           "fragments made from a full-resolution frame (as slow as native; "
                           "to test and judge that path without the GPU)",
                           "", ParamType::Boolean, 0, 1, 0));
  t.resolve_passes = {"hardware_reconstruct", "reconstruct", "reconstruct_copy"};
  t.make = construct<Vrs>();
  return t;
}

}  // namespace foveate::tech
