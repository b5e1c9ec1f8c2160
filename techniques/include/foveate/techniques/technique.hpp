#pragma once
// A foveation technique renders a scene (any foveate::Scene) into a render
// target for a gaze point, shading fewer pixels than native rendering where
// the acuity model says the eye cannot tell. Each technique declares each of
// its parameters once (ParamDecl: key, help, unit, type, range, and a default
// that is a constant or derived from the acuity model and the display); the
// registry, validation, `foveate techniques` and the JSON outputs all come
// from that declaration. Techniques written outside the tree register
// themselves at run time with register_technique().
#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "foveate/core/acuity.hpp"
#include "foveate/core/display.hpp"
#include "foveate/core/gaze_state.hpp"
#include "foveate/core/models.hpp"
#include "foveate/gpu/pass.hpp"
#include "foveate/scenes/scene.hpp"

namespace foveate {

/// What every technique is configured from.
struct TechniqueConfig {
  /// The display at the render resolution (Display::resized keeps its field of view).
  Display display;
  /// The acuity the metrics judge by; a technique plans for it made finer
  /// by its planning margin (kPlanMarginKey).
  AcuityModel acuity;
  /// Every technique's planning margin (1 = each paper's plan); unset, each
  /// technique's own default. params["margin"] overrides it.
  std::optional<double> margin;
  /// Overrides by key (see TechniqueInfo::params); unknown keys are errors.
  std::map<std::string, double> params;
};

enum class ParamType { Real, Integer, Boolean };
/// "real", "integer" or "boolean" (the technique listings' names).
const char* param_type_name(ParamType type);

/// Parameter values in declaration order, read by type.
class ParamValues {
 public:
  void set(const std::string& key, double value);
  [[nodiscard]] bool has(std::string_view key) const;
  /// The value; throws foveate::Error (an internal error) for an undeclared key.
  [[nodiscard]] double real(std::string_view key) const;
  [[nodiscard]] int integer(std::string_view key) const;
  [[nodiscard]] bool boolean(std::string_view key) const;
  [[nodiscard]] const std::vector<std::pair<std::string, double>>& items() const { return items_; }

 private:
  std::vector<std::pair<std::string, double>> items_;
};

/// One parameter of a technique, declared once.
struct ParamDecl {
  std::string key;
  std::string help;  ///< what it means (and where its default comes from)
  std::string unit;  ///< "deg", "px", "ms", "deg/s", or empty for a plain number
  ParamType type = ParamType::Real;
  double min = 0.0;
  double max = 1.0;
  double value = 0.0;  ///< the default when `derive` is not set
  /// A default derived from the configuration (acuity model, display) and the
  /// parameters declared before this one; clamped into [min, max].
  std::function<double(const TechniqueConfig&, const ParamValues& earlier)> derive;
  /// The values `foveate tune` tries for a parameter that trades quality for
  /// time (within [min, max]); empty: tune leaves it at its default.
  std::vector<double> tune = {};
  /// The only values it takes, when not every number in [min, max] of its
  /// type is meaningful (e.g. sample counts that fill a pattern); empty:
  /// any.
  std::vector<double> allowed = {};
  /// Whether `v` is among `allowed` (any value when it is empty).
  [[nodiscard]] bool takes(double v) const {
    return allowed.empty() || std::find(allowed.begin(), allowed.end(), v) != allowed.end();
  }
};

/// `decl` with the values tune tries.
inline ParamDecl tuned(ParamDecl decl, std::vector<double> values) {
  decl.tune = std::move(values);
  return decl;
}

/// `decl` taking only `values` (ParamDecl::allowed).
inline ParamDecl listed(ParamDecl decl, std::vector<double> values) {
  decl.allowed = std::move(values);
  return decl;
}

/// A parameter whose default is the constant `value`.
inline ParamDecl param(std::string key, std::string help, std::string unit, ParamType type,
                       double min, double max, double value) {
  return {std::move(key), std::move(help), std::move(unit), type, min, max, value, {}, {}, {}};
}

/// The key of the planning margin: a technique that declares it (every
/// built-in one but native) plans its layers, rates, regions or circles for
/// the acuity model made this many times finer (AcuityModel::finer), while
/// the metrics keep judging by the model itself. Resolved before every other
/// parameter, so that defaults derived from the acuity model see the plan's.
inline constexpr const char* kPlanMarginKey = "margin";

/// The planning margin's declaration, with the technique's own default: the
/// one `foveate tune` chose, with the technique's other defaults, as its
/// fastest setting whose FovVideoVDP JOD stays within 0.25 of native's on
/// guenter and raymarch at 1920x1080 (docs/fidelity.md); 1 = the paper's
/// plan.
ParamDecl plan_margin_param(double fidelity_default);

/// The declaration of `edge_contrast`, the threshold of
/// PassKit::supersample_edges (texels reshaded with more samples where
/// their luminance differs from a neighbour's by more than this share of the
/// brighter; 0 = off), for the techniques that use it; `note` says what is
/// particular to the technique (may be empty).
ParamDecl edge_contrast_param(const std::string& note = {});

/// The declaration of `edge_samples`, the new samples
/// PassKit::supersample_edges shades in each texel it reshades: 2 on the
/// texel's diagonal averaged with its own centre sample, or 4 on a rotated
/// grid; `fallback` is the technique's default (tune's choice for it).
ParamDecl edge_samples_param(double fallback);

/// What a technique needs from a scene.
struct SceneNeeds {
  bool meshes = false;     ///< rasterised geometry with a G-buffer prepass
  bool mesh_lods = false;  ///< discrete LODs selectable per draw
};

struct PixelPart {
  std::string name;     ///< "layer 1", "region 0", "periphery", ...
  double pixels = 0.0;  ///< fragments shaded this frame (occlusion-query counted)
};

struct FrameStats {
  std::vector<PixelPart> parts;
  double shaded_pixels = 0.0;  ///< sum of parts
  double native_pixels = 0.0;  ///< width * height
};

/// A shape of the inspection overlay (Figure 1 of Guenter et al.).
struct OverlayShape {
  enum class Kind { Circle, Rect, Dot };
  Kind kind = Kind::Circle;
  double x = 0, y = 0;  ///< centre (circle, dot) or corner (rect), pixels, origin top-left
  double w = 0, h = 0;  ///< radius in w (circle, dot) or size (rect)
  float r = 1, g = 1, b = 1;
  /// What the shape marks ("layer 2 (2x subsampled) from 5.2 deg"), for legends.
  std::string label = {};
};

class Technique {
 public:
  virtual ~Technique() = default;
  /// The registered name (set by make_technique).
  [[nodiscard]] const std::string& name() const { return name_; }
  /// The resolved parameter values (declared defaults and overrides).
  [[nodiscard]] const ParamValues& values() const { return values_; }
  /// The display it was configured for; it renders targets of that size.
  [[nodiscard]] const Display& display() const { return display_; }
  /// The values in use, then figures derived from them (layer radii, buffer
  /// sizes) for reports.
  [[nodiscard]] std::vector<std::pair<std::string, double>> parameters() const;
  /// Renders one frame of `scene` into `target` (display-sized; the
  /// technique binds it and sets its own state for every pass). Call
  /// scene.update(frame) first (foveate::FrameRunner does both).
  virtual FrameStats render(Scene& scene, const FrameInput& frame, const GazeState& gaze,
                            const gpu::RenderTarget& target) = 0;
  /// Layer or region borders for the overlay at this gaze.
  [[nodiscard]] virtual std::vector<OverlayShape> overlay(const GazeState& gaze) const = 0;
  /// Forget temporal history (e.g. after a camera cut).
  virtual void reset() {}
  /// Frames after which the work per frame is steady: every layer rendered,
  /// history reprojected and each cadence running at least once (and every
  /// shader variant built). Benchmarks warm up at least this long.
  [[nodiscard]] virtual int settle_frames() const { return 2; }

