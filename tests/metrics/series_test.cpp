// QualitySeries: means over frames, computed against compare() frame by frame.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "foveate/core/error.hpp"
#include "foveate/metrics/metrics.hpp"

namespace foveate::metrics {
namespace {

constexpr int kW = 320, kH = 180;

Display display() { return Display{}.resized(kW, kH); }

// Grey noise in [20, 230], so that the offsets below never clip.
Image noise(std::uint64_t seed) {
  Image img(kW, kH);
  std::uint64_t s = seed * 2862933555777941757ULL + 3037000493ULL;
  for (size_t i = 0; i < img.rgba.size(); i += 4) {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    const auto v = static_cast<std::uint8_t>(20 + (s >> 33) % 211);
    img.rgba[i] = img.rgba[i + 1] = img.rgba[i + 2] = v;
    img.rgba[i + 3] = 255;
  }
  return img;
}

// `ref` with `offset` codes added to R, G and B of the pixels 10 to 20 degrees
// from the image centre (band 2 of the default bands for a gaze at the centre).
Image offset_in_annulus(const Image& ref, int offset) {
  const Display d = display();
  Image out = ref;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const double e = d.eccentricity_deg({x + 0.5, y + 0.5}, {kW / 2.0, kH / 2.0});
      if (e < 10.0 || e >= 20.0) continue;
      for (int c = 0; c < 3; ++c)
        out.at(x, y)[c] = static_cast<std::uint8_t>(ref.at(x, y)[c] + offset);
    }
  }
  return out;
}

// The expected mean, written out independently of the library: the mean of the
// finite values; +inf if there were none but some were +inf; else NaN.
double expected_mean(const std::vector<double>& values) {
  double sum = 0;
  int n = 0;
  bool inf = false;
  for (double v : values) {
    if (std::isfinite(v)) {
      sum += v;
      ++n;
    } else if (std::isinf(v) && v > 0) {
      inf = true;
    }
  }
  if (n > 0) return sum / n;
  return inf ? kInf : kNaN;
}

void expect_same(double actual, double expected, const std::string& what) {
  if (std::isnan(expected)) {
    EXPECT_TRUE(std::isnan(actual)) << what << ": " << actual;
  } else if (std::isinf(expected)) {
    EXPECT_EQ(actual, expected) << what;
  } else {
    EXPECT_NEAR(actual, expected, 1e-9 * std::max(1.0, std::fabs(expected))) << what;
  }
}

// Three frames: +4 codes in the annulus, identical, +8 codes in the annulus;
// the reference changes every frame; the gaze moves in the identical frame.
struct Frames {
  std::vector<Image> reference, test;
  std::vector<Vec2d> gaze;
  Frames() {
    const int offsets[] = {4, 0, 8};
    const Vec2d gazes[] = {{160, 90}, {150, 96}, {160, 90}};
    for (int k = 0; k < 3; ++k) {
      reference.push_back(noise(100 + static_cast<std::uint64_t>(k)));
      test.push_back(offsets[k] ? offset_in_annulus(reference.back(), offsets[k])
                                : reference.back());
      gaze.push_back(gazes[k]);
    }
  }
};

