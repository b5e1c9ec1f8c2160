// Temporary: the metrics module is being written; bench runs with --no-quality.
#include "foveate/core/error.hpp"
#include "quality.hpp"

namespace foveate::app {
struct QualityAccumulator::Impl {};
QualityAccumulator::QualityAccumulator(const Display&, const AcuityModel&) {
  throw Error("image-quality metrics are not built yet: use --no-quality");
}
QualityAccumulator::~QualityAccumulator() = default;
void QualityAccumulator::add(const Image&, const Image&, Vec2d) {}
nlohmann::json QualityAccumulator::summary() const { return {}; }
double QualityAccumulator::flicker_ratio() const { return 0; }
Image QualityAccumulator::heatmap(const Image&, const Image&) { return {}; }
Image QualityAccumulator::acuity_heatmap(const Image&, const Image&, Vec2d) const { return {}; }
}  // namespace foveate::app
