// Reading back what to_json wrote (QualitySummary, FvvdpResult): merged
// benchmark shards and combined reports start from results.json.
#include <cmath>
#include <nlohmann/json.hpp>

#include "foveate/core/error.hpp"
#include "foveate/metrics/metrics.hpp"

namespace foveate::metrics {

namespace {

// A number written by to_json: null stands for NaN (or, with `infinite`,
// for +inf: an identical image's PSNR, a band without end).
double number_at(const nlohmann::json& j, const char* key, bool infinite = false) {
  const auto it = j.find(key);
  if (it == j.end() || it->is_null()) return infinite ? kInf : kNaN;
  if (!it->is_number()) throw Error(std::string(key) + ": expected a number");
  return it->get<double>();
}

std::vector<double> numbers_at(const nlohmann::json& j, const char* key) {
  std::vector<double> out;
  const auto it = j.find(key);
  if (it == j.end()) return out;
  for (const auto& v : *it) out.push_back(v.is_null() ? kNaN : v.get<double>());
  return out;
}

QualityReport report_from_json(const nlohmann::json& j) {
  QualityReport r;
  r.width = j.value("width", 0);
  r.height = j.value("height", 0);
  const bool identical = j.value("identical", false);
  r.psnr_db = number_at(j, "psnr_db", identical);
  r.ssim = number_at(j, "ssim");
  r.acuity_rmse = number_at(j, "acuity_rmse");
  r.jnd_mean = number_at(j, "jnd_mean");
  r.visible_fraction = number_at(j, "visible_fraction");
  r.luminance_ratio = number_at(j, "luminance_ratio");
  r.jnd_threshold = j.value("jnd_threshold", 1.0);
  if (const auto c = j.find("contrast_model"); c != j.end() && c->is_object()) {
    r.contrast.peak_cd_m2 = c->value("peak_cd_m2", r.contrast.peak_cd_m2);
    r.contrast.black_cd_m2 = c->value("black_cd_m2", r.contrast.black_cd_m2);
    r.contrast.field_deg = c->value("field_deg", r.contrast.field_deg);
    r.contrast.pooling_beta = c->value("pooling_beta", r.contrast.pooling_beta);
  }
  r.flip_mean = number_at(j, "flip_mean");
  r.flip_ppd = number_at(j, "flip_ppd");
  if (const auto p = j.find("eccentricity_profile"); p != j.end() && p->is_object()) {
    r.profile.bin_deg = p->value("bin_deg", 1.0);
    r.profile.pixels_fraction = numbers_at(*p, "pixels_fraction");
    r.profile.acuity_rmse = numbers_at(*p, "acuity_rmse");
    r.profile.jnd_mean = numbers_at(*p, "jnd_mean");
  }
  for (const auto& b : j.value("bands", nlohmann::json::array())) {
    BandStats s;
    s.from_deg = b.value("from_deg", 0.0);
    s.to_deg = number_at(b, "to_deg", true);
    s.pixels_fraction = b.value("pixels_fraction", 0.0);
    s.psnr_db = number_at(b, "psnr_db", b.value("identical", false));
    s.ssim = number_at(b, "ssim");
    s.acuity_rmse = number_at(b, "acuity_rmse");
    s.jnd_mean = number_at(b, "jnd_mean");
    s.visible_fraction = number_at(b, "visible_fraction");
    s.luminance_ratio = number_at(b, "luminance_ratio");
    s.flip_mean = number_at(b, "flip_mean");
    r.bands.push_back(s);
  }
  return r;
}

}  // namespace

FvvdpResult fvvdp_result_from_json(const nlohmann::json& j) {
  FvvdpResult r;
  r.jod = number_at(j, "jod");
  r.frames = j.value("frames", 0);
  r.image = j.value("image", false);
  r.fps = j.value("fps", 0.0);
  r.foveated = j.value("foveated", true);
  r.pixels_per_degree = j.value("pixels_per_degree", 0.0);
  if (const auto p = j.find("photometry"); p != j.end() && p->is_object()) {
    r.photometry.peak_cd_m2 = p->value("peak_cd_m2", r.photometry.peak_cd_m2);
    r.photometry.contrast_ratio = p->value("contrast_ratio", r.photometry.contrast_ratio);
    r.photometry.ambient_lux = p->value("ambient_lux", r.photometry.ambient_lux);
    r.photometry.reflectivity = p->value("reflectivity", r.photometry.reflectivity);
  }
  for (const auto& b : j.value("bands", nlohmann::json::array())) {
    FvvdpBand s;
    s.from_deg = b.value("from_deg", 0.0);
    s.to_deg = number_at(b, "to_deg", true);
    s.jod = number_at(b, "jod");
    s.pixels_fraction = b.value("pixels_fraction", 0.0);
    r.bands.push_back(s);
  }
  r.frame_jod = numbers_at(j, "frame_jod");
  return r;
}

QualitySummary quality_summary_from_json(const nlohmann::json& j) {
  QualitySummary s;
  s.frames = j.value("frames", 0);
  s.diagnostics = j.value("diagnostics", true);
  s.identical_frames = j.value("identical_frames", 0);
  s.mean = report_from_json(j);
  s.flicker.ratio = number_at(j, "flicker_ratio");
  s.flicker.reference_change = number_at(j, "flicker_reference_change");
  s.flicker.test_change = number_at(j, "flicker_test_change");
  for (const auto& b : j.value("flicker_bands", nlohmann::json::array())) {
    FlickerBand f;
    f.from_deg = b.value("from_deg", 0.0);
    f.to_deg = number_at(b, "to_deg", true);
    f.reference_change = number_at(b, "reference_change");
    f.test_change = number_at(b, "test_change");
    f.test_change_last = number_at(b, "test_change_last");
    f.excess_change = number_at(b, "excess_change");
    f.ratio = number_at(b, "ratio");
    s.flicker.bands.push_back(f);
  }
  if (const auto f = j.find("fvvdp"); f != j.end() && f->is_object()) {
    s.fvvdp = fvvdp_result_from_json(*f);
  }
  for (const auto& f : j.value("fvvdp_streams", nlohmann::json::array())) {
    s.fvvdp_streams.push_back(fvvdp_result_from_json(f));
  }
  return s;
}

}  // namespace foveate::metrics