TEST(Series, MeansOverFramesOfEveryField) {
  const Frames f;
  const Display d = display();
  QualityOptions o;
  o.acuity = AcuityModel::preset("A");
  QualitySeries series(d, o);
  std::vector<QualityReport> single;
  FlickerTracker flicker(d, 10.0, o.band_edges_deg);
  for (size_t k = 0; k < f.test.size(); ++k) {
    series.add(f.reference[k], f.test[k], f.gaze[k]);
    single.push_back(compare(f.reference[k], f.test[k], d, f.gaze[k], o));
    flicker.add(f.reference[k], f.test[k], f.gaze[k]);
  }
  const QualitySummary s = series.summary();
  EXPECT_EQ(s.frames, 3);
  EXPECT_EQ(series.frames(), 3);
  EXPECT_EQ(s.identical_frames, 1);
  EXPECT_EQ(s.mean.width, kW);
  EXPECT_EQ(s.mean.height, kH);
  EXPECT_EQ(s.mean.jnd_threshold, o.jnd_threshold);
  EXPECT_EQ(s.mean.contrast.peak_cd_m2, o.contrast.peak_cd_m2);

  // Over the image.
  auto overall = [&](double QualityReport::*field) {
    std::vector<double> v;
    for (const QualityReport& r : single) v.push_back(r.*field);
    return expected_mean(v);
  };
  expect_same(s.mean.psnr_db, overall(&QualityReport::psnr_db), "psnr_db");
  expect_same(s.mean.ssim, overall(&QualityReport::ssim), "ssim");
  expect_same(s.mean.acuity_rmse, overall(&QualityReport::acuity_rmse), "acuity_rmse");
  expect_same(s.mean.jnd_mean, overall(&QualityReport::jnd_mean), "jnd_mean");
  expect_same(s.mean.visible_fraction, overall(&QualityReport::visible_fraction),
              "visible_fraction");
  expect_same(s.mean.flip_mean, overall(&QualityReport::flip_mean), "flip_mean");
  expect_same(s.mean.flip_ppd, overall(&QualityReport::flip_ppd), "flip_ppd");
  // PSNR in dB over the two frames that differ, not over all three.
  EXPECT_NEAR(s.mean.psnr_db, 0.5 * (single[0].psnr_db + single[2].psnr_db), 1e-9);

  // Per band, every field.
  ASSERT_EQ(s.mean.bands.size(), 4u);
  for (size_t b = 0; b < 4; ++b) {
    auto band = [&](double BandStats::*field) {
      std::vector<double> v;
      for (const QualityReport& r : single) v.push_back(r.bands[b].*field);
      return expected_mean(v);
    };
    const std::string at = " of band " + std::to_string(b);
    EXPECT_EQ(s.mean.bands[b].from_deg, single[0].bands[b].from_deg);
    EXPECT_EQ(s.mean.bands[b].to_deg, single[0].bands[b].to_deg);
    expect_same(s.mean.bands[b].psnr_db, band(&BandStats::psnr_db), "psnr_db" + at);
    expect_same(s.mean.bands[b].ssim, band(&BandStats::ssim), "ssim" + at);
    expect_same(s.mean.bands[b].acuity_rmse, band(&BandStats::acuity_rmse), "acuity_rmse" + at);
    expect_same(s.mean.bands[b].flip_mean, band(&BandStats::flip_mean), "flip_mean" + at);
    expect_same(s.mean.bands[b].pixels_fraction, band(&BandStats::pixels_fraction),
                "pixels_fraction" + at);
    expect_same(s.mean.bands[b].jnd_mean, band(&BandStats::jnd_mean), "jnd_mean" + at);
    expect_same(s.mean.bands[b].visible_fraction, band(&BandStats::visible_fraction),
                "visible_fraction" + at);
  }

  // The eccentricity profile, bin by bin (the gaze moved in frame 1, so the
  // frames reach different largest eccentricities).
  size_t bins = 0;
  for (const QualityReport& r : single) bins = std::max(bins, r.profile.acuity_rmse.size());
  ASSERT_EQ(s.mean.profile.acuity_rmse.size(), bins);
  EXPECT_EQ(s.mean.profile.bin_deg, 1.0);
  for (size_t i = 0; i < bins; ++i) {
    std::vector<double> rmse, jnd, fraction;
    for (const QualityReport& r : single) {
      rmse.push_back(i < r.profile.acuity_rmse.size() ? r.profile.acuity_rmse[i] : kNaN);
      jnd.push_back(i < r.profile.jnd_mean.size() ? r.profile.jnd_mean[i] : kNaN);
      fraction.push_back(i < r.profile.pixels_fraction.size() ? r.profile.pixels_fraction[i] : 0.0);
    }
    const std::string at = " of profile bin " + std::to_string(i);
    expect_same(s.mean.profile.acuity_rmse[i], expected_mean(rmse), "acuity_rmse" + at);
    expect_same(s.mean.profile.jnd_mean[i], expected_mean(jnd), "jnd_mean" + at);
    expect_same(s.mean.profile.pixels_fraction[i], expected_mean(fraction), "pixels_fraction" + at);
  }
  // The offsets lie between 10 and 20 degrees: nothing within 5 degrees, and
  // the annulus's inner part (away from its edges, where the step is blurred
  // into the neighbouring bins) has an error.
  for (size_t i = 0; i < 5; ++i) EXPECT_EQ(s.mean.profile.acuity_rmse[i], 0.0) << i;
  EXPECT_GT(s.mean.profile.acuity_rmse[15], 1.0);

  // The band with the offsets: known PSNR per frame (a uniform +4 is 16 squared
  // codes per channel, +8 is 64), and the means differ from the last frame's.
  const BandStats& b2 = s.mean.bands[2];
  const BandStats& last = single.back().bands[2];
  const double psnr4 = 10 * std::log10(255.0 * 255.0 / 16.0);
  const double psnr8 = 10 * std::log10(255.0 * 255.0 / 64.0);
  EXPECT_NEAR(single[0].bands[2].psnr_db, psnr4, 0.01);
  EXPECT_NEAR(last.psnr_db, psnr8, 0.01);
  EXPECT_NEAR(b2.psnr_db, 0.5 * (single[0].bands[2].psnr_db + last.psnr_db), 1e-9);
  EXPECT_GT(std::fabs(b2.psnr_db - last.psnr_db), 2.0);
  EXPECT_NEAR(
      b2.acuity_rmse,
      (single[0].bands[2].acuity_rmse + single[1].bands[2].acuity_rmse + last.acuity_rmse) / 3.0,
      1e-9);
  EXPECT_GT(last.acuity_rmse, 1.0);
  EXPECT_LT(b2.acuity_rmse, 0.8 * last.acuity_rmse);
  EXPECT_GT(last.flip_mean, 0.0);
  EXPECT_LT(b2.flip_mean, 0.8 * last.flip_mean);
  EXPECT_NE(b2.pixels_fraction, last.pixels_fraction);  // the gaze moved in frame 1

  // The band around the gaze was identical in every frame.
  EXPECT_TRUE(std::isinf(s.mean.bands[0].psnr_db));
  EXPECT_EQ(s.mean.bands[0].ssim, 1.0);

  // Flicker: the tracker's figures, once, and per band.
  EXPECT_EQ(s.flicker.ratio, flicker.ratio());
  ASSERT_EQ(s.flicker.bands.size(), 4u);
  for (size_t b = 0; b < 4; ++b) {
    EXPECT_EQ(s.flicker.bands[b].test_change, flicker.bands()[b].test_change);
    EXPECT_EQ(s.flicker.bands[b].ratio, flicker.bands()[b].ratio);
    EXPECT_EQ(s.flicker.bands[b].from_deg, o.band_edges_deg[b]);
  }
  EXPECT_EQ(s.flicker.reference_change, flicker.reference_change());
  EXPECT_EQ(s.flicker.test_change, flicker.test_change());
  EXPECT_EQ(s.flicker.frame_pairs, 2);
  EXPECT_TRUE(std::isfinite(s.flicker.ratio));
  EXPECT_GT(s.flicker.reference_change, 10.0);  // the reference noise changes every frame

  // The per-frame reports are compare()'s.
  ASSERT_EQ(series.reports().size(), 3u);
  EXPECT_EQ(series.reports()[2].bands[2].acuity_rmse, last.acuity_rmse);
}

