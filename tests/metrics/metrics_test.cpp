// Metrics against images with known answers.
#include "foveate/metrics/metrics.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <numbers>
#include <vector>

#include "foveate/core/error.hpp"
#include "srgb.hpp"

namespace foveate::metrics {
namespace {

constexpr double kPi = std::numbers::pi;

// ---- Independent helpers (not the library's) ---------------------------------

using test::q8;
using test::to_code;
using test::to_linear;

struct Lcg {
  std::uint64_t s;
  explicit Lcg(std::uint64_t seed) : s(seed * 2862933555777941757ULL + 3037000493ULL) {}
  std::uint32_t next() {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<std::uint32_t>(s >> 33);
  }
};

Image grey(int w, int h, int v) {
  Image img(w, h);
  for (size_t i = 0; i < img.rgba.size(); i += 4) {
    img.rgba[i] = img.rgba[i + 1] = img.rgba[i + 2] = static_cast<std::uint8_t>(v);
    img.rgba[i + 3] = 255;
  }
  return img;
}

// Grey noise, uniform in [lo, hi].
Image grey_noise(int w, int h, int lo, int hi, std::uint64_t seed) {
  Image img(w, h);
  Lcg r(seed);
  for (size_t i = 0; i < img.rgba.size(); i += 4) {
    const auto v = static_cast<std::uint8_t>(lo + static_cast<int>(r.next() % (hi - lo + 1)));
    img.rgba[i] = img.rgba[i + 1] = img.rgba[i + 2] = v;
    img.rgba[i + 3] = 255;
  }
  return img;
}

Image colour_noise(int w, int h, std::uint64_t seed) {
  Image img(w, h);
  Lcg r(seed);
  for (size_t i = 0; i < img.rgba.size(); ++i) {
    img.rgba[i] = (i % 4 == 3) ? 255 : static_cast<std::uint8_t>(r.next() % 256);
  }
  return img;
}

// Gaussian blur in linear light (separable, edges clamped), applied to the
// pixels where mask(x, y) is true.
template <class Mask>
Image blur_where(const Image& in, double sigma, Mask mask) {
  const int r = static_cast<int>(std::ceil(3.5 * sigma));
  std::vector<double> g(2 * r + 1);
  double gs = 0;
  for (int i = -r; i <= r; ++i) gs += g[i + r] = std::exp(-0.5 * i * i / (sigma * sigma));
  for (double& v : g) v /= gs;
  const int w = in.width, h = in.height;
  std::vector<double> lin(static_cast<size_t>(w) * h * 3), tmp(lin.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) lin[(size_t(y) * w + x) * 3 + c] = to_linear(in.at(x, y)[c]);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        double s = 0;
        for (int d = -r; d <= r; ++d)
          s += g[d + r] * lin[(size_t(y) * w + std::clamp(x + d, 0, w - 1)) * 3 + c];
        tmp[(size_t(y) * w + x) * 3 + c] = s;
      }
  Image out = in;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!mask(x, y)) continue;
      for (int c = 0; c < 3; ++c) {
        double s = 0;
        for (int d = -r; d <= r; ++d)
          s += g[d + r] * tmp[(size_t(std::clamp(y + d, 0, h - 1)) * w + x) * 3 + c];
        out.at(x, y)[c] = q8(to_code(s));
      }
    }
  return out;
}

Display small_desktop(int w = 480, int h = 270) { return Display{}.resized(w, h); }

// ---- PSNR ---------------------------------------------------------------------

TEST(Psnr, IdenticalIsInfinite) {
  const Image a = colour_noise(64, 48, 1);
  EXPECT_EQ(mse(a, a), 0.0);
  EXPECT_TRUE(std::isinf(psnr_db(a, a)));
  EXPECT_GT(psnr_db(a, a), 0.0);
}

