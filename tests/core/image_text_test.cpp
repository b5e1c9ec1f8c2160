#include "foveate/core/image_text.hpp"

#include <gtest/gtest.h>

using namespace foveate;

namespace {
bool is(const Image& im, int x, int y, int r, int g, int b) {
  const std::uint8_t* p = im.at(x, y);
  return p[0] == r && p[1] == g && p[2] == b;
}
}  // namespace

// A label is a dark box with the glyphs in the colour given, scaled, and
// clipped to the image.
TEST(ImageText, DrawsGlyphsOnADarkBox) {
  Image im(40, 20);
  draw_label(im, 2, 3, "L1", 1);
  EXPECT_EQ(label_width("L1", 1), 13);
  EXPECT_EQ(label_height(1), 9);
  EXPECT_TRUE(is(im, 2, 3, 16, 16, 16));  // the box's padding
  // 'L': its left column lit in every row, its foot across.
  for (int row = 0; row < 7; ++row) EXPECT_TRUE(is(im, 3, 4 + row, 255, 255, 255)) << row;
  EXPECT_TRUE(is(im, 4, 4, 16, 16, 16));
  EXPECT_TRUE(is(im, 7, 10, 255, 255, 255));
  EXPECT_TRUE(is(im, 1, 3, 0, 0, 0));  // outside the box: untouched
  EXPECT_TRUE(is(im, 15, 3, 0, 0, 0));
  Image big(40, 40);
  draw_label(big, 0, 0, "l", 2, {255, 0, 0});  // lower case is drawn in capitals
  EXPECT_TRUE(is(big, 2, 2, 255, 0, 0));
  EXPECT_TRUE(is(big, 3, 3, 255, 0, 0));
  EXPECT_EQ(label_scale(36), 1);
  EXPECT_EQ(label_scale(1080), 24);
  Image edge(8, 8);
  draw_label(edge, 4, 4, "WWW", 3);  // clipped, not out of bounds
  EXPECT_TRUE(is(edge, 5, 5, 16, 16, 16));
  EXPECT_TRUE(is(edge, 7, 7, 255, 255, 255));
}