TEST(Series, JsonKeysAndNulls) {
  const Frames f;
  const Display d = display();
  QualitySeries series(d);
  for (size_t k = 0; k < f.test.size(); ++k) series.add(f.reference[k], f.test[k], f.gaze[k]);
  const QualitySummary s = series.summary();
  const nlohmann::json j = to_json(s);

  std::set<std::string> keys;
  for (const auto& [k, v] : j.items()) keys.insert(k);
  const std::set<std::string> expect_keys{"width",
                                          "height",
                                          "frames",
                                          "identical_frames",
                                          "identical",
                                          "psnr_db",
                                          "ssim",
                                          "acuity_rmse",
                                          "jnd_mean",
                                          "visible_fraction",
                                          "luminance_ratio",
                                          "jnd_threshold",
                                          "contrast_model",
                                          "eccentricity_profile",
                                          "flip_mean",
                                          "flip_ppd",
                                          "flicker_ratio",
                                          "flicker_reference_change",
                                          "flicker_test_change",
                                          "flicker_bands",
                                          "bands",
                                          "jod",
                                          "diagnostics",
                                          "fvvdp"};
  EXPECT_EQ(keys, expect_keys);
  // FovVideoVDP over the sequence: the same JOD as feeding it the frames directly.
  ASSERT_TRUE(s.fvvdp.has_value());
  EXPECT_EQ(j["jod"].get<double>(), s.fvvdp->jod);
  EXPECT_EQ(j["fvvdp"]["frames"].get<int>(), 3);
  Fvvdp direct(d);
  for (size_t k = 0; k < f.test.size(); ++k) direct.add(f.test[k], f.reference[k], f.gaze[k]);
  EXPECT_DOUBLE_EQ(s.fvvdp->jod, direct.result().jod);
  EXPECT_LT(s.fvvdp->jod, 10.0);
  ASSERT_EQ(j["bands"].size(), 4u);
  const std::set<std::string> expect_band_keys{
      "from_deg",    "to_deg",   "pixels_fraction",  "identical", "psnr_db",        "ssim",
      "acuity_rmse", "jnd_mean", "visible_fraction", "flip_mean", "luminance_ratio"};
  for (const auto& band : j["bands"]) {
    std::set<std::string> band_keys;
    for (const auto& [k, v] : band.items()) band_keys.insert(k);
    EXPECT_EQ(band_keys, expect_band_keys);
  }

  EXPECT_EQ(j["frames"].get<int>(), 3);
  EXPECT_EQ(j["identical_frames"].get<int>(), 1);
  EXPECT_FALSE(j["identical"].get<bool>());
  EXPECT_EQ(j["psnr_db"].get<double>(), s.mean.psnr_db);
  EXPECT_EQ(j["bands"][2]["acuity_rmse"].get<double>(), s.mean.bands[2].acuity_rmse);
  EXPECT_EQ(j["bands"][2]["flip_mean"].get<double>(), s.mean.bands[2].flip_mean);
  EXPECT_EQ(j["flicker_ratio"].get<double>(), s.flicker.ratio);
  EXPECT_EQ(j["flicker_test_change"].get<double>(), s.flicker.test_change);
  EXPECT_EQ(j["jnd_mean"].get<double>(), s.mean.jnd_mean);
  EXPECT_EQ(j["bands"][2]["jnd_mean"].get<double>(), s.mean.bands[2].jnd_mean);
  EXPECT_EQ(j["contrast_model"]["peak_cd_m2"].get<double>(), 100.0);
  EXPECT_EQ(j["contrast_model"]["pooling_beta"].get<double>(), 4.0);
  const auto& prof = j["eccentricity_profile"];
  EXPECT_EQ(prof["bin_deg"].get<double>(), 1.0);
  ASSERT_EQ(prof["acuity_rmse"].size(), s.mean.profile.acuity_rmse.size());
  EXPECT_EQ(prof["jnd_mean"].size(), prof["acuity_rmse"].size());
  EXPECT_EQ(prof["pixels_fraction"].size(), prof["acuity_rmse"].size());
  EXPECT_EQ(prof["acuity_rmse"][15].get<double>(), s.mean.profile.acuity_rmse[15]);
  ASSERT_EQ(j["flicker_bands"].size(), 4u);
  const std::set<std::string> expect_flicker_keys{
      "from_deg",      "to_deg", "reference_change", "test_change", "test_change_last",
      "excess_change", "ratio"};
  for (const auto& band : j["flicker_bands"]) {
    std::set<std::string> band_keys;
    for (const auto& [k, v] : band.items()) band_keys.insert(k);
    EXPECT_EQ(band_keys, expect_flicker_keys);
  }
  EXPECT_EQ(j["flicker_bands"][2]["test_change"].get<double>(), s.flicker.bands[2].test_change);
  EXPECT_TRUE(j["flicker_bands"][3]["to_deg"].is_null());
  // Non-finite numbers are null: the band identical in every frame (+inf PSNR)
  // and the outermost band's upper edge.
  EXPECT_TRUE(j["bands"][0]["psnr_db"].is_null());
  EXPECT_TRUE(j["bands"][0]["identical"].get<bool>());
  EXPECT_FALSE(j["bands"][2]["identical"].get<bool>());
  EXPECT_TRUE(j["bands"][3]["to_deg"].is_null());
  EXPECT_TRUE(nlohmann::json::accept(j.dump()));

  // A static reference and a test that changes: infinite flicker ratio -> null.
  QualitySeries twinkle(d);
  const Image ref = noise(7);
  twinkle.add(ref, offset_in_annulus(ref, 4), {160, 90});
  twinkle.add(ref, offset_in_annulus(ref, 8), {160, 90});
  const QualitySummary t = twinkle.summary();
  EXPECT_TRUE(std::isinf(t.flicker.ratio));
  const nlohmann::json tj = to_json(t);
  EXPECT_TRUE(tj["flicker_ratio"].is_null());
  EXPECT_EQ(tj["flicker_reference_change"].get<double>(), 0.0);
  EXPECT_GT(tj["flicker_test_change"].get<double>(), 0.0);
}

