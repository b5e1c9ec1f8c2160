// Regressions found by the fuzz targets (tests/fuzz) in the JSON reading that
// every JSON input (display, camera path, channels, gaze traces) goes through.
#include "foveate/core/json_read.hpp"

#include <gtest/gtest.h>

#include <string>

#include "foveate/core/display.hpp"
#include "foveate/core/error.hpp"

using namespace foveate;

namespace {
std::string parse_error(const std::string& text, const std::string& where) {
  try {
    (void)parse_json(text, where);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}
}  // namespace

// Found by display_json_fuzz and trace_json_fuzz: a number beyond a double
// escaped as nlohmann's out_of_range (an "internal error", exit 3, no file named).
TEST(JsonRead, NumberOverflowIsAnErrorNamingTheInput) {
  EXPECT_EQ(parse_error("{\"width_px\": 1e999}", "lab.json"),
            "lab.json: the number 1e999 at byte 18 (key width_px) is out of range (beyond the "
            "largest double, about 1.8e308)");
  EXPECT_EQ(parse_error("[-1e400]", "trace.json"),
            "trace.json: the number -1e400 at byte 7 (key [0]) is out of range (beyond the "
            "largest double, about 1.8e308)");
  // Large but representable numbers still parse.
  EXPECT_DOUBLE_EQ(parse_json("[1e308]", "x")[0].get<double>(), 1e308);
}

TEST(JsonRead, SyntaxErrorsStillNameTheByte) {
  const std::string m = parse_error("{\"a\": ", "cam.json");
  EXPECT_EQ(m.rfind("cam.json: invalid JSON at byte 7: ", 0), 0u) << m;
}

TEST(JsonRead, DisplayWithOverflowingNumberIsAUserError) {
  try {
    (void)Display::from_json(parse_json("{\"width_px\": 1e999, \"height_px\": 1080}", "d.json"),
                             "d.json");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "d.json: the number 1e999 at byte 18 (key width_px) is out of range"),
              std::string::npos)
        << e.what();
  }
}
