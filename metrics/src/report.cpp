// The whole-frame comparison, the JSON form of reports and summaries, and the heatmaps.
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "foveate/core/error.hpp"
#include "internal.hpp"

namespace foveate::metrics {

namespace {

nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

}  // namespace

void detail::check_options(const QualityOptions& o) {
  const auto& e = o.band_edges_deg;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!std::isfinite(e[i]) || e[i] < 0.0) {
      throw Error("quality options: band edges must be finite and >= 0 degrees");
    }
    if (i > 0 && e[i] <= e[i - 1]) throw Error("quality options: band edges must be ascending");
  }
  if (e.size() > 250) throw Error("quality options: at most 250 bands");
  if (!(o.jnd_threshold >= 0.0) || !std::isfinite(o.jnd_threshold)) {
    throw Error("quality options: jnd_threshold must be finite and >= 0");
  }
  if (!(o.profile_bin_deg >= 0.1) || !std::isfinite(o.profile_bin_deg)) {
    throw Error("quality options: profile_bin_deg must be finite and >= 0.1 degrees");
  }
  if (!(o.acuity.slope > 0.0) || !(o.acuity.w0_deg > 0.0)) {
    throw Error("quality options: the acuity model needs slope > 0 and w0 > 0");
  }
  const ContrastModel& c = o.contrast;
  if (!std::isfinite(c.peak_cd_m2) || !(c.black_cd_m2 > 0.0) || !(c.peak_cd_m2 > c.black_cd_m2)) {
    throw Error("quality options: the contrast model needs 0 < black < peak (cd/m^2)");
  }
  if (!(c.field_deg > 0.0) || !std::isfinite(c.field_deg)) {
    throw Error("quality options: the CSF field size must be > 0 degrees");
  }
  if (!(c.pooling_beta >= 1.0) || !std::isfinite(c.pooling_beta)) {
    throw Error("quality options: the pooling exponent must be >= 1");
  }
}

std::vector<std::uint8_t> band_indices(const Map& ecc, const std::vector<double>& edges) {
  std::vector<std::uint8_t> out(ecc.values.size(), 255);
  for (size_t i = 0; i < ecc.values.size(); ++i) {
    const double e = ecc.values[i];
    // upper_bound: the first edge above e; the band is the one before it.
    const auto it = std::upper_bound(edges.begin(), edges.end(), e);
    if (it != edges.begin()) out[i] = static_cast<std::uint8_t>(it - edges.begin() - 1);
  }
  return out;
}

