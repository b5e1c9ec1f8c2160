// Quality over a sequence of frames: the per-frame reports averaged field by
// field, and peripheral flicker.
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "foveate/core/error.hpp"
#include "internal.hpp"

namespace foveate::metrics {

namespace {

// The numbers of a report that are averaged over frames. A number added to
// QualityReport or BandStats goes into one of these lists (or, when it is the
// same in every frame, is copied in mean_report); the static_asserts count the
// fields so that none is left out. to_json then writes it.
constexpr std::array kReportMeans{
    &QualityReport::luminance_ratio, &QualityReport::psnr_db,  &QualityReport::ssim,
    &QualityReport::acuity_rmse,     &QualityReport::jnd_mean, &QualityReport::visible_fraction,
    &QualityReport::flip_mean,       &QualityReport::flip_ppd};
constexpr std::array kBandMeans{&BandStats::psnr_db,          &BandStats::ssim,
                                &BandStats::pixels_fraction,  &BandStats::flip_mean,
                                &BandStats::acuity_rmse,      &BandStats::jnd_mean,
                                &BandStats::visible_fraction, &BandStats::luminance_ratio};
constexpr std::array kProfileMeans{&EccentricityProfile::pixels_fraction,
                                   &EccentricityProfile::acuity_rmse,
                                   &EccentricityProfile::jnd_mean};

// Besides the averaged numbers: from_deg and to_deg.
static_assert(sizeof(BandStats) == (kBandMeans.size() + 2) * sizeof(double),
              "a field was added to BandStats: average it in kBandMeans (series.cpp)");
// Besides the averaged vectors: bin_deg.
static_assert(sizeof(EccentricityProfile) ==
                  sizeof(double) + kProfileMeans.size() * sizeof(std::vector<double>),
              "a field was added to EccentricityProfile: average it in kProfileMeans (series.cpp)");
// Besides the averaged numbers: jnd_threshold, the profile, the contrast
// model, width, height and the bands.
static_assert(sizeof(QualityReport) == (kReportMeans.size() + 1) * sizeof(double) +
                                           sizeof(EccentricityProfile) + sizeof(ContrastModel) +
                                           2 * sizeof(int) + sizeof(std::vector<BandStats>),
              "a field was added to QualityReport: average it in kReportMeans (series.cpp)");

// Mean of the finite values; +inf when there were none but some were +inf
// (identical frames' PSNR); NaN when no value was defined.
class Mean {
 public:
  void add(double v) {
    if (std::isfinite(v)) {
      sum_ += v;
      ++finite_;
    } else if (v > 0.0) {  // false for NaN
      infinite_ = true;
    }
  }
  [[nodiscard]] double value() const {
    if (finite_ > 0) return sum_ / finite_;
    return infinite_ ? kInf : kNaN;
  }

