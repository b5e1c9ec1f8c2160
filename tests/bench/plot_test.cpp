// The report's charts without a GL context: the Pareto front, the charts'
// axes and ordering.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "foveate/bench/svg_plot.hpp"

using namespace foveate::bench;

namespace {
long count(const std::string& text, const std::string& what) {
  long n = 0;
  for (size_t i = text.find(what); i != std::string::npos; i = text.find(what, i + 1)) ++n;
  return n;
}
}  // namespace

TEST(Pareto, KeepsOnlyWhatNothingElseBeats) {
  // x = speedup (higher better), y = error (lower better).
  const std::vector<ScatterPoint> p = {{"a", "", 1.0, 0.0},
                                       {"b", "", 3.0, 2.0},
                                       {"c", "", 2.0, 3.0},
                                       {"d", "", 4.0, 5.0},
                                       {"e", "", 3.0, 1.0}};
  const std::vector<size_t> front = pareto_front(p, false);
  EXPECT_EQ(front, (std::vector<size_t>{0, 4, 3}));  // a, e, d by speed; b and c dominated
  // Higher quality better (SSIM): d is now dominated by nothing faster.
  const std::vector<size_t> up = pareto_front(p, true);
  EXPECT_EQ(up, (std::vector<size_t>{3}));
}

TEST(Charts, LinesSortedByXWithMarkersAndTicks) {
  Series s{"s", "#000", {3, 1, 2}, {30, 10, 20}, false};
  ChartOptions o{"t", "x (unit)", "y (unit)", false};
  const std::string svg = svg_line_chart({s}, o);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(svg, m, std::regex("points=\"([^\"]*)\"")));
  // x pixel coordinates increase along the polyline.
  std::vector<double> xs;
  std::string pts = m[1];
  const std::regex pair("([0-9.]+),");
  for (std::sregex_iterator it(pts.begin(), pts.end(), pair), end; it != end; ++it)
    xs.push_back(std::stod((*it)[1]));
  ASSERT_EQ(xs.size(), 3u);
  EXPECT_LT(xs[0], xs[1]);
  EXPECT_LT(xs[1], xs[2]);
  EXPECT_EQ(count(svg, "class=\"point\""), 3);
  EXPECT_GE(count(svg, "class=\"tick\""), 4);
  EXPECT_NE(svg.find("x (unit)"), std::string::npos);
}

TEST(Charts, BarsWithWhiskersAndAnAxisThatNeedNotStartAtZero) {
  BarSeries b{.name = "SSIM",
              .color = "#000",
              .values = {0.92, 0.95},
              .lo = {0.91, 0.94},
              .hi = {0.93, 0.96}};
  const std::string svg =
      svg_bar_chart({"a", "b"}, {b}, {.title = "t", .value_label = "SSIM", .from_zero = false});
  EXPECT_NE(svg.find("class=\"whisker\""), std::string::npos);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(svg, m, std::regex("class=\"tick\"[^>]*>([^<]+)<")));
  EXPECT_GT(std::stod(m[1]), 0.8);  // the first tick is near the data, not 0
  const std::string zero = svg_bar_chart({"a", "b"}, {b}, {.title = "t", .value_label = "SSIM"});
  ASSERT_TRUE(std::regex_search(zero, m, std::regex("class=\"tick\"[^>]*>([^<]+)<")));
  EXPECT_EQ(std::string(m[1]), "0");
}

namespace {

// The y tick labels (right-aligned at their x) and the rotated y axis title's
// x: every label's left edge must lie right of the title (a long label such as
// a pixel count must not run into "pixels per frame"). Widths as a
// sans-serif font draws digits: 0.556 em.
void expect_y_labels_clear_of_title(const std::string& svg) {
  std::smatch m;
  ASSERT_TRUE(std::regex_search(
      svg, m, std::regex("class=\"axis-label\" transform=\"translate\\(([0-9.]+),")));
  const double title_right = std::stod(m[1]) + 4;
  const std::regex tick(
      "class=\"tick\" x=\"([0-9.]+)\" y=\"[0-9.]+\" text-anchor=\"end\">([^<]+)<");
  int n = 0;
  for (std::sregex_iterator it(svg.begin(), svg.end(), tick), end; it != end; ++it, ++n) {
    const std::string label = (*it)[2];
    long chars = 0;
    for (unsigned char c : label) chars += (c & 0xC0) != 0x80;
    EXPECT_GT(std::stod((*it)[1]) - 0.556 * 12 * double(chars), title_right) << label;
  }
  EXPECT_GE(n, 3);
}

}  // namespace