QualityReport compare(const Image& reference, const Image& test, const Display& display, Vec2d gaze,
                      const QualityOptions& options) {
  detail::check_same_size(reference, test, "compare");
  detail::check_options(options);
  detail::check_display(display, reference.width, reference.height, "compare");
  const int w = reference.width, h = reference.height;
  const size_t n = static_cast<size_t>(w) * h;
  QualityReport r;
  r.width = w;
  r.height = h;
  r.jnd_threshold = options.jnd_threshold;
  r.contrast = options.contrast;

  // Per-pixel squared error (RGB mean) for the global and per-band PSNR.
  std::vector<float> sq(n);
  {
    const std::uint8_t* a = reference.rgba.data();
    const std::uint8_t* b = test.rgba.data();
    for (size_t i = 0; i < n; ++i, a += 4, b += 4) {
      int s = 0;
      for (int c = 0; c < 3; ++c) s += (int(a[c]) - int(b[c])) * (int(a[c]) - int(b[c]));
      sq[i] = static_cast<float>(s);
    }
  }
  const Map ssim = ssim_map(reference, test);
  const Map ecc = eccentricity_map(display, gaze);
  Map diff(w, h), jnd, lum_ref, lum_test;
  {
    const detail::PyramidGeometry g = detail::pyramid_geometry(display, gaze, options.acuity, &ecc);
    const detail::AcuityPyramid a = detail::acuity_pyramid(detail::luminance_linear(reference), g);
    const detail::AcuityPyramid b = detail::acuity_pyramid(detail::luminance_linear(test), g);
    lum_ref = a.x0;
    lum_test = b.x0;
    for (size_t i = 0; i < n; ++i) {
      diff.values[i] = detail::luminance_to_code(a.filtered.values[i]) -
                       detail::luminance_to_code(b.filtered.values[i]);
    }
    jnd = detail::jnd_from_pyramids(a, b, g, options.contrast);
  }
  Map flip;
  if (options.flip) {
    r.flip_ppd = display.pixels_per_degree(gaze, gaze);
    flip = flip_map(reference, test, r.flip_ppd);
  }

  const std::vector<std::uint8_t> band = band_indices(ecc, options.band_edges_deg);
  const size_t nb = options.band_edges_deg.size();
  struct Acc {
    double sq = 0, ssim = 0, flip = 0, acu = 0, jnd = 0, visible = 0, count = 0;
    double lum_ref = 0, lum_test = 0;  // linear luminance sums
  };
  std::vector<Acc> acc(nb + 1);  // the last one is the whole image
  std::vector<Acc> bins;         // the eccentricity profile
  const double bin_deg = options.profile_bin_deg;
  for (size_t i = 0; i < n; ++i) {
    const double d = diff.values[i];
    const double j = jnd.values[i];
    const double vis = j >= options.jnd_threshold ? 1.0 : 0.0;
    for (size_t k : {size_t(band[i]), nb}) {
      if (k > nb) continue;  // pixel below the first band edge
      Acc& x = acc[k];
      x.sq += sq[i];
      x.ssim += ssim.values[i];
      x.acu += d * d;
      x.jnd += j;
      x.visible += vis;
      x.count += 1;
      x.lum_ref += lum_ref.values[i];
      x.lum_test += lum_test.values[i];
      if (options.flip) x.flip += flip.values[i];
    }
    const size_t bin = static_cast<size_t>(std::max(0.0, double(ecc.values[i]) / bin_deg));
    if (bin >= bins.size()) bins.resize(bin + 1);
    bins[bin].acu += d * d;
    bins[bin].jnd += j;
    bins[bin].count += 1;
  }
  auto psnr = [](const Acc& x) {
    if (x.count == 0) return kNaN;
    const double m = x.sq / (3.0 * x.count);
    return m == 0.0 ? kInf : 10.0 * std::log10(255.0 * 255.0 / m);
  };
  const Acc& all = acc[nb];
  r.psnr_db = psnr(all);
  r.ssim = all.ssim / all.count;
  r.acuity_rmse = std::sqrt(all.acu / all.count);
  r.jnd_mean = all.jnd / all.count;
  r.visible_fraction = all.visible / all.count;
  auto ratio = [](const Acc& x) { return x.lum_ref > 0 ? x.lum_test / x.lum_ref : kNaN; };
  r.luminance_ratio = ratio(all);
  r.flip_mean = options.flip ? all.flip / all.count : kNaN;
  for (size_t k = 0; k < nb; ++k) {
    BandStats b;
    b.from_deg = options.band_edges_deg[k];
    b.to_deg = k + 1 < nb ? options.band_edges_deg[k + 1] : kInf;
    const Acc& x = acc[k];
    b.pixels_fraction = x.count / all.count;
    if (x.count > 0) {
      b.psnr_db = psnr(x);
      b.ssim = x.ssim / x.count;
      b.acuity_rmse = std::sqrt(x.acu / x.count);
      b.jnd_mean = x.jnd / x.count;
      b.visible_fraction = x.visible / x.count;
      b.luminance_ratio = ratio(x);
      if (options.flip) b.flip_mean = x.flip / x.count;
    }
    r.bands.push_back(b);
  }
  r.profile.bin_deg = bin_deg;
  for (const Acc& x : bins) {
    r.profile.pixels_fraction.push_back(x.count / all.count);
    r.profile.acuity_rmse.push_back(x.count > 0 ? std::sqrt(x.acu / x.count) : kNaN);
    r.profile.jnd_mean.push_back(x.count > 0 ? x.jnd / x.count : kNaN);
  }
  return r;
}

nlohmann::json to_json(const QualityReport& r) {
  nlohmann::json j;
  j["width"] = r.width;
  j["height"] = r.height;
  j["identical"] = std::isinf(r.psnr_db);
  j["psnr_db"] = number(r.psnr_db);
  j["ssim"] = number(r.ssim);
  j["acuity_rmse"] = number(r.acuity_rmse);
  j["jnd_mean"] = number(r.jnd_mean);
  j["visible_fraction"] = number(r.visible_fraction);
  j["luminance_ratio"] = number(r.luminance_ratio);
  j["jnd_threshold"] = r.jnd_threshold;
  j["contrast_model"] = {{"csf", "Barten 1999 (simplified)"},
                         {"peak_cd_m2", r.contrast.peak_cd_m2},
                         {"black_cd_m2", r.contrast.black_cd_m2},
                         {"field_deg", r.contrast.field_deg},
                         {"pooling_beta", r.contrast.pooling_beta}};
  j["flip_mean"] = number(r.flip_mean);
  j["flip_ppd"] = number(r.flip_ppd);
  nlohmann::json fractions = nlohmann::json::array(), rmse = nlohmann::json::array(),
                 jnd = nlohmann::json::array();
  for (size_t i = 0; i < r.profile.acuity_rmse.size(); ++i) {
    fractions.push_back(number(r.profile.pixels_fraction[i]));
    rmse.push_back(number(r.profile.acuity_rmse[i]));
    jnd.push_back(number(r.profile.jnd_mean[i]));
  }
  j["eccentricity_profile"] = {{"bin_deg", r.profile.bin_deg},
                               {"pixels_fraction", fractions},
                               {"acuity_rmse", rmse},
                               {"jnd_mean", jnd}};
  nlohmann::json bands = nlohmann::json::array();
  for (const BandStats& b : r.bands) {
    bands.push_back({{"from_deg", b.from_deg},
                     {"to_deg", number(b.to_deg)},
                     {"pixels_fraction", b.pixels_fraction},
                     {"identical", std::isinf(b.psnr_db)},
                     {"psnr_db", number(b.psnr_db)},
                     {"ssim", number(b.ssim)},
                     {"acuity_rmse", number(b.acuity_rmse)},
                     {"jnd_mean", number(b.jnd_mean)},
                     {"visible_fraction", number(b.visible_fraction)},
                     {"luminance_ratio", number(b.luminance_ratio)},
                     {"flip_mean", number(b.flip_mean)}});
  }
  j["bands"] = bands;
  return j;
}