 private:
  double sum_ = 0;
  int finite_ = 0;
  bool infinite_ = false;
};

// out.*field = the Mean of item->*field over the items, for every field.
template <class T, size_t N>
void average(const std::vector<const T*>& items, const std::array<double T::*, N>& fields, T& out) {
  for (double T::*field : fields) {
    Mean m;
    for (const T* item : items) m.add(item->*field);
    out.*field = m.value();
  }
}

// The reports of one series share their size, options and hence bands.
QualityReport mean_report(const std::vector<QualityReport>& reports) {
  QualityReport out;
  if (reports.empty()) return out;
  const QualityReport& first = reports.front();
  out.width = first.width;
  out.height = first.height;
  out.jnd_threshold = first.jnd_threshold;
  out.contrast = first.contrast;
  out.bands = first.bands;  // the edges; the numbers are replaced below
  std::vector<const QualityReport*> all;
  for (const QualityReport& r : reports) all.push_back(&r);
  average(all, kReportMeans, out);
  for (size_t b = 0; b < out.bands.size(); ++b) {
    std::vector<const BandStats*> band;
    for (const QualityReport& r : reports) band.push_back(&r.bands[b]);
    average(band, kBandMeans, out.bands[b]);
  }
  // The profile, bin by bin; frames whose eccentricities end earlier (the gaze
  // moved) have no value for the outer bins.
  out.profile.bin_deg = first.profile.bin_deg;
  size_t bins = 0;
  for (const QualityReport& r : reports) bins = std::max(bins, r.profile.acuity_rmse.size());
  for (auto field : kProfileMeans) {
    std::vector<double>& dst = out.profile.*field;
    dst.assign(bins, kNaN);
    for (size_t i = 0; i < bins; ++i) {
      Mean m;
      for (const QualityReport& r : reports) {
        const std::vector<double>& v = r.profile.*field;
        // A frame without the bin has no pixels there.
        m.add(i < v.size() ? v[i] : (field == &EccentricityProfile::pixels_fraction ? 0.0 : kNaN));
      }
      dst[i] = m.value();
    }
  }
  return out;
}

}  // namespace

QualitySeries::QualitySeries(Display display, QualityOptions options, double flicker_min_ecc_deg)
    : display_(std::move(display)),
      options_(std::move(options)),
      flicker_(display_, flicker_min_ecc_deg, options_.band_edges_deg) {
  detail::check_options(options_);
}

double QualitySeries::memory_estimate(int width, int height, int frames,
                                      const QualityOptions& options) {
  // Measured at 1920x1080 (maximum resident size of benchmarks judging 1
  // and 4 runs): about 150 bytes a pixel that a series keeps whatever the
  // frames (FovVideoVDP's tables, pyramids and filtered channels), and 8 for
  // each frame its temporal filters still reach (test and reference, 4 bytes
  // each), up to a window of 250 ms; the diagnostics add little per series.
  if (!options.fvvdp && !options.diagnostics) return 0.0;
  const double window = std::ceil(0.25 * options.fvvdp_options.fps);
  const double kept = options.fvvdp ? std::min(double(frames) + 1.0, window) : 1.0;
  return double(width) * double(height) * (150.0 + 8.0 * kept);
}

void QualitySeries::add(const Image& reference, const Image& test, Vec2d gaze_px, int stream) {
  if (stream < 0) throw Error("QualitySeries: stream must be >= 0, got " + std::to_string(stream));
  // Everything that can refuse the frame first, so that a refused frame
  // leaves the series as it was.
  std::optional<QualityReport> report;
  if (options_.diagnostics) report = compare(reference, test, display_, gaze_px, options_);
  if (options_.fvvdp && Fvvdp::fits(display_.width_px, display_.height_px)) {
    const auto s = static_cast<size_t>(stream);
    if (fvvdp_.size() <= s) fvvdp_.resize(s + 1);
    if (!fvvdp_[s]) {
      FvvdpOptions o = options_.fvvdp_options;
      o.band_edges_deg = options_.band_edges_deg;
      fvvdp_[s] = std::make_shared<Fvvdp>(display_, o);
    }
    fvvdp_[s]->set_heatmap(fvvdp_heatmap_);
    fvvdp_[s]->add(test, reference, gaze_px);
  }
  if (report) {
    flicker_.add(reference, test, gaze_px, stream);
    reports_.push_back(std::move(*report));
  }
  ++frames_;
}

void QualitySeries::set_fvvdp_heatmap(bool on) { fvvdp_heatmap_ = on; }

QualitySummary QualitySeries::summary() const {
  QualitySummary s;
  s.frames = frames();
  s.diagnostics = options_.diagnostics;
  for (const QualityReport& r : reports_) s.identical_frames += std::isinf(r.psnr_db) ? 1 : 0;
  s.mean = mean_report(reports_);
  s.flicker.ratio = flicker_.ratio();
  s.flicker.reference_change = flicker_.reference_change();
  s.flicker.test_change = flicker_.test_change();
  s.flicker.frame_pairs = flicker_.frame_pairs();
  s.flicker.bands = flicker_.bands();
  for (const auto& f : fvvdp_) {
    if (!f || f->frames() == 0) continue;
    s.fvvdp_streams.push_back(f->result());
    if (!s.fvvdp || s.fvvdp_streams.back().jod < s.fvvdp->jod) s.fvvdp = s.fvvdp_streams.back();
  }
  if (s.fvvdp_streams.size() < 2) s.fvvdp_streams.clear();
  return s;
}

}  // namespace foveate::metrics