 protected:
  /// Figures derived from the parameters, appended to parameters().
  [[nodiscard]] virtual std::vector<std::pair<std::string, double>> derived() const { return {}; }

 private:
  friend std::unique_ptr<Technique> make_technique(const std::string& name,
                                                   const TechniqueConfig& config);
  std::string name_;
  ParamValues values_;
  Display display_;
};

struct TechniqueInfo {
  std::string name;
  std::string summary;
  std::string source;  ///< the paper it implements
  std::vector<ParamDecl> params;
  SceneNeeds needs;
  /// The passes (by the names they are timed under: a PassKit pass's
  /// fragment file stem, or a gpu::ProfileScope's name) that resolve what the
  /// technique shaded at a lower rate or resolution into the output:
  /// composites, reconstructions, temporal passes, warps, blurs, upscales
  /// and copies. Reports sum their time as the frame's resolve share.
  std::vector<std::string> resolve_passes;
  /// Checks between parameters after overrides (throws foveate::Error); optional.
  std::function<void(const ParamValues&)> check;
  /// Creates the technique from its configuration and resolved parameters.
  std::function<std::unique_ptr<Technique>(const TechniqueConfig&, const ParamValues&)> make;
};

/// TechniqueInfo::make for a technique constructed as T(config, values).
template <class T>
auto construct() {
  return [](const TechniqueConfig& c, const ParamValues& v) -> std::unique_ptr<Technique> {
    return std::make_unique<T>(c, v);
  };
}

/// All techniques: the built-in ones (native, layered, logpolar, checkerboard,
/// lodmask, inset, vrs) in that order, then those registered at run time.
const std::vector<TechniqueInfo>& techniques();
/// The names of techniques(), in their order.
std::vector<std::string> technique_names();
/// Adds a technique; throws foveate::Error when the name is taken or empty,
/// or a parameter declaration is inconsistent (range, default, duplicate key).
void register_technique(TechniqueInfo info);
const TechniqueInfo& technique_info(const std::string& name);
/// Every parameter's value for `config`: declared defaults (derived ones
/// clamped into range), then config.params. Throws foveate::Error naming the
/// technique and the key for an unknown key, a value out of range or a
/// fraction where a whole number or 0/1 is declared.
ParamValues resolve_parameters(const TechniqueInfo& info, const TechniqueConfig& config);
/// Throws foveate::Error, as resolve_parameters does, when `value` is not a
/// value the technique's parameter `key` can take (or it has no such key).
void check_parameter(const TechniqueInfo& info, const std::string& key, double value);
/// The values a parameter takes (ParamDecl::allowed) as a message says
/// them: "2 or 4", "1, 2, 4, 9 or 16"; empty when any in its range.
std::string allowed_text(const ParamDecl& p);
/// `config` with the acuity the technique plans for: made finer by its
/// planning margin (kPlanMarginKey) where it declares one. make_technique
/// hands this to TechniqueInfo::make.
TechniqueConfig planning_config(const TechniqueConfig& config, const ParamValues& values);
/// Creates a technique (resolve_parameters, then make). Needs a current GL context.
std::unique_ptr<Technique> make_technique(const std::string& name, const TechniqueConfig& config);
/// Why `scene` cannot be rendered by the technique, or empty when it can.
std::string scene_mismatch(const TechniqueInfo& info, const SceneInfo& scene);
/// Throws foveate::Error with scene_mismatch's reason.
void check_scene(const TechniqueInfo& info, const SceneInfo& scene);

}  // namespace foveate