TEST(Psnr, KnownNoiseGivesKnownValue) {
  // +-d on every channel (a pattern, never clipped): MSE = d^2 exactly.
  for (int d : {1, 5, 20}) {
    const Image a = grey_noise(64, 48, 30, 220, 2);
    Image b = a;
    Lcg r(3);
    for (size_t i = 0; i < b.rgba.size(); ++i) {
      if (i % 4 == 3) continue;
      b.rgba[i] = static_cast<std::uint8_t>(b.rgba[i] + ((r.next() & 1) ? d : -d));
    }
    EXPECT_DOUBLE_EQ(mse(a, b), double(d * d));
    EXPECT_NEAR(psnr_db(a, b), 10.0 * std::log10(255.0 * 255.0 / (d * d)), 1e-9);
  }
  // One channel of one pixel off by 255 in a 10x10 image: MSE = 255^2 / 300.
  const Image a = grey(10, 10, 0);
  Image b = a;
  b.at(3, 4)[1] = 255;
  EXPECT_NEAR(psnr_db(a, b), 10.0 * std::log10(300.0), 1e-9);
}

TEST(Psnr, AlphaIsIgnored) {
  const Image a = colour_noise(16, 16, 4);
  Image b = a;
  for (size_t i = 3; i < b.rgba.size(); i += 4) b.rgba[i] = 0;
  EXPECT_TRUE(std::isinf(psnr_db(a, b)));
}

// ---- SSIM ---------------------------------------------------------------------

TEST(Ssim, IdenticalIsExactlyOne) {
  const Image a = colour_noise(40, 30, 5);
  const Map m = ssim_map(a, a);
  for (float v : m.values) ASSERT_EQ(v, 1.0f);
  EXPECT_EQ(ssim(a, a), 1.0);
}

TEST(Ssim, ConstantImagesWorkedByHand) {
  // No variance in either window: SSIM = (2 x y + C1) / (x^2 + y^2 + C1) with
  // C1 = (0.01 * 255)^2 = 6.5025. For 100 vs 110:
  //   (22000 + 6.5025) / (10000 + 12100 + 6.5025) = 22006.5025 / 22106.5025 = 0.9954764
  EXPECT_NEAR(ssim(grey(20, 20, 100), grey(20, 20, 110)), 0.9954764, 2e-5);
  // 0 vs 255: C1 / (255^2 + C1) = 6.5025 / 65031.5025 = 0.00009999
  EXPECT_NEAR(ssim(grey(20, 20, 0), grey(20, 20, 255)), 6.5025 / 65031.5025, 1e-6);
}

TEST(Ssim, MatchesDirectWindowSum) {
  // A straightforward 11x11 Gaussian-window SSIM (Wang et al. 2004, eq. 13) at
  // interior pixels, on the same luminance codes.
  const int w = 40, h = 32;
  const Image a = grey_noise(w, h, 0, 255, 6);
  Image b = a;
  Lcg r(7);
  for (size_t i = 0; i < b.rgba.size(); i += 4) {
    const int v = std::clamp(int(b.rgba[i]) / 2 + 40 + int(r.next() % 31), 0, 255);
    b.rgba[i] = b.rgba[i + 1] = b.rgba[i + 2] = static_cast<std::uint8_t>(v);
  }
  const Map m = ssim_map(a, b);
  const double c1 = 6.5025, c2 = 58.5225;
  for (int y = 5; y < h - 5; y += 3) {
    for (int x = 5; x < w - 5; x += 3) {
      double sw = 0, mx = 0, my = 0;
      for (int dy = -5; dy <= 5; ++dy)
        for (int dx = -5; dx <= 5; ++dx) {
          const double g = std::exp(-(dx * dx + dy * dy) / (2 * 1.5 * 1.5));
          sw += g;
          mx += g * a.at(x + dx, y + dy)[0];
          my += g * b.at(x + dx, y + dy)[0];
        }
      mx /= sw;
      my /= sw;
      double vx = 0, vy = 0, cxy = 0;
      for (int dy = -5; dy <= 5; ++dy)
        for (int dx = -5; dx <= 5; ++dx) {
          const double g = std::exp(-(dx * dx + dy * dy) / (2 * 1.5 * 1.5)) / sw;
          const double p = a.at(x + dx, y + dy)[0] - mx, q = b.at(x + dx, y + dy)[0] - my;
          vx += g * p * p;
          vy += g * q * q;
          cxy += g * p * q;
        }
      const double expect =
          ((2 * mx * my + c1) * (2 * cxy + c2)) / ((mx * mx + my * my + c1) * (vx + vy + c2));
      ASSERT_NEAR(m.at(x, y), expect, 2e-4) << x << "," << y;
    }
  }
  // Inverting the contrast gives negative SSIM.
  Image inv = a;
  for (size_t i = 0; i < inv.rgba.size(); i += 4) {
    inv.rgba[i] = inv.rgba[i + 1] = inv.rgba[i + 2] = static_cast<std::uint8_t>(255 - a.rgba[i]);
  }
  EXPECT_LT(ssim(a, inv), -0.5);
}