nlohmann::json to_json(const QualitySummary& s) {
  // Without the diagnostics only FovVideoVDP was measured: the rest is left
  // out rather than written as zeros and nulls that read as measured.
  nlohmann::json j = s.diagnostics ? to_json(s.mean) : nlohmann::json::object();
  j["frames"] = s.frames;
  j["diagnostics"] = s.diagnostics;
  if (s.diagnostics) {
    j["identical_frames"] = s.identical_frames;
    j["flicker_ratio"] = number(s.flicker.ratio);
    j["flicker_reference_change"] = number(s.flicker.reference_change);
    j["flicker_test_change"] = number(s.flicker.test_change);
    nlohmann::json bands = nlohmann::json::array();
    for (const FlickerBand& b : s.flicker.bands) {
      bands.push_back({{"from_deg", b.from_deg},
                       {"to_deg", number(b.to_deg)},
                       {"reference_change", number(b.reference_change)},
                       {"test_change", number(b.test_change)},
                       {"test_change_last", number(b.test_change_last)},
                       {"excess_change", number(b.excess_change)},
                       {"ratio", number(b.ratio)}});
    }
    j["flicker_bands"] = bands;
  }
  j["jod"] = s.fvvdp ? number(s.fvvdp->jod) : nlohmann::json(nullptr);
  if (s.fvvdp) j["fvvdp"] = to_json(*s.fvvdp);
  if (!s.fvvdp_streams.empty()) {
    nlohmann::json streams = nlohmann::json::array();
    for (const FvvdpResult& r : s.fvvdp_streams) streams.push_back(to_json(r));
    j["fvvdp_streams"] = streams;
  }
  return j;
}

void heat_color(double t, std::uint8_t rgb[3]) {
  // Anchors at t = 0, 0.25, 0.5, 0.75, 1: black, purple, red, orange, pale yellow.
  static constexpr double kAnchors[5][3] = {
      {0, 0, 4}, {87, 16, 110}, {188, 55, 84}, {249, 142, 9}, {252, 255, 164}};
  if (!(t > 0.0)) t = 0.0;  // also NaN
  t = std::min(t, 1.0) * 4.0;
  const int i = std::min(static_cast<int>(t), 3);
  const double f = t - i;
  for (int c = 0; c < 3; ++c) {
    const double v = kAnchors[i][c] + f * (kAnchors[i + 1][c] - kAnchors[i][c]);
    rgb[c] = static_cast<std::uint8_t>(std::lround(v));
  }
}

Image heatmap(const Map& values, double max_value) {
  if (!(max_value > 0.0)) throw Error("heatmap: the top of the colour scale must be > 0");
  Image out(values.width, values.height);
  for (size_t i = 0; i < values.values.size(); ++i) {
    std::uint8_t* p = &out.rgba[i * 4];
    heat_color(double(values.values[i]) / max_value, p);
    p[3] = 255;
  }
  return out;
}

Image error_heatmap(const Image& reference, const Image& test, double max_error) {
  detail::check_same_size(reference, test, "error_heatmap");
  Map m(reference.width, reference.height);
  const std::uint8_t* a = reference.rgba.data();
  const std::uint8_t* b = test.rgba.data();
  for (size_t i = 0; i < m.values.size(); ++i, a += 4, b += 4) {
    int e = 0;
    for (int c = 0; c < 3; ++c) e = std::max(e, std::abs(int(a[c]) - int(b[c])));
    m.values[i] = static_cast<float>(e);
  }
  return heatmap(m, max_error);
}

Image acuity_error_heatmap(const Image& reference, const Image& test, const Display& display,
                           Vec2d gaze, const QualityOptions& options, double max_error) {
  Map d = acuity_difference(reference, test, display, gaze, options.acuity);
  for (float& v : d.values) v = std::fabs(v);
  return heatmap(d, max_error);
}

}  // namespace foveate::metrics