TEST(Charts, YTickLabelsClearTheAxisTitle) {
  // Figure 13 of `plan --sweep`: pixels per frame on a log axis up to 10^9.
  Series pixels{"native P*", "#000", {10, 80, 150}, {2e4, 3e7, 9e8}, false};
  ChartOptions log{.title = "t",
                   .x_label = "field of view (degrees)",
                   .y_label = "pixels per frame, log scale",
                   .log_y = true};
  expect_y_labels_clear_of_title(svg_line_chart({pixels}, log));
  const std::string log_svg = svg_line_chart({pixels}, log);
  EXPECT_NE(log_svg.find(">10⁹<"), std::string::npos);  // a power, not 1000000000
  // Long linear labels, and a scatter.
  Series big{"s", "#000", {1, 2, 3}, {1.25e6, 2.5e6, 3.75e6}, false};
  expect_y_labels_clear_of_title(
      svg_line_chart({big}, {.title = "t", .x_label = "x", .y_label = "pixels"}));
  const std::vector<ScatterPoint> pts = {{"a", "#000", 1, 0.001234}, {"b", "#000", 2, 0.001251}};
  expect_y_labels_clear_of_title(
      svg_scatter(pts, {.title = "t", .x_label = "x", .y_label = "y (unit)"}, true));
}

TEST(Charts, NumbersWithSignificantDigitsAndUnits) {
  // Values a raw double or printf would write as 0.00683761 and 2.67701e-05.
  BarSeries b{.name = "error", .color = "#000", .values = {0.00683761, 2.67701e-05}};
  BarChartOptions o{.title = "t", .value_label = "error (codes)", .unit = "codes"};
  const std::string svg = svg_bar_chart({"a", "b"}, {b}, o);
  EXPECT_NE(svg.find(">0.00684 codes<"), std::string::npos) << svg;
  EXPECT_NE(svg.find(">2.68×10⁻⁵ codes<"), std::string::npos);
  EXPECT_EQ(svg.find("0.00683761"), std::string::npos);
  EXPECT_EQ(svg.find("e-05"), std::string::npos);
  // A speedup's x sits on the number; ticks carry only the decimals their step needs.
  BarSeries s{.name = "speedup", .color = "#000", .values = {1.7349}};
  const std::string speed =
      svg_bar_chart({"layered"}, {s}, {.title = "t", .value_label = "speedup (x)", .unit = "x"});
  EXPECT_NE(speed.find(">1.73x<"), std::string::npos);
  std::smatch m;
  const std::regex tick("class=\"tick\"[^>]*>([^<]+)<");
  for (std::sregex_iterator it(speed.begin(), speed.end(), tick), end; it != end; ++it)
    EXPECT_LE(std::string((*it)[1]).size(), 4u) << (*it)[1];
}

TEST(Charts, RowsInTheirOwnColours) {
  BarSeries b{.name = "speedup", .values = {1, 2}, .colors = {"#0072b2", "#e69f00"}};
  BarSeries bound{
      .name = "bound", .values = {3, 4}, .colors = {"#0072b2", "#e69f00"}, .opacity = 0.35};
  const std::string svg =
      svg_bar_chart({"layered", "logpolar"}, {b, bound}, {.title = "t", .value_label = "x"});
  EXPECT_EQ(count(svg, "fill=\"#0072b2\" fill-opacity=\"1\""), 1);
  EXPECT_EQ(count(svg, "fill=\"#e69f00\" fill-opacity=\"0.35\""), 1);
  EXPECT_EQ(count(svg, "class=\"legend\""), 1);
  const std::string box = svg_box_plot({"layered", "logpolar"}, {{1, 2, 3}, {2, 3, 4}},
                                       {.title = "t", .x_label = "ms"}, {"#0072b2", "#e69f00"});
  EXPECT_EQ(count(box, "class=\"point\" "), 6);
  EXPECT_EQ(count(box, "fill=\"#e69f00\""), 4);  // the box and its three dots
}

TEST(Charts, StackedBarsSumTheirSegments) {
  const std::vector<StackSegment> passes = {{"shade", "#111111", {1.0, 2.0}},
                                            {"composite", "#222222", {0.5, std::nan("")}},
                                            {"other", "#333333", {0.25, 0.0}}};
  const std::string svg = svg_stacked_bars(
      {"layered", "native"}, passes, {.title = "t", .value_label = "ms per frame", .unit = "ms"});
  EXPECT_EQ(count(svg, "class=\"bar\""), 4);            // NaN and 0 left out
  EXPECT_NE(svg.find(">1.75 ms<"), std::string::npos);  // layered's total
  EXPECT_NE(svg.find(">2.00 ms<"), std::string::npos);
  EXPECT_NE(svg.find("composite: 0.500 ms (29 %)"), std::string::npos) << svg;
  for (const char* name : {">shade<", ">composite<", ">other<"})
    EXPECT_EQ(count(svg, name), 1) << name;
  EXPECT_GE(count(svg, "class=\"tick\""), 3);
  EXPECT_EQ(count(svg, "class=\"axis-label\""), 1);
}
