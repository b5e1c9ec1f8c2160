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