// ---- Eccentricity bands -------------------------------------------------------

TEST(Bands, MasksFollowDisplayEccentricity) {
  const Display d = small_desktop(320, 180);
  const Vec2d gaze{70.3, 120.8};
  const Map ecc = eccentricity_map(d, gaze);
  const std::vector<double> edges{0, 5, 10, 20};
  const auto band = band_indices(ecc, edges);
  std::vector<int> count(4, 0);
  for (int y = 0; y < d.height_px; ++y) {
    for (int x = 0; x < d.width_px; ++x) {
      const double e = d.eccentricity_deg({x + 0.5, y + 0.5}, gaze);
      ASSERT_NEAR(ecc.at(x, y), e, 1e-4);
      const int expect = e < 5 ? 0 : e < 10 ? 1 : e < 20 ? 2 : 3;
      // Pixels within float rounding of an edge may go either way.
      const bool near_edge =
          std::fabs(e - 5) < 1e-4 || std::fabs(e - 10) < 1e-4 || std::fabs(e - 20) < 1e-4;
      if (!near_edge) {
        ASSERT_EQ(band[static_cast<size_t>(y) * d.width_px + x], expect);
      }
      ++count[expect];
    }
  }
  for (int c : count) EXPECT_GT(c, 0);  // the gaze is placed so that every band is present

  // compare() reports the same pixel shares.
  const Image a = grey_noise(320, 180, 0, 255, 8);
  const QualityReport r = compare(a, a, d, gaze);
  ASSERT_EQ(r.bands.size(), 4u);
  const double n = 320.0 * 180.0;
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(r.bands[k].pixels_fraction, count[k] / n, 2.0 / n);
    EXPECT_EQ(r.bands[k].from_deg, edges[k]);
  }
  EXPECT_TRUE(std::isinf(r.bands[3].to_deg));
  EXPECT_EQ(r.bands[2].to_deg, 20.0);
}

TEST(Bands, ChangeOnlyBeyondTwentyDegreesShowsOnlyThere) {
  const Display d = small_desktop(320, 180);
  const Vec2d gaze{160, 90};
  const Image a = grey_noise(320, 180, 20, 230, 9);
  Image b = a;
  for (int y = 0; y < 180; ++y) {
    for (int x = 0; x < 320; ++x) {
      if (d.eccentricity_deg({x + 0.5, y + 0.5}, gaze) >= 21.0) b.at(x, y)[0] ^= 0x10;
    }
  }
  QualityOptions o;
  o.flip = false;
  const QualityReport r = compare(a, b, d, gaze, o);
  EXPECT_TRUE(std::isinf(r.bands[0].psnr_db));
  EXPECT_TRUE(std::isinf(r.bands[1].psnr_db));
  EXPECT_TRUE(std::isfinite(r.bands[3].psnr_db));
  EXPECT_LT(r.bands[3].psnr_db, 40.0);
  EXPECT_LT(r.bands[3].psnr_db, r.psnr_db);  // the whole image dilutes the error
  EXPECT_EQ(r.bands[0].ssim, 1.0);
  EXPECT_LT(r.bands[3].ssim, 1.0);
  EXPECT_TRUE(std::isnan(r.flip_mean));
}

// ---- Acuity-aware error --------------------------------------------------------

TEST(Acuity, CutoffFollowsTheMarModel) {
  // f_c = 1 / (w(e) ppd) cycles per pixel, w in degrees per cycle (Guenter et al. eq. 1).
  const Display d = small_desktop(480, 270);
  const Vec2d gaze{240, 135};
  const AcuityModel m = AcuityModel::preset("A");
  const Map c = acuity_cutoff_map(d, gaze, m);
  for (Vec2d p : {Vec2d{240.5, 135.5}, Vec2d{100.5, 135.5}, Vec2d{5.5, 260.5}, Vec2d{470.5, 3.5}}) {
    const double e = d.eccentricity_deg(p, gaze);
    const double expect = 1.0 / (m.mar_deg(e) * d.pixels_per_degree(p, gaze));
    EXPECT_NEAR(c.at(int(p.x), int(p.y)), expect, 0.003 * expect) << p.x << "," << p.y;
  }
}

