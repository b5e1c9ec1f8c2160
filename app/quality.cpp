#include "quality.hpp"

#include <cmath>
#include <limits>

#include "foveate/metrics/metrics.hpp"

namespace foveate::app {

struct QualityAccumulator::Impl {
  Display display;
  metrics::QualityOptions options;
  std::vector<metrics::QualityReport> reports;
  metrics::FlickerTracker flicker;
};

QualityAccumulator::QualityAccumulator(const Display& display, const AcuityModel& acuity)
    : impl_(std::make_unique<Impl>()) {
  impl_->display = display;
  impl_->options.acuity = acuity;
  impl_->flicker = metrics::FlickerTracker(display);
}

QualityAccumulator::~QualityAccumulator() = default;

void QualityAccumulator::add(const Image& reference, const Image& test, Vec2d gaze_px) {
  impl_->reports.push_back(
      metrics::compare(reference, test, impl_->display, gaze_px, impl_->options));
  impl_->flicker.add(reference, test, gaze_px);
}

nlohmann::json QualityAccumulator::summary() const {
  const auto& rs = impl_->reports;
  if (rs.empty()) return nlohmann::json::object();
  // Means over frames; PSNR averaged in dB over frames that differ (identical
  // frames have infinite PSNR and are counted separately).
  auto mean = [&](auto get) {
    double s = 0;
    int n = 0;
    for (const auto& r : rs) {
      const double v = get(r);
      if (std::isfinite(v)) s += v, ++n;
    }
    return n ? s / n : std::numeric_limits<double>::quiet_NaN();
  };
  nlohmann::json j = metrics::to_json(rs.back());
  auto num = [](double v) {
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
  };
  int identical = 0;
  for (const auto& r : rs) identical += std::isinf(r.psnr_db) ? 1 : 0;
  j["frames"] = rs.size();
  j["identical_frames"] = identical;
  j["psnr_db"] = num(mean([](const auto& r) { return r.psnr_db; }));
  j["ssim"] = num(mean([](const auto& r) { return r.ssim; }));
  j["acuity_rmse"] = num(mean([](const auto& r) { return r.acuity_rmse; }));
  j["acuity_visible_fraction"] = num(mean([](const auto& r) { return r.acuity_visible_fraction; }));
  j["flip_mean"] = num(mean([](const auto& r) { return r.flip_mean; }));
  for (size_t b = 0; b < rs.back().bands.size(); ++b) {
    j["bands"][b]["psnr_db"] =
        num(mean([&](const auto& r) { return b < r.bands.size() ? r.bands[b].psnr_db : NAN; }));
    j["bands"][b]["ssim"] =
        num(mean([&](const auto& r) { return b < r.bands.size() ? r.bands[b].ssim : NAN; }));
  }
  j["flicker_ratio"] = num(flicker_ratio());
  return j;
}

double QualityAccumulator::flicker_ratio() const { return impl_->flicker.ratio(); }

Image QualityAccumulator::heatmap(const Image& reference, const Image& test) {
  return metrics::error_heatmap(reference, test, 64.0);
}

Image QualityAccumulator::acuity_heatmap(const Image& reference, const Image& test,
                                         Vec2d gaze_px) const {
  return metrics::acuity_error_heatmap(reference, test, impl_->display, gaze_px, impl_->options);
}

}  // namespace foveate::app
