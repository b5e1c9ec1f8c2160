// Numbers printed for people, and the report's image encodings.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "foveate/core/acuity.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/image.hpp"
#include "foveate/core/parse.hpp"

using namespace foveate;

TEST(FormatNumber, NoExponentNoTrailingZeros) {
  EXPECT_EQ(format_number(9.0), "9");
  EXPECT_EQ(format_number(2073600.0), "2073600");
  EXPECT_EQ(format_number(0.0275), "0.0275");
  EXPECT_EQ(format_number(1.0 / 3.0), "0.333333");
  EXPECT_EQ(format_number(1.0 / 3.0, 2), "0.33");
  EXPECT_EQ(format_number(-2.5), "-2.5");
  EXPECT_EQ(format_number(-0.0000001), "-1e-07");  // below the decimals: the exponent says it
  EXPECT_EQ(format_number(0.0), "0");
  EXPECT_EQ(format_number(-0.0), "0");
  EXPECT_EQ(format_number(1e20), "1e+20");
  EXPECT_EQ(format_number(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(format_number(std::nan("")), "nan");
}

TEST(FormatAlternatives, AsASentenceListsThem) {
  EXPECT_EQ(format_alternatives({}), "");
  EXPECT_EQ(format_alternatives({"2"}), "2");
  EXPECT_EQ(format_alternatives({"2", "4"}), "2 or 4");
  EXPECT_EQ(format_alternatives({"8", "16", "32"}), "8, 16 or 32");
}

TEST(FormatNumber, ErrorsUseIt) {
  try {
    (void)AcuityModel::with_slope(2.0);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("got 2"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find("2.000000"), std::string::npos) << e.what();
  }
}

namespace {
Image gradient(int w, int h) {
  Image img(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = img.at(x, y);
      p[0] = static_cast<std::uint8_t>(255 * x / (w - 1));
      p[1] = static_cast<std::uint8_t>(255 * y / (h - 1));
      p[2] = 128;
      p[3] = 255;
    }
  }
  return img;
}
}  // namespace

TEST(Jpeg, DecodesBackCloseToTheOriginal) {
  const Image img = gradient(64, 48);
  const std::string jpeg = encode_jpeg(img, 90);
  ASSERT_GT(jpeg.size(), 100u);
  EXPECT_EQ(static_cast<unsigned char>(jpeg[0]), 0xFF);  // SOI marker
  EXPECT_EQ(static_cast<unsigned char>(jpeg[1]), 0xD8);
  const std::string path = ::testing::TempDir() + "/format_test.jpg";
  {
    FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_TRUE(f);
    std::fwrite(jpeg.data(), 1, jpeg.size(), f);
    std::fclose(f);
  }
  const Image back = read_image(path);
  ASSERT_EQ(back.width, 64);
  ASSERT_EQ(back.height, 48);
  double err = 0;
  for (size_t i = 0; i < img.rgba.size(); ++i)
    err += std::abs(int(img.rgba[i]) - int(back.rgba[i]));
  EXPECT_LT(err / double(img.rgba.size()), 3.0);  // a smooth gradient survives quality 90
  EXPECT_THROW((void)encode_jpeg(img, 0), Error);
  EXPECT_THROW((void)encode_jpeg(Image(), 90), Error);
}

TEST(Downscale, BoxFiltersToTheWidthKeepingTheAspect) {
  Image img(8, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 8; ++x) {
      std::uint8_t* p = img.at(x, y);
      p[0] = p[1] = p[2] = (x + y) % 2 ? 200 : 0;  // a checkerboard averages to 100
      p[3] = 255;
    }
  const Image small = downscale(img, 4);
  ASSERT_EQ(small.width, 4);
  ASSERT_EQ(small.height, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) EXPECT_EQ(small.at(x, y)[0], 100);
  EXPECT_EQ(downscale(img, 16).width, 8);  // never enlarged
}

namespace {
std::string point_error(const std::string& text, bool on_image = false) {
  try {
    if (on_image) {
      (void)parse_point_on_image(text, 1280, 720, "--gaze");
    } else {
      (void)parse_point(text, 1280, 720, "--gaze");
    }
  } catch (const Error& e) {
    return e.what();
  }
  return {};
}
}  // namespace

// A decimal point makes a coordinate normalized; pixels are whole numbers.
TEST(ParsePoint, DecimalPointMeansNormalizedAndOnlyInZeroToOne) {
  const Vec2d n = parse_point("0.25,1.0", 1280, 720, "--gaze");
  EXPECT_DOUBLE_EQ(n.x, 320.0);
  EXPECT_DOUBLE_EQ(n.y, 720.0);
  const Vec2d p = parse_point("1,1", 1280, 720, "--gaze");
  EXPECT_DOUBLE_EQ(p.x, 1.0);
  EXPECT_DOUBLE_EQ(p.y, 1.0);
  // 1.5 has a decimal point: a normalized value, and out of range (not the pixel 1.5).
  const std::string e = point_error("1.5,0.5");
  EXPECT_NE(e.find("--gaze: '1.5,0.5': 1.5 is outside 0.0..1.0"), std::string::npos) << e;
  EXPECT_NE(e.find("whole numbers"), std::string::npos) << e;
  EXPECT_NE(point_error("0.5,-0.1").find("-0.1 is outside 0.0..1.0"), std::string::npos);
  const std::string mixed = point_error("0.5,540");
  EXPECT_NE(mixed.find("mixes a normalized coordinate (0.5"), std::string::npos) << mixed;
  EXPECT_NE(mixed.find("in pixels (540)"), std::string::npos) << mixed;
}

TEST(ParsePoint, OnImageRefusesAPointOffTheImage) {
  EXPECT_EQ(point_error("1280,720", true), "");
  EXPECT_EQ(point_error("0,0", true), "");
  EXPECT_EQ(point_error("1.0,0.0", true), "");
  const std::string e = point_error("5000,100", true);
  EXPECT_NE(e.find("--gaze: '5000,100' is (5000, 100) px, outside the 1280x720 image"),
            std::string::npos)
      << e;
  EXPECT_NE(point_error("-1,10", true).find("outside the 1280x720 image"), std::string::npos);
  EXPECT_EQ(point_error("-1,10", false), "");  // off the screen is a valid point elsewhere
}

TEST(DidYouMean, SuggestsTheCloseNameOnly) {
  const std::vector<std::string> scenes{"raymarch", "detail", "cheap", "guenter"};
  EXPECT_EQ(closest_name("raymrach", scenes), "raymarch");  // two letters swapped
  EXPECT_EQ(closest_name("Detail", scenes), "detail");      // case
  EXPECT_EQ(closest_name("chep", scenes), "cheap");         // a letter missing
  EXPECT_EQ(closest_name("sponza", scenes), "");            // nothing close
  EXPECT_EQ(closest_name("cheap", scenes), "");             // the name itself
  EXPECT_EQ(closest_name("--sise", {"--size", "--scene", "--slope"}), "--size");
  EXPECT_EQ(closest_name("--zzzz", {"--size", "--scene", "--slope"}), "");
  EXPECT_EQ(did_you_mean("layerd", {"native", "layered", "logpolar"}), "; did you mean 'layered'?");
  EXPECT_EQ(did_you_mean("xyz", {"native", "layered"}), "");
}