TEST(Acuity, ConstantImageStaysConstant) {
  const Display d = small_desktop();
  const Map f = acuity_filtered(grey(480, 270, 77), d, {10, 10}, AcuityModel{});
  for (float v : f.values) ASSERT_NEAR(v, 77.0, 0.01);
}

TEST(Acuity, IdenticalImagesGiveZero) {
  const Display d = small_desktop();
  const Image a = colour_noise(480, 270, 10);
  const QualityReport r = compare(a, a, d, {100, 200});
  EXPECT_TRUE(std::isinf(r.psnr_db));
  EXPECT_EQ(r.ssim, 1.0);
  EXPECT_EQ(r.acuity_rmse, 0.0);
  EXPECT_EQ(r.jnd_mean, 0.0);
  EXPECT_EQ(r.visible_fraction, 0.0);
  EXPECT_EQ(r.flip_mean, 0.0);
  for (const BandStats& b : r.bands) {
    EXPECT_TRUE(std::isinf(b.psnr_db));
    EXPECT_EQ(b.ssim, 1.0);
    EXPECT_EQ(b.acuity_rmse, 0.0);
    EXPECT_EQ(b.jnd_mean, 0.0);
  }
  for (double v : r.profile.acuity_rmse) EXPECT_TRUE(std::isnan(v) || v == 0.0);
}

struct BlurCase {
  QualityReport fine, coarse;
  double coarse_sigma, cutoff_min, cutoff_max;
};

// Grey 12-pixel blocks of random level in [lo, lo + 160) plus fine noise of up
// to 40 codes, on the desktop display at 960x540.
Image blocks_and_noise(int w, int h, std::uint64_t seed, int lo = 0) {
  Image img = grey_noise(w, h, 0, 40, seed);
  Lcg r(seed + 1);
  std::vector<int> level(static_cast<size_t>((w / 12 + 1) * (h / 12 + 1)));
  for (int& v : level) v = lo + static_cast<int>(r.next() % 160);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = img.at(x, y);
      p[0] = p[1] = p[2] =
          static_cast<std::uint8_t>(p[0] + level[size_t(y / 12) * (w / 12 + 1) + x / 12]);
    }
  return img;
}

// Beyond 15 degrees the test image differs from the reference by (fine) detail
// at 0.71 cycles per pixel, far above every cutoff there: the reference is a
// pixel checkerboard of codes 150 and 106, the test has its phase swapped
// (so the difference is exactly +-(Y(150) - Y(106)) in linear luminance, with
// no mean change); (coarse) blocks and noise blurred with a Gaussian that
// passes only exp(-2) = 0.135 at half the lowest cutoff there.
const BlurCase& blur_case() {
  static const BlurCase c = [] {
    BlurCase bc;
    const Display d = small_desktop(960, 540);
    const Vec2d gaze{480, 270};
    const Image ref = blocks_and_noise(960, 540, 11, 40);
    auto outside = [&](int x, int y) { return d.eccentricity_deg({x + 0.5, y + 0.5}, gaze) >= 15; };
    const Map fc = acuity_cutoff_map(d, gaze, AcuityModel{});
    bc.cutoff_min = 1e9;
    bc.cutoff_max = 0;
    for (int y = 0; y < 540; ++y)
      for (int x = 0; x < 960; ++x)
        if (outside(x, y)) {
          bc.cutoff_min = std::min(bc.cutoff_min, double(fc.at(x, y)));
          bc.cutoff_max = std::max(bc.cutoff_max, double(fc.at(x, y)));
        }
    Image checker = grey(960, 540, 0), swapped = checker;
    for (int y = 0; y < 540; ++y)
      for (int x = 0; x < 960; ++x) {
        const bool odd = (x + y) % 2 != 0;
        const std::uint8_t a = odd ? 150 : 106, b = odd ? 106 : 150;
        std::uint8_t* p = checker.at(x, y);
        std::uint8_t* q = swapped.at(x, y);
        p[0] = p[1] = p[2] = a;
        q[0] = q[1] = q[2] = outside(x, y) ? b : a;
      }
    bc.coarse_sigma = 2.0 / (kPi * bc.cutoff_min);
    QualityOptions o;
    o.flip = false;
    bc.fine = compare(checker, swapped, d, gaze, o);
    bc.coarse = compare(ref, blur_where(ref, bc.coarse_sigma, outside), d, gaze, o);
    return bc;
  }();
  return c;
}

