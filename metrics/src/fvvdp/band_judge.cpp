#include "fvvdp/band_judge.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <tuple>

#include "foveate/core/error.hpp"
#include "fvvdp/fast_math.hpp"
#include "fvvdp/kernels.hpp"
#include "fvvdp/pyramid.hpp"

namespace foveate::metrics::fvvdp {

namespace {

// Building a table evaluates the CSF model 32768 times; tables are shared
// between metric instances with the same parameters.
std::shared_ptr<const SensitivityTable> shared_table(double omega_hz, const FvvdpParameters& p) {
  using Key = std::tuple<double, double, double, double>;
  static std::mutex mutex;
  static std::map<Key, std::shared_ptr<const SensitivityTable>> cache;
  const Key key{omega_hz, p.csf_sigma, p.k_cm, p.sensitivity_correction_db};
  const std::lock_guard lock(mutex);
  auto it = cache.find(key);
  if (it == cache.end()) {
    it = cache.emplace(key, std::make_shared<SensitivityTable>(make_sensitivity_table(omega_hz, p)))
             .first;
  }
  return it->second;
}

}  // namespace

struct BandJudge::Scratch {
  bool gaze_set = false;
  Vec2d gaze{};
  std::vector<SamplePositions> positions;           // [band], foveated mode
  std::vector<std::vector<std::int8_t>> ecc_bands;  // [band][sample]: band index or -1
  std::vector<std::vector<double>> ecc_samples;     // [ecc band][band]
  std::vector<float> ecc;
  std::vector<Map> expanded;
  std::vector<std::vector<Map>> pyramid;  // [channel][level - 1]
  Map rows;
  std::vector<std::int32_t> luminance_lo;
  std::vector<float> luminance_frac, dbeta;
  std::array<std::vector<float>, 2> log_s;
};

BandJudge::BandJudge(const Display& display, const FvvdpOptions& options,
                     const FvvdpParameters& parameters)
    : options_(options),
      parameters_(parameters),
      width_(display.width_px),
      height_(display.height_px),
      geometry_(display, 0),
      scratch_(std::make_unique<Scratch>()) {
  bands_ = band_count(width_, height_, geometry_.pixels_per_degree());
  if (bands_ < 1) {
    throw Error("FovVideoVDP: a " + std::to_string(width_) + "x" + std::to_string(height_) +
                " frame is too small (at least 4 pixels on each side)");
  }
  geometry_ = ViewGeometry(display, bands_);
  tables_[0] = shared_table(0.0, parameters_);
  tables_[1] = shared_table(parameters_.transient_omega_hz, parameters_);
  if (options_.foveated) {
    rho_positions_.resize(static_cast<size_t>(bands_));
    for (int b = 0; b < bands_; ++b) {
      const LevelGeometry& g = geometry_.level(b);
      const double f = band_frequency(b, geometry_.pixels_per_degree());
      auto& pos = rho_positions_[static_cast<size_t>(b)];
      pos.resize(g.magnification.size());
      for (size_t i = 0; i < pos.size(); ++i) {
        pos[i] = tables_[0]->locate_rho(static_cast<float>(f * g.magnification[i]));
      }
    }
  }
}

BandJudge::~BandJudge() = default;
BandJudge::BandJudge(BandJudge&&) noexcept = default;

void BandJudge::update_gaze(Vec2d gaze_px) const {
  Scratch& s = *scratch_;
  if (s.gaze_set && s.gaze.x == gaze_px.x && s.gaze.y == gaze_px.y) return;
  s.gaze_set = true;
  s.gaze = gaze_px;
  const size_t n_ecc = options_.band_edges_deg.size();
  s.positions.resize(static_cast<size_t>(bands_));
  s.ecc_bands.resize(static_cast<size_t>(bands_));
  s.ecc_samples.assign(n_ecc, std::vector<double>(static_cast<size_t>(bands_), 0.0));
  std::vector<double> counts(n_ecc);
  for (int b = 0; b < bands_; ++b) {
    std::fill(counts.begin(), counts.end(), 0.0);
    geometry_.bands(b, gaze_px, options_.band_edges_deg, s.ecc_bands[static_cast<size_t>(b)],
                    counts);
    for (size_t e = 0; e < n_ecc; ++e) s.ecc_samples[e][static_cast<size_t>(b)] = counts[e];
    if (options_.foveated) {
      geometry_.eccentricity(b, gaze_px, s.ecc);
      const auto& rho = rho_positions_[static_cast<size_t>(b)];
      auto& pos = s.positions[static_cast<size_t>(b)];
      pos.resize(s.ecc.size());
      // The eccentricity axis is uniform in the square root (taken as exactly so).
      const SensitivityTable& t = *tables_[0];
      constexpr int last = SensitivityTable::kSize - 1;
      const float inv_step = static_cast<float>(last) / t.ecc_sqrt[last];
      for (size_t i = 0; i < s.ecc.size(); ++i) {
        const float u = std::min(std::sqrt(std::min(s.ecc[i], t.ecc[last])) * inv_step,
                                 static_cast<float>(last));
        const int lo = std::min(static_cast<int>(u), last - 1);
        pos.set(i, rho[i], {lo, lo + 1, u - static_cast<float>(lo)});
      }
    }
  }
}

std::vector<double> BandJudge::ecc_band_fractions(Vec2d gaze_px) const {
  update_gaze(gaze_px);
  std::vector<double> out;
  const double n = static_cast<double>(width_) * height_;
  for (const auto& per_band : scratch_->ecc_samples) out.push_back(per_band[0] / n);
  return out;
}

void BandJudge::judge_band(int band, const std::vector<const Map*>& fine,
                           const std::vector<const Map*>& coarse, int temporal_channels,
                           FrameDifference& out, Map* distortion_band) const {
  Scratch& s = *scratch_;
  const int w = fine[0]->width, h = fine[0]->height;
  const size_t n = static_cast<size_t>(w) * h;
  const size_t channels = fine.size();
  s.expanded.resize(channels);
  for (size_t c = 0; c < channels; ++c) expand(*coarse[c], w, h, s.expanded[c], s.rows);

  // Local adaptation: the reference's sustained channel one level coarser.
  const float* background = s.expanded[1].values.data();
  s.luminance_lo.resize(n);
  s.luminance_frac.resize(n);
  luminance_positions(background, n, *tables_[0], s.luminance_lo.data(), s.luminance_frac.data());

  // log2 sensitivity of every sample for each temporal channel's table.
  for (int cc = 0; cc < temporal_channels; ++cc) s.log_s[static_cast<size_t>(cc)].resize(n);
  if (options_.foveated) {
    const bool both = temporal_channels > 1;
    sensitivity_per_sample(s.luminance_lo.data(), s.luminance_frac.data(),
                           s.positions[static_cast<size_t>(band)], n, tables_[0]->values.data(),
                           both ? tables_[1]->values.data() : nullptr, s.log_s[0].data(),
                           both ? s.log_s[1].data() : nullptr);
  } else {
    for (int cc = 0; cc < temporal_channels; ++cc) {
      // Frequency and eccentricity are the same everywhere: interpolate the
      // table once along them, then per sample along luminance only.
      const SensitivityTable& t = *tables_[static_cast<size_t>(cc)];
      const AxisPosition r =
          t.locate_rho(static_cast<float>(band_frequency(band, geometry_.pixels_per_degree())));
      const AxisPosition e = t.locate_ecc(0.0f);
      std::array<float, SensitivityTable::kSize> column{};
      for (int j = 0; j < SensitivityTable::kSize; ++j) {
        column[static_cast<size_t>(j)] = t.lookup({j, j, 0.0f}, r, e);
      }
      sensitivity_from_column(s.luminance_lo.data(), s.luminance_frac.data(), n, column.data(),
                              s.log_s[static_cast<size_t>(cc)].data());
    }
  }

  // Contrast (Weber, against the adapting luminance), masking and pooling.
  const FvvdpParameters& p = parameters_;
  MaskingConstants k{};
  k.band_gain = band == 0 ? 1.0f : 2.0f;
  k.log2_k = static_cast<float>(p.mask_c * std::log2(10.0));
  k.p = static_cast<float>(p.mask_p);
  k.beta = static_cast<float>(p.beta);
  k.log2_d_max = std::log2(1e4f);
  if (distortion_band) {
    *distortion_band = Map(w, h, 0.0f);
    s.dbeta.resize(n);
  }
  const auto& ecc_bands = s.ecc_bands[static_cast<size_t>(band)];
  const size_t n_ecc = options_.band_edges_deg.size();
  for (int cc = 0; cc < temporal_channels; ++cc) {
    k.q = static_cast<float>(cc == 0 ? p.mask_q_sustained : p.mask_q_transient);
    const auto c = static_cast<size_t>(2 * cc);
    PooledDifference pooled;
    pooled.by_ecc_band.assign(n_ecc, 0.0);
    masked_difference(fine[c]->values.data(), s.expanded[c].values.data(),
                      fine[c + 1]->values.data(), s.expanded[c + 1].values.data(), background,
                      s.log_s[static_cast<size_t>(cc)].data(), ecc_bands.data(), n, k, pooled,
                      distortion_band ? s.dbeta.data() : nullptr);
    out.mean[static_cast<size_t>(band)][static_cast<size_t>(cc)] =
        pooled.all / static_cast<double>(n);
    for (size_t e = 0; e < n_ecc; ++e) {
      const double count = s.ecc_samples[e][static_cast<size_t>(band)];
      out.by_ecc[e][static_cast<size_t>(band)][static_cast<size_t>(cc)] =
          count > 0 ? pooled.by_ecc_band[e] / count : 0.0;
    }
    if (distortion_band) {
      // The heat map pools the channels linearly (transient weighted).
      const auto weight =
          static_cast<float>((cc == 0 ? 1.0 : p.w_transient) / static_cast<double>(k.band_gain));
      const float inv_beta = 1.0f / k.beta;
      for (size_t i = 0; i < n; ++i) {
        distortion_band->values[i] += weight * fast_exp2(inv_beta * fast_log2(s.dbeta[i]));
      }
    }
  }
}

FrameDifference BandJudge::judge(const FrameChannels& frame, Vec2d gaze_px,
                                 bool want_distortion) const {
  for (const Map& m : frame.planes) {
    if (m.width != width_ || m.height != height_) {
      throw Error("FovVideoVDP: a frame is " + std::to_string(m.width) + "x" +
                  std::to_string(m.height) + ", the display " + std::to_string(width_) + "x" +
                  std::to_string(height_));
    }
  }
  update_gaze(gaze_px);
  const int tc = frame.temporal_channels();
  const size_t channels = frame.planes.size();
  FrameDifference out;
  out.bands = bands_;
  out.mean.assign(static_cast<size_t>(bands_), {0.0, 0.0});
  const size_t n_ecc = options_.band_edges_deg.size();
  out.by_ecc.assign(n_ecc, std::vector<std::array<double, 2>>(static_cast<size_t>(bands_)));
  out.ecc_samples = scratch_->ecc_samples;

  // Gaussian pyramids: level 0 is the frame itself.
  Scratch& s = *scratch_;
  s.pyramid.resize(channels);
  const auto level = [&](size_t c, int l) -> const Map* {
    return l == 0 ? &frame.planes[c] : &s.pyramid[c][static_cast<size_t>(l - 1)];
  };
  for (size_t c = 0; c < channels; ++c) {
    s.pyramid[c].resize(static_cast<size_t>(bands_));
    for (int l = 1; l <= bands_; ++l) {
      reduce(*level(c, l - 1), s.pyramid[c][static_cast<size_t>(l - 1)], s.rows);
    }
  }
  std::vector<Map> distortion_bands(want_distortion ? static_cast<size_t>(bands_) : 0);
  for (int b = 0; b < bands_; ++b) {
    std::vector<const Map*> fine, coarse;
    for (size_t c = 0; c < channels; ++c) {
      fine.push_back(level(c, b));
      coarse.push_back(level(c, b + 1));
    }
    judge_band(b, fine, coarse, tc, out,
               want_distortion ? &distortion_bands[static_cast<size_t>(b)] : nullptr);
  }
  if (want_distortion) {
    // Collapse the per-band maps like a Laplacian pyramid (the base band is
    // zero) and map to JOD below 10: |a| d^b.
    const Map* coarsest = level(0, bands_);
    Map image(coarsest->width, coarsest->height, 0.0f), up;
    for (int b = bands_ - 1; b >= 0; --b) {
      const Map& band = distortion_bands[static_cast<size_t>(b)];
      expand(image, band.width, band.height, up, s.rows);
      for (size_t i = 0; i < up.values.size(); ++i) up.values[i] += band.values[i];
      std::swap(image, up);
    }
    const auto b_jod = static_cast<float>(std::pow(10.0, parameters_.log_jod_exp));
    const auto a = static_cast<float>(std::abs(parameters_.jod_a));
    for (float& v : image.values) v = a * fast_exp2(b_jod * fast_log2(v));
    out.distortion = std::move(image);
  }
  return out;
}

}  // namespace foveate::metrics::fvvdp
