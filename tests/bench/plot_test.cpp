// The report's charts without a GL context: the Pareto front, the charts'
// axes and ordering.
#include <gtest/gtest.h>

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
  BarSeries b{"SSIM", "#000", {0.92, 0.95}, {0.91, 0.94}, {0.93, 0.96}};
  const std::string svg = svg_bar_chart({"a", "b"}, {b}, {"t", "SSIM", false, 700, 3});
  EXPECT_NE(svg.find("class=\"whisker\""), std::string::npos);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(svg, m, std::regex("class=\"tick\"[^>]*>([^<]+)<")));
  EXPECT_GT(std::stod(m[1]), 0.8);  // the first tick is near the data, not 0
  const std::string zero = svg_bar_chart({"a", "b"}, {b}, {"t", "SSIM", true, 700, 3});
  ASSERT_TRUE(std::regex_search(zero, m, std::regex("class=\"tick\"[^>]*>([^<]+)<")));
  EXPECT_EQ(std::string(m[1]), "0");
}