TEST(Acuity, DetailFinerThanTheEyeResolvesIsInvisible) {
  const BlurCase& c = blur_case();
  std::printf(
      "acuity cutoff beyond 15 deg: %.3f..%.3f cycles/px; fine pattern: PSNR %.2f dB, acuity "
      "RMSE %.3f, JND %.3f, visible %.5f; coarse blur %.2f: PSNR %.2f dB, acuity RMSE %.3f, JND "
      "%.3f, visible %.4f\n",
      c.cutoff_min, c.cutoff_max, c.fine.psnr_db, c.fine.acuity_rmse, c.fine.jnd_mean,
      c.fine.visible_fraction, c.coarse_sigma, c.coarse.psnr_db, c.coarse.acuity_rmse,
      c.coarse.jnd_mean, c.coarse.visible_fraction);
  // The premise: the pattern (0.71 cycles per pixel) lies beyond 1.68 times
  // every cutoff there, where the acuity response is 0.
  ASSERT_LT(1.68 * c.cutoff_max, 0.5);
  // Beyond 20 degrees, 5 degrees from the seam at 15 degrees: PSNR sees a
  // large change, the eye none (acuity error in 8-bit luminance codes).
  const BandStats& far = c.fine.bands[3];
  EXPECT_LT(far.psnr_db, 20.0);
  EXPECT_LT(far.acuity_rmse, 0.02);
  EXPECT_LT(far.jnd_mean, 0.05);
  EXPECT_EQ(far.visible_fraction, 0.0);
  EXPECT_TRUE(std::isinf(c.fine.bands[0].psnr_db));
  // The seam itself, where the checkerboard's phase flips, is a line of
  // unmatched pixels with a mean luminance step: visible, as it should be.
  EXPECT_GT(c.fine.profile.jnd_mean[14], 1.0);
  EXPECT_LT(c.fine.profile.jnd_mean[18], 0.05);
}

TEST(Acuity, BlurCoarserThanTheEyeResolvesIsClearlyAboveZero) {
  const BlurCase& c = blur_case();
  EXPECT_GT(c.coarse.acuity_rmse, 3.0);
  EXPECT_GT(c.coarse.visible_fraction, 0.1);
  EXPECT_GT(c.coarse.jnd_mean, 1.0);
  EXPECT_GT(c.coarse.acuity_rmse, 10.0 * c.fine.acuity_rmse);
  // Nothing changed within 5 degrees: the FFTs' float rounding spreads 1e-5
  // codes, and the far tails of the coarse bands' kernels (sharp in frequency,
  // so long in space) carry a few thousandths of the change's JND there.
  EXPECT_LT(c.coarse.bands[0].acuity_rmse, 1e-3);
  EXPECT_LT(c.coarse.bands[0].jnd_mean, 0.2);
}

TEST(Acuity, SteeperSlopeForgivesMore) {
  // The same coarse change measured with a steeper MAR slope (a less demanding viewer).
  const Display d = small_desktop(480, 270);
  const Vec2d gaze{240, 135};
  const Image ref = grey_noise(480, 270, 0, 255, 12);
  const Image test = blur_where(ref, 1.5, [](int, int) { return true; });
  const auto rmse = [&](double slope) {
    const Map diff = acuity_difference(ref, test, d, gaze, AcuityModel::with_slope(slope));
    double s = 0;
    for (float v : diff.values) s += double(v) * v;
    return std::sqrt(s / double(diff.values.size()));
  };
  EXPECT_GT(rmse(0.01), rmse(0.03));
  EXPECT_GT(rmse(0.03), rmse(0.1));
}

// ---- FLIP ---------------------------------------------------------------------