TEST(Series, AllIdenticalAndEmpty) {
  const Display d = display();
  QualitySeries empty(d);
  const QualitySummary e = empty.summary();
  EXPECT_EQ(e.frames, 0);
  EXPECT_TRUE(std::isnan(e.mean.psnr_db));
  EXPECT_TRUE(std::isnan(e.flicker.ratio));
  const nlohmann::json ej = to_json(e);
  EXPECT_EQ(ej["frames"].get<int>(), 0);
  EXPECT_TRUE(ej["psnr_db"].is_null());
  EXPECT_FALSE(ej["identical"].get<bool>());  // undefined, not identical
  EXPECT_TRUE(ej["flicker_ratio"].is_null());
  EXPECT_TRUE(nlohmann::json::accept(ej.dump()));

  QualitySeries same(d);
  for (int k = 0; k < 2; ++k) same.add(noise(200), noise(200), {160, 90});
  const QualitySummary s = same.summary();
  EXPECT_EQ(s.frames, 2);
  EXPECT_EQ(s.identical_frames, 2);
  EXPECT_TRUE(std::isinf(s.mean.psnr_db));
  EXPECT_EQ(s.mean.ssim, 1.0);
  EXPECT_EQ(s.mean.acuity_rmse, 0.0);
  EXPECT_EQ(s.flicker.ratio, 1.0);  // neither changed
  const nlohmann::json sj = to_json(s);
  EXPECT_TRUE(sj["identical"].get<bool>());
  EXPECT_TRUE(sj["psnr_db"].is_null());
  EXPECT_EQ(sj["identical_frames"].get<int>(), 2);
}

