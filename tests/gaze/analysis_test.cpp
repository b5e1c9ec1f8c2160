// I-VT statistics on a trace whose events are known.
#include "foveate/gaze/analysis.hpp"

#include <gtest/gtest.h>

namespace foveate::gaze {
namespace {

TEST(AnalyzeTrace, FindsRateFixationsSaccadesAndDropouts) {
  const Display d;
  Trace t;
  auto add = [&](double time, Vec2d p, bool valid = true) {
    t.samples.push_back({time, p, valid ? 1.0 : 0.0, valid});
  };
  // 100 Hz. Fixation at A, a 40 ms saccade to B, fixation, a 150 ms blink,
  // fixation, a 200 ms gap with no samples, fixation.
  const Vec2d a{0.3, 0.5}, b{0.7, 0.5};
  int k = 0;
  for (; k < 30; ++k) add(k * 0.01, a);                                   // 0.00-0.29
  for (int j = 1; j <= 4; ++j, ++k) add(k * 0.01, {a.x + 0.1 * j, 0.5});  // 0.30-0.33
  for (; k < 60; ++k) add(k * 0.01, b);                                   // 0.34-0.59
  for (; k < 75; ++k) add(k * 0.01, b, false);                            // 0.60-0.74 blink
  for (; k < 100; ++k) add(k * 0.01, b);                                  // 0.75-0.99
  for (k = 120; k < 150; ++k) add(k * 0.01, b);                           // 1.20-1.49
  t.latency_ms = std::vector<double>(t.samples.size(), 12.0);
  t.latency_ms[0] = 30.0;

  const TraceStats s = analyze_trace(t, d);
  EXPECT_EQ(s.samples, 130u);
  EXPECT_NEAR(s.rate_hz, 100.0, 1e-6);
  EXPECT_NEAR(s.duration_s, 1.49, 1e-12);
  EXPECT_EQ(s.lost_samples, 15u);
  ASSERT_EQ(s.dropouts, 2u);
  EXPECT_NEAR(s.longest_dropout_s, 0.21, 1e-9);  // last sample 0.99, next 1.20
  EXPECT_NEAR(s.dropout_s, 0.16 + 0.21, 1e-9);   // 0.59 -> 0.75 and 0.99 -> 1.20
  ASSERT_EQ(s.saccades.size(), 1u);
  EXPECT_NEAR(s.saccades[0].start_s, 0.29, 1e-12);
  EXPECT_NEAR(s.saccades[0].end_s, 0.33, 1e-12);
  EXPECT_NEAR(s.saccades[0].amplitude_deg, angle_between_deg(d, a, b), 1e-9);
  EXPECT_GT(s.saccades[0].peak_deg_per_s, 400.0);
  ASSERT_EQ(s.fixations.size(), 4u);
  EXPECT_NEAR(s.fixations[0].end_s, 0.29, 1e-12);
  EXPECT_NEAR(s.fixations[1].start_s, 0.34, 1e-12);
  EXPECT_NEAR(s.fixations[1].pos.x, 0.7, 1e-12);
  EXPECT_TRUE(s.has_latency);
  EXPECT_NEAR(s.latency_median_ms, 12.0, 1e-12);
  EXPECT_NEAR(s.latency_max_ms, 30.0, 1e-12);
}

TEST(AnalyzeTrace, ShortFixationsAreNotCounted) {
  const Display d;
  Trace t;
  // 50 ms at one place between two saccades: below the 60 ms minimum.
  int k = 0;
  for (; k < 20; ++k) t.samples.push_back({k * 0.01, {0.2, 0.5}, 1.0, true});
  for (; k < 25; ++k) t.samples.push_back({k * 0.01, {0.5, 0.5}, 1.0, true});
  for (; k < 45; ++k) t.samples.push_back({k * 0.01, {0.8, 0.5}, 1.0, true});
  const TraceStats s = analyze_trace(t, d);
  EXPECT_EQ(s.saccades.size(), 2u);
  EXPECT_EQ(s.fixations.size(), 2u);
  EXPECT_EQ(s.dropouts, 0u);
}

}  // namespace
}  // namespace foveate::gaze