std::array<double, 3> hunt_lab_of_code(double r8, double g8, double b8) {
  const double r = to_linear(r8), g = to_linear(g8), b = to_linear(b8);
  const double X = 0.4124564 * r + 0.3575761 * g + 0.1804375 * b;
  const double Y = 0.2126729 * r + 0.7151522 * g + 0.0721750 * b;
  const double Z = 0.0193339 * r + 0.1191920 * g + 0.9503041 * b;
  const double Xw = 0.4124564 + 0.3575761 + 0.1804375, Yw = 1.0;
  const double Zw = 0.0193339 + 0.1191920 + 0.9503041;
  auto f = [](double t) {
    return t > 216.0 / 24389.0 ? std::cbrt(t) : t * 24389.0 / 27.0 / 116.0 + 16.0 / 116.0;
  };
  const double L = 116 * f(Y / Yw) - 16;
  return {L, 0.01 * L * 500 * (f(X / Xw) - f(Y / Yw)), 0.01 * L * 200 * (f(Y / Yw) - f(Z / Zw))};
}

TEST(Flip, UniformColoursWorkedByHand) {
  // Uniform images: the CSF filters (normalised) and the feature detectors
  // (zero response) leave only the colour term: HyAB distance of the Hunt-
  // adjusted L*a*b* colours, ^0.7, remapped against green-vs-blue.
  auto hyab = [](std::array<double, 3> a, std::array<double, 3> b) {
    return std::fabs(a[0] - b[0]) + std::hypot(a[1] - b[1], a[2] - b[2]);
  };
  const double cmax = std::pow(hyab(hunt_lab_of_code(0, 255, 0), hunt_lab_of_code(0, 0, 255)), 0.7);
  auto expected = [&](std::array<int, 3> p, std::array<int, 3> q) {
    const double dc =
        std::pow(hyab(hunt_lab_of_code(p[0], p[1], p[2]), hunt_lab_of_code(q[0], q[1], q[2])), 0.7);
    return dc < 0.4 * cmax ? 0.95 * dc / (0.4 * cmax)
                           : 0.95 + (dc - 0.4 * cmax) / (0.6 * cmax) * 0.05;
  };
  auto solid = [](std::array<int, 3> c) {
    Image img(24, 24);
    for (size_t i = 0; i < img.rgba.size(); i += 4) {
      for (int k = 0; k < 3; ++k) img.rgba[i + k] = static_cast<std::uint8_t>(c[k]);
      img.rgba[i + 3] = 255;
    }
    return img;
  };
  for (auto [p, q] : {std::pair{std::array{0, 0, 0}, std::array{255, 255, 255}},
                      std::pair{std::array{100, 100, 100}, std::array{110, 110, 110}},
                      std::pair{std::array{200, 40, 40}, std::array{40, 200, 40}}}) {
    const Map m = flip_map(solid(p), solid(q), 40.0);
    const double e = expected(p, q);
    EXPECT_NEAR(m.at(12, 12), e, 2e-3) << p[0] << " vs " << q[0];
    EXPECT_NEAR(m.at(0, 0), e, 2e-3);
  }
  // Black vs white lands in the top 5 % of the scale.
  EXPECT_GT(expected({0, 0, 0}, {255, 255, 255}), 0.95);
}

TEST(Flip, IdenticalIsZeroAndEdgesCount) {
  const Image a = colour_noise(48, 48, 13);
  for (float v : flip_map(a, a, 40.0).values) ASSERT_EQ(v, 0.0f);
  // A one-pixel shift of a sharp edge is a larger FLIP error than +-2 noise.
  Image edge = grey(48, 48, 30), shifted = grey(48, 48, 30), noisy = grey(48, 48, 30);
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 48; ++x) {
      if (x >= 24) edge.at(x, y)[0] = edge.at(x, y)[1] = edge.at(x, y)[2] = 220;
      if (x >= 25) shifted.at(x, y)[0] = shifted.at(x, y)[1] = shifted.at(x, y)[2] = 220;
      for (int c = 0; c < 3; ++c)
        noisy.at(x, y)[c] = static_cast<std::uint8_t>(edge.at(x, y)[c] + ((x + y) % 2 ? 2 : -2));
    }
  auto mean = [](const Map& m) {
    double s = 0;
    for (float v : m.values) s += v;
    return s / double(m.values.size());
  };
  const double shift = mean(flip_map(edge, shifted, 40.0));
  const double noise = mean(flip_map(edge, noisy, 40.0));
  EXPECT_GT(shift, 0.0);
  EXPECT_GT(noise, 0.0);
  EXPECT_GT(shift, noise);
  const Map sm = flip_map(edge, shifted, 40.0);
  EXPECT_GT(sm.at(24, 20), 0.5);  // at the moved edge
  EXPECT_LT(sm.at(5, 20), 1e-3);  // far from it
}

