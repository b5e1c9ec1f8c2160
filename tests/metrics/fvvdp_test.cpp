// FovVideoVDP against the reference implementation's JODs and against the
// properties any visible-difference predictor must have.
#include "foveate/metrics/fvvdp.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "errors.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/json_read.hpp"
#include "fvvdp/fast_math.hpp"
#include "fvvdp/pyramid.hpp"

namespace foveate::metrics {
namespace {

namespace fs = std::filesystem;
using test::error_of;

// ---- The reference's test vectors (../shared/fvvdp) ---------------------------

// Where the vectors are: FOVEATE_FVVDP_CASES, else ../shared/fvvdp beside the
// source tree. Without them the tests skip, unless FOVEATE_FVVDP_CASES_REQUIRED
// is set (scripts/test.sh sets it when the folder exists), when they fail.
std::string cases_dir() {
  if (const char* env = std::getenv("FOVEATE_FVVDP_CASES")) return env;
  return std::string(FOVEATE_SOURCE_DIR) + "/../shared/fvvdp";
}

bool cases_available() {
  const bool present = fs::exists(cases_dir() + "/cases.json");
  if (!present && std::getenv("FOVEATE_FVVDP_CASES_REQUIRED")) {
    ADD_FAILURE() << "FovVideoVDP test vectors missing at " << cases_dir();
  }
  return present;
}

Display case_display(const nlohmann::json& spec, int width, int height) {
  Display d;
  d.name = "case";
  d.width_px = width;
  d.height_px = height;
  d.width_mm = spec.at("width_m").get<double>() * 1000.0;
  d.distance_mm = spec.at("distance_m").get<double>() * 1000.0;
  d.photometry.peak_cd_m2 = spec.at("Y_peak").get<double>();
  d.photometry.contrast_ratio = spec.at("contrast").get<double>();
  d.photometry.ambient_lux = spec.at("E_ambient").get<double>();
  d.photometry.reflectivity = spec.at("k_refl").get<double>();
  return d;
}

std::vector<std::string> frames_in(const std::string& dir) {
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() == ".png") files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Runs every case of one kind; returns the largest absolute error.
double check_cases(const std::string& kind) {
  const std::string dir = cases_dir();
  const nlohmann::json all = read_json_file(dir + "/cases.json");
  double worst = 0.0;
  int checked = 0;
  for (const auto& c : all.at("cases")) {
    if (c.at("kind") != kind) continue;
    const std::string test_path = dir + "/" + c.at("test").get<std::string>();
    const std::string ref_path = dir + "/" + c.at("reference").get<std::string>();
    std::vector<std::string> tests{test_path}, refs{ref_path};
    if (kind == "video") {
      tests = frames_in(test_path);
      refs = frames_in(ref_path);
    }
    const Image first = read_image(tests.at(0));
    FvvdpOptions options;
    options.foveated = c.at("foveated").get<bool>();
    if (c.contains("fps")) options.fps = c.at("fps").get<double>();
    Fvvdp metric(case_display(all.at("displays").at(c.at("display").get<std::string>()),
                              first.width, first.height),
                 options);
    // The reference measures from the centre of pixel fixation_px.
    const Vec2d gaze{c.at("fixation_px")[0].get<double>() + 0.5,
                     c.at("fixation_px")[1].get<double>() + 0.5};
    for (size_t f = 0; f < tests.size(); ++f)
      metric.add(read_image(tests[f]), read_image(refs[f]), gaze);
    const double jod = metric.result().jod;
    const double expected = c.at("jod").get<double>();
    EXPECT_NEAR(jod, expected, 0.01)
        << c.at("test") << " on " << c.at("display")
        << (options.foveated ? ", foveated at " : ", not foveated, ") << c.at("fixation_px");
    worst = std::max(worst, std::abs(jod - expected));
    ++checked;
  }
  EXPECT_GT(checked, 0);
  return worst;
}

TEST(FvvdpTest, ImagesMatchTheReferenceImplementation) {
  if (!cases_available()) GTEST_SKIP() << "no test vectors at " << cases_dir();
  const double worst = check_cases("image");
  RecordProperty("max_abs_error_jod", std::to_string(worst));
  std::printf("images: largest difference from the reference %.4f JOD\n", worst);
}

TEST(FvvdpTest, VideosMatchTheReferenceImplementation) {
  if (!cases_available()) GTEST_SKIP() << "no test vectors at " << cases_dir();
  const double worst = check_cases("video");
  std::printf("videos: largest difference from the reference %.4f JOD\n", worst);
}

// ---- Properties -------------------------------------------------------------------

struct Lcg {
  std::uint64_t s;
  explicit Lcg(std::uint64_t seed) : s(seed * 2862933555777941757ULL + 3037000493ULL) {}
  double uniform() {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(s >> 11) / 9007199254740992.0;
  }
};

// A textured grey scene: sinusoids of several frequencies and a few edges.
Image scene(int w, int h) {
  Image img(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const double v = 0.45 + 0.2 * std::sin(x * 0.9) * std::sin(y * 0.7) +
                       0.15 * std::sin(x * 0.11 + y * 0.05) + ((x / 37 + y / 23) % 2 ? 0.1 : -0.1);
      const auto code = static_cast<std::uint8_t>(std::clamp(v, 0.0, 1.0) * 255.0 + 0.5);
      std::uint8_t* p = img.at(x, y);
      p[0] = p[1] = p[2] = code;
      p[3] = 255;
    }
  }
  return img;
}

// A box blur of the given radius, applied `passes` times (a Gaussian-like blur).
Image blurred(const Image& in, int radius, int passes) {
  Image out = in;
  for (int pass = 0; pass < passes; ++pass) {
    const Image src = out;
    for (int y = 0; y < in.height; ++y) {
      for (int x = 0; x < in.width; ++x) {
        int sum = 0, n = 0;
        for (int dy = -radius; dy <= radius; ++dy) {
          for (int dx = -radius; dx <= radius; ++dx) {
            const int xx = std::clamp(x + dx, 0, in.width - 1);
            const int yy = std::clamp(y + dy, 0, in.height - 1);
            sum += src.at(xx, yy)[0];
            ++n;
          }
        }
        std::uint8_t* p = out.at(x, y);
        p[0] = p[1] = p[2] = static_cast<std::uint8_t>((sum + n / 2) / n);
      }
    }
  }
  return out;
}

Image noisy(const Image& in, double amplitude, std::uint64_t seed, int x_from = 0) {
  Image out = in;
  Lcg r(seed);
  for (int y = 0; y < in.height; ++y) {
    for (int x = x_from; x < in.width; ++x) {
      std::uint8_t* p = out.at(x, y);
      const double v = p[0] + amplitude * (r.uniform() * 2.0 - 1.0);
      p[0] = p[1] = p[2] = static_cast<std::uint8_t>(std::clamp(v, 0.0, 255.0) + 0.5);
    }
  }
  return out;
}

Display small_display() { return Display{}.resized(240, 135); }

TEST(FvvdpTest, IdenticalInputsScoreTen) {
  const Image a = scene(240, 135);
  const Display d = small_display();
  EXPECT_EQ(fvvdp_image(a, a, d, {120, 67}).jod, 10.0);
  FvvdpOptions not_foveated;
  not_foveated.foveated = false;
  EXPECT_EQ(fvvdp_image(a, a, d, {120, 67}, not_foveated).jod, 10.0);
  Fvvdp video(d);
  for (int f = 0; f < 6; ++f) video.add(a, a, {120, 67});
  const FvvdpResult r = video.result();
  EXPECT_EQ(r.jod, 10.0);
  EXPECT_FALSE(r.image);
  EXPECT_EQ(r.frames, 6);
  for (const FvvdpBand& b : r.bands) EXPECT_EQ(b.jod, 10.0);
}

TEST(FvvdpTest, MoreBlurNeverRaisesTheScore) {
  const Image ref = scene(240, 135);
  const Display d = small_display();
  double previous = 10.0;
  for (int radius = 1; radius <= 4; ++radius) {
    const double jod = fvvdp_image(blurred(ref, radius, 2), ref, d, {120, 67}).jod;
    EXPECT_LT(jod, previous) << "blur radius " << radius;
    previous = jod;
  }
}

TEST(FvvdpTest, MoreNoiseNeverRaisesTheScore) {
  const Image ref = scene(240, 135);
  const Display d = small_display();
  double previous = 10.0;
  for (double amplitude : {2.0, 6.0, 12.0, 24.0}) {
    const double jod = fvvdp_image(noisy(ref, amplitude, 5), ref, d, {120, 67}).jod;
    EXPECT_LT(jod, previous) << "noise amplitude " << amplitude;
    previous = jod;
  }
}

TEST(FvvdpTest, LookingAtADistortionLowersTheScore) {
  // Noise on the right half only: fixating it shows more than fixating the left edge.
  const Image ref = scene(240, 135);
  const Image test = noisy(ref, 10.0, 9, 120);
  const Display d = small_display();
  const double on = fvvdp_image(test, ref, d, {200, 67}).jod;
  const double away = fvvdp_image(test, ref, d, {10, 67}).jod;
  EXPECT_LT(on, away - 0.05);
  FvvdpOptions not_foveated;
  not_foveated.foveated = false;
  // Without foveation the fixation does not matter.
  EXPECT_EQ(fvvdp_image(test, ref, d, {200, 67}, not_foveated).jod,
            fvvdp_image(test, ref, d, {10, 67}, not_foveated).jod);
}

TEST(FvvdpTest, FlickerIsSeenOnlyInVideo) {
  // Alternating brightness of the test: as an image the odd frames are a small
  // offset; as a 60 Hz video the transient channel sees it flicker.
  const Image ref = scene(240, 135);
  Image bright = ref;
  for (size_t i = 0; i < bright.rgba.size(); i += 4) {
    for (int c = 0; c < 3; ++c) {
      bright.rgba[i + static_cast<size_t>(c)] =
          static_cast<std::uint8_t>(std::min(255, bright.rgba[i + static_cast<size_t>(c)] + 6));
    }
  }
  const Display d = small_display();
  Fvvdp steady(d), flicker(d);
  for (int f = 0; f < 12; ++f) {
    steady.add(ref, ref, {120, 67});
    flicker.add(f % 2 ? bright : ref, ref, {120, 67});
  }
  EXPECT_EQ(steady.result().jod, 10.0);
  const double as_image = fvvdp_image(bright, ref, d, {120, 67}).jod;
  EXPECT_LT(flicker.result().jod, as_image);
}

TEST(FvvdpTest, BandsLocateTheDifference) {
  // Noise beyond 10 degrees only: the inner bands see nothing.
  const Display d = Display{}.resized(480, 270);
  const Image ref = scene(480, 270);
  Image test = ref;
  const Vec2d gaze{240, 135};
  Lcg r(3);
  for (int y = 0; y < 270; ++y) {
    for (int x = 0; x < 480; ++x) {
      if (d.eccentricity_deg({x + 0.5, y + 0.5}, gaze) < 12.0) continue;
      std::uint8_t* p = test.at(x, y);
      p[0] = p[1] = p[2] =
          static_cast<std::uint8_t>(std::clamp(p[0] + 20.0 * (r.uniform() - 0.5), 0.0, 255.0));
    }
  }
  FvvdpOptions o;
  o.band_edges_deg = {0, 5, 10, 20};
  const FvvdpResult res = fvvdp_image(test, ref, d, gaze, o);
  ASSERT_EQ(res.bands.size(), 4u);
  EXPECT_GT(res.bands[0].jod, 9.99);
  EXPECT_LT(res.bands[2].jod, res.bands[0].jod - 0.1);
  double share = 0.0;
  for (const FvvdpBand& b : res.bands) share += b.pixels_fraction;
  EXPECT_NEAR(share, 1.0, 1e-9);
  EXPECT_LT(res.jod, 10.0);
}

TEST(FvvdpTest, HeatmapShowsWhereTheDifferenceIs) {
  const Image ref = scene(240, 135);
  const Image test = noisy(ref, 16.0, 4, 160);  // right third only
  FvvdpOptions o;
  o.heatmap = true;
  const FvvdpResult r = fvvdp_image(test, ref, small_display(), {120, 67}, o);
  ASSERT_EQ(r.heatmap.width, 240);
  ASSERT_EQ(r.heatmap.height, 135);
  double left = 0.0, right = 0.0;
  for (int y = 0; y < 135; ++y) {
    for (int x = 0; x < 80; ++x) left += r.heatmap.at(x, y);
    for (int x = 180; x < 240; ++x) right += r.heatmap.at(x, y);
  }
  EXPECT_GT(right, 20.0 * left);
  const Image pic = fvvdp_heatmap_image(r.heatmap, ref, 0.5);
  EXPECT_EQ(pic.width, 240);
}

TEST(FvvdpTest, BadInputIsRefusedWithTheReason) {
  const Display d = small_display();
  const Image a = scene(240, 135), b = scene(200, 135);
  Fvvdp m(d);
  EXPECT_NE(error_of([&] { m.add(b, b, {1, 1}); }).find("200x135"), std::string::npos);
  EXPECT_NE(error_of([&] { m.add(a, a, {NAN, 1}); }).find("gaze"), std::string::npos);
  EXPECT_NE(error_of([&] { (void)m.result(); }).find("no frames"), std::string::npos);
  FvvdpOptions o;
  o.fps = 0;
  EXPECT_NE(error_of([&] { Fvvdp x(d, o); }).find("fvvdp.fps"), std::string::npos);
  o = {};
  o.band_edges_deg = {0, 10, 5};
  EXPECT_NE(error_of([&] { Fvvdp x(d, o); }).find("band_edges_deg"), std::string::npos);
  Display tiny = Display{}.resized(3, 3);
  EXPECT_NE(error_of([&] { Fvvdp x(tiny); }).find("too small"), std::string::npos);
  Display dark = d;
  dark.photometry.peak_cd_m2 = -1;
  EXPECT_NE(error_of([&] { Fvvdp x(dark); }).find("photometry.peak_cd_m2"), std::string::npos);
}

TEST(FvvdpTest, FastLog2AndExp2AreAccurate) {
  double worst_log = 0.0, worst_exp = 0.0;
  for (double x = 1e-20; x < 1e20; x *= 1.0137) {
    const double got = fvvdp::fast_log2(static_cast<float>(x));
    const double want = std::log2(static_cast<double>(static_cast<float>(x)));
    // Within float's own resolution of the result, plus 1e-6.
    worst_log = std::max(worst_log, std::abs(got - want) / (1e-6 + 2.4e-7 * std::abs(want)));
  }
  for (double x = -120.0; x < 120.0; x += 0.0173) {
    const double got = fvvdp::fast_exp2(static_cast<float>(x));
    const double want = std::exp2(static_cast<double>(static_cast<float>(x)));
    worst_exp = std::max(worst_exp, std::abs(got / want - 1.0));
  }
  EXPECT_LT(worst_log, 1.0);
  EXPECT_LT(worst_exp, 1e-6);
  EXPECT_EQ(fvvdp::fast_exp2(-200.0f), 0.0f);
  EXPECT_LT(fvvdp::fast_log2(0.0f), -99.0f);
}

TEST(FvvdpTest, PyramidReduceAndExpandFollowTheKernel) {
  // A constant stays constant through reduce and expand (the kernel sums to 1,
  // the edges mirror or repeat samples), whatever the sizes' parities.
  for (int w : {5, 6, 7, 8}) {
    for (int h : {5, 6}) {
      Map m(w, h, 3.0f);
      const Map r = fvvdp::reduce(m);
      EXPECT_EQ(r.width, (w + 1) / 2);
      EXPECT_EQ(r.height, (h + 1) / 2);
      Map e;
      fvvdp::expand(Map(r.width, r.height, 3.0f), w, h, e);
      // The reference's last column follows the height's parity: when width
      // and height differ in parity a constant is not kept there.
      for (int y = 0; y < r.height; ++y) {
        for (int x = 0; x < r.width - 1; ++x) EXPECT_NEAR(r.at(x, y), 3.0f, 1e-5f);
      }
      if (w % 2 == h % 2) {
        EXPECT_NEAR(r.at(r.width - 1, 0), 3.0f, 1e-5f);
      }
      for (float v : e.values) EXPECT_NEAR(v, 3.0f, 1e-5f);
    }
  }
  // Band frequencies halve from 0.3228 ppd / 2 on.
  EXPECT_DOUBLE_EQ(fvvdp::band_frequency(0, 40.0), 20.0);
  EXPECT_DOUBLE_EQ(fvvdp::band_frequency(2, 40.0), 0.3228 * 10.0);
  EXPECT_EQ(fvvdp::band_count(1920, 1080, 38.7), 6);
}

}  // namespace
}  // namespace foveate::metrics
