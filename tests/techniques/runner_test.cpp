// What the frame runners read without GL: the reference named on the
// command line.
#include <gtest/gtest.h>

#include "errors.hpp"
#include "foveate/techniques/supersampled_native.hpp"

using namespace foveate;
using foveate::test::error_of;

TEST(SupersampledNative, ParseReference) {
  EXPECT_EQ(parse_reference("native"), 1);
  EXPECT_EQ(parse_reference("ssaa"), 4);
  EXPECT_EQ(parse_reference("ssaa:2"), 2);
  EXPECT_NE(error_of([] { parse_reference("ssaa:9"); }).find("2 to 8"), std::string::npos);
  EXPECT_NE(error_of([] { parse_reference("msaa"); }).find("'msaa'"), std::string::npos);
}