// ---- Flicker ------------------------------------------------------------------

TEST(Flicker, RatioAgainstNative) {
  const Display d = small_desktop(320, 180);
  const Vec2d gaze{160, 90};
  FlickerTracker same(d, 10.0), brighter(d, 10.0), central(d, 10.0);
  EXPECT_TRUE(std::isnan(same.ratio()));
  for (int f = 0; f < 4; ++f) {
    // Native alternates 100/110 everywhere; "brighter" alternates 100/120.
    const Image ref = grey(320, 180, f % 2 ? 110 : 100);
    const Image twice = grey(320, 180, f % 2 ? 120 : 100);
    same.add(ref, ref, gaze);
    brighter.add(ref, twice, gaze);
    // Extra change only inside 5 degrees: invisible to a tracker that starts at 10.
    Image c = ref;
    if (f % 2) {
      for (int y = 80; y < 100; ++y)
        for (int x = 150; x < 170; ++x) c.at(x, y)[0] = c.at(x, y)[1] = c.at(x, y)[2] = 250;
    }
    central.add(ref, c, gaze);
  }
  EXPECT_EQ(same.frame_pairs(), 3);
  EXPECT_EQ(same.ratio(), 1.0);
  EXPECT_EQ(same.excess_change(), 0.0);
  EXPECT_NEAR(same.reference_change(), 10.0, 0.01);
  EXPECT_NEAR(brighter.ratio(), 2.0, 0.005);
  EXPECT_NEAR(brighter.excess_change(), 10.0, 0.01);
  EXPECT_EQ(central.ratio(), 1.0);
}

TEST(Flicker, StaticNativeAndTwinklingPeriphery) {
  const Display d = small_desktop(320, 180);
  FlickerTracker t(d, 10.0);
  const Image ref = grey_noise(320, 180, 0, 255, 14);
  for (int f = 0; f < 3; ++f) t.add(ref, grey_noise(320, 180, 0, 255, 20 + f), {160, 90});
  EXPECT_TRUE(std::isinf(t.ratio()));
  EXPECT_GT(t.test_change(), 50.0);
  FlickerTracker still(d, 10.0);
  for (int f = 0; f < 3; ++f) still.add(ref, ref, {160, 90});
  EXPECT_EQ(still.ratio(), 1.0);
}

TEST(Flicker, StreamsOfAStereoPairArePooledButComparedWithinEachStream) {
  // Two still views (a stereo pair's eyes) that differ from each other, fed
  // alternately: compared within each stream they never change; compared
  // frame after frame (one stream) the tracker would see the difference
  // between the eyes as flicker.
  const Display d = small_desktop(320, 180);
  const Image left = grey_noise(320, 180, 0, 255, 31), right = grey_noise(320, 180, 0, 255, 32);
  const Image left_test = grey_noise(320, 180, 0, 255, 33);
  FlickerTracker pooled(d, 10.0), mixed(d, 10.0);
  for (int f = 0; f < 3; ++f) {
    pooled.add(left, left_test, {160, 90}, 0);
    pooled.add(right, right, {160, 90}, 1);
    mixed.add(left, left_test, {160, 90});
    mixed.add(right, right, {160, 90});
  }
  EXPECT_EQ(pooled.frame_pairs(), 4);  // two pairs per stream
  EXPECT_EQ(pooled.test_change(), 0.0);
  EXPECT_EQ(pooled.ratio(), 1.0);
  EXPECT_GT(mixed.test_change(), 50.0);
  EXPECT_THROW(pooled.add(left, left, {160, 90}, -1), Error);
}

// ---- Report, JSON, pictures, errors ----------------------------------------------

