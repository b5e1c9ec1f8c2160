#pragma once
// A foveation technique renders a scene (any foveate::Scene) into an output
// framebuffer for a gaze point, shading fewer pixels than native rendering
// where the acuity model says the eye cannot tell. Every parameter has a
// default derived from the acuity model and the display; users override any
// of them by key.
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "foveate/core/acuity.hpp"
#include "foveate/core/display.hpp"
#include "foveate/core/models.hpp"
#include "foveate/gpu/gl.hpp"
#include "foveate/scenes/scene.hpp"

namespace foveate {

/// What every technique is configured from.
struct TechniqueConfig {
  /// The display at the render resolution (Display::resized keeps its field of view).
  Display display;
  AcuityModel acuity;
  /// Overrides by key (see TechniqueInfo::params); unknown keys are errors.
  std::map<std::string, double> params;
};

/// The gaze for one frame, after filtering.
struct GazeState {
  Vec2d gaze_px{0.0, 0.0};   ///< pixels, origin top-left
  double fovea_scale = 1.0;  ///< > 1 widens every foveal region (tracker fallback)
  double latency_ms = 0.0;   ///< end-to-end gaze latency: regions grow by the saccade reach
  double saccade_deg_per_s = 200.0;
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
};

class Technique {
 public:
  virtual ~Technique() = default;
  [[nodiscard]] virtual std::string name() const = 0;
  /// The parameter values in use (defaults derived from the acuity model, then overrides).
  [[nodiscard]] virtual std::vector<std::pair<std::string, double>> parameters() const = 0;
  /// Renders one frame of `scene` into `target` (a framebuffer whose colour is
  /// display-sized RGBA8). Call scene.update(frame) first.
  virtual FrameStats render(Scene& scene, const FrameInput& frame, const GazeState& gaze,
                            GLuint target) = 0;
  /// Layer or region borders for the overlay at this gaze.
  [[nodiscard]] virtual std::vector<OverlayShape> overlay(const GazeState& gaze) const = 0;
  /// Forget temporal history (e.g. after a camera cut).
  virtual void reset() {}
};

struct ParamSpec {
  std::string key;
  std::string help;  ///< meaning and unit
  double min = 0.0;
  double max = 0.0;
  bool integer = false;
};

struct TechniqueInfo {
  std::string name;
  std::string summary;
  std::string source;  ///< the paper it implements
  std::vector<ParamSpec> params;
  std::function<std::unique_ptr<Technique>(const TechniqueConfig&)> make;
  /// The parameter values `make` would use (derived defaults + overrides), without GL.
  std::function<std::vector<std::pair<std::string, double>>(const TechniqueConfig&)> defaults;
};

/// All techniques, in a stable order: native, layered, logpolar, checkerboard, lodmask, inset.
const std::vector<TechniqueInfo>& techniques();
const TechniqueInfo& technique_info(const std::string& name);
/// Creates a technique; throws foveate::Error for an unknown name, an unknown
/// parameter key or a value out of range (naming both). Needs a current GL context.
std::unique_ptr<Technique> make_technique(const std::string& name, const TechniqueConfig& config);
/// Default values for a configuration (without creating GL objects).
std::vector<std::pair<std::string, double>> default_parameters(const std::string& name,
                                                               const TechniqueConfig& config);

/// Draws overlay shapes over a display-sized framebuffer. Owns GL objects:
/// create and destroy it while the context is current.
class OverlayRenderer {
 public:
  OverlayRenderer();
  ~OverlayRenderer();
  void draw(const std::vector<OverlayShape>& shapes, int width, int height, GLuint target);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace foveate
