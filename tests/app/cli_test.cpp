// The command's shared logic without a GL context: whether a display leaves
// anything to save, the Pareto front, and the charts' axes and ordering.
#include <gtest/gtest.h>

#include <regex>

#include "cli_util.hpp"
#include "foveate/core/display.hpp"
#include "progress.hpp"
#include "svg_plot.hpp"

using namespace foveate;
using namespace foveate::app;

namespace {
long count(const std::string& text, const std::string& what) {
  long n = 0;
  for (size_t i = text.find(what); i != std::string::npos; i = text.find(what, i + 1)) ++n;
  return n;
}
}  // namespace

TEST(Savings, SmallRendersOfTheDesktopDisplayHaveNothingToSave) {
  const Display d = Display::load("desktop-1080p");
  const AcuityModel a = AcuityModel::quality("A");
  const SavingsCheck small = check_savings(d.resized(320, 180), a);
  EXPECT_TRUE(small.nothing_to_save);
  EXPECT_LT(small.pixel_bound, 1.2);
  EXPECT_NEAR(small.centre_ppd, 6.5, 0.1);  // a sixth of the paper's ~39 px/deg
  EXPECT_NE(small.note.find("320x180"), std::string::npos);
  EXPECT_NE(small.note.find("try --size 1280x720"), std::string::npos) << small.note;
  const SavingsCheck full = check_savings(d.resized(1920, 1080), a);
  EXPECT_FALSE(full.nothing_to_save);
  EXPECT_NEAR(full.pixel_bound, 8.49, 0.1);  // plan's 3 layers at full rate
  EXPECT_TRUE(full.note.empty());
}

TEST(Savings, AWideFieldSavesEvenAtModestSizes) {
  const Display quest = Display::load("hmd-quest3").resized(640, 684);
  EXPECT_FALSE(check_savings(quest, AcuityModel::quality("A")).nothing_to_save);
}

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

TEST(Durations, ReadLikeAClock) {
  EXPECT_EQ(format_duration(4.4), "4 s");
  EXPECT_EQ(format_duration(125), "2 min 05 s");
  EXPECT_EQ(format_duration(7300), "2 h 01 min");
}

TEST(Progress, TimeLeftWeighsEachKindOfStepByItsOwnPace) {
  // 10 frames of 1 s rendered, 2 of 10 metrics steps of 30 s done: what is
  // left is 8 slow steps (240 s) and 5 frames (5 s), not 15 steps at the
  // overall mean.
  std::vector<StepKind> k = {{"", 15, 10, 10.0}, {"metrics", 10, 2, 60.0}};
  EXPECT_DOUBLE_EQ(time_left(k), 5 * 1.0 + 8 * 30.0);
  // A kind not seen yet counts at the mean of all steps so far.
  k[1] = {"metrics", 4, 0, 0.0};
  EXPECT_DOUBLE_EQ(time_left(k), 5 * 1.0 + 4 * 1.0);
  // Done: nothing left.
  EXPECT_DOUBLE_EQ(time_left({{"", 3, 3, 9.0}}), 0.0);
}