TEST(Report, JsonConventions) {
  const Display d = small_desktop(320, 180);
  const Image a = grey_noise(320, 180, 0, 255, 15);
  QualityOptions o;
  o.band_edges_deg = {0, 5, 10, 20, 60};  // nothing lies beyond 60 degrees
  const nlohmann::json same = to_json(compare(a, a, d, {160, 90}, o));
  EXPECT_TRUE(same["identical"].get<bool>());
  EXPECT_TRUE(same["psnr_db"].is_null());
  EXPECT_EQ(same["ssim"].get<double>(), 1.0);
  EXPECT_EQ(same["acuity_rmse"].get<double>(), 0.0);
  ASSERT_EQ(same["bands"].size(), 5u);
  EXPECT_TRUE(same["bands"][0]["identical"].get<bool>());
  EXPECT_TRUE(same["bands"][0]["psnr_db"].is_null());
  EXPECT_TRUE(same["bands"][4]["psnr_db"].is_null());       // empty band: undefined...
  EXPECT_FALSE(same["bands"][4]["identical"].get<bool>());  // ...not identical
  EXPECT_EQ(same["bands"][4]["pixels_fraction"].get<double>(), 0.0);
  EXPECT_TRUE(same["bands"][4]["to_deg"].is_null());
  EXPECT_EQ(same["bands"][3]["to_deg"].get<double>(), 60.0);
  // The dump must be valid JSON (no inf/nan).
  const std::string dumped = same.dump();
  EXPECT_TRUE(nlohmann::json::accept(dumped));

  Image b = a;
  b.at(0, 0)[0] ^= 1;
  const nlohmann::json diff = to_json(compare(a, b, d, {160, 90}, o));
  EXPECT_FALSE(diff["identical"].get<bool>());
  EXPECT_NEAR(diff["psnr_db"].get<double>(), 10 * std::log10(65025.0 * 3 * 320 * 180), 1e-6);
}

TEST(Report, Heatmaps) {
  const Image a = grey(8, 4, 100);
  Image b = a;
  b.at(1, 1)[2] = 200;  // error 100 >= max
  b.at(2, 1)[0] = 116;  // error 16 = a quarter of 64
  const Image h = error_heatmap(a, b, 64.0);
  ASSERT_EQ(h.width, 8);
  ASSERT_EQ(h.height, 4);
  EXPECT_EQ(h.at(0, 0)[0], 0);
  EXPECT_EQ(h.at(0, 0)[2], 4);
  EXPECT_EQ(h.at(1, 1)[0], 252);
  EXPECT_EQ(h.at(1, 1)[1], 255);
  EXPECT_EQ(h.at(2, 1)[0], 87);
  EXPECT_EQ(h.at(2, 1)[3], 255);
  const Display d = Display{}.resized(8, 4);
  const Image ah = acuity_error_heatmap(a, a, d, {4, 2});
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 8; ++x) EXPECT_EQ(ah.at(x, y)[0], 0);
}

TEST(Report, ClearErrors) {
  const Display d = small_desktop(320, 180);
  const Image a = grey(320, 180, 1), b = grey(321, 180, 1);
  try {
    (void)compare(a, b, d, {0, 0});
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("320x180"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("321x180"), std::string::npos);
  }
  EXPECT_THROW((void)compare(a, a, small_desktop(640, 360), {0, 0}), Error);
  EXPECT_THROW((void)compare(Image{}, Image{}, d, {0, 0}), Error);
  QualityOptions o;
  o.band_edges_deg = {0, 10, 5};
  EXPECT_THROW((void)compare(a, a, d, {0, 0}, o), Error);
  EXPECT_THROW((void)flip_map(a, a, 0.0), Error);
}

}  // namespace
TEST(Compare, LuminanceRatioIsInLinearLight) {
  // Black and white pixels average to code 188 in linear light; code 128 is
  // what filtering in sRGB codes gives: 0.43 of the luminance.
  const Display d = small_desktop(64, 36);
  const QualityReport same = compare(grey(64, 36, 188), grey(64, 36, 188), d, {32, 18});
  EXPECT_DOUBLE_EQ(same.luminance_ratio, 1.0);
  const QualityReport dark = compare(grey(64, 36, 188), grey(64, 36, 128), d, {32, 18});
  auto lin = [](double c) { return to_linear(c); };
  EXPECT_NEAR(dark.luminance_ratio, lin(128) / lin(188), 1e-3);
  for (const BandStats& b : dark.bands) {
    if (b.pixels_fraction > 0) {
      EXPECT_NEAR(b.luminance_ratio, lin(128) / lin(188), 1e-3);
    }
  }
}

}  // namespace foveate::metrics