TEST(Series, ClearErrors) {
  const Display d = display();
  QualityOptions bad;
  bad.band_edges_deg = {0, 10, 5};
  EXPECT_THROW((void)QualitySeries(d, bad), Error);
  QualitySeries series(d);
  EXPECT_THROW(series.add(noise(1), Image(kW + 1, kH), {0, 0}), Error);
  EXPECT_THROW(series.add(Image(2 * kW, 2 * kH), Image(2 * kW, 2 * kH), {0, 0}), Error);
  EXPECT_EQ(series.frames(), 0);  // nothing was added
}

// Without the diagnostics only FovVideoVDP is measured; results.json must not
// carry the diagnostics' fields as zeros and nulls that read as measured, and
// reading it back must say they were not.
TEST(Series, WithoutDiagnosticsOnlyFvvdpIsWrittenAndReadBack) {
  const Frames f;
  QualityOptions o;
  o.acuity = AcuityModel::preset("A");
  o.diagnostics = false;
  QualitySeries series(display(), o);
  for (size_t k = 0; k < f.test.size(); ++k) series.add(f.reference[k], f.test[k], f.gaze[k]);
  const QualitySummary s = series.summary();
  EXPECT_FALSE(s.diagnostics);
  EXPECT_EQ(s.frames, 3);
  ASSERT_TRUE(s.fvvdp.has_value());
  const nlohmann::json j = to_json(s);
  EXPECT_EQ(j.at("diagnostics"), false);
  EXPECT_DOUBLE_EQ(j.at("jod").get<double>(), s.fvvdp->jod);
  for (const char* key : {"width", "identical", "psnr_db", "ssim", "acuity_rmse", "bands",
                          "flicker_bands", "identical_frames", "eccentricity_profile"})
    EXPECT_FALSE(j.contains(key)) << key;
  const QualitySummary back = quality_summary_from_json(j);
  EXPECT_FALSE(back.diagnostics);
  EXPECT_EQ(back.frames, 3);
  ASSERT_TRUE(back.fvvdp.has_value());
  EXPECT_DOUBLE_EQ(back.fvvdp->jod, s.fvvdp->jod);

  o.diagnostics = true;
  QualitySeries full(display(), o);
  full.add(f.reference[0], f.test[0], f.gaze[0]);
  const nlohmann::json fj = to_json(full.summary());
  EXPECT_EQ(fj.at("diagnostics"), true);
  EXPECT_TRUE(fj.contains("psnr_db") && fj.contains("flicker_bands"));
  EXPECT_TRUE(quality_summary_from_json(fj).diagnostics);
}

}  // namespace
}  // namespace foveate::metrics
